// Scene: the ray-traceable form of a SceneDescription (DESIGN.md section 2, stage "build").
//
// What goes into the Embree scene: every surface of the description, ports included (a port
// is glazing, real geometry a photon can hit from inside the room; Hit::port tells a port
// hit apart), and outdoor scatterers (Surface::outdoor_scatterer; Hit::scatterer). Sensor grids are NOT geometry: they are kept as given (sensor_grids()) and
// the estimators use them as virtual receiver planes.
//
// Building: each surface is validated and triangulated with dayphoton::triangulate_polygon
// (core/polygon.h; triangles keep the polygon's winding, so each triangle's geometric normal
// is the polygon's normal). Embree drops bad primitives silently, so everything is checked
// first and every problem is reported as a located InputError (the surface's
// SourceLocation), all problems at once: material index out of range, fewer than three
// vertices, NaN/Inf coordinates, a polygon whose area is below 1e-12 m^2 x (scene size in
// m)^2 (minimum 1e-12 m^2), or one that cannot be triangulated. Zero-area triangles that the
// triangulation of a valid polygon may produce at collinear vertices cover nothing and are
// dropped. Embree runs in robust mode (RTC_SCENE_FLAG_ROBUST, watertight edges shared by
// triangles with identical vertices) at high build quality; see engine/src/embree_accel.cpp.
//
// Ports: after the build, each port whose Surface::facing is not Winding gets its room side
// decided by rays (engine/port_facing.h), and Port::normal points into the room whichever way
// the polygon was drawn; the triangles keep the polygon's winding. Port candidates
// (Surface::port_if_outdoors, an imported scene's glazing) become ports facing auto when that
// test finds the sky decisively on one side, ordinary surfaces otherwise (the scene is built
// twice); description() then holds the decision.
//
// Precision: Embree intersects in single precision, so it holds the vertices and the rays'
// origins relative to a local origin, the centre of the scene's bounding box (rounded to a
// whole metre) when that centre lies farther from (0, 0, 0) than the box's diagonal (a
// model drawn around the origin keeps the identity, so its rays are bit for bit those of
// before): a model drawn 1 km or 500 km from its coordinates' origin (site plans,
// survey and UTM coordinates) keeps the precision of one drawn at the origin. Without it a
// 6 x 8 m black room 1 km out read its sky component 1.2 % low and 10 km out 12 % low, and
// 30 km out its sensors saw the sky through the walls. The hit distance t is then refined in
// double precision against the hit triangle's plane (double-precision vertices, world
// coordinates), so Hit::position lies on the surface to about 1e-15 relative, not 1e-7.
// Photon positions are floats in the description's coordinates, so a description must hold
// its geometry within PhotonCoordinateLimit_m of its (0, 0, 0) (photon.h): a project's is
// moved there by build_scene_description (SceneDescription::world_origin_m,
// project/local_origin.h), and Scene::build refuses geometry beyond the limit, a model too
// large, with a located error.
//
// Self-intersection avoidance: a new ray from a hit point starts at
// offset_ray_origin(hit.position, hit.normal, direction) with tmin = 0. The offset is
// ray_epsilon_m() = 1e-5 x max(1 m, largest absolute coordinate relative to the local
// origin): about 100 times Embree's single-precision error at that coordinate size (2^-23 =
// 1.2e-7 relative), and 0.1 mm for an office, far below any photometric length scale.
//
// Thread safety: a built Scene is immutable; intersect/occluded may be called from any
// number of threads at once.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/port_set.h"
#include "dayphoton/engine/ray.h"

namespace dayphoton::engine {

class EmbreeAccel;  // engine/src/embree_accel.h; the only user of <embree3/rtcore.h>

/// Axis-aligned bounding box, metres.
struct Bounds3 {
  Vec3 lower, upper;
  Vec3 extent() const { return upper - lower; }
  Vec3 center() const { return (lower + upper) * 0.5; }
};

/// One triangle of the scene, as handed to Embree (double-precision copy).
struct SceneTriangle {
  std::array<Vec3, 3> vertices;  ///< metres, the source polygon's winding
  Vec3 normal;                   ///< unit geometric normal, (v1 - v0) x (v2 - v0) normalised
  int surface = -1;              ///< index into SceneDescription::surfaces
};

class Scene {
 public:
  /// Validate, triangulate and commit `description`. Throws dayphoton::InputError (every
  /// geometry problem, located) or EngineError (Embree failure).
  static Scene build(const SceneDescription& description);

  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;
  ~Scene();

  /// Closest hit with t in [ray.tmin, ray.tmax], if any.
  std::optional<Hit> intersect(const Ray& ray) const;
  /// True if anything is hit with t in [ray.tmin, ray.tmax] (shadow ray; cheaper).
  bool occluded(const Ray& ray) const;

  /// Batched forms: hits[i] / occluded[i] for rays[i], i < count (same results as the
  /// single-ray calls; one Embree query per ray).
  void intersect_batch(const Ray* rays, std::size_t count, std::optional<Hit>* hits) const;
  void occluded_batch(const Ray* rays, std::size_t count, bool* occluded) const;

  /// Bounds of all triangles (ports included). Empty scene: lower = upper = 0.
  const Bounds3& bounds() const;
  /// Self-intersection offset, metres (see the header comment).
  double ray_epsilon_m() const { return m_epsilon_m; }
  /// offset_ray_origin(position, normal, direction, ray_epsilon_m()). Inline: every photon
  /// and every shadow ray calls it.
  Vec3 offset_ray_origin(const Vec3& position, const Vec3& normal, const Vec3& direction) const {
    return engine::offset_ray_origin(position, normal, direction, m_epsilon_m);
  }

  std::size_t triangle_count() const;
  /// Triangle `primitive` (as in Hit::primitive), < triangle_count().
  const SceneTriangle& triangle(std::uint32_t primitive) const;

  /// The description the scene was built from (materials, surfaces, grids).
  const SceneDescription& description() const;
  /// Photon ports (surfaces with port = true), in surface order.
  const PortSet& ports() const;
  /// Sensor grids, as given; not part of the ray-traceable geometry.
  const std::vector<SensorGrid>& sensor_grids() const;
  /// True if surface `surface_index` is a port.
  bool is_port(int surface_index) const;
  /// Outdoor scatterers (surfaces with outdoor_scatterer = true), in surface order, each with
  /// its triangles and area for uniform sampling (the Port record; its normal is the
  /// polygon's winding normal, and both sides receive light).
  const PortSet& outdoor_scatterers() const;

 private:
  struct Impl;
  explicit Scene(std::unique_ptr<Impl> impl);
  /// build() without its last check (a BSDF port's front must face outdoors), which only the
  /// final scene gets: the trial build of port candidates makes every candidate a port.
  static Scene build_surfaces(const SceneDescription& description);
  std::unique_ptr<Impl> m_impl;
  double m_epsilon_m = 1e-5;  ///< Impl::epsilon_m, kept here for the inline offset
};

}  // namespace dayphoton::engine
