// Scene: validation, triangulation and the Embree-backed queries. Conventions, the
// validation rules, the precision refinement and the self-intersection epsilon are
// documented in scene.h; Embree itself is only touched through EmbreeAccel
// (embree_accel.cpp).
#include "dayphoton/engine/scene.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/polygon.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/engine/port_facing.h"
#include "dayphoton/engine/photon.h"
#include "embree_accel.h"
#include "klems_bsdf.h"

namespace dayphoton::engine {

struct Scene::Impl {
  SceneDescription description;
  std::vector<SceneTriangle> triangles;
  std::vector<int> surface_port;  ///< per surface: port index or -1
  PortSet ports;
  std::vector<int> surface_scatterer;  ///< per surface: outdoor scatterer index or -1
  PortSet scatterers;
  Bounds3 bounds;
  double scale_m = 1;      ///< max(1 m, largest absolute coordinate relative to origin_m)
  double epsilon_m = 1e-5;
  /// Embree's local origin (scene.h, "Precision"): the centre of the bounding box, rounded
  /// to a whole metre, when that lies farther from (0, 0, 0) than the scene's size, else
  /// (0, 0, 0); Embree holds the vertices and rays relative to it.
  Vec3 origin_m{0, 0, 0};
  std::unique_ptr<EmbreeAccel> accel;
};

namespace {

/// Relative size of the smallest polygon area we accept, times (scene size)^2 (scene.h).
constexpr double DegenerateAreaFraction = 1e-12;
/// Self-intersection offset relative to the coordinate scale (scene.h).
constexpr double RayEpsilonFraction = 1e-5;

std::string describe(const Surface& s, std::size_t index) {
  std::ostringstream out;
  out << "surface '" << (s.name.empty() ? "#" + std::to_string(index) : s.name) << "'";
  return out.str();
}

}  // namespace

Scene::Scene(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)), m_epsilon_m(m_impl->epsilon_m) {}
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;
Scene::~Scene() = default;

Scene Scene::build(const SceneDescription& description) {
  Scene scene = build_surfaces(description);
  // A measured BSDF's front (WINDOW's exterior) is the side its surface's normal points away
  // from (docs/materials.md, "Measured BSDF (Klems)"); on a port that side must be outdoors,
  // i.e. the port's room side must be the winding normal's.
  Diagnostics diagnostics;
  for (const Port& port : scene.ports().ports()) {
    const Surface& s = scene.description().surfaces[static_cast<std::size_t>(port.surface)];
    const MaterialSpec& m = scene.description().materials[static_cast<std::size_t>(s.material)];
    if (port.against_winding && bsdf_parameters(m))
      diagnostics.error(s.location, describe(s, static_cast<std::size_t>(port.surface)) + " is a port of BSDF material '" +
                                        m.name + "' whose normal points out of the room, so the BSDF's front (WINDOW's "
                                        "exterior side, the side the normal points away from) would face the room; "
                                        "reverse the order of its vertices");
  }
  diagnostics.throw_if_errors();
  return scene;
}

