// RoundGridMaps (round_grid_maps.h): the maps of one accuracy round's grids hold the round's
// photons without a copy of their own, one surface map serves every grid that reads the
// surface photons, and each map is released after the last grid that reads it.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/study/round_grid_maps.h"

namespace dayphoton::study {
namespace {

using engine::Photon;

/// `count` photons of `sources` sources in a 4 x 3 m box (plane photons at z = 0.8 facing up),
/// in source order as a round merges them; fixed seed.
std::vector<Photon> photons_of(std::size_t count, std::size_t sources, bool on_plane, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Photon> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    Photon& p = out[i];
    p.position = {4.0f * u(rng), 3.0f * u(rng), on_plane ? 0.8f : 2.8f * u(rng)};
    p.flux = {u(rng), u(rng), u(rng)};
    p.source = static_cast<std::uint32_t>(i * sources / count);
    p.set_normal({0, 0, 1});
    p.path_class = i % 5 == 0 ? engine::PathClass::Direct : engine::PathClass::Global;
  }
  return out;
}

engine::TracedPhotons round_of(const std::vector<Photon>& surface, const std::vector<Photon>& plane) {
  engine::TracedPhotons t;
  t.surface = surface;
  t.planes = {plane};
  return t;
}

const std::vector<engine::ReceiverPlane> Planes = {engine::ReceiverPlane(0.8, true, {{0, 0}, {4, 0}, {4, 3}, {0, 3}})};
constexpr std::size_t Sources = 4;

// Grids 0 and 2 gather from the surface photons, grid 1 reads the plane: the gathered grids
// share one map (the same object, built once), whose photons are those of a map built from a
// copy, bit for bit; the plane's map is released after grid 1, the surface map only after
// grid 2, the last grid that reads it.
TEST(RoundGridMaps, GatheredGridsShareOneMapReleasedAfterTheLastOfThem) {
  const std::vector<Photon> surface = photons_of(3000, Sources, false, 3);
  const std::vector<Photon> plane = photons_of(1000, Sources, true, 4);
  RoundGridMaps maps(Planes, {-1, 0, -1}, true, round_of(surface, plane), std::vector<double>(Sources, 1.0));
  const engine::GridPhotons& first = maps.of_grid(0);
  EXPECT_TRUE(first.gather());
  EXPECT_EQ(&maps.of_grid(2), &first);
  const engine::GridPhotons copy = engine::GridPhotons::for_gather(surface, Sources);
  ASSERT_EQ(first.all().size(), surface.size());
  EXPECT_EQ(0, std::memcmp(first.all().photons().data(), copy.all().photons().data(), surface.size() * sizeof(Photon)));
  EXPECT_EQ(first.groups().group_of, copy.groups().group_of);
  EXPECT_TRUE(maps.of_grid(1).planar());

  maps.done(0);
  EXPECT_TRUE(maps.holds(0)) << "grid 2 still reads the surface map";
  EXPECT_TRUE(maps.holds(1));
  maps.done(1);
  EXPECT_FALSE(maps.holds(1));
  EXPECT_TRUE(maps.holds(2));
  maps.done(2);
  EXPECT_FALSE(maps.holds(0));
  EXPECT_FALSE(maps.holds(2));
  EXPECT_THROW(maps.of_grid(2), std::logic_error);
}

// Surface grids (not gathered) share the surface map too, at the round's scale, with the Direct
// photons dropped as GridPhotons::for_surfaces drops them; a map never built (a process that
// estimates no block of the grid) is released all the same.
TEST(RoundGridMaps, SurfaceGridsShareTheScaledMapAndUnbuiltMapsAreReleased) {
  const std::vector<Photon> surface = photons_of(2000, Sources, false, 5);
  const std::vector<double> scale = {1.0, 2.0, 0.5, 1.0};
  RoundGridMaps maps(Planes, {-1, -1, 0}, false, round_of(surface, photons_of(500, Sources, true, 6)), scale);
  const engine::GridPhotons& a = maps.of_grid(0);
  EXPECT_FALSE(a.gather());
  EXPECT_EQ(&maps.of_grid(1), &a);
  engine::GridPhotons copy = engine::GridPhotons::for_surfaces(surface, Sources);
  copy.set_source_scale(scale);
  for (std::size_t p = 0; p < Sources; ++p) {
    ASSERT_EQ(a.of_source(p).size(), copy.of_source(p).size()) << "source " << p;
    EXPECT_EQ(a.bandwidth_of(p, 50), copy.bandwidth_of(p, 50)) << "source " << p;
  }
  maps.done(0);
  maps.done(1);
  EXPECT_FALSE(maps.holds(0));
  EXPECT_TRUE(maps.holds(2));
  maps.done(2);  // grid 2's plane map was never built
  EXPECT_FALSE(maps.holds(2));
}

// A plane with sensors next to a cut (near_cut_sensors) reads the gather map too: with a
// gathered grid, the same shared map (grid 0's plane map points at grid 1's), kept until the
// later of the two is done; without one (the surface estimate for the other grids), a gather map
// of its own from a copy of the surface photons, while the surface grid keeps its map.
TEST(RoundGridMaps, APlaneWithSensorsNextToACutReadsTheGatherMap) {
  const std::vector<Photon> surface = photons_of(3000, Sources, false, 7);
  const std::vector<Photon> plane = photons_of(1000, Sources, true, 8);
  {
    RoundGridMaps maps(Planes, {0, -1}, true, round_of(surface, plane), std::vector<double>(Sources, 1.0), {5});
    const engine::GridPhotons& on_plane = maps.of_grid(0);
    EXPECT_TRUE(on_plane.planar());
    EXPECT_EQ(on_plane.near_cut_gather(), &maps.of_grid(1));
    maps.done(0);
    EXPECT_FALSE(maps.holds(0));
    EXPECT_TRUE(maps.holds(1));
    maps.done(1);
    EXPECT_FALSE(maps.holds(1));
  }
  {
    RoundGridMaps maps(Planes, {-1, 0}, true, round_of(surface, plane), std::vector<double>(Sources, 1.0), {5});
    maps.done(0);
    EXPECT_TRUE(maps.holds(1)) << "grid 1's plane still reads the gather map";
    EXPECT_TRUE(maps.holds(0));
    ASSERT_NE(maps.of_grid(1).near_cut_gather(), nullptr);
    EXPECT_EQ(maps.of_grid(1).near_cut_gather()->all().size(), surface.size());
    maps.done(1);
    EXPECT_FALSE(maps.holds(0));
    EXPECT_FALSE(maps.holds(1));
  }
  {
    RoundGridMaps maps(Planes, {-1, 0}, false, round_of(surface, plane), std::vector<double>(Sources, 1.0), {5});
    const engine::GridPhotons& surface_map = maps.of_grid(0);
    EXPECT_FALSE(surface_map.gather());
    maps.done(0);
    const engine::GridPhotons* gather = maps.of_grid(1).near_cut_gather();
    ASSERT_NE(gather, nullptr);
    EXPECT_TRUE(gather->gather());
    EXPECT_EQ(gather->all().size(), surface.size());  // Direct photons kept, unlike the surface map's
    maps.done(1);
    EXPECT_FALSE(maps.holds(1));
  }
  // Without sensors next to a cut the plane reads no gather map.
  RoundGridMaps maps(Planes, {0, -1}, true, round_of(surface, plane), std::vector<double>(Sources, 1.0), {0});
  EXPECT_EQ(maps.of_grid(0).near_cut_gather(), nullptr);
}

}  // namespace
}  // namespace dayphoton::study
