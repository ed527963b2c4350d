// Tests for study/step_executor.h and plan_step.h: the one seam between a run's steps and
// the cache. A miss computes and stores; a hit takes the stored bytes and computes nothing; a
// damaged artefact, one the step does not take (wrong size) and a step with one of its two
// artefacts missing are computed again; `force` computes everything; a batch keeps its
// results in step order and reports every step once. A batch of real photon steps (a small
// room's sky sources) gives the same bytes with 1 and 3 threads, and each step's bytes are
// what its source traced alone gives.
#include "side_lit_room.h"
#include "dayphoton/study/step_executor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "dayphoton/engine/port_emission.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/simulation_plan.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

using test::fresh_dir;

/// A step whose value is a string made from its index; counts its computations.
Step counting_step(std::size_t index, std::string& slot, std::atomic<int>& computed) {
  return make_step(
      StepKind::SourcePhotons, index, {"test", "k" + std::to_string(index)}, slot,
      [index, &computed] {
        ++computed;
        return "value of step " + std::to_string(index);
      },
      [](const std::string& s) { return s; }, [](const std::string& b) { return b; },
      [index](const std::string& s) { return s == "value of step " + std::to_string(index); });
}

TEST(StepExecutor, AMissComputesAndStoresAHitComputesNothing) {
  const ArtifactStore store(fresh_dir("step_executor_hit").string());
  std::atomic<int> computed{0};
  std::string slot;
  const Step step = counting_step(7, slot, computed);
  {
    const auto executor = make_local_executor(store, false);
    EXPECT_FALSE(executor->lookup(step));
    EXPECT_TRUE(executor->run(step));
    EXPECT_EQ(computed, 1);
    EXPECT_EQ(slot, "value of step 7");
    EXPECT_EQ(store.read("test", "k7").value_or(""), "value of step 7");
  }
  slot.clear();
  const auto again = make_local_executor(store, false);
  EXPECT_TRUE(again->lookup(step));
  EXPECT_EQ(slot, "value of step 7");
  slot.clear();
  EXPECT_FALSE(again->run(step));  // from the cache
  EXPECT_EQ(computed, 1);
  EXPECT_EQ(slot, "value of step 7");
}

TEST(StepExecutor, ADamagedOrUnfittingArtefactIsComputedAgain) {
  const ArtifactStore store(fresh_dir("step_executor_damaged").string());
  const auto executor = make_local_executor(store, false);
  std::atomic<int> computed{0};
  std::string slot;
  const Step step = counting_step(3, slot, computed);
  ASSERT_TRUE(executor->run(step));
  // Flip the last payload byte: the checksum fails, the artefact is absent.
  {
    std::fstream f(store.path_for("test", "k3"), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(-1, std::ios::end);
    f.put('X');
  }
  slot.clear();
  EXPECT_FALSE(executor->lookup(step));
  EXPECT_TRUE(executor->run(step));
  EXPECT_EQ(computed, 2);
  EXPECT_EQ(slot, "value of step 3");
  // Intact bytes the step does not take (another step's value under its key).
  store.write("test", "k3", "value of step 4");
  slot.clear();
  EXPECT_FALSE(executor->lookup(step));
  EXPECT_TRUE(slot.empty());  // a refused artefact leaves the result untouched
  EXPECT_TRUE(executor->run(step));
  EXPECT_EQ(computed, 3);
  EXPECT_EQ(store.read("test", "k3").value_or(""), "value of step 3");
  // Bytes the decoder throws on.
  Step throwing = step;
  throwing.take = [](const std::vector<std::string>&) -> bool { throw std::runtime_error("bad layout"); };
  EXPECT_FALSE(executor->lookup(throwing));
}

TEST(StepExecutor, ForceComputesWhatIsCached) {
  const ArtifactStore store(fresh_dir("step_executor_force").string());
  std::atomic<int> computed{0};
  std::string slot;
  const Step step = counting_step(1, slot, computed);
  make_local_executor(store, false)->run(step);
  const auto forced = make_local_executor(store, true);
  EXPECT_FALSE(forced->lookup(step));
  EXPECT_TRUE(forced->run(step));
  EXPECT_EQ(computed, 2);
}

TEST(StepExecutor, AStepOfTwoArtefactsIsCachedOnlyWhenBothAre) {
  const ArtifactStore store(fresh_dir("step_executor_pair").string());
  const auto executor = make_local_executor(store, false);
  int computed = 0;
  std::vector<std::string> taken;
  Step step;
  step.kind = StepKind::SunCoefficients;
  step.outputs = {{"pair-a", "k"}, {"pair-b", "k"}};
  step.compute = [&]() -> std::vector<std::string> {
    ++computed;
    return {"A", "B"};
  };
  step.take = [&](const std::vector<std::string>& bytes) {
    taken = bytes;
    return true;
  };
  EXPECT_TRUE(executor->run(step));
  EXPECT_EQ(store.read("pair-a", "k").value_or(""), "A");
  EXPECT_EQ(store.read("pair-b", "k").value_or(""), "B");
  EXPECT_TRUE(executor->lookup(step));
  EXPECT_EQ(taken, (std::vector<std::string>{"A", "B"}));
  fs::remove(store.path_for("pair-b", "k"));
  taken.clear();
  EXPECT_FALSE(executor->lookup(step));
  EXPECT_TRUE(taken.empty());
  EXPECT_TRUE(executor->run(step));
  EXPECT_EQ(computed, 2);
  // A compute that returns the wrong number of artefacts is a programming error.
  step.compute = [] { return std::vector<std::string>{"A"}; };
  const auto forced = make_local_executor(store, true);
  EXPECT_THROW(forced->run(step), std::logic_error);
}

TEST(StepExecutor, ABatchKeepsStepOrderAndReportsEveryStepOnce) {
  const ArtifactStore store(fresh_dir("step_executor_batch").string());
  const auto executor = make_local_executor(store, false);
  constexpr std::size_t N = 64;
  std::atomic<int> computed{0};
  std::vector<std::string> slots(N);
  std::vector<Step> steps;
  for (std::size_t i = 0; i < N; ++i) steps.push_back(counting_step(i, slots[i], computed));
  // Half of them cached beforehand.
  for (std::size_t i = 0; i < N; i += 2) store.write("test", "k" + std::to_string(i), "value of step " + std::to_string(i));
  std::vector<std::atomic<int>> done(N);
  const std::vector<char> fresh = executor->run_batch(steps, [&](std::size_t k, bool was_computed) {
    done[k] += 1;
    EXPECT_EQ(was_computed, k % 2 == 1);
  });
  ASSERT_EQ(fresh.size(), N);
  EXPECT_EQ(computed, int(N / 2));
  for (std::size_t i = 0; i < N; ++i) {
    EXPECT_EQ(done[i], 1) << i;
    EXPECT_EQ(fresh[i], i % 2 == 1 ? 1 : 0) << i;
    EXPECT_EQ(slots[i], "value of step " + std::to_string(i)) << i;
  }
}

// A room with a south window under the plan's options: the photon steps of its first sky
// sources, as the run makes them.
const std::string RoomYaml = test::side_lit_room_yaml("[6, 8, 3]", "4", 300);

std::vector<std::string> photon_batch_bytes(int threads, const ArtifactStore& store) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  const project::Project project = project::load_project_from_string(RoomYaml, "room.yaml");
  const SimulationPlan plan = SimulationPlan::of(project);
  const SceneDescription d = project::build_scene_description(project);
  const engine::Scene scene = engine::Scene::build(d);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
  const CaseLayout layout = CaseLayout::of(d.grids);
  const engine::TracingOptions tracing = plan.tracing_for(plan.sky_tracing, layout);
  const engine::SourceSet sources = engine::SourceSet::sky_bins(plan.basis);
  const engine::PortEmitter emitter(scene, sources);
  constexpr std::size_t N = 24;
  std::vector<engine::TracedPhotons> photons(N);
  std::vector<Step> steps;
  for (std::size_t p = 0; p < N; ++p)
    steps.push_back(make_step(
        StepKind::SourcePhotons, p,
        {"photons", photon_source_key(scene_key(d), planes_key(d.grids), plan.basis, p, tracing)}, photons[p],
        [&, p] { return engine::trace_source_photons(scene, materials, emitter, layout.planes, tracing, p); },
        encode_photons, decode_photons, [](const engine::TracedPhotons&) { return true; }));
  const auto executor = make_local_executor(store, true);
  const std::vector<char> computed = executor->run_batch(steps);
  std::vector<std::string> bytes;
  for (std::size_t p = 0; p < N; ++p) {
    EXPECT_EQ(computed[p], 1);
    bytes.push_back(encode_photons(photons[p]));
    EXPECT_EQ(store.read("photons", steps[p].outputs[0].key).value_or(""), bytes.back()) << p;
  }
  // A source alone gives its step's bytes.
  EXPECT_EQ(encode_photons(engine::trace_source_photons(scene, materials, emitter, layout.planes, tracing, 5)), bytes[5]);
  return bytes;
}

