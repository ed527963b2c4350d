// Result images: sensor lattices, grid EXR/PNG, sky fisheyes, tone mapping; see result_images.h.
#include "dayphoton/study/result_images.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/core/units.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/result_tables.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

namespace fs = std::filesystem;

namespace {

SensorLattice one_row(std::size_t n) {
  SensorLattice l;
  l.regular = false;
  l.columns = static_cast<int>(n);
  l.rows = 1;
  for (std::size_t i = 0; i < n; ++i) {
    l.column_of.push_back(static_cast<int>(i));
    l.row_of.push_back(0);
  }
  return l;
}

std::string join(const std::string& dir, const std::string& name) { return (fs::path(dir) / name).string(); }

/// sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1], as an 8-bit code.
std::uint8_t srgb_byte(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(255.0 * e));
}

}  // namespace

SensorLattice sensor_lattice(const std::vector<SensorPoint>& sensors) {
  const std::size_t n = sensors.size();
  if (n < 2) return one_row(n);
  const Vec3 normal = sensors[0].normal;
  if (!(length(normal) > 0.5)) return one_row(n);
  const Vec3 nz = normalize(normal);
  const Vec3 p0 = sensors[0].position;
  for (const SensorPoint& s : sensors)
    if (std::abs(dot(s.position - p0, nz)) > 1e-3) return one_row(n);

  // Spacing: the nearest-neighbour distance of the first sensors (on a lattice every sensor
  // with a neighbour has it at the spacing; 64 of them make a missing-neighbour case moot).
  double best = std::numeric_limits<double>::infinity();
  Vec3 axis;
  const std::size_t probes = std::min<std::size_t>(n, 64);
  for (std::size_t a = 0; a < probes; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b) continue;
      const Vec3 d = sensors[b].position - sensors[a].position;
      const double len = length(d);
      if (len > 1e-9 && len < best) {
        best = len;
        axis = d - nz * dot(d, nz);
      }
    }
  if (!std::isfinite(best) || !(length(axis) > 0)) return one_row(n);
  const double spacing = best;
  const Vec3 a = normalize(axis);
  const Vec3 b = cross(nz, a);
  // Image axes: columns along the lattice axis closest to east, rows toward the south (for
  // vertical grids, downward), so that the picture reads like a plan or an elevation.
  const Vec3 candidates[4] = {a, a * -1.0, b, b * -1.0};
  Vec3 column_axis = candidates[0];
  for (const Vec3& c : candidates)
    if (c.x > column_axis.x + 1e-9) column_axis = c;
  Vec3 row_axis = cross(nz, column_axis);
  const Vec3 down_south{0, -1, -0.5};
  if (dot(row_axis, down_south) < dot(row_axis * -1.0, down_south)) row_axis = row_axis * -1.0;

  std::vector<long long> ci(n), ri(n);
  long long min_c = 0, max_c = 0, min_r = 0, max_r = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = sensors[i].position - p0;
    const double u = dot(d, column_axis) / spacing, v = dot(d, row_axis) / spacing;
    const double ru = std::round(u), rv = std::round(v);
    if (std::abs(u - ru) > 0.01 || std::abs(v - rv) > 0.01) return one_row(n);
    ci[i] = static_cast<long long>(ru);
    ri[i] = static_cast<long long>(rv);
    if (i == 0 || ci[i] < min_c) min_c = ci[i];
    if (i == 0 || ci[i] > max_c) max_c = ci[i];
    if (i == 0 || ri[i] < min_r) min_r = ri[i];
    if (i == 0 || ri[i] > max_r) max_r = ri[i];
  }
  const long long columns = max_c - min_c + 1, rows = max_r - min_r + 1;
  if (columns * rows > 4 * static_cast<long long>(n)) return one_row(n);
  std::vector<char> used(static_cast<std::size_t>(columns * rows), 0);
  SensorLattice l;
  for (std::size_t i = 0; i < n; ++i) {
    const int c = static_cast<int>(ci[i] - min_c), r = static_cast<int>(ri[i] - min_r);
    char& cell = used[static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(c)];
    if (cell) return one_row(n);
    cell = 1;
    l.column_of.push_back(c);
    l.row_of.push_back(r);
  }
  l.regular = true;
  l.columns = static_cast<int>(columns);
  l.rows = static_cast<int>(rows);
  l.spacing_m = spacing;
  l.column_step_m = column_axis * spacing;
  l.row_step_m = row_axis * spacing;
  l.origin_m = p0 + l.column_step_m * static_cast<double>(min_c) + l.row_step_m * static_cast<double>(min_r);
  return l;
}

