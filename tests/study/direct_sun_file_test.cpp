// direct_sun.bin.gz (study/direct_sun_file.h) and the tables of annual's exact-sun mode
// (study/annual_exact_sun.h): the export round-trips bit for bit; the direct-sun table built
// from it equals direct_sun_table from the run's RGB coefficients bit for bit; a sun off the
// exported positions takes its nearest within the limit and is counted, beyond it is a located
// error; a stencil needing an untraced bin is renormalised over the traced ones; damaged files
// are located errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>
#include <zlib.h>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/study/annual_exact_sun.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/direct_sun_file.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

Vec3 from_angles(double altitude_deg, double azimuth_deg) {
  const double h = deg_to_rad(altitude_deg), a = deg_to_rad(azimuth_deg);
  return {std::sin(a) * std::cos(h), std::cos(a) * std::cos(h), std::sin(h)};
}

/// Suns at steps 0, 2, 4, ... along a path, rounded through float as the run keeps them.
std::vector<sky::SunRecord> path_suns(std::size_t count, std::size_t first_step) {
  std::vector<sky::SunRecord> suns;
  for (std::size_t i = 0; i < count; ++i)
    suns.push_back(sky::sun_record(first_step + 2 * i, from_angles(10 + 5.0 * i, 100 + 7.0 * i), 50000 + 1000.0 * i));
  return suns_from_matrix(suns_to_matrix(suns));
}

/// RGB direct coefficients with many zeros (a shadowed sensor, shadowed hours).
RadianceMatrix coefficients(std::size_t sensors, std::size_t suns, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  RadianceMatrix m(sensors, suns, 3);
  for (std::size_t s = 0; s < sensors; ++s)
    for (std::size_t k = 0; k < suns; ++k)
      if (s != 1 && u(rng) < 0.6)
        for (int c = 0; c < 3; ++c) m.at(s, k, c) = 1e-4f * u(rng);
  return m;
}

