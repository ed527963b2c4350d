// Daylight systems as project-file generators (issue 6 item 2; project/src/*_generator.cpp,
// project/src/system_generators.cpp, docs/daylight-systems.md):
// - every system type loads with its keys and defaults, and every input error has its
//   exact message at the exact line:column (unknown window, bad combinations, variants);
// - the geometry of each generator: light shelves (thin and slab, tilt), overhang, fins
//   (left/right seen from outside), blinds (count, angle sign, crown), prismatic and
//   lamella panels and dielectric CPCs as closed solids with outward normals (checked by
//   edge pairing and a positive divergence-theorem volume equal to the profile's area
//   times the length), CPC walls that reflect the edge rays onto the opposite exit edge
//   (the defining property of the profile), light pipes (ceiling opening + diffuser = the
//   ceiling's area, tube, dome), port enclosures (the window stops being a port, the box
//   encloses the system, its faces face in);
// - the generators produce the same surfaces as tests/engine/system_scenes.h for the
//   engine's acceptance tests (mirror shelf, shelf slab and enclosure, light pipes, Y-glass);
// - placement errors: interior parts through the wall or outside the room, light pipes
//   outside the ceiling or overlapping, an enclosure over another window;
// - variants change a system's keys (blind angle, enabled) and build a different scene;
// - the example projects load and build.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "../engine/system_scenes.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/polygon.h"
#include "dayphoton/core/units.h"
#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

namespace test_engine = dayphoton::engine::test;

const std::string ProjectsDir = std::string(DAYPHOTON_SOURCE_DIR) + "/projects";
const std::string FakePath = ProjectsDir + "/office/systems_snippet.yaml";

// Lines 1-19; systems snippets start at line 20.
const std::string Base =
    "version: 1\n"
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "outputs: {annual_illuminance: false, metrics: false}\n"
    "materials:\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "  glass: {type: glass, transmittance: 0.6}\n"
    "  open: {type: opening}\n"
    "  mirror: {type: mirror, reflectance: 0.85}\n"
    "  pmma: {type: dielectric, refractive_index: 1.49}\n"
    "  diffuser: {type: translucent, reflectance: 0.85, transmissivity: 0.6}\n"
    "geometry:\n"
    "  rooms:\n"
    "    - name: room\n"
    "      size: [4, 6, 3]\n"
    "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
    "      windows:\n"
    "        - {name: win, wall: south, width: 3, height: 2, sill: 1, offset: 0.5, material: glass}\n"
    "        - {name: back, wall: north, width: 2, height: 1, sill: 1, offset: 1, material: glass}\n"
    "  systems:\n";

Project load(const std::string& systems, const std::string& tail = "") {
  return load_project_from_string(Base + systems + tail, FakePath);
}

SceneDescription build(const std::string& systems, const std::string& tail = "") {
  return build_scene_description(load(systems, tail));
}

/// "line:col: message" for each diagnostic of loading and building, or nothing.
std::vector<std::string> errors_of(const std::string& systems, const std::string& tail = "") {
  return test::located_errors([&] { build(systems, tail); });
}

std::vector<const Surface*> with_prefix(const SceneDescription& d, const std::string& prefix) {
  std::vector<const Surface*> out;
  for (const Surface& s : d.surfaces)
    if (s.name.compare(0, prefix.size(), prefix) == 0) out.push_back(&s);
  return out;
}

const Surface& named(const SceneDescription& d, const std::string& name) {
  for (const Surface& s : d.surfaces)
    if (s.name == name) return s;
  throw std::runtime_error("no surface " + name);
}

/// Same polygon: same vertices in the same cyclic order (so the same normal).
bool same_polygon(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double tol = 1e-9) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    bool all = true;
    for (std::size_t i = 0; i < a.size() && all; ++i) all = length(a[i] - b[(i + k) % a.size()]) < tol;
    if (all) return true;
  }
  return false;
}

/// Every polygon of `generated` matches exactly one of `expected` (and vice versa), with
/// the same material name.
void expect_same_surfaces(const SceneDescription& gd, const std::vector<const Surface*>& generated,
                          const SceneDescription& ed, const std::vector<const Surface*>& expected) {
  ASSERT_EQ(generated.size(), expected.size());
  std::vector<bool> used(expected.size(), false);
  for (const Surface* g : generated) {
    bool found = false;
    for (std::size_t i = 0; i < expected.size() && !found; ++i)
      if (!used[i] && same_polygon(g->vertices, expected[i]->vertices) &&
          gd.materials[g->material].name == ed.materials[expected[i]->material].name &&
          g->port == expected[i]->port)
        used[i] = found = true;
    EXPECT_TRUE(found) << "generated " << g->name << " has no twin in the test scene";
  }
}

/// Closed surface with outward normals: every directed edge meets its reverse exactly once
/// (vertices equal to 1e-9 m), and the divergence-theorem volume is positive; returns it.
double closed_volume(const std::vector<const Surface*>& faces) {
  struct Edge {
    Vec3 a, b;
  };
  std::vector<Edge> edges;
  double volume = 0;
  for (const Surface* f : faces) {
    const auto& v = f->vertices;
    for (std::size_t i = 0; i < v.size(); ++i) edges.push_back({v[i], v[(i + 1) % v.size()]});
    for (std::size_t i = 1; i + 1 < v.size(); ++i) volume += dot(v[0], cross(v[i], v[i + 1])) / 6;
  }
  for (const Edge& e : edges) {
    int reverse = 0;
    for (const Edge& o : edges) reverse += length(o.a - e.b) < 1e-9 && length(o.b - e.a) < 1e-9;
    EXPECT_EQ(reverse, 1) << "edge (" << e.a.x << ", " << e.a.y << ", " << e.a.z << ") -> (" << e.b.x
                          << ", " << e.b.y << ", " << e.b.z << ") is not shared exactly once";
  }
  EXPECT_GT(volume, 0) << "normals point into the solid";
  return volume;
}

