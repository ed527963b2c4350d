// Tests for study/artifact_codec.h: photons, daylight coefficients and matrices round-trip
// bit for bit (photon arrays compared with memcmp, doubles and floats by bit pattern, odd
// values included: -0, denormals, infinities, NaN payloads); the photon layout is the
// documented little-endian one; decoding throws std::runtime_error at every truncation
// length, for trailing bytes, a wrong tag, a wrong layout version, an invalid path class and
// counts larger than the input (before allocating).
#include "dayphoton/study/artifact_codec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace dayphoton::study {
namespace {

using engine::PathClass;
using engine::Photon;
using engine::SourceTally;
using engine::TracedPhotons;

// Values a careless codec would lose: signed zero, denormals, infinities, a NaN with a
// payload (compared by bits, so its payload must survive too).
float odd_float(int i) {
  switch (i % 6) {
    case 0: return -0.0f;
    case 1: return std::numeric_limits<float>::denorm_min();
    case 2: return -std::numeric_limits<float>::infinity();
    case 3: {
      const std::uint32_t bits = 0x7fc01234u;
      float f;
      std::memcpy(&f, &bits, 4);
      return f;
    }
    case 4: return std::numeric_limits<float>::max();
    default: return 1.0f / 3.0f;
  }
}

std::vector<Photon> random_photons(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(-100.0f, 100.0f);
  std::vector<Photon> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    Photon& p = out[i];
    for (float& x : p.position) x = u(rng);
    for (float& x : p.flux) x = std::abs(u(rng)) * 1e-6f;
    if (i % 5 == 0) p.flux[i % 3] = odd_float(static_cast<int>(i / 5));
    p.source = static_cast<std::uint32_t>(rng() % 146);
    p.sky_ratio_code = static_cast<std::uint32_t>(rng() % 4096);
    if (i == 1) p.set_source_word(0xffffffffu);
    for (std::int8_t& x : p.normal) x = static_cast<std::int8_t>(static_cast<int>(rng() % 255) - 127);
    p.path_class = static_cast<PathClass>(i % 3);
  }
  return out;
}

SourceTally tally(std::uint64_t k) {
  SourceTally t;
  t.prepass_attempts = 1000 + k;
  t.mainpass_attempts = 0xfedcba9876543210ull - k;  // all 64 bits matter
  t.entered = 3 * k + 1;
  t.stored_global = 5 * k + 2;
  t.stored_caustic = 7 * k + 3;
  t.stored_direct = 11 * k + 4;
  t.bound_flux = 0.1 * double(k) + 1e-300;
  t.flux_per_attempt = std::nextafter(1.0 / 3.0, 1.0) * double(k + 1);
  t.storage_probability_global = k == 0 ? -0.0 : 0.123456789012345678;
  t.storage_probability_caustic = k == 1 ? std::numeric_limits<double>::denorm_min() : 1.0;
  t.capped = k % 2 == 1;
  return t;
}

TracedPhotons sample_photons(std::size_t surface, const std::vector<std::size_t>& planes,
                             std::size_t sources) {
  TracedPhotons t;
  t.surface = random_photons(surface, 1);
  for (std::size_t i = 0; i < planes.size(); ++i) t.planes.push_back(random_photons(planes[i], 10 + i));
  for (std::size_t k = 0; k < sources; ++k) t.tallies.push_back(tally(k));
  return t;
}

bool same_bits(const void* a, const void* b, std::size_t n) { return std::memcmp(a, b, n) == 0; }

void expect_same_photons(const std::vector<Photon>& a, const std::vector<Photon>& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(a.empty() || same_bits(a.data(), b.data(), a.size() * sizeof(Photon)));
}

void expect_same_tally(const SourceTally& a, const SourceTally& b) {
  EXPECT_EQ(a.prepass_attempts, b.prepass_attempts);
  EXPECT_EQ(a.mainpass_attempts, b.mainpass_attempts);
  EXPECT_EQ(a.capped, b.capped);
  EXPECT_EQ(a.entered, b.entered);
  EXPECT_EQ(a.stored_global, b.stored_global);
  EXPECT_EQ(a.stored_caustic, b.stored_caustic);
  EXPECT_EQ(a.stored_direct, b.stored_direct);
  EXPECT_TRUE(same_bits(&a.bound_flux, &b.bound_flux, 8));
  EXPECT_TRUE(same_bits(&a.flux_per_attempt, &b.flux_per_attempt, 8));
  EXPECT_TRUE(same_bits(&a.storage_probability_global, &b.storage_probability_global, 8));
  EXPECT_TRUE(same_bits(&a.storage_probability_caustic, &b.storage_probability_caustic, 8));
}

