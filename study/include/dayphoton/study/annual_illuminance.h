// Annual illuminance: coefficients x sky matrix, as RADIANCE's dctimestep computes it
// (DESIGN.md section 4): E[t][s] = 179 * sum_c w_c * sum_p C[s][p][c] S[p][t][c] lux, with
// w = (0.265, 0.670, 0.065). Columns of the sky matrix that are all zero (night) give 0.
//
// Binary layout of illuminance.bin (little-endian), documented in docs/outputs.md:
//   8 bytes  magic "DPILLUM1"
//   uint32   number of time steps T, uint32 number of sensors S
//   T x (uint8 month, uint8 day, uint16 reserved = 0, float32 hour) time stamps
//   T x S float32 illuminance in lux, time step outer, sensor inner
#pragma once

#include <string>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/metrics/illuminance_table.h"

namespace dayphoton::study {

/// `coefficients`: sensors x bins x 3; `sky_matrix`: bins x steps x 3; `steps` one per
/// column. Parallel over time steps. Throws std::invalid_argument on size mismatches.
metrics::IlluminanceTable annual_illuminance(const RadianceMatrix& coefficients,
                                             const RadianceMatrix& sky_matrix,
                                             const std::vector<metrics::TimeStamp>& steps);

/// Write / read the binary layout above (atomic write; read throws std::runtime_error
/// naming the file on any layout problem).
void write_illuminance_binary(const metrics::IlluminanceTable& table, const std::string& path);
metrics::IlluminanceTable read_illuminance_binary(const std::string& path);

/// CSV: header `month,day,hour,s0,s1,...` (hour = mid-hour in local standard time, as the
/// sky was evaluated), one row per time step, lux with 1 decimal. Atomic.
void write_illuminance_csv(const metrics::IlluminanceTable& table, const std::string& path);

}  // namespace dayphoton::study
