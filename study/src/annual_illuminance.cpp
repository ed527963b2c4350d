// Annual illuminance E = C . S (DESIGN.md section 4, dctimestep's product followed by
// rmtxop's photometric conversion, refdata c_annual README), and its CSV and binary files.
//
// Speed (165 sensors x 146 bins x 8760 steps): the photometric weights are folded into the
// coefficients once, W[s][p c] = 179 w_c C[s][p][c], so every step is one dot product of
// length bins x 3 per sensor. Night steps (all-zero sky columns, about half the year) are
// skipped and stay 0. The day columns are processed in tiles of Tile steps: a tile of sky
// columns is gathered into a contiguous, step-interleaved buffer, and each row of W is
// multiplied into Tile independent accumulators, vectorised without reassociating any sum
// (each accumulator is a plain sequential sum over p and c, so the result does not depend on
// the tiling, the thread count or the instruction set: tile_product.h). A task holds
// TilesPerTask tiles, and two rows of W at a time are read once per task (about 10,000
// sensors x 146 bins: W is 35 MB, read from memory once per task instead of once per tile).
// oneTBB spreads the tasks over the cores. W is made and multiplied a block of sensors at a
// time (WeightBlockValues), so the product holds 16 MiB of weights whatever the grid's size
// (with the sub-patch terms a row of W is up to 7 x bins doubles: 80 MB at 10,000 sensors).
//
// The sub-patch correction (sub_patch_shares.h) extends each row of W and each gathered sky
// column: for every sky bin p that some sensor's direct part sees, four more terms, W =
// 179 (lum C_p, Q_p0, Q_p1, Q_p2) against (d_p3, d_p0 - d_p3, d_p1 - d_p3, d_p2 - d_p3), d_pq
// the quadrant deltas, which sum to 179 sum_q Q_pq d_pq with Q_p3 = lum C_p - Q_p0 - Q_p1 -
// Q_p2. Bins no sensor of the rows sees directly (zero shares) add nothing and are left out.
#include "dayphoton/study/annual_illuminance.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/units.h"
#include "dayphoton/study/tile_product.h"

namespace dayphoton::study {

namespace {

constexpr std::size_t Tile = detail::TileSteps;  ///< sky columns per tile (16 double accumulators)
constexpr std::size_t TilesPerTask = 4;          ///< tiles sharing one read of the weights
constexpr std::size_t SensorsPerProduct = 2;     ///< weight rows multiplied into a tile at once
/// Weights W held at once (2^21 doubles, 16 MiB): the rows of a block of sensors.
constexpr std::size_t WeightBlockValues = std::size_t(1) << 21;

std::vector<double> photometric_weights(int components) {
  if (components == 3)
    return {RadianceWhiteEfficacy_lm_per_W * RgbLuminanceWeights.x,
            RadianceWhiteEfficacy_lm_per_W * RgbLuminanceWeights.y,
            RadianceWhiteEfficacy_lm_per_W * RgbLuminanceWeights.z};
  if (components == 1) return {RadianceWhiteEfficacy_lm_per_W};
  throw std::invalid_argument("annual illuminance: matrices must have 1 or 3 components, not " +
                              std::to_string(components));
}

// --- little-endian encoding, independent of the host's byte order ---

void put_u8(std::string& out, unsigned v) { out.push_back(static_cast<char>(v & 0xffu)); }
void put_u16(std::string& out, std::uint16_t v) {
  put_u8(out, v);
  put_u8(out, v >> 8);
}
void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) put_u8(out, (v >> (8 * i)) & 0xffu);
}
void put_f32(std::string& out, float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  put_u32(out, bits);
}

std::uint32_t get_u32(const unsigned char* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
float get_f32(const unsigned char* p) {
  const std::uint32_t bits = get_u32(p);
  float v;
  std::memcpy(&v, &bits, 4);
  return v;
}

constexpr char Magic[8] = {'D', 'P', 'I', 'L', 'L', 'U', 'M', '1'};
constexpr std::size_t HeaderBytes = 8 + 4 + 4;
constexpr std::size_t StampBytes = 1 + 1 + 2 + 4;

[[noreturn]] void layout_error(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": not a valid illuminance.bin file: " + what);
}

