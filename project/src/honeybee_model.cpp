// read_honeybee_model (honeybee_model.h): HBJSON -> surfaces, materials and sensor grids.
//
// Schema: ladybug-tools honeybee-schema, model.py (Model, Room, Face, Aperture, Door, Shade,
// Face3D, units, tolerance) and radiance/ (modifiers, modifier sets, sensor grids). Modifier
// assignment follows honeybee-radiance's ModifierSet (modifierset.py: get_face_modifier,
// get_aperture_modifier, get_door_modifier, get_shade_modifier): an object's own modifier,
// else its room's modifier set (the model's global_modifier_set for a room without one, and
// for orphaned faces, apertures, doors and shades), a slot the set leaves empty taking the
// generic default.
//
// Geometry: coordinates are scaled to metres; a face must be planar within the model's
// tolerance and is then projected onto its mean plane; its apertures and doors (and its
// Face3D holes) must lie in that plane and inside it, and are cut out of it
// (polygon_holes.h). Room faces point out of their room (Honeybee's convention), so an
// aperture in an Outdoors face is a photon port whose normal points out of the room
// (PortFacing::Out, tested against the scene like a declared polygon port); one of a BSDF
// modifier is turned round (its vertices reversed, PortFacing::In), so that the BSDF's front,
// the side its normal points away from, is outdoors. Two rooms that
// share a wall each have a Surface face: only the first in file order becomes a surface (two
// coincident surfaces would be hit at random, and a ray through a shared window would cross
// its glass twice); its apertures and doors stand for both.
#include "dayphoton/project/honeybee_model.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/core/polygon.h"
#include "dayphoton/project/length_units.h"
#include "honeybee_modifiers.h"
#include "json_locator.h"
#include "polygon_holes.h"

namespace dayphoton::project {

double honeybee_metres_per_unit(const std::string& units) { return metres_per_length_unit(units); }

namespace {

/// Deepest nesting of objects and arrays accepted (HBJSON nests about 12 levels).
constexpr std::size_t MaxJsonDepth = 64;

using json = nlohmann::json;
using detail::JsonLocator;
using detail::json_element;
using detail::json_member;
using detail::ModifierSet;
using detail::RadianceModifier;

/// A polygon of the model in metres, projected onto its plane.
struct Polygon3 {
  std::vector<Vec3> boundary;
  std::vector<std::vector<Vec3>> holes;
  Vec3 normal;
  Vec3 centroid;
};

class Reader {
 public:
  Reader(const JsonLocator& locator, Diagnostics& diag, HoneybeeModel& out)
      : m_loc(locator), m_diag(diag), m_out(out) {}

  void read(const json& root) {
    if (!root.is_object()) {
      error("", "", "expected a Honeybee Model (a JSON object), got " + kind(root));
      return;
    }
    std::string type;
    if (get_string(root, "", "", "type", type, false) && type != "Model")
      error("type", "", "expected a Honeybee 'Model', got '" + type + "'");
    get_string(root, "", "", "identifier", m_out.identifier, false);
    m_out.units = "Meters";
    get_string(root, "", m_out.identifier, "units", m_out.units, false);
    m_out.metres_per_unit = honeybee_metres_per_unit(m_out.units);
    if (m_out.metres_per_unit == 0) {
      error("units", m_out.identifier,
            "unknown units '" + m_out.units + "' (Meters, Millimeters, Centimeters, Feet or Inches)");
      m_out.metres_per_unit = 1;
    }
    double tolerance = 0.01;
    if (get_number(root, "", m_out.identifier, "tolerance", tolerance, false) && tolerance < 0)
      error("tolerance", m_out.identifier, "tolerance must be >= 0, got " + format_number(tolerance));
    // A tolerance of 0 means "no checks" in Honeybee; the planarity test then takes the one
    // of the scene's own polygons (1 mm).
    m_out.tolerance_m = tolerance > 0 ? tolerance * m_out.metres_per_unit : 1e-3;
    // Old files' model-level north (honeybee_model.h); null is "not written".
    if (const json* v = find(root, "north_angle"); v && !v->is_null()) {
      double north = 0;
      if (get_number(root, "", m_out.identifier, "north_angle", north, false)) {
        m_out.north_angle_deg = north;
        m_out.north_angle_location = m_loc.locate("north_angle");
      }
    }

    if (const json* v = find(root, "shade_meshes"); v && !v->is_null() && !(v->is_array() && v->empty()))
      error("shade_meshes", m_out.identifier,
            "'shade_meshes' is not supported: dayphoton imports planar shades; export them as Shade objects");

    read_radiance_properties(root);

    if (const json* rooms = find(root, "rooms"); rooms && !rooms->is_null()) {
      if (!rooms->is_array()) {
        error("rooms", m_out.identifier, "expected a list of rooms, got " + kind(*rooms));
      } else {
        for (std::size_t i = 0; i < rooms->size(); ++i) read_room((*rooms)[i], json_element("rooms", i));
      }
    }
    if (const json* shades = find(root, "orphaned_shades"); shades && !shades->is_null()) {
      if (!shades->is_array()) {
        error("orphaned_shades", m_out.identifier, "expected a list of shades, got " + kind(*shades));
      } else {
        for (std::size_t i = 0; i < shades->size(); ++i) {
          const json& s = (*shades)[i];
          const std::string path = json_element("orphaned_shades", i);
          bool indoor = false, detached = false;
          if (s.is_object()) {
            get_bool(s, path, "", "is_indoor", indoor);
            get_bool(s, path, "", "is_detached", detached);
          }
          read_shade(s, path, m_global, indoor, detached && !indoor);
        }
      }
    }
    read_orphans(root);
    check_shared_faces();
    read_grids(root);
    build_materials();
    if (m_out.surfaces.empty() && !m_diag.has_errors())
      error("", m_out.identifier, "the model has no rooms and no shades: nothing to import");
  }

 private:
  // ---- messages ---------------------------------------------------------------------------
  static std::string kind(const json& v) {
    switch (v.type()) {
      case json::value_t::null: return "null";
      case json::value_t::object: return "an object";
      case json::value_t::array: return "a list";
      case json::value_t::string: return "a string";
      case json::value_t::boolean: return "a boolean";
      default: return "a number";
    }
  }

  void error(const std::string& path, const std::string& id, const std::string& message) {
    const SourceLocation where = m_loc.locate(path);
    std::string what = path.empty() ? "model" : path;
    if (!id.empty()) what += " ('" + id + "')";
    std::string line;
    if (!m_diag.at_cap()) line = read_source_line(where.file, where.line);
    m_diag.error(where, what + ": " + message, line);
  }

