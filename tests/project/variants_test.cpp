// Study variants and results settings of the project file (issue 5 items 1-2;
// project/src/load_project.cpp, project/src/apply_variant.cpp, docs/project-format.md):
// - a project with variants and a `metrics` section, written from known values, loads back
//   with exactly those values and the locations of the definitions;
// - every error about variants and metrics settings has its exact message at the exact
//   line:column (ranges, relations between keys, names, references with "did you mean");
// - absent settings take the defaults of the issue (LM-83 / UDI conventions), and the schema
//   defaults, the struct defaults and those numbers agree;
// - apply_variant replaces exactly the named materials, in place, and nothing else: the
//   variant's scene has the same surfaces with the same material indices;
// - projects/office_variants loads and builds a scene per variant; its truncations never
//   crash the loader.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/path_name.h"
#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

const std::string ProjectsDir = std::string(DAYPHOTON_SOURCE_DIR) + "/projects";
const std::string FakePath = ProjectsDir + "/office/snippet.yaml";

// Lines 1-6 of every snippet: a valid site, a daylight-factor-only study (no weather needed),
// two materials and no geometry. Snippet lines are numbered from 7.
const std::string Base =
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "outputs: {annual_illuminance: false, metrics: false}\n"
    "materials:\n"
    "  glazing: {type: glass, transmittance: 0.6}\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "geometry: {}\n";

/// " is not a portable folder name: <problem> (<the rule>)".
std::string name_rule(const std::string& problem) {
  return " is not a portable folder name: " + problem +
         " (1 to 64 of A-Z a-z 0-9 _ - ., not starting with '.' or '-', not ending with '.', not a "
         "device name such as 'nul')";
}

/// "line:col: message" for each diagnostic, or nothing if the text loads.
std::vector<std::string> errors_of(const std::string& text) {
  return test::located_errors([&] { load_project_from_string(text, FakePath); });
}

void expect_same_material(const MaterialSpec& a, const MaterialSpec& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.reflectance, b.reflectance);
  EXPECT_EQ(a.specularity, b.specularity);
  EXPECT_EQ(a.roughness, b.roughness);
  EXPECT_EQ(a.transmittance, b.transmittance);
  EXPECT_EQ(a.refractive_index, b.refractive_index);
  EXPECT_EQ(a.transmissivity, b.transmissivity);
  EXPECT_EQ(a.transmitted_specular, b.transmitted_specular);
  EXPECT_EQ(a.location.file, b.location.file);
  EXPECT_EQ(a.location.line, b.location.line);
  EXPECT_EQ(a.location.column, b.location.column);
}

void expect_settings(const MetricsSettings& m, const std::vector<double>& df, double da,
                     double start, double end, double low, double up1, double up2, double sda,
                     double ase, double ase_h) {
  EXPECT_EQ(m.daylight_factor_thresholds_percent, df);
  EXPECT_EQ(m.da_threshold_lux, da);
  EXPECT_EQ(m.occupancy_start_h, start);
  EXPECT_EQ(m.occupancy_end_h, end);
  EXPECT_EQ(m.udi_lower_lux, low);
  EXPECT_EQ(m.udi_upper_original_lux, up1);
  EXPECT_EQ(m.udi_upper_revised_lux, up2);
  EXPECT_EQ(m.sda_time_fraction, sda);
  EXPECT_EQ(m.ase_threshold_lux, ase);
  EXPECT_EQ(m.ase_hours, ase_h);
}

