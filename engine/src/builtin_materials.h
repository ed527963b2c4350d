// Factories of the built-in scattering models, one per file (engine/src/*_material.cpp),
// listed in material_registry.cpp. Models added later declare their entry function in
// material_registry.cpp instead (material_registry.h).
#pragma once

#include <memory>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/material_model.h"

namespace dayphoton::engine {

/// lambertian (plastic), metal, mirror, translucent: the layered model.
std::shared_ptr<const MaterialModel> make_layered_material(const MaterialSpec& spec);
std::shared_ptr<const MaterialModel> make_glass_material(const MaterialSpec& spec);
std::shared_ptr<const MaterialModel> make_glazing_material(const MaterialSpec& spec);
std::shared_ptr<const MaterialModel> make_dielectric_material(const MaterialSpec& spec);
std::shared_ptr<const MaterialModel> make_opening_material(const MaterialSpec& spec);

}  // namespace dayphoton::engine
