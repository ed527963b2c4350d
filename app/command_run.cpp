// `dayphoton run PROJECT.yaml...`: the full daylight study. Until the photon engine, the
// sky matrices and the annual pipeline exist (issues 3-5), it validates the projects, prints
// their summary, says plainly which steps are missing, writes nothing and exits non-zero.
#include <ostream>

#include "commands.h"
#include "dayphoton/project/project.h"
#include "model_summary.h"

namespace dayphoton::app {

int run_run(const RunOptions& options, std::ostream& out, std::ostream& err) {
  for (const std::string& path : options.project_paths) {
    const project::Project proj = project::load_project(path);
    const ModelSummary summary = summarize_model(proj);
    if (!options.quiet) print_model_summary(summary, out);
  }
  err << "dayphoton run: not implemented yet: photon tracing, daylight coefficients, annual\n"
         "sky multiplication and metrics are still to be built. The projects above are valid;\n"
         "no output was written.\n";
  return ExitNotImplemented;
}

}  // namespace dayphoton::app
