// Dielectric interface (RADIANCE dielectric, type `dielectric`): a smooth interface with the
// unpolarised Fresnel reflectance (fresnel.h); delta reflection or refraction by Snell's law.
// Not symmetric: the front side is outside (relative index n), the back side inside (1/n).
// Absorption inside is the tracers' job, through interior_transmittance_per_m().
// docs/materials.md ("Dielectric interface").
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "builtin_materials.h"
#include "fresnel.h"
#include "material_common.h"

namespace dayphoton::engine {
namespace {

using namespace detail;

class DielectricMaterial final : public MaterialModel {
 public:
  explicit DielectricMaterial(const MaterialSpec& spec)
      : m_refractive_index(spec.refractive_index), m_transmittance_per_m(spec.transmittance) {
    check_unit_range(spec, "transmission per metre", spec.transmittance);
    if (!(spec.refractive_index > 0) || !std::isfinite(spec.refractive_index))
      throw std::invalid_argument("material '" + spec.name + "': refractive index " +
                                  std::to_string(spec.refractive_index) + " must be > 0");
  }

  std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3& normal, double u_component, double,
                                      double) const override {
    const double cos_in = dot(incoming, normal);
    const double cos_i = std::fabs(cos_in);
    // Front side (against the normal) is outside, index 1; the back side is inside.
    const bool front = cos_in < 0;
    const double eta = front ? m_refractive_index : 1.0 / m_refractive_index;
    const Vec3 towards_light = front ? normal : -normal;  // unit normal on the incident side
    const double reflectance = fresnel_dielectric(cos_i, eta).unpolarised();
    // Albedo-proportional choice between reflectance R and transmittance 1 - R: both
    // weights are 1 (uncoloured interface; absorption inside is the tracer's job).
    if (u_component < reflectance)
      return ScatterSample{reflect(incoming, normal), Vec3{1, 1, 1}, ScatterType::SpecularReflection, true};
    const double cos_t = refracted_cosine(cos_i, eta);
    const Vec3 refracted = normalize((incoming + towards_light * cos_i) / eta - towards_light * cos_t);
    return ScatterSample{refracted, Vec3{1, 1, 1}, ScatterType::SpecularTransmission, true};
  }
  Vec3 eval(const Vec3&, const Vec3&, const Vec3&) const override { return {0, 0, 0}; }
  double pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0.0; }
  Vec3 albedo(const Vec3&, const Vec3&) const override {
    return {1, 1, 1};  // R + (1 - R): the interface itself loses nothing
  }
  Vec3 interior_transmittance_per_m() const override { return m_transmittance_per_m; }

 private:
  double m_refractive_index;
  Vec3 m_transmittance_per_m;
};

}  // namespace

std::shared_ptr<const MaterialModel> make_dielectric_material(const MaterialSpec& spec) {
  return std::make_shared<DielectricMaterial>(spec);
}

}  // namespace dayphoton::engine