TEST(ProjectVariants, VariantsAndSettingsLoadBackAsWritten) {
  const std::string text = Base +
      "variants:\n"                                                               // 7
      "  - name: solar_control\n"                                                 // 8
      "    materials:\n"                                                          // 9
      "      glazing: {type: glass, transmittance: [0.35, 0.4, 0.45], refractive_index: 1.6}\n"
      "  - name: Blinds.v2-down\n"                                                // 11
      "    materials:\n"                                                          // 12
      "      glazing:\n"                                                          // 13
      "        type: translucent\n"
      "        reflectance: 0.55\n"
      "        specularity: 0.01\n"
      "        roughness: 0.05\n"
      "        transmissivity: 0.25\n"
      "        transmitted_specular: 0.2\n"
      "      walls: {type: metal, reflectance: 0.8, specularity: 0.9}\n"          // 20
      "metrics:\n"                                                                // 21
      "  daylight_factor_thresholds: [5, 0.5, 100]\n"
      "  da_threshold: 250\n"
      "  occupancy_start: 7.5\n"
      "  occupancy_end: 24\n"
      "  udi_lower: 50\n"
      "  udi_upper_original: 1500\n"
      "  udi_upper_revised: 2500\n"
      "  sda_time_fraction: 0.75\n"
      "  ase_threshold: 1200\n"
      "  ase_hours: 0\n";
  const Project p = load_project_from_string(text, FakePath);

  ASSERT_EQ(p.variants.size(), 2u);
  const VariantSpec& a = p.variants[0];
  EXPECT_EQ(a.name, "solar_control");
  EXPECT_EQ(a.location.line, 8);
  EXPECT_EQ(a.location.column, 5);
  ASSERT_EQ(a.materials.size(), 1u);
  EXPECT_EQ(a.materials[0].name, "glazing");
  EXPECT_EQ(a.materials[0].type, MaterialType::Glass);
  EXPECT_EQ(a.materials[0].transmittance, Vec3(0.35, 0.4, 0.45));
  EXPECT_EQ(a.materials[0].refractive_index, 1.6);
  // The definition's location is in the variant, so later errors point there.
  EXPECT_EQ(a.materials[0].location.file, FakePath);
  EXPECT_EQ(a.materials[0].location.line, 10);
  EXPECT_EQ(a.materials[0].location.column, 7);

  const VariantSpec& b = p.variants[1];
  EXPECT_EQ(b.name, "Blinds.v2-down");
  ASSERT_EQ(b.materials.size(), 2u);
  EXPECT_EQ(b.materials[0].name, "glazing");
  EXPECT_EQ(b.materials[0].type, MaterialType::Translucent);
  EXPECT_EQ(b.materials[0].reflectance, Vec3(0.55, 0.55, 0.55));
  EXPECT_EQ(b.materials[0].specularity, 0.01);
  EXPECT_EQ(b.materials[0].roughness, 0.05);
  EXPECT_EQ(b.materials[0].transmissivity, 0.25);
  EXPECT_EQ(b.materials[0].transmitted_specular, 0.2);
  EXPECT_EQ(b.materials[0].location.line, 13);
  EXPECT_EQ(b.materials[1].name, "walls");
  EXPECT_EQ(b.materials[1].type, MaterialType::Metal);
  EXPECT_EQ(b.materials[1].reflectance, Vec3(0.8, 0.8, 0.8));
  EXPECT_EQ(b.materials[1].specularity, 0.9);
  EXPECT_EQ(b.materials[1].location.line, 20);

  // Thresholds keep the order written; every other value as written.
  expect_settings(p.metrics, {5, 0.5, 100}, 250, 7.5, 24, 50, 1500, 2500, 0.75, 1200, 0);
  EXPECT_EQ(p.metrics.location.line, 22);

  // The base materials are untouched by the variants.
  ASSERT_EQ(p.materials.size(), 2u);
  EXPECT_EQ(p.materials[0].transmittance, Vec3(0.6, 0.6, 0.6));
  EXPECT_EQ(p.materials[1].type, MaterialType::Lambertian);
}

