// Project-file schema tables (see project_schema.h). One line per key; the loader reads each
// key through these entries, so a default or a range written here is the one that applies.
// Units follow DESIGN.md section 4 (metres, degrees in files, hours for time zones).
#include "dayphoton/project/project_schema.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/resource_limits.h"
#include "dayphoton/engine/material_registry.h"
#include "dayphoton/project/length_units.h"

namespace dayphoton::project {

namespace {

// Fluent construction keeps each schema entry on one readable line.
struct P {
  ParamSchema s;
  P(std::string name, ParamType type, std::string help) {
    s.name = std::move(name);
    s.type = type;
    s.help = std::move(help);
  }
  P& unit(std::string u) { s.unit = std::move(u); return *this; }
  P& range(double lo, double hi) { s.min = lo; s.max = hi; return *this; }
  P& above(double lo) { s.min = lo; s.min_exclusive = true; return *this; }
  P& at_least(double lo) { s.min = lo; return *this; }
  P& required() { s.required = true; return *this; }
  P& def(std::string d) { s.default_value = std::move(d); return *this; }
  P& choices(std::vector<std::string> c) { s.choices = std::move(c); return *this; }
  P& section(std::string n) { s.section = std::move(n); return *this; }
  operator ParamSchema() const { return s; }
};

using T = ParamType;

// The built-in material types, then the models registered after them (material_registry.h).
std::vector<std::string> material_types() {
  std::vector<std::string> types = {"lambertian", "plastic", "metal", "mirror", "glass",
                                    "glazing", "dielectric", "translucent", "opening"};
  for (const engine::MaterialModelEntry& e : engine::material_models())
    if (e.parse) types.push_back(e.type_name);
  return types;
}

ParamSchema material_type() {
  return P("type", T::Choice, "material model").required().choices(material_types());
}

// A window material's role as a shading device (MaterialSpec::shading): LM-83 takes ASE with
// operable shading retracted (study/shading_materials.h).
ParamSchema shading_role() {
  return P("shading", T::Choice,
           "the material stands for a shading device that is moved (operable: LM-83's sDA and ASE are then not "
           "assessed with it in place) or a fixed one; a bsdf whose file's DeviceType names a blind, shade or screen "
           "is taken as operable unless this says fixed")
      .choices({"operable", "fixed"});
}

// A registered material model's keys, from its registry entry.
SectionSchema registered_material_section(const engine::MaterialModelEntry& e) {
  SectionSchema section{e.type_name + " material", e.help, {material_type()}};
  for (const engine::MaterialParameterSchema& k : e.parameters) {
    using Kind = engine::MaterialParameterSchema::Kind;
    const ParamType type = k.kind == Kind::Number ? T::Number
                           : k.kind == Kind::Rgb  ? T::Rgb
                           : k.kind == Kind::Path ? T::Path
                                                  : T::String;
    P p(k.key, type, k.help);
    p.unit(k.unit);
    p.s.min = k.min;
    p.s.max = k.max;
    if (k.required) p.required();
    if (!k.default_text.empty()) p.def(k.default_text);
    section.params.push_back(p);
  }
  if (e.takes_transmittance_factor) section.params.push_back(shading_role());
  return section;
}
ParamSchema reflectance(const char* help) {
  return P("reflectance", T::Rgb, help).range(0, 1).required();
}
ParamSchema specularity(bool is_required) {
  P p("specularity", T::Number, "fraction of the reflection that is specular");
  p.range(0, 1);
  if (is_required) p.required(); else p.def("0");
  return p;
}
ParamSchema roughness() {
  return P("roughness", T::Number, "RMS facet slope of the specular lobe (0 = smooth)")
      .range(0, 1).def("0");
}

const std::vector<std::string> SystemTypes = {"light_shelf", "blinds", "prismatic_panel",
                                              "lamella_panel", "cpc", "light_pipe",
                                              "overhang", "fins"};

ParamSchema system_type() {
  return P("type", T::Choice, "kind of daylight system").required().choices(SystemTypes);
}
ParamSchema system_name() { return P("name", T::String, "unique system name").required(); }
ParamSchema system_enabled() {
  return P("enabled", T::Boolean, "false: the system is left out (e.g. blinds raised, in a variant)").def("true");
}
ParamSchema system_window() {
  return P("window", T::String, "window the system belongs to (its frame places the system)").required();
}
ParamSchema system_side() {
  return P("side", T::Choice, "inside the room or outside the wall").choices({"interior", "exterior"}).def("interior");
}
ParamSchema system_port() {
  return P("port", T::Choice, "exterior only, where sky and sun photons enter: the window and the system's own surfaces (what the system reflects and transmits is traced), the window alone (shading only: an approximation that drops the light the system reflects), or an opening box around system and window").choices({"system", "window", "enclosure"}).def("system");
}

std::vector<SectionSchema> build_schema() {
  std::vector<SectionSchema> s;
  s.push_back({"project", "the top level of a project file", {
      P("version", T::Integer, "project-file format version").range(1, 1).def("1"),
      P("site", T::Section, "where the building is").section("site").required(),
      P("study", T::Choice, "what run computes: annual (daylight factors, annual illuminance and metrics from the weather file's skies and sun) or daylight_factor (the CIE overcast sky only: no weather file, no sun traced); default annual, or daylight_factor for a file without weather that sets annual_illuminance and metrics to false").choices({"annual", "daylight_factor"}).def("annual"),
      P("weather", T::Special, "hourly weather file, EPW or RADIANCE/DAYSIM .wea (by its extension): a path, or a map {file: path}; needed by the annual study"),
      P("materials", T::NameMap, "material name -> material definition (map by `type`); required unless `geometry.radiance` or `geometry.honeybee` brings the materials"),
      P("geometry", T::Section, "rooms, polygons, boxes and meshes").section("geometry").required(),
      P("sensors", T::Section, "sensor grids and point sets").section("sensors"),
      P("simulation", T::Section, "photon and sky settings").section("simulation"),
      P("outputs", T::Section, "what to write and where").section("outputs"),
      P("metrics", T::Section, "thresholds and occupancy of the results").section("metrics"),
      P("variants", T::SectionList, "study variants: the project with some materials or systems replaced, geometry removed or added").section("variant"),
      P("points_in_time", T::SectionList, "point-in-time cases: the illuminance at every sensor at one date and time under one sky").section("point_in_time"),
      P("operation", T::Section, "operated shading (LM-83 blinds rule): per hour the open or the shaded case").section("operation"),
      P("limits", T::Section, "the largest study the project may make; raise a limit for a study that needs more").section("limits"),
      P("sunlight_exposure", T::Section, "EN 17037 exposure to sunlight: the hours the sun is seen from each window's reference point on one date").section("sunlight_exposure"),
  }});
  s.push_back({"site", "location of the site and orientation of the model", {
      P("name", T::String, "site name for reports").def(""),
      P("from_weather", T::Boolean, "true: the sun and the sky are computed for the weather file header's site, as RADIANCE's gendaymtx does (latitude, longitude, time_zone, elevation and utm_zone are then not written); false: for this site, with the weather station's irradiance").def("false"),
      P("latitude", T::Angle, "north positive; decimal degrees or DMS (41d58'48\"N); required unless from_weather").unit("deg").range(-90, 90),
      P("longitude", T::Angle, "east positive (as EPW); decimal degrees or DMS (87d54'W); required unless from_weather").unit("deg").range(-180, 180),
      P("time_zone", T::Number, "standard-time offset from UTC, east positive (EPW convention); must be the weather file's (its hours are that clock's); required unless from_weather").unit("h").range(-12, 14),
      P("elevation", T::Number, "site elevation above sea level (SPA sun positions)").unit("m").range(-500, 9000).def("0"),
      P("north", T::Number, "angle clockwise (seen from above) from model +Y to true north").unit("deg").range(-360, 360).def("0"),
      P("utm_zone", T::Special, "UTM zone the model is drawn in: '33N' or {zone: 33, hemisphere: north}; north is then measured to grid north and corrected by the meridian convergence"),
  }});
  s.push_back({"utm_zone", "UTM zone of a model drawn in projected coordinates", {
      P("zone", T::Integer, "UTM zone number").range(1, 60).required(),
      P("hemisphere", T::Choice, "hemisphere of the zone").choices({"north", "south"}).required(),
  }});
  s.push_back({"weather", "weather file (map form of `weather`)", {
      P("file", T::Path, "EPW file, or .wea file (its header gives the site), relative to the project file; must exist").required(),
  }});
  s.push_back({"lambertian material", "ideal diffuse reflector (RADIANCE plastic, no specular lobe)", {
      material_type(), reflectance("diffuse reflectance, grey or [r, g, b]"),
  }});
  s.push_back({"plastic material", "diffuse reflector with an uncoloured specular lobe (RADIANCE plastic)", {
      material_type(), reflectance("reflectance, grey or [r, g, b]"), specularity(false), roughness(),
  }});
  s.push_back({"metal material", "specular reflector tinted by its colour (RADIANCE metal)", {
      material_type(), reflectance("reflectance, grey or [r, g, b]"), specularity(true), roughness(),
  }});
  s.push_back({"mirror material", "perfect specular reflector", {
      material_type(), reflectance("specular reflectance, grey or [r, g, b]"),
  }});
  s.push_back({"glass material", "thin glazing with Fresnel angular transmission", {
      material_type(),
      P("transmittance", T::Rgb, "normal-incidence visible transmittance (not RADIANCE transmissivity)").range(0, 1).required(),
      P("refractive_index", T::Number, "refractive index of the pane").above(1).def("1.52"),
  }});
  s.push_back({"glazing material", "glazing system: panes from the outside in, combined by the multi-layer formulas (docs/materials.md)", {
      material_type(),
      P("panes", T::SectionList, "the panes, from the outside in (pane 1 on the side a surface's normal points away from: outside for a window)").section("glazing pane").required(),
  }});
  s.push_back({"glazing pane", "one pane of a glazing: exactly one of transmittance, absorption or coating", {
      P("transmittance", T::Rgb, "uncoated pane: normal-incidence visible transmittance").range(0, 1),
      P("absorption", T::Rgb, "uncoated pane: absorption coefficient of the glass (needs thickness)").unit("1/m").at_least(0),
      P("thickness", T::Number, "pane thickness (sets the absorption's path; otherwise shown by check)").unit("mm").above(0),
      P("refractive_index", T::Number, "uncoated pane: refractive index of the glass").above(1).def("1.52"),
      P("coating", T::Section, "coated pane (low-e, solar control): its measured normal-incidence optics").section("glazing coating"),
  }});
  s.push_back({"glazing coating", "a coated pane's normal-incidence optics (data sheet or IGDB values of the coated pane)", {
      P("face", T::Choice, "the coated face: the pane's outer face (toward pane 1) or inner face").choices({"outer", "inner"}).required(),
      P("transmittance", T::Rgb, "normal-incidence visible transmittance of the coated pane").range(0, 1).required(),
      P("reflectance", T::Rgb, "normal-incidence visible reflectance of the coated face").range(0, 1).required(),
      P("glass_side_reflectance", T::Rgb, "normal-incidence reflectance of the uncoated face; the coated face's if absent").range(0, 1),
  }});
  s.push_back({"dielectric material", "thick refracting interface (prisms, light pipes)", {
      material_type(),
      P("refractive_index", T::Number, "refractive index").above(1).required(),
      P("transmittance", T::Rgb, "transmission per metre of path (1 - absorption)").range(0, 1).def("1"),
  }});
  s.push_back({"translucent material", "diffusing transmitter (RADIANCE trans)", {
      material_type(), reflectance("reflectance, grey or [r, g, b]"), specularity(false), roughness(),
      P("transmissivity", T::Number, "fraction of the non-specularly reflected light that is transmitted").range(0, 1).required(),
      P("transmitted_specular", T::Number, "fraction of the transmitted light transmitted specularly").range(0, 1).def("0"),
      shading_role(),
  }});
  s.push_back({"opening material", "fully transparent aperture: an open window or an invisible photon port", {
      material_type(),
  }});
  for (const engine::MaterialModelEntry& e : engine::material_models())
    if (e.parse) s.push_back(registered_material_section(e));
  s.push_back({"geometry", "the building and its surroundings (model coordinates, metres)", {
      P("rooms", T::SectionList, "box-shaped rooms with windows").section("room"),
      P("polygons", T::SectionList, "planar polygons").section("polygon"),
      P("boxes", T::SectionList, "solid boxes (shading, furniture)").section("box"),
      P("meshes", T::SectionList, "Wavefront OBJ meshes").section("mesh"),
      P("systems", T::SectionList, "daylight systems generated from a few parameters (docs/daylight-systems.md)").section("system"),
      P("radiance", T::SectionList, "RADIANCE scene files read in place, their materials mapped (docs/radiance-import.md)").section("radiance scene"),
      P("honeybee", T::Path, "Honeybee model (HBJSON), relative to the project file: its rooms, apertures (photon ports), doors, shades, modifiers and sensor grids (docs/honeybee-import.md)"),
  }});
  s.push_back({"radiance scene", "RADIANCE scene description files (.rad) read as oconv reads them; metres unless `units` says otherwise, +Y north (docs/radiance-import.md)", {
      P("files", T::NameList, "scene files read in order (a modifier must be defined before it is used), relative to the project file; each must exist").required(),
      P("ports", T::Special, "auto: the surfaces of transmitting materials (glass, dielectric, trans, ...) with exactly one side seeing the sky become photon ports; or a list of modifier names whose surfaces are ports (facing auto)").def("auto"),
      P("outdoor", T::NameList, "modifier names whose surfaces lie outside the building and are outdoor scatterers: sky and sun photons also land on them, and the light they reflect or transmit toward the ports is traced (as `outdoor: true` on a polygon); the others only shade the ports"),
      P("unsupported", T::Choice, "modifiers and primitives dayphoton does not model (patterns, BSDFs, meshes, ...): an error, or left out with a warning").choices({"error", "skip"}).def("error"),
      P("units", T::Choice, "length unit of the files' numbers (Honeybee's names): coordinates, radii, !xform -t and a dielectric's absorption per unit length are converted to metres; without it the metre is assumed, with a warning when the rooms only make sense in another unit").choices(length_unit_names()).def("Meters"),
  }});
  s.push_back({"room", "a box-shaped room, surfaces facing inward", {
      P("name", T::String, "unique room name").required(),
      P("origin", T::Vec3, "(min x, min y, floor) corner").unit("m").def("[0, 0, 0]"),
      P("size", T::Vec3, "x, y, z extents").unit("m").above(0).required(),
      P("materials", T::Section, "surface materials").section("room materials").required(),
      P("windows", T::SectionList, "openings glazed with a material; they become photon ports (interior windows, in a wall shared with another room, stay glazing)").section("window"),
      P("roof_lights", T::SectionList, "rectangular openings in the ceiling, glazed flush or at the top of a light well; the glazing becomes a photon port").section("roof light"),
  }});
  s.push_back({"room materials", "materials of a room's surfaces (names from `materials`)", {
      P("floor", T::String, "floor material").required(),
      P("ceiling", T::String, "ceiling material").required(),
      P("walls", T::String, "material of every wall not overridden below (required unless all four are given)"),
      P("south", T::String, "wall at minimum y"),
      P("north", T::String, "wall at maximum y"),
      P("east", T::String, "wall at maximum x"),
      P("west", T::String, "wall at minimum x"),
  }});
  s.push_back({"window", "a rectangular opening in a room wall", {
      P("name", T::String, "unique window name").required(),
      P("wall", T::Choice, "wall the window is in").choices({"south", "north", "east", "west"}).required(),
      P("width", T::Number, "width along the wall").unit("m").above(0).required(),
      P("height", T::Number, "height").unit("m").above(0).required(),
      P("sill", T::Number, "height of the bottom edge above the floor").unit("m").at_least(0).required(),
      P("offset", T::Number, "from the wall's lower-coordinate end (min x or min y) to the near edge; centred if absent").unit("m").at_least(0),
      P("material", T::String, "glazing material").required(),
      P("frame_factor", T::Number, "glazed fraction of the opening (the frame absorbs the rest); multiplies the glazing's transmittance").range(0, 1).above(0).def("1"),
      P("maintenance_factor", T::Number, "transmittance left by dirt on the glazing; multiplies the glazing's transmittance").range(0, 1).above(0).def("1"),
  }});
  s.push_back({"roof light", "a rectangular opening in a room's ceiling (room coordinates: x from the west wall, y from the south wall)", {
      P("name", T::String, "unique roof light name").required(),
      P("width", T::Number, "extent along x").unit("m").above(0).required(),
      P("length", T::Number, "extent along y").unit("m").above(0).required(),
      P("offset_x", T::Number, "from the room's west wall (min x) to the near edge; centred if absent").unit("m").at_least(0),
      P("offset_y", T::Number, "from the room's south wall (min y) to the near edge; centred if absent").unit("m").at_least(0),
      P("well_depth", T::Number, "height of the light well from the ceiling up to the glazing; 0: glazing flush with the ceiling").unit("m").at_least(0).def("0"),
      P("well_material", T::String, "walls of the light well (default: the room's ceiling material)"),
      P("material", T::String, "glazing material (glass, opening or translucent)").required(),
  }});
  s.push_back({"polygon", "a planar polygon; normal by counter-clockwise winding", {
      P("name", T::String, "unique polygon name").required(),
      P("vertices", T::PointList, "at least 3 vertices [x, y, z]").unit("m").required(),
      P("material", T::String, "material name").required(),
      P("port", T::Boolean, "photons from sky and sun enter through it").def("false"),
      P("facing", T::Choice, "ports: which side is the room: auto (the side that does not see the sky), in (the normal by the vertex order points into the room) or out").choices({"auto", "in", "out"}).def("auto"),
      P("outdoor", T::Boolean, "outside the building: sky and sun photons also land on it, and the light it reflects or transmits toward the ports is traced (an outdoor scatterer, as exterior systems' parts); false: it only shades the ports").def("false"),
  }});
  s.push_back({"box", "a solid box with outward faces", {
      P("name", T::String, "unique box name").required(),
      P("origin", T::Vec3, "min corner before rotation").unit("m").def("[0, 0, 0]"),
      P("size", T::Vec3, "x, y, z extents").unit("m").above(0).required(),
      P("rotation", T::Number, "counter-clockwise rotation about +Z around the origin").unit("deg").range(-360, 360).def("0"),
      P("material", T::String, "material name").required(),
      P("outdoor", T::Boolean, "outside the building: sky and sun photons also land on it, and the light it reflects or transmits toward the ports is traced (an outdoor scatterer, as exterior systems' parts); false: it only shades the ports").def("false"),
  }});
  s.push_back({"mesh", "a Wavefront OBJ mesh; usemtl groups map to project materials", {
      P("name", T::String, "unique mesh name").required(),
      P("file", T::Path, "OBJ file, relative to the project file; must exist").required(),
      P("material_map", T::NameMap, "OBJ usemtl name -> project material name"),
      P("default_material", T::String, "material of faces whose usemtl is not mapped").def(""),
      P("translate", T::Vec3, "offset applied last").unit("m").def("[0, 0, 0]"),
      P("scale", T::Number, "uniform scale applied first").above(0).def("1"),
      P("rotation", T::Number, "counter-clockwise rotation about +Z after scaling").unit("deg").range(-360, 360).def("0"),
      P("port", T::Boolean, "all faces are photon ports").def("false"),
      P("facing", T::Choice, "ports: which side is the room: auto (the side that does not see the sky), in (the normal of each face by its vertex order points into the room) or out").choices({"auto", "in", "out"}).def("auto"),
      P("outdoor", T::Boolean, "outside the building: sky and sun photons also land on it, and the light it reflects or transmits toward the ports is traced (an outdoor scatterer, as exterior systems' parts); false: it only shades the ports").def("false"),
  }});
  // Daylight systems (docs/daylight-systems.md). Heights are above the room floor; `offset`
  // and `depth` are measured perpendicular to the wall; angles in degrees.
  s.push_back({"system", "a daylight system: `type` selects the keys (sections `<type> system` below)", {
      system_type(), system_name(), system_enabled(),
  }});
  s.push_back({"light_shelf system", "a light shelf along a window, inside or outside", {
      system_type(), system_name(), system_enabled(), system_window(), system_side(), system_port(),
      P("height", T::Number, "height of the shelf's wall edge above the floor").unit("m").at_least(0).required(),
      P("depth", T::Number, "from the wall to the free edge, along the shelf").unit("m").above(0).required(),
      P("tilt", T::Number, "rotation about the wall edge; > 0 raises the free edge").unit("deg").range(-60, 60).def("0"),
      P("thickness", T::Number, "0: one two-sided polygon; > 0: a closed slab this thick").unit("m").at_least(0).def("0"),
      P("extension", T::Number, "length beyond each window jamb").unit("m").at_least(0).def("0"),
      P("material", T::String, "material of the top (of every face of a thin shelf)").required(),
      P("underside_material", T::String, "slab only: material of the faces other than the top (default: material)"),
  }});
  s.push_back({"blinds system", "venetian blinds: horizontal slats in front of a window", {
      system_type(), system_name(), system_enabled(), system_window(), system_side(), system_port(),
      P("slat_width", T::Number, "chord of a slat, edge to edge").unit("m").above(0).required(),
      P("spacing", T::Number, "vertical distance between slat axes").unit("m").above(0).required(),
      P("angle", T::Number, "slat rotation: 0 horizontal, > 0 window-side edge down (closing toward the sky), 90 closed").unit("deg").range(-90, 90).def("0"),
      P("crown", T::Number, "rise of a slat's middle above its chord (convex side up at angle 0)").unit("m").at_least(0).def("0"),
      P("facets", T::Integer, "flat facets across a curved slat").range(1, 32).def("4"),
      P("offset", T::Number, "from the wall plane to the slat axes (default: half the slat width + 0.02)").unit("m").above(0),
      P("bottom", T::Number, "lowest height covered by slats (default: the window sill)").unit("m").at_least(0),
      P("top", T::Number, "highest height covered by slats (default: the window head)").unit("m").at_least(0),
      P("extension", T::Number, "slat length beyond each window jamb").unit("m").at_least(0).def("0"),
      P("material", T::String, "slat material (both sides)").required(),
  }});
  s.push_back({"prismatic_panel system", "a panel of horizontal dielectric prisms parallel to a window", {
      system_type(), system_name(), system_enabled(), system_window(), system_side(), system_port(),
      P("apex_angle", T::Number, "apex angle of the isosceles prism cross-section").unit("deg").range(10, 170).def("90"),
      P("pitch", T::Number, "prism base width = vertical period").unit("m").above(0).required(),
      P("apex", T::Choice, "where the apexes point").choices({"inward", "outward"}).def("inward"),
      P("backing", T::Number, "thickness of a plate joining the prism bases (0: separate prisms)").unit("m").at_least(0).def("0"),
      P("offset", T::Number, "from the wall plane to the panel's nearest face").unit("m").at_least(0).def("0.01"),
      P("bottom", T::Number, "lower edge of the panel (default: the window sill)").unit("m").at_least(0),
      P("top", T::Number, "upper edge of the panel (default: the window head)").unit("m").at_least(0),
      P("material", T::String, "a dielectric material").required(),
  }});
  s.push_back({"lamella_panel system", "a dielectric panel cut by inclined air lamellae (Y-glass, seeds/000 section 4.2.1)", {
      system_type(), system_name(), system_enabled(), system_window(), system_side(), system_port(),
      P("thickness", T::Number, "panel thickness, wall-normal").unit("m").above(0).required(),
      P("spacing", T::Number, "vertical distance between lamellae").unit("m").above(0).required(),
      P("lamella_angle", T::Number, "lamella inclination; > 0: the room-side edge lower").unit("deg").range(-45, 45).def("7"),
      P("gap", T::Number, "air gap of a lamella, perpendicular to it").unit("m").above(0).def("0.0005"),
      P("offset", T::Number, "from the wall plane to the panel's nearest face").unit("m").at_least(0).def("0.01"),
      P("bottom", T::Number, "lower edge of the panel (default: the window sill)").unit("m").at_least(0),
      P("top", T::Number, "upper edge of the panel (default: the window head)").unit("m").at_least(0),
      P("material", T::String, "a dielectric material").required(),
  }});
  s.push_back({"cpc system", "compound parabolic concentrator troughs stacked over a window (seeds/000 section 4.2.2)", {
      system_type(), system_name(), system_enabled(), system_window(), system_side(), system_port(),
      P("acceptance_angle", T::Number, "acceptance half angle of each 2-D CPC").unit("deg").range(5, 60).required(),
      P("count", T::Integer, "troughs stacked over the covered height").range(1, 1000).required(),
      P("kind", T::Choice, "mirror walls (a conventional CPC) or solid dielectric troughs (sun shading)").choices({"reflective", "dielectric"}).def("reflective"),
      P("facets", T::Integer, "straight facets per parabolic wall").range(2, 64).def("8"),
      P("tilt", T::Number, "troughs' axes raised toward the sky by this angle").unit("deg").range(-60, 60).def("0"),
      P("offset", T::Number, "from the wall plane to the nearest aperture").unit("m").at_least(0).def("0.01"),
      P("bottom", T::Number, "lowest covered height (default: the window sill)").unit("m").at_least(0),
      P("top", T::Number, "highest covered height (default: the window head)").unit("m").at_least(0),
      P("material", T::String, "reflective: the wall material; dielectric: the dielectric").required(),
      P("exit_material", T::String, "dielectric only (required there): opaque coating of the exit aperture"),
  }});
  s.push_back({"light_pipe system", "a vertical specular tube from a ceiling to a roof collector (seeds/000 section 4.2.3)", {
      system_type(), system_name(), system_enabled(),
      P("room", T::String, "room whose ceiling the pipe passes").required(),
      P("x", T::Number, "x of the pipe axis (model coordinates)").unit("m").required(),
      P("y", T::Number, "y of the pipe axis (model coordinates)").unit("m").required(),
      P("diameter", T::Number, "diameter of the circle the tube's polygon is inscribed in").unit("m").above(0).required(),
      P("length", T::Number, "tube length from the ceiling up to the collector").unit("m").above(0).required(),
      P("sides", T::Integer, "facets of the tube (a regular polygon)").range(3, 64).def("16"),
      P("collector", T::Choice, "hemispherical dome or flat aperture on top (a photon port)").choices({"dome", "flat"}).def("dome"),
      P("dome_rings", T::Integer, "facet rings of the dome").range(1, 16).def("4"),
      P("tube_material", T::String, "inside of the tube (mirror or metal)").required(),
      P("diffuser_material", T::String, "fills the ceiling opening (translucent, glass or opening)").required(),
      P("collector_material", T::String, "collector glazing (glass or opening)").required(),
  }});
  s.push_back({"overhang system", "a horizontal or tilted projection above a window", {
      system_type(), system_name(), system_enabled(), system_window(), system_port(),
      P("height", T::Number, "height of the overhang's wall edge above the floor (default: the window head)").unit("m").at_least(0),
      P("depth", T::Number, "from the wall to the free edge, along the overhang").unit("m").above(0).required(),
      P("tilt", T::Number, "rotation about the wall edge; > 0 raises the free edge").unit("deg").range(-60, 60).def("0"),
      P("thickness", T::Number, "0: one two-sided polygon; > 0: a closed slab this thick").unit("m").at_least(0).def("0"),
      P("extension", T::Number, "length beyond each window jamb").unit("m").at_least(0).def("0"),
      P("material", T::String, "material of every face").required(),
  }});
  s.push_back({"fins system", "vertical projections beside a window", {
      system_type(), system_name(), system_enabled(), system_window(), system_port(),
      P("depth", T::Number, "from the wall to the free edge, along the fin").unit("m").above(0).required(),
      P("jambs", T::Choice, "which jambs get a fin, as seen from outside").choices({"both", "left", "right"}).def("both"),
      P("offset", T::Number, "from the jamb to the fin, away from the window").unit("m").at_least(0).def("0"),
      P("extension", T::Number, "above the window head and below the sill").unit("m").at_least(0).def("0"),
      P("angle", T::Number, "free edges turned toward the window's centre line").unit("deg").range(-80, 80).def("0"),
      P("thickness", T::Number, "0: one two-sided polygon; > 0: a closed slab this thick").unit("m").at_least(0).def("0"),
      P("material", T::String, "material of every face").required(),
  }});
  s.push_back({"sensors", "where illuminance is computed", {
      P("grids", T::SectionList, "regular grids on a room floor, a polygon, a room wall or any rectangle").section("grid"),
      P("points", T::SectionList, "explicit sensor points").section("points"),
      P("honeybee_grids", T::Special, "sensor grids of the Honeybee model (geometry.honeybee): `all`, or a list of grid identifiers and {grid, name, drop_occluded} maps; each becomes a point set named by its identifier"),
  }});
  s.push_back({"honeybee grid", "one sensor grid of the Honeybee model, in `sensors.honeybee_grids`", {
      P("grid", T::String, "identifier of a sensor grid in the model's properties.radiance.sensor_grids").required(),
      P("name", T::String, "sensor-set name, also its output folder (default: the grid's identifier): a path name (see Names that become folders)"),
      P("drop_occluded", T::Boolean, "drop the sensors that lie outside every room, inside a solid or on a surface crossing the work plane (counted in run.log, summary.json and the report) instead of stopping with an error").def("false"),
  }});
  // Wall and rectangle grids: frames and order in project/src/sensor_grid.cpp.
  s.push_back({"grid", "a regular sensor grid over a room floor, a polygon, a room wall or a rectangle (give exactly one of them)", {
      P("name", T::String, "unique sensor-set name, also its output folder: a path name (see Names that become folders), not `variants` or `operated`").required(),
      P("room", T::String, "room whose floor the grid covers"),
      P("polygon", T::PointList, "outline [x, y, z] (z ignored)").unit("m"),
      P("wall", T::Section, "a wall, the floor or the ceiling of a room; sensors face into the room").section("grid wall"),
      P("rectangle", T::Section, "the parallelogram origin + s u + t v (s, t in [0, 1]); sensors face u x v (right-hand rule)").section("grid rectangle"),
      P("height", T::Number, "room and polygon grids: the sensor plane, above the room floor for room grids, absolute z for polygon grids").unit("m").def("0.8"),
      P("spacing", T::Number, "distance between sensors").unit("m").above(0).def("0.5"),
      P("inset", T::Number, "distance kept from the outline").unit("m").at_least(0).def("0.5"),
      P("offset", T::Number, "wall and rectangle grids: distance of the sensors from the surface along their normal (0: on it)").unit("m").at_least(0).def("0"),
      P("normal", T::Vec3, "room and polygon grids: direction the sensors face").def("[0, 0, 1]"),
      P("drop_occluded", T::Boolean, "drop the sensors that lie outside every room, inside a solid or on a surface crossing the work plane (counted in run.log, summary.json and the report) instead of stopping with an error").def("false"),
      P("occupancy", T::Section, "this sensor set's own occupancy schedule (as metrics.occupancy), instead of the project's").section("occupancy"),
  }});
  s.push_back({"grid wall", "a room surface covered by a grid", {
      P("room", T::String, "name of a room in geometry.rooms").required(),
      P("wall", T::Choice, "which surface: a wall (by the side of the room it is on), the floor or the ceiling").choices({"south", "north", "east", "west", "floor", "ceiling"}).required(),
  }});
  s.push_back({"grid rectangle", "a parallelogram in model coordinates covered by a grid", {
      P("origin", T::Vec3, "the corner s = t = 0").unit("m").required(),
      P("u", T::Vec3, "first edge vector: the lattice's inner (column) direction").unit("m").required(),
      P("v", T::Vec3, "second edge vector: the lattice's outer (row) direction; not parallel to u").unit("m").required(),
  }});
  s.push_back({"points", "explicit sensors (give `points` or `file`)", {
      P("name", T::String, "unique sensor-set name, also its output folder: a path name (see Names that become folders), not `variants` or `operated`").required(),
      P("points", T::Special, "[[x, y, z, nx, ny, nz], ...] in metres"),
      P("file", T::Path, "RADIANCE .pts file (x y z nx ny nz per line), must exist"),
      P("units", T::Choice, "with `file`: length unit of the file's positions (Honeybee's names), converted to metres").choices(length_unit_names()).def("Meters"),
      P("drop_occluded", T::Boolean, "drop the sensors that lie outside every room, inside a solid or on a surface crossing the work plane (counted in run.log, summary.json and the report) instead of stopping with an error").def("false"),
      P("occupancy", T::Section, "this sensor set's own occupancy schedule (as metrics.occupancy), instead of the project's").section("occupancy"),
  }});
  s.push_back({"simulation", "photon tracing and sky discretisation", {
      P("basis", T::Special, "sky patches: tregenza, reinhart:N or {reinhart: N} (N = 1..12)").def("tregenza"),
      P("photons_per_bin", T::Integer, "stored photons per sky/sun bin (written: a fixed count instead of the default accuracy target)").at_least(1).def("20000"),
      P("bandwidth", T::Integer, "nearest photons per density estimate").at_least(1).def("50"),
      P("seed", T::Integer, "random seed").at_least(0).def("1"),
      P("ground_reflectance", T::Number, "reflectance of the ground below the horizon").range(0, 1).def("0.2"),
      P("sun", T::Choice, "direct sun: fixed sun bins, or spread over sky patches").choices({"bins", "spread"}).def("bins"),
      P("sun_mf", T::Integer, "Reinhart subdivision whose patch centres are the sun bins").range(1, 12).def("6"),
      P("direct_samples_per_bin", T::Integer, "shadow rays per bin for the direct component").at_least(1).def("16"),
      P("caustic_photons_per_bin", T::Integer, "stored caustic photons per sky/sun bin, a target of their own (0: stored like the global ones)").at_least(0).def("0"),
      P("caustic_bandwidth", T::Integer, "photons per caustic estimate, among caustic photons only (0: `bandwidth` if caustic_photons_per_bin > 0, else caustic and global photons share one disc)").at_least(0).def("0"),
      P("region_of_interest", T::Section, "store photons only inside this box, and on diffusing ports (a final gather behind one reads them); the photon targets count only those (every sensor must lie inside; a gathered set whose rays reach other surfaces outside it is warned about)").section("region of interest"),
      P("max_attempts_per_photon", T::Integer, "low-yield cap: main-pass attempts per target photon of a bin (0 = no cap)").at_least(0).def("256"),
      P("accuracy", T::Section, "trace the sky bins (and the sun bins) in rounds until the daylight factors (and the annual sun-bin illuminance) reach a relative standard error, instead of photons_per_bin photons each (not with photons_per_bin or caustic_photons_per_bin; without any of the three, the final preset applies)").section("accuracy"),
      P("estimator", T::Choice, "receiver-plane and surface estimates: each source from its own nearest photons, or the nearest photons of all sources binned by source (docs/photon-map.md)").choices({"per_source", "contribution"}).def("per_source"),
      P("point_estimate", T::Choice, "sensors off a receiver plane (points, vertical and tilted grids): a final gather from each sensor, or the surface photons at a sensor lying on a surface").choices({"gather", "surface"}).def("gather"),
      P("gather_rays", T::Integer, "final-gather rays per sensor (rounded up to a square)").range(1, 65536).def("1024"),
      P("gather_bandwidth", T::Integer, "photons per lookup where a gather ray lands (all sources together)").range(1, 10000).def("32"),
  }});
  s.push_back({"accuracy", "the accuracy target of simulation.accuracy (docs/photon-tracing.md, \"Accuracy target\")", {
      P("preset", T::Choice, "a target by name: draft 5 %, standard 2 %, final 1 % (not with target_df_relative_stderr_percent)").choices({"draft", "standard", "final"}),
      P("target_df_relative_stderr_percent", T::Number, "the 95th percentile of the sensors' relative standard error of DF to reach").unit("%").range(0.05, 50).def("1"),
      P("max_photons", T::Integer, "photon budget: stored photons of all sky bins (0: limits.photons)").at_least(0).def("0"),
      P("max_seconds", T::Number, "time budget for tracing and estimating, checked before each round (0: none; a run it stops is not reproducible)").unit("s").at_least(0).def("0"),
  }});
  s.push_back({"region of interest", "a box, model coordinates, where photons are stored", {
      P("origin", T::Vec3, "min corner").unit("m").required(),
      P("size", T::Vec3, "x, y, z extents").unit("m").above(0).required(),
  }});
  s.push_back({"basis", "map form of simulation.basis", {
      P("reinhart", T::Integer, "Reinhart subdivision MF (1 = Tregenza, 145 patches; MF n: 144 n^2 + 1)").range(1, 12).required(),
  }});
  const ResourceLimits limits;  // the defaults, declared once in core/resource_limits.h
  s.push_back({"limits", "resource limits, checked before anything of that size is allocated: a typo such as `spacing: 0.000001` gives an error, not gigabytes of memory", {
      P("sensors_per_grid", T::Integer, "sensors in one grid or point set (an annual table holds 35 KB per sensor)").at_least(1).def(std::to_string(limits.sensors_per_grid)),
      P("sensors", T::Integer, "sensors of all grids and point sets together").at_least(1).def(std::to_string(limits.sensors)),
      P("photons", T::Integer, "photons stored by one tracing pass, (photons_per_bin + caustic_photons_per_bin) x sky bins (146 Tregenza, 144 n^2 + 2 Reinhart MF n); 32 bytes each").at_least(1).def(std::to_string(limits.photons)),
  }});
  s.push_back({"outputs", "what is written, and where", {
      P("folder", T::Path, "output folder, relative to the project file; outside the project's folder (absolute, or leaving it with ..) only with folder_outside_project or `run --output`").def("results"),
      P("folder_outside_project", T::Boolean, "allow `folder` outside the project's folder").def("false"),
      P("daylight_factor", T::Boolean, "CIE overcast daylight factors").def("true"),
      P("annual_illuminance", T::Boolean, "hourly illuminance for the weather year (illuminance.bin, float32)").def("true"),
      P("illuminance_csv", T::Boolean, "the hourly illuminance also as text, illuminance.csv (the same table rounded to 0.1 lx, written a second time: 400 MiB at 10,000 sensors)").def("false"),
      P("metrics", T::Boolean, "annual metrics (DA, UDI, sDA, ASE, ...)").def("true"),
      P("coefficients", T::Boolean, "daylight-coefficient matrices (.mtx) and the exported direct sun").def("true"),
      P("radiance_sun_matrix", T::Boolean, "with coefficients and sun: bins, also the sun on RADIANCE's Reinhart patches for gendaymtx -d (coefficients_sun_mf<N>.mtx; traces the direct sun at every patch centre)").def("false"),
      P("images", T::Boolean, "EXR/PNG false-colour images").def("true"),
      P("report", T::Boolean, "report.html").def("true"),
      P("matrix_format", T::Choice, "encoding of .mtx files: float (RADIANCE's binary float32, FORMAT=float and BigEndian= in the header, as rmtxop and dctimestep read it) or ascii (text, up to 3 times larger)").choices({"ascii", "float"}).def("float"),
  }});
  // Defaults as LM-83 and docs/metrics.md; they mirror metrics::MetricSettings.
  s.push_back({"metrics", "thresholds and occupancy of the daylight-factor statistics and annual metrics", {
      P("daylight_factor_thresholds", T::NumberList, "DF statistics report the area with DF >= each value (no duplicates)").unit("%").range(0, 100).above(0).def("[2]"),
      P("da_threshold", T::Number, "illuminance threshold of DA, cDA and sDA; splits the revised UDI band").unit("lx").above(0).def("300"),
      P("occupancy_start", T::Number, "occupied: records whose mid-hour time t has occupancy_start <= t < occupancy_end (local standard time, no DST, every day)").unit("h").range(0, 24).def("8"),
      P("occupancy_end", T::Number, "end of the occupied hours, greater than occupancy_start").unit("h").range(0, 24).def("18"),
      P("occupancy", T::Section, "an occupancy schedule instead of occupancy_start/occupancy_end: hours per kind of day, holidays, daylight saving time, or a CSV file").section("occupancy"),
      P("udi_lower", T::Number, "UDI: below this the illuminance fell short").unit("lx").above(0).def("100"),
      P("udi_upper_original", T::Number, "UDI (Nabil & Mardaljevic 2005): above this it is exceeded").unit("lx").above(0).def("2000"),
      P("udi_upper_revised", T::Number, "revised UDI (Mardaljevic): above this it is exceeded").unit("lx").above(0).def("3000"),
      P("sda_time_fraction", T::Number, "sDA: fraction of occupied hours a sensor must reach da_threshold").range(0, 1).above(0).def("0.5"),
      P("ase_threshold", T::Number, "ASE: direct-sun illuminance threshold").unit("lx").above(0).def("1000"),
      P("ase_hours", T::Number, "ASE: a sensor fails with more occupied hours than this at or above ase_threshold").unit("h").range(0, 8784).def("250"),
  }});
  // docs/metrics.md "Occupancy schedules"; mirrors metrics::OccupancyPlan.
  s.push_back({"occupancy", "occupied hours of the annual metrics (docs/metrics.md, Occupancy schedules); hours are [start, end] of local clock time: a window such as [8, 17], a list of windows such as [[8, 12], [13, 17]], or closed. A day takes its own key, else weekdays / weekends, else every_day, else it is closed", {
      P("every_day", T::Special, "hours of every day not given otherwise").unit("h"),
      P("weekdays", T::Special, "hours of Monday to Friday").unit("h"),
      P("weekends", T::Special, "hours of Saturday and Sunday").unit("h"),
      P("monday", T::Special, "hours of Mondays").unit("h"),
      P("tuesday", T::Special, "hours of Tuesdays").unit("h"),
      P("wednesday", T::Special, "hours of Wednesdays").unit("h"),
      P("thursday", T::Special, "hours of Thursdays").unit("h"),
      P("friday", T::Special, "hours of Fridays").unit("h"),
      P("saturday", T::Special, "hours of Saturdays").unit("h"),
      P("sunday", T::Special, "hours of Sundays").unit("h"),
      P("holidays", T::Special, "days with holiday_hours instead: a list of dates MM-DD (12-25) and periods MM-DD..MM-DD (07-06..08-31; 12-23..01-03 runs over the year end), the same every year of the weather file"),
      P("holiday_hours", T::Special, "hours of the holidays").unit("h").def("closed"),
      P("january_1", T::Choice, "weekday of 1 January (default: from the weather file's DATA PERIODS start day)").choices({"monday", "tuesday", "wednesday", "thursday", "friday", "saturday", "sunday"}),
      P("daylight_saving", T::Choice, "the hours are clock time with daylight saving time: eu (last Sunday of March to last Sunday of October, 01:00 UTC), us (second Sunday of March to first Sunday of November, 02:00 local time) or none (standard time all year)").choices({"none", "eu", "us"}).def("none"),
      P("file", T::Path, "CSV file, relative to the project file: one value per weather record in file order, 1 occupied or 0 not (a first line that is not a number is a header); no other key with it"),
  }});
  s.push_back({"variant", "a study variant: the whole project with the listed materials and systems replaced, and geometry removed or added", {
      P("name", T::String, "unique variant name, also its output folder: a path name (see Names that become folders)").required(),
      P("materials", T::NameMap, "name of a material in `materials` -> its full definition in this variant"),
      P("systems", T::NameMap, "name of a system in `geometry.systems` -> the keys it changes in this variant (any but type and name)"),
      P("remove", T::Section, "base elements this variant leaves out, by name").section("variant remove"),
      P("add", T::Section, "elements this variant adds, defined as in `geometry`").section("variant add"),
  }});
  s.push_back({"variant remove", "names of base elements a variant leaves out; nothing left may depend on them", {
      P("polygons", T::NameList, "polygons of `geometry.polygons`"),
      P("boxes", T::NameList, "boxes of `geometry.boxes`"),
      P("meshes", T::NameList, "meshes of `geometry.meshes`"),
      P("systems", T::NameList, "systems of `geometry.systems` (not also changed under the variant's `systems`)"),
      P("windows", T::NameList, "windows of rooms (photon ports); no remaining system may be mounted on one, nor a wall grid cover its wall"),
  }});
  s.push_back({"variant add", "elements a variant adds, each a full definition with a name the base does not use (or that the variant removes)", {
      P("polygons", T::SectionList, "planar polygons").section("polygon"),
      P("boxes", T::SectionList, "solid boxes").section("box"),
      P("meshes", T::SectionList, "Wavefront OBJ meshes").section("mesh"),
      P("systems", T::SectionList, "daylight systems").section("system"),
      P("windows", T::SectionList, "windows, each in a room of `geometry.rooms`").section("added window"),
  }});
  {
    // The keys of a window, with the room it is cut into first.
    SectionSchema added{"added window", "a window a variant adds: `room` and the keys of a window", {
        P("room", T::String, "name of the room in `geometry.rooms` whose wall the window is in").required(),
    }};
    for (const SectionSchema& section : s)
      if (section.name == "window") added.params.insert(added.params.end(), section.params.begin(), section.params.end());
    s.push_back(added);
  }
  // LM-83-12 section 2.2.6 and its definition of direct sun (docs/metrics.md).
  s.push_back({"operation", "operated shading: per grid and hour, the shaded case when too many sensors see direct sun in the open case (IES LM-83 blinds rule; needs simulation.sun: bins)", {
      P("open", T::String, "case of the open state: a variant name, or `base` for the project as written; its direct sun decides every hour and gives ASE").required(),
      P("shaded", T::String, "case of the shaded state (a variant name or `base`), used in the hours the rule closes the shading").required(),
      P("direct_sun_threshold", T::Number, "a sensor sees direct sun when its direct-sun-only, zero-bounce illuminance in the open case is >= this").unit("lx").above(0).def("1000"),
      P("sunlit_limit", T::Number, "an hour is shaded when MORE than this share of the grid's sensors see direct sun").unit("%").range(0, 100).def("2"),
  }});
  // EN 17037:2018, exposure to sunlight (docs/metrics.md "EN 17037 exposure to sunlight").
  s.push_back({"sunlight_exposure", "EN 17037 exposure to sunlight: per window of `geometry.rooms` the hours of possible sunlight at its reference point (centre of the width, on the inner surface, the lowest height at least 1.2 m above the floor and 0.3 m above the sill), on a cloudless date, the sun above min_altitude; per room the union of its windows' hours", {
      P("date", T::String, "month-day between 02-01 and 03-21 (EN 17037's dates)").def("03-21"),
      P("min_altitude", T::Number, "the sun counts only at or above this altitude (geometric, of the disc's centre): EN 17037 makes it depend on the site (its table or the national annex); no default").unit("deg").range(0, 45).required(),
      P("time_step", T::Number, "the sun is sampled this often and each change of visibility found to 1 s between samples; a sunlit or shaded spell shorter than the step may be missed").unit("min").range(0.1, 15).def("1"),
      P("windows", T::NameList, "windows of `geometry.rooms` to assess; default every window in an outside wall (roof lights and interior windows are not assessed)"),
  }});
  s.push_back({"point_in_time", "one date and local standard time under one sky: illuminance per sensor (sky, sun and their reflections)", {
      P("name", T::String, "case name: a column of point_in_time.csv and an image name (the folder-name rule)").required(),
      P("date", T::String, "month-day, e.g. 03-21; 02-29 with sky: weather needs a weather file that holds that day, a CIE sky takes a leap year's sun").required(),
      P("time", T::String, "local standard time (no daylight saving), HH:MM or decimal hours, 0 to 24").required(),
      P("sky", T::Choice, "cie_overcast: the CIE standard overcast sky, no sun; cie: the CIE standard general sky of cie_type with its sun; weather: the weather file's hour that contains the time, EPW hour h covering (h-1, h] (15:00 is hour 15) (its Perez sky and sun, as in the annual study)").choices({"cie_overcast", "cie", "weather"}).required(),
      P("cie_type", T::Integer, "CIE standard general sky type (ISO 15469:2004 / CIE S 011), with sky: cie").range(1, 15),
      P("diffuse_horizontal_illuminance", T::Number, "horizontal illuminance of the sky alone (without the sun), CIE skies").unit("lx").above(0).def("10000"),
      P("direct_normal_illuminance", T::Number, "the sun's direct normal illuminance, with sky: cie (required: 0 for a sky without sun)").unit("lx").range(0, 200000),
  }});
  return s;
}

}  // namespace

std::string param_type_name(ParamType type) {
  switch (type) {
    case ParamType::Number: return "number";
    case ParamType::Integer: return "integer";
    case ParamType::Boolean: return "boolean";
    case ParamType::String: return "string";
    case ParamType::Choice: return "choice";
    case ParamType::Angle: return "angle";
    case ParamType::Vec3: return "[x, y, z]";
    case ParamType::Rgb: return "number or [r, g, b]";
    case ParamType::Path: return "path";
    case ParamType::PointList: return "list of [x, y, z]";
    case ParamType::NumberList: return "list of numbers";
    case ParamType::NameList: return "list of names";
    case ParamType::Section: return "map";
    case ParamType::SectionList: return "list";
    case ParamType::NameMap: return "map";
    case ParamType::Special: return "see help";
  }
  return "?";
}

bool ParamSchema::has_range() const { return std::isfinite(min) || std::isfinite(max); }

std::string ParamSchema::range_text() const {
  const bool lo = std::isfinite(min), hi = std::isfinite(max);
  if (lo && hi) return (min_exclusive ? "(" : "[") + format_number(min) + ", " + format_number(max) + "]";
  if (lo) return (min_exclusive ? "> " : ">= ") + format_number(min);
  if (hi) return "<= " + format_number(max);
  return {};
}

bool ParamSchema::in_range(double value) const {
  if (min_exclusive ? !(value > min) : !(value >= min)) return false;
  return value <= max;
}

const ParamSchema* SectionSchema::find(const std::string& key) const {
  for (const auto& p : params)
    if (p.name == key) return &p;
  return nullptr;
}

std::vector<std::string> SectionSchema::keys() const {
  std::vector<std::string> k;
  for (const auto& p : params) k.push_back(p.name);
  return k;
}

const std::vector<SectionSchema>& project_schema() {
  static const std::vector<SectionSchema> schema = build_schema();
  return schema;
}

const SectionSchema& schema_section(const std::string& name) {
  for (const auto& s : project_schema())
    if (s.name == name) return s;
  throw std::logic_error("no schema section '" + name + "'");
}

std::string format_project_schema() {
  std::ostringstream out;
  for (const auto& section : project_schema()) {
    out << "### " << section.name << "\n\n" << section.help << ".\n\n";
    out << "| key | type | unit | range | default | help |\n";
    out << "| --- | --- | --- | --- | --- | --- |\n";
    for (const auto& p : section.params) {
      std::string type = param_type_name(p.type);
      if (p.type == ParamType::Choice) {
        type.clear();
        for (const auto& c : p.choices) type += (type.empty() ? "" : " \\| ") + c;
      } else if (p.type == ParamType::Section) {
        type = "map (" + p.section + ")";
      } else if (p.type == ParamType::SectionList) {
        type = "list of " + p.section;
      }
      const std::string def = p.required ? "**required**"
                              : p.default_value.empty() ? "" : "`" + p.default_value + "`";
      out << "| `" << p.name << "` | " << type << " | " << p.unit << " | " << p.range_text()
          << " | " << def << " | " << p.help << " |\n";
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace dayphoton::project
