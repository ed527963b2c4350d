// `dayphoton report RESULTS_DIR`: report.html and the result images (grid EXR/PNG, sky
// fisheyes) of a finished `dayphoton run`, from the files in its output folder alone
// (study/report_html.h; docs/report.md).
#include <ostream>

#include "commands.h"
#include "dayphoton/study/report_html.h"

namespace dayphoton::app {

int run_report(const ReportOptions& options, std::ostream& out) {
  study::ViewOutputs which;
  which.images = !options.no_images;
  which.report = false;  // written below, to --output if given
  try {
    which.sky_hour = study::parse_year_hour(options.sky_hour);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--sky-hour: ") + e.what());
  }
  std::vector<std::string> written = study::write_images_and_report(options.results_dir, which);
  written.push_back(study::write_report(options.results_dir, options.output_path));
  if (!options.quiet)
    for (const std::string& path : written) out << "wrote " << path << "\n";
  require_written(out, "standard output");
  return ExitOk;
}

}  // namespace dayphoton::app