Scene Scene::build_surfaces(const SceneDescription& description) {
  // Port candidates (Surface::port_if_outdoors): build once with every candidate a port
  // facing auto, keep those whose facing test found the sky on one side, and build again
  // with those as ports and the others as ordinary surfaces.
  const bool has_candidates =
      std::any_of(description.surfaces.begin(), description.surfaces.end(),
                  [](const Surface& s) { return s.port_if_outdoors; });
  if (has_candidates) {
    SceneDescription trial = description;
    for (Surface& s : trial.surfaces)
      if (s.port_if_outdoors) {
        s.port_if_outdoors = false;
        s.port = true;
        s.facing = PortFacing::Auto;
      }
    const Scene tested = build_surfaces(trial);
    SceneDescription resolved = description;
    for (const Port& port : tested.ports().ports()) {
      Surface& s = resolved.surfaces[static_cast<std::size_t>(port.surface)];
      if (!s.port_if_outdoors || port.side_reason != PortSideReason::Sky) continue;
      s.port = true;
      s.facing = PortFacing::Auto;
      s.solid_face = false;
    }
    for (Surface& s : resolved.surfaces) s.port_if_outdoors = false;
    return build_surfaces(resolved);
  }
  auto impl = std::make_unique<Impl>();
  impl->description = description;
  const auto& surfaces = impl->description.surfaces;

  // Scene size from every finite vertex: it scales the degenerate-area threshold and the
  // ray epsilon.
  double max_abs_m = 0;
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& s : surfaces)
    for (const auto& p : s.vertices)
      if (is_finite(p))
        for (int k = 0; k < 3; ++k) {
          max_abs_m = std::max(max_abs_m, std::abs(p[k]));
          lo[k] = std::min(lo[k], p[k]);
          hi[k] = std::max(hi[k], p[k]);
        }
  const double size_m = lo.x <= hi.x ? std::max(1.0, length(hi - lo)) : 1.0;
  const double min_area_m2 = DegenerateAreaFraction * size_m * size_m;
  // A model drawn away from its origin (farther than its own size) gets a local origin
  // (scene.h, "Precision"); one drawn around it keeps the identity, bit for bit.
  if (lo.x <= hi.x && length((lo + hi) * 0.5) > size_m) {
    const Vec3 centre = (lo + hi) * 0.5;
    impl->origin_m = {std::round(centre.x), std::round(centre.y), std::round(centre.z)};
    max_abs_m = 0;
    for (int k = 0; k < 3; ++k)
      max_abs_m = std::max({max_abs_m, std::abs(lo[k] - impl->origin_m[k]),
                            std::abs(hi[k] - impl->origin_m[k])});
  }
  impl->scale_m = std::max(1.0, max_abs_m);
  impl->epsilon_m = RayEpsilonFraction * impl->scale_m;

  // Validate everything first (Embree would drop bad primitives silently), then report all.
  Diagnostics diagnostics;
  // Photon positions are floats in the description's coordinates (photon.h), which a project
  // holds around a local origin (SceneDescription::world_origin_m): refuse geometry so far
  // from that origin that they lose the precision of the estimates, i.e. a model too large,
  // at its farthest surface.
  {
    double farthest_m = 0;
    std::size_t farthest = surfaces.size();
    for (std::size_t i = 0; i < surfaces.size(); ++i)
      for (const auto& p : surfaces[i].vertices)
        if (is_finite(p))
          for (int k = 0; k < 3; ++k)
            if (std::abs(p[k]) > farthest_m) farthest_m = std::abs(p[k]), farthest = i;
    if (farthest_m > PhotonCoordinateLimit_m) {
      const Vec3& o = impl->description.world_origin_m;
      std::ostringstream message;
      message << describe(surfaces[farthest], farthest) << " lies " << format_coordinate(farthest_m) << " m from ("
              << format_coordinate(o.x) << ", " << format_coordinate(o.y) << ", " << format_coordinate(o.z)
              << "), the point the model is held around (the centre of its geometry in whole km), in a model "
              << format_coordinate(length(hi - lo))
              << " m across: photon positions are single precision, which beyond "
              << PhotonCoordinateLimit_m
              << " m from that point reads the daylight wrong by more than its noise; leave out the distant "
                 "geometry (or, in coordinates of another frame, move it to the model's)";
      diagnostics.error(surfaces[farthest].location, message.str());
    }
  }
  const int material_count = static_cast<int>(impl->description.materials.size());
  std::vector<std::vector<std::array<std::uint32_t, 3>>> triangulation(surfaces.size());
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const Surface& s = surfaces[i];
    const std::string what = describe(s, i);
    if (s.material < 0 || s.material >= material_count) {
      diagnostics.error(s.location, what + ": material index " + std::to_string(s.material) +
                                        " is out of range (" + std::to_string(material_count) +
                                        " materials)");
    }
    if (s.port && s.outdoor_scatterer)
      diagnostics.error(s.location, what + " is both a port and an outdoor scatterer; a surface is "
                                           "at most one of them");
    if (s.vertices.size() < 3) {
      diagnostics.error(s.location, what + " has " + std::to_string(s.vertices.size()) +
                                        " vertices; a polygon needs at least 3");
      continue;
    }
    bool finite = true;
    for (std::size_t v = 0; v < s.vertices.size() && finite; ++v)
      if (!is_finite(s.vertices[v])) {
        diagnostics.error(s.location, what + ": vertex " + std::to_string(v + 1) +
                                          " has a NaN or infinite coordinate");
        finite = false;
      }
    if (!finite) continue;
    const double area_m2 = polygon_area_m2(s.vertices);
    if (!(area_m2 >= min_area_m2)) {
      std::ostringstream m;
      m << what << " is degenerate: area " << area_m2 << " m^2 is below " << min_area_m2
        << " m^2 (collinear or repeated vertices?)";
      diagnostics.error(s.location, m.str());
      continue;
    }
    if (s.material >= 0 && s.material < material_count) {
      const MaterialSpec& m = impl->description.materials[static_cast<std::size_t>(s.material)];
      if (const BsdfMaterialParameters* bsdf = bsdf_parameters(m);
          bsdf && !KlemsBsdf::frame_defined(bsdf->up, polygon_normal(s.vertices))) {
        std::ostringstream msg;
        msg << what << ": the up vector (" << bsdf->up.x << ", " << bsdf->up.y << ", " << bsdf->up.z
            << ") of its BSDF material '" << m.name
            << "' is parallel to the surface's normal, which leaves the BSDF's orientation undefined; give the "
               "material an 'up' along the surface (e.g. [0, 1, 0] on a horizontal one)";
        diagnostics.error(s.location, msg.str());
      }
    }
    try {
      triangulation[i] = triangulate_polygon(s.vertices);
    } catch (const std::exception& e) {
      diagnostics.error(s.location, what + " cannot be triangulated: " + e.what());
      continue;
    }
    // Ears at collinear vertices of a valid polygon have zero area: drop them.
    auto& tris = triangulation[i];
    tris.erase(std::remove_if(tris.begin(), tris.end(),
                              [&](const std::array<std::uint32_t, 3>& t) {
                                const Vec3 e = cross(s.vertices[t[1]] - s.vertices[t[0]],
                                                     s.vertices[t[2]] - s.vertices[t[0]]);
                                return !(0.5 * length(e) >= min_area_m2);
                              }),
               tris.end());
    if (tris.empty()) {
      diagnostics.error(s.location, what + " triangulates to degenerate triangles only");
      continue;
    }
  }
  diagnostics.throw_if_errors();

  // Triangles in surface order; the Embree primitive id is the index into impl->triangles.
  std::vector<float> vertices_xyz;
  std::vector<std::uint32_t> indices;
  impl->surface_port.assign(surfaces.size(), -1);
  impl->surface_scatterer.assign(surfaces.size(), -1);
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const Surface& s = surfaces[i];
    const auto base = static_cast<std::uint32_t>(vertices_xyz.size() / 3);
    for (const auto& p : s.vertices) {
      const Vec3 local = p - impl->origin_m;
      vertices_xyz.push_back(static_cast<float>(local.x));
      vertices_xyz.push_back(static_cast<float>(local.y));
      vertices_xyz.push_back(static_cast<float>(local.z));
    }
    for (const auto& t : triangulation[i]) {
      SceneTriangle tri;
      tri.vertices = {s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]};
      tri.normal = normalize(cross(tri.vertices[1] - tri.vertices[0],
                                   tri.vertices[2] - tri.vertices[0]));
      tri.surface = static_cast<int>(i);
      impl->triangles.push_back(tri);
      for (int k = 0; k < 3; ++k) indices.push_back(base + t[k]);
    }
    if (s.port)
      impl->surface_port[i] = impl->ports.add(static_cast<int>(i), s, triangulation[i]);
    else if (s.outdoor_scatterer)
      impl->surface_scatterer[i] = impl->scatterers.add(static_cast<int>(i), s, triangulation[i]);
  }
  if (!impl->triangles.empty()) {
    impl->bounds = {lo, hi};
  }
  impl->accel = std::make_unique<EmbreeAccel>(vertices_xyz, indices);
  // Ports face either way: decide each one's room side from the built scene (port_facing.h).
  // The tests run in parallel (a mesh of port faces is tested face by face); orienting comes
  // after all of them, so every test sees the same scene.
  Scene scene(std::move(impl));
  PortSet& ports = scene.m_impl->ports;
  auto facing_of = [&](std::size_t k) {
    return scene.description().surfaces[static_cast<std::size_t>(ports[k].surface)].facing;
  };
  std::vector<PortSideTest> tests(ports.size());
  tbb::parallel_for(std::size_t(0), ports.size(), [&](std::size_t k) {
    if (facing_of(k) != PortFacing::Winding) tests[k] = test_port_sides(scene, ports[k]);
  });
  for (std::size_t k = 0; k < ports.size(); ++k) {
    if (facing_of(k) == PortFacing::Winding) continue;
    const PortSideDecision decision = decide_port_side(facing_of(k), tests[k]);
    ports.orient(k, decision.against_winding, decision.reason, tests[k].sky_fraction_winding,
                 tests[k].sky_fraction_opposite);
  }
  return scene;
}

