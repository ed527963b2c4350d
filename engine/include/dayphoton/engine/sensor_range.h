// SensorRange: rows [begin, end) of a grid's sensors, so that a block of a grid can be
// estimated alone (a sensor block of an MPI rank, docs/cluster.md "Sensor blocks"). The
// estimators take the whole grid's sensors and a range, and return the range's rows only;
// every random stream of a sensor is indexed by the sensor's index in the WHOLE grid, so the
// rows of a block are bit for bit those rows of the whole grid's result. The default range is
// the whole grid.
#pragma once

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace dayphoton::engine {

struct SensorRange {
  std::size_t begin = 0;
  std::size_t end = std::numeric_limits<std::size_t>::max();  ///< clamped to the grid by within()

  /// The range within a grid of `sensors` sensors: end clamped to `sensors`. Throws
  /// std::invalid_argument when begin > end or begin > sensors.
  SensorRange within(std::size_t sensors) const {
    SensorRange r{begin, end < sensors ? end : sensors};
    if (begin > end || begin > sensors)
      throw std::invalid_argument("sensor range [" + std::to_string(begin) + ", " + std::to_string(end) +
                                  ") is not within a grid of " + std::to_string(sensors) + " sensors");
    return r;
  }
  std::size_t size() const { return end - begin; }
};

}  // namespace dayphoton::engine