TEST(ProjectVariants, DefaultsWhenAbsent) {
  // The numbers of issue 5 and LM-83, written here independently of the schema and struct.
  const std::vector<double> df = {2};
  const Project absent = load_project_from_string(Base, FakePath);
  EXPECT_TRUE(absent.variants.empty());
  expect_settings(absent.metrics, df, 300, 8, 18, 100, 2000, 3000, 0.5, 1000, 250);
  const Project empty = load_project_from_string(Base + "metrics: {}\nvariants: []\n", FakePath);
  EXPECT_TRUE(empty.variants.empty());
  expect_settings(empty.metrics, df, 300, 8, 18, 100, 2000, 3000, 0.5, 1000, 250);
  expect_settings(MetricsSettings{}, df, 300, 8, 18, 100, 2000, 3000, 0.5, 1000, 250);
  // One key given: the others keep their defaults.
  const Project one = load_project_from_string(Base + "metrics: {occupancy_end: 17}\n", FakePath);
  expect_settings(one.metrics, df, 300, 8, 17, 100, 2000, 3000, 0.5, 1000, 250);
}

TEST(ProjectVariants, BoundaryValuesAreAccepted) {
  // Inclusive ends of every range and of the relations (da on either end of the UDI band).
  const std::vector<std::string> good = {
      "metrics: {occupancy_start: 0, occupancy_end: 24, sda_time_fraction: 1, ase_hours: 0}\n",
      "metrics: {ase_hours: 8784, daylight_factor_thresholds: [100, 0.001]}\n",
      "metrics: {da_threshold: 100}\n",
      "metrics: {da_threshold: 3000}\n",
      "metrics: {occupancy_start: 23.5, occupancy_end: 24}\n",
  };
  for (const auto& snippet : good) {
    SCOPED_TRACE(snippet);
    EXPECT_EQ(errors_of(Base + snippet), std::vector<std::string>{});
  }
}

struct BadCase {
  const char* name;
  std::string snippet;                // appended to Base (first line is line 7)
  std::vector<std::string> expected;  // "line:col: message", in order
};

