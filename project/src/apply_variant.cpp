// apply_variant: a study variant's Project from the base Project (issue 5 item 1: variants
// such as alternative glazing or blinds states are first-class). A variant swaps material
// definitions and daylight-system definitions (e.g. a blind's slat angle, or `enabled:
// false` for blinds raised); rooms, sensors and settings stay those of the base, so the
// pipeline builds each variant's scene with the same build_scene_description() and can
// reuse everything that does not depend on them (sky matrices, sensor grids).
// Also the folder-name rule for variant names, which become output folders.
#include <cctype>
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

bool is_portable_folder_name(const std::string& name) {
  // Portable across POSIX and Windows file systems: no separators, no spaces or shell
  // metacharacters, no hidden names (leading '.', also excludes "." and ".."), no name a CLI
  // would take for an option (leading '-'), no trailing '.' (Windows drops it), no Windows
  // device name.
  if (name.empty() || name.size() > 64) return false;
  if (name.front() == '.' || name.front() == '-' || name.back() == '.') return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  // Windows device names are reserved with any extension ("nul", "COM1.txt").
  std::string stem = name.substr(0, name.find('.'));
  for (char& c : stem) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const char* reserved : {"CON", "PRN", "AUX", "NUL"})
    if (stem == reserved) return false;
  if (stem.size() == 4 && (stem.compare(0, 3, "COM") == 0 || stem.compare(0, 3, "LPT") == 0) &&
      stem[3] >= '1' && stem[3] <= '9')
    return false;
  return true;
}

}  // namespace dayphoton::project
