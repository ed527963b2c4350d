// dayphoton command line: parses options with CLI11 and dispatches to app/command_*.cpp.
// Errors in input files are printed located (file:line:col) and give exit code 1.
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "commands.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/dist/launcher.h"
#include "dayphoton/dist/mpi_session.h"
#include "dayphoton/study/output_lock.h"
#include "dayphoton/core/terminal_text.h"

#ifndef DAYPHOTON_VERSION
#define DAYPHOTON_VERSION "unknown"
#endif

namespace {

/// A finite number. CLI11's Range and PositiveNumber let NaN through (every comparison with
/// NaN is false), which then failed deep inside a command with exit 4 or, worse, printed a
/// sky of NaN; "inf" is no value either.
const CLI::Validator FiniteNumber(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0') return "expected a number, not '" + text + "'";
      if (!std::isfinite(v)) return "expected a finite number, not '" + text + "'";
      return {};
    },
    "");

/// A whole number in [lo, hi], with a short message (CLI11's NonNegativeNumber printed its
/// 300-digit upper bound). `what` names the quantity ("threads").
CLI::Validator whole_number(long long lo, long long hi, const std::string& what) {
  const std::string range = hi == std::numeric_limits<long long>::max()
                                ? std::to_string(lo) + " or more"
                                : "from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        char* end = nullptr;
        errno = 0;
        const long long v = std::strtoll(text.c_str(), &end, 10);
        if (end == text.c_str() || *end != '\0' || errno == ERANGE || v < lo || v > hi)
          return "expected a whole number of " + what + ", " + range + ", not '" + text + "'";
        return {};
      },
      hi == std::numeric_limits<long long>::max() ? "INT >= " + std::to_string(lo)
                                                  : "INT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
}

constexpr long long Unbounded = std::numeric_limits<long long>::max();
// More worker threads than this is a typo, not a machine.
constexpr long long MaxThreads = 4096;

