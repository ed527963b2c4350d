// PhotonMap k-NN search against brute force (digest section 2.4 and item 8.5: balanced static
// tree, max-heap search, deterministic ties): random and degenerate point sets (coincident
// photons, photons on a plane and on a line), every filter, maximum search radius, k = 0,
// k > size, empty maps, all photons filtered out; the build is a permutation of its input
// and independent of the thread count; concurrent lookups agree with sequential ones.
//
// The comparison is exact: the brute force computes each squared distance with the same
// expression as the tree (double from the float position, dx^2 + dy^2 + dz^2) and orders by
// (distance, index), so any pruning error or tie-breaking difference shows as a mismatch.
#include "dayphoton/engine/photon_map.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

namespace dayphoton::engine {
namespace {

Photon make_photon(float x, float y, float z, std::uint32_t source, PathClass path_class,
                   const Vec3& normal, float tag) {
  Photon p;
  p.position = {x, y, z};
  p.flux = {tag, 1.0f, 2.0f};  // flux[0] tags the photon so tests can follow it
  p.source = source;
  p.path_class = path_class;
  p.set_normal(normal);
  return p;
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 v{g(rng), g(rng), g(rng)};
  return normalize(v);
}

/// Random photons; `position` draws the coordinates.
template <typename Position>
std::vector<Photon> random_photons(std::size_t n, std::uint64_t seed, Position&& position) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::uint32_t> source(0, 9);
  std::uniform_int_distribution<int> cls(0, 2);
  std::vector<Photon> photons;
  photons.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto p = position(rng);
    photons.push_back(make_photon(p[0], p[1], p[2], source(rng),
                                  static_cast<PathClass>(cls(rng)), random_unit(rng),
                                  static_cast<float>(i)));
  }
  return photons;
}

std::vector<NeighbourPhoton> brute_force(const PhotonMap& map, const Vec3& q, std::size_t k,
                                         double max_radius_m, const PhotonFilter& filter) {
  std::vector<NeighbourPhoton> all;
  const double bound2 = max_radius_m * max_radius_m;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const Photon& p = map.photons()[i];
    const double dx = static_cast<double>(p.position[0]) - q.x;
    const double dy = static_cast<double>(p.position[1]) - q.y;
    const double dz = static_cast<double>(p.position[2]) - q.z;
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (d2 <= bound2 && filter.accepts(p)) all.push_back({static_cast<std::uint32_t>(i), d2});
  }
  std::sort(all.begin(), all.end(), [](const NeighbourPhoton& a, const NeighbourPhoton& b) {
    return a.distance_squared_m2 < b.distance_squared_m2 ||
           (a.distance_squared_m2 == b.distance_squared_m2 && a.index < b.index);
  });
  if (all.size() > k) all.resize(k);
  return all;
}

void expect_same(const std::vector<NeighbourPhoton>& got,
                 const std::vector<NeighbourPhoton>& want, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].index, want[i].index) << what << ", neighbour " << i;
    ASSERT_EQ(got[i].distance_squared_m2, want[i].distance_squared_m2) << what << ", neighbour " << i;
  }
}

std::vector<PhotonFilter> test_filters() {
  std::vector<PhotonFilter> filters(6);
  filters[0].path_classes = 0x7;  // everything
  filters[1].source = 3;          // one source, indirect classes
  filters[2].path_classes = path_class_bit(PathClass::Caustic);
  filters[3].check_normal = true;
  filters[3].normal = normalize(Vec3{0.3, -0.2, 0.9});
  filters[3].min_cos = 0.5;
  filters[4].source = 7;
  filters[4].path_classes = path_class_bit(PathClass::Global);
  filters[4].check_normal = true;
  filters[4].normal = Vec3{0, 0, -1};
  filters[4].min_cos = 0.0;
  filters[5].source = 12345;  // no photon has it
  return filters;
}

