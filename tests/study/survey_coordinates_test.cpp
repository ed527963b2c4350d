// A model in survey coordinates (UTM eastings of about 500 km, northings up to 10 000 km) runs
// as if drawn at the origin, and its outputs keep the user's coordinates
// (project/local_origin.h). Before, geometry beyond engine::PhotonCoordinateLimit_m (100 km)
// was refused, and a room at a UTM northing read its daylight factor 2-3 times too high
// before that (photon positions are floats).
//
// The room: a CIE 171:2006-style black room, 6 x 8 x 3 m, every reflectance 0, ground 0, with
// a 4 x 1.5 m unglazed opening (x 1..5, sill 0.9 m) in its south wall: its daylight factor is
// the sky component alone, whose closed form under the CIE overcast sky, L = L_z (1 + 2 sin a)
// / 3 over an unobstructed E_h = 7 pi L_z / 9 (CIE S 011/E:2003, sky type 1), is integrated
// here over the opening by the midpoint rule (2 cm cells). Tolerance 1 % against it, as the
// point-in-time black-room test (64 shadow rays per bin; the error falls below 0.7 %).
//
// The same room at (0, 0), at (500 000, 5 000 000) and at (500 000, 9 999 000) m: every
// coordinate of the model and its sensors is exact in double precision there, and the local
// origin is a whole kilometre, so the engine sees the same numbers and the daylight factors
// (and their standard errors) are the same bytes; the sensors' positions in sensors.csv,
// daylight_factor.csv and results.json are the input's. Four input paths: YAML polygons with a
// RADIANCE .pts sensor file, a RADIANCE scene file (geometry.radiance) with points in the
// YAML, a Honeybee model (geometry.honeybee, its aperture glazed, its sensor grid) and OBJ
// meshes (geometry.meshes).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "fresh_run.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

/// Sensors relative to the room's south-west floor corner: upward points 0.8 m high from the
/// opening to the back corner (x, y, z as exact binary fractions where they vary).
const std::vector<Vec3> SensorsInRoom = {{3, 1.5, 0.8}, {3.25, 3, 0.8}, {3, 5, 0.8}, {3, 7.5, 0.8}, {0.5, 7.5, 0.8}};

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::string point(double x, double y, double z) {
  return "[" + number(x) + ", " + number(y) + ", " + number(z) + "]";
}

const std::string Head =
    "site: {latitude: 47.0, longitude: 8.0, time_zone: 1}\n"
    "study: daylight_factor\n"
    "materials:\n"
    "  black: {type: lambertian, reflectance: 0}\n"
    "  hole: {type: opening}\n";
const std::string Tail =
    "simulation: {photons_per_bin: 300, seed: 5, ground_reflectance: 0, direct_samples_per_bin: 64}\n"
    "outputs: {images: false, report: false}\n";

/// The room's faces as RADIANCE-style polygons (x0, y0 its south-west floor corner): name,
/// material, vertices. The south wall is four pieces around the opening.
struct Face {
  std::string name, material;
  std::vector<Vec3> vertices;
};
std::vector<Face> faces(double x0, double y0) {
  auto p = [&](double x, double y, double z) { return Vec3{x0 + x, y0 + y, z}; };
  return {
      {"floor", "black", {p(0, 0, 0), p(0, 8, 0), p(6, 8, 0), p(6, 0, 0)}},
      {"ceiling", "black", {p(0, 0, 3), p(6, 0, 3), p(6, 8, 3), p(0, 8, 3)}},
      {"west", "black", {p(0, 0, 0), p(0, 0, 3), p(0, 8, 3), p(0, 8, 0)}},
      {"east", "black", {p(6, 0, 0), p(6, 8, 0), p(6, 8, 3), p(6, 0, 3)}},
      {"north", "black", {p(0, 8, 0), p(0, 8, 3), p(6, 8, 3), p(6, 8, 0)}},
      {"south_low", "black", {p(0, 0, 0), p(6, 0, 0), p(6, 0, 0.9), p(0, 0, 0.9)}},
      {"south_high", "black", {p(0, 0, 2.4), p(6, 0, 2.4), p(6, 0, 3), p(0, 0, 3)}},
      {"south_west", "black", {p(0, 0, 0.9), p(1, 0, 0.9), p(1, 0, 2.4), p(0, 0, 2.4)}},
      {"south_east", "black", {p(5, 0, 0.9), p(6, 0, 0.9), p(6, 0, 2.4), p(5, 0, 2.4)}},
      {"opening", "hole", {p(1, 0, 0.9), p(1, 0, 2.4), p(5, 0, 2.4), p(5, 0, 0.9)}},
  };
}

