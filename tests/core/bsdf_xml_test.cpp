// The BSDF XML reader (core/bsdf_xml.h): a Klems BSDF written by the test helper reads back
// exactly (both data layouts), and every kind of bad file gives an error located at
// file:line:column of the element or value at fault.
#include "dayphoton/core/bsdf_xml.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>

#include "../bsdf_xml_writer.h"
#include "dayphoton/core/diagnostics.h"

using namespace dayphoton;

namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  // One file per test: CTest runs the tests of this suite in parallel processes.
  const std::string path = testing::TempDir() + testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A BSDF whose every value is distinct, so a transposed or shifted read cannot pass.
KlemsBsdfData distinct_values() {
  return test::klems_from(
      KlemsBasis::full(), [](int i, int o) { return 0.001 * (1 + i) + 1e-6 * o; },
      [](int i, int o) { return 0.0005 * (1 + o) + 1e-6 * i; }, [](int i, int o) { return 1e-4 * (i + 2 * o); },
      [](int i, int o) { return 2e-4 * ((i * 7 + o) % 13); });
}

std::string read_error(const std::string& text, const std::string& name = "bad.xml") {
  const std::string path = write_temp(name, text);
  try {
    read_bsdf_xml(path, name, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Line (1-based) and column of the first occurrence of `needle` in `text`.
std::string where(const std::string& text, const std::string& needle, std::size_t from = 0) {
  const std::size_t at = text.find(needle, from);
  if (at == std::string::npos) return "?";
  const std::size_t line_start = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return std::to_string(line) + ":" + std::to_string(at - line_start + 1);
}

std::string replace_first(std::string text, const std::string& from, const std::string& to, std::size_t start = 0) {
  const std::size_t at = text.find(from, start);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace

TEST(BsdfXml, ReadsBackWhatWasWritten) {
  const KlemsBsdfData d = distinct_values();
  const std::string path = write_temp("roundtrip.xml", test::bsdf_xml(d));
  const std::shared_ptr<const KlemsBsdfData> r = read_bsdf_xml(path, "roundtrip.xml", {});
  ASSERT_EQ(r->basis.size(), 145);
  EXPECT_TRUE(r->basis == KlemsBasis::full());
  EXPECT_EQ(r->file, "roundtrip.xml");
  for (std::size_t k = 0; k < d.transmission_front.size(); ++k) {
    ASSERT_DOUBLE_EQ(r->transmission_front[k], d.transmission_front[k]) << k;
    ASSERT_DOUBLE_EQ(r->transmission_back[k], d.transmission_back[k]) << k;
    ASSERT_DOUBLE_EQ(r->reflection_front[k], d.reflection_front[k]) << k;
    ASSERT_DOUBLE_EQ(r->reflection_back[k], d.reflection_back[k]) << k;
  }
}

TEST(BsdfXml, RowsLayoutIsTransposed) {
  // Under "Rows" each line is an incoming patch: the same text read that way is the transpose.
  const KlemsBsdfData d = distinct_values();
  const std::string text = replace_first(test::bsdf_xml(d), ">Columns<", ">Rows<");
  const std::shared_ptr<const KlemsBsdfData> r = read_bsdf_xml(write_temp("rows.xml", text), "rows.xml", {});
  for (int i = 0; i < 145; i += 7)
    for (int o = 0; o < 145; o += 5) EXPECT_DOUBLE_EQ(r->value(r->transmission_front, i, o), d.value(d.transmission_front, o, i));
}

TEST(BsdfXml, BasisComesFromTheFile) {
  // A three-ring basis of the file's own (RADIANCE's "LBNL/Klems Quarter" has other bounds).
  const KlemsBasis basis({{0, deg_to_rad(20), 1}, {deg_to_rad(20), deg_to_rad(60), 4}, {deg_to_rad(60), deg_to_rad(90), 6}});
  const KlemsBsdfData d = test::klems_from(
      basis, [](int i, int o) { return i == o ? 0.1 : 0.0; }, [](int, int) { return 0.05; },
      [](int, int) { return 0.0; }, [](int, int) { return 0.0; });
  const auto r = read_bsdf_xml(write_temp("custom.xml", test::bsdf_xml(d, "Custom")), "custom.xml", {});
  EXPECT_EQ(r->basis.size(), 11);
  EXPECT_TRUE(r->basis == basis);
  EXPECT_NEAR(r->hemispherical(r->transmission_back, 3), 0.05 * Pi, 1e-12);
}

TEST(BsdfXml, BadValuesAreLocated) {
  const std::string good = test::bsdf_xml(distinct_values());
  const std::size_t data = good.find("<ScatteringData>");
  const std::size_t second_line = good.find('\n', good.find('\n', data) + 1) + 1;  // outgoing patch 2
  // The 3rd value of the 2nd line of the first block.
  std::size_t at = second_line;
  for (int k = 0; k < 2; ++k) at = good.find(", ", at) + 2;
  const std::string token = good.substr(at, good.find(',', at) - at);
  for (const std::string& bad : {std::string("-0.5"), std::string("nan"), std::string("0.3x"), std::string("inf")}) {
    std::string text = good;
    text.replace(at, token.size(), bad);
    const std::string e = read_error(text);
    EXPECT_NE(e.find("bad.xml:" + where(text, bad, at - 1) + ": error: BSDF value"), std::string::npos) << bad << "\n" << e;
  }
}

TEST(BsdfXml, WrongValueCountIsLocatedAtScatteringData) {
  const std::string good = test::bsdf_xml(distinct_values());
  const std::size_t data = good.find("<ScatteringData>");
  std::string text = good;
  text.insert(good.find('\n', data) + 1, "0.1, ");
  const std::string e = read_error(text);
  EXPECT_NE(e.find("bad.xml:" + where(text, "<ScatteringData>") + ": error: <ScatteringData> holds 21026 values, not 21025"),
            std::string::npos)
      << e;
}

TEST(BsdfXml, TooMuchLightIsLocatedAtTheSidesTransmissionBlock) {
  // Back side: a diffuse transmission of 0.8 and a diffuse reflection of 0.25: T + R = 1.05.
  const KlemsBsdfData d = test::klems_from(
      KlemsBasis::full(), [](int, int) { return 0.5 / Pi; }, [](int, int) { return 0.8 / Pi; },
      [](int, int) { return 0.2 / Pi; }, [](int, int) { return 0.25 / Pi; });
  const std::string text = test::bsdf_xml(d);
  const std::string e = read_error(text);
  const std::string back_data = where(text, "<ScatteringData>", text.find("Transmission Back"));
  EXPECT_NE(e.find("bad.xml:" + back_data +
                   ": error: back incidence, incoming patch 1 (theta 0, phi 0 degrees): hemispherical T + R = 1.05 "
                   "(T 0.8, R 0.25) exceeds 1 + 0.01; 144 more incoming patches exceed it too"),
            std::string::npos)
      << e;
  EXPECT_EQ(e.find("front incidence"), std::string::npos) << e;  // 0.5 + 0.2 is fine
}

TEST(BsdfXml, StructuralErrorsAreLocated) {
  const std::string good = test::bsdf_xml(distinct_values());
  {
    const std::string text = replace_first(good, ">Columns<", ">TensorTree5<");
    EXPECT_NE(read_error(text).find("bad.xml:" + where(text, "<IncidentDataStructure>") +
                                    ": error: <IncidentDataStructure> 'TensorTree5' is not 'Columns', 'Rows', "
                                    "'TensorTree3' or 'TensorTree4'"),
              std::string::npos)
        << read_error(text);
  }
  {
    const std::string text = replace_first(good, "Reflection Back", "Reflection Sideways");
    const std::string e = read_error(text);
    EXPECT_NE(e.find("error: unknown <WavelengthDataDirection> 'Reflection Sideways'"), std::string::npos) << e;
    EXPECT_NE(e.find("bad.xml:" + where(text, "<WavelengthData>") +
                     ": error: the Visible data has no 'Reflection Back' block"),
              std::string::npos)
        << e;
  }
  {
    const std::string text = replace_first(good, ">Visible<", ">Solar<");
    EXPECT_NE(read_error(text).find("bad.xml:" + where(text, "<Layer>") + ": error: <Layer> has no Visible <WavelengthData>"),
              std::string::npos);
  }
  {
    const std::string text = replace_first(good, "<UpperTheta>15</UpperTheta>", "<UpperTheta>16</UpperTheta>");
    EXPECT_NE(read_error(text).find("bad.xml:" + where(text, "<AngleBasis>") +
                                    ": error: angle basis: ring 3 starts at theta 15 degrees"),
              std::string::npos)
        << read_error(text);
  }
  {
    const std::string text = replace_first(good, "<ColumnAngleBasis>LBNL/Klems Full", "<ColumnAngleBasis>LBNL/Klems Half");
    EXPECT_NE(read_error(text).find("bad.xml:" + where(text, "<ColumnAngleBasis>") +
                                    ": error: undefined angle basis 'LBNL/Klems Half'"),
              std::string::npos);
  }
  {
    // Not well-formed: the parser's offset becomes line:column.
    const std::string text = replace_first(good, "</Optical>", "</Optic>");
    const std::string e = read_error(text);
    EXPECT_TRUE(std::regex_search(e, std::regex("^bad\\.xml:[0-9]+:[0-9]+: error: not well-formed XML"))) << e;
  }
  EXPECT_NE(read_error("<html/>").find("bad.xml:1:1: error: the root element is <html>"), std::string::npos);
}

TEST(BsdfXml, MissingFileIsLocatedWhereItIsNamed) {
  SourceLocation from{"project.yaml", 12, 11};
  try {
    read_bsdf_xml(testing::TempDir() + "no_such_bsdf.xml", "no_such_bsdf.xml", from);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("project.yaml:12:11: error:"), std::string::npos) << e.what();
  }
}