std::optional<Hit> Scene::intersect(const Ray& ray) const {
  AccelHit raw;
  Ray local = ray;
  local.origin = ray.origin - m_impl->origin_m;
  if (!m_impl->accel->intersect(local, raw)) return std::nullopt;
  const SceneTriangle& tri = m_impl->triangles[raw.primitive];
  Hit hit;
  hit.t = raw.t;
  // Refine Embree's single-precision t against the triangle's plane in double precision.
  // Guard: only accept the refinement if it agrees with Embree's t to well within float
  // error (a grazing ray has an ill-conditioned plane distance; keep Embree's t then).
  const double denom = dot(ray.direction, tri.normal);
  if (denom != 0) {
    const double t_plane = dot(tri.vertices[0] - ray.origin, tri.normal) / denom;
    const double tolerance = 1e-4 * (std::abs(hit.t) + m_impl->scale_m / length(ray.direction));
    if (std::isfinite(t_plane) && std::abs(t_plane - hit.t) <= tolerance) hit.t = t_plane;
  }
  hit.t = std::clamp(hit.t, ray.tmin, ray.tmax);
  hit.position = ray.origin + ray.direction * hit.t;
  hit.normal = tri.normal;
  hit.front_face = denom < 0;
  hit.surface = tri.surface;
  hit.material = m_impl->description.surfaces[static_cast<std::size_t>(tri.surface)].material;
  hit.port = m_impl->surface_port[static_cast<std::size_t>(tri.surface)];
  hit.scatterer = m_impl->surface_scatterer[static_cast<std::size_t>(tri.surface)];
  hit.primitive = raw.primitive;
  hit.u = raw.u;
  hit.v = raw.v;
  return hit;
}