engine::DaylightCoefficients sample_coefficients(std::size_t sensors, std::size_t sources) {
  engine::DaylightCoefficients c;
  c.sensors = sensors;
  c.sources = sources;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (auto* part : {&c.direct, &c.caustic, &c.global})
    for (std::size_t i = 0; i < sensors * sources; ++i) part->push_back({u(rng), u(rng) * 1e-9, -u(rng)});
  if (!c.direct.empty()) c.direct[0] = {-0.0, std::numeric_limits<double>::denorm_min(), std::nan("7")};
  for (auto* part : {&c.direct_variance, &c.photon_variance})
    for (std::size_t i = 0; i < sensors * sources; ++i) part->push_back(u(rng) * 1e-7);
  return c;
}

RadianceMatrix sample_matrix(std::size_t rows, std::size_t columns, int components) {
  RadianceMatrix m(rows, columns, components);
  for (std::size_t i = 0; i < m.data().size(); ++i) m.data()[i] = static_cast<float>(i) * 0.37f - 2.0f;
  if (!m.data().empty()) m.data()[0] = odd_float(3);
  m.header_lines() = {"gendaymtx -m 1 weather.wea", "LATLONG= 51.5 -0.1", ""};
  return m;
}

TEST(ArtifactCodec, PhotonsRoundTripBitExact) {
  const TracedPhotons in = sample_photons(500, {0, 37, 1000}, 146);
  const TracedPhotons out = decode_photons(encode_photons(in));
  expect_same_photons(in.surface, out.surface);
  ASSERT_EQ(out.planes.size(), in.planes.size());
  for (std::size_t i = 0; i < in.planes.size(); ++i) expect_same_photons(in.planes[i], out.planes[i]);
  ASSERT_EQ(out.tallies.size(), in.tallies.size());
  for (std::size_t k = 0; k < in.tallies.size(); ++k) expect_same_tally(in.tallies[k], out.tallies[k]);
  // Encoding is a function of the value: re-encoding gives the same bytes.
  EXPECT_EQ(encode_photons(out), encode_photons(in));
}

TEST(ArtifactCodec, EmptyPhotonsRoundTrip) {
  const TracedPhotons out = decode_photons(encode_photons(TracedPhotons{}));
  EXPECT_TRUE(out.surface.empty());
  EXPECT_TRUE(out.planes.empty());
  EXPECT_TRUE(out.tallies.empty());
}

TEST(ArtifactCodec, PhotonLayoutIsLittleEndianAsDocumented) {
  TracedPhotons t;
  Photon p;
  p.position = {1.0f, -2.0f, 0.5f};
  p.flux = {0.25f, 0.0f, 3.0f};
  p.source = 0x20304u;
  p.sky_ratio_code = 0x010u;  // the source word 0x01020304
  p.normal = {-127, 0, 127};
  p.path_class = PathClass::Caustic;
  p.sky_quadrant = 3;
  t.surface.push_back(p);
  const std::string b = encode_photons(t);
  // tag, version, u64 count, 32-byte photon, u64 plane count, u64 source count.
  ASSERT_EQ(b.size(), 4u + 4 + 8 + 32 + 8 + 8);
  EXPECT_EQ(b.substr(0, 4), "PHOT");
  EXPECT_EQ(b.substr(4, 4), std::string("\x05\x00\x00\x00", 4));  // layout 5
  EXPECT_EQ(b.substr(8, 8), std::string("\x01\x00\x00\x00\x00\x00\x00\x00", 8));
  EXPECT_EQ(b.substr(16, 4), std::string("\x00\x00\x80\x3f", 4));  // 1.0f = 0x3f800000
  EXPECT_EQ(b.substr(20, 4), std::string("\x00\x00\x00\xc0", 4));  // -2.0f = 0xc0000000
  EXPECT_EQ(b.substr(40, 4), std::string("\x04\x03\x02\x01", 4));  // source, sky ratio code
  EXPECT_EQ(b.substr(44, 4), std::string("\x81\x00\x7f\x0d", 4));  // normal, class + 4 x quadrant
  EXPECT_EQ(b.substr(48, 16), std::string(16, '\0'));              // no planes, no sources
  const Photon back = decode_photons(b).surface.at(0);
  EXPECT_EQ(back.path_class, PathClass::Caustic);
  EXPECT_EQ(back.sky_quadrant, 3u);
  // A byte with bits above the quadrant's, or a class 3, is refused.
  for (const char bad : {'\x13', '\x03'}) {
    std::string damaged = b;
    damaged[47] = bad;
    EXPECT_THROW(decode_photons(damaged), std::runtime_error) << int(bad);
  }
}

