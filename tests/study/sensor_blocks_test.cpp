// Tests for study/sensor_blocks.h, engine/sensor_range.h and the sensor-block path of the
// distributed executor (distributed_executor.h):
//   - the split: uneven blocks, one sensor, no sensor, a block size of 0 refused;
//   - joining blocks' artefacts gives the whole artefact's bytes; blocks that do not fit are
//     refused;
//   - every estimator a grid step runs (sky coefficients on a receiver plane, with the
//     bias-compensating operator and a caustic map, by final gather, the direct sun) gives
//     for a range of sensors exactly those rows of the whole grid's result, so the joined
//     artefact is byte-identical to the one-process one;
//   - the distributed executor on 1 to 4 in-process ranks (tests/dist/in_process_ranks.h):
//     every rank takes the whole grid's bytes, each block computed once, rank 0 alone stores
//     them; more ranks than blocks, one sensor and no sensor; a failing block fails every
//     rank with the grid and its sensors named;
//   - the annual multiply by blocks (annual_blocks.h) on 2 and 3 ranks: rank 0's study is the
//     one-process study byte for byte (table, per-sensor metrics, ASE hours, grid metrics),
//     with the sun bins and without; the other ranks get none.
#include "side_lit_room.h"
#include "dayphoton/study/sensor_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <optional>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "../dist/in_process_ranks.h"
#include "dayphoton/dist/distributed_job_error.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_blocks.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/distributed_executor.h"
#include "dayphoton/study/simulation_plan.h"
#include "dayphoton/weather/hourly_weather.h"
#include "in_process_study.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

TEST(SensorBlocks, SplitsIntoBlocksInSensorOrderTheLastOneShorter) {
  const std::vector<engine::SensorRange> b = sensor_blocks(37, 8);
  ASSERT_EQ(b.size(), 5u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(b[i].begin, 8 * i);
    EXPECT_EQ(b[i].size(), 8u);
  }
  EXPECT_EQ(b[4].begin, 32u);
  EXPECT_EQ(b[4].end, 37u);
  ASSERT_EQ(sensor_blocks(32, 16).size(), 2u);
  EXPECT_EQ(sensor_blocks(32, 16)[1].end, 32u);
  ASSERT_EQ(sensor_blocks(1, 16).size(), 1u);
  EXPECT_EQ(sensor_blocks(1, 16)[0].end, 1u);
  EXPECT_TRUE(sensor_blocks(0, 16).empty());
  EXPECT_EQ(sensor_blocks(165).size(), 11u);  // the office's grid with the policy's size
  EXPECT_THROW(sensor_blocks(10, 0), std::invalid_argument);
}

TEST(SensorBlocks, ARangeIsClampedToTheGridOrRefused) {
  const engine::SensorRange all = engine::SensorRange{}.within(7);
  EXPECT_EQ(all.begin, 0u);
  EXPECT_EQ(all.end, 7u);
  EXPECT_EQ((engine::SensorRange{7, 9}.within(7).size()), 0u);
  EXPECT_THROW(engine::SensorRange({8, 9}).within(7), std::invalid_argument);
  EXPECT_THROW(engine::SensorRange({5, 3}).within(7), std::invalid_argument);
}

RadianceMatrix numbered_rows(std::size_t begin, std::size_t end, std::size_t columns) {
  RadianceMatrix m(end - begin, columns, 1);
  for (std::size_t s = begin; s < end; ++s)
    for (std::size_t c = 0; c < columns; ++c) m.at(s - begin, c, 0) = float(1000 * s + c) + 0.25f;
  return m;
}

