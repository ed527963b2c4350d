// Honeybee model import (project/honeybee_model.h, docs/honeybee-import.md): units, the
// modifier precedence (own modifier, room set, global set, generic set), boundary conditions
// (ports, interior glazing, one surface per shared wall), openings cut out of their faces,
// sensor grids, and located errors for bad input; then the project keys that use it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/polygon.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/project/honeybee_model.h"
#include "dayphoton/project/project.h"
#include "../tensor_tree_xml_writer.h"
#include "../bsdf_xml_writer.h"
#include "../json_string.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

using test::located_errors;

// ---- building HBJSON text ------------------------------------------------------------------

std::string pts(const std::vector<Vec3>& p) {
  std::string s = "[";
  for (std::size_t i = 0; i < p.size(); ++i)
    s += (i ? ", [" : "[") + format_number(p[i].x) + ", " + format_number(p[i].y) + ", " + format_number(p[i].z) + "]";
  return s + "]";
}

std::string geometry(const std::vector<Vec3>& p) {
  return R"("geometry": {"type": "Face3D", "boundary": )" + pts(p) + "}";
}

std::string rad_modifier(const std::string& modifier) {
  return modifier.empty() ? "" : R"(, "properties": {"radiance": {"modifier": ")" + modifier + R"("}})";
}

std::string outdoors() { return R"({"type": "Outdoors"})"; }
std::string surface_bc(const std::string& adjacent) {
  return R"({"type": "Surface", "boundary_condition_objects": [")" + adjacent + R"(", "x"]})";
}

std::string face(const std::string& id, const std::string& type, const std::string& bc, const std::vector<Vec3>& p,
                 const std::string& extra = "") {
  return R"({"type": "Face", "identifier": ")" + id + R"(", "face_type": ")" + type + R"(", "boundary_condition": )" +
         bc + ", " + geometry(p) + extra + "}";
}

