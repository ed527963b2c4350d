// `dayphoton report RESULTS_DIR`: report.html and the result images (grid EXR/PNG, sky
// fisheyes) of a finished `dayphoton run`, from its results model (results.json) and the value
// tables it names; the project file is never read (report/report_html.h; docs/report.md). A
// results folder of an older dayphoton, without results.json, is an input error that says to
// run the study again.
#include <ostream>

#include "commands.h"
#include "dayphoton/report/report_html.h"

namespace dayphoton::app {

int run_report(const ReportOptions& options, std::ostream& out) {
  report::ViewOutputs which;
  which.images = !options.no_images;
  which.report = false;  // written below, to --output if given
  try {
    which.sky_hour = study::parse_year_hour(options.sky_hour);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--sky-hour: ") + e.what());
  }
  const study::ResultsModel model = study::read_results_model(options.results_dir);
  std::vector<std::string> written = report::write_images_and_report(options.results_dir, model, which);
  written.push_back(report::write_report(options.results_dir, model, options.output_path));
  if (!options.quiet)
    for (const std::string& p : written) out << "wrote " << p << "\n";
  require_written(out, "standard output");
  return ExitOk;
}

}  // namespace dayphoton::app
