// Point-in-time cases as steps of the sun-bins layout (point_in_time.h).
#include "dayphoton/study/point_in_time.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"

namespace dayphoton::study {

namespace {

std::string clock_text(const project::PointInTimeSpec& c) {
  const int minutes = static_cast<int>(std::lround(c.hour_lst * 60.0));
  char text[32];
  std::snprintf(text, sizeof text, "%02d-%02d %02d:%02d", c.month, c.day, minutes / 60, minutes % 60);
  return text;
}

std::string degrees(double rad) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", rad_to_deg(rad));
  return text;
}

std::string lux(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", value);
  return text;
}

/// The step of the weather file's record that contains the time. EPW hour h covers the
/// interval (h - 1, h] ("Hour 1 is 00:01 to 01:00", EnergyPlus Auxiliary Programs, "Data
/// Field Descriptions": its radiation is received in the minutes preceding the hour), and its
/// record is stamped at h - 0.5: a time t falls in hour ceil(t), so 15:00 is hour 15's record
/// (14:00-15:00, stamped 14:30) and 15:20 is hour 16's. 00:00 ends the previous day's last
/// hour; a date's cases stay on that date, so it takes the day's first record.
std::optional<std::size_t> weather_step(const AnnualSky& sky, const project::PointInTimeSpec& c) {
  const double hour = std::clamp(std::ceil(c.hour_lst), 1.0, 24.0);
  const double stamp = hour - 0.5;
  for (std::size_t t = 0; t < sky.steps.size(); ++t) {
    const metrics::TimeStamp& s = sky.steps[t];
    if (s.month == c.month && s.day == c.day && std::fabs(s.hour - stamp) < 1e-6) return t;
  }
  return std::nullopt;
}

void copy_column(const RadianceMatrix& from, std::size_t from_column, RadianceMatrix& to, std::size_t to_column) {
  for (std::size_t bin = 0; bin < from.rows(); ++bin)
    for (int c = 0; c < from.components(); ++c) to.at(bin, to_column, c) = from.at(bin, from_column, c);
}

/// The sun of a CIE case: NREL SPA for the site at the case's date and time (02-29 in a leap
/// year, PointInTimeLeapSolarYear).
sky::SolarPosition cie_sun(const project::PointInTimeSpec& c, const sky::SolarSite& site) {
  const int year = c.month == 2 && c.day == 29 ? PointInTimeLeapSolarYear : PointInTimeSolarYear;
  return sky::solar_position(site, sky::SolarTime{year, c.month, c.day, c.hour_lst}, sky::SolarPositionOptions{});
}

std::string sun_below_horizon(const project::PointInTimeSpec& c, const sky::SolarPosition& sun) {
  return "point-in-time case '" + c.name + "': the sun is below the horizon at " + clock_text(c) + " (altitude " +
         degrees(sun.altitude_rad) + " deg); a CIE general sky needs the sun above it";
}

std::string sun_text(const Vec3& direction) {
  const double altitude = std::asin(std::clamp(direction.z, -1.0, 1.0));
  double azimuth = std::atan2(direction.x, direction.y);
  if (azimuth < 0) azimuth += 2 * Pi;
  return "sun at " + degrees(altitude) + " deg altitude, " + degrees(azimuth) + " deg azimuth";
}

std::string sky_text(const project::PointInTimeSpec& c) {
  switch (c.sky) {
    case project::PointSky::CieOvercast:
      return "CIE standard overcast sky, " + lux(c.diffuse_horizontal_illuminance_lux) + " lx horizontal, no sun";
    case project::PointSky::CieGeneral:
      return "CIE standard general sky type " + std::to_string(c.cie_type) + ", " +
             lux(c.diffuse_horizontal_illuminance_lux) + " lx diffuse horizontal";
    case project::PointSky::Weather: return "the weather file's hour";
  }
  return {};
}

}  // namespace

sky::SolarSite point_in_time_site(const project::Project& project, const SunSite* sun_site) {
  if (sun_site) return sun_site->solar;
  const project::Site& ps = project.site;
  return sky::SolarSite{ps.latitude_deg, ps.longitude_deg, ps.time_zone_h, ps.elevation_m};
}

