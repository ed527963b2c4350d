// Per-grid CSV result files (DESIGN.md section 6): one header row, the columns
// index,x,y,z first, value columns named with their unit. Written atomically
// (core/atomic_file.h); number formats are fixed so that files are byte-identical across
// runs and platforms (std::to_chars, no locale).
#include "dayphoton/study/result_files.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"

namespace dayphoton::study {

namespace {

/// `v` with `decimals` digits after the point.
std::string fixed(double v, int decimals) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, decimals);
  std::string s(buffer, r.ptr);
  if (s.find_first_not_of("-0.") == std::string::npos) s = decimals > 0 ? "0." + std::string(decimals, '0') : "0";
  return s;  // no "-0.000"
}

/// Coordinates: micrometre resolution, trailing zeros dropped ("2.4", "0.8", "-1").
std::string coordinate(double v) {
  std::string s = fixed(v, 6);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

/// A threshold in a column name: shortest form ("300", "250.5").
std::string threshold_name(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

std::string index_xyz(std::size_t i, const SensorPoint& p) {
  return std::to_string(i) + ',' + coordinate(p.position.x) + ',' + coordinate(p.position.y) + ',' +
         coordinate(p.position.z);
}

void check_count(std::size_t sensors, std::size_t values, const std::string& path) {
  if (sensors != values)
    throw std::invalid_argument(path + ": " + std::to_string(sensors) + " sensors but " + std::to_string(values) +
                                " values");
}

}  // namespace

void write_sensors_csv(const std::vector<SensorPoint>& sensors, const std::vector<double>& area_m2,
                       const std::string& path) {
  if (!area_m2.empty()) check_count(sensors.size(), area_m2.size(), path);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "index,x,y,z,nx,ny,nz" << (area_m2.empty() ? "" : ",area_m2") << '\n';
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      out << index_xyz(i, sensors[i]) << ',' << coordinate(sensors[i].normal.x) << ','
          << coordinate(sensors[i].normal.y) << ',' << coordinate(sensors[i].normal.z);
      // The shortest text that reads back as the same double: `annual` weighs with the
      // run's very areas (threshold_name's form).
      if (!area_m2.empty()) out << ',' << threshold_name(area_m2[i]);
      out << '\n';
    }
  });
}

std::vector<SensorPoint> read_sensors_csv(const std::string& path, std::vector<double>* area_m2) {
  std::ifstream in = open_input_file(path, "sensor file");
  const std::string expected_header = "index,x,y,z,nx,ny,nz";
  const std::string with_areas = expected_header + ",area_m2";
  std::string line;
  if (!std::getline(in, line)) throw InputError(SourceLocation{path, 1, 0}, "empty file, expected the header '" + expected_header + "'");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line != expected_header && line != with_areas)
    throw InputError(SourceLocation{path, 1, 1}, "expected the header '" + expected_header + "' or '" + with_areas + "'",
                     line);
  const std::size_t n_fields = line == with_areas ? 8 : 7;
  std::vector<SensorPoint> sensors;
  std::vector<double> areas;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::istringstream split(line);
    std::string field;
    while (std::getline(split, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    if (fields.size() != n_fields)
      throw InputError(SourceLocation{path, line_number, 0},
                       "expected " + std::to_string(n_fields) + " fields, found " + std::to_string(fields.size()), line);
    double v[8];
    for (std::size_t f = 0; f < n_fields; ++f) {
      char* end = nullptr;
      v[f] = std::strtod(fields[f].c_str(), &end);
      if (fields[f].empty() || *end != '\0' || !std::isfinite(v[f]))
        throw InputError(SourceLocation{path, line_number, static_cast<int>(f) + 1},
                         "field " + std::to_string(f + 1) + " is not a finite number: '" + fields[f] + "'", line);
    }
    if (v[0] != static_cast<double>(sensors.size()))
      throw InputError(SourceLocation{path, line_number, 1},
                       "index " + fields[0] + " out of sequence, expected " + std::to_string(sensors.size()), line);
    if (n_fields == 8 && !(v[7] >= 0))
      throw InputError(SourceLocation{path, line_number, 8}, "area_m2 is negative: '" + fields[7] + "'", line);
    sensors.push_back(SensorPoint{Vec3{v[1], v[2], v[3]}, Vec3{v[4], v[5], v[6]}});
    if (n_fields == 8) areas.push_back(v[7]);
  }
  if (area_m2) *area_m2 = std::move(areas);
  return sensors;
}