/// Every filter x several k and radii x queries drawn by `query`.
template <typename Query>
void check_against_brute_force(const PhotonMap& map, std::uint64_t seed, int queries,
                               Query&& query, const std::vector<double>& radii) {
  std::mt19937_64 rng(seed);
  const std::size_t ks[] = {1, 2, 7, 50, 300, map.size() + 5};
  std::vector<NeighbourPhoton> got;
  for (const PhotonFilter& filter : test_filters())
    for (double radius : radii)
      for (std::size_t k : ks)
        for (int i = 0; i < queries; ++i) {
          const Vec3 q = query(rng);
          map.nearest(q, k, radius, filter, got);
          expect_same(got, brute_force(map, q, k, radius, filter), "random query");
          if (::testing::Test::HasFatalFailure()) return;
        }
}

constexpr double Inf = std::numeric_limits<double>::infinity();

TEST(PhotonRecord, NormalIsQuantisedAsLround) {
  // set_normal rounds inline; it must give std::lround's byte for every component, halves
  // (away from zero) and their neighbours included.
  auto expect_lround = [](double c) {
    Photon p;
    p.set_normal({c, -c, 0.5 * c});
    for (int k = 0; k < 3; ++k) {
      const double v = (k == 0 ? c : k == 1 ? -c : 0.5 * c) * 127.0;
      ASSERT_EQ(p.normal[static_cast<std::size_t>(k)], static_cast<std::int8_t>(std::lround(v))) << c;
    }
  };
  for (int i = -127; i <= 127; ++i)
    for (const double half : {-0.5, 0.0, 0.5}) {
      double c = (i + half) / 127.0;
      for (int step = 0; step < 3; ++step) c = std::nextafter(c, -2.0);
      for (int step = 0; step < 7; ++step, c = std::nextafter(c, 2.0)) expect_lround(c);
    }
  std::mt19937_64 rng(5);
  for (int i = 0; i < 100000; ++i) {
    const Vec3 n = random_unit(rng);
    expect_lround(n.x);
  }
  expect_lround(1.0);
  expect_lround(-1.0);
  expect_lround(0.0);
}

TEST(PhotonMap, EmptyMapAndZeroK) {
  const PhotonMap empty;
  std::vector<NeighbourPhoton> out{{1, 2.0}};
  empty.nearest({0, 0, 0}, 10, Inf, PhotonFilter{}, out);
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(empty.empty());

  const PhotonMap one(std::vector<Photon>{
      make_photon(1, 2, 3, 0, PathClass::Global, {0, 0, 1}, 0)});
  out = {{1, 2.0}};
  one.nearest({0, 0, 0}, 0, Inf, PhotonFilter{}, out);
  EXPECT_TRUE(out.empty());
  one.nearest({1, 2, 3}, 5, 0.0, PhotonFilter{}, out);  // radius 0 includes distance 0
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].distance_squared_m2, 0.0);
  one.nearest({1, 2, 3.5}, 5, 0.25, PhotonFilter{}, out);
  EXPECT_TRUE(out.empty());
}

TEST(PhotonMap, InvalidInputThrows) {
  std::vector<Photon> bad{make_photon(0, 0, 0, 0, PathClass::Global, {0, 0, 1}, 0),
                          make_photon(std::numeric_limits<float>::quiet_NaN(), 0, 0, 0,
                                      PathClass::Global, {0, 0, 1}, 1)};
  EXPECT_THROW(PhotonMap{bad}, std::invalid_argument);
  bad[1].position[1] = std::numeric_limits<float>::infinity();
  bad[1].position[0] = 0;
  EXPECT_THROW(PhotonMap{bad}, std::invalid_argument);
  const PhotonMap map(std::vector<Photon>{bad[0]});
  std::vector<NeighbourPhoton> out;
  EXPECT_THROW(map.nearest({0, 0, 0}, 1, -1.0, PhotonFilter{}, out), std::invalid_argument);
  EXPECT_THROW(map.nearest({0, 0, 0}, 1, std::numeric_limits<double>::quiet_NaN(),
                           PhotonFilter{}, out),
               std::invalid_argument);
}