std::string temp_path(const std::string& name) {
  return (fs::temp_directory_path() / ("dayphoton_direct_sun_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::vector<metrics::TimeStamp> steps_of(std::size_t n) { return std::vector<metrics::TimeStamp>(n); }

TEST(DirectSunFile, LuminanceMatricesGiveTheRunsTableBitForBit) {
  // The run keeps a grid's hourly direct sun as one luminance value per sun
  // (DirectSunValues::Luminance): the export and the run's table agree on it exactly too.
  const std::vector<sky::SunRecord> lit = path_suns(9, 1), unlit = path_suns(5, 0);
  const RadianceMatrix rgb_lit = coefficients(4, lit.size(), 1), rgb_unlit = coefficients(4, unlit.size(), 2);
  auto luminance = [](const RadianceMatrix& rgb) {
    RadianceMatrix m(rgb.rows(), rgb.columns(), 1);
    for (std::size_t s = 0; s < rgb.rows(); ++s)
      for (std::size_t k = 0; k < rgb.columns(); ++k)
        m.at(s, k, 0) = float(dot(Vec3{rgb.at(s, k, 0), rgb.at(s, k, 1), rgb.at(s, k, 2)}, RgbLuminanceWeights));
    return m;
  };
  const RadianceMatrix c_lit = luminance(rgb_lit), c_unlit = luminance(rgb_unlit);
  const DirectSunExport e = make_direct_sun_export({{&c_lit, &lit}, {&c_unlit, &unlit}});
  ASSERT_EQ(e.sun_count(), 14u);
  ASSERT_FALSE(e.lux.empty());
  const std::vector<metrics::TimeStamp> steps = steps_of(24);
  const metrics::IlluminanceTable run = direct_sun_table(c_lit, lit, steps);
  ExactSunNotes notes;
  const metrics::IlluminanceTable from_file = exported_direct_sun_table(e, lit, steps, "x", notes);
  for (std::size_t t = 0; t < steps.size(); ++t)
    for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(from_file.lux(t, s), run.lux(t, s)) << t << " " << s;
  // The same illuminance as the RGB matrix to float precision.
  const metrics::IlluminanceTable from_rgb = direct_sun_table(rgb_lit, lit, steps);
  for (std::size_t t = 0; t < steps.size(); ++t)
    for (std::size_t s = 0; s < 4; ++s) EXPECT_NEAR(run.lux(t, s), from_rgb.lux(t, s), 1e-6 * from_rgb.lux(t, s));
  // Parts of different kinds are refused.
  EXPECT_THROW(make_direct_sun_export({{&c_lit, &lit}, {&rgb_unlit, &unlit}}), std::invalid_argument);
}

TEST(DirectSunFile, RoundTripAndTheRunsTableBitForBit) {
  const std::vector<sky::SunRecord> lit = path_suns(9, 1);     // odd steps: the run's lit suns
  std::vector<sky::SunRecord> unlit = path_suns(5, 0);         // even steps: daytime, no direct light
  const RadianceMatrix c_lit = coefficients(4, lit.size(), 1), c_unlit = coefficients(4, unlit.size(), 2);
  DirectSunExport e = make_direct_sun_export({{&c_lit, &lit}, {&c_unlit, &unlit}});
  e.sun_bins_mf = 6;
  e.seed = 17;
  e.samples = 16;
  e.site = "a site";
  e.weather = "w.epw";
  ASSERT_EQ(e.sun_count(), 14u);
  for (std::size_t k = 1; k < e.sun_count(); ++k) EXPECT_LT(e.steps[k - 1], e.steps[k]);
  const std::string path = temp_path("round.bin.gz");
  write_direct_sun_file(e, path);
  const DirectSunExport r = read_direct_sun_file(path);
  fs::remove(path);
  EXPECT_EQ(r.sensors, 4u);
  EXPECT_EQ(r.steps, e.steps);
  EXPECT_EQ(r.sun_bins_mf, 6);
  EXPECT_EQ(r.seed, 17u);
  EXPECT_EQ(r.samples, 16);
  EXPECT_EQ(r.row_start, e.row_start);
  EXPECT_EQ(r.sun, e.sun);
  EXPECT_EQ(r.lux, e.lux);                                     // float64: exact
  EXPECT_EQ(r.row_start[2] - r.row_start[1], 0u);              // sensor 1 is in shadow all year
  for (std::size_t k = 0; k < r.sun_count(); ++k) EXPECT_GT(dot(r.directions[k], e.directions[k]), 1 - 1e-12);

  // The direct-sun table of the run's lit suns, from the file, is the run's bit for bit.
  const std::vector<metrics::TimeStamp> steps = steps_of(24);
  const metrics::IlluminanceTable run = direct_sun_table(c_lit, lit, steps);
  ExactSunNotes notes;
  const metrics::IlluminanceTable from_file = exported_direct_sun_table(r, lit, steps, "x", notes);
  for (std::size_t t = 0; t < steps.size(); ++t)
    for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(from_file.lux(t, s), run.lux(t, s)) << t << " " << s;
  EXPECT_TRUE(notes.exact());
  EXPECT_EQ(notes.suns_exact, lit.size());
  EXPECT_TRUE(notes.warnings().empty());
  // An even step (no direct light in the run's file) with light in another file is exact too.
  std::vector<sky::SunRecord> other = {unlit[2]};
  other[0].disc_radiance = 1e6;
  ExactSunNotes other_notes;
  const metrics::IlluminanceTable t2 = exported_direct_sun_table(r, other, steps, "x", other_notes);
  EXPECT_TRUE(other_notes.exact());
  const Vec3 w = RgbLuminanceWeights * RadianceWhiteEfficacy_lm_per_W;
  for (std::size_t s = 0; s < 4; ++s) {
    double e_s = 0;
    for (int c = 0; c < 3; ++c) e_s += w[c] * double(c_unlit.at(s, 2, c));
    EXPECT_EQ(t2.lux(other[0].step, s), static_cast<float>(e_s * 1e6));
  }
}

TEST(DirectSunFile, NearestWithinTheLimitIsCountedBeyondItIsAnError) {
  const std::vector<sky::SunRecord> lit = path_suns(6, 1);
  const RadianceMatrix c = coefficients(3, lit.size(), 3);
  const DirectSunExport e = make_direct_sun_export({{&c, &lit}});
  const std::vector<metrics::TimeStamp> steps = steps_of(16);
  // 0.5 deg off the exported sun 3: its direct sun, counted and warned about.
  std::vector<sky::SunRecord> moved = {lit[3]};
  moved[0].direction = from_angles(10 + 15 + 0.5, 121);
  ExactSunNotes notes;
  const metrics::IlluminanceTable t = exported_direct_sun_table(e, moved, steps, "x", notes);
  EXPECT_FALSE(notes.exact());
  EXPECT_EQ(notes.suns_nearest, 1u);
  EXPECT_NEAR(notes.largest_nearest_deg, 0.5, 0.01);
  ASSERT_EQ(notes.warnings().size(), 1u);
  EXPECT_NE(notes.warnings()[0].find("interpolated"), std::string::npos);
  const metrics::IlluminanceTable at = direct_sun_table(c, lit, steps);
  for (std::size_t s = 0; s < 3; ++s) EXPECT_EQ(t.lux(moved[0].step, s), at.lux(lit[3].step, s));
  // 3 deg off every exported sun: a located error naming the file.
  moved[0].direction = from_angles(10 + 15 + 3, 121);
  ExactSunNotes far;
  try {
    exported_direct_sun_table(e, moved, steps, "grid/direct_sun.bin.gz", far);
    FAIL() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("grid/direct_sun.bin.gz"), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find("farther than 1 deg"), std::string::npos) << err.what();
  }
}

TEST(DirectSunFile, AStencilOutsideTheBinsIsRenormalisedOverTheTracedOnes) {
  // Bins for one sun; a sun two rows up needs patches that are not bins.
  const Vec3 sun = from_angles(30, 170);
  const engine::SunBins chosen = engine::SunBins::for_suns({sun}, 2);
  std::vector<int> patches;
  for (std::size_t i = 0; i < chosen.size(); ++i) patches.push_back(chosen.patch(i));
  const engine::SunBins bins = engine::SunBins::from_patches(patches, 2);
  ASSERT_EQ(bins.size(), chosen.size());
  RadianceMatrix c(1, bins.size(), 3);
  for (std::size_t j = 0; j < bins.size(); ++j)
    for (int k = 0; k < 3; ++k) c.at(0, j, k) = 2.0f;  // the same for every bin: any convex mix gives 2
  std::vector<sky::SunRecord> suns = {sky::sun_record(0, sun, 1000), sky::sun_record(1, from_angles(36, 172), 1000)};
  ExactSunNotes notes;
  const metrics::IlluminanceTable t = exported_indirect_sun_table(c, bins, suns, steps_of(2), notes);
  EXPECT_EQ(notes.suns_renormalised + notes.suns_nearest_bin, 1u);
  const double expected = 2.0 * RadianceWhiteEfficacy_lm_per_W * (0.265 + 0.670 + 0.065) * suns[1].disc_radiance;
  EXPECT_NEAR(t.lux(1, 0), expected, 1e-5 * expected);
  EXPECT_NEAR(t.lux(0, 0), expected, 1e-5 * expected);
  EXPECT_THROW(engine::SunBins::from_patches({patches[0], patches[0]}, 2), std::invalid_argument);
  EXPECT_THROW(engine::SunBins::from_patches({0}, 2), std::invalid_argument);
}

TEST(DirectSunFile, DamagedFilesAreLocatedErrors) {
  const std::vector<sky::SunRecord> lit = path_suns(5, 1);
  const RadianceMatrix c = coefficients(3, lit.size(), 4);
  const DirectSunExport e = make_direct_sun_export({{&c, &lit}});
  const std::string good = temp_path("good.bin.gz");
  write_direct_sun_file(e, good);
  // Decompressed text, damaged, compressed again.
  gzFile in = gzopen(good.c_str(), "rb");
  std::string data;
  char buf[4096];
  for (int n; (n = gzread(in, buf, sizeof buf)) > 0;) data.append(buf, std::size_t(n));
  gzclose(in);
  fs::remove(good);
  auto expect_error = [&](const std::string& text, const std::string& needle) {
    const std::string path = temp_path("bad.bin.gz");
    gzFile out = gzopen(path.c_str(), "wb");
    gzwrite(out, text.data(), unsigned(text.size()));
    gzclose(out);
    try {
      read_direct_sun_file(path);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find(path), std::string::npos) << err.what();
      EXPECT_NE(std::string(err.what()).find(needle), std::string::npos) << err.what();
    }
    fs::remove(path);
  };
  expect_error(data.substr(0, data.size() - 3), "ends inside sensor 2");
  expect_error(data + "x", "data after the last sensor");
  expect_error("not ours\n\n", "not a dayphoton direct-sun file");
  std::string v2 = data;
  v2.replace(v2.find("version=1"), 9, "version=2");
  expect_error(v2, "version 2");
  std::string huge = data;
  huge.replace(huge.find("sensors=3"), 9, "sensors=99999");
  expect_error(huge, "ends inside sensor 3");
}

}  // namespace
}  // namespace dayphoton::study
