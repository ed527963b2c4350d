// SimulationPlan: what a run computes and how, built once from the project: the sky basis,
// the tracing and estimate options of the sky sources and of the sun bins, with every policy
// constant (plan_policy.h) applied here and nowhere else. `dayphoton run` and `annual` take
// their options from it (study_runner.cpp and the step files it calls), `dayphoton render`
// its sky-source photon allocation (sky_photon_factors).
//
// A case of the run (the base project, each variant) adds what its scene decides: the
// receiver planes of its planar grids (CaseLayout), hence whether surface photons are kept,
// and the cache keys of its steps (cache_keys.h). The steps themselves (plan_step.h) are made
// by the phase that runs them: sky_coefficient_steps.h (photons of the sky sources, sky
// coefficients per grid) and sun_bin_steps.h (photons of the sun bins, sun coefficients and
// direct sun per grid); each phase hands its independent steps to the StepExecutor
// (step_executor.h) as one batch.
#pragma once

#include <cstdint>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/sun_site.h"

namespace dayphoton::study {

/// Sensors next to a cut are gathered only where it pays (near_cut_gathered): the gather
/// reads the surface photons of the whole case, which a case of planar grids alone does not
/// otherwise keep, at 2-4 times its memory (measured: a 10 000-sensor open plan 889 MiB ->
/// 1737 MiB for its 69 sensors next to columns, 0.7 % of them; a room with one column gridded
/// every 0.2 m, 18 of 1196 sensors, 386 MB -> 1.6 GB). So a case keeps them for that when some
/// planar grid has at least this share of its sensors next to a cut (that room 1.5 %, obj_mesh
/// 5.5 %); below it, such sensors keep the plane's estimate and a located warning.
constexpr double NearCutGatherMinShare = 0.01;

/// Per planar grid (`near_cut[i]` of `sensors[i]` sensors next to a cut): whether they are
/// gathered (NearCutGatherMinShare): all of them when `surface_photons_kept` (some grid is
/// not planar) or some grid reaches the share, none otherwise.
std::vector<bool> near_cut_gathered(const std::vector<std::size_t>& near_cut, const std::vector<std::size_t>& sensors,
                                    bool surface_photons_kept);

/// The receiver planes of a case's grids: planar grids are estimated from their plane's
/// crossings, the others (walls, points) from the photons stored on surfaces.
struct CaseLayout {
  std::vector<engine::ReceiverPlane> planes;
  std::vector<int> plane_of_grid;  ///< per grid its plane, or -1
  /// Some grid is not planar, or some planar grid has sensors next to a cut (below).
  bool keep_surface_photons = false;
  /// Per plane: how many of its grid's sensors lie nearer than engine::NearCutGather_m to an
  /// interior cut (engine/plane_cuts.h); they are estimated by final gather from the surface
  /// photons (engine::GridPhotons::set_near_cut_gather). 0 where they are not gathered
  /// (near_cut_gathered). Empty before the cuts are known.
  std::vector<std::size_t> near_cut_sensors;
  /// Per outdoor scatterer of the scene, the sides a final gather from the grids' sensors can
  /// read (engine/gathered_scatterer_sides.h); empty when not decided (every side kept).
  std::vector<std::uint8_t> gathered_scatterer_sides;
  /// The scene description's world origin (SceneDescription::world_origin_m): tracing_for
  /// moves the region of interest, given in world coordinates, into the scene's frame.
  Vec3 world_origin_m{0, 0, 0};

  static CaseLayout of(const std::vector<SensorGrid>& grids);
  /// The planes with where `scene`'s surfaces cut them (engine/plane_cuts.h), for the
  /// estimates' visibility clip (the tracing does not use them), and the scatterer sides a
  /// gather from any grid's sensor can read (`materials` model the scene's materials).
  static CaseLayout of(const std::vector<SensorGrid>& grids, const engine::Scene& scene,
                       const std::vector<engine::Material>& materials);
  /// Whether some plane's sensors next to a cut are gathered (near_cut_sensors).
  bool gathers_near_cuts() const;
  /// Whether grid g lies on a plane with sensors next to a cut.
  bool grid_gathers_near_cuts(std::size_t g) const;
};

/// The daylight factor's sky among the sky coefficients' continuous skies
/// (engine::DirectOptions::skies, SimulationPlan::daylight_factor_continuous_sky).
constexpr std::size_t DaylightFactorSkyIndex = 0;

struct SimulationPlan {
  sky::PatchBasis basis = sky::PatchBasis::tregenza();
  project::PointEstimate point_estimate = project::PointEstimate::Surface;
  std::uint64_t seed = 1;
  /// The sky sources' photons (ground bin GroundPhotonFactor times a sky bin's), for a case
  /// without surface photons (tracing_for adds them).
  engine::TracingOptions sky_tracing;
  engine::CoefficientOptions sky_estimating;
  /// The sun bins' photons (SunBinPhotonFraction of a sky bin's), without surface photons.
  engine::TracingOptions sun_tracing;
  /// The sky's estimate options with the sun bins' bandwidth (SunBinBandwidthFraction).
  engine::CoefficientOptions sun_estimating;
  int sun_direct_samples = SunDirectSamples;
  double sun_bin_minimum_bound_fraction = SunBinMinimumBoundFraction;
  double overcast_horizontal_lux = OvercastHorizontalLux;
  double ground_photon_factor = GroundPhotonFactor;
  double ground_reflectance = 0.2;  ///< simulation.ground_reflectance
  /// Where the low-yield cap (simulation.max_attempts_per_photon) is set: the `simulation`
  /// section as written (unknown when the project has none), for the capped-flux warning.
  SourceLocation cap_location;

  /// Per point-in-time case (project key `points_in_time`): the index of its continuous sky
  /// in sky_estimating.direct.skies (point_in_time_continuous_skies), or -1.
  std::vector<int> point_in_time_sky;

  /// `sun_site`: the annual study's (run_inputs.h), for the point-in-time CIE skies' sun
  /// (point_in_time_site); null for none.
  static SimulationPlan of(const project::Project& project, const SunSite* sun_site = nullptr);

  /// The daylight-factor sky as a vector over the basis: CIE overcast of
  /// overcast_horizontal_lux, the ground of ground_reflectance (1 x bins x RGB).
  RadianceMatrix daylight_factor_sky() const;
  /// The same sky as a continuous radiance (engine/direct_component.h, "Continuous skies"):
  /// sky_estimating.direct.skies[DaylightFactorSkyIndex], so the daylight factor's sky
  /// component is the continuous sky's (daylight_factor.h, daylight_factor_parts).
  engine::ContinuousSky daylight_factor_continuous_sky() const;

  /// `base` (sky_tracing or sun_tracing) for a case: surface photons kept when some grid is
  /// not planar or some plane has sensors next to a cut, and with them the direct hits for a
  /// final gather (on outdoor scatterers only on the sides the gather can read:
  /// CaseLayout::gathered_scatterer_sides).
  engine::TracingOptions tracing_for(const engine::TracingOptions& base, const CaseLayout& layout) const;
};

/// Photons per source relative to a sky bin for the `sources` sources of a sky basis (bin 0
/// the ground): GroundPhotonFactor for the ground, 1 for the sky.
std::vector<double> sky_photon_factors(std::size_t sources);

/// The project's sky basis (Tregenza or Reinhart MF).
sky::PatchBasis basis_of(const project::Simulation& sim);

}  // namespace dayphoton::study
