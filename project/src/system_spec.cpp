// SystemSpec and RoofLightSpec helpers (project.h): the project-file names of a system's
// type and port mode, and the location of keys, used by the generators' located messages.
#include <type_traits>

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

const char* port_mode_name(PortMode mode) {
  switch (mode) {
    case PortMode::System: return "system";
    case PortMode::Window: return "window";
    case PortMode::Enclosure: return "enclosure";
  }
  return "system";
}

}  // namespace dayphoton::project
