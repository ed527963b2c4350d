// Files of other tools in feet, inches or millimetres (docs/radiance-import.md, "Units"):
// `units` on geometry.radiance entries and on .pts point sets scales every coordinate and
// length to metres; a RADIANCE scene read without it whose rooms only make sense in another
// unit is warned about at its entry (scene_unit_check.h), and metric buildings are not.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../radiance_in_units.h"
#include "../temp_folder.h"
#include "dayphoton/project/length_units.h"
#include "dayphoton/project/project.h"
#include "dayphoton/project/radiance_scene.h"
#include "dayphoton/project/scene_unit_check.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

namespace fs = std::filesystem;
const fs::path Data = fs::path(DAYPHOTON_TEST_DATA_DIR) / "radiance";

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A folder with materials.rad, the office in metres (office.rad) and in the unit `name`
/// (office_<name>.rad), and the work plane's .pts in metres and in that unit.
fs::path folder_with_office_in(const std::string& name) {
  const fs::path dir = dayphoton::test::process_temp_dir() / ("units_" + name);
  fs::create_directories(dir);
  const double f = metres_per_length_unit(name);
  fs::copy_file(Data / "materials.rad", dir / "materials.rad", fs::copy_options::overwrite_existing);
  fs::copy_file(Data / "office.rad", dir / "office.rad", fs::copy_options::overwrite_existing);
  std::ofstream(dir / ("office_" + name + ".rad")) << dayphoton::test::radiance_in_units(read_text(Data / "office.rad"), f);
  std::ifstream pts(Data / "grid_0p8m.pts");
  std::ofstream scaled(dir / ("grid_" + name + ".pts"));
  for (double x, y, z, nx, ny, nz; pts >> x >> y >> z >> nx >> ny >> nz;) {
    char line[200];
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g %g %g %g\n", x / f, y / f, z / f, nx, ny, nz);
    scaled << line;
  }
  return dir;
}

std::string project_text(const std::string& radiance_entry, const std::string& sensors) {
  return "version: 1\n"
         "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
         "geometry:\n"
         "  radiance:\n" +
         radiance_entry + "sensors:\n" + sensors + "outputs: {annual_illuminance: false, metrics: false}\n";
}

const std::string Grid =
    "  grids:\n"
    "    - {name: workplane, polygon: [[0, 0, 0], [6, 0, 0], [6, 8, 0], [0, 8, 0]], height: 0.8}\n";

std::vector<std::string> warnings_of(const SceneDescription& d) {
  std::vector<std::string> out;
  for (const Diagnostic& w : d.warnings)
    out.push_back(std::to_string(w.location.line) + ":" + std::to_string(w.location.column) + ": " + w.message);
  return out;
}

TEST(SceneUnits, UnitNamesAreHoneybeesWithExactFactors) {
  EXPECT_EQ(length_unit_names(), (std::vector<std::string>{"Meters", "Millimeters", "Centimeters", "Feet", "Inches"}));
  EXPECT_EQ(metres_per_length_unit("Feet"), 0.3048);
  EXPECT_EQ(metres_per_length_unit("Inches"), 0.0254);
  EXPECT_EQ(metres_per_length_unit("Millimeters"), 0.001);
  EXPECT_EQ(metres_per_length_unit("feet"), 0.0);  // Honeybee's names are capitalised
}

TEST(SceneUnits, AnOfficeInFeetWithUnitsIsTheOfficeInMetres) {
  for (const std::string name : {"Feet", "Inches", "Millimeters"}) {
    const fs::path dir = folder_with_office_in(name);
    const Project metric =
        load_project_from_string(project_text("    - files: [materials.rad, office.rad]\n", Grid), (dir / "m.yaml").string());
    const Project other = load_project_from_string(
        project_text("    - files: [materials.rad, office_" + name + ".rad]\n      units: " + name + "\n", Grid),
        (dir / "u.yaml").string());
    EXPECT_EQ(other.geometry.radiance[0].metres_per_unit, metres_per_length_unit(name));
    const SceneDescription a = build_scene_description(metric), b = build_scene_description(other);
    ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
    for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
      ASSERT_EQ(a.surfaces[i].vertices.size(), b.surfaces[i].vertices.size());
      for (std::size_t k = 0; k < a.surfaces[i].vertices.size(); ++k)
        EXPECT_NEAR(length(a.surfaces[i].vertices[k] - b.surfaces[i].vertices[k]), 0.0, 1e-12)
            << name << " " << a.surfaces[i].name;
    }
    EXPECT_TRUE(b.warnings.empty()) << name << ": " << (b.warnings.empty() ? "" : b.warnings[0].message);
    ASSERT_EQ(b.grids.size(), 1u);
    EXPECT_EQ(b.grids[0].points.size(), 165u);
  }
}