void write_daylight_factor_csv(const std::vector<SensorPoint>& sensors, const std::vector<double>& df_percent,
                               const std::string& path, const std::vector<double>& stderr_percent) {
  check_count(sensors.size(), df_percent.size(), path);
  const bool with_stderr = !stderr_percent.empty();
  if (with_stderr) check_count(sensors.size(), stderr_percent.size(), path);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "index,x,y,z,df_percent" << (with_stderr ? ",df_stderr_percent" : "") << '\n';
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      out << index_xyz(i, sensors[i]) << ',' << fixed(df_percent[i], 4);
      if (with_stderr) out << ',' << fixed(stderr_percent[i], 4);
      out << '\n';
    }
  });
}

void write_point_in_time_csv(const std::vector<SensorPoint>& sensors, const std::vector<std::string>& case_names,
                             const metrics::IlluminanceTable& table, const std::string& path,
                             const std::vector<std::vector<double>>& stderr_lux) {
  check_count(sensors.size(), table.sensor_count(), path);
  if (case_names.size() != table.step_count())
    throw std::invalid_argument(path + ": " + std::to_string(case_names.size()) + " case names for " +
                                std::to_string(table.step_count()) + " steps");
  const bool with_stderr = !stderr_lux.empty();
  if (with_stderr) {
    if (stderr_lux.size() != case_names.size())
      throw std::invalid_argument(path + ": " + std::to_string(stderr_lux.size()) + " cases' standard errors for " +
                                  std::to_string(case_names.size()) + " cases");
    for (const std::vector<double>& e : stderr_lux) check_count(sensors.size(), e.size(), path);
  }
  write_file_atomically(path, [&](std::ostream& out) {
    out << "index,x,y,z";
    for (const std::string& name : case_names) {
      out << ',' << name << "_lux";
      if (with_stderr) out << ',' << name << "_stderr_lux";
    }
    out << '\n';
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      out << index_xyz(i, sensors[i]);
      for (std::size_t k = 0; k < case_names.size(); ++k) {
        out << ',' << fixed(table.lux(k, i), 1);
        if (with_stderr) out << ',' << fixed(stderr_lux[k][i], 1);
      }
      out << '\n';
    }
  });
}

std::vector<std::string> metrics_csv_columns(const metrics::MetricSettings& settings, bool with_ase) {
  const std::string x = threshold_name(settings.da_threshold_lux);
  const std::string low = threshold_name(settings.udi_lower_lux);
  const std::string up1 = threshold_name(settings.udi_upper_original_lux);
  const std::string up2 = threshold_name(settings.udi_upper_revised_lux);
  std::vector<std::string> columns = {"index",
                                      "x",
                                      "y",
                                      "z",
                                      "da" + x + "_percent",
                                      "cda" + x + "_percent",
                                      "damax_percent",
                                      "udi_below" + low + "_percent",
                                      "udi" + low + "_" + up1 + "_percent",
                                      "udi_above" + up1 + "_percent",
                                      "udi_supplementary" + low + "_" + x + "_percent",
                                      "udi_autonomous" + x + "_" + up2 + "_percent",
                                      "udi_above" + up2 + "_percent",
                                      "mean_occupied_lux"};
  if (with_ase) columns.push_back("ase_hours");
  return columns;
}

void write_metrics_csv(const std::vector<SensorPoint>& sensors, const std::vector<metrics::SensorMetrics>& metrics,
                       const metrics::MetricSettings& settings, const std::vector<int>& ase_hours,
                       const std::string& path) {
  check_count(sensors.size(), metrics.size(), path);
  if (!ase_hours.empty()) check_count(sensors.size(), ase_hours.size(), path);
  const std::vector<std::string> columns = metrics_csv_columns(settings, !ase_hours.empty());
  write_file_atomically(path, [&](std::ostream& out) {
    for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c];
    out << '\n';
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      const metrics::SensorMetrics& m = metrics[i];
      out << index_xyz(i, sensors[i]);
      for (double v : {m.da_percent, m.cda_percent, m.da_max_percent, m.udi_below_percent, m.udi_original_percent,
                       m.udi_above_original_percent, m.udi_supplementary_percent, m.udi_autonomous_percent,
                       m.udi_above_revised_percent})
        out << ',' << fixed(v, 3);
      out << ',' << fixed(m.mean_occupied_lux, 1);
      if (!ase_hours.empty()) out << ',' << ase_hours[i];
      out << '\n';
    }
  });
}

}  // namespace dayphoton::study