std::string opening(const char* type, const std::string& id, const std::string& bc, const std::vector<Vec3>& p,
                    const std::string& extra = "") {
  return std::string(R"({"type": ")") + type + R"(", "identifier": ")" + id + R"(", "boundary_condition": )" + bc +
         ", " + geometry(p) + extra + "}";
}

/// The faces of a box room x0..x1, 0..5, 0..3 (outward, counter-clockwise seen from outside).
struct Box {
  double x0 = 0, x1 = 4, y1 = 5, z1 = 3;
  std::vector<Vec3> south() const { return {{x0, 0, 0}, {x1, 0, 0}, {x1, 0, z1}, {x0, 0, z1}}; }
  std::vector<Vec3> north() const { return {{x1, y1, 0}, {x0, y1, 0}, {x0, y1, z1}, {x1, y1, z1}}; }
  std::vector<Vec3> west() const { return {{x0, y1, 0}, {x0, 0, 0}, {x0, 0, z1}, {x0, y1, z1}}; }
  std::vector<Vec3> east() const { return {{x1, 0, 0}, {x1, y1, 0}, {x1, y1, z1}, {x1, 0, z1}}; }
  std::vector<Vec3> floor() const { return {{x0, 0, 0}, {x0, y1, 0}, {x1, y1, 0}, {x1, 0, 0}}; }
  std::vector<Vec3> ceiling() const { return {{x0, 0, z1}, {x1, 0, z1}, {x1, y1, z1}, {x0, y1, z1}}; }
  std::vector<Vec3> window() const { return {{x0 + 1, 0, 1}, {x1 - 1, 0, 1}, {x1 - 1, 0, 2}, {x0 + 1, 0, 2}}; }
};

/// A room of Box `b`: south wall with a window (Outdoors), the other faces as given.
std::string room(const std::string& id, const Box& b, const std::string& west_bc, const std::string& east_bc,
                 const std::string& room_extra = "", const std::string& south_extra = "") {
  const std::string win = opening("Aperture", id + "_window", outdoors(), b.window());
  return R"({"type": "Room", "identifier": ")" + id + R"(", "faces": [)" +
         face(id + "_south", "Wall", outdoors(), b.south(), R"(, "apertures": [)" + win + "]" + south_extra) + ", " +
         face(id + "_north", "Wall", outdoors(), b.north()) + ", " + face(id + "_west", "Wall", west_bc, b.west()) + ", " +
         face(id + "_east", "Wall", east_bc, b.east()) + ", " + face(id + "_floor", "Floor", R"({"type": "Ground"})", b.floor()) +
         ", " + face(id + "_ceiling", "RoofCeiling", outdoors(), b.ceiling()) + "]" + room_extra + "}";
}

std::string model(const std::string& rooms, const std::string& radiance = "", const std::string& head = "") {
  return R"({"type": "Model", "identifier": "m", )" + head + R"("rooms": [)" + rooms + "]" +
         (radiance.empty() ? "" : R"(, "properties": {"radiance": {)" + radiance + "}}") + "}";
}

const HoneybeeSurface& surface(const HoneybeeModel& m, const std::string& name) {
  for (const HoneybeeSurface& s : m.surfaces)
    if (s.name == name) return s;
  throw std::runtime_error("no surface " + name);
}

std::size_t count_prefix(const HoneybeeModel& m, const std::string& prefix) {
  std::size_t n = 0;
  for (const HoneybeeSurface& s : m.surfaces) n += s.name.rfind(prefix, 0) == 0;
  return n;
}

const MaterialSpec& material(const HoneybeeModel& m, const std::string& name) {
  for (const MaterialSpec& s : m.materials)
    if (s.name == name) return s;
  throw std::runtime_error("no material " + name);
}

const Box box;

// ---- geometry ------------------------------------------------------------------------------

TEST(Honeybee, OneRoomHasPortsFacesAndItsWindowCutOut) {
  const HoneybeeModel m = read_honeybee_model_from_string(model(room("r", box, outdoors(), outdoors())), "m.hbjson");
  ASSERT_EQ(m.rooms, std::vector<std::string>{"r"});
  const HoneybeeSurface& w = surface(m, "r_window");
  EXPECT_EQ(w.role, HoneybeeRole::Port);
  EXPECT_EQ(w.material, "generic_exterior_window_vis_0.64");
  // The window's normal points out of the room (-y), as Honeybee draws it.
  EXPECT_NEAR(polygon_normal(w.vertices).y, -1, 1e-12);
  // The south wall is cut into triangles covering the wall minus the window: 12 - 2 m2.
  double area = 0;
  for (const HoneybeeSurface& s : m.surfaces)
    if (s.name.rfind("r_south:", 0) == 0) {
      area += polygon_area_m2(s.vertices);
      EXPECT_NEAR(polygon_normal(s.vertices).y, -1, 1e-12) << s.name;  // the wall's winding kept
      EXPECT_EQ(s.material, "generic_wall_0.50");
    }
  EXPECT_NEAR(area, 12.0 - 2.0, 1e-9);
  EXPECT_EQ(surface(m, "r_north").vertices.size(), 4u);  // no opening: one polygon
  EXPECT_EQ(surface(m, "r_floor").material, "generic_floor_0.20");
  EXPECT_EQ(surface(m, "r_ceiling").material, "generic_ceiling_0.80");
  // Honeybee's generic glass is given by its transmissivity (0.6976); through the RADIANCE
  // mapping it is the visible transmittance its name states, 0.64.
  EXPECT_NEAR(material(m, "generic_exterior_window_vis_0.64").transmittance.y, 0.64, 5e-5);
  EXPECT_DOUBLE_EQ(material(m, "generic_wall_0.50").reflectance.x, 0.5);
}

TEST(Honeybee, FaceWithTwoHolesIsTriangulatedToItsArea) {
  // A floor 4 x 5 with two holes given as Face3D holes (either winding).
  const std::string holes =
      R"(, "holes": [[[1, 1, 0], [1, 2, 0], [2, 2, 0], [2, 1, 0]], [[3, 3, 0], [3.5, 3, 0], [3.5, 4, 0]]])";
  std::string text = model(room("r", box, outdoors(), outdoors()));
  const std::string floor_geometry = geometry(box.floor());
  text.replace(text.find(floor_geometry), floor_geometry.size(),
               floor_geometry.substr(0, floor_geometry.size() - 1) + holes + "}");
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  double area = 0;
  for (const HoneybeeSurface& s : m.surfaces)
    if (s.name.rfind("r_floor:", 0) == 0) {
      area += polygon_area_m2(s.vertices);
      EXPECT_NEAR(polygon_normal(s.vertices).z, -1, 1e-12);
    }
  EXPECT_NEAR(area, 20.0 - 1.0 - 0.25, 1e-9);
}

TEST(Honeybee, UnitsAreConvertedToMetres) {
  for (const auto& [units, scale] : std::map<std::string, double>{
           {"Millimeters", 0.001}, {"Centimeters", 0.01}, {"Feet", 0.3048}, {"Inches", 0.0254}, {"Meters", 1.0}}) {
    // The same numbers in each unit; tolerance 0.01 units.
    const HoneybeeModel m = read_honeybee_model_from_string(
        model(room("r", box, outdoors(), outdoors()), "", R"("units": ")" + units + R"(", "tolerance": 0.01, )"),
        "m.hbjson");
    EXPECT_DOUBLE_EQ(m.metres_per_unit, scale) << units;
    EXPECT_DOUBLE_EQ(m.tolerance_m, 0.01 * scale) << units;
    const HoneybeeSurface& n = surface(m, "r_north");
    EXPECT_NEAR(n.vertices[0].x, 4 * scale, 1e-12) << units;
    EXPECT_NEAR(n.vertices[0].y, 5 * scale, 1e-12) << units;
  }
  EXPECT_EQ(located_errors([] {
              read_honeybee_model_from_string(model(room("r", box, outdoors(), outdoors()), "", R"("units": "Furlongs", )"),
                                              "m.hbjson");
            }),
            std::vector<std::string>{"1:47: units ('m'): unknown units 'Furlongs' (Meters, Millimeters, Centimeters, Feet or Inches)"});
}

TEST(Honeybee, SharedWallIsOneSurfaceAndItsWindowInteriorGlass) {
  Box east = box;
  east.x0 = 4;
  east.x1 = 8;
  // An interior aperture in the shared wall x = 4, in both faces (opposite windings).
  const std::vector<Vec3> in_west = {{4, 1, 1}, {4, 2, 1}, {4, 2, 2}, {4, 1, 2}};
  const std::vector<Vec3> in_east = {{4, 2, 1}, {4, 1, 1}, {4, 1, 2}, {4, 2, 2}};
  std::string a = room("a", box, outdoors(), surface_bc("b_west"));
  std::string b = room("b", east, surface_bc("a_east"), outdoors());
  const std::string a_east = face("a_east", "Wall", surface_bc("b_west"), box.east());
  a.replace(a.find(a_east), a_east.size(),
            face("a_east", "Wall", surface_bc("b_west"), box.east(),
                 R"(, "apertures": [)" + opening("Aperture", "a_inner", surface_bc("b_inner"), in_west) + "]"));
  const std::string b_west = face("b_west", "Wall", surface_bc("a_east"), east.west());
  b.replace(b.find(b_west), b_west.size(),
            face("b_west", "Wall", surface_bc("a_east"), east.west(),
                 R"(, "apertures": [)" + opening("Aperture", "b_inner", surface_bc("a_inner"), in_east) + "]"));
  const HoneybeeModel m = read_honeybee_model_from_string(model(a + ", " + b), "m.hbjson");
  EXPECT_GT(count_prefix(m, "a_east:"), 0u);          // the first face of the pair, cut
  EXPECT_EQ(count_prefix(m, "b_west"), 0u);           // its far side left out
  EXPECT_EQ(count_prefix(m, "b_inner"), 0u);
  const HoneybeeSurface& inner = surface(m, "a_inner");
  EXPECT_EQ(inner.role, HoneybeeRole::InteriorGlass);
  EXPECT_EQ(inner.material, "generic_interior_window_vis_0.88");
  EXPECT_EQ(surface(m, "a_window").role, HoneybeeRole::Port);
  EXPECT_EQ(surface(m, "b_window").role, HoneybeeRole::Port);
  // Interior faces take the interior modifiers; the ground floor too (only Outdoors is exterior).
  EXPECT_EQ(surface(m, "a_east:1").material, "generic_wall_0.50");
  ASSERT_EQ(m.notes.size(), 1u);
  EXPECT_NE(m.notes[0].find("'b_west'"), std::string::npos);
}

TEST(Honeybee, ShadesDoorsAndAirBoundaries) {
  const std::string overhang = R"(, "outdoor_shades": [{"type": "Shade", "identifier": "oh", )" +
                               geometry({{1, 0, 2.1}, {1, -0.5, 2.1}, {3, -0.5, 2.1}, {3, 0, 2.1}}) + "}]";
  const std::string door = R"(, "doors": [)" +
                           opening("Door", "d", outdoors(), {{0.2, 0, 0}, {0.8, 0, 0}, {0.8, 0, 2}, {0.2, 0, 2}}) + ", " +
                           opening("Door", "gd", outdoors(), {{3.2, 0, 0}, {3.8, 0, 0}, {3.8, 0, 2}, {3.2, 0, 2}},
                                   R"(, "is_glass": true)") +
                           "]";
  const std::string desk = R"(, "indoor_shades": [{"type": "Shade", "identifier": "desk", )" +
                           geometry({{1, 1, 0.7}, {2, 1, 0.7}, {2, 2, 0.7}, {1, 2, 0.7}}) + "}]";
  std::string text = model(room("r", box, outdoors(), outdoors(), desk, overhang + door));
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  EXPECT_EQ(surface(m, "oh").role, HoneybeeRole::OutdoorShade);
  EXPECT_EQ(surface(m, "oh").material, "generic_exterior_shade_0.35");
  EXPECT_EQ(surface(m, "desk").role, HoneybeeRole::Opaque);
  EXPECT_EQ(surface(m, "desk").material, "generic_interior_shade_0.50");
  EXPECT_EQ(surface(m, "d").role, HoneybeeRole::Opaque);
  EXPECT_EQ(surface(m, "d").material, "generic_opaque_door_0.50");
  EXPECT_EQ(surface(m, "gd").role, HoneybeeRole::Port);
  EXPECT_EQ(surface(m, "gd").material, "generic_exterior_window_vis_0.64");
  double wall = 0;
  for (const HoneybeeSurface& s : m.surfaces)
    if (s.name.rfind("r_south:", 0) == 0) wall += polygon_area_m2(s.vertices);
  EXPECT_NEAR(wall, 12.0 - 2.0 - 1.2 - 1.2, 1e-9);
}

// ---- modifiers -----------------------------------------------------------------------------

std::string plastic(const std::string& id, double r) {
  const std::string v = format_number(r);
  return R"({"type": "plastic", "identifier": ")" + id + R"(", "r_reflectance": )" + v + R"(, "g_reflectance": )" + v +
         R"(, "b_reflectance": )" + v + "}";
}

TEST(Honeybee, ModifierPrecedenceOwnThenRoomSetThenGlobalSetThenGeneric) {
  const std::string radiance =
      R"("modifiers": [)" + plastic("own", 0.1) + ", " + plastic("room_wall", 0.3) + ", " + plastic("global_wall", 0.4) +
      ", " + plastic("global_floor", 0.6) +
      R"(], "modifier_sets": [)"
      R"({"type": "ModifierSetAbridged", "identifier": "room_set", "wall_set": {"exterior_modifier": "room_wall"}},)"
      R"({"type": "ModifierSetAbridged", "identifier": "global_set", "wall_set": {"exterior_modifier": "global_wall"},)"
      R"( "floor_set": {"interior_modifier": "global_floor"}}], "global_modifier_set": "global_set")";
  Box other = box;
  other.x0 = 10;
  other.x1 = 14;
  std::string with_set = room("s", other, outdoors(), outdoors(),
                              R"(, "properties": {"radiance": {"modifier_set": "room_set"}})");
  std::string plain = room("g", box, outdoors(), outdoors());
  // One face of the plain room names its own modifier.
  const std::string north = face("g_north", "Wall", outdoors(), box.north());
  plain.replace(plain.find(north), north.size(), face("g_north", "Wall", outdoors(), box.north(), rad_modifier("own")));
  const HoneybeeModel m = read_honeybee_model_from_string(model(plain + ", " + with_set, radiance), "m.hbjson");
  EXPECT_EQ(surface(m, "g_north").material, "own");               // its own
  EXPECT_EQ(surface(m, "g_west").material, "global_wall");        // no room set: the global set
  EXPECT_EQ(surface(m, "g_floor").material, "global_floor");
  EXPECT_EQ(surface(m, "s_west").material, "room_wall");          // the room's set
  EXPECT_EQ(surface(m, "s_floor").material, "generic_floor_0.20");  // a slot the room set leaves empty: generic
  EXPECT_EQ(surface(m, "s_ceiling").material, "generic_ceiling_0.80");
  EXPECT_DOUBLE_EQ(material(m, "own").reflectance.x, 0.1);
  EXPECT_DOUBLE_EQ(material(m, "room_wall").reflectance.y, 0.3);
}

TEST(Honeybee, FullModifierSetGivesModifiersInline) {
  const std::string radiance =
      R"("modifier_sets": [{"type": "ModifierSet", "identifier": "full", "wall_set": {"exterior_modifier": )" +
      plastic("inline_wall", 0.45) + R"(}}], "global_modifier_set": "full")";
  const HoneybeeModel m = read_honeybee_model_from_string(model(room("r", box, outdoors(), outdoors()), radiance), "m.hbjson");
  EXPECT_EQ(surface(m, "r_west").material, "inline_wall");
  EXPECT_DOUBLE_EQ(material(m, "inline_wall").reflectance.z, 0.45);
}

TEST(Honeybee, CapitalisedTypesOfTheCurrentSchemaAndItsDefaults) {
  // honeybee-schema's modifier.py: "Plastic", "Metal" (specularity 0.9 by default), "Mirror"
  // (reflectance 1 by default), "Trans", "Glass"; a "Void" base modifier is no modifier.
  const std::string radiance =
      R"("modifiers": [{"type": "Metal", "identifier": "steel", "r_reflectance": 0.6, "g_reflectance": 0.6,)"
      R"( "b_reflectance": 0.6, "modifier": {"type": "Void"}}, {"type": "Mirror", "identifier": "silver"},)"
      R"( {"type": "Trans", "identifier": "diffuser", "r_reflectance": 0.5, "g_reflectance": 0.5, "b_reflectance": 0.5,)"
      R"( "transmitted_diff": 0.4, "transmitted_spec": 0.1},)"
      R"( {"type": "Glass", "identifier": "clear", "r_transmissivity": 0.9, "g_transmissivity": 0.9, "b_transmissivity": 0.9}])";
  std::string text = model(room("r", box, outdoors(), outdoors()), radiance);
  for (const auto& [face_name, modifier] : std::map<std::string, std::string>{
           {"r_north", "steel"}, {"r_west", "silver"}, {"r_east", "diffuser"}}) {
    const std::vector<Vec3> pts_of = face_name == "r_north" ? box.north() : face_name == "r_west" ? box.west() : box.east();
    const std::string f = face(face_name, "Wall", outdoors(), pts_of);
    text.replace(text.find(f), f.size(), face(face_name, "Wall", outdoors(), pts_of, rad_modifier(modifier)));
  }
  const std::string w = opening("Aperture", "r_window", outdoors(), box.window());
  text.replace(text.find(w), w.size(), opening("Aperture", "r_window", outdoors(), box.window(), rad_modifier("clear")));
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  EXPECT_EQ(material(m, "steel").type, MaterialType::Metal);
  EXPECT_DOUBLE_EQ(material(m, "steel").specularity, 0.9);
  EXPECT_EQ(material(m, "silver").type, MaterialType::Mirror);
  EXPECT_DOUBLE_EQ(material(m, "silver").reflectance.y, 1.0);
  EXPECT_EQ(material(m, "diffuser").type, MaterialType::Translucent);
  EXPECT_DOUBLE_EQ(material(m, "diffuser").transmissivity, 0.4);
  EXPECT_DOUBLE_EQ(material(m, "diffuser").transmitted_specular, 0.1);
  EXPECT_EQ(material(m, "clear").type, MaterialType::Glass);
}

TEST(Honeybee, GlobalModifierSetObjectDuplicatesAndContextShades) {
  // As honeybee-radiance writes models: global_modifier_set is a GlobalModifierSet object with
  // its own modifiers, and the model's list may repeat a modifier (the same definition).
  const std::string radiance =
      R"("modifiers": [)" + plastic("wall_g", 0.42) + ", " + plastic("wall_g", 0.42) +
      R"(], "global_modifier_set": {"type": "GlobalModifierSet", "modifiers": [)" + plastic("floor_g", 0.3) +
      R"(], "wall_set": {"exterior_modifier": "wall_g"}, "floor_set": {"interior_modifier": "floor_g"}})";
  std::string text = model(room("r", box, outdoors(), outdoors()), radiance);
  text.insert(text.size() - 1, R"(, "orphaned_shades": [{"type": "Shade", "identifier": "tree", "is_detached": true, )" +
                                   geometry({{0, -10, 0}, {4, -10, 0}, {4, -10, 6}}) +
                                   R"(}, {"type": "Shade", "identifier": "awning", )" +
                                   geometry({{0, -1, 3}, {4, -1, 3}, {4, 0, 3}}) + "}]");
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  EXPECT_EQ(surface(m, "r_north").material, "wall_g");
  EXPECT_EQ(surface(m, "r_floor").material, "floor_g");
  EXPECT_DOUBLE_EQ(material(m, "floor_g").reflectance.x, 0.3);
  EXPECT_EQ(surface(m, "tree").material, "generic_context_0.20");
  EXPECT_EQ(surface(m, "tree").role, HoneybeeRole::OutdoorShade);
  EXPECT_EQ(surface(m, "awning").material, "generic_exterior_shade_0.35");
  // A modifier defined twice differently is an error at the second definition.
  std::string twice = model(room("r", box, outdoors(), outdoors()),
                            R"("modifiers": [)" + plastic("w", 0.4) + ", " + plastic("w", 0.6) + "]");
  const auto errors = located_errors([&] { read_honeybee_model_from_string(twice, "m.hbjson"); });
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("properties.radiance.modifiers[1] ('w'): modifier 'w' is defined twice, differently"),
            std::string::npos) << errors[0];
}