TEST(SensorBlocks, JoinedMatrixAndCoefficientBlocksAreTheWholeArtefact) {
  EXPECT_EQ(join_matrix_blocks({encode_matrix(numbered_rows(0, 3, 4)), encode_matrix(numbered_rows(3, 4, 4)),
                                encode_matrix(numbered_rows(4, 9, 4))}),
            encode_matrix(numbered_rows(0, 9, 4)));
  EXPECT_THROW(join_matrix_blocks({encode_matrix(numbered_rows(0, 3, 4)), encode_matrix(numbered_rows(3, 4, 5))}),
               std::invalid_argument);
  EXPECT_THROW(join_matrix_blocks({}), std::invalid_argument);

  auto coefficients = [](std::size_t begin, std::size_t end, std::size_t sources) {
    engine::DaylightCoefficients c;
    c.sensors = end - begin;
    c.sources = sources;
    for (std::size_t s = begin; s < end; ++s)
      for (std::size_t p = 0; p < sources; ++p) {
        const double v = double(100 * s + p);
        c.direct.push_back({v, v + 0.1, v + 0.2});
        c.caustic.push_back({v + 0.3, v + 0.4, v + 0.5});
        c.global.push_back({v + 0.6, v + 0.7, v + 0.8});
        c.direct_variance.push_back(v * 1e-3);
        c.photon_variance.push_back(v * 2e-3);
      }
    return encode_coefficients(c);
  };
  EXPECT_EQ(join_coefficient_blocks({coefficients(0, 2, 3), coefficients(2, 7, 3)}), coefficients(0, 7, 3));
  EXPECT_EQ(join_coefficient_blocks({coefficients(0, 1, 3)}), coefficients(0, 1, 3));
  EXPECT_THROW(join_coefficient_blocks({coefficients(0, 2, 3), coefficients(2, 7, 4)}), std::invalid_argument);
}

const std::string RoomYaml = test::side_lit_room_yaml("[6, 8, 3]", "4", 400);

/// The small room, traced once: its grid and the photons of every sky source.
struct TracedRoom {
  project::Project project = project::load_project_from_string(RoomYaml, "room.yaml");
  SimulationPlan plan = SimulationPlan::of(project);
  SceneDescription description = project::build_scene_description(project);
  engine::Scene scene = engine::Scene::build(description);
  std::vector<engine::Material> materials;
  CaseLayout layout = CaseLayout::of(description.grids);
  engine::SourceSet sources = engine::SourceSet::sky_bins(plan.basis);
  engine::TracedPhotons photons;

  TracedRoom() {
    for (const MaterialSpec& m : description.materials) materials.push_back(engine::Material::from_spec(m));
    const engine::TracingOptions tracing = plan.tracing_for(plan.sky_tracing, layout);
    const engine::PortEmitter emitter(scene, sources);
    std::vector<engine::TracedPhotons> per_source(sources.size());
    for (std::size_t p = 0; p < sources.size(); ++p)
      per_source[p] = engine::trace_source_photons(scene, materials, emitter, layout.planes, tracing, p);
    photons = engine::merge_traced_photons(std::move(per_source));
  }
  const std::vector<SensorPoint>& sensors() const { return description.grids.at(0).points; }
};

const TracedRoom& room() {
  static const TracedRoom r;
  return r;
}

/// The estimate of the whole grid against its blocks (uneven: 5 sensors, then 16 at a time)
/// joined: the same bytes.
void expect_blocks_join_to_whole(const engine::GridPhotons& photons, const engine::CoefficientOptions& options,
                                 std::size_t max_sensors = 1000) {
  const TracedRoom& r = room();
  std::vector<SensorPoint> sensors = r.sensors();
  if (sensors.size() > max_sensors) sensors.resize(max_sensors);
  const std::string whole = encode_coefficients(
      engine::daylight_coefficients(r.scene, r.materials, r.sources, photons, sensors, options));
  std::vector<std::string> blocks{encode_coefficients(
      engine::daylight_coefficients(r.scene, r.materials, r.sources, photons, sensors, options, {0, 5}))};
  for (const engine::SensorRange& b : sensor_blocks(sensors.size() - 5, 16))
    blocks.push_back(encode_coefficients(engine::daylight_coefficients(r.scene, r.materials, r.sources, photons,
                                                                       sensors, options, {5 + b.begin, 5 + b.end})));
  EXPECT_EQ(join_coefficient_blocks(blocks), whole);
  // The grid does receive light (the test is not comparing zeros).
  const engine::DaylightCoefficients c = decode_coefficients(whole);
  // The photon part under the DF sky is joined too where the options ask for it.
  EXPECT_EQ(c.photon_on_sky.irradiance.size(), options.photon_sky_bin_radiance_rgb.empty() ? 0 : sensors.size());
  double sum = 0;
  for (std::size_t i = 0; i < c.global.size(); ++i) sum += c.global[i].y + c.direct[i].y;
  EXPECT_GT(sum, 0.0);
}