TEST(SceneUnits, ARoomInFeetReadAsMetresIsWarnedAboutAtItsEntry) {
  const fs::path dir = folder_with_office_in("Feet");
  const Project p = load_project_from_string(project_text("    - files: [materials.rad, office_Feet.rad]\n", Grid),
                                             (dir / "u.yaml").string());
  const SceneDescription d = build_scene_description(p);
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_EQ(warnings_of(d)[0],
            "5:7: RADIANCE scene without 'units', read in metres: its rooms are 9.84252 m from floor to ceiling (100 % "
            "of its lit floor area), 3 m in feet: if the files are in feet, set 'units: Feet' on this entry; if they "
            "are in metres, write 'units: Meters' to say so");
  EXPECT_EQ(d.warnings[0].location.file, (dir / "u.yaml").string());
  // Millimetres and inches likewise; the metric office and an explicit 'units: Meters' are quiet.
  for (const std::string name : {"Millimeters", "Inches"}) {
    const fs::path other = folder_with_office_in(name);
    const SceneDescription o = build_scene_description(load_project_from_string(
        project_text("    - files: [materials.rad, office_" + name + ".rad]\n", Grid), (other / "u.yaml").string()));
    ASSERT_EQ(o.warnings.size(), 1u) << name;
    EXPECT_NE(o.warnings[0].message.find("set 'units: " + name + "'"), std::string::npos) << o.warnings[0].message;
  }
  EXPECT_TRUE(build_scene_description(load_project_from_string(
                  project_text("    - files: [materials.rad, office.rad]\n", Grid), (dir / "m.yaml").string()))
                  .warnings.empty());
  EXPECT_TRUE(build_scene_description(
                  load_project_from_string(
                      project_text("    - files: [materials.rad, office_Feet.rad]\n      units: Meters\n", Grid),
                      (dir / "u.yaml").string()))
                  .warnings.empty());
}

TEST(SceneUnits, PtsInFeetWithUnitsGivesTheMetricSensors) {
  const fs::path dir = folder_with_office_in("Feet");
  auto sensors = [](const std::string& entry) { return "  points:\n    - {name: desks, " + entry + "}\n"; };
  const SceneDescription metric = build_scene_description(load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n", sensors("file: grid_Feet.pts, units: Feet")),
      (dir / "m.yaml").string()));
  const SceneDescription reference = build_scene_description(load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n", sensors("file: " + (Data / "grid_0p8m.pts").string())),
      (dir / "m.yaml").string()));
  ASSERT_EQ(metric.grids.size(), 1u);
  ASSERT_EQ(metric.grids[0].points.size(), 165u);
  for (std::size_t i = 0; i < 165; ++i) {
    EXPECT_NEAR(length(metric.grids[0].points[i].position - reference.grids[0].points[i].position), 0.0, 1e-12) << i;
    EXPECT_EQ(metric.grids[0].points[i].normal, reference.grids[0].points[i].normal);
  }
  // `units` belongs to a file; inline points are in metres. A misspelt unit is located.
  EXPECT_EQ(test::located_errors([&] {
              load_project_from_string(project_text("    - files: [materials.rad, office.rad]\n",
                                                    sensors("points: [[1, 1, 0.8, 0, 0, 1]], units: Feet")),
                                       (dir / "m.yaml").string());
            }),
            std::vector<std::string>{"8:60: 'units' is the unit of a .pts 'file'; inline 'points' are in metres"});
  EXPECT_EQ(test::located_errors([&] {
              load_project_from_string(project_text("    - files: [materials.rad, office.rad]\n      units: feet\n", Grid),
                                       (dir / "m.yaml").string());
            }),
            std::vector<std::string>{"6:14: unknown value 'feet' for 'units': expected one of Meters, Millimeters, "
                                     "Centimeters, Feet, Inches (did you mean 'Feet'?)"});
}

