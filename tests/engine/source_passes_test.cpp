// Tests for engine/source_passes.h and the attempt ranges of photon_tracer.h: a source traced
// pass by pass with every pass cut into 1, 2, 3 or 7 ranges (uneven, some empty, traced in
// reverse order and appended in attempt order) gives exactly the passes, the tally and the
// photon bytes of engine::trace_source_photons, for the ground bin, a sky patch and a sun disc
// of a small room with a mirror light shelf (caustic photons with a target of their own, so
// the main pass stores classes with different probabilities), with and without direct
// photons on surfaces. This is what lets the distributed run trace one source on several
// ranks (docs/cluster.md, "Big sources in attempt ranges").
#include "dayphoton/engine/source_passes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

// A 3 x 4 x 2.5 m room with a 2 x 1.2 m glazed window in the south wall y = 0 and a mirror
// light shelf 0.6 m deep under the window head.
SceneDescription shelf_room() {
  SceneDescription d;
  const int floor = test::add_material(d, "floor", MaterialType::Lambertian, 0.3);
  const int wall = test::add_material(d, "wall", MaterialType::Lambertian, 0.5);
  const int ceiling = test::add_material(d, "ceiling", MaterialType::Lambertian, 0.7);
  const int glass = test::add_material(d, "glazing", MaterialType::Glass, 0.0);
  const int mirror = test::add_material(d, "mirror", MaterialType::Mirror, 0.9);
  test::add_surface(d, "floor", floor, {{0, 0, 0}, {3, 0, 0}, {3, 4, 0}, {0, 4, 0}});
  test::add_surface(d, "ceiling", ceiling, {{0, 0, 2.5}, {0, 4, 2.5}, {3, 4, 2.5}, {3, 0, 2.5}});
  test::add_surface(d, "west", wall, {{0, 0, 0}, {0, 4, 0}, {0, 4, 2.5}, {0, 0, 2.5}});
  test::add_surface(d, "east", wall, {{3, 0, 0}, {3, 0, 2.5}, {3, 4, 2.5}, {3, 4, 0}});
  test::add_surface(d, "north", wall, {{0, 4, 0}, {3, 4, 0}, {3, 4, 2.5}, {0, 4, 2.5}});
  test::add_surface(d, "sill", wall, {{0, 0, 0}, {0, 0, 0.8}, {3, 0, 0.8}, {3, 0, 0}});
  test::add_surface(d, "head", wall, {{0, 0, 2.0}, {0, 0, 2.5}, {3, 0, 2.5}, {3, 0, 2.0}});
  test::add_surface(d, "jamb_w", wall, {{0, 0, 0.8}, {0, 0, 2.0}, {0.5, 0, 2.0}, {0.5, 0, 0.8}});
  test::add_surface(d, "jamb_e", wall, {{2.5, 0, 0.8}, {2.5, 0, 2.0}, {3, 0, 2.0}, {3, 0, 0.8}});
  test::add_surface(d, "window", glass, {{0.5, 0, 0.8}, {0.5, 0, 2.0}, {2.5, 0, 2.0}, {2.5, 0, 0.8}}, true);
  test::add_surface(d, "shelf", mirror, {{0.5, 0.01, 1.7}, {2.5, 0.01, 1.7}, {2.5, 0.6, 1.7}, {0.5, 0.6, 1.7}});
  return d;
}

/// Where a pass of each split is cut, as fractions of its length (sorted; equal cuts and cuts
/// at 0 or 1 make empty ranges).
std::vector<double> cuts_for(int ranges) {
  switch (ranges) {
    case 1: return {};
    case 2: return {0.37};
    case 3: return {0.0, 0.71};
    default: return {0.001, 0.001, 0.2, 0.5, 0.5004, 1.0};  // 7 ranges
  }
}

struct Traced {
  std::vector<AttemptPass> passes;
  TracedPhotons photons;
};