TEST(PhotonMap, BuildIsAPermutationOfTheInput) {
  auto photons = random_photons(10000, 11, [](std::mt19937_64& rng) {
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    return std::array<float, 3>{u(rng), u(rng), u(rng)};
  });
  const PhotonMap map(photons);
  ASSERT_EQ(map.size(), photons.size());
  std::vector<bool> seen(photons.size(), false);
  for (const Photon& p : map.photons()) {
    const auto tag = static_cast<std::size_t>(p.flux[0]);
    ASSERT_LT(tag, photons.size());
    EXPECT_FALSE(seen[tag]);
    seen[tag] = true;
    const Photon& original = photons[tag];
    EXPECT_EQ(p.position, original.position);
    EXPECT_EQ(p.source, original.source);
    EXPECT_EQ(p.normal, original.normal);
    EXPECT_EQ(p.path_class, original.path_class);
  }
  EXPECT_GE(map.memory_bytes(), photons.size() * sizeof(Photon));
  // The second constructor reports the permutation: tree slot -> input index.
  std::vector<std::uint32_t> input_index;
  const PhotonMap with_index(photons, input_index);
  ASSERT_EQ(input_index.size(), photons.size());
  for (std::size_t t = 0; t < input_index.size(); ++t)
    EXPECT_EQ(static_cast<std::size_t>(with_index.photons()[t].flux[0]), input_index[t]);
}

TEST(PhotonMap, RandomVolumeMatchesBruteForce) {
  const PhotonMap map(random_photons(4000, 1, [](std::mt19937_64& rng) {
    std::uniform_real_distribution<float> x(0.0f, 6.0f), y(0.0f, 4.0f), z(0.0f, 3.0f);
    return std::array<float, 3>{x(rng), y(rng), z(rng)};
  }));
  check_against_brute_force(
      map, 2, 4,
      [](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(-0.5, 6.5);
        return Vec3{u(rng), u(rng) * 4 / 6, u(rng) * 3 / 6};
      },
      {Inf, 0.3, 1.0});
}

TEST(PhotonMap, PhotonsOnAPlaneAndOnALineMatchBruteForce) {
  // z = 0.8 exactly (a receiver plane) and a line along x: zero extent on some axes.
  const PhotonMap plane(random_photons(3000, 3, [](std::mt19937_64& rng) {
    std::uniform_real_distribution<float> u(0.0f, 5.0f);
    return std::array<float, 3>{u(rng), u(rng), 0.8f};
  }));
  auto query_near_plane = [](std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 5.0), h(-0.1, 0.1);
    return Vec3{u(rng), u(rng), 0.8 + h(rng)};
  };
  check_against_brute_force(plane, 4, 3, query_near_plane, {Inf, 0.2});

  const PhotonMap line(random_photons(2000, 5, [](std::mt19937_64& rng) {
    std::uniform_int_distribution<int> cell(0, 99);  // many exact duplicates too
    return std::array<float, 3>{0.01f * static_cast<float>(cell(rng)), 1.0f, 2.0f};
  }));
  check_against_brute_force(
      line, 6, 3,
      [](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(0.0, 1.0);
        return Vec3{u(rng), 1.0, 2.0 + 0.01 * u(rng)};
      },
      {Inf, 0.05});
}

TEST(PhotonMap, CoincidentPhotonsAreOrderedByIndex) {
  // 3000 photons on 3 points: every distance is tied many times over, so only the index
  // decides which photons are returned.
  const PhotonMap map(random_photons(3000, 7, [](std::mt19937_64& rng) {
    std::uniform_int_distribution<int> which(0, 2);
    const int w = which(rng);
    return std::array<float, 3>{w == 1 ? 1.0f : 0.0f, w == 2 ? 1.0f : 0.0f, 0.5f};
  }));
  check_against_brute_force(
      map, 8, 2,
      [](std::mt19937_64& rng) {
        std::uniform_int_distribution<int> which(0, 3);
        const int w = which(rng);
        return w == 3 ? Vec3{0.5, 0.5, 0.5} : Vec3{w == 1 ? 1.0 : 0.0, w == 2 ? 1.0 : 0.0, 0.5};
      },
      {Inf, 0.0, 1.0});

  // All photons on one point: the k returned are the k smallest indices.
  std::vector<Photon> same(500, make_photon(2, 2, 2, 1, PathClass::Global, {0, 0, 1}, 0));
  const PhotonMap stack(same);
  std::vector<NeighbourPhoton> out;
  stack.nearest({2, 2, 2}, 17, Inf, PhotonFilter{}, out);
  ASSERT_EQ(out.size(), 17u);
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i].index, i);
}

