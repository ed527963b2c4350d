// WeatherSite: where a weather file's records were taken, and on which clock.
//
// Conventions (docs/weather.md): latitude north positive, longitude and time zone EAST
// positive as in EPW (RADIANCE .wea files are west positive; wea.cpp converts). The time zone
// is the clock of the records: their hours are local standard time of this zone.
#pragma once

#include <string>

namespace dayphoton::weather {

struct WeatherSite {
  std::string city;
  std::string state;
  std::string country;
  std::string source;  ///< e.g. "TMY3" (EPW); empty for .wea
  std::string wmo;     ///< station number, kept as text; empty for .wea
  double latitude_deg = 0.0;        ///< north positive
  double longitude_east_deg = 0.0;  ///< east positive (RADIANCE .wea uses west positive)
  double time_zone_h = 0.0;         ///< hours relative to UTC, east positive (-8 = PST)
  double elevation_m = 0.0;
};

}  // namespace dayphoton::weather