  void warning(const std::string& path, const std::string& id, const std::string& message) {
    const SourceLocation where = m_loc.locate(path);
    std::string what = path.empty() ? "model" : path;
    if (!id.empty()) what += " ('" + id + "')";
    m_diag.warning(where, what + ": " + message, read_source_line(where.file, where.line));
  }

  /// An aperture, door or shade of a dynamic group (honeybee-schema's
  /// `properties.radiance.dynamic_group_identifier` and `states`): honeybee-radiance
  /// simulates each state separately (its modifier and its shades), dayphoton models the
  /// object's own modifier in every hour. Said at the object, not left to be found in the
  /// numbers.
  void warn_dynamic_states(const json& obj, const std::string& path, const std::string& id,
                           const std::string& modifier) {
    const json* props = find(obj, "properties");
    const json* rad = props ? find(*props, "radiance") : nullptr;
    if (!rad || !rad->is_object()) return;
    const json* group = find(*rad, "dynamic_group_identifier");
    const json* states = find(*rad, "states");
    const std::size_t count = states && states->is_array() ? states->size() : 0;
    if ((!group || !group->is_string()) && count == 0) return;
    const std::string rpath = json_member(json_member(path, "properties"), "radiance");
    std::string what = group && group->is_string() ? "in dynamic group '" + group->get<std::string>() + "'" : "dynamic";
    if (count > 0) what += " with " + std::to_string(count) + " state" + (count == 1 ? "" : "s");
    warning(group && group->is_string() ? json_member(rpath, "dynamic_group_identifier") : json_member(rpath, "states"), id,
            what + ": dayphoton models its own modifier '" + modifier +
                "' in every hour, not the states' modifiers or shades (honeybee-radiance simulates each state); to "
                "study a state, make its modifier the object's modifier (or use a variant)");
  }

  // ---- typed access -----------------------------------------------------------------------
  static const json* find(const json& obj, const char* key) {
    if (!obj.is_object()) return nullptr;
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  /// Member `key` of object `obj` (at `path`); reports it missing when required.
  const json* member(const json& obj, const std::string& path, const std::string& id, const char* key,
                     bool required) {
    const json* v = find(obj, key);
    if ((!v || v->is_null()) && required) {
      error(path, id, std::string("missing required field '") + key + "'");
      return nullptr;
    }
    return v && !v->is_null() ? v : nullptr;
  }

  bool get_string(const json& obj, const std::string& path, const std::string& id, const char* key,
                  std::string& out, bool required) {
    const json* v = member(obj, path, id, key, required);
    if (!v) return false;
    if (!v->is_string()) {
      error(json_member(path, key), id, "expected a string, got " + kind(*v));
      return false;
    }
    out = v->get<std::string>();
    return true;
  }

  bool get_number(const json& obj, const std::string& path, const std::string& id, const char* key,
                  double& out, bool required) {
    const json* v = member(obj, path, id, key, required);
    if (!v) return false;
    if (!v->is_number() || !std::isfinite(v->get<double>())) {
      error(json_member(path, key), id, "expected a finite number, got " + kind(*v));
      return false;
    }
    out = v->get<double>();
    return true;
  }

  void get_bool(const json& obj, const std::string& path, const std::string& id, const char* key, bool& out) {
    const json* v = member(obj, path, id, key, false);
    if (!v) return;
    if (!v->is_boolean()) {
      error(json_member(path, key), id, "expected true or false, got " + kind(*v));
      return;
    }
    out = v->get<bool>();
  }

  /// A point [x, y, z] in model units -> metres.
  bool point(const json& v, const std::string& path, const std::string& id, Vec3& out, double scale) {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number()) {
      error(path, id, "expected a point [x, y, z] of 3 numbers, got " + (v.is_array() ? "a list of " + std::to_string(v.size()) + " values" : kind(v)));
      return false;
    }
    out = Vec3{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()} * scale;
    if (!is_finite(out)) {
      error(path, id, "a coordinate is not finite");
      return false;
    }
    return true;
  }

  bool points(const json& v, const std::string& path, const std::string& id, std::vector<Vec3>& out) {
    if (!v.is_array()) {
      error(path, id, "expected a list of points, got " + kind(v));
      return false;
    }
    if (v.size() < 3) {
      error(path, id, "a polygon needs at least 3 points, got " + std::to_string(v.size()));
      return false;
    }
    out.clear();
    for (std::size_t i = 0; i < v.size(); ++i) {
      Vec3 p;
      if (!point(v[i], json_element(path, i), id, p, m_out.metres_per_unit)) return false;
      out.push_back(p);
    }
    return true;
  }

  /// The Face3D `geometry` of an object: planar within the tolerance, projected onto its plane.
  bool face3d(const json& obj, const std::string& path, const std::string& id, Polygon3& out) {
    const json* g = member(obj, path, id, "geometry", true);
    if (!g) return false;
    const std::string gpath = json_member(path, "geometry");
    if (!g->is_object()) {
      error(gpath, id, "expected a Face3D object, got " + kind(*g));
      return false;
    }
    std::string type;
    if (get_string(*g, gpath, id, "type", type, false) && type != "Face3D") {
      error(json_member(gpath, "type"), id, "expected a 'Face3D', got '" + type + "' (only planar faces are imported)");
      return false;
    }
    const json* b = member(*g, gpath, id, "boundary", true);
    if (!b || !points(*b, json_member(gpath, "boundary"), id, out.boundary)) return false;
    out.normal = polygon_normal(out.boundary);
    if (out.normal == Vec3{0, 0, 0} || polygon_area_m2(out.boundary) < 1e-10) {
      error(json_member(gpath, "boundary"), id, "the face is degenerate (zero area)");
      return false;
    }
    out.centroid = polygon_centroid(out.boundary);
    if (!planar(out.boundary, out, json_member(gpath, "boundary"), id)) return false;
    if (const json* holes = member(*g, gpath, id, "holes", false)) {
      if (!holes->is_array()) {
        error(json_member(gpath, "holes"), id, "expected a list of holes, got " + kind(*holes));
        return false;
      }
      for (std::size_t i = 0; i < holes->size(); ++i) {
        const std::string hpath = json_element(json_member(gpath, "holes"), i);
        std::vector<Vec3> hole;
        if (!points((*holes)[i], hpath, id, hole) || !planar(hole, out, hpath, id)) return false;
        out.holes.push_back(std::move(hole));
      }
    }
    return true;
  }

