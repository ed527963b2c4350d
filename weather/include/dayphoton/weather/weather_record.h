// WeatherRecord: one hourly record of a weather file, typed and with units in the names.
//
// Conventions (docs/weather.md; facts/sky-and-metrics.md §6.3; EnergyPlus "EPW Data
// Dictionary"):
//  - `hour` is 1..24 and the record covers the interval (hour-1, hour] in local STANDARD
//    time (EPW never applies daylight saving time). Sky and sun are evaluated at the
//    midpoint hour - 0.5 (see SiteClock).
//  - Radiation fields in an EPW file are energies in Wh/m^2 received during the hour; for
//    hourly data this equals the mean irradiance in W/m^2 over the interval, which is how
//    they are stored here (`*_w_m2`).
//  - A missing value is std::nullopt, never the file's magic code (9999, 999900, 99.9, ...).
//    The reader turns the codes into nullopt; whoever needs a value (e.g. the sky needs DNI
//    and DHI) reports its absence, located with `source_line` and the field number
//    (epw_field_location() in epw_reader.h).
#pragma once

#include <optional>

namespace dayphoton::weather {

/// One hourly weather record. Optional fields are std::nullopt when the file marks them
/// missing (or, for trailing fields not modelled by a format such as .wea, absent).
struct WeatherRecord {
  int year = 0;     ///< year field as written (TMY files mix years; informational only)
  int month = 1;    ///< 1..12
  int day = 1;      ///< 1..31
  int hour = 1;     ///< 1..24; the record covers (hour-1, hour] local standard time
  int minute = 60;  ///< as written: 0 or 60 for hourly EPW data (both mean "whole hour")
  int source_line = 0;  ///< 1-based line in the source file (0 if not read from a file)

  std::optional<double> dry_bulb_c;                ///< dry bulb temperature, °C (EPW 99.9 = missing)
  std::optional<double> dew_point_c;               ///< dew point temperature, °C (99.9)
  std::optional<double> relative_humidity_percent; ///< % (999)
  std::optional<double> pressure_pa;               ///< atmospheric station pressure, Pa (999999)

  std::optional<double> extraterrestrial_horizontal_w_m2;    ///< (9999)
  std::optional<double> extraterrestrial_direct_normal_w_m2; ///< (9999)
  std::optional<double> horizontal_infrared_w_m2;            ///< (9999)
  std::optional<double> global_horizontal_w_m2;              ///< GHI (9999)
  std::optional<double> direct_normal_w_m2;                  ///< DNI (9999)
  std::optional<double> diffuse_horizontal_w_m2;             ///< DHI (9999)

  std::optional<double> global_horizontal_lux;  ///< (>= 999900 = missing)
  std::optional<double> direct_normal_lux;      ///< (>= 999900)
  std::optional<double> diffuse_horizontal_lux; ///< (>= 999900)
  std::optional<double> zenith_luminance_cd_m2; ///< (exactly 9999 = missing; see docs)

  std::optional<double> wind_direction_deg;      ///< clockwise from north (999)
  std::optional<double> wind_speed_m_s;          ///< (999)
  std::optional<double> total_sky_cover_tenths;  ///< 0..10 (99)
  std::optional<double> opaque_sky_cover_tenths; ///< 0..10 (99)
  std::optional<double> visibility_km;           ///< (9999)
  std::optional<double> ceiling_height_m;        ///< (99999; 77777 = unlimited, kept as is)
  std::optional<double> precipitable_water_mm;   ///< (999)
  std::optional<double> aerosol_optical_depth;   ///< dimensionless, as written (.999)
  std::optional<double> snow_depth_cm;           ///< (999)
  std::optional<double> days_since_last_snowfall;///< (99)
  std::optional<double> albedo;                  ///< (999)
  std::optional<double> liquid_precipitation_depth_mm;  ///< (999)
  std::optional<double> liquid_precipitation_quantity_h;///< (99)
};

}  // namespace dayphoton::weather
