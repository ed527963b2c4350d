// SystemSpec and RoofLightSpec helpers (project.h): the project-file names of a system's
// type and port mode, and the location of keys, used by the generators' located messages.
#include <string>
#include <type_traits>
#include <variant>

#include "dayphoton/project/project.h"

namespace dayphoton::project {

const char* SystemSpec::type_name() const {
  return std::visit(
      [](const auto& p) -> const char* {
        using T = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<T, LightShelfSpec>) return "light_shelf";
        else if constexpr (std::is_same_v<T, BlindsSpec>) return "blinds";
        else if constexpr (std::is_same_v<T, PrismaticPanelSpec>) return "prismatic_panel";
        else if constexpr (std::is_same_v<T, LamellaPanelSpec>) return "lamella_panel";
        else if constexpr (std::is_same_v<T, CpcSpec>) return "cpc";
        else if constexpr (std::is_same_v<T, LightPipeSpec>) return "light_pipe";
        else if constexpr (std::is_same_v<T, OverhangSpec>) return "overhang";
        else return "fins";
      },
      params);
}

SourceLocation SystemSpec::location_of(const std::string& key) const {
  for (const auto& [k, loc] : key_locations)
    if (k == key) return loc;
  return location;
}

SourceLocation RoofLightSpec::location_of(const std::string& key) const {
  for (const auto& [k, loc] : key_locations)
    if (k == key) return loc;
  return location;
}

std::string describe_system_light(const SystemSpec& system) {
  std::string s = std::string(system.type_name()) + " '" + system.name + "'";
  if (!system.enabled) return s + ": disabled (absent from the scene)";
  if (std::holds_alternative<LightPipeSpec>(system.params))
    return s + ": traced from its collector (a photon port) down the tube";
  const std::string window = " window '" + system.mount.window + "'";
  if (system.mount.side == MountSide::Interior) return s + " inside" + window + ": traced in the room";
  s += " outside" + window + ", port: " + port_mode_name(system.mount.port) + ": ";
  switch (system.mount.port) {
    case PortMode::System:
      return s + "what it reflects and transmits toward the window is traced (its surfaces are outdoor scatterers)";
    case PortMode::Window:
      return s + "SHADING ONLY, an approximation: the light it reflects toward the window is not traced";
    case PortMode::Enclosure:
      return s + "traced through an invisible box of openings around it and its window";
  }
  return s;
}

const char* port_mode_name(PortMode mode) {
  switch (mode) {
    case PortMode::System: return "system";
    case PortMode::Window: return "window";
    case PortMode::Enclosure: return "enclosure";
  }
  return "system";
}

}  // namespace dayphoton::project
