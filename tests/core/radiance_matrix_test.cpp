// RADIANCE matrix format: round trips in every format, foreign byte order, located errors,
// and reading RADIANCE's own gendaymtx output from tests/data/radiance.
#include "dayphoton/core/radiance_matrix.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "../reference_data.h"
#include "dayphoton/core/diagnostics.h"

using namespace dayphoton;

namespace {

RadianceMatrix sample_matrix() {
  RadianceMatrix m(3, 4, 3);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 4; ++c)
      for (int k = 0; k < 3; ++k) m.at(r, c, k) = static_cast<float>(r * 100 + c * 10 + k) * 0.37f + 1e-3f;
  m.header_lines().push_back("dayphoton test");
  return m;
}

std::string read_error(const std::string& text) {
  std::istringstream in(text);
  try {
    RadianceMatrix::read(in, "m.mtx");
  } catch (const InputError& e) {
    return e.diagnostics().front().location.to_string() + ": " + e.diagnostics().front().message;
  }
  return "no error";
}

}  // namespace

TEST(RadianceMatrix, RoundTripsInEveryFormat) {
  const RadianceMatrix m = sample_matrix();
  for (MatrixFormat f : {MatrixFormat::Ascii, MatrixFormat::Float, MatrixFormat::Double}) {
    std::stringstream s;
    m.write(s, f);
    const RadianceMatrix back = RadianceMatrix::read(s, "round-trip");
    ASSERT_EQ(back.rows(), 3u);
    ASSERT_EQ(back.columns(), 4u);
    ASSERT_EQ(back.components(), 3);
    for (std::size_t i = 0; i < m.data().size(); ++i)
      EXPECT_FLOAT_EQ(back.data()[i], m.data()[i]) << "element " << i;
    ASSERT_EQ(back.header_lines().size(), 1u);
    EXPECT_EQ(back.header_lines()[0], "dayphoton test");
  }
}

TEST(RadianceMatrix, ReadsForeignByteOrder) {
  // A big-endian float file written by hand: NROWS=1 NCOLS=1 NCOMP=3 values 1, 2, 0.5.
  std::string text = "#?RADIANCE\nNROWS=1\nNCOLS=1\nNCOMP=3\nBigEndian=1\nFORMAT=float\n\n";
  const unsigned char be[12] = {0x3f, 0x80, 0, 0, 0x40, 0x00, 0, 0, 0x3f, 0x00, 0, 0};
  text.append(reinterpret_cast<const char*>(be), 12);
  std::istringstream in(text);
  const RadianceMatrix m = RadianceMatrix::read(in, "be.mtx");
  EXPECT_EQ(m.at(0, 0, 0), 1.0f);
  EXPECT_EQ(m.at(0, 0, 1), 2.0f);
  EXPECT_EQ(m.at(0, 0, 2), 0.5f);
}

TEST(RadianceMatrix, FormatWithTrailingPaddingIsAccepted) {
  std::istringstream in("#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=1\nFORMAT=ascii   \n\n1\n2\n");
  const RadianceMatrix m = RadianceMatrix::read(in, "pad.mtx");
  EXPECT_EQ(m.at(0, 1, 0), 2.0f);
}

TEST(RadianceMatrix, BadInputGivesLocatedErrors) {
  EXPECT_EQ(read_error(""), "m.mtx:1: empty file: expected a RADIANCE matrix header");
  EXPECT_EQ(read_error("hello\n"), "m.mtx:1: not a RADIANCE matrix: the first line must be '#?RADIANCE'");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=x\n\n"), "m.mtx:2: expected a non-negative integer after NROWS=");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=1\nFORMAT=rgbe\n\n"),
            "m.mtx:4: unsupported matrix FORMAT 'rgbe' (ascii, float or double)");
  EXPECT_EQ(read_error("#?RADIANCE\nNCOLS=1\n\n1 1 1\n"), "m.mtx:3: the header lacks NROWS= or NCOLS=");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=1\n"), "m.mtx:3: the header does not end with an empty line");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=2\n\n1 1 1\n"),
            "m.mtx:6: truncated matrix: 3 of 6 values present");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=1\n\n1 x 1\n"),
            "m.mtx:5:3: not a number: 'x' in row 0, column 0, component 1 (counted from 0)");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=1\n\n1 1 1 1\n"),
            "m.mtx:5:7: data after the NROWS x NCOLS x NCOMP = 1 x 1 x 3 = 3 values");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=1\nFORMAT=float\n\nab"),
            "m.mtx: truncated binary matrix data: 0 of 3 values present");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=4294967296\nNCOLS=4294967296\n\n"),
            "m.mtx:4: NROWS x NCOLS x NCOMP = 4294967296 x 4294967296 x 3 values is more than the limit of "
            "268435456 (raise it with --max-matrix-values if you mean it)");
  EXPECT_EQ(read_error("#?RADIANCE\nBigEndian=2\n\n"), "m.mtx:2: BigEndian= must be 0 or 1");
}

