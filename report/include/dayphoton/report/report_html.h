// report.html: the daylight-factor and annual report a person reads (issue 7 item 1), made
// from a run's results model (results.json, study/results_model.h) and the per-sensor value
// tables it names, so that `dayphoton report RESULTS_DIR` works on any finished run, moved or
// copied, without its project file (which is never read: an edited project would describe
// another building than the results).
//
// One self-contained file: no script, style sheet, font or image is fetched (inline CSS, inline
// SVG, PNGs as data: URIs), so it opens offline and can be mailed. Sections (element ids; the
// page lists them in <body data-sections> and an inline script checks that each rendered and
// writes the outcome into #report-check, which the headless-browser test reads):
//   summary    project, site position in numbers, weather station (the EPW's LOCATION line,
//              when the weather file is still there), simulation settings, versions, notes
//   overview   one row per grid and case: DF, DA, sDA, ASE, EN 17037
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
// The room outline, the windows and the lattice of each grid are the model's (recorded by the
// run): all openings on the plan of a horizontal grid, only those in its wall on the elevation
// of a wall or rectangle grid. Colour scales: colour_scale.h. Print: @media print rules keep
// each plot on one page, print colours exactly and hide the navigation.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/report/result_images.h"
#include "dayphoton/study/results_model.h"

namespace dayphoton::report {

/// The report's HTML text from `model`; value tables are read from `results_dir`. A grid
/// whose tables are missing or malformed gets a section that says what could not be read,
/// and the rest of the report is still written.
std::string report_html(const std::string& results_dir, const study::ResultsModel& model);

/// The same with the model read from <results_dir>/results.json (InputError, located, if it
/// is missing, e.g. in a results folder of an older dayphoton, or malformed).
std::string report_html(const std::string& results_dir);

/// Write report_html() atomically to `output_path` (default <results_dir>/report.html);
/// returns the path.
std::string write_report(const std::string& results_dir, const std::string& output_path = {});
std::string write_report(const std::string& results_dir, const study::ResultsModel& model,
                         const std::string& output_path = {});

/// What write_images_and_report writes.
struct ViewOutputs {
  bool images = true;    ///< grid EXR/PNG (write_grid_images) and sky fisheyes (write_sky_images)
  bool report = true;    ///< report.html
  YearHour sky_hour;     ///< the hour of sky_hour.exr (default 21 June, EPW hour 13)
};

/// Everything for viewing a finished run, in the order the report needs it: the images of
/// every grid of every case, the sky images, then report.html. Returns the paths written.
/// `dayphoton run` calls it (through study::RunSettings::write_views) after results.json.
std::vector<std::string> write_images_and_report(const std::string& results_dir, const study::ResultsModel& model,
                                                 const ViewOutputs& outputs = {});

/// The same with the model read from <results_dir>/results.json.
std::vector<std::string> write_images_and_report(const std::string& results_dir, const ViewOutputs& outputs = {});

/// write_images_and_report with the default sky hour, in the shape of
/// study::RunSettings::write_views (what `dayphoton run` sets it to).
std::vector<std::string> write_views(const std::string& results_dir, const study::ResultsModel& model, bool images,
                                     bool report);

}  // namespace dayphoton::report