FloatImage sensor_value_image(const SensorLattice& lattice, const std::vector<double>& values) {
  if (values.size() != lattice.column_of.size())
    throw std::invalid_argument("sensor_value_image: " + std::to_string(values.size()) + " values for " +
                                std::to_string(lattice.column_of.size()) + " sensors");
  FloatImage image(lattice.columns, lattice.rows, {"Y", "A"});
  for (std::size_t i = 0; i < values.size(); ++i) {
    image.at(0, lattice.column_of[i], lattice.row_of[i]) = static_cast<float>(values[i]);
    image.at(1, lattice.column_of[i], lattice.row_of[i]) = 1.0f;
  }
  image.string_attributes["dayphoton:layout"] = lattice.regular ? "lattice" : "sensor order";
  if (lattice.regular) {
    image.vector_attributes["dayphoton:origin_m"] = lattice.origin_m;
    image.vector_attributes["dayphoton:column_step_m"] = lattice.column_step_m;
    image.vector_attributes["dayphoton:row_step_m"] = lattice.row_step_m;
  }
  return image;
}

RgbaImage false_colour_image(const SensorLattice& lattice, const std::vector<double>& values,
                             const ColourScale& scale, int pixels_per_cell) {
  if (values.size() != lattice.column_of.size())
    throw std::invalid_argument("false_colour_image: value count differs from the sensor count");
  const int k = std::max(1, pixels_per_cell);
  RgbaImage image(lattice.columns * k, lattice.rows * k);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto c = scale.colour(values[i]);
    for (int y = 0; y < k; ++y)
      for (int x = 0; x < k; ++x)
        image.at(lattice.column_of[i] * k + x, lattice.row_of[i] * k + y) = {c[0], c[1], c[2], 255};
  }
  return image;
}

std::vector<GridQuantity> grid_quantities(const std::string& grid_dir) {
  std::vector<GridQuantity> out;
  if (fs::exists(join(grid_dir, "daylight_factor.csv")))
    out.push_back({"daylight_factor", "daylight_factor.csv", "df_percent", "daylight factor", "%",
                   daylight_factor_scale()});
  const std::string metrics = join(grid_dir, "metrics.csv");
  if (fs::exists(metrics)) {
    std::ifstream in(metrics);
    std::string header;
    std::getline(in, header);
    if (!header.empty() && header.back() == '\r') header.pop_back();
    std::vector<std::string> columns;
    std::stringstream ss(header);
    for (std::string c; std::getline(ss, c, ',');) columns.push_back(c);
    auto starts_digit = [](const std::string& s, std::size_t at) {
      return s.size() > at && s[at] >= '0' && s[at] <= '9';
    };
    const std::string percent = "_percent";
    auto stem_of = [&](const std::string& c) { return c.substr(0, c.size() - percent.size()); };
    auto dashed = [](std::string r) {
      std::replace(r.begin(), r.end(), '_', '-');  // "100_2000" -> "100-2000"
      return r;
    };
    auto ends_percent = [&](const std::string& c) {
      return c.size() > percent.size() && c.compare(c.size() - percent.size(), percent.size(), percent) == 0;
    };
    for (const std::string& c : columns)
      if (c.rfind("da", 0) == 0 && starts_digit(c, 2) && ends_percent(c))
        out.push_back({stem_of(c), "metrics.csv", c, "daylight autonomy (" + stem_of(c).substr(2) + " lx)", "%",
                       percent_scale("daylight autonomy")});
    for (const std::string& c : columns)
      if (c.rfind("udi", 0) == 0 && starts_digit(c, 3) && ends_percent(c))
        out.push_back({stem_of(c), "metrics.csv", c, "useful daylight illuminance, achieved (" + dashed(stem_of(c).substr(3)) + " lx)",
                       "%", percent_scale("UDI achieved")});
    for (const std::string& c : columns)
      if (c.rfind("udi_autonomous", 0) == 0 && ends_percent(c))
        out.push_back({stem_of(c), "metrics.csv", c, "useful daylight illuminance, autonomous (" +
                       dashed(stem_of(c).substr(std::string("udi_autonomous").size())) + " lx)", "%",
                       percent_scale("UDI autonomous")});
    for (const std::string& c : columns)
      if (c == "mean_occupied_lux")
        out.push_back({"mean_occupied_illuminance", "metrics.csv", c, "mean illuminance over the occupied hours",
                       "lx", illuminance_scale()});
  }
  // Point-in-time cases: one `<case>_lux` column each (result_files.h), one image each.
  const std::string points = join(grid_dir, "point_in_time.csv");
  if (fs::exists(points)) {
    std::ifstream in(points);
    std::string header;
    std::getline(in, header);
    if (!header.empty() && header.back() == '\r') header.pop_back();
    std::stringstream ss(header);
    const std::string lux = "_lux";
    for (std::string c; std::getline(ss, c, ',');)
      if (c.size() > lux.size() && c.compare(c.size() - lux.size(), lux.size(), lux) == 0) {
        const std::string name = c.substr(0, c.size() - lux.size());
        out.push_back({"point_in_time_" + name, "point_in_time.csv", c, "illuminance at point in time '" + name + "'",
                       "lx", illuminance_scale()});
      }
  }
  return out;
}