/// Parses the command line and runs the command: the whole program of an ordinary run.
/// `agreed` (MPI ranks only) is set when the command failed alike on every rank (AgreedFailure).
int run_command_line(int argc, char** argv, dayphoton::dist::Communicator* ranks = nullptr, bool* agreed = nullptr) {
  using namespace dayphoton::app;
  CLI::App cli{"dayphoton: climate-based daylight modelling with contribution photon maps"};
  cli.name("dayphoton");
  cli.set_version_flag("--version", std::string("dayphoton ") + DAYPHOTON_VERSION);
  cli.require_subcommand(1);
  // Command-line text echoed in an error is printed with its control characters escaped.
  cli.failure_message([](const CLI::App* app, const CLI::Error& e) {
    const std::string text = CLI::FailureMessage::simple(app, e);
    std::string shown;
    for (std::size_t start = 0, end; start < text.size(); start = end + 1) {
      end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      shown += dayphoton::printable_text(std::string_view(text).substr(start, end - start)) + "\n";
    }
    return shown;
  });

  CheckOptions check;
  auto* check_cmd = cli.add_subcommand("check", "Validate a project file and print a summary of the model");
  check_cmd->add_option("project", check.project_path, "Project file (YAML)")->required();

  RunOptions run;
  auto* run_cmd = cli.add_subcommand("run", "Run the daylight study of one or more projects");
  run_cmd->add_option("projects", run.project_paths, "Project files (YAML)")->required();
  run_cmd->add_option("-o,--output", run.output_dir, "Output folder (default: results/ beside the project)");
  run_cmd->add_option("-j,--threads", run.threads, "Worker threads (default: all cores)")
      ->check(whole_number(0, MaxThreads, "threads (0: all cores)"));
  run_cmd->add_option("--cache", run.cache_dir,
                      "Cache folder (default: .<output name>-cache beside the output folder)");
  run_cmd->add_flag("--force", run.force, "Recompute every step even if cached");
  run_cmd->add_flag("-q,--quiet", run.quiet, "Print errors only");

  CleanOptions clean;
  auto* clean_cmd = cli.add_subcommand("clean", "Remove what a run's cache can no longer reuse");
  clean_cmd->add_option("target", clean.target, "Output folder of `run`, or a project file (its outputs.folder)")
      ->required();
  clean_cmd->add_option("--cache", clean.cache_dir, "Cache folder (default: the output folder's)");
  clean_cmd->add_flag("--all", clean.all, "Remove the whole cache folder");
  clean_cmd->add_flag("-n,--dry-run", clean.dry_run, "Say what would be removed, remove nothing");

  SunOptions sun;
  auto* sun_cmd = cli.add_subcommand("sun", "Sun position for every hour of a weather file (CSV)");
  sun_cmd->add_option("weather", sun.weather_path, "Weather file (EPW, or .wea by its extension)")->required();
  sun_cmd->add_option("--solar-position", sun.solar_position,
                      "spa (NREL SPA, default) or radiance (gendaymtx's formulas)")
      ->check(CLI::IsMember({"spa", "radiance"}));
  sun_cmd->add_flag("--no-refraction", sun.no_refraction, "SPA: geometric altitude (no refraction)");
  sun_cmd->add_option("-o,--output", sun.output_path, "Output CSV (default: standard output)");

  SkyOptions sky;
  auto* sky_cmd = cli.add_subcommand(
      "sky", "Annual sky matrix of a weather file, or the sky vector of a CIE sky (RADIANCE matrix format)");
  sky_cmd->add_option("weather", sky.weather_path, "Weather file (EPW, or .wea by its extension)");
  sky_cmd->add_option("--cie", sky.cie, "CIE sky instead of a weather file: 1..15 (ISO 15469), overcast, uniform");
  sky_cmd->add_option("--altitude", sky.sun_altitude_deg, "CIE general skies: sun altitude (deg)")->check(FiniteNumber);
  sky_cmd->add_option("--azimuth", sky.sun_azimuth_deg, "CIE general skies: sun azimuth (deg, clockwise from north)")
      ->check(FiniteNumber);
  sky_cmd->add_option("--illuminance", sky.horizontal_illuminance_lux,
                      "CIE skies: diffuse horizontal illuminance (lux, default 10000)")
      ->check(FiniteNumber)->check(CLI::PositiveNumber);
  sky_cmd->add_option("--basis", sky.basis, "tregenza (default) or reinhart:N");
  sky_cmd->add_option("--sun", sky.sun, "spread (into 4 patches, default), none (sky only), only (sun only)")
      ->check(CLI::IsMember({"spread", "none", "only"}));
  sky_cmd->add_option("--solar-position", sky.solar_position,
                      "spa (default) or radiance (gendaymtx-compatible: its sun formulas, patch-centre values, "
                      "sky colour, 11 C dew point)")
      ->check(CLI::IsMember({"spa", "radiance"}));
  sky_cmd->add_option("--ground-reflectance", sky.ground_reflectance, "Ground reflectance (default 0.2)")
      ->check(FiniteNumber)->check(CLI::Range(0.0, 1.0));
  sky_cmd->add_option("--format", sky.format, "ascii (default), float or double")
      ->check(CLI::IsMember({"ascii", "float", "double"}));
  sky_cmd->add_option("-o,--output", sky.output_path, "Output matrix file (default: standard output)");
  sky_cmd->add_option("--max-matrix-values", sky.max_matrix_values,
                      "Most values (bins x records x 3) of the sky matrix (default " +
                          std::to_string(sky.max_matrix_values) + ", 1 GiB of floats)")
      ->check(whole_number(1, Unbounded, "values"));

  AnnualOptions annual;
  auto* annual_cmd = cli.add_subcommand(
      "annual", "Annual illuminance and metrics from the coefficients of an earlier run (no tracing)");
  annual_cmd->add_option("--coefficients", annual.coefficients_dir,
                         "Grid folder written by `dayphoton run` (coefficients_sky.mtx, sensors.csv), or its "
                         "results folder: every grid folder below it")
      ->required();
  annual_cmd->add_option("--weather", annual.weather_path,
                         "Weather file (EPW, or .wea by its extension): time stamps, and the sky (default: the --project's weather file)");
  annual_cmd->add_option("--project", annual.project_path,
                         "Project file: its metric settings (thresholds, occupancy schedule) and weather file "
                         "(default: the settings the run recorded in results.json above the grid folder)");
  annual_cmd->add_option("--occupancy-hours", annual.occupancy_hours,
                         "START END: occupied every day from START to END (hours, local standard time; "
                         "replaces the run's or project's schedule; default 8 18)")
      ->expected(2)->check(FiniteNumber)->check(CLI::Range(0.0, 24.0));
  annual_cmd->add_option("--daylight-saving", annual.daylight_saving,
                         "none, eu or us: the occupied hours are clock time with that daylight saving time")
      ->check(CLI::IsMember({"none", "eu", "us"}));
  annual_cmd->add_option("--january-1", annual.january_1,
                         "Weekday of 1 January for a weekly schedule (default: the weather file's DATA PERIODS)")
      ->check(CLI::IsMember({"monday", "tuesday", "wednesday", "thursday", "friday", "saturday", "sunday"}));
  annual_cmd->add_option("--da-threshold", annual.da_threshold_lux, "DA, cDA and sDA threshold (lx, default 300)")
      ->check(FiniteNumber)->check(CLI::PositiveNumber);
  annual_cmd->add_option("--udi-lower", annual.udi_lower_lux, "UDI: below this it fell short (lx, default 100)")
      ->check(FiniteNumber)->check(CLI::PositiveNumber);
  annual_cmd->add_option("--udi-upper-original", annual.udi_upper_original_lux,
                         "UDI (Nabil & Mardaljevic): above this it is exceeded (lx, default 2000)")
      ->check(FiniteNumber)->check(CLI::PositiveNumber);
  annual_cmd->add_option("--udi-upper-revised", annual.udi_upper_revised_lux,
                         "revised UDI: above this it is exceeded (lx, default 3000)")
      ->check(FiniteNumber)->check(CLI::PositiveNumber);
  annual_cmd->add_option("--sda-time-fraction", annual.sda_time_fraction,
                         "sDA: fraction of occupied hours at or above the DA threshold (default 0.5)")
      ->check(FiniteNumber)->check(CLI::Range(0.0, 1.0));
  annual_cmd->add_option("--ase-threshold", annual.ase_threshold_lux,
                         "ASE: direct-sun illuminance counted (lx, default 1000)")
      ->check(FiniteNumber)->check(CLI::PositiveNumber);
  annual_cmd->add_option("--ase-hours", annual.ase_hours,
                         "ASE: a sensor counts with more than this many occupied hours at or above the threshold "
                         "(default 250)")
      ->check(FiniteNumber)->check(CLI::NonNegativeNumber);
  annual_cmd->add_option("--sky-matrix", annual.sky_matrix_path,
                         "Read the sky matrix from this RADIANCE matrix file (e.g. gendaymtx output, plain or .gz) "
                         "instead of building it from the weather file");
  annual_cmd->add_option("--sky-vector", annual.sky_vector_path,
                         "One sky (a one-column RADIANCE matrix, e.g. from `dayphoton sky --cie N`): write the "
                         "illuminance per sensor under it (sky_vector_illuminance.csv) instead of the annual study")
      ->excludes("--sky-matrix")->excludes("--weather")->excludes("--project");
  annual_cmd->add_option("-o,--output", annual.output_dir, "Output folder (default: <coefficients>/annual)");
  annual_cmd->add_option("--sun", annual.sun,
                         "exact: the run's exported direct sun (direct_sun.bin.gz), sun bins and ASE, as `run` "
                         "computes them (the default where the grid folder has them); spread: the sun spread into "
                         "the sky patches, sky coefficients only")
      ->check(CLI::IsMember({"exact", "spread"}));
  annual_cmd->add_option("--basis", annual.basis,
                         "tregenza or reinhart:N (default: from the coefficients' column count)");
  annual_cmd->add_option("--ground-reflectance", annual.ground_reflectance,
                         "Ground reflectance of the sky built from the weather file (default: the run's, from "
                         "results.json above the grid folder, else 0.2)")
      ->check(FiniteNumber)->check(CLI::Range(0.0, 1.0));
  annual_cmd->add_flag("--illuminance-csv", annual.illuminance_csv,
                       "Also write the hourly illuminance as text, illuminance.csv (illuminance.bin is always written)");
  annual_cmd->add_flag("-q,--quiet", annual.quiet, "Print errors only");
  annual_cmd->add_option("--max-matrix-values", annual.max_matrix_values,
                         "Most values of each matrix read or built and of the illuminance table (default " +
                             std::to_string(annual.max_matrix_values) + ", 1 GiB of floats)")
      ->check(whole_number(1, Unbounded, "values"));
  annual_cmd->add_option("--max-decompressed-bytes", annual.max_decompressed_bytes,
                         "Most bytes a .gz sky matrix may decompress to (default " +
                             std::to_string(annual.max_decompressed_bytes) + ")")
      ->check(whole_number(1, Unbounded, "bytes"));


  ReportOptions report;
  auto* report_cmd = cli.add_subcommand(
      "report", "Write report.html and the result images of a finished run from its output folder");
  report_cmd->add_option("results", report.results_dir, "Output folder of `dayphoton run` (with results.json)")
      ->required();
  report_cmd->add_option("-o,--output", report.output_path, "Report file (default: RESULTS/report.html)");
  report_cmd->add_flag("--no-images", report.no_images, "Only the report: no grid EXR/PNG files, no sky images");
  report_cmd->add_option("--sky-hour", report.sky_hour,
                         "M/D/H of the one-hour sky image, H in local standard time (default 6/21/12.5)");
  report_cmd->add_flag("--pdf", report.pdf,
                       "Also print the report to a PDF beside it (report.pdf) with headless Chromium");
  report_cmd->add_option("--pdf-timeout", report.pdf_timeout_s, "Seconds Chromium may take to print (default 120)")
      ->check(FiniteNumber)->check(CLI::Range(1.0, 3600.0));
  report_cmd->add_flag("-q,--quiet", report.quiet, "Print errors only");

  RenderOptions render;
  auto* render_cmd = cli.add_subcommand(
      "render", "Render a view of the model lit by a sky from photon maps (EXR radiance + tone-mapped PNG)");
  render_cmd->add_option("project", render.project_path, "Project file (YAML)")->required();
  render_cmd->add_option("--view", render.view, "Camera position x,y,z (m)")->required();
  render_cmd->add_option("--direction", render.direction, "View direction dx,dy,dz")->required();
  render_cmd->add_option("--up", render.up, "Up vector (default 0,0,1)");
  render_cmd->add_option("--fov", render.fov_deg, "Horizontal field of view (deg), or the fisheye's image circle")
      ->check(FiniteNumber)->check(CLI::Range(1.0, 360.0));
  render_cmd->add_flag("--fisheye", render.fisheye, "Angular (equidistant) fisheye instead of a perspective view");
  render_cmd->add_option("--width", render.width, "Image width (pixels, default 512)")->check(CLI::Range(1, 16384));
  render_cmd->add_option("--height", render.height, "Image height (pixels, default 384)")->check(CLI::Range(1, 16384));
  render_cmd->add_option("--sky", render.sky,
                         "overcast (default), uniform, cie:N (ISO 15469 type 1..15) or hour:M/D/H of the weather file");
  render_cmd->add_option("--illuminance", render.horizontal_illuminance_lux,
                         "overcast, uniform, cie:N: diffuse horizontal illuminance (lux, default 10000)")
      ->check(FiniteNumber)->check(CLI::PositiveNumber);
  render_cmd->add_option("--sun-altitude", render.sun_altitude_deg, "cie:N: sun altitude (deg, default 45)")
      ->check(FiniteNumber);
  render_cmd->add_option("--sun-azimuth", render.sun_azimuth_deg,
                         "cie:N: sun azimuth (deg clockwise from north, default 180)")
      ->check(FiniteNumber);
  render_cmd->add_option("--samples", render.samples_per_pixel, "Samples per pixel (default 4)")
      ->check(CLI::Range(1, 4096));
  render_cmd->add_option("--direct-samples", render.direct_samples,
                         "Shadow rays toward the windows per surface point (default 16)")
      ->check(CLI::Range(1, 4096));
  render_cmd->add_option("--photons", render.photons_per_bin, "Stored photons per sky bin (default: the project's)")
      ->check(whole_number(0, Unbounded, "photons"));
  render_cmd->add_option("--bandwidth", render.bandwidth, "Photons per density estimate (default 200)")
      ->check(CLI::Range(1, 100000));
  render_cmd->add_option("-o,--output", render.output_path, "Output EXR (the PNG is written beside it)")->required();
  render_cmd->add_option("-j,--threads", render.threads, "Worker threads (default: all cores)")
      ->check(whole_number(0, MaxThreads, "threads (0: all cores)"));
  render_cmd->add_flag("-q,--quiet", render.quiet, "Print errors only");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    cli.exit(e);
    return ExitUsageError;
  }

  try {
    if (check_cmd->parsed()) return run_check(check, std::cout);
    if (run_cmd->parsed()) {
      run.ranks = ranks;
      return run_run(run, std::cout, std::cerr);
    }
    if (clean_cmd->parsed()) return run_clean(clean, std::cout);
    if (sun_cmd->parsed()) return run_sun(sun, std::cout);
    if (sky_cmd->parsed()) {
      sky.cie_options_given = sky_cmd->count("--altitude") + sky_cmd->count("--azimuth") +
                                  sky_cmd->count("--illuminance") > 0;
      std::string command_line = "dayphoton";
      for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
      return run_sky(sky, command_line, std::cout);
    }
    if (annual_cmd->parsed()) {
      annual.ground_reflectance_given = annual_cmd->count("--ground-reflectance") > 0;
      return run_annual(annual, std::cout);
    }
    if (report_cmd->parsed()) return run_report(report, std::cout);
    if (render_cmd->parsed()) return run_render(render, std::cout);
  } catch (const AgreedFailure& e) {  // every rank of the job failed alike; rank 0 printed why
    if (agreed) *agreed = true;
    return e.exit_code();
  } catch (...) {
    const CommandFailure failure = describe_failure(std::current_exception());
    std::cerr << failure.message;
    return failure.exit_code;
  }
  return ExitUsageError;
}

