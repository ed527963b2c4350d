// The `operation` section (operated shading, LM-83 blinds rule; docs/project-format.md):
// - a valid section loads with its names and locations; absent thresholds take the LM-83
//   defaults (1000 lx, 2 %), equal in the schema and the struct;
// - every error has its exact message at the exact line:column: unknown case names with a
//   hint, `base` when a variant is also called base, open == shaded, sun: spread, no annual
//   results, ranges, unknown keys;
// - projects/blinds loads with its operation (open = raised, shaded = closed).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"
#include "dayphoton/project/project_schema.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

const std::string ProjectsDir = std::string(DAYPHOTON_SOURCE_DIR) + "/projects";
const std::string FakePath = ProjectsDir + "/office/snippet.yaml";

// Lines 1-11: an annual study (weather beside the fake path) with a blinds system and two
// variants. Snippet lines are numbered from 12.
const std::string Base =
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "weather: USA_CA_Oakland.Intl.AP.724930_TMY3.epw\n"
    "materials:\n"
    "  glazing: {type: glass, transmittance: 0.6}\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "geometry: {}\n"
    "variants:\n"
    "  - name: closed\n"
    "    materials: {walls: {type: lambertian, reflectance: 0.4}}\n"
    "  - name: raised\n"
    "    materials: {walls: {type: lambertian, reflectance: 0.3}}\n";

std::vector<std::string> errors_of(const std::string& text) {
  return test::located_errors([&] { load_project_from_string(text, FakePath); });
}

using Errors = std::vector<std::string>;

TEST(Operation, AbsentMeansNone) {
  EXPECT_FALSE(load_project_from_string(Base, FakePath).operation.has_value());
}

TEST(Operation, LoadsNamesLocationsAndLm83Defaults) {
  const Project p = load_project_from_string(Base +
                                                 "operation:\n"
                                                 "  open: raised\n"
                                                 "  shaded: closed\n",
                                             FakePath);
  ASSERT_TRUE(p.operation.has_value());
  const OperationSpec& op = *p.operation;
  EXPECT_EQ(op.open.value, "raised");
  EXPECT_EQ(op.shaded.value, "closed");
  EXPECT_EQ(op.open.location.line, 13);
  EXPECT_EQ(op.open.location.column, 9);
  EXPECT_EQ(op.shaded.location.line, 14);
  EXPECT_EQ(op.direct_sun_threshold_lux, 1000.0);
  EXPECT_EQ(op.sunlit_limit_percent, 2.0);
  // The struct's defaults are the schema's (both LM-83).
  const OperationSpec defaults;
  EXPECT_EQ(defaults.direct_sun_threshold_lux, 1000.0);
  EXPECT_EQ(defaults.sunlit_limit_percent, 2.0);
  EXPECT_EQ(schema_section("operation").find("direct_sun_threshold")->default_value, "1000");
  EXPECT_EQ(schema_section("operation").find("sunlit_limit")->default_value, "2");
}

TEST(Operation, BaseCaseAndExplicitThresholds) {
  const Project p = load_project_from_string(
      Base + "operation: {open: base, shaded: closed, direct_sun_threshold: 900, sunlit_limit: 5}\n", FakePath);
  ASSERT_TRUE(p.operation.has_value());
  EXPECT_EQ(p.operation->open.value, BaseCaseName);
  EXPECT_EQ(p.operation->direct_sun_threshold_lux, 900.0);
  EXPECT_EQ(p.operation->sunlit_limit_percent, 5.0);
}

TEST(Operation, UnknownCaseIsLocatedWithHint) {
  EXPECT_EQ(errors_of(Base +
                      "operation:\n"
                      "  open: raised\n"
                      "  shaded: clossed\n"),
            (Errors{"14:11: unknown case 'clossed' in operation.shaded (a variant name or 'base') (did you mean "
                    "'closed'?)"}));
  EXPECT_EQ(errors_of(Base + "operation: {open: rased, shaded: closed}\n"),
            (Errors{"12:19: unknown case 'rased' in operation.open (a variant name or 'base') (did you mean "
                    "'raised'?)"}));
}

TEST(Operation, SameCaseTwiceIsAnError) {
  EXPECT_EQ(errors_of(Base + "operation: {open: closed, shaded: closed}\n"),
            (Errors{"12:35: operation 'shaded' names the same case as 'open' ('closed'): nothing would be operated"}));
}

TEST(Operation, BaseIsAmbiguousWithAVariantNamedBase) {
  const std::string text = Base +
                           "  - name: base\n"
                           "    materials: {walls: {type: lambertian, reflectance: 0.2}}\n"
                           "operation: {open: base, shaded: closed}\n";
  EXPECT_EQ(errors_of(text), (Errors{"14:19: 'open': 'base' is ambiguous: a variant is named 'base' too (rename "
                                     "the variant)"}));
}

TEST(Operation, NeedsSunBinsAndAnnualResults) {
  EXPECT_EQ(errors_of(Base +
                      "simulation: {sun: spread}\n"
                      "operation: {open: raised, shaded: closed}\n"),
            (Errors{"13:12: operation needs the direct sun of every hour: set simulation.sun to 'bins' (with "
                    "'spread' the sun is smeared into sky patches)"}));
  EXPECT_EQ(errors_of(Base +
                      "outputs: {annual_illuminance: false, metrics: false}\n"
                      "operation: {open: raised, shaded: closed}\n"),
            (Errors{"13:12: operation needs annual results: outputs.annual_illuminance or outputs.metrics must "
                    "be true"}));
}

TEST(Operation, RangesMissingAndUnknownKeys) {
  const Errors e = errors_of(Base + "operation: {shaded: closed, sunlit_limit: 120, threshold: 3}\n");
  ASSERT_EQ(e.size(), 3u) << ::testing::PrintToString(e);
  EXPECT_NE(e[0].find("12:12: missing required key 'open'"), std::string::npos) << e[0];
  EXPECT_NE(e[1].find("12:43: "), std::string::npos) << e[1];
  EXPECT_NE(e[1].find("sunlit_limit"), std::string::npos) << e[1];
  EXPECT_NE(e[2].find("unknown key 'threshold'"), std::string::npos) << e[2];
}

TEST(Operation, BlindsExampleOperatesRaisedAndClosed) {
  const Project p = load_project(ProjectsDir + "/blinds/project.yaml");
  ASSERT_TRUE(p.operation.has_value());
  EXPECT_EQ(p.operation->open.value, "raised");
  EXPECT_EQ(p.operation->shaded.value, "closed");
  EXPECT_EQ(p.operation->direct_sun_threshold_lux, 1000.0);
  EXPECT_EQ(p.operation->sunlit_limit_percent, 2.0);
}

}  // namespace
}  // namespace dayphoton::project
