// Bench support: one weather record's Perez sky as the annual study builds it (gendaymtx's
// conventions), for the Perez benches' continuous-sky references (perez_sky_component_bench,
// perez_photon_part_bench).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/continuous_sky.h"
#include "dayphoton/sky/perez.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/weather/hourly_weather.h"
#include "dayphoton/weather/site_clock.h"

namespace dayphoton::bench {

/// The Perez model's inputs of record t, whose sun `sun[t]` is above the horizon.
inline sky::PerezInputs perez_inputs_of(const weather::HourlyWeather& epw, const std::vector<weather::TimeStep>& steps,
                                        const std::vector<std::optional<Vec3>>& sun, std::size_t t) {
  const weather::WeatherRecord& r = epw.records[t];
  sky::PerezInputs in;
  in.direct_normal_irradiance_W_m2 = r.direct_normal_w_m2.value_or(0.0);
  in.diffuse_horizontal_irradiance_W_m2 = r.diffuse_horizontal_w_m2.value_or(0.0);
  in.sun_direction = *sun[t];
  in.day_of_year = steps[t].day_of_year;  // non-leap files: RADIANCE's day of year too
  return in;                              // dew point: gendaymtx's 11 C, as the study's sky
}

/// The continuous Perez sky of those inputs: the model times gendaymtx's sky colour above the
/// horizon, `ground_rgb` (the sky matrix's ground bin of the record) below it.
inline engine::ContinuousSky continuous_perez_sky(const sky::PerezInputs& in, const Vec3& ground_rgb, std::string key) {
  std::shared_ptr<const sky::SkyModel> model = sky::make_perez_sky(in).sky;
  const Vec3 colour = sky::SkyMatrixOptions::gendaymtx_compatible().sky_colour;
  engine::ContinuousSky sky;
  sky.key = std::move(key);
  sky.radiance_rgb = [model, ground_rgb, colour](const Vec3& w) {
    return w.z > 0 ? mul(colour, model->radiance_rgb(w)) : ground_rgb;
  };
  return sky;
}

}  // namespace dayphoton::bench
