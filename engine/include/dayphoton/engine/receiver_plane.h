// ReceiverPlane: a horizontal virtual sensor plane (DESIGN.md section 5). Sensor grids float
// in the room (a work plane at 0.8 m is not a surface), so the photon tracer records every
// photon that crosses a grid's plane from its front side, inside the grid's outline, without
// disturbing it; the density estimate of those crossings is the irradiance on the plane
// (the flux crossing a unit area per unit time, so no cosine weighting is needed).
//
// The plane also answers the geometric question of the boundary-corrected estimate: what
// area of a kernel disc lies inside the outline (photons cannot cross outside the room,
// so dividing by the full pi r^2 near a wall would underestimate: the "boundary bias" of
// seeds/000 section 5.1).
#pragma once

#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

/// Area moments of a region about a point (x, y): A = int dA, m = int (q - p) dA,
/// M = int (q - p)(q - p)^T dA (m^2, m^3, m^4).
struct AreaMoments {
  double area = 0, mx = 0, my = 0, mxx = 0, mxy = 0, myy = 0;
};

/// Moments up to order 4 of a disc of radius r about its centre p, clipped to an outline, in
/// the disc's scaled coordinates (u, v) = (q - p) / r: at(a, b) = int u^a v^b dA / r^2
/// (a + b <= 4). The unclipped disc: at(0, 0) = pi, at(2, 0) = pi / 4, at(4, 0) = pi / 8,
/// at(2, 2) = pi / 24. What a local fit of degree 2 needs (local_quadratic_fit.h).
struct ScaledMoments4 {
  double value[15] = {};
  /// The index of u^a v^b in `value`: order by order (1; u, v; u^2, uv, v^2; ...).
  static constexpr int index(int a, int b) { return (a + b) * (a + b + 1) / 2 + b; }
  double& at(int a, int b) { return value[index(a, b)]; }
  double at(int a, int b) const { return value[index(a, b)]; }
};

/// A point of the outline in plane coordinates (x, y of the world; the plane is horizontal).
struct PlanePoint {
  double x = 0, y = 0;
};

/// A straight piece in plane coordinates: where a surface cuts the plane (plane_cuts.h).
struct PlaneSegment {
  PlanePoint a, b;
};

/// The distance from (x, y) to the segment a-b, metres.
double distance_to_segment_m(double x, double y, const PlanePoint& a, const PlanePoint& b);

class ReceiverPlane {
 public:
  /// The plane of a planar grid (SensorGrid::planar, normal +Z or -Z). Throws
  /// std::invalid_argument for a non-planar grid or an outline with fewer than 3 points.
  static ReceiverPlane from_grid(const SensorGrid& grid);
  /// Horizontal plane at height z_m facing `up` (+Z) or down, with outline `outline`.
  ReceiverPlane(double z_m, bool faces_up, std::vector<PlanePoint> outline);

  double height_m() const { return m_z_m; }
  Vec3 normal() const { return {0, 0, m_faces_up ? 1.0 : -1.0}; }

  /// Ray parameter where origin + t d crosses the plane from the front (against the normal),
  /// or a negative value if it does not (parallel, leaving, or behind the origin).
  double front_crossing(const Vec3& origin, const Vec3& direction) const;
  /// Area enclosed by the outline, m^2 (shoelace formula; absolute value).
  double outline_area_m2() const;
  /// True if (x, y) is inside the outline (even-odd rule).
  bool contains(double x, double y) const;
  /// Area of the disc of radius r_m centred on (x, y) that lies inside the outline, m^2
  /// (exact: a sum of signed circle-triangle intersections over the outline's edges).
  double disc_area_inside_m2(double x, double y, double r_m) const;
  /// Area moments about (x, y) of the disc of radius r_m centred there, clipped to the
  /// outline: exact, by Green's theorem on the clipped boundary (outline pieces inside the
  /// disc, circle arcs inside the outline).
  AreaMoments clipped_disc_moments(double x, double y, double r_m) const;
  /// The same region's moments up to order 4 in the disc's scaled coordinates (exact, by
  /// Green's theorem; ScaledMoments4).
  ScaledMoments4 clipped_disc_moments4(double x, double y, double r_m) const;

  /// The outline, as given.
  const std::vector<PlanePoint>& outline() const { return m_outline; }
  /// Outline vertices whose interior angle exceeds pi (the re-entrant corners of an L-shaped
  /// room): from near them part of the outline hides another.
  const std::vector<PlanePoint>& reflex_vertices() const { return m_reflex; }
  /// Where the scene's surfaces cut the plane inside the outline (plane_cuts.h: partitions,
  /// columns, tall furniture); none until set. The estimates keep to what a sensor's
  /// position sees across them (plane_visibility.h).
  void set_interior_cuts(std::vector<PlaneSegment> cuts) { m_interior_cuts = std::move(cuts); }
  const std::vector<PlaneSegment>& interior_cuts() const { return m_interior_cuts; }

 private:
  double m_z_m = 0;
  bool m_faces_up = true;
  std::vector<PlanePoint> m_outline;
  std::vector<PlanePoint> m_reflex;
  std::vector<PlaneSegment> m_interior_cuts;
  double m_min_x = 0, m_max_x = 0, m_min_y = 0, m_max_y = 0;
};

}  // namespace dayphoton::engine
