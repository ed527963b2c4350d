// The floor area each sensor of a set stands for (SensorGrid::area_m2), where the sensors
// stand for unequal areas; every area share and spatial mean of the set is weighted by it
// (docs/metrics.md, "Sensor areas").
//
// - A Honeybee grid's mesh: one face per sensor, the area honeybee-radiance-postprocess
//   weighs each sensor's result by (load_project.cpp).
// - A room or polygon grid whose outline cuts its lattice cells: each sensor stands for its
//   cell, the spacing x spacing square centred on it (x, y), clipped to the outline. That
//   happens only where the sensors come within spacing / sqrt(2) of the outline (an inset
//   below that; the default inset 0.5 m at spacing 0.5 m leaves every cell whole, and the
//   reference office's 165 sensors are equal shares). Against the exact share of the outline
//   of a half-plane, over 8 directions and 199 cuts, the clipped cells err less than equal
//   counts on outlines the lattice reaches (inset 0, spacing 0.5 m: a 6 x 8 m room with its
//   sensors on the walls 2.34 -> 1.70 points RMS, 7.2 -> 4.2 largest; a 7 x 5 m right
//   triangle 3.48 -> 2.51 RMS, 16.9 -> 9.0 largest; an L 2.21 -> 2.00, a pentagon 2.15 ->
//   1.78; a rectangle turned 30 degrees 2.16 -> 2.21 RMS but 7.0 -> 6.6 largest): a sensor on
//   a wall stands for the half of its cell that is floor, not for a whole cell.
#pragma once

#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project::detail {

/// Areas that differ by no more than this fraction of the largest are equal: the set carries
/// none (equal shares, the bytes of an unweighted set).
constexpr double EqualAreaRelativeTolerance = 1e-9;

/// `areas_m2`, or empty when they are all equal (EqualAreaRelativeTolerance).
std::vector<double> unequal_areas_m2(const std::vector<double>& areas_m2);

/// Each sensor's lattice cell (the spacing_m square centred on it in x, y) clipped to
/// `outline` (a simple polygon seen from above, its z ignored); empty when every cell is
/// whole (unequal_areas_m2).
std::vector<double> lattice_cell_areas_m2(const std::vector<SensorPoint>& sensors, const std::vector<Vec3>& outline,
                                          double spacing_m);

}  // namespace dayphoton::project::detail
