// Tests for study/split_photon_steps.h and the distributed executor's use of it: photon steps
// (sky sources, sun bins) traced in attempt ranges over 2 and 3 in-process ranks (threads
// with MPI's message semantics, tests/dist/in_process_ranks.h) give every rank the bytes the
// local executor computes, and rank 0 stores them: the split and the rank count change where
// attempts are traced, never the photons.
#include "side_lit_room.h"
#include "dayphoton/study/split_photon_steps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "../dist/in_process_ranks.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/distributed_executor.h"
#include "dayphoton/study/photon_range_step.h"
#include "dayphoton/study/simulation_plan.h"
#include "dayphoton/study/step_executor.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

using test::fresh_dir;

const std::string RoomYaml = test::side_lit_room_yaml("[4, 5, 3]", "3", 1000);

/// A case as the run sees it (scene, materials, layout, the plan's options) and the photon
/// steps of a few of its sky sources and of the sun bins of a south sun, with their slots.
struct Case {
  project::Project project = project::load_project_from_string(RoomYaml, "room.yaml");
  SimulationPlan plan = SimulationPlan::of(project);
  SceneDescription d = project::build_scene_description(project);
  engine::Scene scene = engine::Scene::build(d);
  std::vector<engine::Material> materials;
  CaseLayout layout = CaseLayout::of(d.grids);
  engine::TracingOptions sky_tracing = plan.tracing_for(plan.sky_tracing, layout);
  engine::TracingOptions sun_tracing = plan.tracing_for(plan.sun_tracing, layout);
  engine::SourceSet sources = engine::SourceSet::sky_bins(plan.basis);
  engine::PortEmitter emitter{scene, sources};
  engine::SunBins bins = engine::SunBins::for_suns({{0, -std::cos(0.7), std::sin(0.7)}}, 2);
  std::vector<std::size_t> sky_sources{0};  // the ground, then the two brightest sky patches
  std::vector<engine::TracedPhotons> slots;

  Case() {
    for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
    std::size_t first = 1, second = 2;
    for (std::size_t p = 1; p < sources.size(); ++p) {
      if (emitter.bound_flux(p) > emitter.bound_flux(first)) {
        second = first;
        first = p;
      } else if (p != first && emitter.bound_flux(p) > emitter.bound_flux(second)) {
        second = p;
      }
    }
    sky_sources.push_back(first);
    sky_sources.push_back(second);
  }

  /// The photon steps: the sky sources', then every lit sun bin's.
  std::vector<Step> steps() {
    const engine::SourceSet suns = bins.sources(sky::SunHalfAngle_rad);
    const std::vector<char> lit = sun_bins_to_trace(engine::PortEmitter(scene, suns), bins.size());
    slots.assign(sky_sources.size() + bins.size(), {});
    std::vector<Step> out;
    for (std::size_t i = 0; i < sky_sources.size(); ++i) {
      const std::size_t p = sky_sources[i];
      out.push_back(make_step(
          StepKind::SourcePhotons, p, {"photons", "sky-" + std::to_string(p)}, slots[i],
          [this, p] { return engine::trace_source_photons(scene, materials, emitter, layout.planes, sky_tracing, p); },
          encode_photons, decode_photons, [](const engine::TracedPhotons&) { return true; }));
      out.back().ranges = sky_source_ranges(scene, materials, emitter, layout.planes, sky_tracing, p);
    }
    for (std::size_t b = 0; b < bins.size(); ++b) {
      if (!lit[b]) continue;
      out.push_back(make_step(
          StepKind::SunBinPhotons, b, {"sun-photons", "bin-" + std::to_string(b)}, slots[sky_sources.size() + b],
          [this, b] { return trace_sun_bin(scene, materials, bins, b, layout.planes, sun_tracing); }, encode_photons,
          decode_photons, [](const engine::TracedPhotons&) { return true; }));
      out.back().ranges = sun_bin_ranges(scene, materials, bins, b, layout.planes, sun_tracing);
    }
    return out;
  }
};