/// The source traced pass by pass, every pass cut into `ranges` ranges, traced last range
/// first, appended in attempt order, their counts summed.
Traced trace_in_ranges(const Scene& scene, const std::vector<Material>& materials, const PortEmitter& emitter,
                       const std::vector<ReceiverPlane>& planes, const TracingOptions& options, std::size_t source,
                       int ranges) {
  Traced out;
  SourcePasses passes(scene, materials, emitter, planes, options, source);
  AttemptRange photons;
  while (const std::optional<AttemptPass> pass = passes.next()) {
    out.passes.push_back(*pass);
    const std::uint64_t length = pass->last - pass->first;
    std::vector<std::uint64_t> at{pass->first};
    for (double f : cuts_for(ranges))
      at.push_back(pass->first + std::min(length, static_cast<std::uint64_t>(std::llround(double(length) * f))));
    at.push_back(pass->last);
    std::vector<AttemptRange> parts(at.size() - 1);
    for (std::size_t i = parts.size(); i-- > 0;)
      parts[i] = trace_attempt_range(scene, materials, emitter, planes, options, source, at[i], at[i + 1],
                                     pass->storage);
    AttemptCounts sum;
    for (AttemptRange& part : parts) {
      sum += part.counts;
      append_attempt_range(photons, std::move(part));
    }
    passes.record(sum);
  }
  out.photons = passes.finish(std::move(photons));
  return out;
}

void expect_same_bytes(const std::vector<Photon>& a, const std::vector<Photon>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_EQ(0, a.empty() ? 0 : std::memcmp(a.data(), b.data(), a.size() * sizeof(Photon))) << what;
}

void expect_same_tally(const SourceTally& a, const SourceTally& b) {
  EXPECT_EQ(a.prepass_attempts, b.prepass_attempts);
  EXPECT_EQ(a.mainpass_attempts, b.mainpass_attempts);
  EXPECT_EQ(a.entered, b.entered);
  EXPECT_EQ(a.stored_global, b.stored_global);
  EXPECT_EQ(a.stored_caustic, b.stored_caustic);
  EXPECT_EQ(a.stored_direct, b.stored_direct);
  EXPECT_EQ(a.rays, b.rays);
  EXPECT_EQ(a.bound_flux, b.bound_flux);
  EXPECT_EQ(a.flux_per_attempt, b.flux_per_attempt);
  EXPECT_EQ(a.storage_probability_global, b.storage_probability_global);
  EXPECT_EQ(a.storage_probability_caustic, b.storage_probability_caustic);
  EXPECT_EQ(a.storage_probability_direct, b.storage_probability_direct);
  EXPECT_EQ(a.capped, b.capped);
  EXPECT_EQ(a.nothing_stores, b.nothing_stores);
}