// ---- sensor grids --------------------------------------------------------------------------

TEST(Honeybee, SensorGridsInMetresWithUnitDirections) {
  const std::string grids =
      R"("sensor_grids": [{"type": "SensorGrid", "identifier": "g1", "sensors": [)"
      R"({"pos": [1000, 2000, 800], "dir": [0, 0, 2]}, {"pos": [2000, 2000, 800], "dir": [0, 0, 1]}]}])";
  Box mm;
  mm.x1 = 4000;
  mm.y1 = 5000;
  mm.z1 = 3000;
  std::string rooms = room("r", mm, outdoors(), outdoors());
  const HoneybeeModel m =
      read_honeybee_model_from_string(model(rooms, grids, R"("units": "Millimeters", "tolerance": 1, )"), "m.hbjson");
  ASSERT_EQ(m.grids.size(), 1u);
  EXPECT_EQ(m.grids[0].identifier, "g1");
  ASSERT_EQ(m.grids[0].points.size(), 2u);
  EXPECT_NEAR(m.grids[0].points[0].position.x, 1.0, 1e-12);
  EXPECT_NEAR(m.grids[0].points[0].position.z, 0.8, 1e-12);
  EXPECT_DOUBLE_EQ(m.grids[0].points[0].normal.z, 1.0);
}

// ---- located errors ------------------------------------------------------------------------