TEST(SceneUnits, LengthsInMaterialsTransformsAndRadiiAreConverted) {
  // A dielectric's transmission per foot, a translation in feet and a sphere's radius in feet.
  const fs::path dir = dayphoton::test::process_temp_dir() / "units_lengths";
  fs::create_directories(dir);
  std::ofstream(dir / "part.rad") << "void dielectric acrylic 0 0 5 0.9 0.8 0.7 1.49 0\n"
                                     "acrylic sphere ball 0 0 4 0 0 0 1\n";
  std::ofstream(dir / "scene.rad") << "!xform -t 10 0 0 part.rad\n";
  RadianceSceneOptions options;
  options.metres_per_unit = 0.3048;
  Diagnostics diag;
  const RadianceScene s = read_radiance_scene({(dir / "scene.rad").string()}, options, diag);
  ASSERT_EQ(s.materials.size(), 1u);
  // Over 1 m = 1/0.3048 ft: 0.9^(1/0.3048) per metre.
  EXPECT_NEAR(s.materials[0].transmittance.x, std::pow(0.9, 1 / 0.3048), 1e-15);
  EXPECT_NEAR(s.materials[0].transmittance.z, std::pow(0.7, 1 / 0.3048), 1e-15);
  Vec3 pole{0, 0, -1e9};  // the sphere's north pole: centre + (0, 0, r)
  for (const RadianceSurface& f : s.surfaces)
    for (const Vec3& p : f.vertices)
      if (p.z > pole.z) pole = p;
  EXPECT_NEAR(pole.x, 3.048, 1e-12);   // the translation, in metres
  EXPECT_NEAR(pole.z, 0.3048, 1e-12);  // the radius, in metres
  // RADIANCE's own xform -s scales a dielectric's absorption too (xform.c, m_dielectric).
  std::ofstream(dir / "scaled.rad") << "!xform -s 2 part.rad\n";
  Diagnostics d2;
  const RadianceScene s2 = read_radiance_scene({(dir / "scaled.rad").string()}, RadianceSceneOptions{}, d2);
  EXPECT_NEAR(s2.materials[0].transmittance.x, std::sqrt(0.9), 1e-15);
}

// ---- the heuristic on its own: both sides ----------------------------------------------------