std::vector<std::string> write_grid_images(const std::string& grid_dir) {
  std::vector<std::string> written;
  const std::vector<GridQuantity> quantities = grid_quantities(grid_dir);
  if (quantities.empty()) return written;
  const std::vector<SensorPoint> sensors = read_sensors_csv(join(grid_dir, "sensors.csv"));
  const SensorLattice lattice = sensor_lattice(sensors);
  const int pixels_per_cell =
      std::max(1, std::min(std::max(32, (256 + lattice.columns - 1) / std::max(1, lattice.columns)),
                           4096 / std::max(1, std::max(lattice.columns, lattice.rows))));
  std::map<std::string, SensorTable> tables;
  const std::string grid_name = fs::path(grid_dir).lexically_normal().filename().string();
  for (const GridQuantity& q : quantities) {
    auto it = tables.find(q.table);
    if (it == tables.end()) it = tables.emplace(q.table, read_sensor_table(join(grid_dir, q.table))).first;
    const SensorTable& table = it->second;
    if (table.rows.size() != sensors.size())
      throw InputError(SourceLocation{table.path, 0, 0}, std::to_string(table.rows.size()) + " rows but sensors.csv has " +
                                                             std::to_string(sensors.size()) + " sensors");
    const std::vector<double> values = table.values(q.column);
    FloatImage exr = sensor_value_image(lattice, values);
    exr.string_attributes["dayphoton:grid"] = grid_name;
    exr.string_attributes["dayphoton:source"] = q.table + ":" + q.column;
    exr.string_attributes["dayphoton:description"] = q.quantity;
    const std::string exr_path = join(grid_dir, q.stem + ".exr");
    write_exr(exr, q.quantity, q.unit, exr_path);
    written.push_back(exr_path);
    const std::string png_path = join(grid_dir, q.stem + ".png");
    write_png(false_colour_image(lattice, values, q.scale, pixels_per_cell), png_path);
    written.push_back(png_path);
  }
  return written;
}

FloatImage sky_fisheye(const RadianceMatrix& sky_matrix, int column, const sky::PatchBasis& basis, int size) {
  if (sky_matrix.rows() != static_cast<std::size_t>(basis.bin_count()) || sky_matrix.components() != 3)
    throw std::invalid_argument("sky_fisheye: the sky matrix has " + std::to_string(sky_matrix.rows()) +
                                " rows of " + std::to_string(sky_matrix.components()) + " components, the basis " +
                                std::to_string(basis.bin_count()) + " bins of RGB");
  if (column >= static_cast<int>(sky_matrix.columns()) || column < -1 || sky_matrix.columns() == 0)
    throw std::invalid_argument("sky_fisheye: column out of range");
  std::vector<Vec3> bin_value(static_cast<std::size_t>(basis.bin_count()));
  for (std::size_t bin = 0; bin < bin_value.size(); ++bin) {
    Vec3 v;
    if (column >= 0) {
      const auto c = static_cast<std::size_t>(column);
      v = {sky_matrix.at(bin, c, 0), sky_matrix.at(bin, c, 1), sky_matrix.at(bin, c, 2)};
    } else {
      for (std::size_t t = 0; t < sky_matrix.columns(); ++t)
        v += Vec3{sky_matrix.at(bin, t, 0), sky_matrix.at(bin, t, 1), sky_matrix.at(bin, t, 2)};
      v = v / static_cast<double>(sky_matrix.columns());
    }
    bin_value[bin] = v;
  }
  FloatImage image(size, size, {"R", "G", "B", "A"});
  const double half = 0.5 * size;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double dx = (x + 0.5 - half) / half, dy = (half - (y + 0.5)) / half;
      const double r = std::sqrt(dx * dx + dy * dy);
      if (r > 1.0) continue;
      // Equidistant: zenith angle proportional to the radius; north up, east left (seen from below).
      const double zenith = r * 0.5 * Pi;
      const double azimuth = std::atan2(-dx, dy);  // clockwise from north
      const Vec3 d{std::sin(zenith) * std::sin(azimuth), std::sin(zenith) * std::cos(azimuth), std::cos(zenith)};
      const Vec3 v = bin_value[static_cast<std::size_t>(basis.find_bin(d))];
      image.at(0, x, y) = static_cast<float>(v.x);
      image.at(1, x, y) = static_cast<float>(v.y);
      image.at(2, x, y) = static_cast<float>(v.z);
      image.at(3, x, y) = 1.0f;
    }
  image.string_attributes["dayphoton:projection"] =
      "angular fisheye of the upper hemisphere, zenith at the centre, north up, east left (seen from below)";
  image.string_attributes["dayphoton:luminance"] = "179 * (0.265 R + 0.670 G + 0.065 B) cd/m2";
  return image;
}