/// Shortest text that reads back to the same double (hours: "0.5", "12.25").
void append_shortest(std::string& out, double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, result.ptr);
}

/// Lux with one decimal, from the value rounded to tenths (exact integer arithmetic, so the
/// CSV is identical on every platform and fast for millions of values). A value whose tenths
/// do not fit the integer arithmetic exactly (|v| >= 2^53 / 10) is printed by to_chars with
/// one decimal (such a float is a whole number). False, and nothing appended, if `v` is not
/// finite: llround(NaN) is undefined behaviour, and a NaN must never print as a number.
bool append_tenths(std::string& out, float v) {
  if (!std::isfinite(v)) return false;
  const double scaled = static_cast<double>(v) * 10.0;
  if (std::fabs(scaled) >= 9007199254740992.0) {  // 2^53
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, static_cast<double>(v), std::chars_format::fixed, 1);
    out.append(buffer, result.ptr);
    return true;
  }
  const long long tenths = std::llround(scaled);
  const unsigned long long magnitude = static_cast<unsigned long long>(tenths < 0 ? -tenths : tenths);
  if (tenths < 0) out.push_back('-');
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, magnitude / 10);
  out.append(buffer, result.ptr);
  out.push_back('.');
  out.push_back(static_cast<char>('0' + magnitude % 10));
  return true;
}

}  // namespace

