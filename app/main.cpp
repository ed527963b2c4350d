// dayphoton command line: parses options with CLI11 and dispatches to app/command_*.cpp.
// Errors in input files are printed located (file:line:col) and give exit code 1.
#include <CLI/CLI.hpp>

#include <iostream>

#include "commands.h"
#include "dayphoton/core/diagnostics.h"

#ifndef DAYPHOTON_VERSION
#define DAYPHOTON_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  using namespace dayphoton::app;
  CLI::App cli{"dayphoton: climate-based daylight modelling with contribution photon maps"};
  cli.name("dayphoton");
  cli.set_version_flag("--version", std::string("dayphoton ") + DAYPHOTON_VERSION);
  cli.require_subcommand(1);

  CheckOptions check;
  auto* check_cmd = cli.add_subcommand("check", "Validate a project file and print a summary of the model");
  check_cmd->add_option("project", check.project_path, "Project file (YAML)")->required();

  RunOptions run;
  auto* run_cmd = cli.add_subcommand("run", "Run the daylight study of one or more projects");
  run_cmd->add_option("projects", run.project_paths, "Project files (YAML)")->required();
  run_cmd->add_option("-o,--output", run.output_dir, "Output folder (default: results/ beside the project)");
  run_cmd->add_option("-j,--threads", run.threads, "Worker threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  run_cmd->add_flag("--force", run.force, "Recompute every step even if cached");
  run_cmd->add_flag("-q,--quiet", run.quiet, "Print errors only");

  SunOptions sun;
  auto* sun_cmd = cli.add_subcommand("sun", "Sun position for every hour of a weather file (CSV)");
  sun_cmd->add_option("weather", sun.weather_path, "Weather file (EPW)")->required();
  sun_cmd->add_option("--solar-position", sun.solar_position,
                      "spa (NREL SPA, default) or radiance (gendaymtx's formulas)")
      ->check(CLI::IsMember({"spa", "radiance"}));
  sun_cmd->add_flag("--no-refraction", sun.no_refraction, "SPA: geometric altitude (no refraction)");
  sun_cmd->add_option("-o,--output", sun.output_path, "Output CSV (default: standard output)");

  SkyOptions sky;
  auto* sky_cmd = cli.add_subcommand(
      "sky", "Annual sky matrix of a weather file, or the sky vector of a CIE sky (RADIANCE matrix format)");
  sky_cmd->add_option("weather", sky.weather_path, "Weather file (EPW)");
  sky_cmd->add_option("--cie", sky.cie, "CIE sky instead of a weather file: 1..15 (ISO 15469), overcast, uniform");
  sky_cmd->add_option("--altitude", sky.sun_altitude_deg, "CIE general skies: sun altitude (deg)");
  sky_cmd->add_option("--azimuth", sky.sun_azimuth_deg, "CIE general skies: sun azimuth (deg, clockwise from north)");
  sky_cmd->add_option("--illuminance", sky.horizontal_illuminance_lux,
                      "CIE skies: diffuse horizontal illuminance (lux, default 10000)")
      ->check(CLI::PositiveNumber);
  sky_cmd->add_option("--basis", sky.basis, "tregenza (default) or reinhart:N");
  sky_cmd->add_option("--sun", sky.sun, "spread (into 4 patches, default), none (sky only), only (sun only)")
      ->check(CLI::IsMember({"spread", "none", "only"}));
  sky_cmd->add_option("--solar-position", sky.solar_position,
                      "spa (default) or radiance (gendaymtx-compatible: its sun formulas, patch-centre values, "
                      "sky colour, 11 C dew point)")
      ->check(CLI::IsMember({"spa", "radiance"}));
  sky_cmd->add_option("--ground-reflectance", sky.ground_reflectance, "Ground reflectance (default 0.2)")
      ->check(CLI::Range(0.0, 1.0));
  sky_cmd->add_option("--format", sky.format, "ascii (default), float or double")
      ->check(CLI::IsMember({"ascii", "float", "double"}));
  sky_cmd->add_option("-o,--output", sky.output_path, "Output matrix file (default: standard output)");

  AnnualOptions annual;
  auto* annual_cmd = cli.add_subcommand(
      "annual", "Annual illuminance and metrics from the sky coefficients of an earlier run (no tracing)");
  annual_cmd->add_option("--coefficients", annual.coefficients_dir,
                         "Grid folder written by `dayphoton run` (coefficients_sky.mtx, sensors.csv)")
      ->required();
  annual_cmd->add_option("--weather", annual.weather_path, "Weather file (EPW): time stamps, and the sky")->required();
  annual_cmd->add_option("--sky-matrix", annual.sky_matrix_path,
                         "Read the sky matrix from this RADIANCE matrix file (e.g. gendaymtx output, plain or .gz) "
                         "instead of building it from the weather file");
  annual_cmd->add_option("-o,--output", annual.output_dir, "Output folder (default: <coefficients>/annual)");
  annual_cmd->add_option("--basis", annual.basis,
                         "tregenza or reinhart:N (default: from the coefficients' column count)");
  annual_cmd->add_option("--ground-reflectance", annual.ground_reflectance,
                         "Ground reflectance of the sky built from the weather file (default: the run's, from "
                         "summary.json beside the grid folder, else 0.2)")
      ->check(CLI::Range(0.0, 1.0));
  annual_cmd->add_flag("-q,--quiet", annual.quiet, "Print errors only");

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
    if (run_cmd->parsed()) return run_run(run, std::cout, std::cerr);
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
  } catch (const dayphoton::InputError& e) {
    std::cerr << e.what();
    return ExitInputError;
  } catch (const UsageError& e) {
    std::cerr << "dayphoton: error: " << e.what() << '\n';
    return ExitUsageError;
  } catch (const std::exception& e) {
    std::cerr << "dayphoton: error: " << e.what() << '\n';
    return ExitInternalError;
  }
  return ExitUsageError;
}