/// The command of a command line: its first argument that is not an option.
std::string command_of(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] != '-') return argv[i];
  return "";
}

/// A process started by mpirun or srun: MPI for the process's lifetime. `run` is distributed
/// (docs/cluster.md): every rank runs it, sharing out the steps of the study; rank 0 prints
/// and writes, the other ranks' output is kept and shown only if they fail alone. Every other
/// command runs on rank 0 alone while the others wait for it (asleep, at a barrier), so that
/// the job ends with rank 0's exit code and one set of outputs.
int run_as_mpi_rank(int argc, char** argv, const dayphoton::dist::LauncherInfo& launcher) {
  using namespace dayphoton::app;
  using namespace dayphoton::dist;
  std::optional<MpiSession> session;
  try {
    session.emplace(&argc, &argv);
  } catch (const MpiUnavailable& e) {
    // One copy of a build without MPI is an ordinary run; several would race for one output folder.
    if (launcher.process_count == 1) return run_command_line(argc, argv);
    std::cerr << "dayphoton: error: " << e.what() << " (" << launcher.variable << " is set)\n";
    return ExitUsageError;
  } catch (const std::exception& e) {
    std::cerr << "dayphoton: error: " << e.what() << '\n';
    return ExitInternalError;
  }
  int code = ExitOk;
  {
    const std::unique_ptr<Communicator> world = session->world();
    if (world->size() > 1 && command_of(argc, argv) == "run") {
      // A failure every rank agreed on (the inputs' checks, commands.h agree_on_failure) was
      // printed once, by rank 0: each rank exits with its code, no rank waits for another.
      bool agreed = false;
      if (world->rank() == RootRank) {
        code = run_command_line(argc, argv, world.get(), &agreed);
        // Its message is out; the other ranks may be waiting for it in a step: end them too.
        if (code != ExitOk && !agreed) world->abort_all("the run failed on rank 0; every rank is stopped", code);
      } else {
        // The same lines as rank 0's, so kept back; a failing rank shows them (prefixed by its
        // rank) and ends the whole job, which never waits on a rank that stopped.
        std::ostringstream out, err;
        std::streambuf* const cout_buffer = std::cout.rdbuf(out.rdbuf());
        std::streambuf* const cerr_buffer = std::cerr.rdbuf(err.rdbuf());
        code = run_command_line(argc, argv, world.get(), &agreed);
        std::cout.rdbuf(cout_buffer);
        std::cerr.rdbuf(cerr_buffer);
        if (code != ExitOk && !agreed) world->abort_all(err.str(), code);
      }
    } else {
      if (world->rank() == RootRank) {
        if (world->size() > 1)
          std::cerr << "dayphoton: note: started as " << world->size()
                    << " MPI processes; only `run` distributes its work, rank 0 runs this one alone "
                       "(docs/cluster.md)\n";
        code = run_command_line(argc, argv);
      }
    }
    world->barrier();
  }
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  // Only a process started by a parallel launcher touches MPI (dist/launcher.h).
  const auto launcher = dayphoton::dist::detect_launcher([](const char* name) { return std::getenv(name); });
  if (!launcher) return run_command_line(argc, argv);
  return run_as_mpi_rank(argc, argv, *launcher);
}