double area_of(const std::vector<const Surface*>& faces) {
  double a = 0;
  for (const Surface* f : faces) a += polygon_area_m2(f->vertices);
  return a;
}

// ---- loading ------------------------------------------------------------------------

TEST(Systems, EveryTypeLoadsWithItsKeysAndDefaults) {
  const Project p = load(
      "    - {type: light_shelf, name: shelf, window: win, height: 2.2, depth: 0.6, material: mirror}\n"  // 20
      "    - {type: light_shelf, name: outer, window: win, side: exterior, height: 2.2, depth: 0.5,\n"
      "       thickness: 0.03, material: mirror, underside_material: walls, tilt: 10}\n"
      "    - {type: blinds, name: blinds, window: back, slat_width: 0.05, spacing: 0.045, material: mirror}\n"
      "    - {type: prismatic_panel, name: prisms, window: win, side: exterior, pitch: 0.02, material: pmma}\n"
      "    - {type: lamella_panel, name: yglass, window: win, thickness: 0.016, spacing: 0.01, material: pmma, top: 2.9}\n"
      "    - {type: cpc, name: cpc, window: back, acceptance_angle: 30, count: 4, material: mirror, enabled: false}\n"
      "    - {type: light_pipe, name: pipe, room: room, x: 2, y: 4, diameter: 0.4, length: 1,\n"
      "       tube_material: mirror, diffuser_material: diffuser, collector_material: glass}\n"
      "    - {type: overhang, name: roof, window: win, depth: 0.8, material: walls}\n"
      "    - {type: fins, name: fins, window: win, depth: 0.3, jambs: right, material: walls}\n");
  const auto& s = p.geometry.systems;
  ASSERT_EQ(s.size(), 9u);
  const char* types[] = {"light_shelf", "light_shelf", "blinds", "prismatic_panel", "lamella_panel",
                         "cpc", "light_pipe", "overhang", "fins"};
  for (std::size_t i = 0; i < s.size(); ++i) EXPECT_STREQ(s[i].type_name(), types[i]);
  const auto& shelf = std::get<LightShelfSpec>(s[0].params);
  EXPECT_EQ(s[0].mount.window, "win");
  EXPECT_EQ(s[0].mount.side, MountSide::Interior);
  EXPECT_EQ(s[0].mount.port, PortMode::Window);
  EXPECT_EQ(shelf.tilt_deg, 0);
  EXPECT_EQ(shelf.thickness_m, 0);
  EXPECT_TRUE(shelf.underside_material.empty());
  EXPECT_EQ(s[0].location_of("depth").line, 20);
  EXPECT_EQ(s[1].mount.port, PortMode::System);  // outside, its reflections are traced by default
  EXPECT_EQ(std::get<LightShelfSpec>(s[1].params).underside_material, "walls");
  EXPECT_EQ(s[1].location_of("tilt").line, 22);
  const auto& blinds = std::get<BlindsSpec>(s[2].params);
  EXPECT_EQ(blinds.facets, 4);
  EXPECT_EQ(blinds.angle_deg, 0);
  EXPECT_FALSE(blinds.offset_m.has_value());
  EXPECT_EQ(s[3].mount.port, PortMode::System);  // a transmitting panel too
  const auto& prisms = std::get<PrismaticPanelSpec>(s[3].params);
  EXPECT_EQ(prisms.apex_angle_deg, 90);
  EXPECT_FALSE(prisms.apex_outward);
  EXPECT_EQ(prisms.offset_m, 0.01);
  const auto& yglass = std::get<LamellaPanelSpec>(s[4].params);
  EXPECT_EQ(yglass.lamella_angle_deg, 7);
  EXPECT_EQ(yglass.gap_m, 0.0005);
  EXPECT_EQ(*yglass.top_m, 2.9);
  EXPECT_FALSE(yglass.bottom_m.has_value());
  EXPECT_FALSE(s[5].enabled);
  EXPECT_FALSE(std::get<CpcSpec>(s[5].params).dielectric);
  const auto& pipe = std::get<LightPipeSpec>(s[6].params);
  EXPECT_EQ(pipe.sides, 16);
  EXPECT_TRUE(pipe.dome);
  EXPECT_EQ(pipe.dome_rings, 4);
  EXPECT_EQ(s[7].mount.side, MountSide::Exterior);  // overhangs are outside
  EXPECT_EQ(s[7].mount.port, PortMode::System);     // and their reflections are traced
  const auto& fins = std::get<FinsSpec>(s[8].params);
  EXPECT_FALSE(fins.left);
  EXPECT_TRUE(fins.right);
}

struct BadCase {
  const char* name;
  std::string systems;                // from line 20
  std::vector<std::string> expected;  // "line:col: message"
};

