// `dayphoton sky`: an annual sky matrix from a weather file, or a sky vector for one CIE sky,
// in RADIANCE matrix format (bins x steps x RGB, W/(sr m^2)). See docs/cli.md.
#include <iostream>
#include <sstream>

#include "commands.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"
#include "dayphoton/study/run_inputs.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::app {

namespace {

std::unique_ptr<sky::SkyModel> make_cie_sky(const SkyOptions& o) {
  const sky::SkyScale scale = sky::SkyScale::horizontal_illuminance_lux(o.horizontal_illuminance_lux);
  if (o.cie == "uniform") return sky::make_uniform_sky(o.horizontal_illuminance_lux / Pi);
  if (o.cie == "overcast") return sky::make_cie_overcast_sky(scale);
  int type = 0;
  try {
    std::size_t used = 0;
    type = std::stoi(o.cie, &used);
    if (used != o.cie.size()) type = 0;
  } catch (const std::exception&) {
  }
  if (type < 1 || type > 15)
    throw UsageError("--cie must be 1..15, 'overcast' or 'uniform', not '" + o.cie + "'");
  const double alt = deg_to_rad(o.sun_altitude_deg), az = deg_to_rad(o.sun_azimuth_deg);
  const Vec3 sun{std::cos(alt) * std::sin(az), std::cos(alt) * std::cos(az), std::sin(alt)};
  return sky::make_cie_general_sky(type, sun, scale);
}

}  // namespace

int run_sky(const SkyOptions& o, const std::string& command_line, std::ostream& out) {
  const sky::PatchBasis basis = parse_basis_option(o.basis);
  const MatrixFormat format = parse_matrix_format(o.format);
  RadianceMatrix matrix;

  if (!o.cie.empty() && !o.weather_path.empty())
    throw UsageError("give either a weather file or --cie, not both");
  if (!o.cie.empty() && (o.sun != "spread" || o.solar_position != "spa"))
    throw UsageError("--sun and --solar-position apply to weather files, not to --cie skies");
  if (o.cie.empty() && o.cie_options_given)
    throw UsageError("--altitude, --azimuth and --illuminance apply to --cie skies only");
  if (!o.cie.empty()) {
    const auto sky = make_cie_sky(o);
    const double e_h = sky->horizontal_illuminance_lux();
    // Lambertian ground lit by this sky alone (CIE skies carry no sun here).
    const double ground = o.ground_reflectance * e_h / (Pi * RadianceWhiteEfficacy_lm_per_W);
    matrix = sky::sky_vector(*sky, basis, Vec3{ground, ground, ground});
    matrix.header_lines().push_back(command_line);
    matrix.header_lines().push_back("SKY= " + sky->description());
  } else {
    if (o.weather_path.empty()) throw UsageError("give a weather file or --cie TYPE");
    const weather::HourlyWeather weather = weather::read_hourly_weather(o.weather_path);
    // What the reader accepted with a warning (ignored fields, filled gaps, header variants).
    for (const Diagnostic& w : weather.warnings) std::cerr << w.format();
    // Records stamped on another clock than the header's (docs/weather.md), as `check` says it.
    if (const std::optional<std::string> w =
            study::radiation_clock_message(weather, o.weather_path))
      std::cerr << "warning: " << *w << '\n';
    require_matrix_within_limit("the sky matrix (--basis " + o.basis + ": " + std::to_string(basis.bin_count()) +
                                    " bins, one column per record of " + o.weather_path + ")",
                                static_cast<std::uint64_t>(basis.bin_count()), weather.records.size(), 3,
                                o.max_matrix_values);
    sky::SkyMatrixOptions options;
    if (o.solar_position == "radiance") options = sky::SkyMatrixOptions::gendaymtx_compatible();
    if (o.sun == "spread") options.sun = sky::SunInMatrix::Spread;
    else if (o.sun == "none") options.sun = sky::SunInMatrix::None;
    else options.sun = sky::SunInMatrix::Only;
    options.ground_reflectance = o.ground_reflectance;
    const sky::SolarSite site = sky::solar_site_of(weather);
    sky::SkyMatrix result = sky::build_sky_matrix(weather, site, basis, options);
    matrix = std::move(result.matrix);
    matrix.header_lines().push_back(command_line);
    std::ostringstream latlong;
    latlong.precision(8);
    latlong << std::fixed << "LATLONG= " << site.latitude_deg << ' ' << site.longitude_deg;
    matrix.header_lines().push_back(latlong.str());
    if (result.below_horizon_direct.records_over_20_W_m2 > 0)
      std::cerr << "dayphoton sky: note: " << result.below_horizon_direct.records_over_20_W_m2
                << " records have direct irradiance > 20 W/m2 with the sun below the horizon; "
                   "their sun was kept, as gendaymtx does\n";
  }
  if (o.output_path.empty()) {
    matrix.write(out, format);
    require_written(out, "the sky matrix");
  } else {
    matrix.write_file(o.output_path, format);
  }
  return ExitOk;
}

}  // namespace dayphoton::app
