// radiation_timing: see radiation_timing.h.
#include "dayphoton/sky/radiation_timing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/weather/site_clock.h"

namespace dayphoton::sky {

RadiationTiming radiation_timing(const weather::HourlyWeather& weather, const SolarSite& site) {
  if (site.time_zone_h != weather.site.time_zone_h)
    throw std::invalid_argument("radiation timing: the site's time zone is not the clock of " + weather.source_name +
                                "'s records");
  const weather::SiteClock clock = weather::SiteClock::for_weather(weather);
  const std::vector<weather::TimeStep> steps = clock.steps(weather.records);

  // The records of each day (in file order) and its direct normal irradiation.
  struct Day {
    std::size_t first = 0, end = 0;
    double direct_normal_Wh_m2 = 0;
  };
  std::vector<Day> days;
  for (std::size_t t = 0; t < steps.size(); ++t) {
    if (days.empty() || steps[t].day_of_year != steps[days.back().first].day_of_year) days.push_back({t, t, 0.0});
    days.back().end = t + 1;
    days.back().direct_normal_Wh_m2 += weather.records[t].direct_normal_w_m2.value_or(0.0);
  }
  days.erase(std::remove_if(days.begin(), days.end(), [](const Day& d) { return !(d.direct_normal_Wh_m2 > 0); }),
             days.end());
  // The clearest days; ties broken by the date, so the choice does not depend on the sort.
  std::stable_sort(days.begin(), days.end(),
                   [](const Day& a, const Day& b) { return a.direct_normal_Wh_m2 > b.direct_normal_Wh_m2; });
  const auto clear = static_cast<std::size_t>(std::floor(ClearDayShare * static_cast<double>(days.size())));
  RadiationTiming timing;
  if (clear < RadiationTimingMinimumDays) return timing;

  double weight = 0, weighted_hours = 0;
  for (std::size_t k = 0; k < clear; ++k)
    for (std::size_t t = days[k].first; t < days[k].end; ++t) {
      const weather::WeatherRecord& r = weather.records[t];
      const double w = r.direct_normal_w_m2.value_or(0.0) + r.diffuse_horizontal_w_m2.value_or(0.0);
      if (!(w > 0)) continue;
      const SolarPosition sun =
          solar_position(site, SolarTime{clock.year(), steps[t].month, steps[t].day, steps[t].hour_lst});
      weight += w;
      weighted_hours += w * sun.hour_angle_rad * (12.0 / Pi);
    }
  if (!(weight > 0)) return timing;
  timing.measured = true;
  timing.offset_h = weighted_hours / weight;
  timing.days = clear;
  return timing;
}

}  // namespace dayphoton::sky
