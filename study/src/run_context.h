// What the phases of one `dayphoton run` share (private to study/): the run log, the plan,
// the executor, the caches of the annual sky, and where results go. study_runner.cpp makes
// it; the phase files (sky_steps, sky_coefficient_steps, sun_bin_steps, points_in_time_case,
// operated_case) take it.
#pragma once

#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "dayphoton/core/error_text.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/content_hash.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/output_manifest.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/results_model_builder.h"
#include "dayphoton/study/simulation_plan.h"
#include "dayphoton/study/step_executor.h"
#include "dayphoton/study/study_runner.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

/// The run log (<output>/run.log): every line also goes to the progress output, and to the
/// file at once, so an interrupted run's log says how far it got. The run's history (what was
/// computed or came from the cache, step times) is here, not in the results, so that a
/// repeated run writes byte-identical results. An empty path: no file (a process that writes
/// nothing, the ranks other than 0 of an MPI run), the lines go to the progress output only.
class RunLog {
 public:
  RunLog(Progress& progress, const std::string& path) : m_progress(progress), m_path(path) {
    if (path.empty()) return;
    m_file.open(path, std::ios::trunc | std::ios::binary);
    if (!m_file) throw std::runtime_error("cannot write " + path + ": " + error_text(errno));
  }
  void line(const std::string& text) {
    m_progress.note(text);
    quiet_line(text);
  }
  /// A line for the file only (not shown as progress).
  void quiet_line(const std::string& text) {
    if (m_path.empty()) return;
    m_file << text << "\n";
    m_file.flush();
    if (!m_file) throw std::runtime_error("cannot write " + m_path + ": " + error_text(errno));
  }

 private:
  Progress& m_progress;
  std::string m_path;
  std::ofstream m_file;
};

/// What every case (the base project and each variant) of one run shares.
struct RunContext {
  const RunSettings& settings;
  Progress& progress;
  RunLog& log;
  RunReport& report;
  const ArtifactStore& store;  ///< the cache (the accuracy rounds use it directly, accuracy_rounds.h)
  OutputManifest& outputs;  ///< every output file written, for summary.json `files`
  const SimulationPlan& plan;  ///< built once from the project (simulation_plan.h)
  StepExecutor& executor;      ///< every cached step goes through it (step_executor.h)
  std::optional<AnnualSky> sky;  ///< built or loaded once, on first use (sun spread)
  std::optional<SkyAndSuns> sky_and_suns;  ///< the same for the sun-bins mode
  const weather::HourlyWeather* weather = nullptr;   ///< the project's weather file, if it has one
  const SunSite* sun_site = nullptr;       ///< the site its sun is computed for (sun_site.h)
  CaseResult* results = nullptr;  ///< the case being run, in the results model (results_model_builder.h)
  /// The daylight openings of each sensor set of the case being run, by name
  /// (daylight_openings.h; operated shading's two cases differ by their shading only, so they
  /// share them).
  std::map<std::string, metrics::MetricSettings::Openings> openings{};
  /// The scene warnings already in the log (location and message): a variant's scene repeats
  /// its base's imported files, and their warnings are logged once, by the first case.
  std::set<std::string> scene_warnings_logged{};
  /// Sensor set `name`'s openings; vertical or inclined for a name not recorded.
  metrics::MetricSettings::Openings openings_of(const std::string& name) const {
    const auto it = openings.find(name);
    return it == openings.end() ? metrics::MetricSettings::Openings::VerticalOrInclined : it->second;
  }
};

/// The scene of one case (the base project or a variant) and what its steps' keys share.
struct CaseScene {
  const SceneDescription& description;
  const engine::Scene& scene;
  const std::vector<engine::Material>& materials;
  const CaseLayout& layout;
  ContentHash scene_hash;   ///< cache_keys.h scene_key
  ContentHash planes_hash;  ///< cache_keys.h planes_key
};

/// The photons grid `g` of a case is estimated from: its plane's crossings (and the surface
/// photons for a final gather at its sensors next to a cut, CaseLayout::near_cut_sensors), or
/// the surface photons for a final gather or a surface estimate; `sources` sources.
engine::GridPhotons grid_photons_for(std::size_t g, const CaseLayout& layout, const engine::TracedPhotons& photons,
                                     std::size_t sources, project::PointEstimate estimate);

/// Which annual files the project asks for (outputs.annual_illuminance, outputs.metrics).
AnnualOutputs annual_outputs_of(const project::Project& project);

/// `dir`/`name`.
std::string join_path(const std::string& dir, const std::string& name);

}  // namespace dayphoton::study
