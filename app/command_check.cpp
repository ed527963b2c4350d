// `dayphoton check PROJECT.yaml`: load and validate a project (file, weather, geometry) and
// print what the model contains, so a user can see that the file says what they meant.
#include <cmath>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>

#include "commands.h"
#include "dayphoton/core/polygon.h"
#include "dayphoton/core/units.h"
#include "dayphoton/project/project.h"
#include "model_summary.h"

namespace dayphoton::app {

int run_check(const CheckOptions& options, std::ostream& out) {
  const project::Project proj = project::load_project(options.project_path);
  const ModelSummary summary = summarize_model(proj);
  print_model_summary(summary, out);
  out << "ok: " << options.project_path << " is valid\n";
  return ExitOk;
}

}  // namespace dayphoton::app