TEST(SensorBlocks, SkyCoefficientBlocksOnAReceiverPlaneAreTheWholeGridsRows) {
  const TracedRoom& r = room();
  ASSERT_GE(r.sensors().size(), 40u);
  ASSERT_EQ(r.layout.plane_of_grid.at(0), 0);
  const engine::GridPhotons photons =
      engine::GridPhotons::for_plane(r.layout.planes[0], r.photons.planes[0], r.sources.size());
  expect_blocks_join_to_whole(photons, r.plan.sky_estimating);
  // The bias-compensating operator draws random numbers per (sensor, source), the caustic
  // lookups from a second stream after the whole grid's.
  engine::CoefficientOptions random = r.plan.sky_estimating;
  random.local_linear = false;
  random.bias_compensation = true;
  random.caustic_bandwidth = 10;
  expect_blocks_join_to_whole(photons, random);
  random.estimator = engine::PhotonEstimator::Contribution;
  expect_blocks_join_to_whole(photons, random);
}

TEST(SensorBlocks, GatheredBlocksAreTheWholeGridsRows) {
  const TracedRoom& r = room();
  // The plane's photons stand in for surface photons: the gather's random numbers are what
  // is checked.
  const engine::GridPhotons photons = engine::GridPhotons::for_gather(r.photons.planes[0], r.sources.size());
  engine::CoefficientOptions gather = r.plan.sky_estimating;
  gather.gather.rays_per_sensor = 16;
  expect_blocks_join_to_whole(photons, gather, 24);
}

TEST(SensorBlocks, DirectSunBlocksAreTheWholeGridsRows) {
  const TracedRoom& r = room();
  std::vector<sky::SunRecord> suns;
  for (std::size_t k = 0; k < 6; ++k) {
    sky::SunRecord sun;
    sun.step = 100 + 7 * k;
    const double azimuth = 0.3 * double(k) - 0.75, altitude = 0.35 + 0.1 * double(k);
    sun.direction = {std::sin(azimuth) * std::cos(altitude), -std::cos(azimuth) * std::cos(altitude), std::sin(altitude)};
    sun.disc_radiance = 1e6;
    suns.push_back(sun);
  }
  const RadianceMatrix whole = direct_sun_coefficients(r.scene, r.materials, r.sensors(), suns, 16, 7);
  std::vector<std::string> blocks;
  for (const engine::SensorRange& b : sensor_blocks(r.sensors().size(), 7))
    blocks.push_back(encode_matrix(direct_sun_coefficients(r.scene, r.materials, r.sensors(), suns, 16, 7, DirectSunValues::Rgb, b)));
  EXPECT_EQ(join_matrix_blocks(blocks), encode_matrix(whole));
  double sum = 0;
  for (float v : whole.data()) sum += v;
  EXPECT_GT(sum, 0.0);  // some sun reaches the grid through the window
}

/// A grid step of `sensors` rows with blocks, counting whole and block computations; every
/// value is a pure function of (sensor, column).
struct CountingGridStep {
  RadianceMatrix slot;
  std::atomic<int> whole{0}, blocks{0};
  Step step;

