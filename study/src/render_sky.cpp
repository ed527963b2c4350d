// The sky of a rendering; see render_sky.h.
#include "dayphoton/study/render_sky.h"

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/sky/perez.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/study/year_hour.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"
#include "dayphoton/weather/site_clock.h"

namespace dayphoton::study {

namespace {

Vec3 direction_of(double altitude_deg, double azimuth_deg) {
  const double h = deg_to_rad(altitude_deg), a = deg_to_rad(azimuth_deg);
  return {std::cos(h) * std::sin(a), std::cos(h) * std::cos(a), std::sin(h)};
}

/// Sky and ground radiance along a direction toward the sky.
engine::RenderSky continuous(std::shared_ptr<const sky::SkyModel> model, const Vec3& ground,
                             const sky::PatchBasis& basis) {
  engine::RenderSky out;
  const RadianceMatrix vector = sky::sky_vector(*model, basis, ground);
  for (std::size_t bin = 0; bin < vector.rows(); ++bin)
    out.source_radiance.push_back({vector.at(bin, 0, 0), vector.at(bin, 0, 1), vector.at(bin, 0, 2)});
  out.radiance = [model, ground](const Vec3& d) { return d.z > 0 ? model->radiance_rgb(d) : ground; };
  return out;
}

}  // namespace

void add_sun_source(engine::RenderSky& sky, engine::SourceSet& sources, std::vector<double>& photon_factor) {
  if (!sky.sun) return;
  sources.add_sun_disc(sky.sun->direction, sky.sun->half_angle_rad);
  sky.source_radiance.push_back(sky.sun->radiance);
  photon_factor.push_back(SunPhotonFactor);
}

RenderSkyResult make_render_sky(const RenderSkySettings& settings, const project::Project& project,
                                const sky::PatchBasis& basis) {
  const double rho = project.simulation.ground_reflectance;
  const Vec3 rho_rgb{rho, rho, rho};
  const double e = settings.horizontal_illuminance_lux;
  const std::string& spec = settings.spec;
  RenderSkyResult result;
  std::ostringstream description;
  if (spec == "overcast" || spec == "uniform" || spec.rfind("cie:", 0) == 0) {
    if (!(e > 0) || !std::isfinite(e)) throw std::invalid_argument("the sky's horizontal illuminance must be > 0");
    std::shared_ptr<const sky::SkyModel> model;
    const sky::SkyScale scale = sky::SkyScale::horizontal_illuminance_lux(e);
    if (spec == "overcast") {
      model = sky::make_cie_overcast_sky(scale);
    } else if (spec == "uniform") {
      // Luminance E / pi gives E on a horizontal plane.
      model = sky::make_uniform_sky(e / Pi);
    } else {
      int type = 0;
      std::size_t used = 0;
      try {
        type = std::stoi(spec.substr(4), &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != spec.size() - 4 || type < 1 || type > 15)
        throw std::invalid_argument("--sky cie:N needs a CIE general sky type N in 1..15, not '" + spec + "'");
      model = sky::make_cie_general_sky(type, direction_of(settings.sun_altitude_deg, settings.sun_azimuth_deg), scale);
    }
    const Vec3 ground = sky::ground_radiance_rgb(rho_rgb, e, 0, {0, 0, -1});
    result.sky = continuous(model, ground, basis);
    description << model->description() << "; ground reflectance " << rho;
  } else if (spec.rfind("hour:", 0) == 0) {
    const YearHour when = parse_year_hour(spec.substr(5));
    if (project.weather.path.empty())
      throw std::invalid_argument("--sky hour:M/D/H needs a weather file in the project");
    const weather::HourlyWeather weather = weather::read_hourly_weather(project.weather.path);
    const weather::SiteClock clock = weather::SiteClock::for_weather(weather);
    const std::vector<weather::TimeStep> steps = clock.steps(weather.records);
    const int epw_hour = static_cast<int>(std::ceil(when.hour - 1e-9));
    std::size_t index = steps.size();
    for (std::size_t t = 0; t < steps.size(); ++t)
      if (steps[t].month == when.month && steps[t].day == when.day && steps[t].hour == epw_hour) index = t;
    if (index == steps.size())
      throw InputError(SourceLocation{project.weather.path, 0, 0},
                       "no record for " + when.text() + " (month/day/hour) in the weather file");
    const weather::WeatherRecord& record = weather.records[index];
    const weather::TimeStep& step = steps[index];
    if (!record.direct_normal_w_m2 || !record.diffuse_horizontal_w_m2)
      throw InputError(weather::weather_value_location(weather, record, weather::WeatherValue::DirectNormalIrradiance),
                       "the record of " + when.text() + " lacks its direct normal or diffuse horizontal irradiance");
    // The sun of the project's site (or the header's with from_weather), as in the run.
    const SunSite site = resolve_sun_site(project.site, weather);
    const sky::SolarPosition sun =
        sky::solar_position(site.solar, sky::SolarTime{clock.year(), step.month, step.day, step.hour_lst}, {});
    sky::PerezInputs inputs;
    inputs.direct_normal_irradiance_W_m2 = *record.direct_normal_w_m2;
    inputs.diffuse_horizontal_irradiance_W_m2 = *record.diffuse_horizontal_w_m2;
    inputs.sun_direction = sun.direction;
    inputs.day_of_year = step.day_of_year;
    if (record.dew_point_c) inputs.dew_point_C = *record.dew_point_c;
    sky::PerezSky perez = sky::make_perez_sky(inputs);
    const double sun_lux = sun.direction.z > 0 ? perez.state.direct_normal_illuminance_lux : 0.0;
    const Vec3 ground = sky::ground_radiance_rgb(rho_rgb, perez.state.diffuse_horizontal_illuminance_lux, sun_lux,
                                                 sun.direction);
    std::shared_ptr<const sky::SkyModel> model(std::move(perez.sky));
    result.sky = continuous(model, ground, basis);
    description << "Perez sky of " << when.text() << " (EPW hour " << step.hour << ", sun at " << step.hour_lst
                << " h LST, altitude " << rad_to_deg(sun.altitude_rad) << " deg, azimuth " << rad_to_deg(sun.azimuth_rad)
                << " deg) from " << project.weather.path << "; diffuse horizontal "
                << perez.state.diffuse_horizontal_illuminance_lux << " lx, direct normal " << sun_lux
                << " lx; ground reflectance " << rho;
    if (sun_lux > 0) {
      const double solid_angle_sr = 2.0 * Pi * (1.0 - std::cos(sky::SunHalfAngle_rad));
      // Grey disc in RADIANCE units: luminance / 179 per channel.
      const double l = sun_lux / (RadianceWhiteEfficacy_lm_per_W * solid_angle_sr);
      result.sky.sun = engine::RenderSky::Sun{sun.direction, sky::SunHalfAngle_rad, {l, l, l}};
    }
  } else {
    throw std::invalid_argument("--sky must be overcast, uniform, cie:N or hour:M/D/H, not '" + spec + "'");
  }
  result.description = description.str();
  return result;
}

}  // namespace dayphoton::study
