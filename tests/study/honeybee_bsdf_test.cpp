// A Honeybee model's BSDF modifier in a whole daylight-factor study (docs/honeybee-import.md,
// "BSDF modifiers"). A 4 x 5 x 3 m room, a 3 x 1.5 m south window of the example's venetian
// blind (projects/bsdf_blind/blind_45deg.xml: 45-degree slats, their room-side edge higher, so
// front and back differ), 12 sensors at 0.8 m:
//   - as a Honeybee model (faces and aperture pointing out of the room, as Honeybee writes
//     them; the XML inline in bsdf_data) and as a RADIANCE scene drawn as RADIANCE expects a
//     BSDF window (its normal into the room: genBSDF(1), "the positive Z-axis points into the
//     room"), the two give the same daylight factors within their Monte Carlo errors;
//   - the same model with the up vector reversed (for these slats, the blind turned round:
//     what honeybee-radiance's static export, whose aperture normal points out of the room,
//     gives through RADIANCE) differs from it by many standard errors, so the comparison above
//     would see the blind put in backwards;
//   - the Honeybee blind is operable shading for LM-83 (its file's DeviceType), as the same
//     file is as a project material.
// Tolerances from the runs' own standard errors (df_stderr_percent).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/results_model_builder.h"
#include "fresh_run.h"
#include "numeric_csv.h"
#include "../json_string.h"
#include "../temp_folder.h"