/// Checks every split of the three sources; says whether a main pass and a top-up were traced.
void check_every_split(bool direct_on_surfaces, bool& some_main_pass, bool& some_topup) {
  const SceneDescription d = shelf_room();
  const Scene scene = Scene::build(d);
  std::vector<Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(Material::from_spec(m));
  const std::vector<ReceiverPlane> planes = {ReceiverPlane(0.8, true, {{0, 0}, {3, 0}, {3, 4}, {0, 4}})};
  SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  // A sun 40 degrees high in the south (the room's window faces -y), the sun's half-angle.
  const double alt = 40.0 * M_PI / 180.0;
  const std::size_t sun = sources.add_sun_disc({0, -std::cos(alt), std::sin(alt)}, 0.00465);
  const PortEmitter emitter(scene, sources);
  // The sky patch that sends the most light through the window.
  std::size_t patch = 1;
  for (std::size_t p = 1; p < sun; ++p)
    if (emitter.bound_flux(p) > emitter.bound_flux(patch)) patch = p;

  TracingOptions options;
  options.photons_per_source = 300;
  options.caustic_photons_per_source = 200;
  options.source_photon_factor.assign(sources.size(), 1.0);
  options.source_photon_factor[0] = 4;  // the ground, as the pipeline's ground factor does
  options.store_direct_on_surfaces = direct_on_surfaces;
  options.seed = 17;

  for (std::size_t source : {std::size_t(0), patch, sun}) {
    SCOPED_TRACE("source " + std::to_string(source));
    const TracedPhotons whole = trace_source_photons(scene, materials, emitter, planes, options, source);
    ASSERT_EQ(whole.tallies.size(), 1u);
    ASSERT_GT(whole.tallies[0].stored_global, 0u);  // the source does light the room
    const Traced one = trace_in_ranges(scene, materials, emitter, planes, options, source, 1);
    some_main_pass = some_main_pass || whole.tallies[0].mainpass_attempts > 0;
    std::size_t after_prepass = 0;  // the main pass and the top-up
    for (const AttemptPass& p : one.passes) after_prepass += p.first >= whole.tallies[0].prepass_attempts ? 1 : 0;
    some_topup = some_topup || after_prepass == 2;
    for (int ranges : {1, 2, 3, 7}) {
      SCOPED_TRACE(std::to_string(ranges) + " ranges");
      const Traced split = trace_in_ranges(scene, materials, emitter, planes, options, source, ranges);
      ASSERT_EQ(split.passes.size(), one.passes.size());
      for (std::size_t i = 0; i < one.passes.size(); ++i) {
        EXPECT_EQ(split.passes[i].first, one.passes[i].first);
        EXPECT_EQ(split.passes[i].last, one.passes[i].last);
        EXPECT_EQ(split.passes[i].storage.global, one.passes[i].storage.global);
        EXPECT_EQ(split.passes[i].storage.caustic, one.passes[i].storage.caustic);
        EXPECT_EQ(split.passes[i].storage.direct, one.passes[i].storage.direct);
      }
      ASSERT_EQ(split.photons.tallies.size(), 1u);
      expect_same_tally(split.photons.tallies[0], whole.tallies[0]);
      expect_same_bytes(split.photons.surface, whole.surface, "surface photons");
      ASSERT_EQ(split.photons.planes.size(), whole.planes.size());
      expect_same_bytes(split.photons.planes[0], whole.planes[0], "plane photons");
    }
  }
}

TEST(SourcePasses, RangesOfEveryPassGiveTheWholeSourceByteForByte) {
  bool some_main_pass = false, some_topup = false;
  {
    SCOPED_TRACE("without direct photons");
    check_every_split(false, some_main_pass, some_topup);
  }
  {
    SCOPED_TRACE("with direct photons on surfaces");
    check_every_split(true, some_main_pass, some_topup);
  }
  // The sources went through every kind of pass: pre-pass doublings (5 to 8 of them here),
  // a main pass with storage probabilities below 1 (0 for the global photons of the sky
  // patch and the sun, which have enough after the caustics' pre-pass), a top-up (the ground
  // with direct photons).
  EXPECT_TRUE(some_main_pass);
  EXPECT_TRUE(some_topup);
}

TEST(SourcePasses, ASourceThatIsNotTracedHasNoPass) {
  // A black room behind an opening: nothing can store a photon, no source is traced.
  SceneDescription d;
  const int black = test::add_material(d, "black", MaterialType::Lambertian, 0.0);
  const int open = test::add_material(d, "open", MaterialType::Opening, 0.0);
  d.materials[static_cast<std::size_t>(black)].reflectance = {0, 0, 0};
  test::add_surface(d, "floor", black, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  test::add_surface(d, "roof", open, {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}, true);
  const Scene scene = Scene::build(d);
  std::vector<Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(Material::from_spec(m));
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  const SourcePasses passes(scene, materials, emitter, {}, TracingOptions{}, 100);
  EXPECT_FALSE(passes.next().has_value());
  const TracedPhotons t = passes.finish(AttemptRange{});
  ASSERT_EQ(t.tallies.size(), 1u);
  EXPECT_TRUE(t.tallies[0].nothing_stores);
  EXPECT_EQ(t.tallies[0].prepass_attempts, 0u);
}

}  // namespace
}  // namespace dayphoton::engine
