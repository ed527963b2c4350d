// Annual illuminance (study/annual_illuminance.h): the tiled, parallel product against a
// plain triple loop on random matrices, night columns, thread-count independence, shape
// errors, and the binary and CSV files (layout bytes, round trip, corrupt files); the inner
// tile product (tile_product.h) bit for bit against the plain sequential sum.
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/tile_product.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include "../temp_folder.h"

using namespace dayphoton;
using namespace dayphoton::study;
namespace fs = std::filesystem;

namespace {

RadianceMatrix random_matrix(std::size_t rows, std::size_t columns, int components, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  RadianceMatrix m(rows, columns, components);
  for (float& v : m.data()) v = u(rng);
  return m;
}

std::vector<metrics::TimeStamp> stamps(std::size_t n) {
  std::vector<metrics::TimeStamp> s(n);
  for (std::size_t t = 0; t < n; ++t) s[t] = {1 + static_cast<int>(t / 24 % 12), 1 + static_cast<int>(t / 24 % 28), t % 24 + 0.5};
  return s;
}

/// Plain dctimestep + rmtxop: E = 179 sum_p sum_c w_c C[s][p][c] S[p][t][c], in double.
double reference_lux(const RadianceMatrix& c, const RadianceMatrix& sky, std::size_t s, std::size_t t) {
  const double w3[3] = {0.265, 0.670, 0.065};
  double e = 0;
  for (std::size_t p = 0; p < c.columns(); ++p)
    for (int k = 0; k < c.components(); ++k)
      e += (c.components() == 3 ? w3[k] : 1.0) * double(c.at(s, p, k)) * double(sky.at(p, t, k));
  return 179.0 * e;
}

std::string temp_path(const std::string& name) {
  return (test::process_temp_dir() / ("dayphoton_annual_test_" + name)).string();
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

TEST(AnnualIlluminance, MatchesATripleLoopAndNightColumnsAreZero) {
  std::mt19937 rng(20240605);
  // 37 steps: two full tiles of 16 and a partial one; 11 bins; 7 sensors.
  const RadianceMatrix c = random_matrix(7, 11, 3, rng);
  RadianceMatrix sky = random_matrix(11, 37, 3, rng);
  const std::size_t night[] = {0, 5, 16, 17, 36};
  for (std::size_t t : night)
    for (std::size_t p = 0; p < 11; ++p)
      for (int k = 0; k < 3; ++k) sky.at(p, t, k) = 0.0f;
  // A column lit in one channel of one bin only is a day column.
  for (std::size_t p = 0; p < 11; ++p)
    for (int k = 0; k < 3; ++k) sky.at(p, 20, k) = 0.0f;
  sky.at(10, 20, 2) = 0.25f;

  const metrics::IlluminanceTable table = annual_illuminance(c, sky, stamps(37));
  ASSERT_EQ(table.step_count(), 37u);
  ASSERT_EQ(table.sensor_count(), 7u);
  for (std::size_t t = 0; t < 37; ++t)
    for (std::size_t s = 0; s < 7; ++s) {
      const double ref = reference_lux(c, sky, s, t);
      // Both sums are in double (error ~1e-15 relative); ours is then stored as float:
      // relative error <= 2^-24, so 2^-23 relative bounds the difference.
      EXPECT_NEAR(table.lux(t, s), ref, std::ldexp(ref, -23)) << "step " << t << " sensor " << s;
    }
  for (std::size_t t : night)
    for (std::size_t s = 0; s < 7; ++s) EXPECT_EQ(table.lux(t, s), 0.0f);
  EXPECT_GT(table.lux(20, 0), 0.0f);
  EXPECT_EQ(table.steps()[23].hour, 23.5);
}

TEST(AnnualIlluminance, TheSubPatchCorrectionAddsEachQuadrantsShareTimesItsDelta) {
  // 37 steps, 11 bins (bin 4 seen by no sensor's direct part: left out of the product), 7
  // sensors: E + 179 sum_p sum_q Q_pq d_pq(t), Q_p3 = lum C_p - Q_p0 - Q_p1 - Q_p2, in double.
  std::mt19937 rng(31);
  const RadianceMatrix c = random_matrix(7, 11, 3, rng);
  RadianceMatrix sky = random_matrix(11, 37, 3, rng);
  for (std::size_t p = 0; p < 11; ++p)
    for (int k = 0; k < 3; ++k) sky.at(p, 3, k) = 0.0f;  // a night
  RadianceMatrix deltas = random_matrix(44, 37, 1, rng);
  for (float& v : deltas.data()) v -= 0.5f;
  for (std::size_t r = 0; r < 44; ++r) deltas.at(r, 3, 0) = 0.0f;
  SubPatchShares shares;
  shares.sensors = 7;
  shares.bins = 11;
  std::uniform_real_distribution<float> u(0.0f, 0.3f);
  for (std::size_t i = 0; i < 7 * 11 * 4; ++i) shares.values.push_back(i / 4 % 11 == 4 ? 0.0f : u(rng));
  const metrics::IlluminanceTable plain = annual_illuminance(c, sky, stamps(37));
  const metrics::IlluminanceTable table = annual_illuminance(c, sky, stamps(37), 0, &shares, &deltas);
  double largest = 0;
  for (std::size_t t = 0; t < 37; ++t)
    for (std::size_t s = 0; s < 7; ++s) {
      double correction = 0;
      for (std::size_t p = 0; p < 11; ++p) {
        const float* v = shares.values.data() + (s * 11 + p) * 4;
        const double q3 = double(v[0]) - v[1] - v[2] - v[3];
        for (std::size_t q = 0; q < 3; ++q) correction += double(v[1 + q]) * deltas.at(4 * p + q, t, 0);
        correction += q3 * deltas.at(4 * p + 3, t, 0);
      }
      const double ref = reference_lux(c, sky, s, t) + 179.0 * correction;
      EXPECT_NEAR(table.lux(t, s), ref, 1e-6 * std::fabs(reference_lux(c, sky, s, t)) + 1e-9) << t << " " << s;
      largest = std::max(largest, std::fabs(179.0 * correction) / std::max(1e-9, double(plain.lux(t, s))));
    }
  EXPECT_GT(largest, 0.01);  // the correction is there (the plain product misses it)
  for (std::size_t s = 0; s < 7; ++s) EXPECT_EQ(table.lux(3, s), 0.0f);
  // Without deltas (a matrix read from a file) or without shares: the plain product.
  const SubPatchShares none;
  const RadianceMatrix no_deltas;
  EXPECT_TRUE(annual_illuminance(c, sky, stamps(37), 0, &none, &deltas).lux(5, 2) == plain.lux(5, 2));
  EXPECT_TRUE(annual_illuminance(c, sky, stamps(37), 0, &shares, &no_deltas).lux(5, 2) == plain.lux(5, 2));
  // Shapes that do not match are refused; the rows of a block give the whole's rows.
  const RadianceMatrix short_deltas = random_matrix(40, 37, 1, rng);
  EXPECT_THROW(annual_illuminance(c, sky, stamps(37), 0, &shares, &short_deltas), std::invalid_argument);
  const SubPatchShares block = shares.rows(2, 5);
  ASSERT_EQ(block.sensors, 3u);
  EXPECT_TRUE(std::equal(block.values.begin(), block.values.end(), shares.values.begin() + 2 * 11 * 4));
  EXPECT_THROW(annual_illuminance(c, sky, stamps(37), 0, &block, &deltas), std::invalid_argument);
}

TEST(AnnualIlluminance, OneComponentMatricesUse179) {
  std::mt19937 rng(7);
  const RadianceMatrix c = random_matrix(3, 5, 1, rng);
  const RadianceMatrix sky = random_matrix(5, 4, 1, rng);
  const auto table = annual_illuminance(c, sky, stamps(4));
  for (std::size_t t = 0; t < 4; ++t)
    for (std::size_t s = 0; s < 3; ++s) {
      const double ref = reference_lux(c, sky, s, t);
      EXPECT_NEAR(table.lux(t, s), ref, std::ldexp(ref, -23));
    }
}

TEST(AnnualIlluminance, ResultDoesNotDependOnTheThreadCount) {
  std::mt19937 rng(99);
  const RadianceMatrix c = random_matrix(13, 146, 3, rng);
  const RadianceMatrix sky = random_matrix(146, 200, 3, rng);
  const auto parallel = annual_illuminance(c, sky, stamps(200));
  metrics::IlluminanceTable serial;
  tbb::task_arena one_thread(1);
  one_thread.execute([&] { serial = annual_illuminance(c, sky, stamps(200)); });
  for (std::size_t t = 0; t < 200; ++t)
    for (std::size_t s = 0; s < 13; ++s) ASSERT_EQ(parallel.lux(t, s), serial.lux(t, s));
}

// Every variant of the tile product (the AVX one where the processor has it, the portable
// one) gives each sum bit for bit as the plain loop adds it: products rounded, then added in
// order from 0. Values of mixed sign and magnitude, so that any reassociation or fused
// multiply-add would show in the last bits.
TEST(TileProduct, EverySumIsThePlainSequentialOneBitForBit) {
  using detail::TileSteps;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-30, 30);
  for (std::size_t k : {std::size_t(1), std::size_t(3), std::size_t(438)}) {
    std::vector<double> rows(2 * k), columns(k * TileSteps);
    for (double& v : rows) v = std::ldexp(u(rng), e(rng));
    for (double& v : columns) v = std::ldexp(u(rng), e(rng));
    for (std::size_t sensors : {std::size_t(1), std::size_t(2)}) {
      std::vector<double> out(2 * TileSteps, -1.0), portable(2 * TileSteps, -1.0);
      detail::tile_product(rows.data(), sensors, k, columns.data(), out.data());
      detail::tile_product_portable(rows.data(), sensors, k, columns.data(), portable.data());
      for (std::size_t r = 0; r < sensors; ++r)
        for (std::size_t j = 0; j < TileSteps; ++j) {
          volatile double sum = 0.0;  // volatile: each product and sum rounded to double in order
          for (std::size_t i = 0; i < k; ++i) {
            volatile double product = rows[r * k + i] * columns[i * TileSteps + j];
            sum = sum + product;
          }
          ASSERT_EQ(out[r * TileSteps + j], sum) << "k " << k << " row " << r << " step " << j
                                                 << (detail::tile_product_uses_avx() ? " (AVX)" : "");
          ASSERT_EQ(portable[r * TileSteps + j], sum) << "k " << k << " row " << r << " step " << j;
        }
    }
  }
}

TEST(AnnualIlluminance, RejectsMismatchedShapes) {
  RadianceMatrix c(2, 5), sky(5, 3), sky6(6, 3), grey(5, 3, 1);
  EXPECT_THROW(annual_illuminance(c, sky6, stamps(3)), std::invalid_argument);
  EXPECT_THROW(annual_illuminance(c, grey, stamps(3)), std::invalid_argument);
  EXPECT_THROW(annual_illuminance(c, sky, stamps(4)), std::invalid_argument);
  EXPECT_NO_THROW(annual_illuminance(c, sky, stamps(3)));
}

TEST(IlluminanceBinary, LayoutIsTheDocumentedLittleEndianOne) {
  metrics::IlluminanceTable table({{2, 28, 13.5}, {12, 31, 23.5}}, 3);
  table.lux(0, 0) = 1.0f;
  table.lux(1, 2) = 1234.5f;
  const std::string path = temp_path("layout.bin");
  write_illuminance_binary(table, path);
  const std::string b = read_bytes(path);
  fs::remove(path);
  ASSERT_EQ(b.size(), 16u + 2 * 8 + 2 * 3 * 4);
  EXPECT_EQ(b.substr(0, 8), "DPILLUM1");
  const auto u = [&](std::size_t i) { return static_cast<unsigned>(static_cast<unsigned char>(b[i])); };
  EXPECT_EQ(u(8), 2u);  // T = 2, little-endian uint32
  EXPECT_EQ(u(9) | u(10) | u(11), 0u);
  EXPECT_EQ(u(12), 3u);  // S = 3
  EXPECT_EQ(u(16), 2u);  // month
  EXPECT_EQ(u(17), 28u); // day
  EXPECT_EQ(u(18) | u(19), 0u);
  // float32 13.5 = 0x41580000, little-endian.
  EXPECT_EQ(u(20), 0x00u);
  EXPECT_EQ(u(21), 0x00u);
  EXPECT_EQ(u(22), 0x58u);
  EXPECT_EQ(u(23), 0x41u);
  // First value (step 0, sensor 0) = 1.0f = 0x3f800000 at byte 16 + 2 x 8 = 32.
  EXPECT_EQ(u(32), 0x00u);
  EXPECT_EQ(u(34), 0x80u);
  EXPECT_EQ(u(35), 0x3fu);
}

TEST(IlluminanceBinary, RoundTripsExactly) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1e5f);
  metrics::IlluminanceTable table(stamps(50), 9);
  for (std::size_t t = 0; t < 50; ++t)
    for (std::size_t s = 0; s < 9; ++s) table.lux(t, s) = u(rng);
  const std::string path = temp_path("roundtrip.bin");
  write_illuminance_binary(table, path);
  const metrics::IlluminanceTable back = read_illuminance_binary(path);
  fs::remove(path);
  ASSERT_EQ(back.step_count(), 50u);
  ASSERT_EQ(back.sensor_count(), 9u);
  for (std::size_t t = 0; t < 50; ++t) {
    EXPECT_EQ(back.steps()[t].month, table.steps()[t].month);
    EXPECT_EQ(back.steps()[t].day, table.steps()[t].day);
    EXPECT_EQ(back.steps()[t].hour, table.steps()[t].hour);
    for (std::size_t s = 0; s < 9; ++s) ASSERT_EQ(back.lux(t, s), table.lux(t, s));
  }
}