  CountingGridStep(std::size_t sensors, const std::string& key, std::size_t failing_sensor = SIZE_MAX) {
    step = make_step(
        StepKind::DirectSun, 3, {"sun-direct", key}, slot,
        [this, sensors] {
          ++whole;
          return numbered_rows(0, sensors, 5);
        },
        encode_matrix, decode_matrix, [sensors](const RadianceMatrix& m) { return m.rows() == sensors; });
    step.blocks = matrix_sensor_blocks(sensors, [this, failing_sensor](engine::SensorRange rows) {
      ++blocks;
      if (failing_sensor >= rows.begin && failing_sensor < rows.end)
        throw std::runtime_error("no light at sensor " + std::to_string(failing_sensor));
      return numbered_rows(rows.begin, rows.end, 5);
    });
  }
};

using test::fresh_dir;

/// Every rank of `errors` failed, with a DistributedJobError that `check` examines.
void expect_every_rank_failed(const std::vector<std::exception_ptr>& errors,
                              const std::function<void(const dist::DistributedJobError&)>& check) {
  for (std::size_t r = 0; r < errors.size(); ++r) {
    ASSERT_TRUE(errors[r]) << "rank " << r;
    try {
      std::rethrow_exception(errors[r]);
    } catch (const dist::DistributedJobError& x) {
      check(x);
    } catch (const std::exception& x) {
      ADD_FAILURE() << "rank " << r << ": not a DistributedJobError: " << x.what();
    }
  }
}

/// Runs a CountingGridStep of `sensors` rows on `ranks` in-process ranks with blocks of 8.
void expect_distributed_step_is_whole(int ranks, std::size_t sensors) {
  SCOPED_TRACE(std::to_string(ranks) + " ranks, " + std::to_string(sensors) + " sensors");
  const std::string expected = encode_matrix(numbered_rows(0, sensors, 5));
  const std::string name = "sensor_blocks_" + std::to_string(ranks) + "_" + std::to_string(sensors);
  std::atomic<int> whole{0}, blocks{0};
  std::vector<std::string> taken(static_cast<std::size_t>(ranks));
  test::run_ranks_expecting_no_error(ranks, [&](dist::Communicator& comm) {
    const ArtifactStore store(fresh_dir(name + "_rank" + std::to_string(comm.rank())).string());
    const auto executor = make_distributed_executor(comm, store, false, 8);
    CountingGridStep g(sensors, "k");
    if (!executor->run(g.step)) throw std::runtime_error("the step was not computed");
    taken[static_cast<std::size_t>(comm.rank())] = encode_matrix(g.slot);
    whole += g.whole;
    blocks += g.blocks;
    // Rank 0 alone stores the joined artefact.
    const auto stored = store.read("sun-direct", "k");
    if (comm.rank() == dist::RootRank ? stored.value_or("") != expected : stored.has_value())
      throw std::runtime_error("rank " + std::to_string(comm.rank()) + ": wrong store");
  });
  for (const std::string& t : taken) EXPECT_EQ(t, expected);
  const std::size_t block_count = sensor_blocks(sensors, 8).size();
  if (ranks > 1 && block_count >= 2) {
    EXPECT_EQ(whole, 0);  // by blocks, each once over all ranks
    EXPECT_EQ(blocks, int(block_count));
  } else {
    EXPECT_EQ(whole, 1);  // one process, or a single block: computed whole on one rank
    EXPECT_EQ(blocks, 0);
  }
}

TEST(SensorBlocks, TheDistributedExecutorGivesEveryRankTheWholeGrid) {
  for (int ranks : {1, 2, 3, 4}) {
    expect_distributed_step_is_whole(ranks, 37);  // uneven: 8, 8, 8, 8, 5
    expect_distributed_step_is_whole(ranks, 20);  // 3 blocks: fewer than 4 ranks
    expect_distributed_step_is_whole(ranks, 8);   // one block
    expect_distributed_step_is_whole(ranks, 1);   // one sensor
    expect_distributed_step_is_whole(ranks, 0);   // no sensor
  }
}