std::vector<BadCase> variant_cases() {
  return {
      {"unknown_material_with_hint",
       "variants:\n"
       "  - name: low_e\n"
       "    materials:\n"
       "      glazzing: {type: glass, transmittance: 0.4}\n",
       {"10:7: unknown material 'glazzing' in variant 'low_e' (did you mean 'glazing'?)"}},
      {"unknown_material_without_hint",
       "variants:\n"
       "  - name: blinds\n"
       "    materials:\n"
       "      roller_blind: {type: translucent, reflectance: 0.5, transmissivity: 0.2}\n",
       {"10:7: unknown material 'roller_blind' in variant 'blinds'"}},
      {"duplicate_variant_names",
       "variants:\n"
       "  - {name: a, materials: {glazing: {type: glass, transmittance: 0.4}}}\n"
       "  - {name: a, materials: {walls: {type: lambertian, reflectance: 0.3}}}\n",
       {"9:12: duplicate variant name 'a' (first defined at line 8)"}},
      {"names_that_are_not_folder_names",
       "variants:\n"
       "  - {name: low e, materials: {walls: {type: lambertian, reflectance: 0.3}}}\n"
       "  - {name: ../up, materials: {walls: {type: lambertian, reflectance: 0.3}}}\n"
       "  - {name: .hidden, materials: {walls: {type: lambertian, reflectance: 0.3}}}\n"
       "  - {name: -x, materials: {walls: {type: lambertian, reflectance: 0.3}}}\n"
       "  - {name: x., materials: {walls: {type: lambertian, reflectance: 0.3}}}\n"
       "  - {name: Nul, materials: {walls: {type: lambertian, reflectance: 0.3}}}\n"
       "  - {name: com1.txt, materials: {walls: {type: lambertian, reflectance: 0.3}}}\n"
       "  - {name: " + std::string(65, 'v') + ", materials: {walls: {type: lambertian, reflectance: 0.3}}}\n"
       "  - {name: " + std::string(64, 'v') + ", materials: {walls: {type: lambertian, reflectance: 0.3}}}\n",
       {"8:12: variant name 'low e'" + name_rule("' ' is not allowed"),
        "9:12: variant name '../up'" + name_rule("'/' is not allowed"),
        "10:12: variant name '.hidden'" + name_rule("it starts with '.'"),
        "11:12: variant name '-x'" + name_rule("it starts with '-'"),
        "12:12: variant name 'x.'" + name_rule("it ends with '.'"),
        "13:12: variant name 'Nul'" + name_rule("'Nul' is a device name"),
        "14:12: variant name 'com1.txt'" + name_rule("'com1' is a device name"),
        "15:12: variant name '" + std::string(64, 'v') + "...'" + name_rule("it has 65 characters (at most 64)")}},
      {"variant_replacing_nothing",
       "variants:\n"
       "  - {name: a, materials: {}}\n",
       {"8:26: variant 'a' changes nothing (replace a material or system, or remove or add an element)"}},
      {"missing_name_and_missing_materials",
       "variants:\n"
       "  - {materials: {glazing: {type: glass, transmittance: 0.4}}}\n"
       "  - name: b\n",
       {"8:5: missing required key 'name' in variant",
        "9:5: missing required key 'materials', 'systems', 'remove' or 'add' in variant"}},
      {"unknown_key_in_variant",
       "variants:\n"
       "  - {name: a, material: {glazing: {type: glass, transmittance: 0.4}}}\n",
       {"8:5: missing required key 'materials', 'systems', 'remove' or 'add' in variant",
        "8:15: unknown key 'material' in variant (did you mean 'materials'?)"}},
      {"bad_material_definitions_inside_a_variant",
       "variants:\n"
       "  - name: dim\n"
       "    materials:\n"
       "      walls: {type: lambertian, reflectance: 1.5}\n"
       "      glazing: {type: glas, transmittance: 0.4}\n",
       {"10:46: 'reflectance' must be in [0, 1], got 1.5",
        "11:23: unknown value 'glas' for 'type': expected one of lambertian, plastic, metal, "
        "mirror, glass, glazing, dielectric, translucent, opening, bsdf (did you mean 'glass'?)"}},
      {"variants_not_a_list",
       "variants: {name: a}\n",
       {"7:11: expected a list for 'variants', got a map"}},
      {"variant_not_a_map",
       "variants: [low_e]\n",
       {"7:12: expected a map for 'variant', got 'low_e'"}},
      {"unknown_top_level_key_hint",
       "variant:\n"
       "  - {name: a, materials: {walls: {type: lambertian, reflectance: 0.3}}}\n",
       {"7:1: unknown key 'variant' in project (did you mean 'variants'?)"}},
  };
}