/// Each step's bytes by the local executor (one process).
std::vector<std::string> local_bytes(Case& c) {
  const ArtifactStore store(fresh_dir("split_photon_steps_local").string());
  std::vector<Step> steps = c.steps();
  const auto executor = make_local_executor(store, true);
  executor->run_batch(steps);
  std::vector<std::string> bytes;
  for (const Step& s : steps) bytes.push_back(store.read(s.outputs[0].kind, s.outputs[0].key).value_or(""));
  return bytes;
}

TEST(SplitPhotonSteps, RangesOverTwoAndThreeRanksGiveTheOneProcessBytes) {
  Case c;
  const std::vector<std::string> expected = local_bytes(c);
  ASSERT_GE(expected.size(), 4u);  // 3 sky sources and at least one lit sun bin
  std::size_t lit_sky = 0;
  for (std::size_t i = 0; i < c.sky_sources.size(); ++i)
    lit_sky += decode_photons(expected[i]).planes.at(0).empty() ? 0 : 1;
  EXPECT_EQ(lit_sky, c.sky_sources.size());  // every sky source does bring light in

  for (int ranks : {2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    // Every step split, a pass cut into ranges of at least 256 attempts, at most one per rank.
    std::vector<std::vector<std::string>> got(static_cast<std::size_t>(ranks));
    const auto errors = dist::test::run_ranks(ranks, [&](dist::Communicator& comm) {
      Case mine;  // each rank builds its own case and steps, as every rank of a run does
      std::vector<Step> steps = mine.steps();
      std::vector<std::size_t> all(steps.size());
      for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
      // The policy splits the ground (16 sky bins' photons) at least; here every step is.
      EXPECT_EQ(photon_steps_to_split(steps, all, comm.size()).at(0), 0u);
      std::vector<std::string>& out = got[static_cast<std::size_t>(comm.rank())];
      out.assign(steps.size(), "");
      run_split_photon_steps(
          comm, steps, all,
          [&](std::size_t k, const std::vector<std::string>& artefacts) {
            ASSERT_TRUE(steps[k].take(artefacts));
            out[k] = artefacts.at(0);
          },
          256);
      // The typed value each rank took encodes to the same bytes.
      for (std::size_t k = 0; k < steps.size(); ++k)
        EXPECT_EQ(encode_photons(mine.slots[k < 3 ? k : 3 + steps[k].index]), out[k]);
    });
    for (const std::exception_ptr& e : errors)
      if (e) std::rethrow_exception(e);
    for (int r = 0; r < ranks; ++r)
      for (std::size_t k = 0; k < expected.size(); ++k)
        EXPECT_EQ(got[static_cast<std::size_t>(r)][k], expected[k]) << "rank " << r << ", step " << k;
  }
}

TEST(SplitPhotonSteps, TheDistributedExecutorSplitsABatchOfFewSourcesAndStoresTheOneProcessBytes) {
  Case c;
  const std::vector<std::string> expected = local_bytes(c);
  const int ranks = 3;
  const fs::path root = fresh_dir("split_photon_steps_rank0");
  const auto errors = dist::test::run_ranks(ranks, [&](dist::Communicator& comm) {
    Case mine;
    std::vector<Step> steps = mine.steps();
    // Rank 0's store is the run's cache; the others never write to theirs.
    const fs::path dir = comm.rank() == 0 ? root : fresh_dir("split_photon_steps_rank" + std::to_string(comm.rank()));
    const ArtifactStore store(dir.string());
    const auto executor = make_distributed_executor(comm, store, true);
    const std::vector<char> computed = executor->run_batch(steps);
    for (std::size_t k = 0; k < steps.size(); ++k) {
      EXPECT_EQ(computed[k], 1) << k;
      EXPECT_EQ(encode_photons(mine.slots[k < 3 ? k : 3 + steps[k].index]), expected[k]) << "rank " << comm.rank();
    }
  });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  const ArtifactStore store(root.string());
  std::vector<Step> steps = c.steps();
  for (std::size_t k = 0; k < steps.size(); ++k)
    EXPECT_EQ(store.read(steps[k].outputs[0].kind, steps[k].outputs[0].key).value_or(""), expected[k]) << k;
}

}  // namespace
}  // namespace dayphoton::study
