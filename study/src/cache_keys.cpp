// Cache keys: see cache_keys.h. Every field that changes an artefact is hashed; names and
// source locations (which do not change results) are not.
#include "dayphoton/study/cache_keys.h"

namespace dayphoton::study {

ContentHash scene_key(const SceneDescription& scene) {
  ContentHash h;
  h.text("scene").integer(EngineCacheVersion);
  h.integer(static_cast<std::int64_t>(scene.materials.size()));
  for (const MaterialSpec& m : scene.materials) {
    h.integer(static_cast<int>(m.type)).vec3(m.reflectance).number(m.specularity).number(m.roughness);
    h.vec3(m.transmittance).number(m.refractive_index).number(m.transmissivity).number(m.transmitted_specular);
  }
  h.integer(static_cast<std::int64_t>(scene.surfaces.size()));
  for (const Surface& s : scene.surfaces) {
    h.integer(s.material).integer(s.port ? 1 : 0).integer(static_cast<std::int64_t>(s.vertices.size()));
    for (const Vec3& v : s.vertices) h.vec3(v);
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

std::string photon_source_key(const ContentHash& scene, const ContentHash& planes,
                              const sky::PatchBasis& basis, std::size_t source,
                              const engine::TracingOptions& o) {
  ContentHash h;
  h.text("photons").hash(scene).hash(planes).integer(basis.multiplication_factor());
  h.integer(static_cast<std::int64_t>(source));
  h.integer(static_cast<std::int64_t>(o.photons_per_source));
  h.integer(static_cast<std::int64_t>(o.caustic_photons_per_source));
  h.number(source < o.source_photon_factor.size() ? o.source_photon_factor[source] : 1.0);
  h.integer(static_cast<std::int64_t>(o.seed)).number(o.prepass_fraction);
  h.integer(static_cast<std::int64_t>(o.max_prepass_attempts_per_target));
  h.integer(o.store_direct ? 1 : 0).integer(o.keep_surface_photons ? 1 : 0).integer(o.max_events);
  h.integer(o.region_of_interest ? 1 : 0);
  if (o.region_of_interest) h.vec3(o.region_of_interest->lower).vec3(o.region_of_interest->upper);
  return h.hex();
}

std::string coefficients_key(const std::vector<std::string>& photon_keys, const SensorGrid& grid,
                             const engine::CoefficientOptions& o) {
  ContentHash h;
  h.text("coefficients");
  for (const std::string& k : photon_keys) h.text(k);
  h.integer(grid.planar ? 1 : 0).vec3(grid.plane_normal).number(grid.plane_height_m);
  for (const Vec3& v : grid.outline) h.vec3(v);
  h.integer(static_cast<std::int64_t>(grid.points.size()));
  for (const SensorPoint& p : grid.points) h.vec3(p.position).vec3(p.normal);
  h.integer(static_cast<std::int64_t>(o.density.bandwidth)).number(o.density.max_radius_m);
  h.integer(static_cast<int>(o.density.kernel)).integer(o.density.average_radius ? 1 : 0);
  h.integer(static_cast<int>(o.estimator)).integer(o.boundary_correction ? 1 : 0);
  h.integer(o.direct.samples_per_source).integer(static_cast<std::int64_t>(o.direct.seed));
  return h.hex();
}

}  // namespace dayphoton::study
