// Filling the results model (results_model.h) from the run's data in memory: the scene of
// each case, the sensor grids, and the typed results of each step (DF statistics, the annual
// study and its settings, the points in time). Called by run_study as it goes; nothing here
// reads a file the run wrote.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/point_in_time_accuracy.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/study/verdict_uncertainty.h"

namespace dayphoton::study {

/// Ports farther than this from a wall or rectangle grid's plane are not drawn on its
/// elevation: the windows in the wall a grid covers are at its offset, which is small.
constexpr double ElevationWindowDistance_m = 0.5;

/// The run-level part: project name, versions, study kind, site and sun, weather file, the
/// sky settings the sky images need, every simulation setting labelled (from the run's
/// summary `simulation` object, built from the project in memory) and the notes.
ResultsModel results_model_header(const project::Project& project, const std::string& version, const SunSite* sun_site,
                                  const sky::BelowHorizonDirect* below, const nlohmann::json& simulation,
                                  const std::vector<std::string>& notes);

/// A case without grids yet; `folder` relative to the output folder.
CaseResult results_case(const std::string& kind, const std::string& name, const std::string& folder,
                        const std::vector<std::string>& changes);

/// The plan geometry of a case's scene: ports (and port candidates of an imported scene) as
/// openings, outdoor daylight-system surfaces as systems, in world coordinates.
void set_plan_geometry(CaseResult& c, const SceneDescription& scene);

/// The building of a case for the report's tables: the materials of its scene's surfaces
/// (photometric reflectance, normal-incidence transmittance, area) and the rooms of the
/// case's project (the variant's own, e.g. with a window added) with their windows, roof
/// lights, window-to-wall and window-to-floor areas; the total area of the scene's openings;
/// the enabled blinds (CaseResult::blinds_in_place) and the materials taken as operable shading
/// (CaseResult::shading_materials_in_place, shading_materials.h).
void set_building(CaseResult& c, const project::Project& project, const SceneDescription& scene);

/// The project's name for titles (ResultsModel::title): the folder's name for a file called
/// project.yaml, else the file's name without extension.
std::string project_title(const std::string& project_path);

/// The operated-shading case: the geometry and sensors of `base` (the variants share the
/// sensors), with no results until add_operated_grid.
CaseResult operated_case(const CaseResult& base, const std::string& name, const std::string& folder);

/// One grid of the operated case (matched by name): its folder and annual results.
void add_operated_grid(CaseResult& c, const std::string& grid, const std::string& folder, const AnnualStudy& study,
                       const AnnualStudySettings& settings, const AnnualOutputs& which);

/// A grid of `c` with its sensors, orientation, lattice (sensor_lattice.h), outline and the
/// openings drawn on its picture (all on a plan; on a wall or rectangle grid's elevation only
/// those parallel to it within ElevationWindowDistance_m). `grid` in world coordinates
/// (SceneDescription::world_grid), as c's openings are.
GridResult results_grid(const SensorGrid& grid, const std::string& folder, const CaseResult& c,
                        std::size_t dropped_outside_rooms, std::size_t dropped_inside_solid,
                        std::size_t dropped_on_cut_surface = 0, std::size_t dropped_enclosed = 0);

/// The daylight factor's statistics and uncertainty, and its value table daylight_factor.csv.
void add_daylight_factor(GridResult& grid, const GridStatistics& statistics, const DaylightFactorUncertainty& u);

/// The annual summary of `study` under `settings`; with `which.metrics` the per-sensor
/// quantities of metrics.csv (columns named by result_files.h metrics_csv_columns), with
/// `which.illuminance` the illuminance table.
void add_annual(GridResult& grid, const AnnualStudy& study, const AnnualStudySettings& settings,
                const AnnualOutputs& which);

void add_verdict_uncertainty(GridResult& grid, const VerdictUncertainty& u);

/// One point-in-time case's statistics, and its column of point_in_time.csv.
/// `u`: the case's Monte Carlo uncertainty (its relative standard errors); `accuracy`: the case
/// against the run's accuracy target (point_in_time_accuracy.h), null without one.
void add_point_in_time(GridResult& grid, const std::string& name, const std::string& sky, const GridStatistics& st,
                       const DaylightFactorUncertainty& u, const PointInTimeAccuracy* accuracy = nullptr);

/// `folder` relative to `output_dir`, '/'-separated ("" for the output folder itself).
std::string relative_folder(const std::string& output_dir, const std::string& folder);

}  // namespace dayphoton::study