std::vector<BadCase> metrics_cases() {
  return {
      {"every_range",
       "metrics:\n"
       "  daylight_factor_thresholds: [0, 2, 101]\n"
       "  da_threshold: 0\n"
       "  occupancy_start: -1\n"
       "  occupancy_end: 25\n"
       "  sda_time_fraction: 0\n"
       "  ase_threshold: -5\n"
       "  ase_hours: 9000\n"
       "  udi_lower: 0\n"
       "  udi_upper_original: -1\n"
       "  udi_upper_revised: 0\n",
       // In reading order: thresholds, DA, occupancy, UDI, sDA, ASE.
       {"8:32: 'daylight_factor_thresholds' must be in (0, 100], got 0",
        "8:38: 'daylight_factor_thresholds' must be in (0, 100], got 101",
        "9:17: 'da_threshold' must be > 0, got 0",
        "10:20: 'occupancy_start' must be in [0, 24], got -1",
        "11:18: 'occupancy_end' must be in [0, 24], got 25",
        "15:14: 'udi_lower' must be > 0, got 0",
        "16:23: 'udi_upper_original' must be > 0, got -1",
        "17:22: 'udi_upper_revised' must be > 0, got 0",
        "12:22: 'sda_time_fraction' must be in (0, 1], got 0",
        "13:18: 'ase_threshold' must be > 0, got -5",
        "14:14: 'ase_hours' must be in [0, 8784], got 9000"}},
      {"occupancy_end_before_start_and_udi_bands_reversed",
       "metrics:\n"
       "  occupancy_start: 18\n"
       "  occupancy_end: 8\n"
       "  udi_lower: 500\n"
       "  udi_upper_original: 400\n",
       {"9:18: 'occupancy_end' (8) must be after 'occupancy_start' (18)",
        "11:23: 'udi_upper_original' (400) must be greater than 'udi_lower' (500)",
        // da_threshold keeps its default 300: the caret goes to the key that was written.
        "10:14: 'da_threshold' (300) must lie between 'udi_lower' (500) and "
        "'udi_upper_revised' (3000): the revised UDI band is split there"}},
      {"empty_occupancy",
       "metrics: {occupancy_start: 8, occupancy_end: 8}\n",
       {"7:46: 'occupancy_end' (8) must be after 'occupancy_start' (8)"}},
      {"only_start_written_after_default_end",
       "metrics: {occupancy_start: 19}\n",
       {"7:28: 'occupancy_end' (18) must be after 'occupancy_start' (19)"}},
      {"revised_band_empty",
       "metrics: {udi_upper_revised: 100}\n",
       {"7:30: 'udi_upper_revised' (100) must be greater than 'udi_lower' (100)"}},
      {"da_threshold_outside_the_revised_band",
       "metrics: {da_threshold: 3000.5}\n",
       {"7:25: 'da_threshold' (3000.5) must lie between 'udi_lower' (100) and "
        "'udi_upper_revised' (3000): the revised UDI band is split there"}},
      {"duplicate_threshold",
       "metrics:\n"
       "  daylight_factor_thresholds: [2, 5, 2]\n",
       {"8:38: duplicate value 2 in 'daylight_factor_thresholds'"}},
      {"empty_threshold_list",
       "metrics:\n"
       "  daylight_factor_thresholds: []\n",
       {"8:31: expected a list of one or more numbers for 'daylight_factor_thresholds', got an "
        "empty list"}},
      {"threshold_not_a_list",
       "metrics:\n"
       "  daylight_factor_thresholds: 2\n",
       {"8:31: expected a list of one or more numbers for 'daylight_factor_thresholds', got '2'"}},
      {"threshold_not_a_number",
       "metrics:\n"
       "  daylight_factor_thresholds: [2, x]\n",
       {"8:35: expected a number in 'daylight_factor_thresholds', got 'x'"}},
      {"wrong_types",
       "metrics:\n"
       "  da_threshold: high\n"
       "  ase_hours: [250]\n",
       {"8:17: expected a number for 'da_threshold', got 'high'",
        "9:14: expected a number for 'ase_hours', got a list"}},
      {"unknown_key_with_hint",
       "metrics:\n"
       "  da_treshold: 250\n",
       {"8:3: unknown key 'da_treshold' in metrics (did you mean 'da_threshold'?)"}},
      {"metrics_not_a_map",
       "metrics: [1]\n",
       {"7:10: expected a map for 'metrics', got a list"}},
  };
}

TEST(ProjectVariants, EachVariantErrorHasItsExactMessageAndLocation) {
  for (const auto& c : variant_cases()) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(errors_of(Base + c.snippet), c.expected);
  }
}

TEST(ProjectVariants, EachSettingsErrorHasItsExactMessageAndLocation) {
  for (const auto& c : metrics_cases()) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(errors_of(Base + c.snippet), c.expected);
  }
}

TEST(ProjectVariants, PortableFolderNames) {
  for (const char* good : {"a", "low_e", "Blinds.v2-down", "2024", "con_", "console", "com0",
                           "lpt10", "a..b"})
    EXPECT_TRUE(is_portable_folder_name(good)) << good;
  for (const char* bad : {"", ".", "..", ".x", "-x", "x.", "a b", "a/b", "a\\b", "a:b", "é",
                          "CON", "aux.json", "lpt9", "COM1"})
    EXPECT_FALSE(is_portable_folder_name(bad)) << bad;
  EXPECT_TRUE(is_portable_folder_name(std::string(64, 'x')));
  EXPECT_FALSE(is_portable_folder_name(std::string(65, 'x')));
}

