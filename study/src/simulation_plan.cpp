// SimulationPlan: see simulation_plan.h.
#include "dayphoton/study/simulation_plan.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/gathered_scatterer_sides.h"
#include "dayphoton/engine/plane_cuts.h"
#include "dayphoton/engine/sky_ratios.h"
#include "dayphoton/project/north_rotation.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/point_in_time.h"

namespace dayphoton::study {
namespace {

/// The project's region of interest in world coordinates (tracing_for moves it into a case's
/// scene frame, CaseLayout::world_origin_m): the axis-aligned box around the
/// rotated model box (with a north rotation a little larger, which only stores more).
std::optional<engine::Bounds3> region_of_interest(const project::Project& project) {
  const auto& roi = project.simulation.region_of_interest;
  if (!roi) return std::nullopt;
  const double north = project.site.rotation_to_true_north_deg();
  engine::Bounds3 b{project::model_to_world(roi->origin_m, north), project::model_to_world(roi->origin_m, north)};
  for (int corner = 1; corner < 8; ++corner) {
    const Vec3 c{roi->origin_m.x + ((corner & 1) ? roi->size_m.x : 0), roi->origin_m.y + ((corner & 2) ? roi->size_m.y : 0),
                 roi->origin_m.z + ((corner & 4) ? roi->size_m.z : 0)};
    const Vec3 w = project::model_to_world(c, north);
    for (int k = 0; k < 3; ++k) {
      b.lower[k] = std::min(b.lower[k], w[k]);
      b.upper[k] = std::max(b.upper[k], w[k]);
    }
  }
  return b;
}

/// What the sky and the sun passes share: seed, caustic target, low-yield cap, region of
/// interest.
engine::TracingOptions shared_tracing_options(const project::Project& project) {
  const project::Simulation& sim = project.simulation;
  engine::TracingOptions o;
  o.caustic_photons_per_source = static_cast<std::size_t>(sim.caustic_photons_per_bin);
  o.seed = sim.seed;
  o.max_mainpass_attempts_per_target = static_cast<std::size_t>(sim.max_attempts_per_photon);
  o.region_of_interest = region_of_interest(project);
  return o;
}

engine::CoefficientOptions coefficient_options(const project::Simulation& sim) {
  engine::CoefficientOptions o;
  o.density.bandwidth = static_cast<std::size_t>(sim.bandwidth);
  // Caustic photons with a target of their own are counted unlike the global ones, so they
  // always get the caustic map (a shared disc would be sized by their count).
  o.caustic_bandwidth = static_cast<std::size_t>(
      sim.caustic_bandwidth > 0 ? sim.caustic_bandwidth : (sim.caustic_photons_per_bin > 0 ? sim.bandwidth : 0));
  o.direct.samples_per_source = sim.direct_samples_per_bin;
  o.direct.seed = sim.seed;
  o.estimator = sim.estimator == project::Estimator::Contribution ? engine::PhotonEstimator::Contribution
                                                                  : engine::PhotonEstimator::PerSource;
  o.gather.rays_per_sensor = sim.gather_rays;
  o.gather.bandwidth = static_cast<std::size_t>(sim.gather_bandwidth);
  o.gather.seed = sim.seed;
  return o;
}

}  // namespace

CaseLayout CaseLayout::of(const std::vector<SensorGrid>& grids) {
  CaseLayout l;
  for (const SensorGrid& g : grids) {
    if (g.planar) {
      l.plane_of_grid.push_back(static_cast<int>(l.planes.size()));
      l.planes.push_back(engine::ReceiverPlane::from_grid(g));
    } else {
      l.plane_of_grid.push_back(-1);
      l.keep_surface_photons = true;
    }
  }
  return l;
}

CaseLayout CaseLayout::of(const std::vector<SensorGrid>& grids, const engine::Scene& scene,
                          const std::vector<engine::Material>& materials) {
  CaseLayout l = of(grids);
  l.world_origin_m = scene.description().world_origin_m;
  for (engine::ReceiverPlane& plane : l.planes) plane.set_interior_cuts(engine::interior_plane_cuts(scene, plane));
  // The planar grids' sensors next to a cut, gathered from the surface photons.
  l.near_cut_sensors.assign(l.planes.size(), 0);
  std::vector<std::size_t> plane_sensors(l.planes.size(), 0);
  for (std::size_t g = 0; g < grids.size(); ++g)
    if (const int plane = l.plane_of_grid[g]; plane >= 0) {
      l.near_cut_sensors[std::size_t(plane)] = engine::sensors_near_cuts(l.planes[std::size_t(plane)], grids[g].points).size();
      plane_sensors[std::size_t(plane)] = grids[g].points.size();
    }
  const std::vector<bool> gathered = near_cut_gathered(l.near_cut_sensors, plane_sensors, l.keep_surface_photons);
  for (std::size_t p = 0; p < gathered.size(); ++p)
    if (!gathered[p]) l.near_cut_sensors[p] = 0;
  if (l.gathers_near_cuts()) l.keep_surface_photons = true;
  // Every grid's sensors, the planar ones included (they gather nothing: it only keeps more).
  std::vector<Vec3> sensors;
  for (const SensorGrid& g : grids)
    for (const SensorPoint& p : g.points) sensors.push_back(p.position);
  l.gathered_scatterer_sides = engine::gathered_scatterer_sides(scene, materials, sensors);
  return l;
}

std::vector<bool> near_cut_gathered(const std::vector<std::size_t>& near_cut, const std::vector<std::size_t>& sensors,
                                    bool surface_photons_kept) {
  bool kept = surface_photons_kept;
  for (std::size_t i = 0; i < near_cut.size() && !kept; ++i)
    kept = near_cut[i] > 0 && double(near_cut[i]) >= NearCutGatherMinShare * double(sensors.at(i));
  std::vector<bool> out(near_cut.size());
  for (std::size_t i = 0; i < near_cut.size(); ++i) out[i] = kept && near_cut[i] > 0;
  return out;
}

bool CaseLayout::gathers_near_cuts() const {
  for (std::size_t n : near_cut_sensors)
    if (n > 0) return true;
  return false;
}

bool CaseLayout::grid_gathers_near_cuts(std::size_t g) const {
  const int plane = g < plane_of_grid.size() ? plane_of_grid[g] : -1;
  return plane >= 0 && std::size_t(plane) < near_cut_sensors.size() && near_cut_sensors[std::size_t(plane)] > 0;
}

std::vector<double> sky_photon_factors(std::size_t sources) {
  std::vector<double> f(sources, 1.0);
  if (sources > 0) f[0] = GroundPhotonFactor;
  return f;
}

sky::PatchBasis basis_of(const project::Simulation& sim) {
  return sim.basis == project::SkyBasis::Tregenza ? sky::PatchBasis::tregenza()
                                                  : sky::PatchBasis::reinhart(sim.reinhart_mf);
}

SimulationPlan SimulationPlan::of(const project::Project& project, const SunSite* sun_site) {
  const project::Simulation& sim = project.simulation;
  SimulationPlan p;
  p.basis = basis_of(sim);
  p.point_estimate = sim.point_estimate;
  p.seed = sim.seed;
  p.sky_tracing = shared_tracing_options(project);
  p.cap_location = sim.location;
  p.sky_tracing.photons_per_source = static_cast<std::size_t>(sim.photons_per_bin);
  p.sky_tracing.source_photon_factor = sky_photon_factors(p.basis.bin_count());
  p.sky_estimating = coefficient_options(sim);
  // The ground bin 0 (the sky's sources are the basis's bins, engine::SourceSet::sky_bins)
  // and no other source: its discs get the local-quadratic fit where a wall cuts them
  // (engine::CoefficientOptions::quadratic_fit_sources; why only the ground: docs/photon-map.md,
  // "Curvature at the walls").
  p.sky_estimating.quadratic_fit_sources = {0};
  p.sun_tracing = shared_tracing_options(project);
  p.sun_tracing.photons_per_source = static_cast<std::size_t>(
      std::max(1LL, std::llround(double(sim.photons_per_bin) * SunBinPhotonFraction)));
  p.sun_estimating = p.sky_estimating;
  p.sun_estimating.quadratic_fit_sources.clear();  // the sun bins have no ground bin
  p.sun_estimating.density.bandwidth = sun_bin_bandwidth(p.sky_estimating.density.bandwidth);
  p.ground_reflectance = sim.ground_reflectance;
  // The daylight factor's sky component from the continuous sky (the sun bins have none).
  p.sky_estimating.direct.skies = {p.daylight_factor_continuous_sky()};
  // Then each point-in-time CIE case's sky, so its direct part is the continuous sky's too.
  std::vector<engine::ContinuousSky> cases = point_in_time_continuous_skies(
      project.points_in_time, point_in_time_site(project, sun_site), sim.ground_reflectance, p.point_in_time_sky);
  for (int& k : p.point_in_time_sky)
    if (k >= 0) k += static_cast<int>(p.sky_estimating.direct.skies.size());
  for (engine::ContinuousSky& sky : cases) p.sky_estimating.direct.skies.push_back(std::move(sky));
  // The sky gather's rays' variance is taken on the daylight factor's sky (final_gather.h,
  // "Variance"). The sun bins' weights are the year's, known once the suns are
  // (sun_annual_estimating, in sun_bin_steps.cpp and the sun rounds), so sun_estimating,
  // copied above, has none.
  const RadianceMatrix df_sky = p.daylight_factor_sky();
  const std::vector<double> df_luminance = sky_vector_luminance(df_sky);
  p.sky_estimating.gather.variance_weights = df_luminance;
  // The daylight factor's photon part under the continuous sky too (engine/sky_ratios.h): the
  // sky photons carry their ratio to the bin's mean, and the sky coefficients the photon part
  // under the sky itself. The sun bins have no sky ratio (sun_tracing and sun_estimating
  // were copied before).
  // The ratios depend on the sky's shape and the bins alone (the photons' keys have the
  // basis): not on its illuminance, nor on the ground, whose bin is uniform (ratio 1). So
  // their key names the shape, and changing the ground keeps the cached photons.
  // The key: the sky's name and its sky bins' luminances relative to their sum at full
  // precision (the means the ratios divide by, free of the illuminance; the ground bin's
  // ratio is 1 whatever the ground).
  engine::ContinuousSky ratio_sky = p.daylight_factor_continuous_sky();
  double sky_sum = 0;
  for (std::size_t b = 1; b < df_luminance.size(); ++b) sky_sum += df_luminance[b];
  std::ostringstream ratio_key;
  ratio_key.precision(17);
  ratio_key << "CIE overcast over its bin means, relative:";
  for (std::size_t b = 1; b < df_luminance.size(); ++b) ratio_key << ' ' << df_luminance[b] / sky_sum;
  ratio_sky.key = ratio_key.str();
  p.sky_tracing.sky_ratios =
      std::make_shared<const engine::SkyRatios>(std::move(ratio_sky), df_luminance);
  // The gathered rows' paths that leave to the sky take the same ratios (engine/final_gather.h).
  p.sky_estimating.photon_sky_ratios = p.sky_tracing.sky_ratios;
  for (std::size_t b = 0; b < df_sky.rows(); ++b)
    p.sky_estimating.photon_sky_bin_radiance_rgb.push_back(
        Vec3{df_sky.at(b, 0, 0), df_sky.at(b, 0, df_sky.components() > 1 ? 1 : 0),
             df_sky.at(b, 0, df_sky.components() > 2 ? 2 : 0)});
  // The photon part's sub-patch shares for the annual product's correction (the sky photons
  // carry their quadrant, engine/photon.h; study/sub_patch_shares.h), as the direct part's.
  // The sun bins have no quadrants (sun_estimating was copied before).
  p.sky_estimating.photon_quadrants = true;
  return p;
}

RadianceMatrix SimulationPlan::daylight_factor_sky() const {
  const auto overcast = sky::make_cie_overcast_sky(sky::SkyScale::horizontal_illuminance_lux(overcast_horizontal_lux));
  const double rho_g = ground_reflectance;
  return sky::sky_vector(*overcast, basis,
                         sky::ground_radiance_rgb({rho_g, rho_g, rho_g}, overcast_horizontal_lux, 0, {0, 0, -1}));
}

engine::ContinuousSky SimulationPlan::daylight_factor_continuous_sky() const {
  const std::shared_ptr<const sky::SkyModel> overcast =
      sky::make_cie_overcast_sky(sky::SkyScale::horizontal_illuminance_lux(overcast_horizontal_lux));
  const double rho_g = ground_reflectance;
  const Vec3 ground = sky::ground_radiance_rgb({rho_g, rho_g, rho_g}, overcast_horizontal_lux, 0, {0, 0, -1});
  engine::ContinuousSky sky;
  std::ostringstream key;  // every parameter of the radiance, at full precision
  key.precision(17);
  key << "daylight factor CIE overcast " << overcast_horizontal_lux << " lx, ground " << ground.x << ' ' << ground.y
      << ' ' << ground.z;
  sky.key = key.str();
  // The basis's ground bin 0 is every direction with z <= 0 (sky::PatchBasis::find_bin).
  sky.radiance_rgb = [overcast, ground](const Vec3& w) { return w.z > 0 ? overcast->radiance_rgb(w) : ground; };
  return sky;
}

engine::TracingOptions SimulationPlan::tracing_for(const engine::TracingOptions& base, const CaseLayout& layout) const {
  engine::TracingOptions o = base;
  o.keep_surface_photons = layout.keep_surface_photons;
  o.store_direct_on_surfaces =
      layout.keep_surface_photons && (point_estimate == project::PointEstimate::Gather || layout.gathers_near_cuts());
  if (o.store_direct_on_surfaces) o.scatterer_direct_sides = layout.gathered_scatterer_sides;
  if (o.region_of_interest && layout.world_origin_m != Vec3{0, 0, 0}) {
    o.region_of_interest->lower = o.region_of_interest->lower - layout.world_origin_m;
    o.region_of_interest->upper = o.region_of_interest->upper - layout.world_origin_m;
  }
  return o;
}

}  // namespace dayphoton::study
