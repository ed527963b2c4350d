// Material: the value the tracers hold (material.h). The models are in engine/src/*_material.cpp;
// which one a spec gets is the material registry's business (material_registry.cpp).
#include "dayphoton/engine/material.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "dayphoton/engine/material_registry.h"

namespace dayphoton::engine {

Material Material::from_spec(const MaterialSpec& spec) {
  const MaterialModelEntry& entry = material_model_of(spec);
  std::shared_ptr<const MaterialModel> model = entry.make(spec);
  if (spec.transmittance_factor != 1.0 &&
      (!entry.takes_transmittance_factor || !(spec.transmittance_factor > 0.0 && spec.transmittance_factor <= 1.0)))
    throw std::invalid_argument("material '" + spec.name + "': transmittance factor " +
                                std::to_string(spec.transmittance_factor) +
                                " needs a glass, glazing or opening material and a value in (0, 1]");
  return Material(spec, std::move(model));
}

Material::Material(MaterialSpec spec, std::shared_ptr<const MaterialModel> model)
    : m_spec(std::move(spec)), m_model(std::move(model)) {
  if (!m_model) throw std::invalid_argument("material '" + m_spec.name + "': no scattering model");
  m_stores_photons = m_model->stores_photons();
  const Vec3 t = m_model->interior_transmittance_per_m();
  m_absorbs_inside = t.x != 1.0 || t.y != 1.0 || t.z != 1.0;
}

MaterialType Material::type() const { return m_spec.type; }
const MaterialSpec& Material::spec() const { return m_spec; }

Vec3 Material::eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const {
  return m_model->eval(incoming, outgoing, normal);
}

double Material::pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const {
  return m_model->pdf(incoming, outgoing, normal);
}

Vec3 Material::albedo(const Vec3& incoming, const Vec3& normal) const { return m_model->albedo(incoming, normal); }

Vec3 Material::interior_transmittance_per_m() const { return m_model->interior_transmittance_per_m(); }

Vec3 Material::diffuse_reflectance() const { return m_model->diffuse_reflectance(); }
Vec3 Material::diffuse_transmittance() const { return m_model->diffuse_transmittance(); }

Vec3 diffuse_reflectance(const MaterialSpec& spec) {
  switch (spec.type) {
    case MaterialType::Lambertian:
    case MaterialType::Metal:
    case MaterialType::Translucent: {
      const double t = spec.type == MaterialType::Translucent ? spec.transmissivity : 0.0;
      return spec.reflectance * ((1.0 - spec.specularity) * (1.0 - t));
    }
    default:
      return {0, 0, 0};
  }
}

std::vector<Material> materials_of(const std::vector<MaterialSpec>& specs) {
  std::vector<Material> materials;
  materials.reserve(specs.size());
  for (const MaterialSpec& m : specs) materials.push_back(Material::from_spec(m));
  return materials;
}

Vec3 diffuse_transmittance(const MaterialSpec& spec) {
  if (spec.type != MaterialType::Translucent) return {0, 0, 0};
  return spec.reflectance * ((1.0 - spec.specularity) * spec.transmissivity * (1.0 - spec.transmitted_specular));
}

}  // namespace dayphoton::engine
