// RADIANCE matrix format: round trips in every format, foreign byte order, located errors,
// and reading RADIANCE's own gendaymtx output from tests/data/radiance.
#include "dayphoton/core/radiance_matrix.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
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
            "m.mtx:5: truncated matrix: 3 of 6 values present");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=1\n\n1 x 1\n"), "m.mtx:5: not a number: 'x'");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=1\n\n1 1 1 1\n"),
            "m.mtx:5: more values than NROWS x NCOLS x NCOMP");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=1\nNCOLS=1\nFORMAT=float\n\nab"), "m.mtx:5: truncated binary matrix data");
  EXPECT_EQ(read_error("#?RADIANCE\nNROWS=4294967296\nNCOLS=4294967296\n\n"),
            "m.mtx:4: NROWS x NCOLS x NCOMP is implausibly large (more than 2^31 values)");
  EXPECT_EQ(read_error("#?RADIANCE\nBigEndian=2\n\n"), "m.mtx:2: BigEndian= must be 0 or 1");
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