TEST(IlluminanceBinary, CorruptFilesAreErrorsNamingTheFile) {
  metrics::IlluminanceTable table(stamps(4), 2);
  const std::string path = temp_path("corrupt.bin");
  write_illuminance_binary(table, path);
  const std::string good = read_bytes(path);
  auto expect_error = [&](const std::string& bytes, const std::string& what) {
    write_bytes(path, bytes);
    try {
      read_illuminance_binary(path);
      ADD_FAILURE() << "no error for " << what;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  };
  expect_error(good.substr(0, good.size() - 1), "truncated data");
  expect_error(good + "x", "trailing byte");
  expect_error(good.substr(0, 10), "truncated header");
  std::string bad = good;
  bad[0] = 'X';
  expect_error(bad, "magic");
  bad = good;
  bad[16] = 13;  // month 13
  expect_error(bad, "month");
  bad = good;
  bad[18] = 1;  // reserved
  expect_error(bad, "reserved");
  bad = good;
  bad[8] = 5;  // T = 5 but data for 4
  expect_error(bad, "count");
  bad = good;
  const std::uint32_t nan_bits = 0x7fc00000u;
  std::memcpy(&bad[16 + 4 * 8], &nan_bits, 4);
  expect_error(bad, "NaN");
  fs::remove(path);
  EXPECT_THROW(read_illuminance_binary(path), std::runtime_error);  // missing
}

TEST(IlluminanceCsv, HeaderRowsAndOneDecimal) {
  metrics::IlluminanceTable table({{1, 1, 0.5}, {7, 15, 12.5}}, 3);
  table.lux(1, 0) = 123.44f;
  table.lux(1, 1) = 0.05f;
  table.lux(1, 2) = 99999.96f;
  const std::string path = temp_path("illuminance.csv");
  write_illuminance_csv(table, path);
  std::ifstream in(path);
  std::string header, row0, row1, extra;
  std::getline(in, header);
  std::getline(in, row0);
  std::getline(in, row1);
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(header, "month,day,hour,s0,s1,s2");
  EXPECT_EQ(row0, "1,1,0.5,0.0,0.0,0.0");
  EXPECT_EQ(row1, "7,15,12.5,123.4,0.1,100000.0");
  // The layout is the one metrics::read_illuminance_csv (and refdata) use.
  const metrics::IlluminanceTable back = metrics::read_illuminance_csv(path);
  fs::remove(path);
  ASSERT_EQ(back.step_count(), 2u);
  EXPECT_EQ(back.steps()[1].month, 7);
  EXPECT_FLOAT_EQ(back.lux(1, 0), 123.4f);
}

TEST(IlluminanceCsv, NonFiniteValuesAreRefusedAndHugeOnesPrintExactly) {
  // NaN used to go through llround (undefined behaviour) and print as a number ("-0.8").
  const std::string path = temp_path("nonfinite.csv");
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()}) {
    metrics::IlluminanceTable table({{1, 1, 0.5}, {1, 1, 1.5}}, 2);
    table.lux(1, 1) = bad;
    try {
      write_illuminance_csv(table, path);
      FAIL() << "wrote " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), path + ": the illuminance of sensor 1 at step 1 is not a finite number");
    }
    EXPECT_FALSE(fs::exists(path));  // nothing written
  }
  // Beyond the integer arithmetic's exact range (2^53 tenths) the value is printed in full.
  metrics::IlluminanceTable table({{1, 1, 0.5}}, 3);
  table.lux(0, 0) = 1e20f;
  table.lux(0, 1) = -3e38f;
  table.lux(0, 2) = 9e14f;  // just below: the integer path
  write_illuminance_csv(table, path);
  std::ifstream in(path);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(row, "1,1,0.5,100000002004087734272.0,-300000000549775575777803994281145270272.0,899999995002880.0");
  fs::remove(path);
}

TEST(AnnualIlluminance, OverflowingProductsAreAnErrorNotInfinity) {
  RadianceMatrix coefficients(1, 1, 3), sky(1, 1, 3);
  for (int c = 0; c < 3; ++c) {
    coefficients.at(0, 0, c) = 1e30f;
    sky.at(0, 0, c) = 1e30f;
  }
  EXPECT_THROW(annual_illuminance(coefficients, sky, {{1, 1, 12.5}}), std::range_error);
}