TEST(PhotonMap, AllPhotonsFilteredOut) {
  const PhotonMap map(random_photons(1000, 9, [](std::mt19937_64& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    return std::array<float, 3>{u(rng), u(rng), u(rng)};
  }));
  PhotonFilter none;
  none.path_classes = 0;
  std::vector<NeighbourPhoton> out{{3, 1.0}};
  map.nearest({0.5, 0.5, 0.5}, 50, Inf, none, out);
  EXPECT_TRUE(out.empty());
}

TEST(PhotonMap, HintedSearchMatchesBruteForce) {
  // The hint only decides the cost: every hint (none, zero, too small, the k-th distance
  // itself, the k-th distance seeded from a neighbouring point by the triangle inequality,
  // the maximum itself (every photon within it collected), wider than the maximum, NaN)
  // gives brute force's photons. Coincident photons on a
  // receiver-like plane make the k-th distance tied many times over.
  const PhotonMap map(random_photons(3000, 15, [](std::mt19937_64& rng) {
    std::uniform_int_distribution<int> cell(0, 30);  // duplicates: ties at the k-th distance
    return std::array<float, 3>{0.1f * static_cast<float>(cell(rng)), 0.1f * static_cast<float>(cell(rng)), 0.8f};
  }));
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-0.2, 3.2), step(-0.5, 0.5);
  std::vector<NeighbourPhoton> got, previous;
  int repeats = 0, hinted = 0;
  for (const PhotonFilter& filter : test_filters())
    for (double radius : {Inf, 0.4})
      for (std::size_t k : {std::size_t(1), std::size_t(7), std::size_t(101), map.size() + 5}) {
        Vec3 prev_q{u(rng), u(rng), 0.8};
        map.nearest(prev_q, k, radius, filter, previous);
        for (int i = 0; i < 8; ++i) {
          const Vec3 q{prev_q.x + step(rng), prev_q.y + step(rng), 0.8};
          const std::vector<NeighbourPhoton> want = brute_force(map, q, k, radius, filter);
          const double kth = want.empty() ? 0.0 : std::sqrt(want.back().distance_squared_m2);
          const double seeded = previous.size() == k
                                    ? std::sqrt(previous.back().distance_squared_m2) + length(q - prev_q)
                                    : Inf;
          for (double hint : {0.0, 0.5 * kth, kth, std::nextafter(kth, Inf), seeded, 2 * kth + 1, radius, Inf,
                              std::numeric_limits<double>::quiet_NaN()}) {
            const bool first_pass = map.nearest(q, k, radius, hint, filter, got);
            expect_same(got, want, "hinted query");
            if (::testing::Test::HasFatalFailure()) return;
            ++hinted;
            if (!first_pass) ++repeats;
          }
          previous = want;
          prev_q = q;
        }
      }
  // Both paths ran: hints that held k photons, and hints too small that were repeated.
  EXPECT_GT(repeats, 0);
  EXPECT_LT(repeats, hinted);
}