// An aperture of a dynamic group (honeybee-schema's dynamic_group_identifier and states, as
// in its sample model_radiance_dynamic_states): honeybee-radiance simulates each state (an
// electrochromic glass, a state with an awning), dayphoton the aperture's own modifier. That
// was silent: the model ran with the generic glass where the user had drawn the states.
// Now a warning at the aperture's dynamic_group_identifier, and the scene carries it to check
// and run.
TEST(Honeybee, DynamicStatesAreAWarningAtTheAperture) {
  const std::string states =
      R"(, "properties": {"radiance": {"dynamic_group_identifier": "ec_window",
 "states": [{"modifier": "dark"}, {"modifier": "darker"}]}})";
  const std::string win = opening("Aperture", "w", outdoors(), box.window(), states);
  const std::string text = R"({"type": "Model", "identifier": "m", "rooms": [{"type": "Room", "identifier": "r", "faces": [)" +
                           face("s", "Wall", outdoors(), box.south(), R"(, "apertures": [)" + win + "]") + ", " +
                           face("n", "Wall", outdoors(), box.north()) + ", " + face("w_", "Wall", outdoors(), box.west()) +
                           ", " + face("e", "Wall", outdoors(), box.east()) + ", " +
                           face("f", "Floor", R"({"type": "Ground"})", box.floor()) + ", " +
                           face("c", "RoofCeiling", outdoors(), box.ceiling()) + "]}]}";
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  ASSERT_EQ(m.warnings.size(), 1u);
  const Diagnostic& w = m.warnings[0];
  EXPECT_EQ(w.severity, Severity::Warning);
  EXPECT_EQ(w.location.line, 1);
  EXPECT_EQ(text.substr(w.location.column - 1, 11), "\"ec_window\"") << w.location.column;  // the group's value
  EXPECT_NE(w.message.find("('w'): in dynamic group 'ec_window' with 2 states: dayphoton models its own modifier "
                           "'generic_exterior_window_vis_0.64' in every hour"),
            std::string::npos)
      << w.message;
  // A static model: no warning.
  EXPECT_TRUE(read_honeybee_model_from_string(model(room("r", box, outdoors(), outdoors())), "m.hbjson").warnings.empty());
}

// A face whose modifier lets light through (a glazed wall or roof drawn as a Face with a glass
// modifier, not as an aperture; a translucent fabric roof): honeybee-radiance writes it as that
// material and RADIANCE lets the sky in through it. It was an ordinary surface, no port, so
// no sky light came through it: a room glazed that way read almost nothing (only a warning
// at the sensors, about a gap), or, with a window elsewhere, only that window's light.
// Now an Outdoors face of glass or trans is a port facing out of its room, a Surface face of
// glass interior glazing; an opaque face, and a glass face on the ground, stay surfaces.
TEST(Honeybee, AGlassFaceIsAPortLikeAnAperture) {
  const std::string clear = R"("modifiers": [{"type": "Glass", "identifier": "clear", "r_transmissivity": 0.9,
 "g_transmissivity": 0.9, "b_transmissivity": 0.9}, {"type": "Trans", "identifier": "fabric", "r_reflectance": 0.6,
 "g_reflectance": 0.6, "b_reflectance": 0.6, "transmitted_diff": 0.3}, {"type": "Trans", "identifier": "opaque_trans",
 "r_reflectance": 0.6, "g_reflectance": 0.6, "b_reflectance": 0.6, "transmitted_diff": 0}])";
  const std::string text =
      model(R"({"type": "Room", "identifier": "r", "faces": [)" +
                face("s", "Wall", outdoors(), box.south(), rad_modifier("clear")) + ", " +
                face("n", "Wall", outdoors(), box.north(), rad_modifier("opaque_trans")) + ", " +
                face("w_", "Wall", outdoors(), box.west()) + ", " + face("e", "Wall", outdoors(), box.east()) + ", " +
                face("f", "Floor", R"({"type": "Ground"})", box.floor(), rad_modifier("clear")) + ", " +
                face("c", "RoofCeiling", outdoors(), box.ceiling(), rad_modifier("fabric")) + "]}",
            clear);
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  EXPECT_EQ(surface(m, "s").role, HoneybeeRole::Port);
  EXPECT_EQ(surface(m, "s").facing, PortFacing::Out);
  EXPECT_EQ(surface(m, "c").role, HoneybeeRole::Port);
  EXPECT_EQ(surface(m, "n").role, HoneybeeRole::Opaque);  // a trans that transmits nothing
  EXPECT_EQ(surface(m, "w_").role, HoneybeeRole::Opaque);
  EXPECT_EQ(surface(m, "f").role, HoneybeeRole::Opaque);  // no light comes through the ground
  // An opaque door given a glass modifier lets light in as a glass door does.
  const std::string door = opening("Door", "d", outdoors(), box.window(), rad_modifier("clear"));
  const HoneybeeModel d = read_honeybee_model_from_string(
      model(R"({"type": "Room", "identifier": "r", "faces": [)" +
                face("s", "Wall", outdoors(), box.south(), R"(, "doors": [)" + door + "]") + "]}",
            clear),
      "m.hbjson");
  EXPECT_EQ(surface(d, "d").role, HoneybeeRole::Port);
}

// ---- BSDF modifiers -------------------------------------------------------------------------

/// A Lambertian Klems BSDF whose two sides differ (front reflectance 0.1, back 0.6, T 0.3).
std::string two_sided_xml() {
  return dayphoton::test::bsdf_xml(dayphoton::test::klems_from(
      KlemsBasis::full(), [](int, int) { return 0.3 / Pi; }, [](int, int) { return 0.3 / Pi; },
      [](int, int) { return 0.1 / Pi; }, [](int, int) { return 0.6 / Pi; }));
}

/// "line:column" of the first occurrence of `needle` in `text`.
std::string where(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  const std::size_t line_start = text.rfind('\n', at);
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  const std::size_t column = at - (line_start == std::string::npos ? 0 : line_start + 1) + 1;
  return std::to_string(line) + ":" + std::to_string(column);
}

// A BSDF modifier (honeybee-schema radiance/modifier.py BSDF: the Klems XML inline in
// bsdf_data, up_orientation) on a room's aperture becomes a `bsdf` material with the file's
// data and up vector, and the aperture is turned round: RADIANCE (and dayphoton) take the side
// a BSDF surface's normal points to as the file's back (WINDOW's room side), and Honeybee's
// aperture normals point out of the room. Before, the modifier was refused ("not supported").
TEST(Honeybee, ABsdfApertureIsTurnedSoThatItsFrontIsOutdoors) {
  const std::string radiance = R"("modifiers": [{"type": "BSDF", "identifier": "blind", "up_orientation": [0, 0, 1],
 "thickness": 0, "function_file": ".", "transform": null, "front_diffuse_reflectance": [0, 0, 0],
 "bsdf_data": )" + dayphoton::test::json_string(two_sided_xml()) + "}]";
  std::string text = model(room("r", box, outdoors(), outdoors()), radiance);
  const std::string win = opening("Aperture", "r_window", outdoors(), box.window());
  text.replace(text.find(win), win.size(), opening("Aperture", "r_window", outdoors(), box.window(), rad_modifier("blind")));
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  const HoneybeeSurface& w = surface(m, "r_window");
  EXPECT_EQ(w.role, HoneybeeRole::Port);
  EXPECT_EQ(w.facing, PortFacing::In);
  const std::vector<Vec3> hb = box.window();
  ASSERT_EQ(w.vertices.size(), hb.size());
  for (std::size_t i = 0; i < hb.size(); ++i) EXPECT_EQ(w.vertices[i], hb[hb.size() - 1 - i]);
  EXPECT_GT(polygon_normal(w.vertices).y, 0.99);  // into the room (y 0..5): the file's front outdoors
  const engine::BsdfMaterialParameters* bsdf = engine::bsdf_parameters(material(m, "blind"));
  ASSERT_NE(bsdf, nullptr);
  EXPECT_EQ(bsdf->up, Vec3(0, 0, 1));
  EXPECT_EQ(bsdf->data->basis.size(), 145);
  // The user is told that honeybee-radiance's static export gives the device turned round.
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].message.find("properties.radiance.modifiers[0] ('blind'): the BSDF's front"), std::string::npos)
      << m.warnings[0].message;
  EXPECT_NE(m.warnings[0].message.find("turned round"), std::string::npos);
  // The schema's default up vector, (0.01, 0.01, 1), when none is written.
  std::string plain = text;
  const std::string up = R"("up_orientation": [0, 0, 1],)";
  plain.replace(plain.find(up), up.size(), "");
  EXPECT_EQ(engine::bsdf_parameters(material(read_honeybee_model_from_string(plain, "m.hbjson"), "blind"))->up,
            Vec3(0.01, 0.01, 1));
}

