// Which sides of an outdoor scatterer can receive light from the sky (port_emission.h).
//
// A thin part (a blind's slat, a shelf drawn as one polygon) is lit on both sides. A face of
// a closed solid (a shelf slab, a prism) is lit only on the side outside the solid: light
// reaching its inner side has crossed another face of the solid first, and is traced from
// there. Emission sites on inner sides would only draw attempts that are always occluded.
//
// A set of scatterer polygons is a closed solid when every edge of each polygon is shared,
// in the opposite direction, with exactly one other polygon of the set (a consistently
// oriented closed 2-manifold; vertices matched to ClosedSolidTolerance_m). Its outside is
// the side its normals point to if its signed volume (divergence theorem: sum over the
// triangles of v0 . (v1 x v2) / 6) is positive, else the other side. Anything else is thin,
// lit on both sides: a solid whose faces do not share whole edges (T-junctions) is treated
// as thin, which costs attempts but never light.
#pragma once

#include <vector>

#include "dayphoton/core/scene_description.h"

namespace dayphoton::engine {

/// The sides of a scatterer that receive light.
enum class LitSides { Both, Front, Back };

/// Vertices closer than this (per coordinate) are the same vertex when matching edges.
constexpr double ClosedSolidTolerance_m = 1e-9;

/// For each index in `scatterers` (indices into description.surfaces), its lit sides.
std::vector<LitSides> scatterer_lit_sides(const SceneDescription& description,
                                          const std::vector<int>& scatterers);

}  // namespace dayphoton::engine