TEST(Systems, EachInputErrorHasItsExactMessageAndLocation) {
  const std::vector<BadCase> cases = {
      {"unknown_type",
       "    - {type: light_shelve, name: a, window: win}\n",
       {"20:14: unknown value 'light_shelve' for 'type': expected one of light_shelf, blinds, "
        "prismatic_panel, lamella_panel, cpc, light_pipe, overhang, fins (did you mean 'light_shelf'?)"}},
      {"unknown_window",
       "    - {type: overhang, name: a, window: wn, depth: 1, material: walls}\n",
       {"20:41: unknown window 'wn' (did you mean 'win'?)"}},
      {"duplicate_name_and_missing_keys",
       "    - {type: overhang, name: a, window: win, depth: 1, material: walls}\n"
       "    - {type: fins, name: a, window: win}\n",
       {"21:26: duplicate system name 'a' (first defined at line 20)",
        "21:7: missing required key 'depth' in fins system",
        "21:7: missing required key 'material' in fins system"}},
      {"port_on_an_interior_system",
       "    - {type: blinds, name: b, window: win, port: enclosure, slat_width: 0.05, spacing: 0.04, material: walls}\n",
       {"20:50: 'port' applies to exterior systems only (inside the room the window is the photon port)"}},
      {"underside_of_a_thin_shelf",
       "    - {type: light_shelf, name: s, window: win, height: 2, depth: 0.5, material: mirror, underside_material: walls}\n",
       {"20:110: 'underside_material' needs a slab: give 'thickness' > 0 (a thin shelf is one polygon "
        "whose two sides share 'material')"}},
      {"dielectric_cpc_without_coating_and_reflective_with_one",
       "    - {type: cpc, name: c, window: win, acceptance_angle: 30, count: 3, kind: dielectric, material: pmma}\n"
       "    - {type: cpc, name: d, window: back, acceptance_angle: 30, count: 3, material: mirror, exit_material: mirror}\n",
       {"20:7: missing required key 'exit_material' in cpc system (a dielectric CPC's exit aperture is coated)",
        "21:107: 'exit_material' applies to kind: dielectric only (a reflective CPC's exit aperture is open)"}},
      {"out_of_range_and_unknown_key",
       "    - {type: blinds, name: b, window: win, slat_width: 0, spacing: 0.04, angle: 95, material: walls, colour: red}\n",
       {"20:56: 'slat_width' must be > 0, got 0",
        "20:81: 'angle' must be in [-90, 90], got 95",
        "20:102: unknown key 'colour' in blinds system"}},
      {"wrong_material_types",
       "    - {type: prismatic_panel, name: p, window: win, pitch: 0.02, material: glass}\n"
       "    - {type: blinds, name: b, window: back, slat_width: 0.05, spacing: 0.04, material: pmma}\n"
       "    - {type: light_pipe, name: l, room: room, x: 2, y: 3, diameter: 0.4, length: 1,\n"
       "       tube_material: mirror, diffuser_material: diffuser, collector_material: walls}\n",
       {"20:76: prismatic_panel 'p' needs a dielectric material, but 'glass' is glass",
        "21:88: blinds 'b' cannot use the dielectric 'pmma' for slats (a dielectric is the surface "
        "of a closed solid; give the part a thickness or use another material)",
        "23:80: light_pipe 'l': the collector is the photon port and must let light in (glass, "
        "glazing, opening or translucent), but 'walls' is lambertian"}},
      {"interior_blinds_through_the_glass",
       "    - {type: blinds, name: b, window: win, slat_width: 0.08, spacing: 0.06, angle: 45, offset: 0.02, material: walls}\n",
       {"20:7: blinds 'b' (interior) reaches 0.0083 m out of room 'room' through the wall plane; give "
        "it more offset or mount it outside"}},
      {"interior_shelf_deeper_than_the_room",
       "    - {type: light_shelf, name: s, window: win, height: 2, depth: 7, material: mirror}\n",
       {"20:7: light_shelf 's' (interior) reaches 7 m into room 'room', which is only 6 m deep"}},
      {"exterior_shelf_into_the_room",
       "    - {type: light_shelf, name: s, window: win, side: exterior, height: 2, depth: 0.05, tilt: -30,\n"
       "       thickness: 0.1, material: mirror}\n",
       {"20:7: light_shelf 's' (exterior) reaches 0.0057 m into room 'room' behind the wall plane; move "
        "it out (offset) or mount it inside"}},
      {"exterior_dielectric_behind_a_window_port",
       "    - {type: cpc, name: c, window: win, side: exterior, port: window, acceptance_angle: 25, count: 8,\n"
       "       kind: dielectric, material: pmma, exit_material: mirror}\n",
       {"20:63: cpc 'c' (exterior, port: window) transmits light, but outside its window's port every "
        "surface only shades: the window would be blocked; use port: system"}},
      {"light_pipe_outside_the_ceiling_and_overlapping",
       "    - {type: light_pipe, name: l, room: room, x: 3.9, y: 3, diameter: 0.4, length: 1,\n"
       "       tube_material: mirror, diffuser_material: diffuser, collector_material: glass}\n"
       "    - {type: light_pipe, name: m, room: room, x: 2, y: 3, diameter: 0.4, length: 1,\n"
       "       tube_material: mirror, diffuser_material: diffuser, collector_material: glass}\n"
       "    - {type: light_pipe, name: n, room: room, x: 2.3, y: 3, diameter: 0.4, length: 1,\n"
       "       tube_material: mirror, diffuser_material: diffuser, collector_material: glass}\n",
       {"20:50: light_pipe 'l' (diameter 0.4 m at x = 3.9, y = 3) does not fit in the ceiling of "
        "room 'room' (x 0 to 4, y 0 to 6)",
        "24:7: light_pipe 'n' overlaps light_pipe 'm' (axes 0.3 m apart)"}},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(errors_of(c.systems), c.expected);
  }
}

// ---- geometry -----------------------------------------------------------------------

