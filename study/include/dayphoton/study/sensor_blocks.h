// Sensor blocks: a grid's sensors split into consecutive blocks that the ranks of an MPI run
// estimate separately (docs/cluster.md "Sensor blocks"), and the blocks' artefacts joined back
// into the whole grid's. Every estimator computes a block's rows exactly as the whole grid's
// (engine/sensor_range.h), and the codecs lay a grid's values out sensor by sensor, so joining
// the blocks' bytes in sensor order gives the whole grid's artefact byte for byte.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/sensor_range.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/plan_step.h"

namespace dayphoton::study {

/// `sensors` split into blocks of `block_size` (the last one shorter), in sensor order; no
/// block for no sensor. Throws std::invalid_argument for block_size 0.
std::vector<engine::SensorRange> sensor_blocks(std::size_t sensors, std::size_t block_size = SensorBlockSize);

/// Daylight-coefficient artefacts (artifact_codec.h) of consecutive blocks of one grid joined
/// into one. Throws std::invalid_argument when there is none or their source counts differ
/// (and std::runtime_error for a damaged one, as the decoder does).
std::string join_coefficient_blocks(const std::vector<std::string>& blocks);

/// Matrix artefacts (artifact_codec.h) of consecutive row blocks joined into one (the first
/// block's header lines). Throws std::invalid_argument when there is none or their columns,
/// components or header lines differ.
std::string join_matrix_blocks(const std::vector<std::string>& blocks);

/// Output `k` of every block (a SensorBlocks::join's input), in block order.
std::vector<std::string> output_of_blocks(const std::vector<std::vector<std::string>>& blocks, std::size_t k);

/// The sensor blocks of a step whose one output is a matrix artefact with a row per sensor
/// (the direct sun): `rows(range)` computes the range's rows.
SensorBlocks matrix_sensor_blocks(std::size_t sensors, std::function<RadianceMatrix(engine::SensorRange)> rows);

}  // namespace dayphoton::study
