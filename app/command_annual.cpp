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
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/project_metric_settings.h"
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

/// The metric settings: the project's (--project) or the defaults, then the command line's
/// overrides, checked as the project file's keys are (UsageError).
study::AnnualStudySettings annual_settings(const AnnualOptions& o, const project::Project* project,
                                           const weather::HourlyWeather& weather) {
  // The grid folder is named after its sensor set, whose own schedule (if any) applies.
  fs::path grid = fs::absolute(o.coefficients_dir).lexically_normal();
  if (!grid.has_filename()) grid = grid.parent_path();
  study::AnnualStudySettings settings = project ? study::annual_settings_of(*project, &weather, grid.filename().string())
                                                : study::AnnualStudySettings{};
  settings.calendar = study::weather_calendar(weather);
  metrics::MetricSettings& m = settings.metrics;
  if (o.da_threshold_lux) m.da_threshold_lux = *o.da_threshold_lux;
  if (o.udi_lower_lux) m.udi_lower_lux = *o.udi_lower_lux;
  if (o.udi_upper_original_lux) m.udi_upper_original_lux = *o.udi_upper_original_lux;
  if (o.udi_upper_revised_lux) m.udi_upper_revised_lux = *o.udi_upper_revised_lux;
  if (o.sda_time_fraction) {
    if (!(*o.sda_time_fraction > 0)) throw UsageError("--sda-time-fraction must be in (0, 1]");
    m.sda_time_fraction = *o.sda_time_fraction;
  }
  if (!(m.udi_upper_original_lux > m.udi_lower_lux))
    throw UsageError("the UDI upper limit (" + format_number(m.udi_upper_original_lux) +
                     " lx) must be greater than the lower one (" + format_number(m.udi_lower_lux) + " lx)");
  if (!(m.udi_upper_revised_lux > m.udi_lower_lux))
    throw UsageError("the revised UDI upper limit (" + format_number(m.udi_upper_revised_lux) +
                     " lx) must be greater than the lower one (" + format_number(m.udi_lower_lux) + " lx)");
  if (m.da_threshold_lux < m.udi_lower_lux || m.da_threshold_lux > m.udi_upper_revised_lux)
    throw UsageError("the DA threshold (" + format_number(m.da_threshold_lux) + " lx) must lie between the UDI lower limit (" +
                     format_number(m.udi_lower_lux) + " lx) and the revised upper limit (" +
                     format_number(m.udi_upper_revised_lux) + " lx): the revised UDI band is split there");

  metrics::OccupancyPlan& plan = settings.occupancy;
  if (!o.occupancy_hours.empty()) {
    const double start = o.occupancy_hours[0], end = o.occupancy_hours[1];
    if (!(end > start))
      throw UsageError("--occupancy-hours: the end (" + format_number(end) + ") must be after the start (" +
                       format_number(start) + ")");
    plan = metrics::OccupancyPlan::daily_hours(start, end);
  }
  if (!o.daylight_saving.empty() || !o.january_1.empty()) {
    if (plan.kind == metrics::OccupancyPlan::Kind::Hourly)
      throw UsageError("--daylight-saving and --january-1 do not apply to an hourly schedule (a CSV file)");
    if (plan.kind == metrics::OccupancyPlan::Kind::Daily) {  // the same window every day, now on the clock
      const metrics::HourWindow window = plan.daily;
      plan = metrics::OccupancyPlan{};
      plan.kind = metrics::OccupancyPlan::Kind::Weekly;
      plan.week.fill({window});
    }
    if (!o.daylight_saving.empty()) plan.daylight_saving = *metrics::parse_daylight_saving(o.daylight_saving);
    if (!o.january_1.empty()) plan.january_1 = metrics::parse_weekday(o.january_1);
  }
  return settings;
}