std::vector<std::string> check_points_in_time(const std::vector<project::PointInTimeSpec>& cases,
                                              const sky::SolarSite& site) {
  Diagnostics diagnostics;
  std::vector<std::string> lines;
  for (const project::PointInTimeSpec& c : cases) {
    std::string line = c.name + ": " + clock_text(c) + " local standard time, " + sky_text(c);
    if (c.sky == project::PointSky::CieGeneral) {
      const sky::SolarPosition sun = cie_sun(c, site);
      if (!sun.sun_up) diagnostics.error(c.time_location, sun_below_horizon(c, sun));
      line += ", " + sun_text(sun.direction) + ", " +
              (c.direct_normal_illuminance_lux > 0 ? lux(c.direct_normal_illuminance_lux) + " lx direct normal"
                                                   : std::string("no direct sun"));
    }
    lines.push_back(line);
  }
  diagnostics.throw_if_errors();
  return lines;
}

namespace {

/// A CIE case's sky (overcast or general) and its ground radiance: the one sky model both
/// the case's patch column and its continuous sky come from. Throws InputError for a
/// general sky whose sun is below the horizon.
struct CieCaseSky {
  std::shared_ptr<const sky::SkyModel> sky;
  Vec3 ground_rgb;
  sky::SolarPosition sun;  ///< general skies only
};
CieCaseSky cie_case_sky(const project::PointInTimeSpec& c, const sky::SolarSite& site, double ground_reflectance) {
  const Vec3 rho{ground_reflectance, ground_reflectance, ground_reflectance};
  const sky::SkyScale scale = sky::SkyScale::horizontal_illuminance_lux(c.diffuse_horizontal_illuminance_lux);
  CieCaseSky out;
  if (c.sky == project::PointSky::CieOvercast) {
    // As the daylight factor's sky (SimulationPlan::daylight_factor_sky), so E = DF x E_h / 100.
    out.sky = sky::make_cie_overcast_sky(scale);
    out.ground_rgb = sky::ground_radiance_rgb(rho, c.diffuse_horizontal_illuminance_lux, 0, {0, 0, -1});
    return out;
  }
  out.sun = cie_sun(c, site);
  if (!out.sun.sun_up) throw InputError(c.time_location, sun_below_horizon(c, out.sun));
  out.sky = sky::make_cie_general_sky(c.cie_type, out.sun.direction, scale);
  out.ground_rgb = sky::ground_radiance_rgb(rho, out.sky->horizontal_illuminance_lux(), c.direct_normal_illuminance_lux,
                                            out.sun.direction);
  return out;
}

}  // namespace

std::vector<engine::ContinuousSky> point_in_time_continuous_skies(const std::vector<project::PointInTimeSpec>& cases,
                                                                  const sky::SolarSite& site, double ground_reflectance,
                                                                  std::vector<int>& sky_of_case) {
  std::vector<engine::ContinuousSky> skies;
  sky_of_case.assign(cases.size(), -1);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const project::PointInTimeSpec& c = cases[k];
    if (c.sky == project::PointSky::Weather) continue;
    if (c.sky != project::PointSky::CieOvercast && !cie_sun(c, site).sun_up) continue;
    const CieCaseSky cs = cie_case_sky(c, site, ground_reflectance);
    engine::ContinuousSky sky;
    // Every parameter the radiance depends on, at full precision: the description rounds the
    // sun's altitude and leaves out its azimuth, so two times either side of noon would share
    // a cache entry.
    std::ostringstream key;
    key.precision(17);
    key << "point in time " << (c.sky == project::PointSky::CieOvercast ? 0 : c.cie_type) << " diffuse "
        << c.diffuse_horizontal_illuminance_lux << " direct normal " << c.direct_normal_illuminance_lux << " sun "
        << cs.sun.direction.x << ' ' << cs.sun.direction.y << ' ' << cs.sun.direction.z << " ground " << cs.ground_rgb.x
        << ' ' << cs.ground_rgb.y << ' ' << cs.ground_rgb.z;
    sky.key = key.str();
    sky.radiance_rgb = [model = cs.sky, ground = cs.ground_rgb](const Vec3& w) {
      return w.z > 0 ? model->radiance_rgb(w) : ground;
    };
    sky_of_case[k] = static_cast<int>(skies.size());
    skies.push_back(std::move(sky));
  }
  return skies;
}

