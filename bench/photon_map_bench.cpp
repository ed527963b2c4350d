// Photon map throughput: build time, k-NN lookups per second (k = 50, 200, 1000) with and
// without a source filter, bytes per stored photon, and the cost of the density estimates
// (fixed bandwidth, contributions, bias compensation against a fixed n_max: thesis
// Table 5.1 / digest T-9 reports +20-30 %).
//
// Two photon sets in a 6 x 4 x 3 m room: "volume" (uniform in the box, the worst case for
// a 3-d tree) and "surfaces" (uniform over the six faces, area-weighted, as photons really
// lie). Every photon gets one of 146 sources (a Tregenza sky plus ground), so a source
// filter keeps 1/146 of them. Queries: uniform in the box / on the faces, fixed seed.
// Then a receiver plane (photons of one source on a 50 m floor, sensors on a 0.5 m grid):
// plain k-NN lookups against those hinted with the previous sensor's k-th distance.
// Usage: photon_map_bench [photons]   (default 1 000 000)
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <thread>
#include <vector>

#include "dayphoton/engine/density_estimate.h"
#include "dayphoton/engine/photon_map.h"

using namespace dayphoton;
using namespace dayphoton::engine;

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint32_t Sources = 146;
constexpr double RoomX = 6, RoomY = 4, RoomZ = 3;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// A point on the room's faces, area-weighted.
Vec3 on_faces(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double areas[3] = {RoomY * RoomZ, RoomX * RoomZ, RoomX * RoomY};  // x-, y-, z-faces
  const double total = 2 * (areas[0] + areas[1] + areas[2]);
  double pick = u(rng) * total;
  const double a = u(rng), b = u(rng);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      if (pick < areas[axis] || (axis == 2 && side == 1)) {
        if (axis == 0) return {side * RoomX, a * RoomY, b * RoomZ};
        if (axis == 1) return {a * RoomX, side * RoomY, b * RoomZ};
        return {a * RoomX, b * RoomY, side * RoomZ};
      }
      pick -= areas[axis];
    }
  return {0, 0, 0};
}

Vec3 in_volume(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return {u(rng) * RoomX, u(rng) * RoomY, u(rng) * RoomZ};
}

template <typename Where>
std::vector<Photon> make_photons(std::size_t n, Where&& where) {
  std::mt19937_64 rng(2024);
  std::uniform_int_distribution<std::uint32_t> source(0, Sources - 1);
  std::uniform_real_distribution<float> flux(0.5f, 1.5f);
  std::vector<Photon> photons(n);
  for (Photon& p : photons) {
    const Vec3 x = where(rng);
    p.position = {static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z)};
    p.flux = {flux(rng), flux(rng), flux(rng)};
    p.source = source(rng);
    p.path_class = PathClass::Global;
    p.set_normal({0, 0, 1});
  }
  return photons;
}

/// Runs `one(i)` over the queries, repeating until at least `min_seconds`; returns calls/s.
template <typename One>
double rate(std::size_t queries, double min_seconds, One&& one) {
  const auto t0 = Clock::now();
  std::size_t calls = 0;
  do {
    for (std::size_t i = 0; i < queries; ++i) one(i);
    calls += queries;
  } while (seconds_since(t0) < min_seconds);
  return calls / seconds_since(t0);
}

template <typename Where>
void bench_set(const char* name, std::size_t n, Where&& where) {
  std::printf("\n== %s: %zu photons in a %.0f x %.0f x %.0f m room ==\n", name, n, RoomX, RoomY, RoomZ);
  std::vector<Photon> photons = make_photons(n, where);
  std::vector<Photon> copy = photons;
  auto t0 = Clock::now();
  const PhotonMap map(std::move(photons));
  const double build_s = seconds_since(t0);
  double build_serial_s = 0;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    t0 = Clock::now();
    const PhotonMap serial(std::move(copy));
    build_serial_s = seconds_since(t0);
  }
  std::printf("build: %.3f s (%u threads), %.3f s (1 thread)\n", build_s,
              std::max(1u, std::thread::hardware_concurrency()), build_serial_s);
  std::printf("memory: %.2f bytes/photon (sizeof(Photon) = %zu, tree %.2f)\n",
              double(map.memory_bytes()) / n, sizeof(Photon),
              double(map.memory_bytes()) / n - sizeof(Photon));

  std::mt19937_64 rng(99);
  std::vector<Vec3> queries(2000);
  for (Vec3& q : queries) q = where(rng);
  PhotonFilter any;
  PhotonFilter one_source;
  one_source.source = 17;
  std::vector<NeighbourPhoton> out;
  std::printf("%-28s %12s %12s %14s\n", "k-NN lookups (1 thread)", "k", "lookups/s", "mean radius m");
  for (std::size_t k : {50, 200, 1000})
    for (const PhotonFilter* filter : {&any, &one_source}) {
      const std::size_t count = filter == &any ? queries.size() : queries.size() / 10;
      double radius_sum = 0;
      std::size_t calls = 0;
      const double per_s = rate(count, 0.5, [&](std::size_t i) {
        map.nearest(queries[i], k, 1e30, *filter, out);
        radius_sum += out.empty() ? 0.0 : std::sqrt(out.back().distance_squared_m2);
        ++calls;
      });
      std::printf("%-28s %12zu %12.0f %14.3f\n", filter == &any ? "  any source" : "  one source of 146",
                  k, per_s, radius_sum / calls);
    }
  // All cores, k = 200, any source.
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  t0 = Clock::now();
  std::size_t total = 0;
  do {
    tbb::parallel_for(std::size_t(0), queries.size(), [&](std::size_t i) {
      std::vector<NeighbourPhoton> local;
      map.nearest(queries[i], 200, 1e30, any, local);
    });
    total += queries.size();
  } while (seconds_since(t0) < 0.5);
  std::printf("  any source, k = 200, %u threads: %.0f lookups/s\n", threads, total / seconds_since(t0));

  // Density estimates (1 thread).
  std::printf("%-44s %12s\n", "estimates (1 thread)", "per s");
  for (std::size_t bandwidth : {50, 1000}) {
    DensityEstimateOptions options;
    options.bandwidth = bandwidth;
    const double per_s = rate(queries.size() / 4, 0.5, [&](std::size_t i) {
      estimate_irradiance(map, queries[i], any, options);
    });
    std::printf("  irradiance, N = %-27zu %12.0f\n", bandwidth, per_s);
  }
  {
    DensityEstimateOptions options;
    options.bandwidth = 1000;
    std::vector<Vec3> per_source(Sources);
    const double per_s = rate(queries.size() / 4, 0.5, [&](std::size_t i) {
      estimate_contributions(map, queries[i], any, options, per_source);
    });
    std::printf("  contributions of %u sources, N = %-10d %12.0f\n", Sources, 1000, per_s);
  }
  {
    BiasCompensationOptions options;
    options.n_min = 50;
    options.n_max = 1000;
    double bandwidth_sum = 0;
    std::size_t calls = 0;
    const double per_s = rate(queries.size() / 4, 0.5, [&](std::size_t i) {
      options.rng_index = i;
      bandwidth_sum += estimate_irradiance_bias_compensated(map, queries[i], any, options).photon_count;
      ++calls;
    });
    std::printf("  bias compensated, N = 50..1000 %13s %12.0f  (mean bandwidth %.0f)\n", "", per_s,
                bandwidth_sum / calls);
  }
}