RgbaImage luminance_false_colour(const FloatImage& rgb, const ColourScale& scale) {
  const int a = rgb.channel("A");
  RgbaImage out(rgb.width, rgb.height);
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x) {
      if (a >= 0 && rgb.at(static_cast<std::size_t>(a), x, y) <= 0) continue;
      const double l = rgb_to_photometric({rgb.at(0, x, y), rgb.at(1, x, y), rgb.at(2, x, y)});
      const auto c = scale.colour(l);
      out.at(x, y) = {c[0], c[1], c[2], 255};
    }
  return out;
}

RgbaImage tone_map(const FloatImage& rgb) {
  const int r = rgb.channel("R"), g = rgb.channel("G"), b = rgb.channel("B"), alpha = rgb.channel("A");
  if (r < 0 || g < 0 || b < 0) throw std::invalid_argument("tone_map: the image needs R, G and B channels");
  auto pixel = [&](int x, int y) {
    return Vec3{rgb.at(static_cast<std::size_t>(r), x, y), rgb.at(static_cast<std::size_t>(g), x, y),
                rgb.at(static_cast<std::size_t>(b), x, y)};
  };
  auto valid = [&](int x, int y, double& luminance) {
    if (alpha >= 0 && !(rgb.at(static_cast<std::size_t>(alpha), x, y) > 0)) return false;
    const Vec3 p = pixel(x, y);
    if (!is_finite(p) || p.x < 0 || p.y < 0 || p.z < 0) return false;
    luminance = rgb_to_photometric(p);
    return true;
  };
  // Log-average luminance (Reinhard eq. 1) with delta = 1e-4 cd/m2 against log(0).
  double log_sum = 0;
  std::size_t count = 0;
  std::vector<double> luminances;
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x) {
      double l = 0;
      if (!valid(x, y, l)) continue;
      log_sum += std::log(1e-4 + l);
      luminances.push_back(l);
      ++count;
    }
  RgbaImage out(rgb.width, rgb.height, {0, 0, 0, 255});
  if (count == 0) return out;
  const double log_average = std::exp(log_sum / static_cast<double>(count));
  const double key = 0.18 / log_average;
  std::sort(luminances.begin(), luminances.end());
  // The brightest 0.1 % are let burn out (none in images of fewer than 1000 pixels).
  const std::size_t white_index = luminances.size() - 1 - luminances.size() / 1000;
  const double white = std::max(1e-12, key * luminances[white_index]);
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x) {
      double l = 0;
      if (!valid(x, y, l)) {
        if (alpha >= 0 && !(rgb.at(static_cast<std::size_t>(alpha), x, y) > 0)) out.at(x, y) = {0, 0, 0, 0};
        continue;
      }
      if (l <= 0) continue;
      const double ls = key * l;
      const double ld = ls * (1 + ls / (white * white)) / (1 + ls);
      // Display RGB whose luminance weights give Ld: radiance x 179 x Ld / L.
      const Vec3 d = pixel(x, y) * (RadianceWhiteEfficacy_lm_per_W * ld / l);
      out.at(x, y) = {srgb_byte(d.x), srgb_byte(d.y), srgb_byte(d.z), 255};
    }
  return out;
}

std::string YearHour::text() const {
  std::ostringstream s;
  s << month << '/' << day << '/' << hour;
  return s.str();
}