TEST(ArtifactCodec, CoefficientsRoundTripBitExact) {
  const engine::DaylightCoefficients in = sample_coefficients(13, 146);
  const engine::DaylightCoefficients out = decode_coefficients(encode_coefficients(in));
  EXPECT_EQ(out.sensors, in.sensors);
  EXPECT_EQ(out.sources, in.sources);
  ASSERT_EQ(out.direct.size(), in.direct.size());
  ASSERT_EQ(out.caustic.size(), in.caustic.size());
  ASSERT_EQ(out.global.size(), in.global.size());
  EXPECT_TRUE(same_bits(out.direct.data(), in.direct.data(), in.direct.size() * sizeof(Vec3)));
  EXPECT_TRUE(same_bits(out.caustic.data(), in.caustic.data(), in.caustic.size() * sizeof(Vec3)));
  EXPECT_TRUE(same_bits(out.global.data(), in.global.data(), in.global.size() * sizeof(Vec3)));
  EXPECT_TRUE(out.direct_variance == in.direct_variance);
  EXPECT_TRUE(out.photon_variance == in.photon_variance);
}

TEST(ArtifactCodec, ThePhotonPartOnTheSkyRoundTripsBitExact) {
  engine::DaylightCoefficients in = sample_coefficients(4, 146);
  in.photon_on_sky.irradiance = {{1, 2, 3}, {-0.0, 1e-300, 5}, {7, 8, 9}, {0.25, 0.5, 0.75}};
  in.photon_on_sky.variance = {1e-9, 0, 3, std::numeric_limits<double>::denorm_min()};
  in.photon_on_sky.basis_rows = 2;
  const engine::DaylightCoefficients out = decode_coefficients(encode_coefficients(in));
  ASSERT_EQ(out.photon_on_sky.irradiance.size(), 4u);
  EXPECT_TRUE(same_bits(out.photon_on_sky.irradiance.data(), in.photon_on_sky.irradiance.data(), 4 * sizeof(Vec3)));
  EXPECT_TRUE(same_bits(out.photon_on_sky.variance.data(), in.photon_on_sky.variance.data(), 4 * sizeof(double)));
  EXPECT_EQ(out.photon_on_sky.basis_rows, 2u);
  EXPECT_TRUE(out.caustic == in.caustic);
  // Without it, none comes back.
  EXPECT_TRUE(decode_coefficients(encode_coefficients(sample_coefficients(4, 146))).photon_on_sky.empty());
  // A part of the wrong length is refused when encoding, a flag other than 0 or 1 when decoding.
  engine::DaylightCoefficients short_part = in;
  short_part.photon_on_sky.variance.pop_back();
  EXPECT_THROW(encode_coefficients(short_part), std::invalid_argument);
  std::string bytes = encode_coefficients(in);
  bytes[8 + 24] = 2;  // the u64 after sensors, sources and skies
  EXPECT_THROW(decode_coefficients(bytes), std::runtime_error);
}