/// A receiver plane as the coefficients see it: `n` photons of one source uniform on a
/// 50 m x 50 m plane at 0.8 m, sensors on a 0.5 m grid visited row by row (the order of a
/// task of consecutive sensors). Plain lookups against lookups hinted with the previous
/// sensor's k-th distance plus the step (PhotonMap::nearest's hint), in one run; the photons
/// found are compared too.
void bench_plane(std::size_t n) {
  constexpr double Side = 50, Height = 0.8, Spacing = 0.5;
  std::printf("\n== receiver plane: %zu photons of one source on %.0f m x %.0f m, sensors every %.1f m ==\n", n,
              Side, Side, Spacing);
  const PhotonMap map(make_photons(n, [](std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, Side);
    return Vec3{u(rng), u(rng), Height};
  }));
  std::vector<Vec3> sensors;  // 20 rows of 100 (2,000 sensors)
  for (int row = 0; row < 20; ++row)
    for (int col = 0; col < 100; ++col) sensors.push_back({0.25 + Spacing * col, 0.25 + Spacing * (40 + row), Height});
  PhotonFilter filter;  // indirect classes, any source: what a per-source map's lookup asks
  std::printf("%-10s %16s %16s %8s %10s\n", "k", "plain lookups/s", "hinted lookups/s", "ratio", "repeats");
  for (std::size_t k : {101, 1601}) {
    std::vector<NeighbourPhoton> out, check;
    std::vector<double> kth(sensors.size());
    const double plain = rate(sensors.size(), 0.5, [&](std::size_t i) {
      map.nearest(sensors[i], k, 1e30, filter, out);
      kth[i] = out.size() == k ? std::sqrt(out.back().distance_squared_m2) : 1e30;
    });
    std::size_t repeats = 0, calls = 0;
    double previous_kth = std::numeric_limits<double>::quiet_NaN();
    const double hinted = rate(sensors.size(), 0.5, [&](std::size_t i) {
      const double hint = i > 0 ? (previous_kth + length(sensors[i] - sensors[i - 1])) * (1 + 1e-9)
                                : std::numeric_limits<double>::quiet_NaN();
      if (!map.nearest(sensors[i], k, 1e30, hint, filter, out)) ++repeats;
      ++calls;
      previous_kth = out.size() == k ? std::sqrt(out.back().distance_squared_m2) : 1e30;
    });
    std::size_t differ = 0;
    for (std::size_t i = 0; i < sensors.size(); i += 7) {
      map.nearest(sensors[i], k, 1e30, filter, check);
      map.nearest(sensors[i], k, 1e30, i > 0 ? kth[i - 1] + Spacing * 1.000001 : -1.0, filter, out);
      if (out.size() != check.size() || !std::equal(out.begin(), out.end(), check.begin(), [](auto& a, auto& b) {
            return a.index == b.index && a.distance_squared_m2 == b.distance_squared_m2;
          }))
        ++differ;
    }
    std::printf("%-10zu %16.0f %16.0f %8.2f %9.2f%%%s\n", k, plain, hinted, hinted / plain,
                100.0 * double(repeats) / double(calls), differ ? "  RESULTS DIFFER" : "");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? static_cast<std::size_t>(std::atof(argv[1])) : 1000000;
  std::printf("photon_map_bench: PhotonMap::LeafSize = %zu\n", PhotonMap::LeafSize);
  bench_set("volume", n, in_volume);
  bench_set("surfaces", n, on_faces);
  bench_plane(20000);
  return 0;
}