TEST(Systems, AnEnclosureMustNotCoverAnotherWindow) {
  // Two windows in the south wall; the overhang's enclosure over the upper one would cover
  // the lower one, which is a port of its own.
  const std::string text =
      Base.substr(0, Base.find("geometry:")) +
      "geometry:\n"                                                                        // 11
      "  rooms:\n"
      "    - name: room\n"
      "      size: [4, 6, 3]\n"
      "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
      "      windows:\n"
      "        - {name: view, wall: south, width: 3, height: 1, sill: 0.8, material: glass}\n"
      "        - {name: clerestory, wall: south, width: 3, height: 0.6, sill: 2.2, material: glass}\n"
      "  systems:\n"
      "    - {type: overhang, name: o, window: clerestory, depth: 1.5, height: 2.9, port: enclosure,\n"  // 20
      "       tilt: -60, material: walls}\n";
  const std::vector<std::string> got =
      test::located_errors([&] { build_scene_description(load_project_from_string(text, FakePath)); });
  EXPECT_EQ(got, std::vector<std::string>{
                     "20:7: overhang 'o': the port enclosure of window 'clerestory' (-0.01 m to 3.01 m "
                     "along the wall, heights 1.591 m to 2.91 m) covers window 'view', which would be a "
                     "second port behind it; use port: system or move the system"});
}

TEST(Systems, InteriorMirrorShelfIsTheEngineTestShelf) {
  // The engine's footprint test (daylight_systems_test.cpp) uses a 0.6 m mirror shelf at
  // 1.5 m across a south window x 0.5..3.5: the generator's thin interior shelf is that
  // polygon (normal up).
  const SceneDescription d =
      build("    - {type: light_shelf, name: shelf, window: win, height: 1.5, depth: 0.6, material: mirror}\n");
  SceneDescription t;
  test_engine::add_spec(t, test_engine::grey("mirror", MaterialType::Mirror, 0.85));
  test_engine::add_facing(t, "shelf", 0, test_engine::rect_z(0.5, 3.5, 0, 0.6, 1.5), {0, 0, 1});
  expect_same_surfaces(d, with_prefix(d, "shelf"), t, with_prefix(t, "shelf"));
  EXPECT_TRUE(named(d, "room.win").port);
}

TEST(Systems, ExteriorSlabShelfInItsEnclosureIsTheEngineTestScene) {
  // The engine's energy-balance scene: an exterior slab shelf 0.5 m deep, 3 cm thick, top
  // at 2.2 m, mirror top and Lambertian rest, with the port enclosure around it and the
  // window (x 0.5..3.5, z 1.0..2.8), which stops being a port.
  const std::string window_room =
      "geometry:\n  rooms:\n    - name: room\n      size: [4, 6, 3]\n"
      "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
      "      windows: [{name: win, wall: south, width: 3, height: 1.8, sill: 1, offset: 0.5, material: glass}]\n"
      "  systems:\n"
      "    - {type: light_shelf, name: shelf_out, window: win, side: exterior, port: enclosure,\n"
      "       height: 2.2, depth: 0.5, thickness: 0.03, material: mirror, underside_material: walls}\n";
  std::string text = Base.substr(0, Base.find("geometry:")) + window_room;
  const SceneDescription d = build_scene_description(load_project_from_string(text, FakePath));
  SceneDescription t;
  const int mirror = test_engine::add_spec(t, test_engine::grey("mirror", MaterialType::Mirror, 0.85));
  const int walls = test_engine::add_spec(t, test_engine::grey("walls", MaterialType::Lambertian, 0.5));
  const int open = test_engine::add_spec(t, test_engine::material_of("system port opening", MaterialType::Opening));
  test_engine::add_box(t, "shelf_out", {0.5, -0.501, 2.17}, {3.5, -0.001, 2.2}, mirror, walls);
  test_engine::add_enclosure(t, open, 0.49, 3.51, 0.99, 2.81, 0.511);
  expect_same_surfaces(d, with_prefix(d, "shelf_out"), t, with_prefix(t, "shelf_out"));
  expect_same_surfaces(d, with_prefix(d, "win.enclosure"), t, with_prefix(t, "enclosure"));
  EXPECT_NEAR(closed_volume(with_prefix(d, "shelf_out")), 3 * 0.5 * 0.03, 1e-12);
  EXPECT_FALSE(named(d, "room.win").port);
  EXPECT_EQ(d.materials.back().type, MaterialType::Opening);
  int ports = 0;
  for (const Surface& s : d.surfaces) ports += s.port;
  EXPECT_EQ(ports, 5);
}

TEST(Systems, TiltedSlabShelfIsAClosedSolidAwayFromTheWall) {
  // Tilt 15 degrees (free edge up), interior: the slab's wall-side face is vertical, 1 mm
  // from the wall; its cross-section is the trapezoid of projection_generators.cpp whose
  // area is depth t + t^2 tan(a) / 2.
  const SceneDescription d = build(
      "    - {type: light_shelf, name: s, window: win, height: 2.0, depth: 0.8, tilt: 15, thickness: 0.04,\n"
      "       material: mirror, underside_material: walls, extension: 0.2}\n");
  const auto faces = with_prefix(d, "s.");
  ASSERT_EQ(faces.size(), 6u);
  const double a = 15 * Pi / 180, t = 0.04;
  EXPECT_NEAR(closed_volume(faces), (0.8 * t + 0.5 * t * t * std::tan(a)) * 3.4, 1e-12);
  double y_min = 1e9, z_max = -1e9;
  for (const Surface* f : faces)
    for (const Vec3& v : f->vertices) {
      y_min = std::min(y_min, v.y);
      z_max = std::max(z_max, v.z);
    }
  EXPECT_NEAR(y_min, 0.001, 1e-12);                       // standoff from the wall
  EXPECT_NEAR(z_max, 2.0 + 0.8 * std::sin(a), 1e-12);      // free edge raised
  EXPECT_EQ(d.materials[named(d, "s.side0").material].name, "mirror");  // the top
}

