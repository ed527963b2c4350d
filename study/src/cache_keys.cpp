// Cache keys: see cache_keys.h. Every field that changes an artefact is hashed; names and
// source locations (which do not change results) are not.
#include "dayphoton/study/cache_keys.h"

#include "dayphoton/engine/plane_cuts.h"

#include "dayphoton/engine/material_registry.h"

namespace dayphoton::study {

ContentHash scene_key(const SceneDescription& scene) {
  ContentHash h;
  h.text("scene").integer(EngineCacheVersion);
  h.integer(static_cast<std::int64_t>(scene.materials.size()));
  for (const MaterialSpec& m : scene.materials) {
    h.integer(static_cast<int>(m.type)).vec3(m.reflectance).number(m.specularity).number(m.roughness);
    h.vec3(m.transmittance).number(m.refractive_index).number(m.transmissivity).number(m.transmitted_specular);
    // Hashed only where they exist, so the keys of projects without them stay as they were.
    if (m.type == MaterialType::Glazing) {
      h.integer(static_cast<std::int64_t>(m.panes.size()));
      for (const GlazingPaneSpec& p : m.panes) {
        h.integer(static_cast<int>(p.optics)).vec3(p.transmittance).vec3(p.absorption_per_m);
        h.number(p.thickness_m).number(p.refractive_index).vec3(p.outer_reflectance).vec3(p.inner_reflectance);
      }
    }
    if (m.transmittance_factor != 1.0) h.text("transmittance factor").number(m.transmittance_factor);
    // A registered model's own parameters, as its registry entry writes them.
    if (m.type == MaterialType::Registered) {
      std::string parameters;
      const engine::MaterialModelEntry& model = engine::material_model_of(m);
      if (model.cache_key) model.cache_key(m, parameters);
      h.text("model").text(m.model).text(parameters);
    }
  }
  h.integer(static_cast<std::int64_t>(scene.surfaces.size()));
  for (const Surface& s : scene.surfaces) {
    h.integer(s.material).integer(s.port ? 1 : s.outdoor_scatterer ? 2 : 0).integer(static_cast<std::int64_t>(s.vertices.size()));
    for (const Vec3& v : s.vertices) h.vec3(v);
    // Which side of a port is the room changes its emission; generated ports (Winding) keep
    // the keys they had before ports could face either way.
    if (s.port && s.facing != PortFacing::Winding) h.text("facing").integer(static_cast<int>(s.facing));
    if (s.port_if_outdoors) h.text("port if outdoors");
  }
  return h;
}

ContentHash planes_key(const std::vector<SensorGrid>& grids) {
  ContentHash h;
  h.text("planes");
  for (const SensorGrid& g : grids) {
    if (!g.planar) continue;
    h.vec3(g.plane_normal).number(g.plane_height_m).integer(static_cast<std::int64_t>(g.outline.size()));
    for (const Vec3& v : g.outline) h.vec3(v);
  }
  return h;
}

namespace {

/// Every tracing option that changes a source's photons, for source `source`.
void add_tracing_options(ContentHash& h, std::size_t source, const engine::TracingOptions& o) {
  h.integer(static_cast<std::int64_t>(o.photons_per_source));
  h.integer(static_cast<std::int64_t>(o.caustic_photons_per_source));
  h.number(source < o.source_photon_factor.size() ? o.source_photon_factor[source] : 1.0);
  h.integer(static_cast<std::int64_t>(o.seed)).number(o.prepass_fraction);
  h.integer(static_cast<std::int64_t>(o.max_prepass_attempts_per_target));
  h.integer(static_cast<std::int64_t>(o.max_mainpass_attempts_per_target));
  // Hashed only where set, so the keys of every other source stay as they were.
  if (source < o.raw_attempt_cap.size() && o.raw_attempt_cap[source]) h.text("raw attempt cap");
  h.integer(o.store_direct ? 1 : 0).integer(o.keep_surface_photons ? 1 : 0).integer(o.max_events);
  h.integer(o.store_direct_on_surfaces ? 1 : 0);
  // Which scatterer sides keep their Direct photons (since the rule of
  // gathered_scatterer_sides.h: photons cached before it differ).
  h.text("scatterer direct sides").integer(static_cast<std::int64_t>(o.scatterer_direct_sides.size()));
  for (const std::uint8_t sides : o.scatterer_direct_sides) h.integer(sides);
  h.integer(o.region_of_interest ? 1 : 0);
  if (o.region_of_interest) h.vec3(o.region_of_interest->lower).vec3(o.region_of_interest->upper);
  // The records' sky ratios (engine/photon.h): hashed only where set.
  if (o.sky_ratios) h.text("sky ratios").text(o.sky_ratios->key());
}

/// The grid's geometry and sensors.
void add_grid(ContentHash& h, const SensorGrid& grid) {
  h.integer(grid.planar ? 1 : 0).vec3(grid.plane_normal).number(grid.plane_height_m);
  for (const Vec3& v : grid.outline) h.vec3(v);
  h.integer(static_cast<std::int64_t>(grid.points.size()));
  for (const SensorPoint& p : grid.points) h.vec3(p.position).vec3(p.normal);
}

/// The estimate and direct-sampling options.
void add_estimate_options(ContentHash& h, const engine::CoefficientOptions& o) {
  h.integer(static_cast<std::int64_t>(o.density.bandwidth)).number(o.density.max_radius_m);
  h.integer(static_cast<int>(o.density.kernel)).integer(static_cast<int>(o.density.radius));
  h.integer(static_cast<int>(o.estimator)).integer(o.boundary_correction ? 1 : 0);
  h.integer(static_cast<std::int64_t>(o.caustic_bandwidth));
  h.integer(static_cast<std::int64_t>(o.quadratic_fit_sources.size()));
  for (std::size_t p : o.quadratic_fit_sources) h.integer(static_cast<std::int64_t>(p));
  h.integer(o.visibility_clip ? 1 : 0);
  h.integer(static_cast<int>(o.curvature_correction));
  h.integer(o.direct.samples_per_source).integer(static_cast<std::int64_t>(o.direct.seed));
  h.integer(static_cast<std::int64_t>(o.direct.skies.size()));
  for (const engine::ContinuousSky& sky : o.direct.skies) h.text(sky.key);
  h.integer(o.gather.rays_per_sensor).integer(static_cast<std::int64_t>(o.gather.bandwidth));
  h.integer(o.gather.max_specular_events).integer(static_cast<std::int64_t>(o.gather.seed));
  h.integer(static_cast<std::int64_t>(o.gather.variance_weights.size()));
  for (const double w : o.gather.variance_weights) h.number(w);
  h.text("photon sky").integer(static_cast<std::int64_t>(o.photon_sky_bin_radiance_rgb.size()));
  for (const Vec3& l : o.photon_sky_bin_radiance_rgb) h.vec3(l);
  // The gathered rows' photon part on the sky (engine/final_gather.h): hashed only where set.
  if (o.photon_sky_ratios) h.text("photon sky ratios").text(o.photon_sky_ratios->key());
  // The photon part's sub-patch shares: hashed only where asked for.
  if (o.photon_quadrants) h.text("photon sub-patch shares");
}

/// A plane's sensors gathered next to a cut (engine/plane_cuts.h): nothing without any.
void add_near_cut_gather(ContentHash& h, std::size_t near_cut_sensors) {
  if (near_cut_sensors == 0) return;
  h.text("near-cut gather").number(engine::NearCutGather_m).integer(static_cast<std::int64_t>(near_cut_sensors));
}

}  // namespace

std::string photon_source_key(const ContentHash& scene, const ContentHash& planes,
                              const sky::PatchBasis& basis, std::size_t source,
                              const engine::TracingOptions& o) {
  ContentHash h;
  h.text("photons").hash(scene).hash(planes).integer(basis.multiplication_factor());
  h.integer(static_cast<std::int64_t>(source));
  add_tracing_options(h, source, o);
  return h.hex();
}

std::string coefficients_key(const std::vector<std::string>& photon_keys, const SensorGrid& grid,
                             const engine::CoefficientOptions& o, std::size_t near_cut_sensors) {
  ContentHash h;
  h.text("coefficients");
  for (const std::string& k : photon_keys) h.text(k);
  add_grid(h, grid);
  add_estimate_options(h, o);
  add_near_cut_gather(h, near_cut_sensors);
  return h.hex();
}

std::string sky_matrix_key(const std::string& weather_path, const sky::SolarSite& site,
                           const sky::PatchBasis& basis, double ground_reflectance, bool sun_excluded) {
  ContentHash h;
  h.text("sky matrix").integer(EngineCacheVersion).file(weather_path);
  // Every field of the site the sun is computed for (SPA also reads pressure and temperature).
  h.number(site.latitude_deg).number(site.longitude_deg).number(site.time_zone_h).number(site.elevation_m);
  h.number(site.pressure_mbar).number(site.temperature_c);
  h.integer(basis.multiplication_factor()).number(ground_reflectance);
  h.text(sun_excluded ? "radiance-compatible, sun excluded; suns" : "radiance-compatible, sun spread");
  return h.hex();
}

std::string sun_photon_key(const ContentHash& scene, const ContentHash& planes, int mf, int patch,
                           double half_angle_rad, const engine::TracingOptions& o) {
  ContentHash h;
  h.text("sun photons").hash(scene).hash(planes).integer(mf).integer(patch).number(half_angle_rad);
  add_tracing_options(h, 0, o);
  return h.hex();
}

std::string sun_coefficients_key(const std::vector<std::string>& sun_photon_keys,
                                 double minimum_bound_fraction, const SensorGrid& grid,
                                 const engine::CoefficientOptions& o, std::size_t near_cut_sensors) {
  ContentHash h;
  h.text("sun coefficients");
  h.integer(static_cast<std::int64_t>(sun_photon_keys.size()));
  for (const std::string& k : sun_photon_keys) h.text(k);
  h.number(minimum_bound_fraction);
  add_grid(h, grid);
  add_estimate_options(h, o);
  h.integer(o.local_linear ? 1 : 0).integer(o.bias_compensation ? 1 : 0);
  h.integer(static_cast<std::int64_t>(o.bias_compensation_max_factor)).integer(static_cast<std::int64_t>(o.seed));
  add_near_cut_gather(h, near_cut_sensors);
  return h.hex();
}

std::string direct_sun_key(const ContentHash& scene, const SensorGrid& grid,
                           const std::vector<std::size_t>& steps, const std::vector<Vec3>& directions,
                           int samples, std::uint64_t seed, DirectSunValues values) {
  ContentHash h;
  h.text(values == DirectSunValues::Rgb ? "direct sun" : "direct sun, luminance").hash(scene);
  add_grid(h, grid);
  h.integer(static_cast<std::int64_t>(steps.size()));
  for (std::size_t i = 0; i < steps.size(); ++i)
    h.integer(static_cast<std::int64_t>(steps[i])).vec3(directions.at(i));
  h.integer(samples).integer(static_cast<std::int64_t>(seed));
  return h.hex();
}

}  // namespace dayphoton::study
