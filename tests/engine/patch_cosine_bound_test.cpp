// max_cosine_over_patch (engine/patch_cosine_bound.h): the exact largest cosine over a sky
// patch, against dense sampling of the patch and against cases with a known answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/patch_cosine_bound.h"
#include "dayphoton/sky/patch_basis.h"

namespace dayphoton::engine {
namespace {

struct SampledMax {
  double value = -2;
  double spacing_rad = 0;  ///< largest angle between neighbouring nodes
};

/// Largest m . d over an (n + 1) x (n + 1) node lattice of the patch, borders included, as
/// sky::PatchBasis::sample_direction maps (sin altitude, azimuth); every direction of the
/// patch is within one spacing of a node, and m . d is 1-Lipschitz in the angle.
SampledMax sampled_max(const Vec3& m, double z0, double z1, double a0, double a1, int n) {
  SampledMax s;
  auto dir = [&](int i, int j) {
    const double z = z0 + (z1 - z0) * i / n, az = a0 + (a1 - a0) * j / n;
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    return Vec3{r * std::sin(az), r * std::cos(az), z};
  };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Vec3 d = dir(i, j);
      s.value = std::max(s.value, dot(m, d));
      for (const Vec3& e : {i > 0 ? dir(i - 1, j) : d, j > 0 ? dir(i, j - 1) : d})
        s.spacing_rad = std::max(s.spacing_rad, std::atan2(length(cross(d, e)), dot(d, e)));
    }
  return s;
}

std::vector<Vec3> test_directions() {
  std::vector<Vec3> m = {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}};
  // Tilted and oblique ones (a sloped roof light, a skewed facade).
  for (const Vec3& v : {Vec3{0.3, -0.8, 0.5}, Vec3{-0.6, 0.2, -0.77}, Vec3{0.7071, 0.7071, 0}, Vec3{0.1, 0.2, 0.97}})
    m.push_back(normalize(v));
  return m;
}

TEST(PatchCosineBound, EqualsTheDenseMaximumOverEveryTregenzaBinAndItsCells) {
  // Upper bound: never below any sampled direction. Tight: at most one lattice spacing above
  // the sampled maximum (the true maximum is within one spacing of a node).
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  for (const Vec3& m : test_directions())
    for (int bin = 0; bin < basis.bin_count(); ++bin) {
      const sky::PatchBounds b = basis.bounds(bin);
      const double z0 = std::sin(b.altitude_min_rad), z1 = std::sin(b.altitude_max_rad);
      for (int cells : {1, 8}) {
        const int cell = (bin * 7) % (cells * cells);  // one cell per bin, varying
        const int ci = cell / cells, cj = cell % cells;
        const double cz0 = z0 + (z1 - z0) * ci / cells, cz1 = z0 + (z1 - z0) * (ci + 1) / cells;
        const double ca0 = b.azimuth_min_rad + (b.azimuth_max_rad - b.azimuth_min_rad) * cj / cells;
        const double ca1 = b.azimuth_min_rad + (b.azimuth_max_rad - b.azimuth_min_rad) * (cj + 1) / cells;
        const double bound = max_cosine_over_patch(m, cz0, cz1, ca0, ca1);
        const SampledMax s = sampled_max(m, cz0, cz1, ca0, ca1, 24);
        EXPECT_GE(bound, s.value - 1e-12) << "bin " << bin << " cells " << cells;
        EXPECT_LE(bound, s.value + s.spacing_rad + 1e-12) << "bin " << bin << " cells " << cells;
      }
    }
}

TEST(PatchCosineBound, KnownCases) {
  // The patch holds m: the largest cosine is 1.
  EXPECT_NEAR(max_cosine_over_patch({0, 0, 1}, 0.9, 1.0, 0, 2 * Pi), 1.0, 1e-15);
  EXPECT_NEAR(max_cosine_over_patch(normalize(Vec3{1, 1, 1}), 0.0, 1.0, 0, Pi / 2), 1.0, 1e-15);
  // A south window (room normal north, +y) takes light from d . (0, -1, 0) > 0, i.e. from
  // the south: a bin of the northern half of the sky (azimuths within 90 degrees of north,
  // 0) touches the window's plane at most along an edge: its largest cosine is 0, not more.
  EXPECT_NEAR(max_cosine_over_patch({0, -1, 0}, 0.0, 0.2, -Pi / 2, Pi / 2), 0.0, 1e-15);
  // Behind the plane: the least negative cosine, at the band's top corner.
  EXPECT_NEAR(max_cosine_over_patch({0, -1, 0}, 0.0, 0.2, -0.2, 0.2), -std::cos(0.2) * std::sqrt(1 - 0.04), 1e-15);
  // The horizon band seen by a skylight (m up): its top edge.
  EXPECT_NEAR(max_cosine_over_patch({0, 0, 1}, 0.0, 0.2, 0, 1), 0.2, 1e-15);
  // The ground seen by a skylight: nothing above the horizon; by a window: the horizon ahead.
  EXPECT_NEAR(max_cosine_over_patch({0, 0, 1}, -1.0, 0.0, 0, 2 * Pi), 0.0, 1e-15);
  EXPECT_NEAR(max_cosine_over_patch({0, -1, 0}, -1.0, 0.0, 0, 2 * Pi), 1.0, 1e-15);
  // Azimuth ranges given past 2 pi or below 0 (the north patch starts below 0).
  EXPECT_NEAR(max_cosine_over_patch({0, 1, 0}, 0.0, 0.1, -0.1, 0.1), 1.0, 1e-15);
  EXPECT_NEAR(max_cosine_over_patch({0, 1, 0}, 0.0, 0.1, 2 * Pi - 0.1, 2 * Pi + 0.1), 1.0, 1e-15);
}

}  // namespace
}  // namespace dayphoton::engine