// A tensor-tree BSDF (TensorTree3) inline in bsdf_data is read where a Klems one is.
TEST(Honeybee, ATensorTreeBsdfApertureIsReadLikeAKlemsOne) {
  const std::string radiance = R"("modifiers": [{"type": "BSDF", "identifier": "film", "up_orientation": [0, 0, 1],
 "thickness": 0, "function_file": ".", "transform": null, "front_diffuse_reflectance": [0, 0, 0],
 "bsdf_data": )" + dayphoton::test::json_string(dayphoton::test::tensor_tree_xml({"{ 0.2 }", "{ 0.2 }", "{ 0.05 }", "{ 0.05 }"})) + "}]";
  std::string text = model(room("r", box, outdoors(), outdoors()), radiance);
  const std::string win = opening("Aperture", "r_window", outdoors(), box.window());
  text.replace(text.find(win), win.size(), opening("Aperture", "r_window", outdoors(), box.window(), rad_modifier("film")));
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  const engine::BsdfMaterialParameters* bsdf = engine::bsdf_parameters(material(m, "film"));
  ASSERT_NE(bsdf, nullptr);
  ASSERT_TRUE(bsdf->data->tensor_tree);
  EXPECT_NEAR(bsdf->data->tensor_tree->slices[0][0].transmittance, 0.2 * Pi, 1e-6);
  EXPECT_EQ(surface(m, "r_window").role, HoneybeeRole::Port);
}

// What RADIANCE's BSDF primitive takes and dayphoton does not model is refused at its very key
// (file:line:column of its value), as the RADIANCE import refuses it; a thickness is ignored
// with a warning there; the XML's own errors are reported at bsdf_data with their place in
// the XML; a BSDF where no room says which side is outdoors is refused at the object.
TEST(HoneybeeErrors, BsdfFieldsThatAreNotModelledAreLocatedAtTheirKeys) {
  const std::string radiance =
      "\"modifiers\": [{\"type\": \"BSDF\", \"identifier\": \"blind\",\n"
      " \"function_file\": \"blind.cal\",\n"
      " \"transform\": \"-rz 90\",\n"
      " \"thickness\": 0.05,\n"
      " \"front_diffuse_reflectance\": [0.1, 0.1, 0.1],\n"
      " \"back_diffuse_reflectance\": [0, 0, 0],\n"
      " \"diffuse_transmittance\": [0.2, 0.2, 0.2],\n"
      " \"up_orientation\": [0, 0, 0],\n"
      " \"bsdf_data\": " + dayphoton::test::json_string(two_sided_xml()) + "},\n"
      " {\"type\": \"BSDF\", \"identifier\": \"broken\",\n"
      " \"bsdf_data\": \"<WindowElement>\\n<Optical>\"},\n"
      " {\"type\": \"BSDF\", \"identifier\": \"nodata\"}]";
  std::string text = model(room("r", box, outdoors(), outdoors()), radiance);
  const std::string win = opening("Aperture", "r_window", outdoors(), box.window());
  text.replace(text.find(win), win.size(), opening("Aperture", "r_window", outdoors(), box.window(), rad_modifier("blind")));
  const std::string north = face("r_north", "Wall", outdoors(), box.north());
  text.replace(text.find(north), north.size(), face("r_north", "Wall", outdoors(), box.north(), rad_modifier("broken")));
  const std::string east = face("r_east", "Wall", outdoors(), box.east());
  text.replace(text.find(east), east.size(), face("r_east", "Wall", outdoors(), box.east(), rad_modifier("nodata")));
  const auto errors = located_errors([&] { read_honeybee_model_from_string(text, "m.hbjson"); }, "m.hbjson");
  const std::string m0 = "properties.radiance.modifiers[0].";
  const std::vector<std::string> expected_starts = {
      where(text, "\"blind.cal\"") + ": " + m0 + "function_file ('blind'): a function file ('blind.cal') is not supported",
      where(text, "\"-rz 90\"") + ": " + m0 + "transform ('blind'): a transform is not supported",
      where(text, "0.05") + ": " + m0 + "thickness ('blind'): a thickness (0.05 model units) is ignored",  // a warning
      where(text, "[0.1, 0.1, 0.1]") + ": " + m0 + "front_diffuse_reflectance ('blind'): an extra diffuse component is not supported",
      where(text, "[0.2, 0.2, 0.2]") + ": " + m0 + "diffuse_transmittance ('blind'): an extra diffuse component is not supported",
      where(text, "[0, 0, 0],\n \"bsdf_data\"") + ": " + m0 + "up_orientation ('blind'): the BSDF's up vector is zero",
      where(text, "\"<WindowElement>") + ": properties.radiance.modifiers[1] ('broken').bsdf_data (line 2, column",
      where(text, "{\"type\": \"BSDF\", \"identifier\": \"nodata\"") +
          ": properties.radiance.modifiers[2].bsdf_data ('nodata'): missing required field 'bsdf_data'",
  };
  ASSERT_EQ(errors.size(), expected_starts.size()) << ::testing::PrintToString(errors);
  for (const std::string& e : expected_starts)
    EXPECT_TRUE(std::any_of(errors.begin(), errors.end(), [&](const std::string& got) { return got.rfind(e, 0) == 0; }))
        << e << "\n" << ::testing::PrintToString(errors);

  // The thickness alone: a warning at its value, and the model reads.
  std::string thick = model(room("r", box, outdoors(), outdoors()),
                            "\"modifiers\": [{\"type\": \"BSDF\", \"identifier\": \"blind\",\n \"thickness\": 0.05,\n"
                            " \"bsdf_data\": " + dayphoton::test::json_string(two_sided_xml()) + "}]");
  thick.replace(thick.find(win), win.size(), opening("Aperture", "r_window", outdoors(), box.window(), rad_modifier("blind")));
  const HoneybeeModel t = read_honeybee_model_from_string(thick, "m.hbjson");
  ASSERT_EQ(t.warnings.size(), 2u);
  EXPECT_EQ(std::to_string(t.warnings[0].location.line) + ":" + std::to_string(t.warnings[0].location.column),
            where(thick, "0.05"));
  EXPECT_NE(t.warnings[0].message.find("thickness ('blind'): a thickness (0.05 model units) is ignored"), std::string::npos)
      << t.warnings[0].message;

  // A BSDF between two rooms, on an orphaned aperture, on a shade: no room says which side
  // is outdoors (or the object lets no light in), so the file's front cannot be placed.
  const std::string ok = "\"modifiers\": [{\"type\": \"BSDF\", \"identifier\": \"blind\", \"bsdf_data\": " +
                         dayphoton::test::json_string(two_sided_xml()) + "}]";
  std::string orphan = model(room("r", box, outdoors(), outdoors()), ok);
  orphan.insert(orphan.size() - 1, ", \"orphaned_apertures\": [" +
                                       opening("Aperture", "loose", outdoors(), {{9, 0, 1}, {10, 0, 1}, {10, 0, 2}, {9, 0, 2}},
                                               rad_modifier("blind")) +
                                       "], \"orphaned_shades\": [{\"type\": \"Shade\", \"identifier\": \"screen\", " +
                                       geometry({{0, -1, 3}, {4, -1, 3}, {4, -1, 4}, {0, -1, 4}}) + rad_modifier("blind") +
                                       "}]");
  const auto refused = located_errors([&] { read_honeybee_model_from_string(orphan, "m.hbjson"); });
  ASSERT_EQ(refused.size(), 3u) << ::testing::PrintToString(refused);  // and the room's window's warning
  EXPECT_NE(refused[0].find("('screen'): has BSDF modifier 'blind': a BSDF is read on the apertures"),
            std::string::npos) << refused[0];
  EXPECT_NE(refused[1].find("('loose'): has BSDF modifier 'blind': an orphaned object has no room"), std::string::npos)
      << refused[1];
}

