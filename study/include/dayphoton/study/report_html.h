// report.html: the daylight-factor and annual report a person reads (issue 7 item 1), made
// from the files of a results folder alone (summary.json and each grid's CSV/binary tables,
// docs/outputs.md), so that `dayphoton report RESULTS_DIR` works on any finished run.
//
// One self-contained file: no script, style sheet, font or image is fetched (inline CSS, inline
// SVG, PNGs as data: URIs), so it opens offline and can be mailed. Sections (element ids; the
// page lists them in <body data-sections> and an inline script checks that each rendered and
// writes the outcome into #report-check, which the headless-browser test reads):
//   summary    project, site position in numbers, weather station (the EPW's LOCATION line),
//              simulation settings, versions, run time per step (summary.json timings), notes
//   overview   one row per grid and variant: DF, DA, sDA, ASE, EN 17037
//   grid-<name>  per grid (variants: grid-<variant>--<name>), with sub-sections
//     -df          false-colour plan of the daylight factor with room outline and windows,
//                  DF statistics
//     -da          plan of DA (threshold from the run)
//     -udi         plans of UDI achieved (Nabil & Mardaljevic) and UDI autonomous (revised),
//                  the grid's time shares in both conventions
//     -compliance  sDA / ASE against IES LM-83 (sDA300/50% >= 55 % nominally accepted,
//                  >= 75 % preferred; ASE1000,250 <= 10 %), EN 17037 levels
//     -temporal    day of year x hour map of the grid's mean illuminance (illuminance.bin)
//     -histograms  distribution of DF and of DA over the sensors
//     -metrics     the table of grid metrics with units
//   sky        fisheyes of the annual mean sky and of one hour, if sky_mean.exr / sky_hour.exr
//              exist (write_sky_images)
// The room outline and the windows come from the project file named in summary.json when it
// still loads (the grid's outline; ports drawn in the plan's frame: all of them on the plan of a
// horizontal grid, only those in its wall on the elevation of a wall or rectangle grid); otherwise the plan shows
// the sensors' extent and says so. Colour scales: colour_scale.h. Print: @media print rules
// keep each plot on one page, print colours exactly and hide the navigation.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/study/result_images.h"

namespace dayphoton::study {

/// The report's HTML text. Throws InputError (located) if summary.json is missing or not a
/// JSON object; a grid whose tables are missing or malformed gets a section that says what
/// could not be read, and the rest of the report is still written.
std::string report_html(const std::string& results_dir);

/// The same from `summary_json`, the text of the run's summary (what `run` writes as
/// summary.json after the report, as its last file) instead of the folder's summary.json.
std::string report_html(const std::string& results_dir, const std::string& summary_json);

/// Write report_html() atomically to `output_path` (default <results_dir>/report.html);
/// returns the path.
std::string write_report(const std::string& results_dir, const std::string& output_path = {});

/// What write_images_and_report writes.
struct ViewOutputs {
  bool images = true;    ///< grid EXR/PNG (write_grid_images) and sky fisheyes (write_sky_images)
  bool report = true;    ///< report.html
  YearHour sky_hour;     ///< the hour of sky_hour.exr (default 21 June, EPW hour 13)
};

/// Everything for viewing a finished run, in the order the report needs it: the images of
/// every grid of summary.json (base case and variants), the sky images, then report.html.
/// Returns the paths written. This is the one call `dayphoton run` makes after summary.json.
std::vector<std::string> write_images_and_report(const std::string& results_dir, const ViewOutputs& outputs = {});

/// The same from `summary_json` (see report_html above): what `dayphoton run` calls before it
/// writes summary.json.
std::vector<std::string> write_images_and_report(const std::string& results_dir, const ViewOutputs& outputs,
                                                 const std::string& summary_json);

}  // namespace dayphoton::study