/// A box room from (x0, y0, z0) of size (sx, sy, sz), walls and floor and ceiling, with a
/// glazed window in its south wall (x from 1/6 to 5/6 of sx, z from 0.3 to 0.8 of sz), all
/// lengths times `s`.
void add_room(std::vector<UnitCheckFacet>& out, Vec3 o, Vec3 size, double s = 1, bool window = true) {
  const Vec3 a = o * s, b = (o + size) * s;
  auto quad = [&](Vec3 p, Vec3 q, Vec3 r, Vec3 t, bool glazed = false) { out.push_back({{p, q, r, t}, glazed}); };
  quad({a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, b.y, a.z}, {a.x, b.y, a.z});  // floor
  quad({a.x, a.y, b.z}, {a.x, b.y, b.z}, {b.x, b.y, b.z}, {b.x, a.y, b.z});  // ceiling
  quad({a.x, b.y, a.z}, {b.x, b.y, a.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z});  // north
  quad({a.x, a.y, a.z}, {a.x, b.y, a.z}, {a.x, b.y, b.z}, {a.x, a.y, b.z});  // west
  quad({b.x, a.y, a.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {b.x, b.y, a.z});  // east
  quad({a.x, a.y, a.z}, {a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, a.y, a.z});  // south (a sheet)
  if (window) {
    const double x0 = a.x + (b.x - a.x) / 6, x1 = b.x - (b.x - a.x) / 6;
    const double z0 = a.z + 0.3 * (b.z - a.z), z1 = a.z + 0.8 * (b.z - a.z);
    quad({x0, a.y, z0}, {x1, a.y, z0}, {x1, a.y, z1}, {x0, a.y, z1}, true);
  }
}

/// A horizontal rectangle (a desk top, a column's top, ...).
void add_slab(std::vector<UnitCheckFacet>& out, double x0, double y0, double x1, double y1, double z) {
  out.push_back({{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, false});
}

TEST(SceneUnitCheck, MetricBuildingsAreNotFlagged) {
  std::vector<UnitCheckFacet> office;
  add_room(office, {0, 0, 0}, {6, 8, 3});
  EXPECT_FALSE(suggest_scene_units(office));

  // bench's open plan: 50 x 50 x 3 m, columns every 8 m (their tops and feet), desks.
  std::vector<UnitCheckFacet> open_plan;
  add_room(open_plan, {0, 0, 0}, {50, 50, 3});
  for (double x = 8; x < 50; x += 8)
    for (double y = 8; y < 50; y += 8) {
      add_slab(open_plan, x, y, x + 0.4, y + 0.4, 0);
      add_slab(open_plan, x, y, x + 0.4, y + 0.4, 3);
      add_slab(open_plan, x + 1.3, y + 1.3, x + 2.9, y + 2.1, 0.75);
    }
  EXPECT_FALSE(suggest_scene_units(open_plan));

  // A 30 m atrium with a glazed roof, and four 3.5 m storeys beside it.
  std::vector<UnitCheckFacet> atrium;
  add_room(atrium, {0, 0, 0}, {20, 20, 30}, 1, false);
  atrium.push_back({{{2, 2, 30}, {18, 2, 30}, {18, 18, 30}, {2, 18, 30}}, true});
  for (int storey = 0; storey < 4; ++storey) add_room(atrium, {20, 0, 3.5 * storey}, {12, 20, 3.5});
  EXPECT_FALSE(suggest_scene_units(atrium));
  // The atrium alone: 30 m is no room in any unit.
  atrium.resize(7);
  EXPECT_FALSE(suggest_scene_units(atrium));

  // The office beside a neighbouring block 12 m high drawn as massing (no glazing), and a
  // ground polygon under both: the block's height is no room's.
  std::vector<UnitCheckFacet> context = office;
  add_room(context, {20, -10, 0}, {40, 40, 12}, 1, false);
  add_slab(context, -100, -100, 100, 100, 0);
  EXPECT_FALSE(suggest_scene_units(context));

  // A scene without glazing has no lit room to judge by.
  std::vector<UnitCheckFacet> shell;
  add_room(shell, {0, 0, 0}, {6, 8, 3}, 1 / 0.3048, false);
  EXPECT_FALSE(suggest_scene_units(shell));
}

TEST(SceneUnitCheck, RoomsInOtherUnitsAreFlagged) {
  // A 10 x 12 x 9 ft room; an office floor 30 x 60 ft with 10 ft ceilings and desks; a
  // three-storey house in inches; an office in millimetres.
  std::vector<UnitCheckFacet> room;
  add_room(room, {0, 0, 0}, {10, 12, 9});
  std::optional<SceneUnitSuggestion> u = suggest_scene_units(room);
  ASSERT_TRUE(u);
  EXPECT_EQ(u->units, "Feet");
  EXPECT_NEAR(u->room_height_m, 9 * 0.3048, 1e-12);

  std::vector<UnitCheckFacet> floor;
  add_room(floor, {0, 0, 0}, {30, 60, 10});
  for (double x = 3; x < 27; x += 6) add_slab(floor, x, 3, x + 5, 5.5, 2.5);
  u = suggest_scene_units(floor);
  ASSERT_TRUE(u);
  EXPECT_EQ(u->units, "Feet");

  std::vector<UnitCheckFacet> house;
  for (int storey = 0; storey < 3; ++storey) add_room(house, {0, 0, 108.0 * storey}, {360, 480, 96});
  u = suggest_scene_units(house);
  ASSERT_TRUE(u);
  EXPECT_EQ(u->units, "Inches");
  EXPECT_NEAR(u->room_height_m, 96 * 0.0254, 1e-12);

  std::vector<UnitCheckFacet> mm;
  add_room(mm, {0, 0, 0}, {6000, 8000, 2700});
  u = suggest_scene_units(mm);
  ASSERT_TRUE(u);
  EXPECT_EQ(u->units, "Millimeters");

  // Not told apart (header): a metric hall 30 x 60 x 9 m and nothing lower reads as feet;
  // `units: Meters` on its entry says so.
  std::vector<UnitCheckFacet> hall;
  add_room(hall, {0, 0, 0}, {30, 60, 9});
  u = suggest_scene_units(hall);
  ASSERT_TRUE(u);
  EXPECT_EQ(u->units, "Feet");
}

}  // namespace
}  // namespace dayphoton::project
