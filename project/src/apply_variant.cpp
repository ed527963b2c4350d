// apply_variant: a study variant's Project from the base Project. A variant swaps material
// definitions and daylight-system definitions (e.g. a blind's slat angle, or `enabled:
// false` for blinds raised), leaves out polygons, boxes, meshes, systems and windows, and
// adds new ones; rooms, sensors and settings stay those of the base, so the pipeline builds
// each variant's scene with the same build_scene_description() and can reuse everything
// that does not depend on the scene (sky matrices, sensor grids). The loader has checked
// the variant against the base (variant_checks.h); the throws here only guard hand-made
// variants.
#include <algorithm>
#include <stdexcept>

#include "dayphoton/project/project.h"

namespace dayphoton::project {

bool VariantRemovals::empty() const {
  return polygons.empty() && boxes.empty() && meshes.empty() && systems.empty() && windows.empty();
}

bool VariantAdditions::empty() const {
  return polygons.empty() && boxes.empty() && meshes.empty() && systems.empty() && windows.empty();
}

namespace {

/// Leave out of `items` every element named in `names`; each must be there.
template <typename Spec>
void remove_named(std::vector<Spec>& items, const std::vector<Located<std::string>>& names,
                  const std::string& kind, const std::string& variant) {
  for (const Located<std::string>& name : names) {
    const auto it = std::find_if(items.begin(), items.end(), [&](const Spec& s) { return s.name == name.value; });
    if (it == items.end())
      throw std::invalid_argument("variant '" + variant + "' removes " + kind + " '" + name.value +
                                  "', which the project does not define");
    items.erase(it);
  }
}

template <typename Spec>
void append(std::vector<Spec>& items, const std::vector<Spec>& added) {
  items.insert(items.end(), added.begin(), added.end());
}

}  // namespace

Project apply_variant(const Project& base, const VariantSpec& variant) {
  Project result = base;
  for (const MaterialSpec& replacement : variant.materials) {
    bool found = false;
    // Replace in place: material indices in the scene stay the same for every variant.
    for (MaterialSpec& m : result.materials)
      if (m.name == replacement.name) {
        m = replacement;
        found = true;
        break;
      }
    if (!found)
      throw std::invalid_argument("variant '" + variant.name + "' replaces material '" +
                                  replacement.name + "', which the project does not define");
  }
  for (const SystemSpec& replacement : variant.systems) {
    bool found = false;
    for (SystemSpec& s : result.geometry.systems)
      if (s.name == replacement.name) {
        s = replacement;
        found = true;
        break;
      }
    if (!found)
      throw std::invalid_argument("variant '" + variant.name + "' replaces system '" +
                                  replacement.name + "', which the project does not define");
  }

  Geometry& g = result.geometry;
  const VariantRemovals& removed = variant.remove;
  remove_named(g.polygons, removed.polygons, "polygon", variant.name);
  remove_named(g.boxes, removed.boxes, "box", variant.name);
  remove_named(g.meshes, removed.meshes, "mesh", variant.name);
  remove_named(g.systems, removed.systems, "system", variant.name);
  for (const Located<std::string>& window : removed.windows) {
    bool found = false;
    for (RoomSpec& room : g.rooms) {
      const auto it = std::find_if(room.windows.begin(), room.windows.end(),
                                   [&](const WindowSpec& w) { return w.name == window.value; });
      if (it == room.windows.end()) continue;
      room.windows.erase(it);
      found = true;
      break;
    }
    if (!found)
      throw std::invalid_argument("variant '" + variant.name + "' removes window '" + window.value +
                                  "', which the project does not define");
  }

  const VariantAdditions& added = variant.add;
  append(g.polygons, added.polygons);
  append(g.boxes, added.boxes);
  append(g.meshes, added.meshes);
  append(g.systems, added.systems);
  for (const AddedWindow& window : added.windows) {
    const auto room = std::find_if(g.rooms.begin(), g.rooms.end(),
                                   [&](const RoomSpec& r) { return r.name == window.room.value; });
    if (room == g.rooms.end())
      throw std::invalid_argument("variant '" + variant.name + "' adds window '" + window.window.name +
                                  "' to room '" + window.room.value + "', which the project does not define");
    room->windows.push_back(window.window);
  }
  return result;
}

std::vector<std::string> variant_changes(const VariantSpec& variant) {
  std::vector<std::string> changes;
  for (const MaterialSpec& m : variant.materials) changes.push_back("material " + m.name + " replaced");
  for (const SystemSpec& s : variant.systems) changes.push_back("system " + s.name + " changed");
  const VariantRemovals& r = variant.remove;
  for (const auto& [kind, names] : {std::pair{"polygon", &r.polygons}, {"box", &r.boxes}, {"mesh", &r.meshes},
                                    {"system", &r.systems}, {"window", &r.windows}})
    for (const Located<std::string>& name : *names) changes.push_back(std::string(kind) + " " + name.value + " removed");
  const VariantAdditions& a = variant.add;
  for (const PolygonSpec& p : a.polygons) changes.push_back("polygon " + p.name + " added");
  for (const BoxSpec& b : a.boxes) changes.push_back("box " + b.name + " added");
  for (const MeshSpec& m : a.meshes) changes.push_back("mesh " + m.name + " added");
  for (const SystemSpec& s : a.systems) changes.push_back("system " + s.name + " added");
  for (const AddedWindow& w : a.windows)
    changes.push_back("window " + w.window.name + " added to room " + w.room.value);
  return changes;
}

}  // namespace dayphoton::project
