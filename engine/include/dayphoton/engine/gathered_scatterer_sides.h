// Which sides of the outdoor scatterers a final gather can read (final_gather.h), so that the
// photon tracer stores the Direct photons that land on an outdoor scatterer only where a
// gather lookup can find them (TracingOptions::scatterer_direct_sides).
//
// A photon stored on side S of a surface is read only by a lookup at a gather ray's hit on
// side S (the lookup's side filter, final_gather.h), and a ray that hits side S of a planar
// triangle comes from a point strictly in front of S's supporting plane. The last segment of
// a gather path before it meets an outdoor scatterer starts at one of:
//   - the sensor itself (a sensor outdoors, or a room that is not closed);
//   - a point on a port (after a port, the gather follows nothing but outdoor scatterers);
//   - a point on a surface where the gather goes on after a specular, glossy or straight
//     event: any surface whose material is not purely diffuse (a mirror shelf, a glazed
//     canopy, interior glass that is not a port), indoors or outdoors.
// A point of a polygon lies in the convex hull of its vertices, so if no sensor and no vertex
// of a port or of a surface that is not purely diffuse lies in front of a side's plane (for
// any triangle of the scatterer), no gather ray can hit that side and its Direct photons are
// never read there. The test counts points within a tolerance of the plane as in front, so
// it errs only toward storing. A scatterer that transmits diffusely (a translucent panel)
// keeps both sides when either is read: the lookup at a hit on one side also reads the
// photons of the other (the transmitted light). Decided once per scene and set of sensors, from the geometry
// and the materials alone, with no ray cast.
//
// What the rule drops is read by no lookup on that side; a lookup on ANOTHER surface facing
// the same way close by (a coplanar neighbour) could have counted them in its disc (the
// kernel's leakage across surfaces: a bias, not light of that surface).
#pragma once

#include <cstdint>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine {

/// Bits of a scatterer's entry: its side along Port::normal (the tracer's scatterer normal),
/// and the other side.
constexpr std::uint8_t ScattererNormalSide = 1, ScattererOppositeSide = 2;
constexpr std::uint8_t ScattererBothSides = ScattererNormalSide | ScattererOppositeSide;

/// Points this close to a side's plane (times the scene's ray epsilon, Scene::ray_epsilon_m)
/// count as in front of it: offset ray origins and sensors on the plane stay readable.
constexpr double GatherSideToleranceEpsilons = 100.0;

/// Whether a material may send a gather ray on (a specular, glossy or straight part): its
/// directional albedo differs from its diffuse reflectance plus transmittance at some of a
/// few incidences from normal to grazing.
bool continues_gather(const Material& material);

/// Per outdoor scatterer of `scene` (Scene::outdoor_scatterers order), the sides a gather
/// from sensors at `sensor_positions_m` can read (header comment): ScattererNormalSide,
/// ScattererOppositeSide, or both. `materials[m]` models the scene's material m.
std::vector<std::uint8_t> gathered_scatterer_sides(const Scene& scene, const std::vector<Material>& materials,
                                                   const std::vector<Vec3>& sensor_positions_m);

/// The bit of the side `side` (a vector pointing away from the lit side of a scatterer with
/// normal `scatterer_normal`): ScattererNormalSide if it points along the normal.
inline std::uint8_t scatterer_side_bit(const Vec3& side, const Vec3& scatterer_normal) {
  return dot(side, scatterer_normal) >= 0 ? ScattererNormalSide : ScattererOppositeSide;
}

}  // namespace dayphoton::engine