/// Path 1: YAML polygons (the opening a port) and a .pts file of the sensors.
std::string polygons_project(const fs::path& dir, double x0, double y0) {
  std::ofstream pts(dir / "sensors.pts");
  for (const Vec3& s : SensorsInRoom) pts << number(x0 + s.x) << ' ' << number(y0 + s.y) << ' ' << number(s.z) << " 0 0 1\n";
  std::string yaml = Head + "geometry:\n  polygons:\n";
  for (const Face& f : faces(x0, y0)) {
    yaml += "    - {name: " + f.name + ", material: " + f.material + (f.material == "hole" ? ", port: true" : "") +
            ", vertices: [";
    for (std::size_t i = 0; i < f.vertices.size(); ++i)
      yaml += (i ? ", " : "") + point(f.vertices[i].x, f.vertices[i].y, f.vertices[i].z);
    yaml += "]}\n";
  }
  return yaml + "sensors:\n  points:\n    - {name: depth, file: sensors.pts}\n" + Tail;
}

/// Path 2: a RADIANCE scene file (its `hole` glass replaced by the project's opening, a port
/// candidate that faces the sky) and the sensors as YAML points.
std::string radiance_project(const fs::path& dir, double x0, double y0) {
  std::ofstream rad(dir / "room.rad");
  rad << "void plastic black\n0\n0\n5 0 0 0 0 0\n\nvoid glass hole\n0\n0\n3 0.9 0.9 0.9\n";
  for (const Face& f : faces(x0, y0)) {
    rad << "\n" << f.material << " polygon " << f.name << "\n0\n0\n" << 3 * f.vertices.size();
    for (const Vec3& v : f.vertices) rad << "  " << number(v.x) << ' ' << number(v.y) << ' ' << number(v.z);
    rad << "\n";
  }
  std::string yaml = Head + "geometry:\n  radiance:\n    - {files: [room.rad], ports: auto}\n"
                            "sensors:\n  points:\n    - name: depth\n      points: [";
  for (std::size_t i = 0; i < SensorsInRoom.size(); ++i) {
    const Vec3& s = SensorsInRoom[i];
    yaml += std::string(i ? ", " : "") + "[" + number(x0 + s.x) + ", " + number(y0 + s.y) + ", " + number(s.z) +
            ", 0, 0, 1]";
  }
  return yaml + "]\n" + Tail;
}

/// The YAML polygons with the opening glazed (a project glass of normal transmittance 0.64,
/// Honeybee's generic exterior window): the reference for the Honeybee path at the origin.
std::string glazed_polygons_project(const fs::path& dir, double x0, double y0) {
  std::string yaml = polygons_project(dir, x0, y0);
  const std::string hole = "hole: {type: opening}";
  yaml.replace(yaml.find(hole), hole.size(), "hole: {type: glass, transmittance: 0.64}");
  return yaml;
}

