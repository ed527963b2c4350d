// A small side-lit room with three point-in-time cases, each made of different parts (a weather
// hour with its sun, the CIE overcast sky, a CIE clear sky with a sun), for the point-in-time
// tests (point_in_time_honesty_test.cpp, point_in_time_accuracy_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace dayphoton::test {

/// The office's weather file (Oakland) cut to the one day of the weather case, 12-21 (its DATA
/// PERIODS line says so): the annual sky the case is taken from, and its sub-patch deltas,
/// which a run makes from the weather and does not cache, are then a day's, not a year's.
inline void write_one_day_weather(const std::filesystem::path& to) {
  std::ifstream in(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw");
  ASSERT_TRUE(in);
  std::ofstream out(to);
  std::string line;
  for (int header = 0; header < 8 && std::getline(in, line); ++header)
    out << (line.rfind("DATA PERIODS", 0) == 0 ? "DATA PERIODS,1,1,Data,Monday,12/21,12/21" : line) << '\n';
  while (std::getline(in, line)) {
    const std::size_t year_end = line.find(',');  // year, month, day, hour, ...
    if (year_end != std::string::npos && line.compare(year_end + 1, 6, "12,21,") == 0) out << line << '\n';
  }
}

/// A 4 x 5 x 3 m room with a south window, in Oakland: at 12-21 11:30 (the weather file's hour
/// 12: 740 W/m^2 direct normal) the sun falls through the window onto the work plane.
/// `simulation`: the project's simulation map, e.g. "{photons_per_bin: 300}".
inline std::string point_in_time_room(const std::filesystem::path& weather, const std::string& simulation) {
  return std::string("site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n") +
         "weather: " + weather.string() + "\n" +
         "materials:\n"
         "  floor: {type: lambertian, reflectance: 0.2}\n"
         "  walls: {type: lambertian, reflectance: 0.5}\n"
         "  ceiling: {type: lambertian, reflectance: 0.7}\n"
         "  glazing: {type: glass, transmittance: 0.6}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: room\n"
         "      size: [4, 5, 3]\n"
         "      materials: {floor: floor, ceiling: ceiling, walls: walls}\n"
         "      windows: [{name: win, wall: south, width: 2.4, height: 1.4, sill: 0.9, offset: 0.8, material: glazing}]\n"
         "sensors:\n"
         "  grids: [{name: floor, room: room, height: 0.8, spacing: 0.25, inset: 0.125}]\n"
         "simulation: " + simulation + "\n"
         "outputs: {daylight_factor: true, annual_illuminance: false, metrics: false, coefficients: false,\n"
         "          images: false, report: false}\n"
         "points_in_time:\n"
         "  - {name: weather_sun, date: 12-21, time: \"11:30\", sky: weather}\n"
         "  - {name: overcast, date: 03-21, time: \"12:00\", sky: cie_overcast, diffuse_horizontal_illuminance: 20000}\n"
         "  - {name: clear, date: 06-21, time: \"10:00\", sky: cie, cie_type: 12, diffuse_horizontal_illuminance: 8000,\n"
         "     direct_normal_illuminance: 70000}\n";
}

}  // namespace dayphoton::test
