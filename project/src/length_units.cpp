// Length units of imported files (length_units.h).
#include "dayphoton/project/length_units.h"

namespace dayphoton::project {

const std::vector<std::string>& length_unit_names() {
  static const std::vector<std::string> names = {"Meters", "Millimeters", "Centimeters", "Feet", "Inches"};
  return names;
}

double metres_per_length_unit(std::string_view name) {
  if (name == "Meters") return 1.0;
  if (name == "Millimeters") return 0.001;
  if (name == "Centimeters") return 0.01;
  if (name == "Feet") return 0.3048;    // international foot, exact
  if (name == "Inches") return 0.0254;  // international inch, exact
  return 0;
}

}  // namespace dayphoton::project