/// Surfaces of two scenes are identical (names, vertices, material indices, ports).
void expect_same_surfaces(const SceneDescription& a, const SceneDescription& b) {
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    SCOPED_TRACE(a.surfaces[i].name);
    EXPECT_EQ(a.surfaces[i].name, b.surfaces[i].name);
    EXPECT_EQ(a.surfaces[i].material, b.surfaces[i].material);
    EXPECT_EQ(a.surfaces[i].port, b.surfaces[i].port);
    EXPECT_EQ(a.surfaces[i].vertices, b.surfaces[i].vertices);
  }
}

TEST(ProjectVariants, ApplyVariantReplacesExactlyTheNamedMaterials) {
  const Project base = load_project(ProjectsDir + "/office_variants/project.yaml");
  ASSERT_EQ(base.materials.size(), 4u);
  ASSERT_EQ(base.variants.size(), 2u);
  const SceneDescription base_scene = build_scene_description(base);
  for (const VariantSpec& v : base.variants) {
    SCOPED_TRACE(v.name);
    const Project p = apply_variant(base, v);
    ASSERT_EQ(p.materials.size(), base.materials.size());
    for (std::size_t i = 0; i < base.materials.size(); ++i) {
      SCOPED_TRACE(base.materials[i].name);
      const MaterialSpec* replacement = nullptr;
      for (const MaterialSpec& m : v.materials)
        if (m.name == base.materials[i].name) replacement = &m;
      expect_same_material(p.materials[i], replacement ? *replacement : base.materials[i]);
    }
    // Everything that is not a material is the base's.
    EXPECT_EQ(p.path, base.path);
    EXPECT_EQ(p.weather.path, base.weather.path);
    EXPECT_EQ(p.site.latitude_deg, base.site.latitude_deg);
    EXPECT_EQ(p.simulation.photons_per_bin, base.simulation.photons_per_bin);
    EXPECT_EQ(p.simulation.seed, base.simulation.seed);
    EXPECT_EQ(p.outputs.folder, base.outputs.folder);
    expect_settings(p.metrics, base.metrics.daylight_factor_thresholds_percent,
                    base.metrics.da_threshold_lux, base.metrics.occupancy_start_h,
                    base.metrics.occupancy_end_h, base.metrics.udi_lower_lux,
                    base.metrics.udi_upper_original_lux, base.metrics.udi_upper_revised_lux,
                    base.metrics.sda_time_fraction, base.metrics.ase_threshold_lux,
                    base.metrics.ase_hours);
    EXPECT_EQ(p.variants.size(), base.variants.size());
    EXPECT_EQ(p.geometry.rooms.at(0).windows.at(0).material, "glazing");
    EXPECT_EQ(p.sensors.grids.size(), base.sensors.grids.size());

    // The variant's scene: same surfaces and material indices, only the glazing differs.
    const SceneDescription scene = build_scene_description(p);
    expect_same_surfaces(scene, base_scene);
    EXPECT_EQ(scene.grids.size(), base_scene.grids.size());
    ASSERT_EQ(scene.materials.size(), base_scene.materials.size());
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
      expect_same_material(scene.materials[i], p.materials[i]);
  }
  // The second variant turns the glass into a translucent blind (a type change).
  const Project blind = apply_variant(base, base.variants[1]);
  EXPECT_EQ(base.materials[3].name, "glazing");
  EXPECT_EQ(base.materials[3].type, MaterialType::Glass);
  EXPECT_EQ(blind.materials[3].type, MaterialType::Translucent);
  EXPECT_EQ(blind.materials[3].location.line, base.variants[1].materials[0].location.line);
}