metrics::IlluminanceTable annual_illuminance(const RadianceMatrix& coefficients,
                                             const RadianceMatrix& sky_matrix,
                                             const std::vector<metrics::TimeStamp>& steps,
                                             std::size_t first_sensor, const SubPatchShares* shares,
                                             const RadianceMatrix* quadrant_deltas) {
  if (coefficients.columns() != sky_matrix.rows())
    throw std::invalid_argument("annual illuminance: " + std::to_string(coefficients.columns()) +
                                " coefficient bins but a sky matrix of " + std::to_string(sky_matrix.rows()) +
                                " bins");
  if (coefficients.components() != sky_matrix.components())
    throw std::invalid_argument("annual illuminance: coefficients have " +
                                std::to_string(coefficients.components()) + " components, the sky matrix " +
                                std::to_string(sky_matrix.components()));
  if (steps.size() != sky_matrix.columns())
    throw std::invalid_argument("annual illuminance: " + std::to_string(steps.size()) +
                                " time stamps for a sky matrix of " + std::to_string(sky_matrix.columns()) +
                                " steps");
  const std::vector<double> w = photometric_weights(coefficients.components());
  const std::size_t n_sensors = coefficients.rows();
  const std::size_t n_bins = coefficients.columns();
  const std::size_t n_comp = static_cast<std::size_t>(coefficients.components());
  const std::size_t n_steps = sky_matrix.columns();
  constexpr std::size_t Q = SubPatchShares::ValuesPerBin;
  const bool correct = shares && !shares->empty() && quadrant_deltas && quadrant_deltas->rows() > 0;
  if (correct && (shares->sensors != n_sensors || shares->bins != n_bins || quadrant_deltas->rows() != Q * n_bins ||
                  quadrant_deltas->columns() != n_steps || quadrant_deltas->components() != 1))
    throw std::invalid_argument("annual illuminance: sub-patch shares of " + std::to_string(shares->sensors) +
                                " sensors x " + std::to_string(shares->bins) + " bins and quadrant deltas of " +
                                std::to_string(quadrant_deltas->rows()) + " rows x " +
                                std::to_string(quadrant_deltas->columns()) + " steps for " +
                                std::to_string(n_sensors) + " sensors x " + std::to_string(n_bins) + " bins x " +
                                std::to_string(n_steps) + " steps");
  // The bins some row's direct part sees (their shares are not all zero).
  std::vector<std::size_t> seen;
  if (correct)
    for (std::size_t p = 0; p < n_bins; ++p) {
      bool any = false;
      for (std::size_t s = 0; s < n_sensors && !any; ++s)
        for (std::size_t v = 0; v < Q; ++v) any = any || shares->values[(s * n_bins + p) * Q + v] != 0.0f;
      if (any) seen.push_back(p);
    }
  const std::size_t k_sky = n_bins * n_comp;
  const std::size_t k = k_sky + Q * seen.size();  // length of one dot product

  metrics::IlluminanceTable table(steps, n_sensors);
  if (n_sensors == 0 || n_steps == 0) return table;

  const float* deltas = correct ? quadrant_deltas->data().data() : nullptr;

  // Day steps: columns with any non-zero value. Row by row, so the matrix is read in order.
  std::vector<char> lit(n_steps, 0);
  const float* sky = sky_matrix.data().data();
  for (std::size_t p = 0; p < n_bins; ++p)
    for (std::size_t t = 0; t < n_steps; ++t) {
      const float* v = sky + (p * n_steps + t) * n_comp;
      for (std::size_t c = 0; c < n_comp; ++c) lit[t] |= v[c] != 0.0f;
    }
  std::vector<std::size_t> day;
  for (std::size_t t = 0; t < n_steps; ++t)
    if (lit[t]) day.push_back(t);
  const std::size_t n_tiles = (day.size() + Tile - 1) / Tile;

  // Tasks of TilesPerTask tiles: each pair of weight rows is read from memory once per task and
  // kept in the first-level cache for its tiles (the gathered columns of the task's tiles stay
  // in the second-level cache), a quarter of the memory traffic of a pass over the weights per
  // tile. Each value is still the one sequential sum of the plain loop (detail::tile_product).
  const std::size_t n_tasks = (n_tiles + TilesPerTask - 1) / TilesPerTask;
  // W a block of sensors at a time (WeightBlockValues doubles, an even count of rows): the
  // weights held do not grow with the grid (docs/photon-tracing.md "Scale"); each value is the
  // same sum whatever the block.
  const std::size_t block_rows = std::max<std::size_t>(
      SensorsPerProduct, WeightBlockValues / std::max<std::size_t>(1, k) / SensorsPerProduct * SensorsPerProduct);
  std::vector<double> weighted(std::min(block_rows, n_sensors) * k);
  for (std::size_t block_first = 0; block_first < n_sensors; block_first += block_rows) {
    const std::size_t block_end = std::min(n_sensors, block_first + block_rows);
    // W[s][p c] = 179 w_c C[s][p][c]; the coefficient matrix is already row-major (p, c). Then
    // the correction's 179 (lum C_p, Q_p0, Q_p1, Q_p2) of the bins seen.
    for (std::size_t s = block_first; s < block_end; ++s) {
      double* row = weighted.data() + (s - block_first) * k;
      for (std::size_t i = 0; i < k_sky; ++i)
        row[i] = w[i % n_comp] * static_cast<double>(coefficients.data()[s * k_sky + i]);
      for (std::size_t j = 0; j < seen.size(); ++j)
        for (std::size_t v = 0; v < Q; ++v)
          row[k_sky + j * Q + v] =
              RadianceWhiteEfficacy_lm_per_W * static_cast<double>(shares->values[(s * n_bins + seen[j]) * Q + v]);
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_tasks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
      std::vector<double> columns(TilesPerTask * k * Tile);  // tile u: columns[(u k + i) Tile + j] = S[p][t_j][c], i = p c
      double acc[SensorsPerProduct * Tile];
      for (std::size_t task = r.begin(); task != r.end(); ++task) {
        const std::size_t first_tile = task * TilesPerTask;
        const std::size_t tiles = std::min(TilesPerTask, n_tiles - first_tile);
        std::fill(columns.begin(), columns.end(), 0.0);
        for (std::size_t u = 0; u < tiles; ++u) {
          const std::size_t first = (first_tile + u) * Tile;
          const std::size_t m = std::min(Tile, day.size() - first);
          double* tile_columns = columns.data() + u * k * Tile;
          for (std::size_t j = 0; j < m; ++j) {
            const std::size_t t = day[first + j];
            for (std::size_t p = 0; p < n_bins; ++p)
              for (std::size_t c = 0; c < n_comp; ++c)
                tile_columns[(p * n_comp + c) * Tile + j] = sky[(p * n_steps + t) * n_comp + c];
            for (std::size_t i = 0; i < seen.size(); ++i) {
              const float* d = deltas + (Q * seen[i]) * n_steps + t;  // row Q p + q, column t
              const double d3 = d[3 * n_steps];
              double* col = tile_columns + (k_sky + i * Q) * Tile + j;
              col[0] = d3;
              for (std::size_t q = 0; q < 3; ++q) col[(q + 1) * Tile] = double(d[q * n_steps]) - d3;
            }
          }
        }
        for (std::size_t s = block_first; s < block_end; s += SensorsPerProduct) {
          const std::size_t rows = std::min(SensorsPerProduct, block_end - s);
          for (std::size_t u = 0; u < tiles; ++u) {
            const std::size_t first = (first_tile + u) * Tile;
            const std::size_t m = std::min(Tile, day.size() - first);
            detail::tile_product(weighted.data() + (s - block_first) * k, rows, k, columns.data() + u * k * Tile, acc);
            for (std::size_t q = 0; q < rows; ++q)
              for (std::size_t j = 0; j < m; ++j) table.lux(day[first + j], s + q) = static_cast<float>(acc[q * Tile + j]);
          }
        }
      }
    });
  }
  // Finite inputs can still overflow a float (coefficients of 1e30 under a sky of 1e10).
  for (std::size_t t = 0; t < n_steps; ++t)
    for (std::size_t s = 0; s < n_sensors; ++s)
      if (!std::isfinite(table.lux(t, s)))
        throw std::range_error("annual illuminance: sensor " + std::to_string(first_sensor + s) + " at step " +
                               std::to_string(t) +
                               " is not a finite number (the coefficients times the sky matrix overflow a float)");
  return table;
}

