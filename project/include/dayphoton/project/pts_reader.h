// Sensor point files (.pts): one sensor per line, "x y z nx ny nz" in metres and direction
// components, separated by blanks, as RADIANCE's rtrace -I / rcontrib -I read them
// (see ../shared/refdata/sensors/README.md). Blank lines and '#' comments are allowed.
// Normals are normalised; a zero or non-finite value is a located error
// "file.pts:LINE:COL: error: ...".
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/resource_limits.h"
#include "dayphoton/core/scene_description.h"

namespace dayphoton::project {

/// Read every sensor of `path` (also the name printed in messages); problems go to `diag`.
/// If the file cannot be opened (or is not a regular file) the error is placed at
/// `referenced_from` when known. More than `max_points` sensors is an error at the line
/// of the first one too many (limits.sensors_per_grid). A file giving several errors is not
/// read further (a wrongly named file is not echoed line by line).
std::vector<SensorPoint> read_pts(const std::string& path, Diagnostics& diag,
                                  const SourceLocation& referenced_from = {},
                                  std::uint64_t max_points = ResourceLimits{}.sensors_per_grid);

/// Same, from text in memory; `path` is used in messages.
std::vector<SensorPoint> read_pts_from_string(const std::string& text, const std::string& path,
                                              Diagnostics& diag);

}  // namespace dayphoton::project
