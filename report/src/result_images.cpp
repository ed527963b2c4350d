// Result images: grid EXR/PNG and sky fisheyes from the results model; see result_images.h.
#include "dayphoton/report/result_images.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>


#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/report/image_legend.h"
#include "dayphoton/report/sky_picture.h"
#include "dayphoton/report/temporal_map.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::report {

namespace fs = std::filesystem;

namespace {

std::string join(const std::string& dir, const std::string& name) { return (fs::path(dir) / name).string(); }

}  // namespace

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

void outline_sensor_cells(RgbaImage& image, const SensorLattice& lattice, int pixels_per_cell) {
  const int k = pixels_per_cell;
  if (!lattice.regular || k < 4) return;
  std::vector<char> has(static_cast<std::size_t>(lattice.columns) * static_cast<std::size_t>(lattice.rows), 0);
  const auto index = [&](int c, int r) { return static_cast<std::size_t>(r) * lattice.columns + c; };
  for (std::size_t i = 0; i < lattice.column_of.size(); ++i) has[index(lattice.column_of[i], lattice.row_of[i])] = 1;
  const auto sensor_at = [&](int c, int r) {
    return c >= 0 && r >= 0 && c < lattice.columns && r < lattice.rows && has[index(c, r)];
  };
  const std::array<std::uint8_t, 4> ink{OutlineGrey, OutlineGrey, OutlineGrey, 255};
  for (int r = 0; r < lattice.rows; ++r)
    for (int c = 0; c < lattice.columns; ++c) {
      if (!sensor_at(c, r)) continue;
      const int x0 = c * k, y0 = r * k;
      for (int t = 0; t < k; ++t) {
        if (!sensor_at(c, r - 1)) image.at(x0 + t, y0) = ink;
        if (!sensor_at(c, r + 1)) image.at(x0 + t, y0 + k - 1) = ink;
        if (!sensor_at(c - 1, r)) image.at(x0, y0 + t) = ink;
        if (!sensor_at(c + 1, r)) image.at(x0 + k - 1, y0 + t) = ink;
      }
    }
}

std::string legend_title(const study::SensorQuantity& quantity) {
  std::string title = quantity.quantity;
  if (!title.empty() && title[0] >= 'a' && title[0] <= 'z') title[0] = static_cast<char>(title[0] - 'a' + 'A');
  // The percent scale is the one of the time metrics (DA, UDI): shares of the occupied hours.
  const std::string unit = quantity.scale == study::QuantityScale::Percent && quantity.unit == "%"
                               ? "% of occupied hours"
                               : quantity.unit;
  return unit.empty() ? title : title + ", " + unit;
}

RgbaImage grid_png(const SensorLattice& lattice, const std::vector<double>& values,
                   const study::SensorQuantity& quantity, int pixels_per_cell, const PlanGeometry& geometry) {
  const RgbaImage plan = plan_picture(lattice, values, scale_of(quantity), pixels_per_cell, geometry).image;
  const std::string note = lattice.regular ? "1 cell = " + format_number(lattice.spacing_m) + " m"
                                           : "one cell per sensor, in sensor order";
  return with_legend(plan, scale_of(quantity), legend_title(quantity), note).image;
}

ColourScale scale_of(const study::SensorQuantity& quantity) {
  switch (quantity.scale) {
    case study::QuantityScale::DaylightFactor: return daylight_factor_scale();
    case study::QuantityScale::Illuminance: return illuminance_scale();
    case study::QuantityScale::Percent: break;
  }
  return percent_scale(quantity.scale_label);
}