/// Path 3: a Honeybee model (geometry.honeybee): the room's faces as Honeybee faces (pointing
/// out of the room, as Honeybee writes them) of modifier 'hb_black', the south wall one face
/// with the opening as an aperture of Honeybee's generic exterior glass (visible transmittance
/// 0.64), and the sensors as the model's sensor grid.
std::string honeybee_project(const fs::path& dir, double x0, double y0) {
  auto loop = [](const std::vector<Vec3>& vertices) {
    std::string s = "[";
    for (std::size_t i = 0; i < vertices.size(); ++i)
      s += (i ? ", " : "") + point(vertices[i].x, vertices[i].y, vertices[i].z);
    return s + "]";
  };
  auto p = [&](double x, double y, double z) { return Vec3{x0 + x, y0 + y, z}; };
  struct HbFace {
    std::string name, type, boundary;
    std::vector<Vec3> vertices;
  };
  std::vector<HbFace> hb_faces;
  for (const Face& f : faces(x0, y0)) {
    if (f.name.rfind("south", 0) == 0 || f.name == "opening") continue;
    const std::string type = f.name == "floor" ? "Floor" : f.name == "ceiling" ? "RoofCeiling" : "Wall";
    hb_faces.push_back({f.name, type, f.name == "floor" ? "Ground" : "Outdoors", f.vertices});
  }
  hb_faces.push_back({"south", "Wall", "Outdoors", {p(0, 0, 0), p(6, 0, 0), p(6, 0, 3), p(0, 0, 3)}});
  std::ostringstream hb;
  hb << "{\"type\": \"Model\", \"identifier\": \"survey_room\", \"units\": \"Meters\", \"tolerance\": 0.001,\n"
        " \"properties\": {\"type\": \"ModelProperties\", \"radiance\": {\"type\": \"ModelRadianceProperties\",\n"
        "  \"modifiers\": [{\"type\": \"Plastic\", \"identifier\": \"hb_black\", \"r_reflectance\": 0,"
        " \"g_reflectance\": 0, \"b_reflectance\": 0}],\n"
        "  \"sensor_grids\": [{\"type\": \"SensorGrid\", \"identifier\": \"depth\", \"sensors\": [";
  for (std::size_t i = 0; i < SensorsInRoom.size(); ++i) {
    const Vec3& s = SensorsInRoom[i];
    hb << (i ? ", " : "") << "{\"pos\": " << point(x0 + s.x, y0 + s.y, s.z) << ", \"dir\": [0, 0, 1]}";
  }
  hb << "]}]}},\n \"rooms\": [{\"type\": \"Room\", \"identifier\": \"room\", \"faces\": [\n";
  for (std::size_t i = 0; i < hb_faces.size(); ++i) {
    const HbFace& f = hb_faces[i];
    hb << (i ? ",\n" : "") << "  {\"type\": \"Face\", \"identifier\": \"" << f.name << "\", \"face_type\": \"" << f.type
       << "\", \"boundary_condition\": {\"type\": \"" << f.boundary << "\"}, \"geometry\": {\"type\": \"Face3D\", "
       << "\"boundary\": " << loop(f.vertices) << "}, \"properties\": {\"type\": \"FacePropertiesAbridged\", "
       << "\"radiance\": {\"type\": \"FaceRadiancePropertiesAbridged\", \"modifier\": \"hb_black\"}}";
    if (f.name == "south")
      hb << ", \"apertures\": [{\"type\": \"Aperture\", \"identifier\": \"opening\", \"boundary_condition\": "
            "{\"type\": \"Outdoors\"}, \"geometry\": {\"type\": \"Face3D\", \"boundary\": "
         << loop({p(1, 0, 0.9), p(5, 0, 0.9), p(5, 0, 2.4), p(1, 0, 2.4)}) << "}}]";
    hb << "}";
  }
  hb << "]}]}\n";
  std::ofstream(dir / "model.hbjson") << hb.str();
  return Head + "geometry:\n  honeybee: model.hbjson\nsensors:\n  honeybee_grids: all\n" + Tail;
}

