// `dayphoton annual --coefficients DIR --weather FILE.epw|FILE.wea`: the annual illuminance
// tables and metrics of a grid from the sky coefficients an earlier `dayphoton run` exported
// (DIR/coefficients_sky.mtx, DIR/sensors.csv), without any tracing (issue 5 item 6). The sky
// matrix is built from the weather file in the RADIANCE-compatible mode (gendaymtx -m MF, sun
// spread into patches) or read from a RADIANCE matrix file (--sky-matrix, e.g. gendaymtx
// output, plain or .gz); the weather file always gives the time stamps. The sun is computed for the site the
// run's summary.json records (study/sun_site.h), else for the weather file header's site.
// See docs/outputs.md and docs/cli.md.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>
#include <iomanip>
#include <ostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::app {

namespace {

namespace fs = std::filesystem;

/// The basis whose bin count (144 MF^2 + 2) is the coefficient matrix's column count.
sky::PatchBasis basis_of_columns(std::size_t columns, const std::string& coefficients_path) {
  for (int mf = 1; mf <= 64; ++mf)
    if (static_cast<std::size_t>(144 * mf * mf + 2) == columns) return sky::PatchBasis::reinhart(mf);
  throw InputError(SourceLocation{coefficients_path, 0, 0},
                   std::to_string(columns) + " columns match no sky basis (Tregenza 146, Reinhart MF n 144 n^2 + 2)");
}

/// The run's summary.json beside the grid folder: its path and text ("" if there is no such
/// regular file).
std::pair<std::string, std::string> run_summary(const std::string& grid_dir) {
  fs::path dir = fs::absolute(grid_dir).lexically_normal();
  if (!dir.has_filename()) dir = dir.parent_path();  // "grid/" -> "grid"
  const fs::path summary = dir.parent_path() / "summary.json";
  if (!input_file_problem(summary.string()).empty()) return {summary.string(), ""};  // absent, or a FIFO: not waited on
  std::ifstream in(summary);
  std::ostringstream text;
  text << in.rdbuf();
  return {summary.string(), in ? text.str() : std::string()};
}

/// The ground reflectance the run used, from its summary.json (simulation.ground_reflectance),
/// so that the rebuilt sky equals the run's; nullopt if there is no such file or key.
std::optional<double> run_ground_reflectance(const std::string& summary_text) {
  if (summary_text.empty()) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(summary_text, nullptr, false);
  if (j.is_discarded() || !j.contains("simulation") || !j["simulation"].is_object()) return std::nullopt;
  const nlohmann::json& s = j["simulation"];
  if (!s.contains("ground_reflectance") || !s["ground_reflectance"].is_number()) return std::nullopt;
  const double rho = s["ground_reflectance"].get<double>();
  if (!(rho >= 0 && rho <= 1)) return std::nullopt;
  return rho;
}

std::string percent(double v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << v << " %";
  return s.str();
}

/// Folders up to two levels below `dir` that hold a coefficients_sky.mtx (a run's grid
/// folders: <results>/<grid> and <results>/<variant>/<grid>), sorted, at most 8.
std::vector<std::string> grid_folders_below(const std::string& dir) {
  constexpr std::size_t MaxListed = 8;
  std::vector<std::string> found;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it.depth() >= 2) it.disable_recursion_pending();
    if (it->is_directory(ec) && fs::exists(it->path() / "coefficients_sky.mtx", ec)) found.push_back(it->path().string());
  }
  std::sort(found.begin(), found.end());
  if (found.size() > MaxListed) found.resize(MaxListed);
  return found;
}

std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

