// Annual illuminance: coefficients x sky matrix, as RADIANCE's dctimestep computes it
// (DESIGN.md section 4): E[t][s] = 179 * sum_c w_c * sum_p C[s][p][c] S[p][t][c] lux, with
// w = (0.265, 0.670, 0.065). Columns of the sky matrix that are all zero (night) give 0.
//
// The sums are accumulated in double, in bin order, so the result does not depend on the
// thread count; values are stored as float (IlluminanceTable).
//
// Binary layout of illuminance.bin (little-endian), documented in docs/outputs.md:
//   8 bytes  magic "DPILLUM1"
//   uint32   number of time steps T, uint32 number of sensors S
//   T x (uint8 month, uint8 day, uint16 reserved = 0, float32 hour) time stamps
//   T x S float32 illuminance in lux, time step outer, sensor inner
// File size is exactly 16 + 8 T + 4 T S bytes.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/study/sub_patch_shares.h"

namespace dayphoton::study {

/// `coefficients`: sensors x bins x 3; `sky_matrix`: bins x steps x 3 (both may instead have
/// one component, weight 179); `steps` one per column. Parallel over time steps (oneTBB).
/// Throws std::invalid_argument on size or component mismatches, std::range_error naming the
/// sensor and step where a value overflows a float. `first_sensor`: the grid's index of the
/// coefficients' first row, when they are a block of a grid's sensors (annual_blocks.h), so
/// that the error names the grid's own sensor. `shares` and `quadrant_deltas` (both given and
/// non-empty; sky::SkyMatrix::quadrant_deltas of the same sky): the sub-patch correction of
/// the direct part is added (sub_patch_shares.h), in the same sequential sum per value, after
/// the patch-uniform terms; a std::invalid_argument if their shapes do not match.
metrics::IlluminanceTable annual_illuminance(const RadianceMatrix& coefficients,
                                             const RadianceMatrix& sky_matrix,
                                             const std::vector<metrics::TimeStamp>& steps,
                                             std::size_t first_sensor = 0,
                                             const SubPatchShares* shares = nullptr,
                                             const RadianceMatrix* quadrant_deltas = nullptr);

/// Write / read the binary layout above (atomic write; read throws std::runtime_error
/// naming the file on any layout problem: magic, size, a time stamp outside month 1..12,
/// day 1..31, hour 0..24, non-zero reserved bytes, a non-finite value).
void write_illuminance_binary(const metrics::IlluminanceTable& table, const std::string& path);
metrics::IlluminanceTable read_illuminance_binary(const std::string& path);

/// CSV: header `month,day,hour,s0,s1,...` (hour = mid-hour in local standard time, as the
/// sky was evaluated, in its shortest form "0.5"), one row per time step, lux with 1
/// decimal. Atomic. The layout of refdata's annual tables (metrics::read_illuminance_csv).
void write_illuminance_csv(const metrics::IlluminanceTable& table, const std::string& path);

}  // namespace dayphoton::study