bool Scene::occluded(const Ray& ray) const {
  Ray local = ray;
  local.origin = ray.origin - m_impl->origin_m;
  return m_impl->accel->occluded(local);
}

void Scene::intersect_batch(const Ray* rays, std::size_t count, std::optional<Hit>* hits) const {
  for (std::size_t i = 0; i < count; ++i) hits[i] = intersect(rays[i]);
}

void Scene::occluded_batch(const Ray* rays, std::size_t count, bool* occluded_out) const {
  for (std::size_t i = 0; i < count; ++i) occluded_out[i] = occluded(rays[i]);
}

const Bounds3& Scene::bounds() const { return m_impl->bounds; }

std::size_t Scene::triangle_count() const { return m_impl->triangles.size(); }

const SceneTriangle& Scene::triangle(std::uint32_t primitive) const {
  return m_impl->triangles.at(primitive);
}

const SceneDescription& Scene::description() const { return m_impl->description; }
const PortSet& Scene::ports() const { return m_impl->ports; }
const PortSet& Scene::outdoor_scatterers() const { return m_impl->scatterers; }
const std::vector<SensorGrid>& Scene::sensor_grids() const { return m_impl->description.grids; }

bool Scene::is_port(int surface_index) const {
  return surface_index >= 0 &&
         static_cast<std::size_t>(surface_index) < m_impl->surface_port.size() &&
         m_impl->surface_port[static_cast<std::size_t>(surface_index)] >= 0;
}

}  // namespace dayphoton::engine