TEST(Systems, OverhangAndFinsSitOutsideTheirWindow) {
  // North window "back" (x 1..3 in the wall y = 6, z 1..2): seen from outside (looking
  // south) the LEFT jamb is the east one, x = 3. Overhang at the head by default.
  const SceneDescription d = build(
      "    - {type: overhang, name: o, window: back, depth: 0.6, extension: 0.25, material: walls}\n"
      "    - {type: fins, name: f, window: back, depth: 0.4, jambs: left, offset: 0.1, material: walls}\n");
  const Surface& o = named(d, "o");
  for (const Vec3& v : o.vertices) EXPECT_NEAR(v.z, 2.0, 1e-12);
  double y_max = 0, x_min = 1e9, x_max = -1e9;
  for (const Vec3& v : o.vertices) {
    y_max = std::max(y_max, v.y);
    x_min = std::min(x_min, v.x);
    x_max = std::max(x_max, v.x);
  }
  EXPECT_NEAR(y_max, 6.6, 1e-12);
  EXPECT_NEAR(x_min, 0.75, 1e-12);
  EXPECT_NEAR(x_max, 3.25, 1e-12);
  const Surface& f = named(d, "f.left");
  for (const Vec3& v : f.vertices) EXPECT_NEAR(v.x, 3.1, 1e-12);
  EXPECT_TRUE(named(d, "room.back").port);  // shading only: the window stays the port
  EXPECT_TRUE(with_prefix(d, "back.enclosure").empty());
}

TEST(Systems, BlindsCountAngleAndCrown) {
  // Window "win" z 1..3: 2 / 0.045 -> 44 slats 45 mm apart, centred. Angle 30: the
  // window-side edge (toward y = 0) is lower than the room-side edge; crown 5 mm with 4
  // facets: the slat's middle rises 5 mm above its chord (perpendicular to it).
  const SceneDescription d = build(
      "    - {type: blinds, name: b, window: win, slat_width: 0.05, spacing: 0.045, angle: 30,\n"
      "       crown: 0.005, facets: 4, offset: 0.05, material: walls}\n");
  std::map<int, std::vector<const Surface*>> slats;
  for (const Surface* s : with_prefix(d, "b.slat")) {
    const std::string rest = s->name.substr(6);
    slats[std::stoi(rest.substr(0, rest.find('.')))].push_back(s);
  }
  ASSERT_EQ(slats.size(), 44u);
  for (const auto& [k, facets] : slats) ASSERT_EQ(facets.size(), 4u) << k;
  // Slat 1: its profile at x = 0.5 (the window's left edge).
  std::vector<Vec3> profile;
  for (const Surface* f : slats[1])
    for (const Vec3& v : f->vertices)
      if (std::fabs(v.x - 0.5) < 1e-12) profile.push_back(v);
  std::sort(profile.begin(), profile.end(), [](const Vec3& a, const Vec3& b) { return a.y < b.y; });
  const Vec3 window_edge = profile.front(), room_edge = profile.back();
  EXPECT_LT(window_edge.z, room_edge.z);
  const Vec3 chord = room_edge - window_edge;
  EXPECT_NEAR(length(chord), 0.05, 1e-12);
  EXPECT_NEAR(std::atan2(chord.z, chord.y) * 180 / Pi, 30, 1e-9);
  const Vec3 middle = 0.5 * (window_edge + room_edge);
  const Vec3 up = normalize(Vec3{0, -chord.z, chord.y});
  double rise = 0;
  for (const Vec3& v : profile) rise = std::max(rise, dot(v - middle, up));
  EXPECT_NEAR(rise, 0.005, 1e-12);
  // Slat 1's axis (its chord's midpoint): 44 slats centred on 2.0 m, `offset` from the glass.
  EXPECT_NEAR(middle.z, 2.0 - 21.5 * 0.045, 1e-12);
  EXPECT_NEAR(middle.y, 0.05, 1e-12);
}

TEST(Systems, PrismaticPanelIsAStackOfClosedPrisms) {
  // Covered 2.2..3.0 m, pitch 0.02 -> 40 prisms; apex 90 degrees: height 0.01 m; volume
  // of each pitch * height / 2 * width 3 m. With a 2 mm backing: one solid, volume + plate.
  const SceneDescription d = build(
      "    - {type: prismatic_panel, name: p, window: win, pitch: 0.02, bottom: 2.2, material: pmma}\n"
      "    - {type: prismatic_panel, name: q, window: back, pitch: 0.02, backing: 0.002, apex: outward,\n"
      "       material: pmma}\n");
  int prisms = 0;
  double volume = 0;
  for (int k = 1; k <= 40; ++k) {
    const auto faces = with_prefix(d, "p.prism" + std::to_string(k) + ".");
    ASSERT_EQ(faces.size(), 5u) << k;
    volume += closed_volume(faces);
    ++prisms;
  }
  EXPECT_TRUE(with_prefix(d, "p.prism41.").empty());
  EXPECT_NEAR(volume, 40 * 0.02 * 0.01 / 2 * 3, 1e-12);
  // Interior panel, apexes into the room: the apexes reach y = 0.01 + 0.01.
  double y_max = 0;
  for (const Surface* f : with_prefix(d, "p.")) for (const Vec3& v : f->vertices) y_max = std::max(y_max, v.y);
  EXPECT_NEAR(y_max, 0.02, 1e-12);
  const auto panel = with_prefix(d, "q.panel.");
  EXPECT_NEAR(closed_volume(panel), (50 * 0.02 * 0.01 / 2 + 1.0 * 0.002) * 2, 1e-12);
  // North window, interior, apexes outward = toward the glass (y = 6): the flat face is
  // toward the room, 0.01 + 0.012 from the wall.
  double y_min = 1e9;
  for (const Surface* f : panel) for (const Vec3& v : f->vertices) y_min = std::min(y_min, v.y);
  EXPECT_NEAR(y_min, 6 - 0.022, 1e-12);
}