void write_illuminance_binary(const metrics::IlluminanceTable& table, const std::string& path) {
  const std::size_t n_steps = table.step_count(), n_sensors = table.sensor_count();
  if (n_steps > 0xffffffffu || n_sensors > 0xffffffffu)
    throw std::invalid_argument(path + ": illuminance table too large for the binary layout");
  std::string bytes;
  bytes.reserve(HeaderBytes + n_steps * StampBytes);
  bytes.append(Magic, sizeof Magic);
  put_u32(bytes, static_cast<std::uint32_t>(n_steps));
  put_u32(bytes, static_cast<std::uint32_t>(n_sensors));
  for (const metrics::TimeStamp& stamp : table.steps()) {
    if (stamp.month < 1 || stamp.month > 12 || stamp.day < 1 || stamp.day > 31)
      throw std::invalid_argument(path + ": time stamp with month " + std::to_string(stamp.month) + " day " +
                                  std::to_string(stamp.day) + " cannot be written");
    put_u8(bytes, static_cast<unsigned>(stamp.month));
    put_u8(bytes, static_cast<unsigned>(stamp.day));
    put_u16(bytes, 0);
    put_f32(bytes, static_cast<float>(stamp.hour));
  }
  // The values a row at a time: the file is never held whole in memory.
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    std::string row;
    row.reserve(4 * n_sensors);
    for (std::size_t t = 0; t < n_steps; ++t) {
      row.clear();
      for (std::size_t s = 0; s < n_sensors; ++s) put_f32(row, table.lux(t, s));
      out.write(row.data(), static_cast<std::streamsize>(row.size()));
    }
  }, true);
}

