// The material registry's list (material_registry.h): one line per model.
#include "dayphoton/engine/material_registry.h"

#include <stdexcept>

#include "builtin_materials.h"

namespace dayphoton::engine {
namespace {

MaterialModelEntry builtin(MaterialType type, std::shared_ptr<const MaterialModel> (*make)(const MaterialSpec&),
                           bool takes_transmittance_factor = false) {
  MaterialModelEntry e;
  e.type_name = material_type_name(type);
  e.make = make;
  e.takes_transmittance_factor = takes_transmittance_factor;
  return e;
}

}  // namespace

// Entry functions of the models added after the built-ins, each defined in its own file
// (engine/src/<model>_material.cpp). One declaration here, one line in the list below.
MaterialModelEntry bsdf_material_entry();

const std::vector<MaterialModelEntry>& material_models() {
  static const std::vector<MaterialModelEntry> models = {
      builtin(MaterialType::Lambertian, &make_layered_material),
      builtin(MaterialType::Metal, &make_layered_material),
      builtin(MaterialType::Mirror, &make_layered_material),
      builtin(MaterialType::Glass, &make_glass_material, true),
      builtin(MaterialType::Dielectric, &make_dielectric_material),
      builtin(MaterialType::Translucent, &make_layered_material),
      builtin(MaterialType::Opening, &make_opening_material, true),
      builtin(MaterialType::Glazing, &make_glazing_material, true),
      // Registered models, one line each:
      bsdf_material_entry(),
  };
  return models;
}

const MaterialModelEntry* find_material_model(const std::string& type_name) {
  for (const MaterialModelEntry& e : material_models())
    if (e.type_name == type_name) return &e;
  return nullptr;
}

const MaterialModelEntry& material_model_of(const MaterialSpec& spec) {
  const std::string name = spec.type == MaterialType::Registered ? spec.model : material_type_name(spec.type);
  const MaterialModelEntry* e = find_material_model(name);
  if (!e || (spec.type == MaterialType::Registered && !e->parse))
    throw std::invalid_argument("material '" + spec.name + "': unknown material type '" + name + "'");
  return *e;
}

}  // namespace dayphoton::engine
