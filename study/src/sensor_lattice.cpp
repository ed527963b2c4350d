// Lattice of a grid's sensors; see sensor_lattice.h.
#include "dayphoton/study/sensor_lattice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dayphoton::study {

namespace {

SensorLattice one_row(std::size_t n) {
  SensorLattice l;
  l.regular = false;
  l.columns = static_cast<int>(n);
  l.rows = 1;
  for (std::size_t i = 0; i < n; ++i) {
    l.column_of.push_back(static_cast<int>(i));
    l.row_of.push_back(0);
  }
  return l;
}

}  // namespace

SensorLattice sensor_lattice(const std::vector<SensorPoint>& sensors) {
  const std::size_t n = sensors.size();
  if (n < 2) return one_row(n);
  const Vec3 normal = sensors[0].normal;
  if (!(length(normal) > 0.5)) return one_row(n);
  const Vec3 nz = normalize(normal);
  const Vec3 p0 = sensors[0].position;
  for (const SensorPoint& s : sensors)
    if (std::abs(dot(s.position - p0, nz)) > 1e-3) return one_row(n);

  // Spacing: the nearest-neighbour distance of the first sensors (on a lattice every sensor
  // with a neighbour has it at the spacing; 64 of them make a missing-neighbour case moot).
  double best = std::numeric_limits<double>::infinity();
  Vec3 axis;
  const std::size_t probes = std::min<std::size_t>(n, 64);
  for (std::size_t a = 0; a < probes; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b) continue;
      const Vec3 d = sensors[b].position - sensors[a].position;
      const double len = length(d);
      if (len > 1e-9 && len < best) {
        best = len;
        axis = d - nz * dot(d, nz);
      }
    }
  if (!std::isfinite(best) || !(length(axis) > 0)) return one_row(n);
  const double spacing = best;
  const Vec3 a = normalize(axis);
  const Vec3 b = cross(nz, a);
  // Image axes: columns along the lattice axis closest to east, rows toward the south (for
  // vertical grids, downward), so that the picture reads like a plan or an elevation.
  const Vec3 candidates[4] = {a, a * -1.0, b, b * -1.0};
  Vec3 column_axis = candidates[0];
  for (const Vec3& c : candidates)
    if (c.x > column_axis.x + 1e-9) column_axis = c;
  Vec3 row_axis = cross(nz, column_axis);
  const Vec3 down_south{0, -1, -0.5};
  if (dot(row_axis, down_south) < dot(row_axis * -1.0, down_south)) row_axis = row_axis * -1.0;

  std::vector<long long> ci(n), ri(n);
  long long min_c = 0, max_c = 0, min_r = 0, max_r = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = sensors[i].position - p0;
    const double u = dot(d, column_axis) / spacing, v = dot(d, row_axis) / spacing;
    const double ru = std::round(u), rv = std::round(v);
    if (std::abs(u - ru) > 0.01 || std::abs(v - rv) > 0.01) return one_row(n);
    ci[i] = static_cast<long long>(ru);
    ri[i] = static_cast<long long>(rv);
    if (i == 0 || ci[i] < min_c) min_c = ci[i];
    if (i == 0 || ci[i] > max_c) max_c = ci[i];
    if (i == 0 || ri[i] < min_r) min_r = ri[i];
    if (i == 0 || ri[i] > max_r) max_r = ri[i];
  }
  const long long columns = max_c - min_c + 1, rows = max_r - min_r + 1;
  if (columns * rows > 4 * static_cast<long long>(n)) return one_row(n);
  std::vector<char> used(static_cast<std::size_t>(columns * rows), 0);
  SensorLattice l;
  for (std::size_t i = 0; i < n; ++i) {
    const int c = static_cast<int>(ci[i] - min_c), r = static_cast<int>(ri[i] - min_r);
    char& cell = used[static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(c)];
    if (cell) return one_row(n);
    cell = 1;
    l.column_of.push_back(c);
    l.row_of.push_back(r);
  }
  l.regular = true;
  l.columns = static_cast<int>(columns);
  l.rows = static_cast<int>(rows);
  l.spacing_m = spacing;
  l.column_step_m = column_axis * spacing;
  l.row_step_m = row_axis * spacing;
  l.origin_m = p0 + l.column_step_m * static_cast<double>(min_c) + l.row_step_m * static_cast<double>(min_r);
  return l;
}

}  // namespace dayphoton::study