TEST(HoneybeeErrors, SyntaxErrorAtLineAndColumn) {
  const std::string text = "{\n  \"type\": \"Model\",\n  \"rooms\": [,]\n}\n";
  const auto errors = located_errors([&] { read_honeybee_model_from_string(text, "m.hbjson"); }, "m.hbjson");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].substr(0, 5), "3:13:") << errors[0];
  EXPECT_NE(errors[0].find("not valid JSON"), std::string::npos) << errors[0];
}

TEST(HoneybeeErrors, DeepNestingIsRefusedWhereItIsReached) {
  // Valid JSON, but 65 levels deep: the located scan would recurse once per level.
  const std::string text = "{\"rooms\":\n" + std::string(64, '[') + std::string(64, ']') + "}";
  EXPECT_EQ(located_errors([&] { read_honeybee_model_from_string(text, "m.hbjson"); }),
            std::vector<std::string>{"2:64: the JSON nests deeper than 64 levels; a Honeybee model needs about 12"});
}

TEST(HoneybeeErrors, MissingFieldNamesPathIdentifierAndLine) {
  const std::string text =
      "{\"type\": \"Model\", \"identifier\": \"m\", \"rooms\": [\n"
      "  {\"type\": \"Room\", \"identifier\": \"r\", \"faces\": [\n"
      "    {\"type\": \"Face\", \"identifier\": \"f0\", \"face_type\": \"Floor\", \"boundary_condition\": {\"type\": \"Ground\"}}\n"
      "  ]}\n"
      "]}\n";
  EXPECT_EQ(located_errors([&] { read_honeybee_model_from_string(text, "m.hbjson"); }),
            std::vector<std::string>{"3:5: rooms[0].faces[0] ('f0'): missing required field 'geometry'"});
}

TEST(HoneybeeErrors, OddValuesAreLocatedAtTheirField) {
  std::string text = model(room("r", box, outdoors(), outdoors()));
  // A boundary condition Honeybee does not have, a non-planar face, an aperture outside its face.
  const std::string west = face("r_west", "Wall", outdoors(), box.west());
  text.replace(text.find(west), west.size(), face("r_west", "Wall", R"({"type": "Sky"})", box.west()));
  const std::string north = face("r_north", "Wall", outdoors(), box.north());
  text.replace(text.find(north), north.size(),
               face("r_north", "Wall", outdoors(), {{4, 5, 0}, {0, 5, 0}, {0, 5.3, 3}, {4, 5, 3}}));
  const std::string win = geometry(box.window());
  text.replace(text.find(win), win.size(), geometry({{1, 0, 1}, {5, 0, 1}, {5, 0, 2}, {1, 0, 2}}));
  const auto errors = located_errors([&] { read_honeybee_model_from_string(text, "m.hbjson"); });
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_NE(errors[0].find("rooms[0].faces[0].apertures[0].geometry.boundary ('r_window'): is not inside its face 'r_south'"),
            std::string::npos) << errors[0];
  EXPECT_NE(errors[1].find("rooms[0].faces[1].geometry.boundary ('r_north'): not planar: a vertex is"), std::string::npos)
      << errors[1];
  EXPECT_NE(errors[2].find("rooms[0].faces[2].boundary_condition.type ('r_west'): unknown boundary condition 'Sky'"),
            std::string::npos) << errors[2];
  // Each is located at its own column of the one-line text.
  EXPECT_EQ(errors[0].substr(0, 2), "1:");
}

TEST(HoneybeeErrors, UnsupportedAndUnknownModifiers) {
  const std::string radiance =
      R"("modifiers": [{"type": "aBSDF", "identifier": "blind", "bsdf_data": "x"},)"
      R"( {"type": "plastic", "identifier": "patterned", "r_reflectance": 0.5, "modifier": {"type": "brightfunc"}}])";
  std::string text = model(room("r", box, outdoors(), outdoors()), radiance);
  const std::string north = face("r_north", "Wall", outdoors(), box.north());
  text.replace(text.find(north), north.size(), face("r_north", "Wall", outdoors(), box.north(), rad_modifier("blind")));
  const std::string west = face("r_west", "Wall", outdoors(), box.west());
  text.replace(text.find(west), west.size(), face("r_west", "Wall", outdoors(), box.west(), rad_modifier("patterned")));
  const std::string east = face("r_east", "Wall", outdoors(), box.east());
  text.replace(text.find(east), east.size(), face("r_east", "Wall", outdoors(), box.east(), rad_modifier("nothing")));
  const auto errors = located_errors([&] { read_honeybee_model_from_string(text, "m.hbjson"); });
  ASSERT_EQ(errors.size(), 3u) << ::testing::PrintToString(errors);
  EXPECT_NE(errors[0].find("rooms[0].faces[3].properties.radiance.modifier ('r_east'): unknown modifier 'nothing'"),
            std::string::npos) << errors[0];
  EXPECT_NE(errors[1].find("properties.radiance.modifiers[0] ('blind'): modifier 'blind' has type 'aBSDF'"), std::string::npos)
      << errors[1];
  EXPECT_NE(errors[2].find("modifier 'patterned' is modified by another modifier"), std::string::npos) << errors[2];
}

TEST(HoneybeeErrors, ShadeMeshesAreRefusedNotDropped) {
  std::string text = model(room("r", box, outdoors(), outdoors()));
  text.insert(text.size() - 1, R"(, "shade_meshes": [{"type": "ShadeMesh"}])");
  const auto errors = located_errors([&] { read_honeybee_model_from_string(text, "m.hbjson"); });
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("shade_meshes ('m'): 'shade_meshes' is not supported"), std::string::npos) << errors[0];
}

TEST(Honeybee, OrphanedFacesAperturesAndDoorsHaveAutoFacingPorts) {
  // A wall without a room, with a window; a skylight and a glass door without a face.
  const std::vector<Vec3> wall = {{0, 20, 0}, {4, 20, 0}, {4, 20, 3}, {0, 20, 3}};
  const std::vector<Vec3> window = {{1, 20, 1}, {3, 20, 1}, {3, 20, 2}, {1, 20, 2}};
  std::string text = model(room("r", box, outdoors(), outdoors()));
  text.insert(text.size() - 1,
              R"(, "orphaned_faces": [)" +
                  face("lone_wall", "Wall", outdoors(), wall, R"(, "apertures": [)" + opening("Aperture", "lone_window", outdoors(), window) + "]") +
                  R"(], "orphaned_apertures": [)" +
                  opening("Aperture", "lone_skylight", outdoors(), {{0, 30, 3}, {1, 30, 3}, {1, 31, 3}, {0, 31, 3}}) +
                  R"(], "orphaned_doors": [)" +
                  opening("Door", "lone_door", outdoors(), {{0, 40, 0}, {1, 40, 0}, {1, 40, 2}, {0, 40, 2}}, R"(, "is_glass": true)") +
                  "]");
  const HoneybeeModel m = read_honeybee_model_from_string(text, "m.hbjson");
  for (const char* name : {"lone_window", "lone_skylight", "lone_door"}) {
    EXPECT_EQ(surface(m, name).role, HoneybeeRole::Port) << name;
    EXPECT_EQ(surface(m, name).facing, PortFacing::Auto) << name;
  }
  EXPECT_EQ(surface(m, "r_window").facing, PortFacing::Out);
  EXPECT_EQ(surface(m, "lone_skylight").material, "generic_exterior_window_vis_0.64");
  EXPECT_GT(count_prefix(m, "lone_wall:"), 0u);  // the window cut out of it
  EXPECT_EQ(surface(m, "lone_wall:1").material, "generic_wall_0.50");
}

// ---- the project keys ----------------------------------------------------------------------