  /// Every vertex of `pts` within the tolerance of `plane`'s mean plane; then projected onto it.
  bool planar(std::vector<Vec3>& pts, const Polygon3& plane, const std::string& path, const std::string& id) {
    double worst = 0;
    for (const Vec3& p : pts) worst = std::max(worst, std::abs(dot(p - plane.centroid, plane.normal)));
    if (worst > m_out.tolerance_m) {
      error(path, id, "not planar: a vertex is " + format_number(worst) + " m from the face's plane (the model's tolerance is " +
                          format_number(m_out.tolerance_m) + " m); split it into planar faces");
      return false;
    }
    for (Vec3& p : pts) p = p - plane.normal * dot(p - plane.centroid, plane.normal);
    return true;
  }

  /// A sub-face (aperture, door) lies in its face's plane and inside its boundary.
  bool inside_face(std::vector<Vec3>& pts, const Polygon3& face, const std::string& path, const std::string& id,
                   const std::string& face_id) {
    if (!planar(pts, face, path, id)) return false;
    for (const Vec3& p : pts)
      if (!polygon_contains(face.boundary, p) && distance_to_polygon_boundary_m(face.boundary, p) > m_out.tolerance_m) {
        error(path, id, "is not inside its face '" + face_id + "' (a vertex at (" + format_coordinate(p.x) + ", " +
                            format_coordinate(p.y) + ", " + format_coordinate(p.z) + ") m lies outside it)");
        return false;
      }
    return true;
  }

  /// Whether a modifier lets light through (a glass of any transmissivity, a dielectric, a
  /// trans with a transmitted fraction and a colour): honeybee-radiance writes a Face or an
  /// opaque Door of such a modifier as that material, so RADIANCE lets the sky in through it.
  bool transmits(const std::string& modifier) const {
    const RadianceModifier* m = nullptr;
    if (const auto it = m_modifiers.find(modifier); it != m_modifiers.end()) m = &it->second;
    for (const RadianceModifier& g : detail::honeybee_generic_modifiers())
      if (!m && g.identifier == modifier) m = &g;
    if (!m) return false;
    auto any_positive = [&](std::size_t from, std::size_t count) {
      for (std::size_t i = from; i < from + count && i < m->args.size(); ++i)
        if (m->args[i] > 0) return true;
      return false;
    };
    std::string type = m->type;
    std::transform(type.begin(), type.end(), type.begin(), [](unsigned char c) { return std::tolower(c); });
    if (type == "bsdf") return true;  // measured: its matrices say how much
    if (type == "glass" || type == "dielectric") return any_positive(0, 3);
    if (type == "trans") return m->args.size() >= 6 && m->args[5] > 0 && any_positive(0, 3);
    return false;
  }

  /// Whether modifier `id` is a BSDF (its surfaces are turned so that its front is outdoors).
  bool is_bsdf(const std::string& id) const {
    const auto it = m_modifiers.find(id);
    return it != m_modifiers.end() && it->second.type == "BSDF";
  }

  /// The role of a face or opaque door of modifier `material` with boundary condition `bc`:
  /// one that lets light through is glazing, a port in an Outdoors face and interior glazing
  /// in a Surface face, as an aperture there; on the ground or an adiabatic face no light
  /// comes through it, and it stays an ordinary surface.
  HoneybeeRole wall_role(const std::string& material, const std::string& bc) const {
    if (!transmits(material)) return HoneybeeRole::Opaque;
    if (bc == "Outdoors") return HoneybeeRole::Port;
    if (bc == "Surface") return HoneybeeRole::InteriorGlass;
    return HoneybeeRole::Opaque;
  }

  // ---- surfaces ---------------------------------------------------------------------------
  void emit(const std::string& id, const std::string& path, const std::vector<Vec3>& boundary,
            const std::vector<std::vector<Vec3>>& holes, const std::string& material, HoneybeeRole role,
            PortFacing facing = PortFacing::Out) {
    if (material.empty()) return;
    // A BSDF's front (WINDOW's exterior side) is the side its surface's normal points away
    // from, as in RADIANCE (docs/materials.md, "Measured BSDF (Klems)"), and must face
    // outdoors: a room's aperture, whose normal points out of the room, is turned round (its
    // vertices reversed, its port facing in). Where no room says which side is outdoors, the
    // BSDF is refused rather than put either way.
    const bool bsdf = is_bsdf(material);
    if (bsdf) {
      if (const char* why = honeybee_bsdf_refusal(role, facing)) {
        error(path, id, "has BSDF modifier '" + material + "': " + why);
        return;
      }
    }
    HoneybeeSurface s;
    s.material = material;
    s.role = role;
    s.facing = facing;
    s.path = path;
    s.location = m_loc.locate(path);
    if (holes.empty()) {
      s.name = id;
      s.vertices = boundary;
      if (bsdf) turn_for_bsdf(s.vertices, s.facing);
      m_out.surfaces.push_back(std::move(s));
      return;
    }
    std::vector<std::array<Vec3, 3>> triangles;
    try {
      triangles = detail::triangulate_with_holes(boundary, holes);
    } catch (const std::invalid_argument& e) {
      error(path, id, std::string("cannot cut its apertures, doors and holes out of it: ") + e.what() +
                          "; keep every opening inside the face, apart from its edges and from each other");
      return;
    }
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      HoneybeeSurface t = s;
      t.name = id + ":" + std::to_string(k + 1);
      t.vertices.assign(triangles[k].begin(), triangles[k].end());
      t.facing = facing;
      if (bsdf) turn_for_bsdf(t.vertices, t.facing);
      m_out.surfaces.push_back(std::move(t));
    }
  }

  // ---- modifiers --------------------------------------------------------------------------
  /// The modifier `id` named at `path`: recorded as used, or "" after an error.
  std::string use_modifier(const std::string& modifier, const std::string& path, const std::string& id) {
    const bool generic = std::any_of(detail::honeybee_generic_modifiers().begin(), detail::honeybee_generic_modifiers().end(),
                                     [&](const RadianceModifier& m) { return m.identifier == modifier; });
    if (!m_modifiers.count(modifier) && !generic) {
      error(path, id, "unknown modifier '" + modifier + "' (not in properties.radiance.modifiers)");
      return "";
    }
    if (m_used.emplace(modifier, m_loc.locate(path)).second) m_used_order.push_back(modifier);
    return modifier;
  }

  /// The modifier of an object: its own `properties.radiance.modifier`, else `slot` of `set`.
  std::string object_modifier(const json& obj, const std::string& path, const std::string& id,
                              const ModifierSet* set, const std::string& slot) {
    std::string own;
    if (const json* props = find(obj, "properties"); props && props->is_object())
      if (const json* rad = find(*props, "radiance"); rad && rad->is_object())
        if (get_string(*rad, json_member(json_member(path, "properties"), "radiance"), id, "modifier", own, false))
          return use_modifier(own, json_member(json_member(json_member(path, "properties"), "radiance"), "modifier"), id);
    const std::string& chosen = set ? set->modifier_for(slot) : detail::generic_modifier_for(slot);
    return use_modifier(chosen, set ? set->path : path, id);
  }

