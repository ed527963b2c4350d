// ResourceLimits: the largest study dayphoton runs without being told, so that a typo
// (`spacing: 0.000001`, `photons_per_bin: 1000000000000`, `--basis reinhart:64`) or a
// hostile file (a 7 KB matrix claiming 4.9 million rows, a gzip bomb) gives a clear error
// instead of gigabytes of allocation and a crash. Each limit is checked against the size an
// input implies *before* anything of that size is allocated, and each is raised explicitly:
// the project keys `limits.sensors_per_grid`, `limits.sensors` and `limits.photons`
// (docs/project-format.md), the options `--max-matrix-values` and `--max-decompressed-bytes`
// of `dayphoton sky` and `dayphoton annual` (docs/cli.md).
//
// The defaults keep every single allocation near or below 1 GiB on an hourly year.
#pragma once

#include <cstdint>
#include <string>

namespace dayphoton {

struct ResourceLimits {
  /// Sensors of one grid or point set. An annual study holds 8760 floats per sensor in the
  /// illuminance table alone (35 KB): 20 000 sensors make 0.7 GB.
  std::uint64_t sensors_per_grid = 20'000;
  /// Sensors of all grids and point sets of a project together.
  std::uint64_t sensors = 100'000;
  /// Photons stored by one tracing pass, counted as (photons_per_bin +
  /// caustic_photons_per_bin) x sky bins; a photon record is 32 bytes, so 2^25 is 1 GiB.
  std::uint64_t photons = 1ULL << 25;
  /// Values (NROWS x NCOLS x NCOMP) of one matrix read or built, and of an annual
  /// illuminance table (steps x sensors): 2^28 floats are 1 GiB. A Tregenza sky matrix of an
  /// hourly year holds 3.8 million, a Reinhart MF 8 one 242 million.
  std::uint64_t matrix_values = 1ULL << 28;
  /// Bytes a compressed input (.gz) may decompress to: 4 GiB (gendaymtx's ascii output of a
  /// Reinhart MF 6 year is 1.4 GB).
  std::uint64_t decompressed_bytes = 4ULL << 30;
};

/// The end of every limit message, saying how to raise the limit:
/// "more than the limit of 20000 (raise it with limits.sensors_per_grid if you mean it)";
/// `unit` follows the number ("bytes").
std::string over_limit_text(std::uint64_t limit, const std::string& raised_by, const std::string& unit = {});

}  // namespace dayphoton
