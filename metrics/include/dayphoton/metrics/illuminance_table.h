// IlluminanceTable: illuminance (lux) per time step and sensor, the product of a daylight-
// coefficient matrix and an annual sky matrix. Rows are time steps (EPW records, each
// stamped with its month, day and mid-hour local standard time), columns are sensors.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace dayphoton::metrics {

struct TimeStamp {
  int month = 1;             ///< 1..12
  int day = 1;               ///< 1..31
  double hour = 0.5;         ///< mid-hour local standard time, 0.5 .. 23.5 for hourly EPW data
};

class IlluminanceTable {
 public:
  IlluminanceTable() = default;
  IlluminanceTable(std::vector<TimeStamp> steps, std::size_t sensors)
      : m_steps(std::move(steps)), m_sensors(sensors), m_lux(m_steps.size() * sensors, 0.0f) {}

  std::size_t step_count() const { return m_steps.size(); }
  std::size_t sensor_count() const { return m_sensors; }
  const std::vector<TimeStamp>& steps() const { return m_steps; }

  float& lux(std::size_t step, std::size_t sensor) { return m_lux[step * m_sensors + sensor]; }
  float lux(std::size_t step, std::size_t sensor) const { return m_lux[step * m_sensors + sensor]; }

 private:
  std::vector<TimeStamp> m_steps;
  std::size_t m_sensors = 0;
  std::vector<float> m_lux;  ///< row-major: step outer, sensor inner
};

/// Read a table in dayphoton's annual CSV layout (header "month,day,hour,<one column per
/// sensor>"), which is also the layout of ../shared/refdata's annual results. Located errors.
IlluminanceTable read_illuminance_csv(const std::string& path);

}  // namespace dayphoton::metrics
