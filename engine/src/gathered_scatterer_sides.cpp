// Which sides of the outdoor scatterers a final gather can read: see gathered_scatterer_sides.h.
#include "dayphoton/engine/gathered_scatterer_sides.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {
namespace {

// Viewpoints in runs of this many (consecutive sensors of a grid lie close together), each
// with its bounding box: a run whose box lies wholly behind a plane is skipped at once.
constexpr std::size_t ViewpointsPerRun = 64;

struct ViewpointRun {
  std::size_t begin = 0, end = 0;
  Vec3 lower, upper;
};

std::vector<ViewpointRun> runs_of(const std::vector<Vec3>& points) {
  std::vector<ViewpointRun> runs;
  for (std::size_t b = 0; b < points.size(); b += ViewpointsPerRun) {
    ViewpointRun r;
    r.begin = b;
    r.end = std::min(points.size(), b + ViewpointsPerRun);
    r.lower = r.upper = points[b];
    for (std::size_t i = b; i < r.end; ++i) {
      const Vec3& p = points[i];
      r.lower = {std::min(r.lower.x, p.x), std::min(r.lower.y, p.y), std::min(r.lower.z, p.z)};
      r.upper = {std::max(r.upper.x, p.x), std::max(r.upper.y, p.y), std::max(r.upper.z, p.z)};
    }
    runs.push_back(r);
  }
  return runs;
}

// The range of dot(p - origin, d) over the box: at its corners.
void box_heights(const ViewpointRun& r, const Vec3& origin, const Vec3& d, double& low, double& high) {
  const double lo_x = (r.lower.x - origin.x) * d.x, hi_x = (r.upper.x - origin.x) * d.x;
  const double lo_y = (r.lower.y - origin.y) * d.y, hi_y = (r.upper.y - origin.y) * d.y;
  const double lo_z = (r.lower.z - origin.z) * d.z, hi_z = (r.upper.z - origin.z) * d.z;
  low = std::min(lo_x, hi_x) + std::min(lo_y, hi_y) + std::min(lo_z, hi_z);
  high = std::max(lo_x, hi_x) + std::max(lo_y, hi_y) + std::max(lo_z, hi_z);
}

}  // namespace

bool continues_gather(const Material& material) {
  const Vec3 n{0, 0, 1};
  const Vec3 diffuse = material.diffuse_reflectance() + material.diffuse_transmittance();
  // Normal to grazing incidence, on the front (against n) and on the back (along n).
  for (const double theta_deg : {0.0, 30.0, 60.0, 80.0, 89.0}) {
    const double t = theta_deg * RadPerDeg;
    for (const double side : {-1.0, 1.0}) {
      const Vec3 incoming = normalize(Vec3{std::sin(t), 0.0, side * std::cos(t)});
      const Vec3 rest = material.albedo(incoming, n) - diffuse;
      if (std::fabs(rest.x) > 1e-9 || std::fabs(rest.y) > 1e-9 || std::fabs(rest.z) > 1e-9) return true;
    }
  }
  return false;
}

std::vector<std::uint8_t> gathered_scatterer_sides(const Scene& scene, const std::vector<Material>& materials,
                                                   const std::vector<Vec3>& sensor_positions_m) {
  const SceneDescription& description = scene.description();
  if (materials.size() < description.materials.size())
    throw std::invalid_argument("gathered scatterer sides: fewer material models than the scene has materials");
  // Where the last segment of a gather path before an outdoor scatterer can start (header
  // comment): the sensors, the ports' vertices, and the vertices of every surface whose
  // material sends a gather ray on.
  std::vector<Vec3> viewpoints = sensor_positions_m;
  const PortSet& ports = scene.ports();
  for (std::size_t i = 0; i < ports.size(); ++i)
    for (const std::array<Vec3, 3>& tri : ports[i].triangles) viewpoints.insert(viewpoints.end(), tri.begin(), tri.end());
  std::vector<char> continues(description.materials.size());
  for (std::size_t m = 0; m < continues.size(); ++m) continues[m] = continues_gather(materials[m]) ? 1 : 0;
  for (const Surface& surface : description.surfaces)
    if (surface.material >= 0 && continues[static_cast<std::size_t>(surface.material)])
      viewpoints.insert(viewpoints.end(), surface.vertices.begin(), surface.vertices.end());

  const std::vector<ViewpointRun> runs = runs_of(viewpoints);
  const double tolerance_m = GatherSideToleranceEpsilons * scene.ray_epsilon_m();
  const PortSet& scatterers = scene.outdoor_scatterers();
  std::vector<std::uint8_t> sides(scatterers.size(), 0);
  for (std::size_t s = 0; s < scatterers.size(); ++s) {
    const Port& scatterer = scatterers[s];
    std::uint8_t read = 0;
    for (const std::array<Vec3, 3>& tri : scatterer.triangles) {
      const Vec3 c = cross(tri[1] - tri[0], tri[2] - tri[0]);
      const double len = length(c);
      // A degenerate triangle or one folded away from the scatterer's normal: no plane to
      // decide by, both sides kept.
      if (!(len > 0) || std::fabs(dot(c, scatterer.normal)) < 0.5 * len) {
        read = ScattererBothSides;
        break;
      }
      const Vec3 along = (dot(c, scatterer.normal) > 0 ? c : c * -1.0) / len;  // toward the normal side
      for (const ViewpointRun& run : runs) {
        double low = 0, high = 0;
        box_heights(run, tri[0], along, low, high);
        // Nothing of this run can add a side not yet read.
        if (!(high > -tolerance_m && !(read & ScattererNormalSide)) && !(low < tolerance_m && !(read & ScattererOppositeSide)))
          continue;
        for (std::size_t i = run.begin; i < run.end; ++i) {
          const double h = dot(viewpoints[i] - tri[0], along);
          if (h > -tolerance_m) read |= ScattererNormalSide;
          if (h < tolerance_m) read |= ScattererOppositeSide;
        }
        if (read == ScattererBothSides) break;
      }
      if (read == ScattererBothSides) break;
    }
    // A diffusely transmitting scatterer: a lookup at a hit on one side also reads the other
    // side's photons (the transmitted light, final_gather.h).
    const Material& material = materials[static_cast<std::size_t>(description.surfaces[static_cast<std::size_t>(scatterer.surface)].material)];
    const Vec3 tau_d = material.diffuse_transmittance();
    if (read != 0 && std::max({tau_d.x, tau_d.y, tau_d.z}) > 0) read = ScattererBothSides;
    sides[s] = read;
  }
  return sides;
}

}  // namespace dayphoton::engine