  std::optional<RadianceModifier> parse_modifier(const json& m, const std::string& path) {
    RadianceModifier mod;
    mod.path = path;
    mod.location = m_loc.locate(path);
    if (!m.is_object()) {
      error(path, "", "expected a modifier object, got " + kind(m));
      return std::nullopt;
    }
    if (!get_string(m, path, "", "identifier", mod.identifier, true)) return std::nullopt;
    const std::string& id = mod.identifier;
    if (!get_string(m, path, id, "type", mod.type, true)) return std::nullopt;
    // honeybee-schema writes the types capitalised since its modifier.py ("Plastic", "Glass",
    // "Void"), lower case before (material.py: "plastic"); RADIANCE's own words are lower case.
    static const std::set<std::string> capitalised = {"Plastic", "Metal", "Trans", "Glass", "Mirror", "Void", "Light", "Glow"};
    auto radiance_type = [](std::string t) {
      if (capitalised.count(t)) t[0] = static_cast<char>(t[0] - 'A' + 'a');
      return t;
    };
    mod.type = radiance_type(mod.type);
    if (const json* base = member(m, path, id, "modifier", false)) {
      std::string base_type;
      if (!base->is_object() || !get_string(*base, json_member(path, "modifier"), id, "type", base_type, false) ||
          radiance_type(base_type) != "void") {
        m_problems[id] = "is modified by another modifier (a pattern, texture or mixture), which is not supported";
        return mod;
      }
    }
    auto arg = [&](const char* key, double fallback) {
      double v = fallback;
      get_number(m, path, id, key, v, false);
      mod.args.push_back(v);
    };
    // Fields and defaults: honeybee-schema radiance/modifier.py. The real arguments are
    // RADIANCE's, in its order (honeybee-radiance modifier/material/*.py, _update_values:
    // trans writes transmitted_diff and transmitted_spec as RADIANCE's trans and tspec).
    if (mod.type == "plastic" || mod.type == "metal" || mod.type == "trans") {
      arg("r_reflectance", 0);
      arg("g_reflectance", 0);
      arg("b_reflectance", 0);
      arg("specularity", mod.type == "metal" ? 0.9 : 0);
      arg("roughness", 0);
      if (mod.type == "trans") {
        arg("transmitted_diff", 0);
        arg("transmitted_spec", 0);
      }
    } else if (mod.type == "glass") {
      arg("r_transmissivity", 0);
      arg("g_transmissivity", 0);
      arg("b_transmissivity", 0);
      arg("refraction_index", 1.52);
    } else if (mod.type == "mirror") {
      arg("r_reflectance", 1);
      arg("g_reflectance", 1);
      arg("b_reflectance", 1);
      if (const json* alt = member(m, path, id, "alternate_material", false); alt && !alt->is_null())
        m_problems[id] = "has an alternate_material, which is not supported";
    } else if (mod.type == "BSDF") {
      read_bsdf_fields(m, path, mod);
    } else {
      m_problems[id] = "has type '" + mod.type + "', which the Honeybee import does not support (plastic, metal, trans, glass, mirror, BSDF)";
    }
    return mod;
  }

  /// The fields of a BSDF modifier (honeybee-schema radiance/modifier.py `BSDF`, as
  /// honeybee-radiance's BSDF.to_dict writes them). What RADIANCE's BSDF primitive takes that
  /// dayphoton does not model is refused at its field, as the RADIANCE import refuses it
  /// (docs/radiance-import.md, "BSDF"); the problems are reported where an object uses it.
  void read_bsdf_fields(const json& m, const std::string& path, RadianceModifier& mod) {
    const std::string& id = mod.identifier;
    auto problem = [&](const char* key, const std::string& message, bool is_error = true) {
      mod.field_problems.push_back({json_member(path, key), message, is_error});
    };
    const json* data = find(m, "bsdf_data");
    if (!data || data->is_null()) {
      problem("bsdf_data", "missing required field 'bsdf_data' (the BSDF's XML)");
    } else if (!data->is_string()) {
      problem("bsdf_data", "expected the BSDF's XML as a string, got " + kind(*data));
    } else {
      mod.bsdf_xml = data->get<std::string>();
      mod.bsdf_data_location = m_loc.locate(json_member(path, "bsdf_data"));
    }
    if (const json* up = member(m, path, id, "up_orientation", false)) {
      const bool three = up->is_array() && up->size() == 3 &&
                         std::all_of(up->begin(), up->end(), [](const json& v) { return v.is_number() && std::isfinite(v.get<double>()); });
      if (!three)
        problem("up_orientation", "expected a list of three numbers (the BSDF's up vector), got " + kind(*up));
      else if (Vec3 u{(*up)[0].get<double>(), (*up)[1].get<double>(), (*up)[2].get<double>()}; length(u) == 0)
        problem("up_orientation", "the BSDF's up vector is zero");
      else
        mod.bsdf_up = u;
    }
    double thickness = 0;
    if (get_number(m, path, id, "thickness", thickness, false) && thickness != 0)
      problem("thickness",
              "a thickness (" + format_number(thickness) +
                  " model units) is ignored: the BSDF is applied at the aperture (RADIANCE uses it to hide proxied "
                  "geometry behind the surface)",
              false);
    std::string function_file = ".";
    if (get_string(m, path, id, "function_file", function_file, false) && function_file != ".")
      problem("function_file", "a function file ('" + function_file +
                                   "') is not supported: only the up vector of 'up_orientation' orients the BSDF; "
                                   "leave it at '.'");
    if (member(m, path, id, "transform", false))
      problem("transform", "a transform is not supported: turn the BSDF by its 'up_orientation' instead");
    for (const char* key : {"front_diffuse_reflectance", "back_diffuse_reflectance", "diffuse_transmittance"}) {
      const json* v = member(m, path, id, key, false);
      if (!v) continue;
      const bool three = v->is_array() && v->size() == 3 &&
                         std::all_of(v->begin(), v->end(), [](const json& x) { return x.is_number(); });
      if (!three)
        problem(key, "expected a list of three numbers, got " + kind(*v));
      else if (std::any_of(v->begin(), v->end(), [](const json& x) { return x.get<double>() != 0; }))
        problem(key, std::string("an extra diffuse component is not supported (RADIANCE adds it to the BSDF's ") +
                         "matrices); add it to the matrices of the XML instead, or set it to zero");
    }
  }

