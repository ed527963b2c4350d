// The lattice of a grid's sensors, found once by the run from the sensor positions in memory
// and recorded in results.json (results_model.h SensorLattice): generated grids of a polygon
// or of a wall with windows leave lattice points out, and the generators do not keep the
// lattice, so it is found here from the positions they produced.
#pragma once

#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/study/results_model.h"

namespace dayphoton::study {

/// Find the lattice of `sensors`: all on one plane (positions within 1 mm of it), spacing =
/// the nearest-neighbour distance, every sensor within 1 % of a spacing of a lattice point,
/// no two on the same point, and at most 4 times as many cells as sensors. Otherwise (or
/// with fewer than 2 sensors) the one-row layout in sensor order. Columns run along the
/// lattice axis closest to east, rows toward the south (on a wall, downward).
SensorLattice sensor_lattice(const std::vector<SensorPoint>& sensors);

}  // namespace dayphoton::study
