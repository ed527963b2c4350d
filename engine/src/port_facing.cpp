// Port facing: see port_facing.h.
#include "dayphoton/engine/port_facing.h"

#include "dayphoton/core/polygon.h"
#include "dayphoton/engine/scene.h"
#include "spread_directions.h"

namespace dayphoton::engine {

PortSideTest test_port_sides(const Scene& scene, const Port& port) {
  const PortSet& ports = scene.ports();
  const Vec3 winding = polygon_normal(scene.description().surfaces.at(static_cast<std::size_t>(port.surface)).vertices);
  const std::vector<Vec3> front = detail::hemisphere_directions(winding, PortFacingDirections);
  const std::vector<Vec3> back = detail::hemisphere_directions(winding * -1.0, PortFacingDirections);
  const int index = ports.port_of_surface(port.surface);
  int escaped_front = 0, escaped_back = 0, rays = 0;
  constexpr int Strata = 4;
  static_assert(Strata * Strata == PortFacingPoints, "points on the port: a square lattice");
  for (int i = 0; i < Strata; ++i)
    for (int j = 0; j < Strata; ++j) {
      const Vec3 p = ports.sample(static_cast<std::size_t>(index), (i + 0.5) / Strata, (j + 0.5) / Strata).position;
      for (int k = 0; k < PortFacingDirections; ++k) {
        const Vec3& df = front[static_cast<std::size_t>(k)];
        const Vec3& db = back[static_cast<std::size_t>(k)];
        if (!scene.occluded(Ray{scene.offset_ray_origin(p, winding, df), df})) ++escaped_front;
        if (!scene.occluded(Ray{scene.offset_ray_origin(p, winding, db), db})) ++escaped_back;
        ++rays;
      }
    }
  return {double(escaped_front) / rays, double(escaped_back) / rays};
}

PortSideDecision decide_port_side(PortFacing facing, const PortSideTest& test) {
  if (facing == PortFacing::Winding) return {false, PortSideReason::Generated};
  const double w = test.sky_fraction_winding, o = test.sky_fraction_opposite;
  // The side that sees the sky decisively, if any: +1 the winding side, -1 the other.
  int sky_side = 0;
  if (w >= PortFacingMinSkyFraction && w >= PortFacingSkyRatio * o) sky_side = +1;
  else if (o >= PortFacingMinSkyFraction && o >= PortFacingSkyRatio * w) sky_side = -1;
  if (facing == PortFacing::Auto) {
    if (sky_side == 0) return {false, PortSideReason::Ambiguous};
    return {sky_side > 0, PortSideReason::Sky};  // the room lies opposite the sky
  }
  const bool against = facing == PortFacing::Out;
  // Declared: the room is on the winding side (In) or the other (Out); contradicted when
  // that side is the one that sees the sky.
  const bool room_sees_sky = against ? sky_side < 0 : sky_side > 0;
  return {against, room_sees_sky ? PortSideReason::Contradicted : PortSideReason::Declared};
}

}  // namespace dayphoton::engine
