// Thin glass: transmittance and reflectance of a plane-parallel pane (RADIANCE `glass`),
// summing the infinite series of internal reflections for each polarisation.
//
// Model (RADIANCE reference manual, "glass"; G. Ward, "Rendering with Radiance" ch. 4; the
// series goes back to Stokes): with r the single-interface Fresnel reflectance of one
// polarisation (fresnel.h, index n, angle of incidence theta) and d = tn^(1/cos theta_t) the
// fraction surviving one pass through the pane along the refracted direction (tn is the
// per-pass transmissivity at normal incidence, cos theta_t the cosine of the refracted angle
// inside the pane),
//     T_pol = (1 - r)^2 d / (1 - r^2 d^2),
//     R_pol = r + r (1 - r)^2 d^2 / (1 - r^2 d^2) = r (1 + (1 - 2r) d^2) / (1 - r^2 d^2),
// and T, R are the means over s and p. The pane is thin: transmitted light leaves undeviated
// (StraightTransmission), as in RADIANCE.
//
// Convention (docs/materials.md): project files give the NORMAL TRANSMITTANCE Tn that
// glazing data sheets quote; the per-pass transmissivity tn is obtained by solving
// T(normal incidence; tn) = Tn exactly for the pane's index (closed form of the quadratic
// r^2 Tn tn^2 + (1 - r)^2 tn - Tn = 0). For n = 1.52 this is RADIANCE's documented
// conversion tn = (sqrt(0.8402528435 + 0.0072522239 Tn^2) - 0.9166530661) / 0.0036261119 / Tn.
#pragma once

namespace dayphoton::engine {

struct ThinGlassResponse {
  double transmittance = 0;  ///< fraction passing straight through
  double reflectance = 0;    ///< fraction mirror-reflected (both faces, all internal bounces)
};

/// Response of a pane with index `refractive_index` and per-pass normal transmissivity
/// `transmissivity` (tn in [0, 1]) to light arriving with cosine `cos_incident` (either side,
/// absolute value used).
ThinGlassResponse thin_glass_response(double cos_incident, double refractive_index,
                                      double transmissivity);

/// Largest normal transmittance a non-absorbing pane (tn = 1) of this index has:
/// (1 - r0) / (1 + r0) with r0 = ((n - 1) / (n + 1))^2 (0.9183 for n = 1.52).
double max_normal_transmittance(double refractive_index);

/// Per-pass transmissivity tn giving normal transmittance `normal_transmittance` for this
/// index. Throws std::invalid_argument if the transmittance exceeds
/// max_normal_transmittance() (no tn <= 1 reaches it) or is outside [0, 1].
double glass_transmissivity(double normal_transmittance, double refractive_index);

}  // namespace dayphoton::engine
