// Triangulation of a planar polygon with holes: a Honeybee face with its apertures and doors
// cut out, or a Face3D with `holes`. Each hole is joined to the outer boundary by a bridge to
// a mutually visible vertex, which makes one weakly simple polygon, then ear clipping cuts it
// into triangles (D. Eberly, "Triangulation by Ear Clipping", Geometric Tools, 2008,
// sections 3-5). Holes are taken in order of their largest coordinate along the bridging
// direction, so each bridge only crosses the polygon built so far.
#pragma once

#include <array>
#include <vector>

#include "dayphoton/core/vec3.h"

namespace dayphoton::project::detail {

/// Triangles covering `outer` minus `holes`. `outer` is planar and simple, each hole planar
/// in its plane, strictly inside it and apart from the other holes (the caller checks). Each
/// triangle has the winding of `outer` (its normal is polygon_normal(outer)); holes may be
/// wound either way. Throws std::invalid_argument when no triangulation is found (a hole
/// touching the boundary or another hole, a self-intersecting outline).
std::vector<std::array<Vec3, 3>> triangulate_with_holes(const std::vector<Vec3>& outer,
                                                        const std::vector<std::vector<Vec3>>& holes);

}  // namespace dayphoton::project::detail