/// Path 4: Wavefront OBJ meshes, as exported at survey coordinates: the room (usemtl black)
/// and the opening (a port of the project's opening material), the sensors as YAML points.
std::string obj_project(const fs::path& dir, double x0, double y0) {
  std::ofstream room(dir / "room.obj"), opening(dir / "opening.obj");
  room << "# the room\nusemtl black\n";
  std::size_t next = 1;
  for (const Face& f : faces(x0, y0)) {
    std::ofstream& out = f.material == "hole" ? opening : room;
    const std::size_t first = f.material == "hole" ? 1 : next;
    for (const Vec3& v : f.vertices) out << "v " << number(v.x) << ' ' << number(v.y) << ' ' << number(v.z) << "\n";
    out << "f";
    for (std::size_t i = 0; i < f.vertices.size(); ++i) out << ' ' << first + i;
    out << "\n";
    if (f.material != "hole") next += f.vertices.size();
  }
  std::string yaml = Head +
                     "geometry:\n  meshes:\n"
                     "    - {name: room, file: room.obj, material_map: {black: black}}\n"
                     "    - {name: opening, file: opening.obj, default_material: hole, port: true}\n"
                     "sensors:\n  points:\n    - name: depth\n      points: [";
  for (std::size_t i = 0; i < SensorsInRoom.size(); ++i) {
    const Vec3& s = SensorsInRoom[i];
    yaml += std::string(i ? ", " : "") + "[" + number(x0 + s.x) + ", " + number(y0 + s.y) + ", " + number(s.z) +
            ", 0, 0, 1]";
  }
  return yaml + "]\n" + Tail;
}

std::string text_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The CSV's rows split into cells (header left out).
std::vector<std::vector<std::string>> rows_of(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) row.push_back(c);
    rows.push_back(row);
  }
  return rows;
}

struct Outputs {
  std::string sensors_csv, df_csv;
  nlohmann::json results;
};

using ProjectText = std::string (*)(const fs::path&, double, double);