TEST(Systems, LamellaPanelIsTheEngineTestYGlass) {
  // The engine's Y-glass scene: PMMA 16 mm, lamellae 10 mm apart at 7 degrees, 0.5 mm gaps,
  // 1 cm behind the window's upper part z 2.0..2.8 of a window x 0.5..3.5.
  const SceneDescription d = build(
      "    - {type: lamella_panel, name: panel, window: win, thickness: 0.016, spacing: 0.01,\n"
      "       lamella_angle: 7, gap: 0.0005, offset: 0.01, bottom: 2.0, top: 2.8, material: pmma}\n");
  SceneDescription t;
  const int pmma = test_engine::add_spec(t, test_engine::dielectric_of("pmma", 1.49));
  test_engine::add_lamella_panel(t, pmma, 0.5, 3.5, 2.0, 2.8, 0.01, 0.016, 0.01, 7 * Pi / 180, 0.0005);
  expect_same_surfaces(d, with_prefix(d, "panel."), t, with_prefix(t, "panel."));
  // 80 strips, each closed; together the panel minus the 79 gaps (0.5 mm thick, 16 mm deep
  // measured along the lamella: 16 / cos 7 mm, i.e. 0.5 x 16 mm^2 in the vertical section
  // ... gap_v * T = 0.5 / cos 7 x 16 mm^2).
  double volume = 0;
  for (int k = 1; k <= 80; ++k) volume += closed_volume(with_prefix(d, "panel.strip" + std::to_string(k) + "."));
  const double gap_section = 0.0005 / std::cos(7 * Pi / 180) * 0.016;
  EXPECT_NEAR(volume, (0.8 * 0.016 - 79 * gap_section) * 3, 1e-12);
  // Lamellae slope: the room-side edge lower. Strip 2's bottom face at the outside face
  // (y = 0.01) is higher than at the room face (y = 0.026) by 16 mm x tan 7.
  const Surface& bottom = named(d, "panel.strip2.side0");
  double z_out = 0, z_in = 0;
  for (const Vec3& v : bottom.vertices) (std::fabs(v.y - 0.01) < 1e-12 ? z_out : z_in) = v.z;
  EXPECT_NEAR(z_out - z_in, 0.016 * std::tan(7 * Pi / 180), 1e-12);
}

/// A reflective CPC's upper wall (the CPC frame's right wall) as model points, exit to
/// entrance, read from the generated facets of trough 1 at x = 0.5 (window "win", south).
std::vector<Vec3> cpc_wall(const SceneDescription& d, const std::string& prefix) {
  std::vector<Vec3> points;
  for (const Surface* f : with_prefix(d, prefix))
    for (const Vec3& v : f->vertices)
      if (std::fabs(v.x - 0.5) < 1e-12 &&
          std::none_of(points.begin(), points.end(), [&](const Vec3& p) { return length(p - v) < 1e-12; }))
        points.push_back(v);
  std::sort(points.begin(), points.end(), [](const Vec3& a, const Vec3& b) { return a.y > b.y; });
  return points;  // exit (room side, larger y) first
}

TEST(Systems, CpcWallsReflectTheEdgeRaysOntoTheOppositeExitEdge) {
  // One reflective CPC of acceptance 30 degrees filling the window height (2 m): entrance
  // half width a = 1, exit half width a' = a sin 30 = 0.5, length L = (a + a') cot 30 =
  // 2.598 m (interior, entrance 1 cm behind the glass). The defining property (Welford &
  // Winston): a ray entering at the acceptance angle and meeting the upper wall is
  // reflected through the LOWER exit edge. Checked at every facet's midpoint with the
  // facet's own normal (64 facets: the chord's slope differs from the parabola's by
  // ~1/64 of the wall's turn, so the reflected ray misses the edge by < 2 mm).
  const SceneDescription d = build(
      "    - {type: cpc, name: c, window: win, acceptance_angle: 30, count: 1, facets: 64, material: mirror}\n");
  const std::vector<Vec3> upper = cpc_wall(d, "c.trough1.right");
  const std::vector<Vec3> lower = cpc_wall(d, "c.trough1.left");
  ASSERT_EQ(upper.size(), 65u);
  const double theta = 30 * Pi / 180;
  // Exit (room side) and entrance (window side) edges.
  EXPECT_NEAR(upper.front().z - lower.front().z, 2 * 0.5, 1e-9);
  EXPECT_NEAR(upper.back().z - lower.back().z, 2 * 1.0, 1e-9);
  EXPECT_NEAR(upper.back().z, 3.0, 1e-9);
  EXPECT_NEAR(lower.back().z, 1.0, 1e-9);
  EXPECT_NEAR(upper.back().y, 0.01, 1e-9);
  EXPECT_NEAR(upper.front().y - upper.back().y, 1.5 / std::tan(theta), 1e-9);
  const Vec3 focus = lower.front();
  // Extreme ray for the upper wall: travelling into the room (+y) and upward at theta.
  const Vec3 ray = normalize(Vec3{0, std::cos(theta), std::sin(theta)});
  for (std::size_t i = 0; i + 1 < upper.size(); ++i) {
    const Vec3 a = upper[i], b = upper[i + 1], mid = 0.5 * (a + b);
    const Vec3 tangent = normalize(b - a);
    const Vec3 normal = normalize(Vec3{0, -tangent.z, tangent.y});
    const Vec3 r = ray - normal * (2 * dot(ray, normal));
    // Distance from the focus to the reflected line.
    const Vec3 to_focus = focus - mid;
    const double miss = length(to_focus - r * dot(to_focus, r));
    EXPECT_LT(miss, 2e-3) << "facet " << i;
  }
  // The troughs tile the covered height; the walls' first and last points are the exact
  // aperture edges.
  const SceneDescription six = build(
      "    - {type: cpc, name: c, window: win, acceptance_angle: 30, count: 5, material: mirror}\n");
  EXPECT_EQ(with_prefix(six, "c.trough5.").size(), 16u);
  EXPECT_TRUE(with_prefix(six, "c.trough6.").empty());
}