/// `--sky-vector`: coefficients x one sky column = the illuminance per sensor under that sky
/// (what dctimestep computes for one sky vector), written as sky_vector_illuminance.csv.
int sky_vector_illuminance(const AnnualOptions& o, const RadianceMatrix& coefficients,
                           const std::string& coefficients_path, const std::vector<SensorPoint>& sensors,
                           std::ostream& out) {
  MatrixReadOptions read_options;
  read_options.non_negative = true;
  read_options.max_values = o.max_matrix_values;
  const RadianceMatrix vector = study::read_matrix_file(o.sky_vector_path, read_options, o.max_decompressed_bytes);
  if (vector.columns() != 1)
    throw InputError(SourceLocation{o.sky_vector_path, 0, 0},
                     "has " + std::to_string(vector.columns()) +
                         " columns; --sky-vector takes one sky (one column; --sky-matrix takes an annual matrix)");
  if (vector.rows() != coefficients.columns() || vector.components() != coefficients.components())
    throw InputError(SourceLocation{o.sky_vector_path, 0, 0},
                     "has " + std::to_string(vector.rows()) + " rows x " + std::to_string(vector.components()) +
                         " components but " + coefficients_path + " has " + std::to_string(coefficients.columns()) +
                         " bins x " + std::to_string(coefficients.components()));
  const metrics::IlluminanceTable table = study::annual_illuminance(coefficients, vector, {metrics::TimeStamp{}});
  const std::string output_dir =
      o.output_dir.empty() ? (fs::path(o.coefficients_dir) / "annual").string() : o.output_dir;
  fs::create_directories(output_dir);
  const std::string path = (fs::path(output_dir) / "sky_vector_illuminance.csv").string();
  study::write_point_in_time_csv(sensors, {"illuminance"}, table, path);
  if (!o.quiet) {
    double sum = 0, low = 0, high = 0;
    for (std::size_t i = 0; i < table.sensor_count(); ++i) {
      const double e = table.lux(0, i);
      sum += e;
      low = i == 0 ? e : std::min(low, e);
      high = i == 0 ? e : std::max(high, e);
    }
    out << "dayphoton annual: " << sensors.size() << " sensors under the sky of " << o.sky_vector_path << ": mean "
        << std::fixed << std::setprecision(1) << sum / double(std::max<std::size_t>(1, sensors.size())) << " lux, min "
        << low << ", max " << high << "\n  wrote " << path << '\n';
    require_written(out, "the summary");
  }
  return ExitOk;
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

  if (!o.sky_vector_path.empty()) return sky_vector_illuminance(o, coefficients, coefficients_path, sensors, out);

  // The project first: its errors are located in it (exit 1), before any matrix is read.
  std::optional<project::Project> project;
  if (!o.project_path.empty()) project = project::load_project(o.project_path);
  const std::string weather_path = !o.weather_path.empty() ? o.weather_path
                                   : project                 ? project->weather.path
                                                             : std::string();
  if (weather_path.empty())
    throw UsageError(project ? "the project " + o.project_path + " has no weather file: give --weather"
                             : std::string("--weather is required (or --project, whose weather file is used)"));
  // A missing weather file (or a FIFO) is bad input (exit 1): read_epw says so, located.
  const weather::HourlyWeather weather = weather::read_hourly_weather(weather_path);
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
                                    " bins, one column per record of " + weather_path + ")",
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
  const study::AnnualStudySettings settings = annual_settings(o, project ? &*project : nullptr, weather);
  const study::AnnualStudy result = study::compute_annual_study(coefficients, sky, settings);
  const std::string output_dir =
      o.output_dir.empty() ? (fs::path(o.coefficients_dir) / "annual").string() : o.output_dir;
  const std::vector<std::string> written = study::write_annual_outputs(result, sensors, settings, output_dir);

  if (!o.quiet) {
    const metrics::GridMetrics& g = result.grid;
    std::size_t sda_sensors = 0;
    const bool overridden = !o.occupancy_hours.empty() || !o.daylight_saving.empty() || !o.january_1.empty() ||
                            o.da_threshold_lux || o.udi_lower_lux || o.udi_upper_original_lux ||
                            o.udi_upper_revised_lux || o.sda_time_fraction;
    const metrics::MetricSettings& ms = settings.metrics;
    for (const metrics::SensorMetrics& m : result.sensors) sda_sensors += m.da_percent >= 100.0 * ms.sda_time_fraction;
    const std::string da = "DA" + format_number(ms.da_threshold_lux);
    out << "dayphoton annual: " << sensors.size() << " sensors x " << result.illuminance.step_count()
        << " steps, " << result.occupied_hours << " occupied hours (" << settings.occupancy.description() << ")\n"
        << (project ? "  metric settings: " + o.project_path + (overridden ? ", with the command line's overrides" : "") + "\n"
                    : std::string())
        << "  sky: " << result.sky_description << "\n"
        << (site_line.empty() ? std::string() : "  site: " + site_line + "\n")
        << "  mean " << da << " " << percent(g.mean.da_percent) << ", s" << da << "/"
        << format_number(100.0 * ms.sda_time_fraction) << "% " << percent(g.sda_percent) << " ("
        << sda_sensors << " of " << sensors.size() << " sensors), mean UDI " << format_number(ms.udi_lower_lux) << "-"
        << format_number(ms.udi_upper_original_lux) << " " << percent(g.mean.udi_original_percent) << ", mean occupied illuminance " << std::fixed
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