TEST(RadianceMatrix, NonFiniteAndOutOfRangeAsciiValuesAreLocated) {
  const std::string header = "#?RADIANCE\nNROWS=2\nNCOLS=2\nNCOMP=3\nFORMAT=ascii\n\n";
  const std::string good_row = "1 2 3\n4 5 6\n\n";
  EXPECT_EQ(read_error(header + good_row + "1 nan 3\n4 5 6\n"),
            "m.mtx:10:3: NaN in row 1, column 0, component 1 (counted from 0)");
  EXPECT_EQ(read_error(header + good_row + "1 2 3\n4 5 -inf\n"),
            "m.mtx:11:5: an infinite value in row 1, column 1, component 2 (counted from 0)");
  EXPECT_EQ(read_error(header + "1e39 2 3\n"),
            "m.mtx:7:1: value 1e+39 beyond the range of a float (3.4e38) in row 0, column 0, component 0 (counted from 0)");
  EXPECT_EQ(read_error(header + good_row + "1 2 3\n4 5 6\n\n7\n"),
            "m.mtx:13:1: data after the NROWS x NCOLS x NCOMP = 2 x 2 x 3 = 12 values");
  // The echo under the error is the offending line.
  std::istringstream in(header + "1 2 3 4 5 nan\n");
  try {
    RadianceMatrix::read(in, "m.mtx");
    FAIL() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().front().source_line, "1 2 3 4 5 nan");
  }
  // Negative values only where the caller says the matrix cannot hold them.
  MatrixReadOptions non_negative;
  non_negative.non_negative = true;
  std::istringstream negative(header + "1 2 3\n4 -5 6\n1 2 3\n4 5 6\n");
  try {
    RadianceMatrix::read(negative, "m.mtx", non_negative);
    FAIL() << "negative value accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().front().location.to_string() + ": " + e.diagnostics().front().message,
              "m.mtx:8:3: negative value -5 in row 0, column 1, component 1 (counted from 0)");
  }
  std::istringstream allowed(header + "1 2 3\n4 -5 6\n1 2 3\n4 5 6\n");
  EXPECT_EQ(RadianceMatrix::read(allowed, "m.mtx").at(0, 1, 1), -5.0f);
}

TEST(RadianceMatrix, BinaryValuesAreCheckedWithTheirByteOffset) {
  const std::string header = "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=3\nBigEndian=0\nFORMAT=float\n\n";
  auto with = [&](std::vector<float> values) {
    std::string text = header;
    text.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
    return text;
  };
  ASSERT_EQ(header.size(), 61u);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(read_error(with({1, 2, 3, 4, nan, 6})), "m.mtx: NaN at byte 77, in row 0, column 1, component 1 (counted from 0)");
  EXPECT_EQ(read_error(with({1, 2, 3, 4, 5, 6, 7})), "m.mtx: data after the NROWS x NCOLS x NCOMP = 6 values, at byte 85");
}

TEST(RadianceMatrix, ByteSwappedBinaryDataAreRejected) {
  // A little-endian float matrix of sky-like radiances whose header claims big-endian data
  // (and the same values written big-endian under a header claiming little-endian).
  const std::vector<float> values = {0.0f, 0.0f, 0.0f, 1.0f, 25.3f, 3.14159f};
  for (const bool header_big : {true, false}) {
    std::string text = std::string("#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=3\nBigEndian=") + (header_big ? "1" : "0") +
                       "\nFORMAT=float\n\n";
    for (float v : values) {
      unsigned char b[4];
      std::memcpy(b, &v, 4);  // this machine's order (little-endian on every CI host)
      if (!header_big) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
      text.append(reinterpret_cast<const char*>(b), 4);
    }
    // 1.0 read in the wrong order is 4.6e-41, a subnormal.
    EXPECT_EQ(read_error(text), "m.mtx: subnormal value 4.6006e-41 at byte 73, in row 0, column 1, component 0 "
                                "(counted from 0); in the other byte order it reads 1, so the data look byte-swapped "
                                "(the header says BigEndian=" + std::string(header_big ? "1" : "0") + ")")
        << header_big;
  }
  // 3.14159 read in the wrong order is negative: caught where negatives are errors.
  std::string text = "#?RADIANCE\nNROWS=1\nNCOLS=1\nNCOMP=1\nBigEndian=1\nFORMAT=float\n\n";
  const float pi = 3.14159f;
  text.append(reinterpret_cast<const char*>(&pi), 4);
  MatrixReadOptions non_negative;
  non_negative.non_negative = true;
  std::istringstream in(text);
  try {
    RadianceMatrix::read(in, "m.mtx", non_negative);
    FAIL() << "byte-swapped value accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.diagnostics().front().message.find("in the other byte order it reads 3.14159, so the data look "
                                                   "byte-swapped (the header says BigEndian=1)"),
              std::string::npos)
        << e.what();
  }
}

