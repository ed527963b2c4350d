// Glazing system optics; formulas and sources in glazing_system.h.
#include "glazing_system.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "thin_glass_fresnel.h"

namespace dayphoton::engine {
namespace {

// WINDOW 4's coated-glass fits (Finlayson et al. 1993; RADIANCE lib/glazing.cal): fourth-
// order polynomials in cos(theta), coefficients of cos^0 .. cos^4.
constexpr double ClearTransmittanceFit[5] = {-0.0015, 3.355, -3.840, 1.460, 0.0288};
constexpr double ClearReflectanceFit[5] = {0.999, -0.563, 2.043, -2.532, 1.054};
constexpr double BronzeTransmittanceFit[5] = {-0.002, 2.813, -2.341, -0.05725, 0.599};
constexpr double BronzeReflectanceFit[5] = {0.997, -1.868, 6.513, -7.862, 3.225};
// Normal transmittance above which the clear reference glass's fits apply (the same source).
constexpr double ClearFitMinTransmittance = 0.645;

double polynomial(const double (&c)[5], double x) {
  return c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * c[4])));
}

std::string pane_name(std::size_t index) { return "pane " + std::to_string(index + 1); }

void check_unit(const std::string& what, const Vec3& rgb) {
  for (int c = 0; c < 3; ++c)
    if (!(rgb[c] >= 0.0 && rgb[c] <= 1.0))
      throw std::invalid_argument(what + " " + std::to_string(rgb[c]) + " is outside [0, 1]");
}

}  // namespace

LayerOptics combine_layers(const LayerOptics& outer, const LayerOptics& inner) {
  const double denominator = 1.0 - outer.inner_reflectance * inner.outer_reflectance;
  // Two perfect mirrors facing each other (grazing light on non-absorbing panes): nothing
  // passes, and each side sees its own mirror.
  if (!(denominator > 0)) return {0.0, outer.outer_reflectance, inner.inner_reflectance};
  LayerOptics s;
  s.transmittance = outer.transmittance * inner.transmittance / denominator;
  s.outer_reflectance = outer.outer_reflectance +
                        outer.transmittance * outer.transmittance * inner.outer_reflectance / denominator;
  s.inner_reflectance = inner.inner_reflectance +
                        inner.transmittance * inner.transmittance * outer.inner_reflectance / denominator;
  return s;
}

LayerOptics coated_pane_optics(double normal_transmittance, double outer_reflectance,
                               double inner_reflectance, double cos_incident) {
  const double c = std::min(1.0, std::fabs(cos_incident));
  const bool clear = normal_transmittance > ClearFitMinTransmittance;
  const double(&t_fit)[5] = clear ? ClearTransmittanceFit : BronzeTransmittanceFit;
  const double(&r_fit)[5] = clear ? ClearReflectanceFit : BronzeReflectanceFit;
  const double tau = polynomial(t_fit, c);
  const double tau_normalised = std::max(0.0, tau) / polynomial(t_fit, 1.0);
  const double rho = std::clamp(polynomial(r_fit, c) - tau, 0.0, 1.0);
  LayerOptics o;
  o.outer_reflectance = outer_reflectance * (1.0 - rho) + rho;
  o.inner_reflectance = inner_reflectance * (1.0 - rho) + rho;
  // The fits keep T + R <= 1 (docs/materials.md); the cap guards the last rounding.
  o.transmittance = std::min(normal_transmittance * tau_normalised,
                             1.0 - std::max(o.outer_reflectance, o.inner_reflectance));
  o.transmittance = std::max(0.0, o.transmittance);
  return o;
}

std::vector<ResolvedPane> resolve_panes(const std::vector<GlazingPaneSpec>& panes) {
  if (panes.empty()) throw std::invalid_argument("a glazing needs at least one pane");
  std::vector<ResolvedPane> resolved;
  for (std::size_t i = 0; i < panes.size(); ++i) {
    const GlazingPaneSpec& p = panes[i];
    const std::string name = pane_name(i);
    ResolvedPane r;
    switch (p.optics) {
      case GlazingPaneSpec::Optics::Coated:
        r.coated = true;
        check_unit(name + ": coated transmittance", p.transmittance);
        check_unit(name + ": outer-face reflectance", p.outer_reflectance);
        check_unit(name + ": inner-face reflectance", p.inner_reflectance);
        for (int c = 0; c < 3; ++c)
          if (p.transmittance[c] + std::max(p.outer_reflectance[c], p.inner_reflectance[c]) > 1.0 + 1e-12)
            throw std::invalid_argument(name + ": transmittance " + std::to_string(p.transmittance[c]) +
                                        " and face reflectance " +
                                        std::to_string(std::max(p.outer_reflectance[c], p.inner_reflectance[c])) +
                                        " add up to more than 1");
        r.transmittance = p.transmittance;
        r.outer_reflectance = p.outer_reflectance;
        r.inner_reflectance = p.inner_reflectance;
        break;
      case GlazingPaneSpec::Optics::Transmittance:
      case GlazingPaneSpec::Optics::Absorption:
        if (!(p.refractive_index >= 1.0) || !std::isfinite(p.refractive_index))
          throw std::invalid_argument(name + ": refractive index " + std::to_string(p.refractive_index) +
                                      " must be >= 1");
        r.refractive_index = p.refractive_index;
        if (p.optics == GlazingPaneSpec::Optics::Transmittance) {
          check_unit(name + ": transmittance", p.transmittance);
          try {
            for (int c = 0; c < 3; ++c)
              r.transmissivity[c] = glass_transmissivity(p.transmittance[c], p.refractive_index);
          } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(name + ": " + e.what());
          }
        } else {
          if (!(p.thickness_m > 0) || !std::isfinite(p.thickness_m))
            throw std::invalid_argument(name + ": an absorption coefficient needs a thickness > 0");
          for (int c = 0; c < 3; ++c) {
            if (!(p.absorption_per_m[c] >= 0) || !std::isfinite(p.absorption_per_m[c]))
              throw std::invalid_argument(name + ": absorption coefficient " +
                                          std::to_string(p.absorption_per_m[c]) + " must be >= 0");
            // Beer-Lambert over one normal pass through the pane.
            r.transmissivity[c] = std::exp(-p.absorption_per_m[c] * p.thickness_m);
          }
        }
        break;
    }
    resolved.push_back(r);
  }
  return resolved;
}

LayerOptics pane_optics(const ResolvedPane& pane, double cos_incident, int channel) {
  if (pane.coated)
    return coated_pane_optics(pane.transmittance[channel], pane.outer_reflectance[channel],
                              pane.inner_reflectance[channel], cos_incident);
  const ThinGlassResponse g =
      thin_glass_response(cos_incident, pane.refractive_index, pane.transmissivity[channel]);
  return {g.transmittance, g.reflectance, g.reflectance};
}

LayerOptics glazing_optics(const std::vector<ResolvedPane>& panes, double cos_incident, int channel) {
  LayerOptics stack = pane_optics(panes.front(), cos_incident, channel);
  for (std::size_t i = 1; i < panes.size(); ++i)
    stack = combine_layers(stack, pane_optics(panes[i], cos_incident, channel));
  return stack;
}

bool is_grey(const std::vector<ResolvedPane>& panes) {
  auto grey = [](const Vec3& v) { return v.x == v.y && v.y == v.z; };
  for (const ResolvedPane& p : panes)
    if (!grey(p.transmissivity) || !grey(p.transmittance) || !grey(p.outer_reflectance) ||
        !grey(p.inner_reflectance))
      return false;
  return true;
}

}  // namespace dayphoton::engine
