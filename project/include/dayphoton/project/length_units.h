// Length units of imported files: the names a `units` key takes (the Honeybee schema's
// Model.units names, so one project speaks of units one way) and metres per unit. The foot
// and the inch are the international ones, exact by definition (0.3048 m and 0.0254 m:
// "International Yard and Pound Agreement", 1959; NIST Handbook 44, Appendix C).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace dayphoton::project {

/// The unit names `units` takes, in the order messages list them.
const std::vector<std::string>& length_unit_names();

/// Metres per unit of a `units` name (Meters 1, Millimeters 0.001, Centimeters 0.01,
/// Feet 0.3048, Inches 0.0254); 0 for an unknown name.
double metres_per_length_unit(std::string_view name);

}  // namespace dayphoton::project