TEST(Systems, DielectricCpcIsClosedWithACoatedExit) {
  // Exterior dielectric CPCs in a port enclosure; each trough one solid whose last profile
  // edge (the exit) is the coating; the profile's area is that of the CPC: the sum of the
  // trapezoids under the facets.
  const SceneDescription d = build(
      "    - {type: cpc, name: c, window: win, side: exterior, port: enclosure, acceptance_angle: 25,\n"
      "       count: 8, kind: dielectric, material: pmma, exit_material: mirror, tilt: 10}\n");
  for (int k = 1; k <= 8; ++k) {
    const auto faces = with_prefix(d, "c.trough" + std::to_string(k) + ".");
    ASSERT_EQ(faces.size(), 2u * 8 + 2 + 2) << k;  // two walls of 8 facets, entrance, exit, caps
    EXPECT_GT(closed_volume(faces), 0);
    int coated = 0;
    for (const Surface* f : faces) coated += d.materials[f->material].name == "mirror";
    EXPECT_EQ(coated, 1);
  }
  EXPECT_FALSE(named(d, "room.win").port);
  EXPECT_EQ(with_prefix(d, "win.enclosure.").size(), 5u);
}

TEST(Systems, LightPipesAreTheEngineTestPipes) {
  // The engine's pipes: 4 sides (a square 0.424 m wide), 1.2 m, glass dome of 3 rings, in
  // the ceiling at (1.5, 1.5) of a 3 x 3 x 2.7 m room; and 12 sides, flat opening collector.
  const std::string room =
      "geometry:\n  rooms:\n    - name: room\n      size: [3, 3, 2.7]\n"
      "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
      "  systems:\n"
      "    - {type: light_pipe, name: pipe, room: room, x: 1.5, y: 1.5, diameter: 0.6, length: 1.2,\n"
      "       sides: 4, dome_rings: 3, tube_material: mirror, diffuser_material: diffuser,\n"
      "       collector_material: glass}\n"
      "    - {type: light_pipe, name: flat, room: room, x: 0.5, y: 2.4, diameter: 0.5, length: 2,\n"
      "       sides: 12, collector: flat, tube_material: mirror, diffuser_material: diffuser,\n"
      "       collector_material: open}\n";
  const std::string text = Base.substr(0, Base.find("geometry:")) + room;
  const SceneDescription d = build_scene_description(load_project_from_string(text, FakePath));
  SceneDescription t;
  const int mirror = test_engine::add_spec(t, test_engine::grey("mirror", MaterialType::Mirror, 0.85));
  const int diffuser = test_engine::add_spec(t, test_engine::material_of("diffuser", MaterialType::Translucent));
  const int glass = test_engine::add_spec(t, test_engine::glass_of("glass", 0.6));
  const int open = test_engine::add_spec(t, test_engine::material_of("open", MaterialType::Opening));
  test_engine::add_light_pipe(t, 1.5, 1.5, 0.6, 2.7, 1.2, 4, mirror, diffuser, glass, 3);
  SceneDescription t2;
  for (const MaterialSpec& m : t.materials) t2.materials.push_back(m);
  test_engine::add_light_pipe(t2, 0.5, 2.4, 0.5, 2.7, 2.0, 12, mirror, diffuser, open, 0);
  expect_same_surfaces(d, with_prefix(d, "pipe."), t, with_prefix(t, "pipe."));
  expect_same_surfaces(d, with_prefix(d, "flat."), t2, with_prefix(t2, "pipe."));
  // The ceiling with its two openings plus the two diffusers cover the ceiling exactly.
  const auto ceiling = with_prefix(d, "room.ceiling");
  EXPECT_NEAR(area_of(ceiling) + area_of({&named(d, "pipe.diffuser"), &named(d, "flat.diffuser")}), 9.0, 1e-12);
  for (const Surface* c : ceiling) EXPECT_LT(polygon_normal(c->vertices).z, -0.999999);
  // Only the collectors are ports: 3 rings x 4 facets, and the flat one.
  int ports = 0;
  for (const Surface& s : d.surfaces) ports += s.port;
  EXPECT_EQ(ports, 13);
  // Tube area: sides x side length x length; side = 2 r sin(pi / n).
  EXPECT_NEAR(area_of(with_prefix(d, "flat.tube.")), 12 * 0.5 * std::sin(Pi / 12) * 2.0, 1e-12);
}

TEST(Systems, SixteenSidedPipeCeilingHasNoGapAndNoOverlap) {
  // A 16-gon opening: the ceiling pieces (rectangles around the opening's bounding box,
  // 16 ring pieces) and the diffuser cover the 4 x 6 m ceiling with total area 24 m^2;
  // and no point of the ceiling is covered twice: a 200 x 300 grid of sample points each
  // lies in exactly one piece (or the diffuser).
  const SceneDescription d = build(
      "    - {type: light_pipe, name: p, room: room, x: 1.3, y: 4.1, diameter: 0.45, length: 0.8,\n"
      "       tube_material: mirror, diffuser_material: diffuser, collector_material: glass}\n");
  auto pieces = with_prefix(d, "room.ceiling");
  pieces.push_back(&named(d, "p.diffuser"));
  EXPECT_NEAR(area_of(pieces), 24.0, 1e-12);
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 300; ++j) {
      const Vec3 q{(i + 0.5) * 4 / 200.0, (j + 0.5) * 6 / 300.0, 3.0};
      int inside = 0;
      for (const Surface* s : pieces) inside += polygon_contains(s->vertices, q);
      ASSERT_EQ(inside, 1) << q.x << ", " << q.y;
    }
}