TEST(SensorBlocks, AFailingBlockFailsEveryRankNamingTheGridAndItsSensors) {
  const auto errors = dist::test::run_ranks(3, [&](dist::Communicator& comm) {
    const ArtifactStore store(fresh_dir("sensor_blocks_fail_rank" + std::to_string(comm.rank())).string());
    const auto executor = make_distributed_executor(comm, store, false, 8);
    CountingGridStep g(30, "k", 17);
    executor->run(g.step);
  });
  expect_every_rank_failed(errors, [](const dist::DistributedJobError& x) {
    EXPECT_NE(std::string(x.what()).find("direct sun 3, sensors 16 to 23"), std::string::npos) << x.what();
    EXPECT_EQ(x.job_message(), "no light at sensor 17");
  });
}

/// An annual study of the Oakland weather file for synthetic coefficients (20 sensors), with
/// the sun bins' tables (`with_sun`) or without, one process against blocks of 8 on ranks.
void expect_annual_blocks_are_the_whole_study(bool with_sun) {
  SCOPED_TRACE(with_sun ? "sun bins" : "sky alone");
  const weather::HourlyWeather epw = weather::read_hourly_weather(std::string(DAYPHOTON_SOURCE_DIR) +
                                                                  "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw");
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  const SkyAndSuns ss = annual_sky_and_suns(epw, sky::solar_site_of(epw), basis, sun_excluded_sky_options(0.2));
  std::vector<Vec3> directions;
  for (const sky::SunRecord& sun : ss.suns) directions.push_back(sun.direction);
  const engine::SunBins bins = engine::SunBins::for_suns(directions, 1);
  const std::size_t sensors = 20;
  RadianceMatrix sky_c(sensors, std::size_t(basis.bin_count()), 3), direct(sensors, ss.suns.size(), 3),
      bin_c(sensors, bins.size(), 3);
  auto fill = [](RadianceMatrix& m, double scale) {
    for (std::size_t i = 0; i < m.data().size(); ++i) m.data()[i] = float(scale * double((i * 7919) % 1000) / 1000.0);
  };
  fill(sky_c, 0.02);
  fill(direct, 2e-3);
  fill(bin_c, 1e-4);
  AnnualStudySettings settings;
  AnnualStudy whole;
  if (with_sun) {
    const metrics::IlluminanceTable dir = direct_sun_table(direct, ss.suns, ss.sky.steps);
    const metrics::IlluminanceTable ind = indirect_sun_table(bin_c, bins, ss.suns, ss.sky.steps);
    whole = compute_annual_study_with_sun(sky_c, ss.sky, dir, ind, settings);
  } else {
    whole = compute_annual_study(sky_c, ss.sky, settings);
  }
  const GridSunCoefficients parts{&direct, &ss.suns, &bin_c, &bins};
  for (int ranks : {2, 3}) {
    std::vector<std::optional<AnnualStudy>> got(static_cast<std::size_t>(ranks));
    const auto errors = dist::test::run_ranks(ranks, [&](dist::Communicator& comm) {
      const ArtifactStore store(fresh_dir("annual_blocks_rank" + std::to_string(comm.rank())).string());
      const auto executor = make_distributed_executor(comm, store, false, 8);
      got[static_cast<std::size_t>(comm.rank())] =
          annual_study_in_blocks(*executor, "grid", sky_c, ss.sky, settings, with_sun ? &parts : nullptr);
    });
    for (const std::exception_ptr& e : errors) ASSERT_FALSE(e);
    for (int r = 1; r < ranks; ++r) EXPECT_FALSE(got[static_cast<std::size_t>(r)].has_value());
    ASSERT_TRUE(got[0].has_value());
    const AnnualStudy& b = *got[0];
    EXPECT_EQ(b.illuminance.sensor_count(), sensors);
    EXPECT_TRUE(std::equal(b.illuminance.steps().begin(), b.illuminance.steps().end(), whole.illuminance.steps().begin(),
                           whole.illuminance.steps().end(), [](const metrics::TimeStamp& x, const metrics::TimeStamp& y) {
                             return x.month == y.month && x.day == y.day && x.hour == y.hour;
                           }));
    bool same_table = true;
    for (std::size_t t = 0; t < whole.illuminance.step_count(); ++t)
      for (std::size_t s = 0; s < sensors; ++s) same_table = same_table && b.illuminance.lux(t, s) == whole.illuminance.lux(t, s);
    EXPECT_TRUE(same_table);
    ASSERT_EQ(b.sensors.size(), sensors);
    EXPECT_EQ(std::memcmp(b.sensors.data(), whole.sensors.data(), sensors * sizeof(metrics::SensorMetrics)), 0);
    EXPECT_EQ(b.ase_hours, whole.ase_hours);
    EXPECT_EQ(b.occupied_hours, whole.occupied_hours);
    EXPECT_EQ(grid_metrics_json(b, settings), grid_metrics_json(whole, settings));
  }
  // Not a trivial comparison: light, and with the sun some ASE hours.
  EXPECT_GT(whole.grid.mean.mean_occupied_lux, 10.0);
  if (with_sun) {
    EXPECT_GT(*std::max_element(whole.ase_hours.begin(), whole.ase_hours.end()), 0);
  }
}

