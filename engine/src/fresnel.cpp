// Fresnel equations for a smooth dielectric interface; see fresnel.h for sources.
#include "fresnel.h"

#include <algorithm>
#include <cmath>

namespace dayphoton::engine {

double refracted_cosine(double cos_incident_in, double relative_index) {
  const double cos_i = std::clamp(cos_incident_in, 0.0, 1.0);
  // Snell: sin_t = sin_i / eta.
  const double sin2_t = (1.0 - cos_i * cos_i) / (relative_index * relative_index);
  if (sin2_t >= 1.0) return -1.0;
  return std::sqrt(1.0 - sin2_t);
}

FresnelReflectance fresnel_dielectric(double cos_incident_in, double relative_index) {
  return fresnel_dielectric(cos_incident_in, relative_index, refracted_cosine(cos_incident_in, relative_index));
}

FresnelReflectance fresnel_dielectric(double cos_incident_in, double relative_index, double cos_transmitted) {
  const double cos_i = std::clamp(cos_incident_in, 0.0, 1.0);
  const double cos_t = cos_transmitted;
  if (cos_t < 0) return {1.0, 1.0};
  const double eta = relative_index;
  // Amplitude ratios (Born & Wolf eqs. 1.5 (21a), (21b) in cosine form); at cos_i = 0 both
  // are -1 / +1 in magnitude, i.e. grazing light is totally reflected.
  const double r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const double r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return {r_s * r_s, r_p * r_p};
}

}  // namespace dayphoton::engine
