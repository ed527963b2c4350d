// apply_variant: a study variant's Project from the base Project (issue 5 item 1: variants
// such as alternative glazing or blinds states are first-class). A variant swaps material
// definitions and daylight-system definitions (e.g. a blind's slat angle, or `enabled:
// false` for blinds raised); rooms, sensors and settings stay those of the base, so the
// pipeline builds each variant's scene with the same build_scene_description() and can
// reuse everything that does not depend on them (sky matrices, sensor grids).
#include <stdexcept>

#include "dayphoton/project/project.h"

namespace dayphoton::project {

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
  return result;
}

}  // namespace dayphoton::project