metrics::IlluminanceTable read_illuminance_binary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open illuminance file");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size < 0 || in.bad()) throw std::runtime_error(path + ": read error");
  const std::uint64_t file_bytes = static_cast<std::uint64_t>(size);
  unsigned char header[HeaderBytes];
  if (file_bytes < HeaderBytes) layout_error(path, "shorter than its 16-byte header");
  if (!in.read(reinterpret_cast<char*>(header), HeaderBytes)) throw std::runtime_error(path + ": read error");
  if (std::memcmp(header, Magic, sizeof Magic) != 0) layout_error(path, "wrong magic (expected DPILLUM1)");
  const std::uint64_t n_steps = get_u32(header + 8), n_sensors = get_u32(header + 12);
  const std::uint64_t expected = HeaderBytes + n_steps * StampBytes + n_steps * n_sensors * 4;
  if (file_bytes != expected)
    layout_error(path, std::to_string(n_steps) + " steps x " + std::to_string(n_sensors) + " sensors need " +
                           std::to_string(expected) + " bytes, the file has " + std::to_string(file_bytes));
  // Read a part at a time: the table is the only copy of the values held.
  std::vector<unsigned char> buffer(std::max<std::uint64_t>(n_steps * StampBytes, n_sensors * 4));
  auto read = [&](std::size_t n) {
    if (!in.read(reinterpret_cast<char*>(buffer.data()), static_cast<std::streamsize>(n)))
      throw std::runtime_error(path + ": read error");
  };
  read(static_cast<std::size_t>(n_steps * StampBytes));
  std::vector<metrics::TimeStamp> steps(n_steps);
  const unsigned char* p = buffer.data();
  for (std::uint64_t t = 0; t < n_steps; ++t, p += StampBytes) {
    const int month = p[0], day = p[1];
    const unsigned reserved = unsigned(p[2]) | unsigned(p[3]) << 8;
    const float hour = get_f32(p + 4);
    if (month < 1 || month > 12 || day < 1 || day > 31 || reserved != 0 || !std::isfinite(hour) || hour < 0 ||
        hour > 24)
      layout_error(path, "time stamp " + std::to_string(t) + " is invalid");
    steps[t] = metrics::TimeStamp{month, day, static_cast<double>(hour)};
  }
  metrics::IlluminanceTable table(std::move(steps), n_sensors);
  for (std::uint64_t t = 0; t < n_steps; ++t) {
    read(static_cast<std::size_t>(n_sensors * 4));
    p = buffer.data();
    for (std::uint64_t s = 0; s < n_sensors; ++s, p += 4) {
      const float lux = get_f32(p);
      if (!std::isfinite(lux))
        layout_error(path, "illuminance of step " + std::to_string(t) + ", sensor " + std::to_string(s) +
                               " is not finite");
      table.lux(t, s) = lux;
    }
  }
  return table;
}

void write_illuminance_csv(const metrics::IlluminanceTable& table, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    std::string line = "month,day,hour";
    for (std::size_t s = 0; s < table.sensor_count(); ++s) line += ",s" + std::to_string(s);
    line += '\n';
    out << line;
    for (std::size_t t = 0; t < table.step_count(); ++t) {
      const metrics::TimeStamp& stamp = table.steps()[t];
      line = std::to_string(stamp.month) + ',' + std::to_string(stamp.day) + ',';
      append_shortest(line, stamp.hour);
      for (std::size_t s = 0; s < table.sensor_count(); ++s) {
        line.push_back(',');
        if (!append_tenths(line, table.lux(t, s)))
          throw std::invalid_argument(path + ": the illuminance of sensor " + std::to_string(s) + " at step " +
                                      std::to_string(t) + " is not a finite number");
      }
      line.push_back('\n');
      out.write(line.data(), static_cast<std::streamsize>(line.size()));
    }
  });
}

}  // namespace dayphoton::study
