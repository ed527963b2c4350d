// `dayphoton annual --coefficients DIR --weather FILE.epw|FILE.wea`: the annual illuminance
// tables and metrics of a grid from the sky coefficients an earlier `dayphoton run` exported
// (DIR/coefficients_sky.mtx, DIR/sensors.csv), without any tracing (issue 5 item 6). The sky
// matrix is built from the weather file in the RADIANCE-compatible mode (gendaymtx -m MF, sun
// spread into patches) or read from a RADIANCE matrix file (--sky-matrix, e.g. gendaymtx
// output, plain or .gz); the weather file always gives the time stamps. The run's results.json
// (study/recorded_metric_settings.h) gives the grid's metric settings, the site the sun is
// computed for (else the weather file header's) and the ground reflectance; --project and the
// command line's options override the settings.
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
#include <iostream>
#include <ostream>

#include "commands.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_exact_sun.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/daylight_openings.h"
#include "dayphoton/study/project_metric_settings.h"
#include "dayphoton/study/recorded_metric_settings.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/run_inputs.h"
#include "dayphoton/study/sub_patch_shares.h"
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

std::string percent(double v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << v << " %";
  return s.str();
}

/// Folders up to three levels below `dir` that hold a coefficients_sky.mtx (a run's grid
/// folders: <results>/<grid> and <results>/variants/<variant>/<grid>), sorted.
std::vector<std::string> grid_folders_below(const std::string& dir) {
  std::vector<std::string> found;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it.depth() >= 2) it.disable_recursion_pending();
    if (it->path().filename() == "annual") {  // annual's own output folders
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_directory(ec) && fs::exists(it->path() / "coefficients_sky.mtx", ec)) found.push_back(it->path().string());
  }
  std::sort(found.begin(), found.end());
  return found;
}