struct TempDir {
  std::string path;
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "dayphoton_hb_XXXXXX").string();
    path = mkdtemp(pattern.data());
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path + "/" + name) << text;
    return path + "/" + name;
  }
};

const char* const ProjectHead = R"(version: 1
site: {latitude: 37.7, longitude: -122.2, time_zone: -8}
materials:
  grey: {type: lambertian, reflectance: 0.5}
outputs: {annual_illuminance: false, metrics: false}
)";

std::string two_grids() {
  return R"("sensor_grids": [)"
         R"({"identifier": "north", "sensors": [{"pos": [2, 4, 0.8], "dir": [0, 0, 1]}]},)"
         R"({"identifier": "south", "sensors": [{"pos": [2, 1, 0.8], "dir": [0, 0, 1]}, {"pos": [3, 1, 0.8], "dir": [0, 0, 1]}]}])";
}

TEST(HoneybeeProject, GridsAllOrByIdentifierBecomePointSets) {
  TempDir dir;
  dir.write("model.hbjson", model(room("r", box, outdoors(), outdoors()), two_grids()));
  const std::string yaml = dir.write("p.yaml", std::string(ProjectHead) +
                                                   "geometry: {honeybee: model.hbjson}\n"
                                                   "sensors:\n  honeybee_grids: all\n");
  const Project all = load_project(yaml);
  ASSERT_TRUE(all.geometry.honeybee.has_value());
  ASSERT_EQ(all.sensors.points.size(), 2u);
  EXPECT_EQ(all.sensors.points[0].name, "north");
  EXPECT_EQ(all.sensors.points[1].points.size(), 2u);
  // The modifiers the model uses are project materials; the scene has its surfaces and port.
  EXPECT_GE(all.materials.size(), 5u);
  const SceneDescription scene = build_scene_description(all);
  int ports = 0;
  for (const Surface& s : scene.surfaces) ports += s.port ? 1 : 0;
  EXPECT_EQ(ports, 1);
  ASSERT_EQ(scene.grids.size(), 2u);

  const std::string by_id = dir.write("q.yaml", std::string(ProjectHead) +
                                                    "geometry: {honeybee: model.hbjson}\n"
                                                    "sensors:\n  honeybee_grids: [south, {grid: north, name: back}]\n");
  const Project some = load_project(by_id);
  ASSERT_EQ(some.sensors.points.size(), 2u);
  EXPECT_EQ(some.sensors.points[0].name, "south");
  EXPECT_EQ(some.sensors.points[1].name, "back");
}

TEST(HoneybeeProject, VariantReplacesAnImportedModifierByName) {
  TempDir dir;
  dir.write("model.hbjson", model(room("r", box, outdoors(), outdoors()), two_grids()));
  const std::string yaml = dir.write("p.yaml", std::string(ProjectHead) +
                                                   "geometry: {honeybee: model.hbjson}\n"
                                                   "sensors: {honeybee_grids: all}\n"
                                                   "variants:\n"
                                                   "  - name: low_e\n"
                                                   "    materials:\n"
                                                   "      generic_exterior_window_vis_0.64: {type: glass, transmittance: 0.4}\n");
  const Project base = load_project(yaml);
  ASSERT_EQ(base.variants.size(), 1u);
  const SceneDescription scene = build_scene_description(apply_variant(base, base.variants[0]));
  bool found = false;
  for (const Surface& s : scene.surfaces)
    if (s.port) {
      EXPECT_DOUBLE_EQ(scene.materials[static_cast<std::size_t>(s.material)].transmittance.x, 0.4);
      found = true;
    }
  EXPECT_TRUE(found);
  // A project material named like a modifier the model uses is an error at the project's name.
  const std::string clash = dir.write("c.yaml",
                                      "version: 1\n"
                                      "site: {latitude: 37.7, longitude: -122.2, time_zone: -8}\n"
                                      "materials:\n"
                                      "  generic_wall_0.50: {type: lambertian, reflectance: 0.1}\n"
                                      "outputs: {annual_illuminance: false, metrics: false}\n"
                                      "geometry: {honeybee: model.hbjson}\n");
  const auto errors = located_errors([&] { load_project(clash); });
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].substr(0, 4), "4:3:");
  EXPECT_NE(errors[0].find("material 'generic_wall_0.50' is also a modifier of the Honeybee model"), std::string::npos)
      << errors[0];
}

TEST(HoneybeeProject, UnknownGridHintAndErrorsOfTheModelAreReported) {
  TempDir dir;
  dir.write("model.hbjson", model(room("r", box, outdoors(), outdoors()), two_grids()));
  const std::string yaml = dir.write("p.yaml", std::string(ProjectHead) +
                                                   "geometry: {honeybee: model.hbjson}\n"
                                                   "sensors:\n  honeybee_grids: [soth]\n");
  EXPECT_EQ(located_errors([&] { load_project(yaml); }),
            std::vector<std::string>{"8:20: the Honeybee model has no sensor grid 'soth' (did you mean 'south'?)"});
  // An error inside the model is reported in the model's file, at its line.
  dir.write("bad.hbjson", "{\"type\": \"Model\",\n \"rooms\": 3}\n");
  const std::string bad = dir.write("b.yaml", std::string(ProjectHead) + "geometry: {honeybee: bad.hbjson}\n"
                                                                         "sensors: {honeybee_grids: all}\n");
  EXPECT_EQ(located_errors([&] { load_project(bad); }, dir.path + "/bad.hbjson"),
            std::vector<std::string>{"2:11: rooms: expected a list of rooms, got a number"});
}

// A project whose geometry is a Honeybee model needs no materials of its own: the model
// brings its modifiers (a new user's first project was refused for the missing key). The
// model's warnings reach the scene, which check and run print.
TEST(HoneybeeProject, AModelBringsItsMaterialsAndItsWarningsReachTheScene) {
  TempDir dir;
  const std::string states = R"(, "properties": {"radiance": {"dynamic_group_identifier": "g"}})";
  const std::string win = opening("Aperture", "w", outdoors(), box.window(), states);
  dir.write("model.hbjson",
            R"({"type": "Model", "identifier": "m", "rooms": [{"type": "Room", "identifier": "r", "faces": [)" +
                face("s", "Wall", outdoors(), box.south(), R"(, "apertures": [)" + win + "]") + ", " +
                face("n", "Wall", outdoors(), box.north()) + ", " + face("w_", "Wall", outdoors(), box.west()) + ", " +
                face("e", "Wall", outdoors(), box.east()) + ", " + face("f", "Floor", R"({"type": "Ground"})", box.floor()) +
                ", " + face("c", "RoofCeiling", outdoors(), box.ceiling()) + "]}], " +
                R"("properties": {"radiance": {)" + two_grids() + "}}}");
  const std::string yaml = dir.write("p.yaml",
                                     "version: 1\n"
                                     "site: {latitude: 37.7, longitude: -122.2, time_zone: -8}\n"
                                     "outputs: {annual_illuminance: false, metrics: false}\n"
                                     "geometry: {honeybee: model.hbjson}\n"
                                     "sensors: {honeybee_grids: all}\n");
  const Project p = load_project(yaml);
  EXPECT_EQ(p.materials.size(), 4u);  // the generic wall, floor, ceiling and window modifiers
  const SceneDescription scene = build_scene_description(p);
  bool warned = false;
  for (const Diagnostic& w : scene.warnings)
    warned = warned || (w.location.file == dir.path + "/model.hbjson" && w.message.find("in dynamic group 'g'") != std::string::npos);
  EXPECT_TRUE(warned);
  // Without any geometry that brings materials the key is still required.
  const std::string bare = dir.write("q.yaml",
                                     "version: 1\n"
                                     "site: {latitude: 37.7, longitude: -122.2, time_zone: -8}\n"
                                     "geometry: {polygons: []}\n");
  const auto errors = located_errors([&] { load_project(bare); });
  bool missing = false;
  for (const std::string& e : errors) missing = missing || e.find("missing required key 'materials'") != std::string::npos;
  EXPECT_TRUE(missing);
}