TEST(Systems, VariantsChangeASystemsGeometry) {
  // Blinds open (base), tilted to 60 degrees and raised (disabled) as variants; a variant's
  // error points at the variant's own line.
  const std::string systems =
      "    - {type: blinds, name: blinds, window: win, slat_width: 0.05, spacing: 0.045, material: walls}\n";
  const std::string variants =
      "variants:\n"                                              // 21
      "  - name: tilted\n"                                       // 22
      "    systems: {blinds: {angle: 60}}\n"                     // 23
      "  - name: raised\n"                                       // 24
      "    systems: {blinds: {enabled: false}}\n"                // 25
      "  - name: glazing_and_blinds\n"                           // 26
      "    materials: {glass: {type: glass, transmittance: 0.4}}\n"
      "    systems: {blinds: {angle: 80, crown: 0.004}}\n";
  const Project p = load(systems, variants);
  ASSERT_EQ(p.variants.size(), 3u);
  const auto& tilted = std::get<BlindsSpec>(p.variants[0].systems.at(0).params);
  EXPECT_EQ(tilted.angle_deg, 60);
  EXPECT_EQ(tilted.slat_width_m, 0.05);  // the base's other keys
  EXPECT_EQ(p.variants[0].systems.at(0).location_of("angle").line, 23);
  EXPECT_EQ(p.variants[0].systems.at(0).location_of("spacing").line, 20);
  const SceneDescription base = build_scene_description(p);
  const SceneDescription t = build_scene_description(apply_variant(p, p.variants[0]));
  const SceneDescription r = build_scene_description(apply_variant(p, p.variants[1]));
  const SceneDescription g = build_scene_description(apply_variant(p, p.variants[2]));
  EXPECT_EQ(with_prefix(base, "blinds.").size(), 44u);
  ASSERT_EQ(with_prefix(t, "blinds.").size(), 44u);
  EXPECT_TRUE(with_prefix(r, "blinds.").empty());
  EXPECT_EQ(with_prefix(g, "blinds.").size(), 44u * 4);  // curved: 4 facets a slat
  EXPECT_FALSE(same_polygon(with_prefix(base, "blinds.")[0]->vertices, with_prefix(t, "blinds.")[0]->vertices));
  EXPECT_NEAR(g.materials[1].transmittance.x, 0.4, 0);
  EXPECT_EQ(base.surfaces.size() - 44, r.surfaces.size());  // the room is the same

  const std::vector<std::pair<std::string, std::vector<std::string>>> bad = {
      {"variants:\n  - name: v\n    systems: {blind: {angle: 60}}\n",
       {"23:15: unknown system 'blind' in variant 'v' (did you mean 'blinds'?)"}},
      {"variants:\n  - name: v\n    systems: {blinds: {type: fins, angle: 100}}\n",
       {"23:24: a variant cannot change 'type' of system 'blinds' (define another system and disable this one)"}},
      {"variants:\n  - name: v\n    systems: {blinds: {angle: 100, colour: red}}\n",
       {"23:31: 'angle' must be in [-90, 90], got 100",
        "23:36: unknown key 'colour' in blinds system"}},
      {"variants:\n  - name: v\n    systems: {blinds: {offset: 0.01}}\n",
       {"20:7: blinds 'blinds' (interior) reaches 0.015 m out of room 'room' through the wall plane; "
        "give it more offset or mount it outside"}},
      {"variants:\n  - name: v\n    systems: {blinds: {}}\n",
       {"23:23: variant 'v' changes no key of system 'blinds'"}},
  };
  for (const auto& [tail, expected] : bad) {
    SCOPED_TRACE(tail);
    const std::string& variant_text = tail;  // a lambda cannot capture a structured binding in C++17 (clang)
    const std::vector<std::string> got = test::located_errors([&] {
      const Project q = load(systems, variant_text);
      for (const VariantSpec& v : q.variants) build_scene_description(apply_variant(q, v));
    });
    EXPECT_EQ(got, expected);
  }
}

TEST(Systems, ExampleProjectsLoadAndBuild) {
  const std::map<std::string, std::vector<std::string>> examples = {
      {"light_shelf", {"shelf", "outer_shelf"}},
      {"blinds", {"venetian"}},
      {"prismatic_panel", {"yglass", "prisms"}},
      {"cpc", {"cpc"}},
      {"light_pipe", {"pipe"}},
      {"overhang", {"overhang", "fins"}},
  };
  for (const auto& [folder, systems] : examples) {
    SCOPED_TRACE(folder);
    const Project p = load_project(ProjectsDir + "/" + folder + "/project.yaml");
    const SceneDescription d = build_scene_description(p);
    for (const std::string& name : systems) EXPECT_FALSE(with_prefix(d, name + ".").empty() &&
                                                         with_prefix(d, name).empty()) << name;
    int ports = 0;
    for (const Surface& s : d.surfaces) ports += s.port;
    EXPECT_GT(ports, 0);
    for (const VariantSpec& v : p.variants) build_scene_description(apply_variant(p, v));
  }
}

}  // namespace
}  // namespace dayphoton::project
