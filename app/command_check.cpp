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
  // Each variant's scene is generated and validated like the base's (its errors are located
  // in the variant), so `check` finds what `run` would; nothing is printed before.
  std::ostringstream variants;
  for (const project::VariantSpec& v : proj.variants) {
    const SceneDescription scene = project::build_scene_description(project::apply_variant(proj, v));
    std::string changes;
    for (const std::string& c : project::variant_changes(v)) changes += (changes.empty() ? "" : ", ") + c;
    variants << "variant " << v.name << ": " << changes << " (" << scene.surfaces.size() << " surfaces, base "
             << summary.scene.surfaces.size() << ")\n";
  }
  print_model_summary(summary, out);
  out << variants.str();
  out << "ok: " << options.project_path << " is valid\n";
  return ExitOk;
}

}  // namespace dayphoton::app