  void read_radiance_properties(const json& root) {
    const json* props = find(root, "properties");
    const json* rad = props ? find(*props, "radiance") : nullptr;
    if (!rad || rad->is_null()) return;
    const std::string rpath = "properties.radiance";
    if (!rad->is_object()) {
      error(rpath, m_out.identifier, "expected an object, got " + kind(*rad));
      return;
    }
    if (const json* mods = member(*rad, rpath, "", "modifiers", false)) {
      const std::string mpath = json_member(rpath, "modifiers");
      if (!mods->is_array()) {
        error(mpath, "", "expected a list of modifiers, got " + kind(*mods));
      } else {
        for (std::size_t i = 0; i < mods->size(); ++i)
          if (auto m = parse_modifier((*mods)[i], json_element(mpath, i))) add_modifier(std::move(*m));
      }
    }
    if (const json* sets = member(*rad, rpath, "", "modifier_sets", false)) {
      const std::string spath = json_member(rpath, "modifier_sets");
      if (!sets->is_array()) {
        error(spath, "", "expected a list of modifier sets, got " + kind(*sets));
      } else {
        for (std::size_t i = 0; i < sets->size(); ++i)
          if (auto set = read_modifier_set((*sets)[i], json_element(spath, i))) add_modifier_set(std::move(*set));
      }
    }
    // global_modifier_set: the identifier of one of modifier_sets, or (as honeybee-radiance
    // writes it) a GlobalModifierSet object with its own list of modifiers.
    const std::string gpath = json_member(rpath, "global_modifier_set");
    if (const json* g = member(*rad, rpath, "", "global_modifier_set", false)) {
      if (g->is_string()) {
        const auto it = m_sets.find(g->get<std::string>());
        if (it == m_sets.end())
          error(gpath, "", "unknown modifier set '" + g->get<std::string>() + "' (not in properties.radiance.modifier_sets)");
        else
          m_global = &it->second;
      } else if (g->is_object()) {
        if (const json* mods = member(*g, gpath, "", "modifiers", false); mods && mods->is_array())
          for (std::size_t i = 0; i < mods->size(); ++i)
            if (auto m = parse_modifier((*mods)[i], json_element(json_member(gpath, "modifiers"), i))) add_modifier(std::move(*m));
        if (auto set = read_modifier_set(*g, gpath, /*global=*/true)) m_global_set = std::move(*set);
        m_global = &*m_global_set;
      } else {
        error(gpath, "", "expected a modifier set identifier or a GlobalModifierSet object, got " + kind(*g));
      }
    }
  }

  void add_modifier(RadianceModifier m) {
    if (const auto it = m_modifiers.find(m.identifier); it != m_modifiers.end()) {
      // Modifier sets repeat the model's modifiers, and Honeybee's own files list some twice:
      // a second definition must say the same; the first stays.
      if (it->second.type != m.type || it->second.args != m.args || it->second.bsdf_xml != m.bsdf_xml ||
          it->second.bsdf_up != m.bsdf_up)
        error(m.path, m.identifier, "modifier '" + m.identifier + "' is defined twice, differently (first at " +
                                        it->second.location.to_string() + ")");
      return;
    }
    const std::string id = m.identifier;
    m_modifiers.emplace(id, std::move(m));
  }

  /// One modifier set; `global`: the model's GlobalModifierSet object (no identifier needed).
  std::optional<ModifierSet> read_modifier_set(const json& s, const std::string& path, bool global = false) {
    if (!s.is_object()) {
      error(path, "", "expected a modifier set object, got " + kind(s));
      return std::nullopt;
    }
    ModifierSet set;
    set.path = path;
    set.location = m_loc.locate(path);
    if (global) set.identifier = "global_modifier_set";
    else if (!get_string(s, path, "", "identifier", set.identifier, true)) return std::nullopt;
    for (const std::string& slot : detail::modifier_set_slots()) {
      const std::size_t dot_at = slot.find('.');
      const json* holder = &s;
      std::string hpath = path;
      std::string field = slot;
      if (dot_at != std::string::npos) {
        const std::string subset = slot.substr(0, dot_at);
        field = slot.substr(dot_at + 1);
        holder = find(s, subset.c_str());
        hpath = json_member(path, subset);
        if (!holder || holder->is_null()) continue;
        if (!holder->is_object()) {
          error(hpath, set.identifier, "expected an object, got " + kind(*holder));
          continue;
        }
      }
      const json* v = find(*holder, field.c_str());
      if (!v || v->is_null()) continue;
      const std::string vpath = json_member(hpath, field);
      if (v->is_string()) {
        set.slots[slot] = v->get<std::string>();
      } else if (v->is_object()) {  // a full ModifierSet gives the modifier itself
        if (auto m = parse_modifier(*v, vpath)) {
          set.slots[slot] = m->identifier;
          add_modifier(std::move(*m));
        }
      } else {
        error(vpath, set.identifier, "expected a modifier identifier or a modifier, got " + kind(*v));
      }
    }
    // Each named modifier must exist (checked here, where the set names it).
    for (const auto& [slot, modifier] : set.slots) {
      const bool generic = std::any_of(detail::honeybee_generic_modifiers().begin(), detail::honeybee_generic_modifiers().end(),
                                       [&](const RadianceModifier& m) { return m.identifier == modifier; });
      if (!m_modifiers.count(modifier) && !generic)
        error(json_member(path, slot), set.identifier, "unknown modifier '" + modifier + "' (not in properties.radiance.modifiers)");
    }
    return set;
  }

  void add_modifier_set(ModifierSet set) {
    if (m_sets.count(set.identifier)) {
      error(set.path, set.identifier, "modifier set '" + set.identifier + "' is defined twice");
      return;
    }
    const std::string id = set.identifier;
    m_sets.emplace(id, std::move(set));
  }

  void build_materials() {
    for (const std::string& id : m_used_order) {
      const SourceLocation& where = m_used.at(id);
      RadianceModifier mod;
      if (const auto it = m_modifiers.find(id); it != m_modifiers.end()) {
        mod = it->second;
        if (const auto p = m_problems.find(id); p != m_problems.end()) {
          error(mod.path, id, "modifier '" + id + "' " + p->second);
          continue;
        }
        bool refused = false;
        for (const detail::ModifierFieldProblem& p : mod.field_problems) {
          if (p.error) error(p.path, id, p.message);
          else warning(p.path, id, p.message);
          refused = refused || p.error;
        }
        if (refused) continue;
      } else {
        for (const RadianceModifier& g : detail::honeybee_generic_modifiers())
          if (g.identifier == id) mod = g;
      }
      MaterialSpec material;
      if (detail::honeybee_modifier_material(mod, where, m_diag, material)) m_out.materials.push_back(std::move(material));
    }
  }

