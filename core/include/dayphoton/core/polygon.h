// Planar polygon utilities: Newell normal, area, planarity, triangulation.
// Used by the project's geometry generators and by the engine when it hands triangles to Embree.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "dayphoton/core/vec3.h"

namespace dayphoton {

/// Unit normal by Newell's method; its direction follows the vertex winding
/// (counter-clockwise seen from the side the normal points to). Zero vector if degenerate.
Vec3 polygon_normal(const std::vector<Vec3>& vertices);

/// Area in m^2 (vector area magnitude; exact for planar simple polygons).
double polygon_area_m2(const std::vector<Vec3>& vertices);

/// Largest distance (m) of any vertex from the polygon's mean plane (Newell normal through
/// the centroid). 0 for triangles.
double planarity_deviation_m(const std::vector<Vec3>& vertices);

/// Mean of the vertices.
Vec3 polygon_centroid(const std::vector<Vec3>& vertices);

/// Triangulate a simple planar polygon (convex or concave, no holes) by ear clipping.
/// Every triangle keeps the polygon's winding, so its geometric normal equals
/// polygon_normal(). Returns indices into `vertices`; throws std::invalid_argument if the
/// polygon is degenerate or self-intersecting so that no ear can be found.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(const std::vector<Vec3>& vertices);

/// True if point p (assumed in the polygon's plane) lies inside the polygon (even-odd rule).
bool polygon_contains(const std::vector<Vec3>& vertices, const Vec3& p);

/// Distance from p (in the plane) to the polygon's boundary.
double distance_to_polygon_boundary_m(const std::vector<Vec3>& vertices, const Vec3& p);

}  // namespace dayphoton