// An old file's model-level north_angle (honeybee-schema's Model before the north moved to the
// energy simulation parameter): degrees clockwise from +Y to north (honeybee-core's
// Model.north_vector is +Y rotated by minus the angle), site.north's own convention. It was
// ignored: a model drawn with north_angle 90 (true north along +X) was simulated facing south.
TEST(HoneybeeProject, AnOldModelsNorthAngleOrientsItWhereTheProjectWritesNoNorth) {
  TempDir dir;
  dir.write("model.hbjson", model(room("r", box, outdoors(), outdoors()), "", R"("north_angle": 90, )"));
  const std::string yaml = dir.write("p.yaml", std::string(ProjectHead) + "geometry: {honeybee: model.hbjson}\n");
  const Project p = load_project(yaml);
  EXPECT_DOUBLE_EQ(p.site.north_deg, 90.0);
  ASSERT_TRUE(p.geometry.honeybee.has_value());
  bool noted = false;
  for (const std::string& n : p.geometry.honeybee->model.notes) noted = noted || n.find("north_angle 90") == 0;
  EXPECT_TRUE(noted);
  // The window of the model's south wall (y = 0) faces east: world x = -y = 0.
  const SceneDescription scene = build_scene_description(p);
  int ports = 0;
  for (const Surface& s : scene.surfaces)
    if (s.port) {
      ++ports;
      for (const Vec3& v : s.vertices) EXPECT_NEAR(v.x, 0.0, 1e-12);
    }
  EXPECT_EQ(ports, 1);
  // The same north written in the project: no conflict.
  std::string with_north = std::string(ProjectHead);
  with_north.replace(with_north.find("time_zone: -8}"), 14, "time_zone: -8, north: -270}");
  EXPECT_DOUBLE_EQ(load_project(dir.write("n.yaml", with_north + "geometry: {honeybee: model.hbjson}\n")).site.north_deg,
                   -270.0);
  // Another north in the project: which one is meant is the user's to say, at site.north.
  std::string other = std::string(ProjectHead);
  other.replace(other.find("time_zone: -8}"), 14, "time_zone: -8, north: 30}");
  const auto errors = located_errors([&] { load_project(dir.write("o.yaml", other + "geometry: {honeybee: model.hbjson}\n")); });
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].substr(0, 5), "2:65:") << errors[0];
  EXPECT_NE(errors[0].find("site.north is 30 degrees but the Honeybee model's north_angle, 90 degrees"), std::string::npos)
      << errors[0];
}

// A Honeybee SensorGrid's `mesh` gives each sensor the floor area Honeybee weighs its result
// by (honeybee-radiance-postprocess: "these meshes will be used to compute percentages of
// occupied floor area"). dayphoton counted every sensor equally and only warned. Now the
// grid's sensors carry their faces' areas (two sensors on faces of 1 and 0.25 m^2, a cell
// trimmed at a wall) with a located note at the mesh; equal faces give no areas (equal
// shares, the bytes of an unweighted grid) and no note; a mesh that cannot be read, or whose
// face count is not the sensors', is a located warning and not used.
TEST(HoneybeeProject, AGridMeshOfUnequalFacesWeighsItsSensorsByTheirFaces) {
  auto grids = [](const std::string& faces) {
    return R"("sensor_grids": [{"identifier": "g", "sensors": [)"
           R"({"pos": [1.5, 1.5, 0.8], "dir": [0, 0, 1]}, {"pos": [2.75, 1.5, 0.8], "dir": [0, 0, 1]}],)"
           "\n"
           R"("mesh": {"type": "Mesh3D", "vertices": [[1, 1, 0.8], [2, 1, 0.8], [2, 2, 0.8], [1, 2, 0.8], )"
           R"([2.5, 1, 0.8], [3, 1, 0.8], [3, 1.5, 0.8], [2.5, 1.5, 0.8], [3, 2, 0.8], [2, 1.5, 0.8]], )"
           R"("faces": [)" + faces + "]}}]";
  };
  struct Case {
    std::string faces;
    std::vector<double> area_m2;  // the grid's areas
    Severity severity;            // of the diagnostic at the mesh (Error: none)
    std::string text;
  };
  const std::vector<Case> cases = {
      {"[0, 1, 2, 3], [4, 5, 6, 7]", {1.0, 0.25}, Severity::Note,
       "sensor grid 'g': the faces of its mesh differ in area (0.25 to 1 m^2, 1.25 m^2 in all): each sensor's share of "
       "the area (sDA, ASE, EN 17037's target areas, the grid means) is weighted by its face's area, as Honeybee does"},
      {"[0, 1, 2, 3], [1, 5, 8, 2]", {}, Severity::Error, ""},  // 1 x 1 m twice: equal shares
      {"[0, 1, 2, 3]", {}, Severity::Warning, "sensor grid 'g': its mesh has 1 faces for 2 sensors, so it is not used"},
      {"[0, 1, 2, 3], [4, 5, 60]", {}, Severity::Warning, "sensor grid 'g': its mesh cannot be read as a Mesh3D"},
  };
  for (const Case& c : cases) {
    TempDir dir;
    dir.write("model.hbjson", model(room("r", box, outdoors(), outdoors()), grids(c.faces)));
    const std::string yaml = dir.write("p.yaml", std::string(ProjectHead) +
                                                     "geometry: {honeybee: model.hbjson}\n"
                                                     "sensors:\n  honeybee_grids: all\n");
    const SceneDescription scene = build_scene_description(load_project(yaml));
    ASSERT_EQ(scene.grids.size(), 1u);
    EXPECT_EQ(scene.grids[0].area_m2, c.area_m2) << c.faces;
    const Diagnostic* found = nullptr;
    for (const Diagnostic& w : scene.warnings)
      if (w.message.find("sensor grid 'g'") != std::string::npos) found = &w;
    ASSERT_EQ(found != nullptr, c.severity != Severity::Error) << c.faces;
    if (!found) continue;
    EXPECT_EQ(found->severity, c.severity) << c.faces;
    EXPECT_EQ(found->location.file, dir.path + "/model.hbjson");
    EXPECT_EQ(found->location.line, 2);  // the line of "mesh"
    EXPECT_EQ(found->message.rfind(c.text, 0), 0u) << found->message;
  }
}

// One grid listed twice (under its own name and another) is two point sets with the same
// areas, and its mesh's note is given once, not once per mention.
TEST(HoneybeeProject, AGridListedTwiceGetsItsMeshNoteOnce) {
  const std::string grids =
      R"("sensor_grids": [{"identifier": "g", "sensors": [)"
      R"({"pos": [1.5, 1.5, 0.8], "dir": [0, 0, 1]}, {"pos": [2.75, 1.5, 0.8], "dir": [0, 0, 1]}],)"
      "\n"
      R"("mesh": {"type": "Mesh3D", "vertices": [[1, 1, 0.8], [2, 1, 0.8], [2, 2, 0.8], [1, 2, 0.8], )"
      R"([2.5, 1, 0.8], [3, 1, 0.8], [3, 1.5, 0.8], [2.5, 1.5, 0.8]], "faces": [[0, 1, 2, 3], [4, 5, 6, 7]]}}])";
  TempDir dir;
  dir.write("model.hbjson", model(room("r", box, outdoors(), outdoors()), grids));
  const std::string yaml = dir.write("p.yaml", std::string(ProjectHead) +
                                                   "geometry: {honeybee: model.hbjson}\n"
                                                   "sensors:\n  honeybee_grids: [g, {grid: g, name: g_again}]\n");
  const SceneDescription scene = build_scene_description(load_project(yaml));
  ASSERT_EQ(scene.grids.size(), 2u);
  EXPECT_EQ(scene.grids[0].area_m2, (std::vector<double>{1.0, 0.25}));
  EXPECT_EQ(scene.grids[1].area_m2, (std::vector<double>{1.0, 0.25}));
  std::size_t notes = 0;
  for (const Diagnostic& w : scene.warnings)
    if (w.message.find("sensor grid 'g': the faces of its mesh differ in area") != std::string::npos) ++notes;
  EXPECT_EQ(notes, 1u);
}

}  // namespace
}  // namespace dayphoton::project