int run_annual(const AnnualOptions& o, std::ostream& out) {
  if (!o.sky_matrix_path.empty() && o.ground_reflectance_given)
    throw UsageError("--ground-reflectance applies to sky matrices built from the weather file, not to --sky-matrix");
  if (!fs::is_directory(o.coefficients_dir))
    throw InputError(SourceLocation{o.coefficients_dir, 0, 0},
                     "not a folder; --coefficients takes a grid folder written by `dayphoton run`");
  const std::string coefficients_path = (fs::path(o.coefficients_dir) / "coefficients_sky.mtx").string();
  if (!fs::exists(coefficients_path)) {
    // The usual slip: the results folder (or a case's folder) instead of one of its grids.
    std::vector<std::string> grids = grid_folders_below(o.coefficients_dir);
    std::string hint = grids.empty() ? std::string("; `dayphoton run` writes it into each grid's folder")
                                     : "; grid folders below it: " + join_names(grids);
    throw InputError(SourceLocation{o.coefficients_dir, 0, 0},
                     "no coefficients_sky.mtx in this folder: --coefficients takes a grid folder written by "
                     "`dayphoton run`" + hint);
  }
  const std::string sensors_path = (fs::path(o.coefficients_dir) / "sensors.csv").string();
  std::optional<sky::PatchBasis> requested_basis;
  if (!o.basis.empty()) requested_basis = parse_basis_option(o.basis);

  // Sky radiances and daylight coefficients are never negative: in binary data a negative
  // value is the usual sign of the wrong byte order.
  MatrixReadOptions read_options;
  read_options.non_negative = true;
  read_options.max_values = o.max_matrix_values;
  const RadianceMatrix coefficients = RadianceMatrix::read_file(coefficients_path, read_options);
  const std::vector<SensorPoint> sensors = study::read_sensors_csv(sensors_path);
  if (sensors.size() != coefficients.rows())
    throw InputError(SourceLocation{sensors_path, 0, 0},
                     "has " + std::to_string(sensors.size()) + " sensors but " + coefficients_path + " has " +
                         std::to_string(coefficients.rows()) + " rows");
  if (coefficients.components() != 3)
    throw InputError(SourceLocation{coefficients_path, 0, 0},
                     "NCOMP=" + std::to_string(coefficients.components()) + ", expected 3 (RGB coefficients)");
  const sky::PatchBasis basis = requested_basis ? *requested_basis : basis_of_columns(coefficients.columns(), coefficients_path);
  if (static_cast<std::size_t>(basis.bin_count()) != coefficients.columns())
    throw InputError(SourceLocation{coefficients_path, 0, 0},
                     "has " + std::to_string(coefficients.columns()) + " columns but --basis " + o.basis + " has " +
                         std::to_string(basis.bin_count()) + " bins");

  // A missing weather file (or a FIFO) is bad input (exit 1): read_epw says so, located.
  const weather::HourlyWeather weather = weather::read_hourly_weather(o.weather_path);
  study::AnnualSky sky;
  std::string site_line;
  if (o.sky_matrix_path.empty()) {
    const auto [summary_path, summary_text] = run_summary(o.coefficients_dir);
    double rho = o.ground_reflectance;
    if (!o.ground_reflectance_given)
      if (const std::optional<double> from_run = run_ground_reflectance(summary_text)) rho = *from_run;
    // The sun of the run's site (its summary.json), else of the weather file's header.
    const std::optional<study::SunSite> recorded = study::recorded_sun_site(summary_text, summary_path, weather);
    const study::SunSite site = recorded ? *recorded : study::header_sun_site(weather);
    site_line = study::sun_site_sentence(site) +
                (recorded ? " (the run's, from " + summary_path + ")" : std::string(" (no run summary records a site)"));
    require_matrix_within_limit("the sky matrix (" + std::to_string(basis.bin_count()) +
                                    " bins, one column per record of " + o.weather_path + ")",
                                static_cast<std::uint64_t>(basis.bin_count()), weather.records.size(), 3,
                                o.max_matrix_values);
    sky = study::annual_sky_from_weather(weather, site.solar, basis, study::radiance_compatible_sky_options(rho));
  } else {
    sky = study::annual_sky_from_matrix_file(o.sky_matrix_path, weather, read_options, o.max_decompressed_bytes);
    if (sky.matrix.rows() != coefficients.columns() || sky.matrix.components() != coefficients.components())
      throw InputError(SourceLocation{o.sky_matrix_path, 0, 0},
                       "has " + std::to_string(sky.matrix.rows()) + " rows x " +
                           std::to_string(sky.matrix.components()) + " components but " + coefficients_path +
                           " has " + std::to_string(coefficients.columns()) + " bins x " +
                           std::to_string(coefficients.components()));
  }

  require_matrix_within_limit("the illuminance table (" + std::to_string(sensors.size()) + " sensors, one row per record)",
                              sensors.size(), sky.steps.size(), 1, o.max_matrix_values);
  const study::AnnualStudySettings settings;
  const study::AnnualStudy result = study::compute_annual_study(coefficients, sky, settings);
  const std::string output_dir =
      o.output_dir.empty() ? (fs::path(o.coefficients_dir) / "annual").string() : o.output_dir;
  const std::vector<std::string> written = study::write_annual_outputs(result, sensors, settings, output_dir);

  if (!o.quiet) {
    const metrics::GridMetrics& g = result.grid;
    std::size_t sda_sensors = 0;
    for (const metrics::SensorMetrics& m : result.sensors) sda_sensors += m.da_percent >= 50.0;
    out << "dayphoton annual: " << sensors.size() << " sensors x " << result.illuminance.step_count()
        << " steps, " << result.occupied_hours << " occupied hours (08:00-18:00 local standard time)\n"
        << "  sky: " << result.sky_description << "\n"
        << (site_line.empty() ? std::string() : "  site: " + site_line + "\n")
        << "  mean DA300 " << percent(g.mean.da_percent) << ", sDA300/50% " << percent(g.sda_percent) << " ("
        << sda_sensors << " of " << sensors.size() << " sensors), mean UDI 100-2000 "
        << percent(g.mean.udi_original_percent) << ", mean occupied illuminance " << std::fixed
        << std::setprecision(0) << g.mean.mean_occupied_lux << " lux\n";
    if (!g.en17037.empty()) {
      out << "  EN 17037 daylight provision:";
      for (std::size_t i = 0; i < g.en17037.size(); ++i)
        out << (i ? ", " : " ") << g.en17037[i].level << (g.en17037[i].passes ? " passes" : " fails");
      out << '\n';
    }
    out << "  ASE not computed (needs direct-sun coefficients; sky coefficients only here)\n";
    for (const std::string& path : written) out << "  wrote " << path << '\n';
    require_written(out, "the summary");
  }
  return ExitOk;
}

}  // namespace dayphoton::app
