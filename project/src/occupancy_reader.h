// Reading `metrics.occupancy` (docs/metrics.md, "Occupancy schedules"; schema section
// "occupancy"): hours per kind of day, holidays, weekday of 1 January, daylight saving time,
// or a CSV file read here, every problem located in the project or in the CSV.
#pragma once

#include <string>

#include "dayphoton/project/project.h"
#include "yaml_document.h"

namespace dayphoton::project {

/// Fill `out` from the map `node`; paths are relative to `project_directory`. Errors go to
/// `reporter`; returns false if there were any.
bool read_occupancy(const YamlNode& node, const std::string& project_directory, Reporter& reporter,
                    OccupancySpec& out);

}  // namespace dayphoton::project