TEST(PhotonMap, RangeQueryMatchesBruteForce) {
  // within() returns brute force's photons within the radius (the rim included, ties of
  // coincident photons all kept), in some order: compared as sorted lists. A radius of 0
  // keeps only photons on the query point; a bad radius throws.
  const PhotonMap map(random_photons(3000, 17, [](std::mt19937_64& rng) {
    std::uniform_int_distribution<int> cell(0, 30);  // duplicates: photons exactly on the rim
    return std::array<float, 3>{0.1f * static_cast<float>(cell(rng)), 0.1f * static_cast<float>(cell(rng)), 0.8f};
  }));
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(-0.2, 3.2);
  std::vector<NeighbourPhoton> got;
  for (const PhotonFilter& filter : test_filters())
    for (double radius : {0.0, 0.1, 0.35, 1.2, 5.0})
      for (int i = 0; i < 6; ++i) {
        // Every third query on a lattice point, so that the rim and zero distances are hit.
        const Vec3 q = i % 3 == 0 ? Vec3{0.1 * (i + 3), 0.1 * (2 * i + 1), 0.8} : Vec3{u(rng), u(rng), 0.8};
        const std::vector<NeighbourPhoton> want = brute_force(map, q, map.size() + 1, radius, filter);
        map.within(q, radius, filter, got);
        std::sort(got.begin(), got.end(), [](const NeighbourPhoton& a, const NeighbourPhoton& b) {
          return a.distance_squared_m2 != b.distance_squared_m2 ? a.distance_squared_m2 < b.distance_squared_m2
                                                                : a.index < b.index;
        });
        expect_same(got, want, "range query");
        if (::testing::Test::HasFatalFailure()) return;
      }
  EXPECT_THROW(map.within(Vec3{1, 1, 0.8}, -1.0, PhotonFilter{}, got), std::invalid_argument);
  EXPECT_THROW(map.within(Vec3{1, 1, 0.8}, Inf, PhotonFilter{}, got), std::invalid_argument);
  EXPECT_THROW(map.within(Vec3{1, 1, 0.8}, std::numeric_limits<double>::quiet_NaN(), PhotonFilter{}, got),
               std::invalid_argument);
}

TEST(PhotonMap, BuildDoesNotDependOnThreadCount) {
  // Above the parallel build threshold (2^16) so that subtrees are built concurrently.
  const auto photons = random_photons(200000, 12, [](std::mt19937_64& rng) {
    std::uniform_int_distribution<int> grid(0, 40);  // duplicates exercise the tie order
    return std::array<float, 3>{0.1f * static_cast<float>(grid(rng)),
                                0.1f * static_cast<float>(grid(rng)),
                                0.1f * static_cast<float>(grid(rng))};
  });
  const PhotonMap parallel(photons);
  std::vector<Photon> serial_order;
  {
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    serial_order = PhotonMap(photons).photons();
  }
  ASSERT_EQ(serial_order.size(), parallel.size());
  for (std::size_t i = 0; i < serial_order.size(); ++i)
    ASSERT_EQ(serial_order[i].flux[0], parallel.photons()[i].flux[0]) << i;
}

TEST(PhotonMap, ConcurrentLookupsAreIdentical) {
  const PhotonMap map(random_photons(50000, 13, [](std::mt19937_64& rng) {
    std::uniform_real_distribution<float> u(0.0f, 4.0f);
    return std::array<float, 3>{u(rng), u(rng), 0.25f * u(rng)};
  }));
  std::vector<Vec3> queries;
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(0.0, 4.0);
  for (int i = 0; i < 200; ++i) queries.push_back({u(rng), u(rng), 0.25 * u(rng)});
  PhotonFilter filter;
  filter.source = 2;
  auto run = [&](std::vector<std::vector<NeighbourPhoton>>& results) {
    results.resize(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i)
      map.nearest(queries[i], 200, 1.5, i % 2 ? filter : PhotonFilter{}, results[i]);
  };
  std::vector<std::vector<NeighbourPhoton>> reference;
  run(reference);
  constexpr int Threads = 4;
  std::vector<std::vector<std::vector<NeighbourPhoton>>> per_thread(Threads);
  std::vector<std::thread> threads;
  for (int t = 0; t < Threads; ++t) threads.emplace_back([&, t] { run(per_thread[t]); });
  for (auto& thread : threads) thread.join();
  for (int t = 0; t < Threads; ++t)
    for (std::size_t i = 0; i < queries.size(); ++i)
      expect_same(per_thread[t][i], reference[i], "concurrent lookup");
}

}  // namespace
}  // namespace dayphoton::engine