TEST(SensorBlocks, AnOverflowInTheAnnualMultiplyNamesTheGridsOwnSensor) {
  // Sensor 13 (the second block of 8) has a coefficient near the float maximum: its
  // illuminance overflows a float. One process and the blocks name the same sensor.
  const weather::HourlyWeather epw = weather::read_hourly_weather(std::string(DAYPHOTON_SOURCE_DIR) +
                                                                  "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw");
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  const SkyAndSuns ss = annual_sky_and_suns(epw, sky::solar_site_of(epw), basis, sun_excluded_sky_options(0.2));
  RadianceMatrix sky_c(20, std::size_t(basis.bin_count()), 3);
  for (std::size_t i = 0; i < sky_c.data().size(); ++i) sky_c.data()[i] = 0.01f;
  const std::size_t per_row = std::size_t(basis.bin_count()) * 3;
  for (std::size_t i = 0; i < per_row; ++i) sky_c.data()[13 * per_row + i] = 3e38f;
  const AnnualStudySettings settings;
  std::string alone;
  try {
    compute_annual_study(sky_c, ss.sky, settings);
    ADD_FAILURE() << "no overflow in one process";
  } catch (const std::range_error& e) {
    alone = e.what();
  }
  ASSERT_EQ(alone.rfind("annual illuminance: sensor 13 at step ", 0), 0u) << alone;
  const auto errors = dist::test::run_ranks(2, [&](dist::Communicator& comm) {
    const ArtifactStore store(fresh_dir("annual_overflow_rank" + std::to_string(comm.rank())).string());
    const auto executor = make_distributed_executor(comm, store, false, 8);
    annual_study_in_blocks(*executor, "grid", sky_c, ss.sky, settings);
  });
  expect_every_rank_failed(errors, [&](const dist::DistributedJobError& x) {
    EXPECT_EQ(x.job_message(), alone);
    EXPECT_NE(std::string(x.what()).find("sensors 8 to 15"), std::string::npos) << x.what();
  });
}

TEST(SensorBlocks, TheAnnualMultiplyByBlocksIsTheWholeStudyOnRankZero) {
  expect_annual_blocks_are_the_whole_study(true);
  expect_annual_blocks_are_the_whole_study(false);
}

}  // namespace
}  // namespace dayphoton::study