TEST(ArtifactCodec, TheSubPatchSharesRoundTripBitExact) {
  engine::DaylightCoefficients in = sample_coefficients(3, 5);
  in.direct_quadrants.resize(3 * 5 * engine::StoredQuadrants);
  for (std::size_t i = 0; i < in.direct_quadrants.size(); ++i) in.direct_quadrants[i] = 0.125f * float(i) - 1e-30f;
  in.direct_quadrants[4] = -0.0f;
  in.direct_quadrants[7] = std::numeric_limits<float>::denorm_min();
  const std::string bytes = encode_coefficients(in);
  const engine::DaylightCoefficients out = decode_coefficients(bytes);
  ASSERT_EQ(out.direct_quadrants.size(), in.direct_quadrants.size());
  EXPECT_TRUE(same_bits(out.direct_quadrants.data(), in.direct_quadrants.data(), in.direct_quadrants.size() * sizeof(float)));
  EXPECT_TRUE(same_bits(out.direct.data(), in.direct.data(), in.direct.size() * sizeof(Vec3)));
  // Without them, none come back, and the artefact is that much shorter.
  const std::string without = encode_coefficients(sample_coefficients(3, 5));
  EXPECT_TRUE(decode_coefficients(without).direct_quadrants.empty());
  EXPECT_EQ(bytes.size(), without.size() + 3 * 5 * engine::StoredQuadrants * 4);
  // The photon part's shares too (flag bit 2), bit exact, beside the direct part's.
  engine::DaylightCoefficients both = in;
  both.photon_quadrants.resize(in.direct_quadrants.size());
  for (std::size_t i = 0; i < both.photon_quadrants.size(); ++i) both.photon_quadrants[i] = -0.5f * float(i) + 1e-3f;
  const std::string with_photon = encode_coefficients(both);
  EXPECT_EQ(with_photon.size(), bytes.size() + 3 * 5 * engine::StoredQuadrants * 4);
  const engine::DaylightCoefficients both_out = decode_coefficients(with_photon);
  ASSERT_EQ(both_out.photon_quadrants.size(), both.photon_quadrants.size());
  EXPECT_TRUE(same_bits(both_out.photon_quadrants.data(), both.photon_quadrants.data(),
                        both.photon_quadrants.size() * sizeof(float)));
  EXPECT_TRUE(same_bits(both_out.direct_quadrants.data(), in.direct_quadrants.data(),
                        in.direct_quadrants.size() * sizeof(float)));
  // Shares of the wrong length are refused when encoding, flags beyond 0-3 or not matching the
  // size when decoding.
  engine::DaylightCoefficients short_part = in;
  short_part.direct_quadrants.pop_back();
  EXPECT_THROW(encode_coefficients(short_part), std::invalid_argument);
  engine::DaylightCoefficients short_photon = both;
  short_photon.photon_quadrants.pop_back();
  EXPECT_THROW(encode_coefficients(short_photon), std::invalid_argument);
  for (const char flags : {'\x04', '\x03'}) {
    std::string damaged = bytes;
    damaged[8 + 40] = flags;  // the u64 after sensors, sources, skies, photon part and its basis rows
    EXPECT_THROW(decode_coefficients(damaged), std::runtime_error) << int(flags);
  }
}

TEST(ArtifactCodec, InconsistentCoefficientsAreRefusedWhenEncoding) {
  engine::DaylightCoefficients c = sample_coefficients(2, 3);
  c.global.pop_back();
  EXPECT_THROW(encode_coefficients(c), std::invalid_argument);
  c = sample_coefficients(2, 3);
  c.photon_variance.clear();  // without its variance a coefficient artefact is incomplete
  EXPECT_THROW(encode_coefficients(c), std::invalid_argument);
}

TEST(ArtifactCodec, MatrixRoundTripsBitExact) {
  for (const int components : {1, 3}) {
    const RadianceMatrix in = sample_matrix(146, 24, components);
    const RadianceMatrix out = decode_matrix(encode_matrix(in));
    EXPECT_EQ(out.rows(), in.rows());
    EXPECT_EQ(out.columns(), in.columns());
    EXPECT_EQ(out.components(), in.components());
    EXPECT_EQ(out.header_lines(), in.header_lines());
    ASSERT_EQ(out.data().size(), in.data().size());
    EXPECT_TRUE(same_bits(out.data().data(), in.data().data(), in.data().size() * sizeof(float)));
  }
  const RadianceMatrix empty = decode_matrix(encode_matrix(RadianceMatrix()));
  EXPECT_EQ(empty.rows(), 0u);
  EXPECT_TRUE(empty.header_lines().empty());
}