YearHour parse_year_hour(const std::string& text) {
  YearHour h;
  std::istringstream in(text);
  char s1 = 0, s2 = 0;
  if (!(in >> h.month >> s1 >> h.day >> s2 >> h.hour) || s1 != '/' || s2 != '/' || !in.eof() ||
      h.month < 1 || h.month > 12 || h.day < 1 || h.day > 31 || !(h.hour > 0) || h.hour > 24)
    throw std::invalid_argument("expected M/D/H (month 1-12, day 1-31, hour of local standard time in (0, 24]), not '" +
                                text + "'");
  return h;
}

namespace {

/// A decade-rounded logarithmic luminance scale covering the image's non-zero pixels.
ColourScale luminance_scale_for(const FloatImage& rgb) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  const int a = rgb.channel("A");
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x) {
      if (a >= 0 && rgb.at(static_cast<std::size_t>(a), x, y) <= 0) continue;
      const double l = rgb_to_photometric({rgb.at(0, x, y), rgb.at(1, x, y), rgb.at(2, x, y)});
      if (l > 0) {
        lo = std::min(lo, l);
        hi = std::max(hi, l);
      }
    }
  if (!(hi > 0)) return {1, 10, true, "luminance", "cd/m2"};
  return {std::pow(10.0, std::floor(std::log10(lo))), std::pow(10.0, std::ceil(std::log10(hi) + 1e-12)), true,
          "luminance", "cd/m2"};
}

}  // namespace

std::vector<std::string> write_sky_images(const std::string& results_dir, const YearHour& hour, int size) {
  const std::string summary_path = join(results_dir, "summary.json");
  std::ifstream in = open_input_file(summary_path, "run summary");
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.is_object())
    throw InputError(SourceLocation{summary_path, 0, 0}, "not a JSON object");
  return write_sky_images(results_dir, hour, summary.dump(), summary_path, size);
}

std::vector<std::string> write_sky_images(const std::string& results_dir, const YearHour& hour,
                                          const std::string& summary_text, const std::string& summary_path, int size) {
  nlohmann::json summary = nlohmann::json::parse(summary_text, nullptr, false);
  if (!summary.is_object()) summary = nlohmann::json::object();
  const std::string weather = summary.value("weather", std::string());
  if (weather.empty() || !fs::exists(weather)) return {};
  nlohmann::json sim = summary.value("simulation", nlohmann::json::object());
  if (!sim.is_object()) sim = nlohmann::json::object();
  const double rho = sim.value("ground_reflectance", 0.2);
  const sky::PatchBasis basis = sim.value("basis", std::string("tregenza")) == "reinhart"
                                    ? sky::PatchBasis::reinhart(sim.value("reinhart_mf", 1))
                                    : sky::PatchBasis::tregenza();
  const weather::HourlyWeather series = weather::read_hourly_weather(weather);
  const SunSite site = recorded_or_header_sun_site(summary_text, summary_path, series);
  const AnnualSky sky = annual_sky_from_weather(series, site.solar, basis, radiance_compatible_sky_options(rho));

  // The record whose interval (h - 1, h] holds the hour: mid-hour stamp ceil(H) - 0.5.
  const double stamp = std::ceil(hour.hour - 1e-9) - 0.5;
  int column = -1;
  for (std::size_t t = 0; t < sky.steps.size(); ++t)
    if (sky.steps[t].month == hour.month && sky.steps[t].day == hour.day && std::abs(sky.steps[t].hour - stamp) < 1e-6)
      column = static_cast<int>(t);
  if (column < 0)
    throw InputError(SourceLocation{weather, 0, 0}, "no record for " + hour.text() + " (month/day/hour) in the weather file");

  std::vector<std::string> written;
  const auto write_one = [&](int c, const std::string& stem, const std::string& time) {
    FloatImage image = sky_fisheye(sky.matrix, c, basis, size);
    image.string_attributes["dayphoton:weather"] = weather;
    image.string_attributes["dayphoton:time"] = time;
    image.string_attributes["dayphoton:sky"] = sky.description;
    const std::string exr = join(results_dir, stem + ".exr");
    write_exr(image, "sky radiance", "W/(sr m2)", exr);
    written.push_back(exr);
    const std::string png = join(results_dir, stem + ".png");
    write_png(luminance_false_colour(image, luminance_scale_for(image)), png);
    written.push_back(png);
  };
  write_one(-1, "sky_mean", "mean over all " + std::to_string(sky.steps.size()) + " records of the weather file");
  std::ostringstream time;
  time << hour.month << '/' << hour.day << " record of EPW hour " << static_cast<int>(stamp + 0.5) << " (sky at "
       << stamp << " h local standard time)";
  write_one(column, "sky_hour", time.str());
  return written;
}

}  // namespace dayphoton::study