/// Runs the project `make` writes for the room at (x0, y0); `reflectance` (e.g. "0.5")
/// replaces the black material's 0; `region` gives it a region of interest around the room.
Outputs run(ProjectText make, const std::string& name, double x0, double y0, const std::string& reflectance = "0",
            bool region = false) {
  const fs::path dir = test::process_temp_dir() / ("dayphoton_survey_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string yaml = make(dir, x0, y0);
  const std::string black = "black: {type: lambertian, reflectance: 0}";
  yaml.replace(yaml.find(black), black.size(), "black: {type: lambertian, reflectance: " + reflectance + "}");
  if (region) {
    const std::string simulation = "simulation: {";
    yaml.replace(yaml.find(simulation), simulation.size(),
                 simulation + "region_of_interest: {origin: " + point(x0 - 0.5, y0 - 0.5, -0.5) +
                     ", size: [7, 9, 4]}, ");
  }
  std::ofstream(dir / "project.yaml") << yaml;
  test::run_file_in_fresh_folder(dir / "project.yaml", dir / "out");
  Outputs o{text_of(dir / "out" / "depth" / "sensors.csv"), text_of(dir / "out" / "depth" / "daylight_factor.csv"),
            nlohmann::json::parse(text_of(dir / "out" / "results.json"))};
  fs::remove_all(dir);
  return o;
}

/// The closed-form daylight factor (%) at an upward sensor `at` (room coordinates).
double closed_form_df_percent(const Vec3& at) {
  constexpr int Nx = 200, Nz = 75;  // the opening x 1..5, z 0.9..2.4 in the wall y = 0
  const double dx = 4.0 / Nx, dz = 1.5 / Nz;
  double sum = 0;  // integral of (1 + 2 sin a) / 3 cos(theta) d omega, L_z = 1
  for (int i = 0; i < Nx; ++i)
    for (int j = 0; j < Nz; ++j) {
      const Vec3 to = Vec3{1.0 + (i + 0.5) * dx, 0.0, 0.9 + (j + 0.5) * dz} - at;
      const double r = length(to);
      const Vec3 w = to / r;
      sum += (1 + 2 * w.z) / 3 * w.z * (-w.y) / (r * r) * dx * dz;
    }
  return 100 * sum / (7 * M_PI / 9);
}

/// `glazed_reference`: the opening is glazed (Honeybee's apertures are glass), so the origin is
/// compared with the YAML polygons glazed alike instead of the closed form.
void expect_same_room(ProjectText make, const std::string& path_name, ProjectText glazed_reference = nullptr) {
  const Outputs at_origin = run(make, path_name + "_origin", 0, 0);
  const auto origin_rows = rows_of(at_origin.df_csv);
  ASSERT_EQ(origin_rows.size(), SensorsInRoom.size());
  if (!glazed_reference) {
    // Against the closed form, at the origin.
    for (std::size_t i = 0; i < SensorsInRoom.size(); ++i) {
      const double expected = closed_form_df_percent(SensorsInRoom[i]);
      EXPECT_NEAR(std::stod(origin_rows[i].at(4)), expected, 0.01 * expected) << path_name << " sensor " << i;
    }
  } else {
    // Against the same glazing drawn as YAML polygons: the sky component through glass of
    // normal transmittance 0.64 by 64 shadow rays per bin in each (the error of either against
    // its exact value stays below 0.7 %, as the open room's against the closed form).
    const auto reference = rows_of(run(glazed_reference, path_name + "_reference", 0, 0).df_csv);
    ASSERT_EQ(reference.size(), SensorsInRoom.size());
    for (std::size_t i = 0; i < SensorsInRoom.size(); ++i) {
      const double expected = std::stod(reference[i].at(4));
      EXPECT_NEAR(std::stod(origin_rows[i].at(4)), expected, 0.015 * expected) << path_name << " sensor " << i;
      // The glass is there: below the open opening's sky component, above half of it.
      EXPECT_LT(expected, 0.66 * closed_form_df_percent(SensorsInRoom[i])) << "sensor " << i;
      EXPECT_GT(expected, 0.5 * closed_form_df_percent(SensorsInRoom[i])) << "sensor " << i;
    }
  }
  for (const auto& [x0, y0] : {std::pair{500000.0, 5000000.0}, std::pair{500000.0, 9999000.0}}) {
    const Outputs moved = run(make, path_name + "_utm_" + std::to_string(long(y0)), x0, y0);
    const auto rows = rows_of(moved.df_csv), sensor_rows = rows_of(moved.sensors_csv);
    ASSERT_EQ(rows.size(), SensorsInRoom.size()) << path_name << " at y " << y0;
    ASSERT_EQ(sensor_rows.size(), SensorsInRoom.size());
    const nlohmann::json& sensors = moved.results.at("cases").at(0).at("grids").at(0).at("sensors");
    ASSERT_EQ(sensors.size(), SensorsInRoom.size());
    for (std::size_t i = 0; i < SensorsInRoom.size(); ++i) {
      const Vec3 input{x0 + SensorsInRoom[i].x, y0 + SensorsInRoom[i].y, SensorsInRoom[i].z};
      // The daylight factor and its standard error: the same bytes as at the origin.
      EXPECT_EQ(std::vector<std::string>(rows[i].begin() + 4, rows[i].end()),
                std::vector<std::string>(origin_rows[i].begin() + 4, origin_rows[i].end()))
          << path_name << " sensor " << i << " at y " << y0;
      // Positions: the user's input, in every output that gives them.
      for (const auto* r : {&rows[i], &sensor_rows[i]}) {
        EXPECT_EQ(std::stod(r->at(1)), input.x) << path_name << " sensor " << i;
        EXPECT_EQ(std::stod(r->at(2)), input.y) << path_name << " sensor " << i;
        EXPECT_EQ(std::stod(r->at(3)), input.z) << path_name << " sensor " << i;
      }
      const nlohmann::json& p = sensors.at(i).at("position_m");
      EXPECT_EQ(p.at(0).get<double>(), input.x);
      EXPECT_EQ(p.at(1).get<double>(), input.y);
      EXPECT_EQ(p.at(2).get<double>(), input.z);
    }
    // The opening drawn on the plans: where the user drew it.
    const nlohmann::json& openings = moved.results.at("cases").at(0).at("openings");
    ASSERT_EQ(openings.size(), 1u);
    for (const nlohmann::json& v : openings.at(0)) {
      EXPECT_GE(v.at(0).get<double>(), x0 + 1);
      EXPECT_LE(v.at(0).get<double>(), x0 + 5);
      EXPECT_EQ(v.at(1).get<double>(), y0);
    }
  }
}

TEST(SurveyCoordinates, PolygonsAndAPtsFileAtUtmCoordinatesReadAsAtTheOrigin) {
  expect_same_room(polygons_project, "polygons");
}

TEST(SurveyCoordinates, ARadianceSceneAtUtmCoordinatesReadsAsAtTheOrigin) {
  expect_same_room(radiance_project, "radiance");
}

// A Honeybee model exported at survey coordinates (its faces, aperture and sensor grid in
// metres east and north of the UTM origin) reads as the same model at the origin.
TEST(SurveyCoordinates, AHoneybeeModelAtUtmCoordinatesReadsAsAtTheOrigin) {
  expect_same_room(honeybee_project, "honeybee", glazed_polygons_project);
}

// OBJ meshes exported at survey coordinates, likewise.
TEST(SurveyCoordinates, ObjMeshesAtUtmCoordinatesReadAsAtTheOrigin) {
  expect_same_room(obj_project, "obj");
}

// The photons too: with walls, floor and ceiling of reflectance 0.5 (a photon part of about
// half the daylight factor at the back), the room at a UTM northing of 9 999 km gives the
// origin's daylight factors, the same bytes. Photon positions are floats in the engine's
// coordinates: before the local origin such a room was refused beyond 100 km, and before that
// read 2-3 times its daylight factor at a northing of 4 200 km. With a region of interest
// (in the user's coordinates, as the model), which must move with the scene: left in the
// user's coordinates it would store no photon.
TEST(SurveyCoordinates, AReflectingRoomsPhotonsAtUtmCoordinatesReadAsAtTheOrigin) {
  const Outputs at_origin = run(polygons_project, "grey_origin", 0, 0, "0.5", true);
  const Outputs moved = run(polygons_project, "grey_utm", 500000, 9999000, "0.5", true);
  const auto origin_rows = rows_of(at_origin.df_csv), rows = rows_of(moved.df_csv);
  ASSERT_EQ(rows.size(), SensorsInRoom.size());
  ASSERT_EQ(origin_rows.size(), SensorsInRoom.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    // More light than the black room's sky component: the photons are there.
    EXPECT_GT(std::stod(origin_rows[i].at(4)), 1.05 * closed_form_df_percent(SensorsInRoom[i])) << "sensor " << i;
    EXPECT_EQ(std::vector<std::string>(rows[i].begin() + 4, rows[i].end()),
              std::vector<std::string>(origin_rows[i].begin() + 4, origin_rows[i].end()))
        << "sensor " << i;
  }
}

// What stays refused: a model larger than the photon positions' limit about its centre, a
// located error at its farthest surface.
TEST(SurveyCoordinates, AModelMoreThan200KmAcrossIsALocatedError) {
  const fs::path dir = test::process_temp_dir() / "dayphoton_survey_too_large";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string yaml = polygons_project(dir, 500000, 5000000);
  // A shading polygon 250 km east of the room.
  yaml.replace(yaml.find("sensors:\n"), 0,
               "    - {name: far_shade, material: black, vertices: [[750000, 5000000, 0], [750010, 5000000, 0], "
               "[750010, 5000000, 10]]}\n");
  std::ofstream(dir / "project.yaml") << yaml;
  const project::Project project = project::load_project((dir / "project.yaml").string());
  const SceneDescription description = project::build_scene_description(project);
  try {
    (void)engine::Scene::build(description);
    FAIL() << "a model 250 km across was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("project.yaml:"), std::string::npos) << what;
    EXPECT_NE(what.find("'far_shade'"), std::string::npos) << what;
    EXPECT_NE(what.find("m across"), std::string::npos) << what;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dayphoton::study
