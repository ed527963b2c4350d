// Honeybee's generic modifiers and default modifier set (honeybee_modifiers.h).
#include "honeybee_modifiers.h"

#include <stdexcept>

namespace dayphoton::project::detail {

const std::vector<RadianceModifier>& honeybee_generic_modifiers() {
  // honeybee-radiance, lib/data/modifiers/default.mat: plastic arguments are red, green, blue
  // reflectance, specularity, roughness; glass arguments the RGB transmissivities.
  static const std::vector<RadianceModifier> generic = [] {
    auto modifier = [](const char* id, const char* type, std::vector<double> args) {
      RadianceModifier m;
      m.identifier = id;
      m.type = type;
      m.args = std::move(args);
      return m;
    };
    auto plastic = [&](const char* id, double r) { return modifier(id, "plastic", {r, r, r, 0, 0}); };
    auto glass = [&](const char* id, double tn) { return modifier(id, "glass", {tn, tn, tn}); };
    return std::vector<RadianceModifier>{
        plastic("generic_floor_0.20", 0.2),
        plastic("generic_wall_0.50", 0.5),
        plastic("generic_ceiling_0.80", 0.8),
        plastic("generic_opaque_door_0.50", 0.5),
        plastic("generic_interior_shade_0.50", 0.5),
        plastic("generic_exterior_shade_0.35", 0.35),
        plastic("generic_context_0.20", 0.2),
        glass("generic_interior_window_vis_0.88", 0.9584154328610596),
        glass("generic_exterior_window_vis_0.64", 0.6975761815384331),
        glass("air_boundary", 1.0),
    };
  }();
  return generic;
}

namespace {

const std::map<std::string, std::string>& generic_set() {
  static const std::map<std::string, std::string> set = {
      {"wall_set.exterior_modifier", "generic_wall_0.50"},
      {"wall_set.interior_modifier", "generic_wall_0.50"},
      {"floor_set.exterior_modifier", "generic_floor_0.20"},
      {"floor_set.interior_modifier", "generic_floor_0.20"},
      {"roof_ceiling_set.exterior_modifier", "generic_ceiling_0.80"},
      {"roof_ceiling_set.interior_modifier", "generic_ceiling_0.80"},
      {"aperture_set.window_modifier", "generic_exterior_window_vis_0.64"},
      {"aperture_set.skylight_modifier", "generic_exterior_window_vis_0.64"},
      {"aperture_set.operable_modifier", "generic_exterior_window_vis_0.64"},
      {"aperture_set.interior_modifier", "generic_interior_window_vis_0.88"},
      {"door_set.exterior_modifier", "generic_opaque_door_0.50"},
      {"door_set.interior_modifier", "generic_opaque_door_0.50"},
      {"door_set.overhead_modifier", "generic_opaque_door_0.50"},
      {"door_set.exterior_glass_modifier", "generic_exterior_window_vis_0.64"},
      {"door_set.interior_glass_modifier", "generic_interior_window_vis_0.88"},
      {"shade_set.exterior_modifier", "generic_exterior_shade_0.35"},
      {"shade_set.interior_modifier", "generic_interior_shade_0.50"},
      {"air_boundary_modifier", "air_boundary"},
      // honeybee-radiance's GlobalModifierSet: detached shades (context: neighbouring
      // buildings, trees) take generic_context_0.20.
      {"context_modifier", "generic_context_0.20"},
  };
  return set;
}

}  // namespace

const std::vector<std::string>& modifier_set_slots() {
  static const std::vector<std::string> slots = [] {
    std::vector<std::string> s;
    for (const auto& kv : generic_set()) s.push_back(kv.first);
    return s;
  }();
  return slots;
}

const std::string& generic_modifier_for(const std::string& slot) {
  const auto it = generic_set().find(slot);
  if (it == generic_set().end()) throw std::logic_error("no modifier set slot '" + slot + "'");
  return it->second;
}

const std::string& ModifierSet::modifier_for(const std::string& slot) const {
  const auto it = slots.find(slot);
  return it != slots.end() ? it->second : generic_modifier_for(slot);
}

}  // namespace dayphoton::project::detail