std::vector<std::string> write_grid_images(const std::string& results_dir, const study::CaseResult& c,
                                           const study::GridResult& grid) {
  std::vector<std::string> written;
  const std::string grid_dir = study::grid_folder(results_dir, grid);
  const SensorLattice& lattice = grid.lattice;
  const int pixels_per_cell =
      std::max(1, std::min(std::max(32, (256 + lattice.columns - 1) / std::max(1, lattice.columns)),
                           4096 / std::max(1, std::max(lattice.columns, lattice.rows))));
  const PlanGeometry geometry = plan_geometry(c, grid);
  for (const study::SensorQuantity& q : grid.quantities) {
    const std::vector<double> values = study::read_quantity_values(results_dir, grid, q);
    FloatImage exr = sensor_value_image(lattice, values);
    exr.string_attributes["dayphoton:grid"] = grid.name;
    exr.string_attributes["dayphoton:source"] = q.file + ":" + q.column;
    exr.string_attributes["dayphoton:description"] = q.quantity;
    const std::string exr_path = join(grid_dir, q.stem + ".exr");
    study::write_exr(exr, q.quantity, q.unit, exr_path);
    written.push_back(exr_path);
    const std::string png_path = join(grid_dir, q.stem + ".png");
    study::write_png(grid_png(lattice, values, q, pixels_per_cell, geometry), png_path);
    written.push_back(png_path);
  }
  if (const std::string temporal = write_temporal_map(results_dir, grid); !temporal.empty()) written.push_back(temporal);
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

std::vector<std::string> write_sky_images(const std::string& results_dir, const study::ResultsModel& model,
                                          const YearHour& hour, int size) {
  const std::string& weather = model.weather_file;
  if (weather.empty() || !model.sun_site || !fs::exists(weather)) return {};
  const double rho = model.ground_reflectance;
  const sky::PatchBasis basis =
      model.basis == "reinhart" ? sky::PatchBasis::reinhart(model.reinhart_mf) : sky::PatchBasis::tregenza();
  const weather::HourlyWeather series = weather::read_hourly_weather(weather);
  const auto& s = *model.sun_site;
  const sky::SolarSite site{s[0], s[1], s[2], s[3]};
  if (std::abs(series.site.time_zone_h - site.time_zone_h) > 1e-9)
    throw InputError(SourceLocation{weather, 0, 0},
                     "the weather file's clock (UTC" + format_number(series.site.time_zone_h) +
                         ") is not the one the run used (UTC" + format_number(site.time_zone_h) +
                         "): it is not the run's weather file any more");
  const study::AnnualSky sky =
      study::annual_sky_from_weather(series, site, basis, study::radiance_compatible_sky_options(rho));

  // The record whose interval (h - 1, h] holds the hour: mid-hour stamp ceil(H) - 0.5.
  const double stamp = std::ceil(hour.hour - 1e-9) - 0.5;
  int column = -1;
  for (std::size_t t = 0; t < sky.steps.size(); ++t)
    if (sky.steps[t].month == hour.month && sky.steps[t].day == hour.day && std::abs(sky.steps[t].hour - stamp) < 1e-6)
      column = static_cast<int>(t);
  if (column < 0)
    throw InputError(SourceLocation{weather, 0, 0}, "no record for " + hour.text() + " (month/day/hour) in the weather file");

  std::vector<std::string> written;
  const auto write_one = [&](int c, const std::string& stem, const std::string& time, const std::string& note) {
    FloatImage image = sky_fisheye(sky.matrix, c, basis, size);
    image.string_attributes["dayphoton:weather"] = weather;
    image.string_attributes["dayphoton:time"] = time;
    image.string_attributes["dayphoton:sky"] = sky.description;
    const std::string exr = join(results_dir, stem + ".exr");
    study::write_exr(image, "sky radiance", "W/(sr m2)", exr);
    written.push_back(exr);
    const std::string png = join(results_dir, stem + ".png");
    study::write_png(sky_png(image, luminance_scale_for(image), note), png);
    written.push_back(png);
  };
  write_one(-1, "sky_mean", "mean over all " + std::to_string(sky.steps.size()) + " records of the weather file",
            "annual mean, seen from below (east left)");
  std::ostringstream time;
  time << hour.month << '/' << hour.day << " record of EPW hour " << static_cast<int>(stamp + 0.5) << " (sky at "
       << stamp << " h local standard time)";
  std::ostringstream note;
  note << hour.month << '/' << hour.day << ' ' << stamp << " h, seen from below (east left)";
  write_one(column, "sky_hour", time.str(), note.str());
  return written;
}

}  // namespace dayphoton::report
