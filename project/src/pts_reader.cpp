// Sensor point files (.pts), "x y z nx ny nz" per line (format in pts_reader.h; the
// RADIANCE rtrace -I input convention, ../shared/refdata/sensors/README.md).
#include "dayphoton/project/pts_reader.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "dayphoton/core/error_text.h"
#include "dayphoton/core/input_file.h"
#include "text_tokens.h"

namespace dayphoton::project {

namespace {

std::vector<SensorPoint> parse_pts(std::istream& in, const std::string& path, Diagnostics& diag,
                                   std::uint64_t max_points, const std::string& limit_raised_by) {
  std::vector<SensorPoint> points;
  std::string line;
  int line_no = 0;
  const std::size_t errors_before = diag.error_count();
  std::size_t valid_lines = 0;
  while (std::getline(in, line) && !diag.at_cap()) {
    ++line_no;
    if (valid_lines == 0 && diag.error_count() - errors_before >= detail::MaxErrorsBeforeValidLine) {
      diag.error({path, line_no, 0}, "stopping after " + std::to_string(detail::MaxErrorsBeforeValidLine) +
                                         " errors and no valid line: is this a sensor file (x y z nx ny nz per line)?");
      break;
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<detail::Token> tokens = detail::tokenize(line);
    if (tokens.empty()) continue;
    double values[6] = {0, 0, 0, 0, 0, 0};
    bool ok = true;
    for (std::size_t i = 0; i < tokens.size() && i < 6; ++i) {
      const detail::NumberStatus status = detail::parse_number(tokens[i].text, values[i]);
      if (status != detail::NumberStatus::Ok) {
        diag.error({path, line_no, tokens[i].column},
                   status == detail::NumberStatus::NotFinite
                       ? "value is not finite ('" + detail::quoted_token(tokens[i].text) + "')"
                       : "expected a number, found '" + detail::quoted_token(tokens[i].text) + "'",
                   line);
        ok = false;
      }
    }
    if (tokens.size() != 6) {
      const int column = tokens.size() > 6 ? tokens[6].column
                                           : tokens.back().column + static_cast<int>(tokens.back().text.size());
      diag.error({path, line_no, column},
                 "expected 6 values per sensor (x y z nx ny nz), found " + std::to_string(tokens.size()),
                 line);
      continue;
    }
    if (!ok) continue;
    const Vec3 position{values[0], values[1], values[2]};
    const Vec3 direction{values[3], values[4], values[5]};
    const double len = length(direction);
    if (!(len > 1e-12)) {
      diag.error({path, line_no, tokens[3].column}, "sensor direction is zero", line);
      continue;
    }
    if (points.size() == max_points) {
      diag.error({path, line_no, 1}, "this file holds " + over_limit_text(max_points, limit_raised_by, "sensors"));
      break;
    }
    points.push_back({position, direction / len});
    ++valid_lines;
  }
  return points;
}

}  // namespace

std::vector<SensorPoint> read_pts(const std::string& path, Diagnostics& diag,
                                  const SourceLocation& referenced_from, std::uint64_t max_points) {
  // A FIFO or a device would block or stream forever: refuse anything but a regular file.
  std::string why = input_file_problem(path);
  std::ifstream in;
  if (why.empty()) {
    in.open(path, std::ios::binary);
    if (!in) why = std::string("cannot be opened: ") + error_text(errno);
  }
  if (!why.empty()) {
    if (referenced_from.known())
      diag.error(referenced_from, "sensor file '" + path + "' " + why);
    else
      diag.error({path, 0, 0}, "sensor file " + why);
    return {};
  }
  return parse_pts(in, path, diag, max_points, "limits.sensors_per_grid");
}

std::vector<SensorPoint> read_pts_from_string(const std::string& text, const std::string& path,
                                              Diagnostics& diag) {
  std::istringstream in(text);
  return parse_pts(in, path, diag, ResourceLimits{}.sensors_per_grid, "limits.sensors_per_grid");
}

}  // namespace dayphoton::project
