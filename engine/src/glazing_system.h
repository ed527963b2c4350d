// Glazing system: the angular transmittance and reflectance of a stack of panes (double,
// triple glazing, coated panes), for MaterialType::Glazing. Formulas, parameters and
// measured numbers: docs/materials.md, "Glazing systems".
//
// Per pane (one channel, angle of incidence theta):
//   - uncoated: the thin-glass series of thin_glass_fresnel.h (Fresnel reflectance of each
//     polarisation at both faces, absorption exp(-K d / cos theta_t) along the refracted
//     path), averaged over the two polarisations (M. Rubin, "Optical properties of soda lime
//     silica glasses", Solar Energy Materials 12, 1985; R. Furler, "Angular dependence of
//     optical properties of homogeneous glasses", ASHRAE Transactions 98(1), 1991). The pane
//     is symmetric: the same reflectance from both sides.
//   - coated (a low-e or solar-control pane given by its measured normal transmittance T0
//     and face reflectances Rf0, Rb0): the angular fits of LBL's WINDOW 4 for coated glass,
//         T(theta) = T0 tau(cos theta) / tau(1),
//         R(theta) = R0 (1 - rho(cos theta)) + rho(cos theta),  rho = p_R - p_T clipped to [0, 1],
//     with the fourth-order polynomials p_T, p_R in cos theta of a clear reference glass
//     (T0 > 0.645) or a bronze one (J. Finlayson, D. Arasteh, C. Huizenga, M. Rubin,
//     M. Reilly, "WINDOW 4.0: Documentation of calculation procedures", LBL-33943, 1993;
//     the same fits are RADIANCE's lib/glazing.cal and window.cal, G. Ward 1993 / 2006, and
//     the EnergyPlus Engineering Reference, "Window Calculation Module"). We divide tau by
//     its value at normal incidence (1.0023 clear, 1.0118 bronze) so that T(0) is exactly the
//     data-sheet T0, and clip tau to >= 0 at grazing incidence.
// Panes combined (the multiple-reflection sum between two layers, outer a and inner b;
// Finlayson et al. 1993, "optical properties of a glazing system"; EnergyPlus Engineering
// Reference, "Glazing System Properties"; the same recursion as ISO 15099:2003):
//     T     = Ta Tb / (1 - Ra_in Rb_out)
//     R_out = Ra_out + Ta^2 Rb_out / (1 - Ra_in Rb_out)
//     R_in  = Rb_in + Tb^2 Ra_in / (1 - Ra_in Rb_out)
// applied from the outside in. Like WINDOW and ISO 15099, panes are combined with their
// polarisation-averaged values (see docs/materials.md for the size of this approximation).
// Gas gaps are non-absorbing and, the glazing being thin, do not displace the beam.
#pragma once

#include <vector>

#include "dayphoton/core/scene_description.h"

namespace dayphoton::engine {

/// Optics of one layer (or of a stack) at one angle, one channel. The transmittance is the
/// same from both sides (reciprocity); the reflectances differ for a coated or mixed stack.
struct LayerOptics {
  double transmittance = 0;
  double outer_reflectance = 0;  ///< for light arriving from the outside (pane 1's side)
  double inner_reflectance = 0;  ///< for light arriving from the inside
};

/// Stack `outer` (nearer the outside) on `inner`, summing the reflections between them.
LayerOptics combine_layers(const LayerOptics& outer, const LayerOptics& inner);

/// A pane ready for evaluation, per RGB channel.
struct ResolvedPane {
  bool coated = false;
  double refractive_index = 1.52;  ///< uncoated
  Vec3 transmissivity{0, 0, 0};    ///< uncoated: per-pass transmissivity at normal incidence
  Vec3 transmittance{0, 0, 0};     ///< coated: normal-incidence values
  Vec3 outer_reflectance{0, 0, 0}, inner_reflectance{0, 0, 0};
};

/// Check and resolve the panes of a glazing (uncoated: the per-pass transmissivity from the
/// normal transmittance, as for glass, or exp(-K d)). Throws std::invalid_argument naming
/// the pane (1-based) for an empty stack, values out of range, a transmittance no pane of
/// its index reaches, or a coated pane with T0 + R0 > 1 on a face.
std::vector<ResolvedPane> resolve_panes(const std::vector<GlazingPaneSpec>& panes);

/// One pane at incidence cosine `cos_incident` (absolute value used), channel 0..2.
LayerOptics pane_optics(const ResolvedPane& pane, double cos_incident, int channel);

/// The coated-pane angular fit (above) for one channel.
LayerOptics coated_pane_optics(double normal_transmittance, double outer_reflectance,
                               double inner_reflectance, double cos_incident);

/// The whole stack at incidence cosine `cos_incident`, channel 0..2.
LayerOptics glazing_optics(const std::vector<ResolvedPane>& panes, double cos_incident, int channel);

/// True when the three channels of every pane are equal (a grey glazing: one evaluation
/// serves all channels).
bool is_grey(const std::vector<ResolvedPane>& panes);

}  // namespace dayphoton::engine