  // ---- rooms ------------------------------------------------------------------------------
  void read_room(const json& room, const std::string& path) {
    if (!room.is_object()) {
      error(path, "", "expected a Room object, got " + kind(room));
      return;
    }
    std::string id;
    if (!get_string(room, path, "", "identifier", id, true)) return;
    if (std::find(m_out.rooms.begin(), m_out.rooms.end(), id) != m_out.rooms.end())
      error(json_member(path, "identifier"), id, "room identifier '" + id + "' is used twice");
    m_out.rooms.push_back(id);
    const ModifierSet* set = m_global;
    if (const json* props = find(room, "properties"); props && props->is_object())
      if (const json* rad = find(*props, "radiance"); rad && rad->is_object()) {
        const std::string rpath = json_member(json_member(path, "properties"), "radiance");
        std::string name;
        if (get_string(*rad, rpath, id, "modifier_set", name, false)) {
          const auto it = m_sets.find(name);
          if (it == m_sets.end())
            error(json_member(rpath, "modifier_set"), id, "unknown modifier set '" + name + "' (not in properties.radiance.modifier_sets)");
          else
            set = &it->second;
        }
      }
    const json* faces = member(room, path, id, "faces", true);
    if (faces && !faces->is_array()) error(json_member(path, "faces"), id, "expected a list of faces, got " + kind(*faces));
    if (faces && faces->is_array())
      for (std::size_t j = 0; j < faces->size(); ++j) read_face((*faces)[j], json_element(json_member(path, "faces"), j), set, id);
    read_shades(room, path, set);
  }

  void read_shades(const json& owner, const std::string& path, const ModifierSet* set) {
    for (const char* key : {"indoor_shades", "outdoor_shades"}) {
      const json* list = find(owner, key);
      if (!list || list->is_null()) continue;
      const std::string lpath = json_member(path, key);
      if (!list->is_array()) {
        error(lpath, "", "expected a list of shades, got " + kind(*list));
        continue;
      }
      for (std::size_t i = 0; i < list->size(); ++i)
        read_shade((*list)[i], json_element(lpath, i), set, std::string(key) == "indoor_shades");
    }
  }

  /// A shade; `context`: a detached orphaned shade (the set's context modifier).
  void read_shade(const json& shade, const std::string& path, const ModifierSet* set, bool indoor, bool context = false) {
    if (!shade.is_object()) {
      error(path, "", "expected a Shade object, got " + kind(shade));
      return;
    }
    std::string id;
    if (!get_string(shade, path, "", "identifier", id, true)) return;
    Polygon3 poly;
    if (!face3d(shade, path, id, poly)) return;
    const std::string material =
        object_modifier(shade, path, id, set,
                        context ? "context_modifier" : indoor ? "shade_set.interior_modifier" : "shade_set.exterior_modifier");
    emit(id, path, poly.boundary, poly.holes, material, indoor ? HoneybeeRole::Opaque : HoneybeeRole::OutdoorShade);
    warn_dynamic_states(shade, path, id, material);
  }

  /// The boundary condition's type ("Outdoors", ...) and, for Surface, its first object.
  bool boundary_condition(const json& obj, const std::string& path, const std::string& id, std::string& type,
                          std::string& adjacent) {
    const json* bc = member(obj, path, id, "boundary_condition", true);
    if (!bc) return false;
    const std::string bpath = json_member(path, "boundary_condition");
    if (!bc->is_object()) {
      error(bpath, id, "expected a boundary condition object, got " + kind(*bc));
      return false;
    }
    if (!get_string(*bc, bpath, id, "type", type, true)) return false;
    if (type == "Surface") {
      const json* objs = member(*bc, bpath, id, "boundary_condition_objects", true);
      if (!objs) return false;
      if (!objs->is_array() || objs->empty() || !(*objs)[0].is_string()) {
        error(json_member(bpath, "boundary_condition_objects"), id, "expected a list of identifiers, the adjacent object's first");
        return false;
      }
      adjacent = (*objs)[0].get<std::string>();
    }
    return true;
  }

  /// Faces, apertures and doors without a parent: the global (or generic) set's modifiers;
  /// their openings are ports whose room side the scene decides (no room says it).
  void read_orphans(const json& root) {
    for (const char* key : {"orphaned_faces", "orphaned_apertures", "orphaned_doors"}) {
      const json* list = find(root, key);
      if (!list || list->is_null()) continue;
      if (!list->is_array()) {
        error(key, m_out.identifier, "expected a list, got " + kind(*list));
        continue;
      }
      for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string path = json_element(key, i);
        if (std::string(key) == "orphaned_faces") {
          read_face((*list)[i], path, m_global, "", /*orphaned=*/true);
        } else {
          std::vector<Vec3> outline;
          read_opening((*list)[i], path, std::string(key) == "orphaned_doors", nullptr, "", "Wall", nullptr, m_global,
                       PortFacing::Auto, outline);
        }
      }
    }
  }

  void read_face(const json& face, const std::string& path, const ModifierSet* set, const std::string& room,
                 bool orphaned = false) {
    const std::string owner = orphaned ? std::string("orphaned") : "of room '" + room + "'";
    if (!face.is_object()) {
      error(path, "", "expected a Face object, got " + kind(face));
      return;
    }
    std::string id, face_type, bc, adjacent;
    if (!get_string(face, path, "", "identifier", id, true)) return;
    m_face_ids.insert(id);
    if (!get_string(face, path, id, "face_type", face_type, true)) return;
    if (!boundary_condition(face, path, id, bc, adjacent)) return;
    static const std::map<std::string, std::string> subsets = {
        {"Wall", "wall_set"}, {"Floor", "floor_set"}, {"RoofCeiling", "roof_ceiling_set"}};
    if (face_type == "AirBoundary") {
      // Honeybee's air_boundary modifier is a glass of transmissivity 1; an air boundary is
      // an opening between two parts of one space: no surface at all.
      m_out.notes.push_back("air boundary '" + id + "' " + owner + " is open (no surface)");
      return;
    }
    if (!subsets.count(face_type)) {
      error(json_member(path, "face_type"), id, "unknown face_type '" + face_type + "' (Wall, Floor, RoofCeiling or AirBoundary)");
      return;
    }
    if (bc != "Outdoors" && bc != "Ground" && bc != "Adiabatic" && bc != "Surface" && bc != "OtherSideTemperature") {
      error(json_member(json_member(path, "boundary_condition"), "type"), id,
            "unknown boundary condition '" + bc + "' (Outdoors, Ground, Adiabatic, Surface or OtherSideTemperature)");
      return;
    }
    Polygon3 poly;
    if (!face3d(face, path, id, poly)) return;
    // The second face of a shared wall is left out: the first stands for both.
    bool second_of_pair = false;
    if (bc == "Surface") {
      m_shared.push_back({id, adjacent, path});
      second_of_pair = m_emitted_shared.count(adjacent) > 0;
      if (second_of_pair)
        m_out.notes.push_back("face '" + id + "' " + owner + " is the far side of face '" + adjacent +
                              "' (one surface for a shared wall)");
      else
        m_emitted_shared.insert(id);
    }
    std::vector<std::vector<Vec3>> holes = poly.holes;
    if (!second_of_pair) {
      for (const char* key : {"apertures", "doors"}) {
        const json* list = find(face, key);
        if (!list || list->is_null()) continue;
        const std::string lpath = json_member(path, key);
        if (!list->is_array()) {
          error(lpath, id, "expected a list, got " + kind(*list));
          continue;
        }
        for (std::size_t k = 0; k < list->size(); ++k) {
          std::vector<Vec3> opening;
          if (read_opening((*list)[k], json_element(lpath, k), std::string(key) == "doors", &poly, id, face_type, &bc, set,
                           orphaned ? PortFacing::Auto : PortFacing::Out, opening))
            holes.push_back(std::move(opening));
        }
      }
    }
    const std::string slot = subsets.at(face_type) + (bc == "Outdoors" ? ".exterior_modifier" : ".interior_modifier");
    read_shades(face, path, set);
    if (second_of_pair) return;
    const std::string material = object_modifier(face, path, id, set, slot);
    // A face of glass (a curtain wall or a glazed roof drawn as a face, not as an aperture):
    // light comes in through it, so it is a port like an aperture, not a wall the sky
    // cannot pass.
    emit(id, path, poly.boundary, holes, material, wall_role(material, bc), orphaned ? PortFacing::Auto : PortFacing::Out);
  }