/// The metric settings, in increasing precedence: the run's (its results model's record of
/// this grid), the project's (--project), the command line's overrides, checked as the
/// project file's keys are (UsageError). `source` receives where the base settings came from.
study::AnnualStudySettings annual_settings(const AnnualOptions& o, const std::string& grid_dir,
                                           const project::Project* project,
                                           const std::optional<study::RecordedGrid>& recorded,
                                           const weather::HourlyWeather& weather, std::string& source) {
  // The grid folder is named after its sensor set, whose own schedule (if any) applies.
  fs::path grid = fs::absolute(grid_dir).lexically_normal();
  if (!grid.has_filename()) grid = grid.parent_path();
  study::AnnualStudySettings settings;
  if (project) {
    // EN 17037's rule for horizontal openings: the run's record of this grid's case (a
    // variant may add roof lights), else the project's own model.
    metrics::MetricSettings::Openings openings;
    if (recorded && recorded->grid && recorded->grid->annual) {
      openings = study::recorded_annual_settings(*recorded->grid->annual, SourceLocation{recorded->results_path, 0, 0})
                     .metrics.en17037_openings;
    } else {
      // The grid's openings as a run decides them (daylight_openings.h); a folder no set of the
      // project names takes the model's kind.
      const SceneDescription description = project::build_scene_description(*project);
      const engine::Scene scene = engine::Scene::build(description);
      const study::DaylightOpenings model = study::daylight_openings(scene);
      openings = model.kind == metrics::MetricSettings::Openings::Both ? metrics::MetricSettings::Openings::VerticalOrInclined
                                                                       : model.kind;
      const std::vector<engine::Material> materials = engine::materials_of(description.materials);
      for (const SensorGrid& g : description.grids)
        if (g.name == grid.filename().string())
          openings = study::grid_daylight_openings(scene, materials, {g}, model).front().kind;
    }
    settings = study::annual_settings_of(*project, &weather, openings, grid.filename().string());
    source = o.project_path;
  } else if (recorded && recorded->grid && recorded->grid->annual) {
    settings = study::recorded_annual_settings(*recorded->grid->annual, SourceLocation{recorded->results_path, 0, 0});
    source = "the run's, from " + recorded->results_path;
  } else {
    source = "the defaults (no --project, and no results.json above the grid folder records its metrics)";
  }
  settings.calendar = study::weather_calendar(weather);
  metrics::MetricSettings& m = settings.metrics;
  if (o.da_threshold_lux) m.da_threshold_lux = *o.da_threshold_lux;
  if (o.udi_lower_lux) m.udi_lower_lux = *o.udi_lower_lux;
  if (o.udi_upper_original_lux) m.udi_upper_original_lux = *o.udi_upper_original_lux;
  if (o.udi_upper_revised_lux) m.udi_upper_revised_lux = *o.udi_upper_revised_lux;
  if (o.sda_time_fraction) {
    if (!(*o.sda_time_fraction > 0 && *o.sda_time_fraction <= 1)) throw UsageError("--sda-time-fraction must be in (0, 1]");
    m.sda_time_fraction = *o.sda_time_fraction;
  }
  if (o.ase_threshold_lux) {
    if (!(*o.ase_threshold_lux > 0)) throw UsageError("--ase-threshold must be positive (lx)");
    m.ase_threshold_lux = *o.ase_threshold_lux;
  }
  if (o.ase_hours) {
    if (!(*o.ase_hours >= 0)) throw UsageError("--ase-hours must not be negative");
    m.ase_hours = *o.ase_hours;
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
void sky_vector_illuminance(const AnnualOptions& o, const RadianceMatrix& coefficients,
                            const std::string& coefficients_path, const std::vector<SensorPoint>& sensors,
                            const std::string& output_dir, std::ostream& out) {
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
  // Never silently patch-uniform: on stderr even with --quiet.
  std::cerr << "note: " << coefficients_path << ": " << study::SkyVectorPatchUniformNote << '\n';
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
    out.unsetf(std::ios::floatfield);
    require_written(out, "the summary");
  }
}

/// What every grid of one `annual` call shares: the project and the weather file.
struct AnnualInputs {
  std::optional<project::Project> project;
  std::optional<weather::HourlyWeather> weather;
  std::string weather_path;
};

/// The sun of the annual study: "exact" (the exported direct sun and sun bins of a sun-bins
/// run), "spread" (the sun spread into the sky patches, sky coefficients only).
bool use_exact_sun(const AnnualOptions& o, const std::string& grid_dir) {
  const bool exported = study::has_exact_sun_export(grid_dir);
  if (o.sun == "spread") return false;
  if (o.sun == "exact") {
    if (!o.sky_matrix_path.empty())
      throw UsageError("--sun exact builds its sky without the sun from the weather file; --sky-matrix gives a whole "
                       "sky (use --sun spread with it)");
    if (!exported)
      throw InputError(SourceLocation{grid_dir, 0, 0},
                       std::string("--sun exact: no ") + study::DirectSunFileName +
                           " in this grid folder (a run with `simulation.sun: bins` and outputs.coefficients writes it)");
    return true;
  }
  if (!o.sun.empty()) throw UsageError("--sun takes exact or spread, not '" + o.sun + "'");
  return exported && o.sky_matrix_path.empty();
}

/// The annual study of one grid folder into `output_dir`.
void annual_of_grid(const AnnualOptions& o, const std::string& grid_dir, const std::string& output_dir,
                    AnnualInputs& inputs, std::ostream& out) {
  const std::string coefficients_path = (fs::path(grid_dir) / "coefficients_sky.mtx").string();
  const std::string sensors_path = (fs::path(grid_dir) / "sensors.csv").string();
  std::optional<sky::PatchBasis> requested_basis;
  if (!o.basis.empty()) requested_basis = parse_basis_option(o.basis);

  // Sky radiances and daylight coefficients are never negative: in binary data a negative
  // value is the usual sign of the wrong byte order.
  MatrixReadOptions read_options;
  read_options.non_negative = true;
  read_options.max_values = o.max_matrix_values;
  const RadianceMatrix coefficients = RadianceMatrix::read_file(coefficients_path, read_options);
  std::vector<double> sensor_area_m2;  // the run's sensor areas (sensors.csv's area_m2), if any
  const std::vector<SensorPoint> sensors = study::read_sensors_csv(sensors_path, &sensor_area_m2);
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

  if (!o.sky_vector_path.empty()) {
    sky_vector_illuminance(o, coefficients, coefficients_path, sensors, output_dir, out);
    return;
  }

  // The project first: its errors are located in it (exit 1), before any matrix is read.
  if (!o.project_path.empty() && !inputs.project) inputs.project = project::load_project(o.project_path);
  const project::Project* project = inputs.project ? &*inputs.project : nullptr;
  if (!inputs.weather) {
    inputs.weather_path = !o.weather_path.empty() ? o.weather_path : project ? project->weather.path : std::string();
    if (inputs.weather_path.empty())
      throw UsageError(project ? "the project " + o.project_path + " has no weather file: give --weather"
                               : std::string("--weather is required (or --project, whose weather file is used)"));
    // A missing weather file (or a FIFO) is bad input (exit 1): read_epw says so, located.
    inputs.weather = weather::read_hourly_weather(inputs.weather_path);
    // A part-year file, as `check` and `run` say it (on stderr even with --quiet).
    if (const std::optional<std::string> w = study::partial_year_message(*inputs.weather, inputs.weather_path))
      std::cerr << "warning: " << *w << '\n';
    // Records stamped on another clock than the header's, as `check` and `run` say it, when
    // the sky and the sun come from the file (not with --sky-matrix).
    if (o.sky_matrix_path.empty())
      if (const std::optional<std::string> w = study::radiation_clock_message(*inputs.weather, inputs.weather_path))
        std::cerr << "warning: " << *w << '\n';
  }
  const weather::HourlyWeather& weather = *inputs.weather;
  const std::string& weather_path = inputs.weather_path;
  const bool exact_sun = use_exact_sun(o, grid_dir);

  // The run's record of this grid (results.json above the folder), if any.
  const std::optional<study::RecordedGrid> recorded = study::find_recorded_grid(grid_dir);
  study::AnnualSky sky;
  std::optional<study::SkyAndSuns> sky_and_suns;
  std::string site_line;
  if (o.sky_matrix_path.empty()) {
    const std::optional<study::SunSite> run_site =
        recorded ? study::recorded_sun_site(recorded->model, recorded->results_path, weather) : std::nullopt;
    double rho = o.ground_reflectance;
    if (!o.ground_reflectance_given && recorded) rho = recorded->model.ground_reflectance;
    // The sun of the run's site (its results.json), else of the weather file's header.
    const study::SunSite site = run_site ? *run_site : study::header_sun_site(weather);
    site_line = study::sun_site_sentence(site) + (run_site ? " (the run's, from " + recorded->results_path + ")"
                                                           : std::string(" (no results.json records a site)"));
    // A weather file of another station than the run's: its irradiance stands for the site's
    // sky only where the climates are alike. `run` says so in its log; `annual` on stderr,
    // even with --quiet (the sun is still the run's site's, so the numbers are what `run`
    // would compute with this file).
    if (const std::string w = study::station_distance_warning(site); !w.empty())
      std::cerr << "warning: " << grid_dir << ": " << (w.rfind("warning: ", 0) == 0 ? w.substr(9) : w) << '\n';
    require_matrix_within_limit("the sky matrix (" + std::to_string(basis.bin_count()) +
                                    " bins, one column per record of " + weather_path + ")",
                                static_cast<std::uint64_t>(basis.bin_count()), weather.records.size(), 3,
                                o.max_matrix_values);
    if (exact_sun)
      sky_and_suns = study::annual_sky_and_suns(weather, site.solar, basis, study::sun_excluded_sky_options(rho));
    else
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
  const study::AnnualSky& the_sky = sky_and_suns ? sky_and_suns->sky : sky;

  require_matrix_within_limit("the illuminance table (" + std::to_string(sensors.size()) + " sensors, one row per record)",
                              sensors.size(), the_sky.steps.size(), 1, o.max_matrix_values);
  std::string settings_source;
  study::AnnualStudySettings settings = annual_settings(o, grid_dir, project, recorded, weather, settings_source);
  settings.sensor_area_m2 = sensor_area_m2;
  // The coefficients' sub-patch shares, exported beside the coefficients by a run: with them
  // (and a sky built here, which has the quadrant deltas) the table is the run's. The photon
  // part's shares are unclamped fits (docs/photon-map.md, "The annual photon part on
  // sub-patches"), so a share may be slightly negative.
  const std::string shares_path = (fs::path(grid_dir) / study::SubPatchSharesFileName).string();
  study::SubPatchShares shares;
  if (fs::exists(shares_path)) {
    MatrixReadOptions share_options = read_options;
    share_options.non_negative = false;
    const RadianceMatrix m = RadianceMatrix::read_file(shares_path, share_options);
    try {
      shares = study::sub_patch_shares_of(m, sensors.size(), coefficients.columns());
    } catch (const std::invalid_argument& e) {
      throw InputError(SourceLocation{shares_path, 0, 0}, e.what());
    }
  }
  study::ExactSunNotes notes;
  const study::AnnualStudy result =
      exact_sun ? study::annual_study_exact_sun(
                      coefficients,
                      study::read_exact_sun_export(grid_dir, sensors.size(), read_options, o.max_decompressed_bytes),
                      *sky_and_suns, settings, grid_dir, notes, &shares)
                : study::compute_annual_study(coefficients, sky, settings, nullptr, &shares);
  study::AnnualOutputs which;
  which.illuminance_csv = o.illuminance_csv;
  const std::vector<std::string> written = study::write_annual_outputs(result, sensors, settings, output_dir, which);
  if (!project && !(recorded && recorded->grid && recorded->grid->annual))
    std::cerr << "warning: " << grid_dir
              << ": no results.json above the grid folder records its metric settings and no --project is given: "
                 "the default thresholds and occupancy (08:00-18:00 every day) apply\n";
  // Never silently interpolated: the warnings go to stderr even with --quiet.
  for (const std::string& w : notes.warnings()) std::cerr << "warning: " << grid_dir << ": " << w << '\n';
  // Nor silently patch-uniform (a sky matrix file has no quadrant deltas).
  if (shares.empty())
    std::cerr << "warning: " << grid_dir << ": " << study::SubPatchSharesMissingWarning << '\n';
  else if (the_sky.quadrant_deltas.rows() == 0)
    std::cerr << "warning: " << grid_dir << ": " << study::SkyMatrixFileQuadrantsWarning << '\n';

  if (!o.quiet) {
    const metrics::GridMetrics& g = result.grid;
    std::size_t sda_sensors = 0;
    const bool overridden = !o.occupancy_hours.empty() || !o.daylight_saving.empty() || !o.january_1.empty() ||
                            o.da_threshold_lux || o.udi_lower_lux || o.udi_upper_original_lux ||
                            o.udi_upper_revised_lux || o.sda_time_fraction || o.ase_threshold_lux || o.ase_hours;
    const metrics::MetricSettings& ms = settings.metrics;
    for (const metrics::SensorMetrics& m : result.sensors) sda_sensors += m.da_percent >= 100.0 * ms.sda_time_fraction;
    const std::string da = "DA" + format_number(ms.da_threshold_lux);
    out << "dayphoton annual: " << grid_dir << ": " << sensors.size() << " sensors x " << result.illuminance.step_count()
        << " steps, " << result.occupied_hours << " occupied hours (" << settings.occupancy.description() << ")\n"
        << "  metric settings: " << settings_source << (overridden ? ", with the command line's overrides" : "") << "\n"
        << "  sky: " << result.sky_description << "\n"
        << (site_line.empty() ? std::string() : "  site: " + site_line + "\n")
        << "  mean " << da << " " << percent(g.mean.da_percent) << ", s" << da << "/"
        << format_number(100.0 * ms.sda_time_fraction) << "% " << percent(g.sda_percent) << " ("
        << sda_sensors << " of " << sensors.size() << " sensors), mean UDI " << format_number(ms.udi_lower_lux) << "-"
        << format_number(ms.udi_upper_original_lux) << " " << percent(g.mean.udi_original_percent) << ", mean occupied illuminance " << std::fixed
        << std::setprecision(0) << g.mean.mean_occupied_lux << " lux\n";
    out.unsetf(std::ios::floatfield);
    out << std::setprecision(6);
    if (!g.en17037.empty()) {
      out << "  EN 17037 daylight provision:";
      for (std::size_t i = 0; i < g.en17037.size(); ++i)
        out << (i ? ", " : " ") << g.en17037[i].level << (g.en17037[i].passes ? " passes" : " fails");
      out << '\n';
    }
    if (exact_sun)
      out << "  sun: exact (" << study::DirectSunFileName << ", coefficients_sun.mtx): " << notes.suns_exact << " of "
          << notes.suns << " suns at exported positions; ASE" << format_number(ms.ase_threshold_lux) << ","
          << format_number(ms.ase_hours) << " " << percent(g.ase_percent) << "\n";
    else
      out << "  sun: spread into the sky patches; ASE not computed (needs the direct sun: "
          << study::DirectSunFileName << " of a sun-bins run)\n";
    for (const std::string& path : written) out << "  wrote " << path << '\n';
    require_written(out, "the summary");
  }
}

}  // namespace

int run_annual(const AnnualOptions& o, std::ostream& out) {
  if (!o.sky_matrix_path.empty() && o.ground_reflectance_given)
    throw UsageError("--ground-reflectance applies to sky matrices built from the weather file, not to --sky-matrix");
  if (!fs::is_directory(o.coefficients_dir))
    throw InputError(SourceLocation{o.coefficients_dir, 0, 0},
                     "not a folder; --coefficients takes a grid folder or the results folder written by `dayphoton run`");
  AnnualInputs inputs;
  if (fs::exists(fs::path(o.coefficients_dir) / "coefficients_sky.mtx")) {
    const std::string output_dir =
        o.output_dir.empty() ? (fs::path(o.coefficients_dir) / "annual").string() : o.output_dir;
    annual_of_grid(o, o.coefficients_dir, output_dir, inputs, out);
    return ExitOk;
  }
  // A results folder (or a case's folder): every grid folder below it, each into its own
  // annual folder (or -o DIR/<the grid's path below the results folder>).
  const std::vector<std::string> grids = grid_folders_below(o.coefficients_dir);
  if (grids.empty())
    throw InputError(SourceLocation{o.coefficients_dir, 0, 0},
                     "no coefficients_sky.mtx in this folder or in grid folders below it: --coefficients takes a grid "
                     "folder or the results folder written by `dayphoton run`, which writes it into each grid's folder");
  if (!o.quiet)
    out << "dayphoton annual: " << grids.size() << " grid folder" << (grids.size() == 1 ? "" : "s") << " below "
        << o.coefficients_dir << '\n';
  for (const std::string& grid : grids) {
    const std::string output_dir =
        o.output_dir.empty() ? (fs::path(grid) / "annual").string()
                             : (fs::path(o.output_dir) / fs::path(grid).lexically_relative(o.coefficients_dir)).string();
    annual_of_grid(o, grid, output_dir, inputs, out);
  }
  return ExitOk;
}

}  // namespace dayphoton::app