namespace dayphoton {
namespace {

namespace fs = std::filesystem;

const std::string BlindFile = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/bsdf_blind/blind_45deg.xml";

fs::path folder() {
  const fs::path f = test::process_temp_dir() / "honeybee_bsdf_test";
  fs::create_directories(f);
  return f;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string num(double v) { return format_number(v); }

std::string loop(const std::vector<Vec3>& p) {
  std::string s = "[";
  for (std::size_t i = 0; i < p.size(); ++i) s += (i ? ", [" : "[") + num(p[i].x) + ", " + num(p[i].y) + ", " + num(p[i].z) + "]";
  return s + "]";
}

// The room, its faces counter-clockwise seen from outside (normals out of the room).
const std::vector<Vec3> South{{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}};
const std::vector<Vec3> North{{4, 5, 0}, {0, 5, 0}, {0, 5, 3}, {4, 5, 3}};
const std::vector<Vec3> West{{0, 5, 0}, {0, 0, 0}, {0, 0, 3}, {0, 5, 3}};
const std::vector<Vec3> East{{4, 0, 0}, {4, 5, 0}, {4, 5, 3}, {4, 0, 3}};
const std::vector<Vec3> Floor{{0, 0, 0}, {0, 5, 0}, {4, 5, 0}, {4, 0, 0}};
const std::vector<Vec3> Ceiling{{0, 0, 3}, {4, 0, 3}, {4, 5, 3}, {0, 5, 3}};
const std::vector<Vec3> Window{{0.5, 0, 0.9}, {3.5, 0, 0.9}, {3.5, 0, 2.4}, {0.5, 0, 2.4}};  // normal -y: out

std::vector<Vec3> sensors() {
  std::vector<Vec3> s;
  for (double y : {1.0, 2.0, 3.0, 4.0})
    for (double x : {1.0, 2.0, 3.0}) s.push_back({x, y, 0.8});
  return s;
}

const std::string Head =
    "version: 1\n"
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "study: daylight_factor\n"
    "outputs: {images: false, report: false, coefficients: false}\n"
    "simulation: {basis: tregenza, photons_per_bin: 2000, seed: 11}\n";

/// The room as a Honeybee model with the blind's XML inline, up vector `up`; with
/// `window_modifier` "glass" the aperture is clear glass instead (the blind not used).
std::string honeybee_project(const std::string& name, const std::string& up,
                             const std::string& window_modifier = "blind") {
  std::ostringstream hb;
  hb << "{\"type\": \"Model\", \"identifier\": \"blind_room\", \"units\": \"Meters\", \"tolerance\": 0.001,\n"
        " \"properties\": {\"type\": \"ModelProperties\", \"radiance\": {\"type\": \"ModelRadianceProperties\",\n"
        "  \"modifiers\": [\n"
        "   {\"type\": \"Plastic\", \"identifier\": \"floor\", \"r_reflectance\": 0.2, \"g_reflectance\": 0.2, \"b_reflectance\": 0.2},\n"
        "   {\"type\": \"Plastic\", \"identifier\": \"walls\", \"r_reflectance\": 0.5, \"g_reflectance\": 0.5, \"b_reflectance\": 0.5},\n"
        "   {\"type\": \"Plastic\", \"identifier\": \"ceiling\", \"r_reflectance\": 0.7, \"g_reflectance\": 0.7, \"b_reflectance\": 0.7},\n"
        "   {\"type\": \"BSDF\", \"identifier\": \"blind\", \"modifier\": {\"type\": \"Void\"}, \"up_orientation\": " << up
     << ", \"thickness\": 0, \"function_file\": \".\", \"transform\": null,\n    \"bsdf_data\": "
     << test::json_string(read_text(BlindFile)) << "},\n"
     << "   {\"type\": \"Glass\", \"identifier\": \"glass\", \"r_transmissivity\": 0.9, \"g_transmissivity\": 0.9, "
        "\"b_transmissivity\": 0.9}],\n"
     << "  \"sensor_grids\": [{\"type\": \"SensorGrid\", \"identifier\": \"points\", \"sensors\": [";
  const std::vector<Vec3> s = sensors();
  for (std::size_t i = 0; i < s.size(); ++i)
    hb << (i ? ", " : "") << "{\"pos\": [" << num(s[i].x) << ", " << num(s[i].y) << ", " << num(s[i].z) << "], \"dir\": [0, 0, 1]}";
  hb << "]}]}},\n \"rooms\": [{\"type\": \"Room\", \"identifier\": \"room\", \"faces\": [\n";
  struct F {
    const char *id, *type, *bc, *modifier;
    const std::vector<Vec3>& v;
  };
  const F faces[] = {{"south", "Wall", "Outdoors", "walls", South},       {"north", "Wall", "Outdoors", "walls", North},
                     {"west", "Wall", "Outdoors", "walls", West},         {"east", "Wall", "Outdoors", "walls", East},
                     {"floor", "Floor", "Ground", "floor", Floor},        {"ceiling", "RoofCeiling", "Outdoors", "ceiling", Ceiling}};
  bool first = true;
  for (const F& f : faces) {
    hb << (first ? "" : ",\n") << "  {\"type\": \"Face\", \"identifier\": \"" << f.id << "\", \"face_type\": \"" << f.type
       << "\", \"boundary_condition\": {\"type\": \"" << f.bc << "\"}, \"geometry\": {\"type\": \"Face3D\", \"boundary\": "
       << loop(f.v) << "}, \"properties\": {\"radiance\": {\"modifier\": \"" << f.modifier << "\"}}";
    if (std::string(f.id) == "south")
      hb << ", \"apertures\": [{\"type\": \"Aperture\", \"identifier\": \"window\", \"boundary_condition\": {\"type\": "
            "\"Outdoors\"}, \"geometry\": {\"type\": \"Face3D\", \"boundary\": "
         << loop(Window) << "}, \"properties\": {\"radiance\": {\"modifier\": \"" << window_modifier << "\"}}}]";
    hb << "}";
    first = false;
  }
  hb << "]}]}\n";
  std::ofstream(folder() / (name + ".hbjson")) << hb.str();
  return Head + "geometry:\n  honeybee: " + name + ".hbjson\nsensors:\n  honeybee_grids: all\n";
}

/// The same room as a RADIANCE scene, the window's normal into the room, the blind's file
/// beside it; the sensors as a point set of the same name.
std::string radiance_project() {
  fs::copy_file(BlindFile, folder() / "blind.xml", fs::copy_options::overwrite_existing);
  std::ostringstream rad;
  rad << "void plastic floor 0 0 5 0.2 0.2 0.2 0 0\n"
         "void plastic walls 0 0 5 0.5 0.5 0.5 0 0\n"
         "void plastic ceiling 0 0 5 0.7 0.7 0.7 0 0\n"
         "void BSDF blind 6 0 blind.xml 0 0 1 . 0 0\n";
  auto polygon = [&](const std::string& modifier, const std::string& id, const std::vector<Vec3>& v) {
    rad << modifier << " polygon " << id << " 0 0 " << 3 * v.size();
    for (const Vec3& p : v) rad << ' ' << num(p.x) << ' ' << num(p.y) << ' ' << num(p.z);
    rad << "\n";
  };
  polygon("walls", "north", North);
  polygon("walls", "west", West);
  polygon("walls", "east", East);
  polygon("floor", "floor", Floor);
  polygon("ceiling", "ceiling", Ceiling);
  // The south wall around the window.
  polygon("walls", "south_below", {{0, 0, 0}, {4, 0, 0}, {4, 0, 0.9}, {0, 0, 0.9}});
  polygon("walls", "south_above", {{0, 0, 2.4}, {4, 0, 2.4}, {4, 0, 3}, {0, 0, 3}});
  polygon("walls", "south_left", {{0, 0, 0.9}, {0.5, 0, 0.9}, {0.5, 0, 2.4}, {0, 0, 2.4}});
  polygon("walls", "south_right", {{3.5, 0, 0.9}, {4, 0, 0.9}, {4, 0, 2.4}, {3.5, 0, 2.4}});
  polygon("blind", "window", {Window.rbegin(), Window.rend()});  // normal +y: into the room
  std::ofstream(folder() / "room.rad") << rad.str();
  std::string yaml = Head + "geometry:\n  radiance:\n    - {files: [room.rad], ports: auto}\nsensors:\n  points:\n"
                            "    - name: points\n      points: [";
  const std::vector<Vec3> s = sensors();
  for (std::size_t i = 0; i < s.size(); ++i)
    yaml += std::string(i ? ", " : "") + "[" + num(s[i].x) + ", " + num(s[i].y) + ", " + num(s[i].z) + ", 0, 0, 1]";
  return yaml + "]\n";
}

struct Df {
  std::vector<double> value, stderr_;
};

Df run(const std::string& name, const std::string& yaml, const std::string& grid_folder = "points") {
  const fs::path project_file = folder() / (name + ".yaml");
  const project::Project p = project::load_project_from_string(yaml, project_file.string());
  const fs::path out = folder() / name;
  test::run_in_fresh_folder(p, out);
  Df df;
  for (const std::vector<double>& row : test::read_csv(out / grid_folder / "daylight_factor.csv")) {
    df.value.push_back(row.at(4));  // index,x,y,z,df_percent,df_stderr_percent
    df.stderr_.push_back(row.at(5));
  }
  fs::remove_all(out);
  return df;
}

/// The grid means' ratio b / a and its standard error, and the largest per-sensor |z|.
struct Comparison {
  double mean_ratio = 0, mean_ratio_se = 0, max_abs_z = 0;
};

Comparison compare(const Df& a, const Df& b) {
  Comparison c;
  double sa = 0, sb = 0, va = 0, vb = 0;
  for (std::size_t i = 0; i < a.value.size(); ++i) {
    sa += a.value[i];
    sb += b.value[i];
    va += a.stderr_[i] * a.stderr_[i];
    vb += b.stderr_[i] * b.stderr_[i];
    const double z = (b.value[i] - a.value[i]) / std::hypot(a.stderr_[i], b.stderr_[i]);
    c.max_abs_z = std::max(c.max_abs_z, std::abs(z));
  }
  c.mean_ratio = sb / sa;
  // The sensors' errors taken as independent: neighbouring sensors share photons, so this
  // understates the mean's error; the checks use 5 of them.
  c.mean_ratio_se = c.mean_ratio * std::sqrt(va / (sa * sa) + vb / (sb * sb));
  return c;
}

TEST(HoneybeeBsdf, ABlindInAHoneybeeApertureGivesTheRadianceScenesLightWithItsFrontOutdoors) {
  const Df radiance = run("radiance", radiance_project());
  const Df honeybee = run("honeybee", honeybee_project("model", "[0, 0, 1]"));
  const Df turned = run("turned", honeybee_project("turned_model", "[0, 0, -1]"));
  ASSERT_EQ(radiance.value.size(), 12u);
  ASSERT_EQ(honeybee.value.size(), 12u);
  ASSERT_EQ(turned.value.size(), 12u);
  const Comparison same = compare(radiance, honeybee), reversed = compare(radiance, turned);
  std::printf("[ honeybee bsdf ] mean DF: RADIANCE scene %.3f %%, Honeybee %.3f %% (ratio %.4f, se %.4f, max |z| %.2f); "
              "turned round: ratio %.4f (se %.4f)\n",
              [&] { double s = 0; for (double v : radiance.value) s += v; return s / 12; }(),
              [&] { double s = 0; for (double v : honeybee.value) s += v; return s / 12; }(), same.mean_ratio,
              same.mean_ratio_se, same.max_abs_z, reversed.mean_ratio, reversed.mean_ratio_se);
  // The same light: the means within 5 standard errors, no sensor beyond 4 (12 sensors: a
  // |z| > 4 has probability < 1e-3 by noise alone).
  EXPECT_NEAR(same.mean_ratio, 1.0, 5 * same.mean_ratio_se);
  EXPECT_LT(same.max_abs_z, 4.0);
  // The blind turned round is far outside that: the test sees the orientation.
  EXPECT_GT(std::abs(reversed.mean_ratio - 1.0), 10 * reversed.mean_ratio_se);
}

// A variant that gives a Honeybee aperture a project `bsdf` material in place of its glass
// modifier puts the BSDF's front outdoors, as the model's own BSDF modifier does: the
// aperture, whose normal points out of the room, is turned round for it.
TEST(HoneybeeBsdf, AVariantsBsdfMaterialOnAHoneybeeApertureHasItsFrontOutdoors) {
  fs::copy_file(BlindFile, folder() / "blind.xml", fs::copy_options::overwrite_existing);
  const std::string yaml = honeybee_project("glass_model", "[0, 0, 1]", "glass") +
                           "variants:\n  - name: blind\n    materials:\n"
                           "      glass: {type: bsdf, file: blind.xml, up: [0, 0, 1]}\n";
  const Df variant = run("glass_variant", yaml, "variants/blind/points");
  const Df honeybee = run("honeybee_again", honeybee_project("model_again", "[0, 0, 1]"));
  ASSERT_EQ(variant.value.size(), 12u);
  const Comparison same = compare(honeybee, variant);
  std::printf("[ honeybee bsdf variant ] ratio %.4f (se %.4f), max |z| %.2f\n", same.mean_ratio, same.mean_ratio_se,
              same.max_abs_z);
  EXPECT_NEAR(same.mean_ratio, 1.0, 5 * same.mean_ratio_se);
  EXPECT_LT(same.max_abs_z, 4.0);
}

// Where a model's BSDF modifier is refused (a shade: no side of it is outdoors), a variant's
// project `bsdf` material in the shade's modifier's place is refused too, at the shade.
TEST(HoneybeeBsdf, AVariantsBsdfMaterialOnAHoneybeeShadeIsALocatedError) {
  const std::string yaml = honeybee_project("shaded_model", "[0, 0, 1]", "glass") +
                           "variants:\n  - name: blind\n    materials:\n"
                           "      glass: {type: bsdf, file: blind.xml, up: [0, 0, 1]}\n";
  const fs::path model = folder() / "shaded_model.hbjson";
  std::string text = read_text(model.string());
  const std::size_t end = text.rfind('}');
  text.insert(end, ", \"orphaned_shades\": [{\"type\": \"Shade\", \"identifier\": \"screen\", \"geometry\": {\"type\": "
                   "\"Face3D\", \"boundary\": [[0, -1, 3], [4, -1, 3], [4, -1, 4], [0, -1, 4]]}, \"properties\": "
                   "{\"radiance\": {\"modifier\": \"glass\"}}}]");
  std::ofstream(model) << text;
  fs::copy_file(BlindFile, folder() / "blind.xml", fs::copy_options::overwrite_existing);
  const project::Project p = project::load_project_from_string(yaml, (folder() / "shaded.yaml").string());
  ASSERT_EQ(p.variants.size(), 1u);
  (void)project::build_scene_description(p);  // the base: clear glass on the shade is read
  try {
    (void)project::build_scene_description(project::apply_variant(p, p.variants[0]));
    ADD_FAILURE() << "the variant's BSDF on a shade was not refused";
  } catch (const InputError& e) {
    const std::string what = e.what();
    const std::string at = model.string() + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(end), '\n'));
    EXPECT_NE(what.find(at), std::string::npos) << what;
    EXPECT_NE(what.find("('screen') has BSDF material 'glass': a BSDF is read on the apertures, glass doors and faces of "
                        "a room facing Outdoors only"),
              std::string::npos)
        << what;
  }
}

TEST(HoneybeeBsdf, ABlindInAHoneybeeApertureIsOperableShadingByItsDeviceType) {
  const project::Project p =
      project::load_project_from_string(honeybee_project("shading_model", "[0, 0, 1]"), (folder() / "shading.yaml").string());
  study::CaseResult c;
  study::set_building(c, p, project::build_scene_description(p));
  ASSERT_EQ(c.shading_materials_in_place.size(), 1u);
  EXPECT_EQ(c.shading_materials_in_place[0].material, "blind");
  EXPECT_NE(c.shading_materials_in_place[0].why.find("DeviceType is 'Venetian blind'"), std::string::npos)
      << c.shading_materials_in_place[0].why;
}

}  // namespace
}  // namespace dayphoton