  /// An aperture or door: its own surface; `outline` is the hole it cuts in its face. `face`
  /// and `face_bc` are null for an orphaned one (then nothing to lie inside or agree with).
  bool read_opening(const json& obj, const std::string& path, bool door, const Polygon3* face, const std::string& face_id,
                    const std::string& face_type, const std::string* face_bc, const ModifierSet* set, PortFacing facing,
                    std::vector<Vec3>& outline) {
    const char* what = door ? "Door" : "Aperture";
    if (!obj.is_object()) {
      error(path, "", std::string("expected a ") + what + " object, got " + kind(obj));
      return false;
    }
    std::string id, bc, adjacent;
    if (!get_string(obj, path, "", "identifier", id, true)) return false;
    if (!boundary_condition(obj, path, id, bc, adjacent)) return false;
    if (bc != "Outdoors" && bc != "Surface") {
      error(json_member(json_member(path, "boundary_condition"), "type"), id,
            std::string("a ") + what + " takes boundary condition Outdoors or Surface, got '" + bc + "'");
      return false;
    }
    if (face_bc && bc != *face_bc) {
      error(json_member(json_member(path, "boundary_condition"), "type"), id,
            std::string("boundary condition '") + bc + "' differs from its face '" + face_id + "' ('" + *face_bc +
                "'): an opening to the outdoors needs an Outdoors face, one to another room a Surface face");
      return false;
    }
    Polygon3 poly;
    if (!face3d(obj, path, id, poly)) return false;
    if (!poly.holes.empty()) {
      error(json_member(json_member(path, "geometry"), "holes"), id,
            std::string(door ? "a " : "an ") + what + " with holes is not supported");
      return false;
    }
    if (face && !inside_face(poly.boundary, *face, json_member(json_member(path, "geometry"), "boundary"), id, face_id))
      return false;
    bool glass = !door, operable = false;
    if (door) get_bool(obj, path, id, "is_glass", glass);
    else get_bool(obj, path, id, "is_operable", operable);
    const bool outdoors = bc == "Outdoors";
    std::string slot;
    if (!door)
      slot = !outdoors ? "aperture_set.interior_modifier"
             : operable ? "aperture_set.operable_modifier"
             : face_type == "Wall" ? "aperture_set.window_modifier" : "aperture_set.skylight_modifier";
    else if (glass)
      slot = outdoors ? "door_set.exterior_glass_modifier" : "door_set.interior_glass_modifier";
    else
      slot = !outdoors ? "door_set.interior_modifier" : face_type == "Wall" ? "door_set.exterior_modifier" : "door_set.overhead_modifier";
    const std::string material = object_modifier(obj, path, id, set, slot);
    const HoneybeeRole role = !glass                    ? wall_role(material, bc)  // an opaque door of glass
                              : outdoors ? HoneybeeRole::Port
                                         : HoneybeeRole::InteriorGlass;
    emit(id, path, poly.boundary, {}, material, role, facing);
    warn_dynamic_states(obj, path, id, material);
    read_shades(obj, path, set);
    outline = poly.boundary;
    return true;
  }

  /// Each Surface face names an existing face.
  void check_shared_faces() {
    for (const SharedFace& s : m_shared)
      if (!m_face_ids.count(s.adjacent))
        error(json_member(json_member(s.path, "boundary_condition"), "boundary_condition_objects"), s.id,
              "adjacent face '" + s.adjacent + "' is not a face of any room");
  }