SkyAndSuns point_in_time_skies(const std::vector<project::PointInTimeSpec>& cases, const sky::SolarSite& site,
                               const sky::PatchBasis& basis, double ground_reflectance,
                               const SkyAndSuns* annual) {
  SkyAndSuns out;
  out.sky.matrix = RadianceMatrix(static_cast<std::size_t>(basis.bin_count()), cases.size(), 3);
  // A weather case's quadrant deltas are its hour's (the annual product's sub-patch
  // correction); a CIE case's direct part comes from its continuous sky instead: zero.
  out.sky.quadrant_deltas =
      RadianceMatrix(static_cast<std::size_t>(sky::PatchBasis::QuadrantCount * basis.bin_count()), cases.size(), 1);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const project::PointInTimeSpec& c = cases[k];
    out.sky.steps.push_back({c.month, c.day, c.hour_lst});
    if (c.sky == project::PointSky::Weather) {
      if (!annual) throw std::logic_error("point in time: a weather case without the annual sky");
      const std::optional<std::size_t> t = weather_step(annual->sky, c);
      if (!t) {
        const bool leap_day = c.month == 2 && c.day == 29 &&
                              std::none_of(annual->sky.steps.begin(), annual->sky.steps.end(),
                                           [](const metrics::TimeStamp& s) { return s.month == 2 && s.day == 29; });
        throw InputError(c.location, "point-in-time case '" + c.name + "': the weather file has no record for " +
                                         clock_text(c) +
                                         (leap_day ? " (it has no 29 February: not a leap year's records)" : ""));
      }
      copy_column(annual->sky.matrix, *t, out.sky.matrix, k);
      if (annual->sky.quadrant_deltas.rows() == out.sky.quadrant_deltas.rows())
        copy_column(annual->sky.quadrant_deltas, *t, out.sky.quadrant_deltas, k);
      for (const sky::SunRecord& sun : annual->suns)
        if (sun.step == *t) {
          sky::SunRecord r = sun;
          r.step = k;
          out.suns.push_back(r);
        }
      continue;
    }
    const CieCaseSky cs = cie_case_sky(c, site, ground_reflectance);
    copy_column(sky::sky_vector(*cs.sky, basis, cs.ground_rgb), 0, out.sky.matrix, k);
    if (c.sky != project::PointSky::CieOvercast && c.direct_normal_illuminance_lux > 0)
      out.suns.push_back(sky::sun_record(k, cs.sun.direction, c.direct_normal_illuminance_lux));
  }
  out.sky.description = "point-in-time skies: " + std::to_string(cases.size()) + " case(s)";
  return out;
}

RadianceMatrix point_in_time_cie_quadrant_deltas(const std::vector<project::PointInTimeSpec>& cases,
                                                 const sky::SolarSite& site, const sky::PatchBasis& basis,
                                                 double ground_reflectance) {
  RadianceMatrix out(static_cast<std::size_t>(sky::PatchBasis::QuadrantCount * basis.bin_count()), cases.size(), 1);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const project::PointInTimeSpec& c = cases[k];
    if (c.sky != project::PointSky::CieGeneral || !cie_sun(c, site).sun_up) continue;
    const CieCaseSky cs = cie_case_sky(c, site, ground_reflectance);
    const RadianceMatrix deltas =
        sky::sky_vector_quadrant_deltas(*cs.sky, basis, sky::sky_vector(*cs.sky, basis, cs.ground_rgb));
    copy_column(deltas, 0, out, k);
  }
  return out;
}

std::vector<std::string> describe_points_in_time(const std::vector<project::PointInTimeSpec>& cases,
                                                 const SkyAndSuns& skies) {
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const project::PointInTimeSpec& c = cases[k];
    std::string s = c.name + ": " + clock_text(c) + " local standard time, " + sky_text(c);
    if (c.sky != project::PointSky::CieOvercast) {
      const sky::SunRecord* sun = nullptr;
      for (const sky::SunRecord& r : skies.suns)
        if (r.step == k) sun = &r;
      s += sun ? ", " + sun_text(sun->direction) + ", " + lux(sun->direct_normal_illuminance_lux) + " lx direct normal"
               : std::string(", no direct sun");
    }
    lines.push_back(s);
  }
  return lines;
}

RadianceMatrix point_in_time_sky_column(const SkyAndSuns& skies, std::size_t k) {
  const RadianceMatrix& matrix = skies.sky.matrix;
  if (k >= matrix.columns())
    throw std::invalid_argument("point in time: case " + std::to_string(k) + " of " +
                                std::to_string(matrix.columns()) + " sky columns");
  RadianceMatrix column(matrix.rows(), 1, matrix.components());
  for (std::size_t p = 0; p < column.rows(); ++p)
    for (int c = 0; c < column.components(); ++c) column.at(p, 0, c) = matrix.at(p, k, c);
  return column;
}

}  // namespace dayphoton::study
