// check_variant: see variant_checks.h.
#include "variant_checks.h"

#include <algorithm>
#include <map>
#include <set>
#include <variant>

#include "dayphoton/core/diagnostics.h"

namespace dayphoton::project {

namespace {

template <typename Spec>
std::vector<std::string> names_of(const std::vector<Spec>& items) {
  std::vector<std::string> names;
  for (const Spec& s : items) names.push_back(s.name);
  return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool removes(const std::vector<Located<std::string>>& removed, const std::string& name) {
  return std::any_of(removed.begin(), removed.end(), [&](const Located<std::string>& r) { return r.value == name; });
}

std::string with_hint(std::string message, const std::string& name, const std::vector<std::string>& known) {
  const std::string hint = closest_match(name, known);
  if (!hint.empty()) message += " (did you mean '" + hint + "'?)";
  return message;
}

class VariantChecker {
 public:
  VariantChecker(const Project& base, const VariantSpec& variant, Reporter& reporter)
      : m_base(base), m_variant(variant), m_reporter(reporter), m_quoted("variant '" + variant.name + "'") {}

  /// Removals and additions of one kind.
  void check_kind(const std::string& kind, const std::vector<std::string>& base_names,
                  const std::vector<Located<std::string>>& removed, const std::vector<Located<std::string>>& added) {
    std::map<std::string, int> first_line;
    for (const Located<std::string>& r : removed) {
      if (!contains(base_names, r.value)) {
        m_reporter.error(r.location, with_hint(m_quoted + " removes " + kind + " '" + r.value +
                                                   "', which the project does not have",
                                               r.value, base_names));
        continue;
      }
      const auto [it, first] = first_line.emplace(r.value, r.location.line);
      if (!first)
        m_reporter.error(r.location, m_quoted + " removes " + kind + " '" + r.value + "' twice (first at line " +
                                         std::to_string(it->second) + ")");
    }
    for (const Located<std::string>& a : added)
      if (contains(base_names, a.value) && !removes(removed, a.value))
        m_reporter.error(a.location, m_quoted + " adds " + kind + " '" + a.value +
                                         "', which the project already has (to replace it, remove it in the "
                                         "same variant)");
  }

  /// A system both changed and removed.
  void check_changed_and_removed() {
    for (const Located<std::string>& r : m_variant.remove.systems)
      for (const SystemSpec& s : m_variant.systems)
        if (s.name == r.value)
          m_reporter.error(r.location, m_quoted + " both changes (under 'systems') and removes system '" + r.value + "'");
  }

  /// Every system of the variant is mounted on one of its windows.
  void check_mounts() {
    std::vector<std::string> windows;  // the variant's: the base's less the removed, plus the added
    for (const RoomSpec& room : m_base.geometry.rooms)
      for (const WindowSpec& w : room.windows)
        if (!removes(m_variant.remove.windows, w.name)) windows.push_back(w.name);
    for (const AddedWindow& a : m_variant.add.windows) windows.push_back(a.window.name);

    for (const SystemSpec& base : m_base.geometry.systems) {
      if (removes(m_variant.remove.systems, base.name)) continue;
      const SystemSpec* own = &base;
      for (const SystemSpec& changed : m_variant.systems)
        if (changed.name == base.name) own = &changed;
      // The variant's own `window` only if it changed it; else the base's mount.
      check_mount(*own, windows, own != &base && own->mount.window != base.mount.window);
    }
    for (const SystemSpec& s : m_variant.add.systems) check_mount(s, windows, true);
  }

  /// Windows removed or added in a wall a wall grid covers.
  void check_wall_grids(const std::vector<Located<std::string>>& added_windows) {
    auto check = [&](const std::string& room, Wall wall, const std::string& window, const SourceLocation& at,
                     const char* verb) {
      for (const GridSpec& g : m_base.sensors.grids)
        if (g.wall && g.wall->room == room && room_surface_name(g.wall->surface) == std::string(wall_name(wall)))
          m_reporter.error(at, m_quoted + " " + verb + " window '" + window + "' in the " + wall_name(wall) +
                                   " wall of room '" + room + "', which grid '" + g.name + "' (line " +
                                   std::to_string(g.location.line) +
                                   ") covers: the grid leaves windows out, so its sensors would change, and "
                                   "every case has the base's sensors");
    };
    for (const Located<std::string>& r : m_variant.remove.windows)
      for (const RoomSpec& room : m_base.geometry.rooms)
        for (const WindowSpec& w : room.windows)
          if (w.name == r.value) check(room.name, w.wall, w.name, r.location, "removes");
    for (const AddedWindow& a : m_variant.add.windows) {
      SourceLocation at = a.window.location;  // its name's, if it has one
      for (const Located<std::string>& name : added_windows)
        if (name.value == a.window.name) at = name.location;
      check(a.room.value, a.window.wall, a.window.name, at, "adds");
    }
  }

 private:
  /// `own_window`: the system's `window` was written in the variant (else it is the base's).
  void check_mount(const SystemSpec& s, const std::vector<std::string>& windows, bool own_window) {
    if (std::holds_alternative<LightPipeSpec>(s.params) || s.mount.window.empty()) return;
    if (contains(windows, s.mount.window)) return;
    for (const Located<std::string>& r : m_variant.remove.windows)
      if (r.value == s.mount.window) {
        if (own_window)
          m_reporter.error(s.location_of("window"), "system '" + s.name + "' of " + m_quoted +
                                                        " is mounted on window '" + s.mount.window +
                                                        "', which the variant removes");
        else
          m_reporter.error(r.location, m_quoted + " removes window '" + r.value + "', on which system '" + s.name +
                                           "' (line " + std::to_string(s.location.line) +
                                           ") is mounted: remove the system too");
        return;
      }
    // A base system's unknown window is reported with the base.
    if (own_window)
      m_reporter.error(s.location_of("window"),
                       with_hint("unknown window '" + s.mount.window + "' in " + m_quoted, s.mount.window, windows));
  }

  const Project& m_base;
  const VariantSpec& m_variant;
  Reporter& m_reporter;
  const std::string m_quoted;
};

}  // namespace

void check_variant(const Project& base, const VariantSpec& variant, const AddedNames& added,
                   Reporter& reporter) {
  VariantChecker c(base, variant, reporter);
  const Geometry& g = base.geometry;
  std::vector<std::string> windows;
  for (const RoomSpec& room : g.rooms)
    for (const WindowSpec& w : room.windows) windows.push_back(w.name);
  c.check_kind("polygon", names_of(g.polygons), variant.remove.polygons, added.polygons);
  c.check_kind("box", names_of(g.boxes), variant.remove.boxes, added.boxes);
  c.check_kind("mesh", names_of(g.meshes), variant.remove.meshes, added.meshes);
  c.check_kind("system", names_of(g.systems), variant.remove.systems, added.systems);
  c.check_kind("window", windows, variant.remove.windows, added.windows);
  c.check_changed_and_removed();
  c.check_mounts();
  c.check_wall_grids(added.windows);
}

}  // namespace dayphoton::project
