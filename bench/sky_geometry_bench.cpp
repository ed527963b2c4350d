// Throughput of the sky geometry: solar positions per second for each algorithm
// (sky/solar_position.h) and patch-bin lookups and samples per second (sky/patch_basis.h).
// Prints figures only; not a test. Single thread.
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/solar_position.h"

using namespace dayphoton;
using namespace dayphoton::sky;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double bench_solar(SolarPositionAlgorithm alg, bool refraction, const char* name) {
  SolarSite site;
  site.latitude_deg = 37.72;
  site.longitude_deg = -122.22;
  site.time_zone_h = -8.0;
  SolarPositionOptions o;
  o.algorithm = alg;
  o.apply_refraction = refraction;
  static constexpr int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  double checksum = 0.0;
  long count = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int rep = 0; rep < (alg == SolarPositionAlgorithm::Spa ? 4 : 40); ++rep)
    for (int m = 1; m <= 12; ++m)
      for (int d = 1; d <= days[m - 1]; ++d)
        for (int h = 0; h < 24; ++h) {
          checksum += solar_position(site, SolarTime{2021, m, d, h + 0.5}, o).altitude_rad;
          ++count;
        }
  const double s = seconds_since(t0);
  std::printf("solar position %-22s %12.0f positions/s  (%ld in %.3f s, checksum %.6f)\n", name,
              count / s, count, s, checksum);
  return count / s;
}

void bench_bins(const PatchBasis& b, const char* name) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> dirs(1 << 20);
  for (Vec3& d : dirs) d = Vec3{u(rng), u(rng), u(rng)};
  long sum = 0;
  auto t0 = std::chrono::steady_clock::now();
  for (int rep = 0; rep < 4; ++rep)
    for (const Vec3& d : dirs) sum += b.find_bin(d);
  double s = seconds_since(t0);
  std::printf("find_bin %-28s %12.0f lookups/s  (checksum %ld)\n", name, 4.0 * dirs.size() / s, sum);

  double zsum = 0.0;
  std::uniform_real_distribution<double> v(0.0, 1.0);
  t0 = std::chrono::steady_clock::now();
  const long n = 1 << 22;
  for (long i = 0; i < n; ++i)
    zsum += b.sample_direction(static_cast<int>(i % b.bin_count()), v(rng), v(rng)).z;
  s = seconds_since(t0);
  std::printf("sample_direction %-20s %12.0f samples/s  (checksum %.3f)\n", name, n / s, zsum);
}

}  // namespace

int main() {
  bench_solar(SolarPositionAlgorithm::Spa, false, "SPA");
  bench_solar(SolarPositionAlgorithm::Spa, true, "SPA + refraction");
  bench_solar(SolarPositionAlgorithm::Radiance, false, "RADIANCE (IES)");
  bench_solar(SolarPositionAlgorithm::RadianceMichalsky, false, "RADIANCE Michalsky");
  bench_bins(PatchBasis::tregenza(), "Tregenza (146 bins)");
  bench_bins(PatchBasis::reinhart(4), "Reinhart MF4 (2306 bins)");
  bench_bins(PatchBasis::reinhart(6), "Reinhart MF6 (5186 bins)");
  return 0;
}
