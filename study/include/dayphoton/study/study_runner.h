// run_study: one project from file to results (issue 5; DESIGN.md sections 1, 2 and 6).
//
// Steps, each cached in the cache folder by the hash of its inputs (cache_keys.h) and each
// written atomically, so an interrupted run resumes from what it had finished. The options
// come from one SimulationPlan (simulation_plan.h) and every cached step goes through one
// StepExecutor (step_executor.h); docs/architecture.md "Plan and executor":
//   1. scene      : project -> SceneDescription -> Embree scene, materials, sources
//   2. photons    : the forward pass, ONE CACHED ARTEFACT PER SOURCE (a killed run loses at
//                   most the sources in flight)
//   3. coefficients per grid: direct (shadow rays) + caustic + global photon estimates
//   4. daylight factor per grid: coefficients x CIE overcast sky vector (10 000 lux,
//                   ground from the project's ground reflectance)
//   5. sky matrix  : the weather file's hourly Perez skies, RADIANCE-compatible (gendaymtx
//                   conventions); with `sun: spread` the sun is spread into the 4 nearest
//                   patches, with `sun: bins` (the default) it is left out and listed hour
//                   by hour instead
//   5b. sun bins (`sun: bins`, study/annual_sun.h): the Reinhart MF sun_mf patch centres
//                   on the year's sun path, each a sun disc with its own photons (one cached
//                   artefact per bin); per grid their caustic + global coefficients and the
//                   exact direct sun of every hour (shadow rays)
//   6. annual      : sky coefficients x sky matrix (+ direct sun + interpolated indirect sun)
//                   -> illuminance, metrics (ASE from the direct sun in the sun-bins mode)
//   6b. operated   : with a project `operation` (sun: bins), per grid and hour the shaded
//                   case's illuminance when more than 2 % of the sensors see direct sun in
//                   the open case (LM-83 blinds rule, operated_shading.h), into
//                   <output>/operated/<grid>/; computed from the two cases' annual tables,
//                   whose inputs come from the cache as above
//   7. files       : results.json (the typed results model, results_model.h), then per grid
//                   folder images and report.html (RunSettings::write_views, made from the
//                   model), then summary.json last, with the size and SHA-256 of every output
//                   (result_files.h, docs/outputs.md)
// Before step 1 the run takes the output folder's lock (output_lock.h; OutputFolderBusy when
// another run holds it), deletes temporaries of killed writers and the previous run's outputs,
// and marks the folder INCOMPLETE until summary.json is written (output_manifest.h).
// Under MPI with at least as many cases (base and variants) as ranks, each rank first runs
// the steps of its own cases alone (case_units.h); the cases then run from the cache. Several
// projects of one command go the same way, their cases the units (run_case_steps).
// The writer flag is the executor's writes_results() (step_executor.h): false on the ranks
// other than 0 of an MPI run, which then run every step with the others but take no lock,
// write no marker, run.log, result file or used-by-last-run.txt, and create no folder.
// The run log (<output>/run.log, and the progress output) states for every step whether it
// was computed or taken from the cache, e.g. "photons: traced 0 of 146 sources (146 cached)".
#pragma once

#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/run_inputs.h"
#include "dayphoton/study/step_executor.h"

namespace dayphoton::study {

struct RunSettings {
  std::string output_dir;  ///< empty: the project's outputs.folder
  std::string cache_dir;   ///< empty: beside the output folder (cache_folder.h)
  bool force = false;      ///< ignore the cache (recompute and overwrite)
  std::string version;     ///< dayphoton's version, recorded in summary.json
  std::string command;     ///< the command line, recorded in the output folder's lock file
  /// Writes the views of a finished run (images if `images`, report.html if `report`) from
  /// its results model and returns the paths written; called after results.json and before
  /// summary.json when the project asks for images or a report. The app sets it to the report
  /// library's writer (report/); empty: no images and no report (the study library does not
  /// depend on the report).
  std::function<std::vector<std::string>(const std::string& output_dir, const ResultsModel& model, bool images,
                                         bool report)>
      write_views;
  /// The executor every cached step goes through (step_executor.h); empty: this machine's
  /// (make_local_executor). `dayphoton run` under mpirun gives each rank the distributed one
  /// (distributed_executor.h).
  std::function<std::unique_ptr<StepExecutor>(const ArtifactStore& store, bool force)> make_executor;
  /// Called once the inputs run_study reads itself (the weather file, the site of its sun, the
  /// points in time, the operation's sun mode) are checked, before anything is written, with
  /// their failure or null; it throws to end the run. Empty: the failure is rethrown. Under
  /// mpirun the app makes the ranks agree on it here, so that rank 0 alone prints it.
  std::function<void(const std::exception_ptr& failure)> inputs_checked;
  /// The project's inputs, read already (run_inputs.h; `dayphoton run` reads every project's
  /// first); null: run_study reads them. inputs_checked is called either way.
  const RunInputs* inputs = nullptr;
  /// Whether the run may hand its cases out as units (case_units.h); false when the command
  /// made its projects' cases units already (run_case_steps), whose line `units_line` is
  /// then, for the run log.
  bool cases_as_units = true;
  std::string units_line;
  /// The project's cache as the command's units used it (a copy shares its list of used
  /// artefacts, artifact_store.h: what the units stored is used by this run, which then
  /// takes only what it needs from it); null: a store of run_cache_folder.
  const ArtifactStore* store = nullptr;
};

struct GridReport {
  std::string name;
  std::size_t sensors = 0;
  std::string folder;
};

struct RunReport {
  std::string output_dir;
  std::size_t sources = 0, sources_traced = 0, sources_cached = 0;
  std::size_t grids_estimated = 0, grids_cached = 0;
  bool sky_matrix_cached = false;
  std::size_t sun_bins = 0;         ///< sun bins of all cases (sun: bins)
  std::size_t sun_bins_lit = 0;     ///< of which send light through the ports (traced or cached)
  std::size_t sun_bins_traced = 0;  ///< of which were traced in this run
  /// Sources (all cases) and sun bins whose main pass hit the low-yield cap
  /// (engine::TracingOptions::max_mainpass_attempts_per_target), counted over the photons
  /// traced or read from the cache in this run (none when every grid's coefficients were cached).
  std::size_t sources_capped = 0, sun_bins_capped = 0;
  std::vector<GridReport> grids;
  std::vector<std::string> notes;  ///< things the user should know (e.g. sun mode)
};

/// The cache folder of `project`'s run with `settings`: settings.cache_dir, else beside the
/// output folder (cache_folder.h).
std::string run_cache_folder(const project::Project& project, const RunSettings& settings);

/// The steps of case `case_index` of `project` (0: the base project, then each variant in
/// order) through `executor`, the unit executor of the project's cache `store`
/// (case_units.h), with the project's `inputs` (read_run_inputs): several projects of one
/// command as units under mpirun. Writes nothing itself (its lines go to the progress output
/// only); the project's run_study, with cases_as_units false, then takes every step from the
/// cache.
void run_case_steps(const project::Project& project, const RunInputs& inputs, std::size_t case_index,
                    const RunSettings& settings, const ArtifactStore& store, StepExecutor& executor,
                    Progress& progress);

/// Run the study of `project`. Throws InputError for bad input (weather file), OutputFolderBusy
/// when another run holds the output folder, EngineError or std::runtime_error for failures;
/// nothing is left half-written, and an interrupted run leaves the folder marked INCOMPLETE.
RunReport run_study(const project::Project& project, const RunSettings& settings,
                    Progress& progress);

}  // namespace dayphoton::study