TEST(ProjectVariants, ApplyVariantOnHandMadeVariants) {
  const Project base = load_project_from_string(Base, FakePath);
  // Several replacements, given in another order than the base's.
  VariantSpec both;
  both.name = "both";
  MaterialSpec walls;
  walls.name = "walls";
  walls.type = MaterialType::Lambertian;
  walls.reflectance = {0.3, 0.3, 0.3};
  MaterialSpec glazing;
  glazing.name = "glazing";
  glazing.type = MaterialType::Opening;
  both.materials = {walls, glazing};
  const Project p = apply_variant(base, both);
  ASSERT_EQ(p.materials.size(), 2u);
  expect_same_material(p.materials[0], glazing);
  expect_same_material(p.materials[1], walls);
  // No replacement: the base itself.
  const Project same = apply_variant(base, VariantSpec{"none", {}, {}, {}, {}, {}});
  for (std::size_t i = 0; i < base.materials.size(); ++i)
    expect_same_material(same.materials[i], base.materials[i]);
  // A material the base does not have cannot be replaced.
  MaterialSpec stray;
  stray.name = "roof";
  EXPECT_THROW(apply_variant(base, VariantSpec{"stray", {stray}, {}, {}, {}, {}}), std::invalid_argument);
}

TEST(ProjectVariants, OfficeVariantsExample) {
  const std::string path = ProjectsDir + "/office_variants/project.yaml";
  const Project p = load_project(path);
  EXPECT_EQ(p.weather.path, ProjectsDir + "/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw");
  ASSERT_EQ(p.variants.size(), 2u);
  EXPECT_EQ(p.variants[0].name, "solar_control");
  ASSERT_EQ(p.variants[0].materials.size(), 1u);
  EXPECT_EQ(p.variants[0].materials[0].transmittance, Vec3(0.4, 0.4, 0.4));
  EXPECT_EQ(p.variants[1].name, "blind_down");
  ASSERT_EQ(p.variants[1].materials.size(), 1u);
  const MaterialSpec& blind = p.variants[1].materials[0];
  EXPECT_EQ(blind.type, MaterialType::Translucent);
  // The comment in the file: diffuse reflection R (1 - T) = 0.41, diffuse transmission
  // R T (1 - Ts) = 0.11, straight transmission R T Ts = 0.03 (RADIANCE trans, s = 0).
  EXPECT_NEAR(blind.reflectance.x * (1 - blind.transmissivity), 0.41, 0.005);
  EXPECT_NEAR(blind.reflectance.x * blind.transmissivity * (1 - blind.transmitted_specular), 0.11, 0.005);
  EXPECT_NEAR(blind.reflectance.x * blind.transmissivity * blind.transmitted_specular, 0.03, 0.005);
  expect_settings(p.metrics, {1, 2, 5}, 300, 7, 19, 100, 2000, 3000, 0.5, 1000, 250);
  // Base and office are the same study: same materials as projects/office.
  const Project office = load_project(ProjectsDir + "/office/project.yaml");
  ASSERT_EQ(p.materials.size(), office.materials.size());
  for (std::size_t i = 0; i < p.materials.size(); ++i) {
    EXPECT_EQ(p.materials[i].name, office.materials[i].name);
    EXPECT_EQ(p.materials[i].reflectance, office.materials[i].reflectance);
    EXPECT_EQ(p.materials[i].transmittance, office.materials[i].transmittance);
  }
}

TEST(ProjectVariants, TruncatedVariantProjectsNeverCrash) {
  // Every 23-byte truncation of the example (cut inside variants and metrics too) either
  // loads or throws InputError whose diagnostics are all located.
  std::ifstream in(ProjectsDir + "/office_variants/project.yaml");
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  ASSERT_GT(text.size(), 1000u);
  for (std::size_t n = 0; n < text.size(); n += 23) {
    try {
      load_project_from_string(text.substr(0, n), FakePath);
    } catch (const InputError& e) {
      for (const auto& d : e.diagnostics()) EXPECT_TRUE(d.location.known()) << n << ": " << d.format();
    }
  }
}

}  // namespace
}  // namespace dayphoton::project
