// Rules between a variant and its base project that the schema cannot express
// (docs/project-format.md, `variants`), checked by the loader once the whole file is read:
//  - what a variant removes exists in the base, and is removed once; a system is not both
//    changed (under the variant's `systems`) and removed;
//  - what it adds is new: a name the base already uses is an error unless the same variant
//    removes it (remove + add replaces an element);
//  - nothing left depends on what it removes: every system of the variant (kept, changed or
//    added) is mounted on a window the variant has;
//  - the sensors stay the base's: a window removed or added is not in a wall that a wall
//    grid covers (such a grid leaves windows out, so its sensors would change). Every case
//    has the same sensors, so results compare side by side and operated shading can pick
//    each hour's row from one case or the other.
// Rooms cannot be removed or added, so references to rooms (grids, light pipes, added
// windows) are the loader's ordinary checks.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "yaml_document.h"

namespace dayphoton::project {

/// The names of what a variant adds, each where its `name` value was written (the specs keep
/// only where their definition starts).
struct AddedNames {
  std::vector<Located<std::string>> polygons, boxes, meshes, systems, windows;
};

/// Report every broken rule above, located at the offending name (a removal, an added
/// element's name or a system's `window`).
void check_variant(const Project& base, const VariantSpec& variant, const AddedNames& added,
                   Reporter& reporter);

}  // namespace dayphoton::project