TEST(StepExecutor, PhotonBatchIsIndependentOfTheThreadCount) {
  const ArtifactStore one(fresh_dir("step_executor_threads_1").string());
  const ArtifactStore three(fresh_dir("step_executor_threads_3").string());
  const std::vector<std::string> a = photon_batch_bytes(1, one);
  const std::vector<std::string> b = photon_batch_bytes(3, three);
  ASSERT_EQ(a.size(), b.size());
  std::size_t with_photons = 0;
  for (std::size_t p = 0; p < a.size(); ++p) {
    EXPECT_EQ(a[p], b[p]) << "source " << p;
    with_photons += decode_photons(a[p]).planes.at(0).empty() ? 0 : 1;
  }
  EXPECT_GT(with_photons, a.size() / 2);  // the batch does trace light into the room
}

TEST(SimulationPlan, AppliesThePolicyOnce) {
  const project::Project project = project::load_project_from_string(RoomYaml, "room.yaml");
  const SimulationPlan plan = SimulationPlan::of(project);
  ASSERT_EQ(plan.sky_tracing.source_photon_factor.size(), std::size_t(plan.basis.bin_count()));
  EXPECT_EQ(plan.sky_tracing.source_photon_factor[0], GroundPhotonFactor);
  EXPECT_EQ(plan.sky_tracing.source_photon_factor[1], 1.0);
  EXPECT_EQ(plan.sky_tracing.photons_per_source, 300u);
  EXPECT_EQ(plan.sun_tracing.photons_per_source, 30u);  // SunBinPhotonFraction 0.1
  EXPECT_TRUE(plan.sun_tracing.source_photon_factor.empty());
  EXPECT_EQ(plan.sun_estimating.density.bandwidth, sun_bin_bandwidth(plan.sky_estimating.density.bandwidth));
  EXPECT_EQ(plan.sun_direct_samples, SunDirectSamples);
  EXPECT_EQ(sky_photon_factors(3), (std::vector<double>{GroundPhotonFactor, 1.0, 1.0}));
  // The local-quadratic fit at walls: the ground bin 0 of the sky's sources and nothing else,
  // whatever photons the accuracy rounds give a sky bin; no sun bin.
  EXPECT_EQ(plan.sky_estimating.quadratic_fit_sources, (std::vector<std::size_t>{0}));
  EXPECT_TRUE(plan.sun_estimating.quadratic_fit_sources.empty());
}

}  // namespace
}  // namespace dayphoton::study
