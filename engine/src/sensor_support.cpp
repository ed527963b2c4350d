// Sensor support: see sensor_support.h.
#include "dayphoton/engine/sensor_support.h"

#include <algorithm>
#include <cmath>

namespace dayphoton::engine {

SensorSupport sensor_support(const Scene& scene, const std::vector<Material>& materials,
                             const SensorPoint& sensor) {
  const double len = length(sensor.normal);
  if (!(len > 0) || !is_finite(sensor.normal) || !is_finite(sensor.position)) return SensorSupport::Free;
  const Vec3 n = sensor.normal / len;
  const double probe_m = std::max(SupportProbe_m, 10.0 * scene.ray_epsilon_m());
  const std::optional<Hit> hit = scene.intersect(Ray{sensor.position + n * probe_m, n * -1.0, 0.0, 2.0 * probe_m});
  if (!hit) return SensorSupport::Free;
  const Material& m = materials[static_cast<std::size_t>(hit->material)];
  return m.stores_photons() ? SensorSupport::OnStoringSurface : SensorSupport::OnNonStoringSurface;
}

}  // namespace dayphoton::engine