  // ---- sensor grids -----------------------------------------------------------------------
  void read_grids(const json& root) {
    const json* props = find(root, "properties");
    const json* rad = props ? find(*props, "radiance") : nullptr;
    const json* grids = rad ? find(*rad, "sensor_grids") : nullptr;
    if (!grids || grids->is_null()) return;
    const std::string gpath = "properties.radiance.sensor_grids";
    if (!grids->is_array()) {
      error(gpath, "", "expected a list of sensor grids, got " + kind(*grids));
      return;
    }
    for (std::size_t i = 0; i < grids->size(); ++i) {
      const json& g = (*grids)[i];
      const std::string path = json_element(gpath, i);
      if (!g.is_object()) {
        error(path, "", "expected a SensorGrid object, got " + kind(g));
        continue;
      }
      HoneybeeGrid grid;
      grid.location = m_loc.locate(path);
      if (!get_string(g, path, "", "identifier", grid.identifier, true)) continue;
      const std::string& id = grid.identifier;
      for (const HoneybeeGrid& other : m_out.grids)
        if (other.identifier == id) error(json_member(path, "identifier"), id, "sensor grid identifier '" + id + "' is used twice");
      const json* sensors = member(g, path, id, "sensors", true);
      if (!sensors) continue;
      const std::string spath = json_member(path, "sensors");
      if (!sensors->is_array() || sensors->empty()) {
        error(spath, id, "expected a non-empty list of sensors");
        continue;
      }
      bool ok = true;
      for (std::size_t k = 0; k < sensors->size() && ok; ++k) {
        const json& s = (*sensors)[k];
        const std::string sp = json_element(spath, k);
        SensorPoint p;
        const json* pos = s.is_object() ? find(s, "pos") : nullptr;
        const json* dir = s.is_object() ? find(s, "dir") : nullptr;
        if (!pos || !dir) {
          error(sp, id, "a sensor needs 'pos' and 'dir'");
          ok = false;
          break;
        }
        ok = point(*pos, json_member(sp, "pos"), id, p.position, m_out.metres_per_unit) &&
             point(*dir, json_member(sp, "dir"), id, p.normal, 1.0);
        if (ok && length(p.normal) < 1e-12) {
          error(json_member(sp, "dir"), id, "the sensor's direction is zero");
          ok = false;
        }
        if (ok) {
          p.normal = normalize(p.normal);
          grid.points.push_back(p);
        }
      }
      if (!ok) continue;
      if (const json* mesh = find(g, "mesh"); mesh && !mesh->is_null()) {
        grid.mesh_face_areas_m2 = mesh_face_areas_m2(*mesh);
        grid.mesh_location = m_loc.locate(json_member(path, "mesh"));
        if (grid.mesh_face_areas_m2.empty()) {
          grid.mesh_problem = "cannot be read as a Mesh3D ('vertices' [[x, y, z], ...] and 'faces' of 3 or more "
                              "vertex indices, of a positive total area)";
        } else if (grid.mesh_face_areas_m2.size() != grid.points.size()) {
          grid.mesh_problem = "has " + std::to_string(grid.mesh_face_areas_m2.size()) + " faces for " +
                              std::to_string(grid.points.size()) + " sensors";
          grid.mesh_face_areas_m2.clear();
        }
      }
      m_out.grids.push_back(std::move(grid));
    }
  }

  /// The face areas of a Mesh3D (`vertices` [[x, y, z], ...], `faces` [[i, j, k(, l)], ...]),
  /// in m^2; empty for anything else, or a mesh of no area (the mesh only weighs the sensors'
  /// areas, so a mesh that cannot be read is warned about and left out, not an error).
  std::vector<double> mesh_face_areas_m2(const json& mesh) const {
    const json* vertices = mesh.is_object() ? find(mesh, "vertices") : nullptr;
    const json* faces = mesh.is_object() ? find(mesh, "faces") : nullptr;
    if (!vertices || !faces || !vertices->is_array() || !faces->is_array()) return {};
    std::vector<Vec3> v;
    for (const json& p : *vertices) {
      if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number()) return {};
      v.push_back(Vec3{p[0].get<double>(), p[1].get<double>(), p[2].get<double>()} * m_out.metres_per_unit);
    }
    std::vector<double> areas;
    for (const json& f : *faces) {
      if (!f.is_array() || f.size() < 3) return {};
      std::vector<Vec3> polygon;
      for (const json& i : f) {
        if (!i.is_number_integer() || i.get<long long>() < 0 || i.get<long long>() >= static_cast<long long>(v.size()))
          return {};
        polygon.push_back(v[static_cast<std::size_t>(i.get<long long>())]);
      }
      areas.push_back(polygon_area_m2(polygon));
    }
    double total_m2 = 0;
    for (double a : areas) total_m2 += a;
    if (!std::isfinite(total_m2) || !(total_m2 > 0)) return {};
    return areas;
  }

  struct SharedFace {
    std::string id, adjacent, path;
  };

  const JsonLocator& m_loc;
  Diagnostics& m_diag;
  HoneybeeModel& m_out;
  std::map<std::string, RadianceModifier> m_modifiers;
  std::map<std::string, std::string> m_problems;  ///< modifier -> why it cannot be mapped
  std::map<std::string, ModifierSet> m_sets;
  const ModifierSet* m_global = nullptr;
  std::optional<ModifierSet> m_global_set;  ///< a GlobalModifierSet object, if the model gives one
  std::map<std::string, SourceLocation> m_used;  ///< modifier -> where first used
  std::vector<std::string> m_used_order;
  std::set<std::string> m_face_ids, m_emitted_shared;
  std::vector<SharedFace> m_shared;
};

}  // namespace

const char* honeybee_bsdf_refusal(HoneybeeRole role, PortFacing facing) {
  if (role == HoneybeeRole::Port)
    return facing == PortFacing::Auto ? "an orphaned object has no room to say which side is outdoors, where the BSDF's "
                                        "front (WINDOW's exterior side) must face; put it in a room"
                                      : nullptr;
  if (role == HoneybeeRole::InteriorGlass)
    return "between two rooms neither side is outdoors, so which side is the BSDF's front (WINDOW's exterior side) "
           "cannot be told; give the interior opening a glass or trans modifier";
  return "a BSDF is read on the apertures, glass doors and faces of a room facing Outdoors only, whose outside is its "
         "front (WINDOW's exterior side); give this object another modifier";
}

void turn_for_bsdf(std::vector<Vec3>& vertices, PortFacing& facing) {
  if (facing != PortFacing::Out) return;
  std::reverse(vertices.begin(), vertices.end());
  facing = PortFacing::In;
}

HoneybeeModel read_honeybee_model_from_string(const std::string& text, const std::string& file) {
  Diagnostics diag;
  HoneybeeModel model;
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    // e.byte: 1-based position of the byte where parsing stopped.
    const SourceLocation where = detail::JsonLocator::line_and_column(
        text, file, std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size()));
    std::string message = e.what();
    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." ->
    // the part after the position, which the location already gives.
    if (const std::size_t colon = message.find(": "); colon != std::string::npos) message = message.substr(colon + 2);
    diag.error(where, "not valid JSON: " + message, read_source_line(file, where.line));
    diag.throw_if_errors();
  }
  // Honeybee models nest about a dozen levels; the locator's scan recurses once per level.
  if (const auto [depth, offset] = detail::json_nesting(text); depth > MaxJsonDepth) {
    const SourceLocation where = detail::JsonLocator::line_and_column(text, file, offset);
    diag.error(where, "the JSON nests deeper than " + std::to_string(MaxJsonDepth) + " levels; a Honeybee model needs about 12",
               read_source_line(file, where.line));
    diag.throw_if_errors();
  }
  const detail::JsonLocator locator(text, file);
  Reader(locator, diag, model).read(root);
  diag.throw_if_errors();
  for (const Diagnostic& d : diag.entries())
    if (d.severity == Severity::Warning) model.warnings.push_back(d);
  return model;
}

HoneybeeModel read_honeybee_model(const std::string& path, const std::string& shown_path) {
  std::ifstream in = open_input_file(path, "Honeybee model");
  std::ostringstream text;
  text << in.rdbuf();
  return read_honeybee_model_from_string(text.str(), shown_path);
}

}  // namespace dayphoton::project
