// The sections of report.html that are made from the results model alone, one file each
// (report_html.cpp assembles them with the per-grid sections and the sky). Every function
// returns a <section> with the id named here; numbers go through report_format.h. Internal
// to report/.
#pragma once

#include <string>

#include "dayphoton/study/results_model.h"

namespace dayphoton::report {

/// "summary" (summary_section.cpp): per case and grid mean and median DF, sDA, ASE, UDI,
/// EN 17037 level and the verdicts, then what was not assessed. The first thing a reader sees.
std::string summary_section(const study::ResultsModel& model);

/// "verdicts" (summary_section.cpp): every verdict of every grid with its requirement, value
/// and standard.
std::string verdicts_section(const study::ResultsModel& model);

/// "sunlight" (sunlight_section.cpp): EN 17037 exposure to sunlight, a row per case and room
/// (hours, level, spells, each window's hours). Empty when the run did not assess it.
std::string sunlight_section(const study::ResultsModel& model);

/// "building" (building_section.cpp): rooms and windows (dimensions, areas, window-to-wall
/// and window-to-floor ratios), materials (type, reflectance, transmittance, area), sensor
/// grids (sensors, spacing, orientation).
std::string building_section(const study::ResultsModel& model);

/// "variants" (variants_section.cpp): the cases side by side per grid, with the difference
/// of each from the base case, what each variant changes and its materials that differ.
/// Empty when the run has one case.
std::string variants_section(const study::ResultsModel& model);

/// "methods" (methods_section.cpp): what was computed and how, the validation figures
/// (validation_figures.h) and the uncertainty the run reached per grid.
std::string methods_section(const study::ResultsModel& model);

/// The accuracy statements (accuracy_statements.cpp), part of the methods section: per case
/// and grid, in plain words, what the accuracy target's rounds reached for the sky patches
/// (the daylight factor) and for the sun bins (the annual sun-bin illuminance), why they
/// stopped and, for a grid above the target, why and what to change. Empty when the run gave
/// photon counts.
std::string accuracy_statements(const study::ResultsModel& model);
/// The statement of one grid's sky or sun accuracy (no markup around it).
std::string sky_accuracy_statement(const study::DaylightFactorSummary::AccuracyReached& accuracy);
std::string sun_accuracy_statement(const study::SunAccuracyReached& accuracy);

/// "appendix" (appendix_section.cpp): site, weather station, simulation settings, the run's
/// times per step (timings.json in `results_dir`, read through study::read_run_timings; a
/// folder without it says so), versions and notes.
std::string appendix_section(const study::ResultsModel& model, const std::string& results_dir);

/// The element id of a grid's section: "grid-<grid>" or "grid-<case>--<grid>".
std::string grid_section_id(const study::CaseResult& c, const study::GridResult& g);

/// "base", the variant's name, or the operated case's name.
std::string case_label(const study::CaseResult& c);

}  // namespace dayphoton::report