TEST(RadianceMatrix, HeaderSizeIsCheckedAgainstTheFileBeforeAllocating) {
  // A 7 KB file claiming NROWS=4900000: rejected from the header and the file size alone
  // (the old reader allocated 8.4 GB before it found the data truncated).
  const std::string path = testing::TempDir() + "radiance_matrix_claims_too_much.mtx";
  {
    std::ofstream out(path, std::ios::binary);
    out << "#?RADIANCE\nNROWS=4900000\nNCOLS=146\nNCOMP=3\nFORMAT=ascii\n\n";
    for (int i = 0; i < 1000; ++i) out << "0.1 0.2 0.3\n";
  }
  MatrixReadOptions unlimited;
  unlimited.max_values = std::uint64_t(1) << 40;  // only the size check stands in the way
  try {
    RadianceMatrix::read_file(path, unlimited);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().front().location.to_string() + ": " + e.diagnostics().front().message,
              path + ":6: truncated matrix: NROWS x NCOLS x NCOMP = 4900000 x 146 x 3 = 2146200000 ascii values need "
                     "at least 4292399999 bytes, but the file holds 12000 bytes after its header");
  }
  // Binary: the size must match exactly, in both directions.
  const RadianceMatrix m = sample_matrix();
  for (const long extra : {-1L, 1L}) {
    std::stringstream s;
    m.write(s, MatrixFormat::Float);
    std::string bytes = s.str();
    if (extra < 0) bytes.pop_back(); else bytes.push_back('x');
    std::ofstream(path, std::ios::binary) << bytes;
    try {
      RadianceMatrix::read_file(path);
      FAIL() << "accepted with " << extra << " bytes";
    } catch (const InputError& e) {
      EXPECT_NE(e.diagnostics().front().message.find(extra < 0 ? "truncated binary matrix data: NROWS x NCOLS x NCOMP = 3 x 4 x 3 values take 144 bytes, but the file holds 143"
                                                                : "data after the NROWS x NCOLS x NCOMP = 3 x 4 x 3 values: they take 144 bytes, but the file holds 145"),
                std::string::npos)
          << e.what();
    }
  }
  std::filesystem::remove(path);
}

TEST(RadianceMatrix, StreamsOfUnknownSizeGrowWithTheirData) {
  // Without a known size, a header claiming 10^8 values must not reserve them up front: the
  // truncation is found after reading the few values present.
  std::istringstream in("#?RADIANCE\nNROWS=100000000\nNCOLS=1\nNCOMP=1\n\n1 2 3\n");
  try {
    RadianceMatrix::read(in, "m.mtx");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().front().message, "truncated matrix: 3 of 100000000 values present");
  }
}

TEST(RadianceMatrix, SubnormalFloatsAreWrittenAsZero) {
  RadianceMatrix m(1, 1, 3);
  m.at(0, 0, 0) = 1e-40f;  // subnormal
  m.at(0, 0, 1) = 2.0f;
  std::stringstream s;
  m.write(s, MatrixFormat::Float);
  const RadianceMatrix back = RadianceMatrix::read(s, "sub.mtx");
  EXPECT_EQ(back.at(0, 0, 0), 0.0f);
  EXPECT_EQ(back.at(0, 0, 1), 2.0f);
}

TEST(RadianceMatrix, ReadsGendaymtxOutput) {
  const std::string path = std::string(DAYPHOTON_TEST_DATA_DIR) + "/radiance/oakland_sky_m1.mtx.gz";
  ASSERT_TRUE(std::filesystem::exists(path)) << "reference data not found: " << path;
  const RadianceMatrix m = test::read_gzip_matrix(path);
  EXPECT_EQ(m.rows(), 146u);
  EXPECT_EQ(m.columns(), 8760u);
  EXPECT_EQ(m.components(), 3);
  // The first data lines of the file (ground row, hours 1..12 of January 1st).
  EXPECT_FLOAT_EQ(m.at(0, 6, 0), 0.0f);
  EXPECT_FLOAT_EQ(m.at(0, 7, 0), 0.067f);
  EXPECT_FLOAT_EQ(m.at(0, 8, 1), 4.3f);
  EXPECT_FLOAT_EQ(m.at(0, 11, 2), 17.2f);
  ASSERT_FALSE(m.header_lines().empty());
  EXPECT_EQ(m.header_lines()[0], "gendaymtx -m 1 oakland.wea");
}
