// `dayphoton report RESULTS_DIR`: report.html and the result images (grid EXR/PNG, sky
// fisheyes) of a finished `dayphoton run`, from its results model (results.json) and the value
// tables it names; the project file is never read (report/report_html.h; docs/report.md). A
// results folder of an older dayphoton, without results.json, is an input error that says to
// run the study again. With --pdf the written report is printed to a PDF beside it (same
// name, extension .pdf) by headless Chromium (report/report_pdf.h); without Chromium that is
// a usage error naming the package, after report.html was written.
#include <filesystem>
#include <ostream>

#include "commands.h"
#include "dayphoton/report/report_html.h"
#include "dayphoton/report/report_pdf.h"

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
  const std::string html = report::write_report(options.results_dir, model, options.output_path);
  written.push_back(html);
  if (options.pdf) {
    report::PdfSettings settings;
    settings.timeout_s = options.pdf_timeout_s;
    const std::string pdf = std::filesystem::path(html).replace_extension(".pdf").string();
    try {
      written.push_back(report::print_pdf(html, pdf, settings));
    } catch (const report::PdfPrinterMissing& e) {
      if (!options.quiet)
        for (const std::string& p : written) out << "wrote " << p << "\n";
      throw UsageError(std::string("--pdf: ") + e.what());
    }
  }
  if (!options.quiet)
    for (const std::string& p : written) out << "wrote " << p << "\n";
  require_written(out, "standard output");
  return ExitOk;
}

}  // namespace dayphoton::app