// Every strict prefix of a valid encoding must be refused with std::runtime_error, as must
// the encoding with one extra byte.
template <typename Decode>
void expect_every_truncation_throws(const std::string& bytes, Decode decode) {
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_THROW(decode(bytes.substr(0, n)), std::runtime_error) << "length " << n << " of " << bytes.size();
  EXPECT_THROW(decode(bytes + '\0'), std::runtime_error) << "trailing byte";
  EXPECT_NO_THROW(decode(bytes));
}

TEST(ArtifactCodec, EveryTruncationThrows) {
  expect_every_truncation_throws(encode_photons(sample_photons(2, {1, 0}, 2)), decode_photons);
  expect_every_truncation_throws(encode_coefficients(sample_coefficients(2, 3)), decode_coefficients);
  engine::DaylightCoefficients with_shares = sample_coefficients(2, 3);
  with_shares.direct_quadrants.assign(2 * 3 * engine::StoredQuadrants, 0.5f);
  expect_every_truncation_throws(encode_coefficients(with_shares), decode_coefficients);
  expect_every_truncation_throws(encode_matrix(sample_matrix(2, 3, 3)), decode_matrix);
}

TEST(ArtifactCodec, LayoutVersionAndTagAreChecked) {
  std::string photons = encode_photons(sample_photons(2, {1}, 1));
  std::string coefficients = encode_coefficients(sample_coefficients(1, 2));
  std::string matrix = encode_matrix(sample_matrix(1, 2, 3));
  // Another type's payload.
  EXPECT_THROW(decode_photons(coefficients), std::runtime_error);
  EXPECT_THROW(decode_coefficients(matrix), std::runtime_error);
  EXPECT_THROW(decode_matrix(photons), std::runtime_error);
  // The next layout version.
  for (std::string* bytes : {&photons, &coefficients, &matrix}) (*bytes)[4] = static_cast<char>((*bytes)[4] + 1);
  try {
    decode_photons(photons);
    FAIL() << "expected runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("version 6"), std::string::npos) << e.what();
  }
  EXPECT_THROW(decode_coefficients(coefficients), std::runtime_error);
  EXPECT_THROW(decode_matrix(matrix), std::runtime_error);
}

TEST(ArtifactCodec, InvalidPathClassThrows) {
  std::string b = encode_photons(sample_photons(1, {}, 0));
  b[16 + 31] = 3;  // the class byte of the first surface photon
  EXPECT_THROW(decode_photons(b), std::runtime_error);
}

TEST(ArtifactCodec, InvalidCappedFlagThrows) {
  std::string b = encode_photons(sample_photons(0, {}, 1));
  ASSERT_NO_THROW(decode_photons(b));
  b[b.size() - 16] = 2;  // the capped flag, the second-last field of the last tally
  EXPECT_THROW(decode_photons(b), std::runtime_error);
  b[b.size() - 16] = 0;
  b[b.size() - 8] = 2;  // the nothing_stores flag, the last field
  EXPECT_THROW(decode_photons(b), std::runtime_error);
}

TEST(ArtifactCodec, HugeCountsThrowBeforeAllocating) {
  // A damaged count must give runtime_error, not bad_alloc or a multi-gigabyte allocation.
  std::string photons = encode_photons(sample_photons(1, {}, 0));
  photons[8 + 7] = 0x40;  // surface count 2^62 + 1
  EXPECT_THROW(decode_photons(photons), std::runtime_error);

  std::string coefficients = encode_coefficients(sample_coefficients(1, 2));
  coefficients[8 + 7] = 0x40;   // sensors 2^62 + 1: sensors x sources overflows 64 bits
  EXPECT_THROW(decode_coefficients(coefficients), std::runtime_error);

  std::string matrix = encode_matrix(sample_matrix(1, 2, 3));
  matrix[16 + 7] = 0x7f;  // columns ~ 2^63
  EXPECT_THROW(decode_matrix(matrix), std::runtime_error);
  matrix = encode_matrix(sample_matrix(1, 2, 3));
  matrix[28 + 7] = 0x10;  // header line count 2^60 + 3
  EXPECT_THROW(decode_matrix(matrix), std::runtime_error);
}

}  // namespace
}  // namespace dayphoton::study
