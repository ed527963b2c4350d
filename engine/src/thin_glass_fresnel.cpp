// Thin glass (RADIANCE `glass`) response and the transmittance -> transmissivity conversion;
// formulas and sources in thin_glass_fresnel.h.
#include "thin_glass_fresnel.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "dayphoton/engine/material.h"
#include "fresnel.h"

namespace dayphoton::engine {
namespace {

// One polarisation: interface reflectance r, per-pass survival d.
ThinGlassResponse pane_series(double r, double d) {
  const double denominator = 1.0 - r * r * d * d;
  // r = 1 and d = 1 (grazing light on a non-absorbing pane): everything is reflected at the
  // first face; the series' 0/0 limit is T = 0, R = 1.
  if (!(denominator > 0)) return {0.0, 1.0};
  return {(1.0 - r) * (1.0 - r) * d / denominator,
          r * (1.0 + (1.0 - 2.0 * r) * d * d) / denominator};
}

}  // namespace

ThinGlassResponse thin_glass_response(double cos_incident, double refractive_index,
                                      double transmissivity) {
  const double cos_i = std::fabs(cos_incident);
  // Light entering a denser pane always refracts (no total internal reflection inside a
  // plane-parallel pane), so cos_t >= sqrt(1 - 1/n^2) > 0 for n > 1.
  const double cos_t = refracted_cosine(cos_i, refractive_index);
  const FresnelReflectance r = fresnel_dielectric(cos_i, refractive_index, cos_t);
  const double d = transmissivity > 0 ? std::pow(transmissivity, 1.0 / cos_t) : 0.0;
  const ThinGlassResponse s = pane_series(r.s, d);
  const ThinGlassResponse p = pane_series(r.p, d);
  return {0.5 * (s.transmittance + p.transmittance), 0.5 * (s.reflectance + p.reflectance)};
}

double max_normal_transmittance(double refractive_index) {
  const double r0 = std::pow((refractive_index - 1.0) / (refractive_index + 1.0), 2);
  return (1.0 - r0) / (1.0 + r0);
}

double glass_transmissivity(double normal_transmittance, double refractive_index) {
  const double tn_normal = normal_transmittance;
  if (!(tn_normal >= 0.0 && tn_normal <= 1.0))
    throw std::invalid_argument("glass normal transmittance must be in [0, 1]");
  const double r0 = std::pow((refractive_index - 1.0) / (refractive_index + 1.0), 2);
  const double a = (1.0 - r0) * (1.0 - r0);
  // Root of r0^2 Tn x^2 + a x - Tn = 0 in the rationalised form 2 Tn / (a + sqrt(a^2 +
  // 4 r0^2 Tn^2)): identical to (sqrt(a^2 + 4 r0^2 Tn^2) - a) / (2 r0^2 Tn) but free of
  // cancellation, and correct for Tn = 0 and r0 = 0 (n = 1) as well.
  const double x = 2.0 * tn_normal / (a + std::sqrt(a * a + 4.0 * r0 * r0 * tn_normal * tn_normal));
  if (x > 1.0 + 1e-12) {
    std::ostringstream msg;
    msg << "glass normal transmittance " << tn_normal << " exceeds "
        << max_normal_transmittance(refractive_index)
        << ", the transmittance of a non-absorbing pane with refractive index " << refractive_index
        << " (use an opening for a fully transparent aperture)";
    throw std::invalid_argument(msg.str());
  }
  return x > 1.0 ? 1.0 : x;
}

double radiance_glass_transmissivity(double normal_transmittance) {
  const double t = normal_transmittance;
  if (t == 0) return 0;
  return (std::sqrt(0.8402528435 + 0.0072522239 * t * t) - 0.9166530661) / 0.0036261119 / t;
}

}  // namespace dayphoton::engine
