// generate_systems: the daylight systems of a project as surfaces (see system_generators.h
// for the split into generators, docs/daylight-systems.md for what each builds).
//
// Placement rule for window-mounted systems: an interior system must lie inside its room
// (behind the wall plane, within the wall's length, the room's height and depth); an
// exterior one must stay outside the wall plane. Both are checked on the generated
// vertices in the window frame, with 1e-6 m tolerance.
//
// Ports (seeds/000 section 4.1.3; digest: "ports may be closed invisible geometry
// enclosing an external system"): the window stays the photon port of interior systems
// and of exterior ones with `port: system` or `port: window`; port emission tests the path
// from the window toward the source, so exterior geometry shades it. With `port: system`
// (the default) the exterior parts are outdoor scatterers (Surface::outdoor_scatterer):
// photons land on them straight from the sources too, and what they reflect or transmit
// toward the window is traced (engine/port_emission.h). With `port: window` they only
// shade: light they reflect is lost (no external inter-reflection), an approximation
// named as such wherever it is reported. With `port: enclosure` the exterior parts of every such
// system of a window and the window itself are enclosed in a box of `opening` polygons
// (ports, normals into the box), EnclosureMargin_m larger than their bounding box in the
// window frame, open toward the wall; the window then stays glazing but is no longer a
// port, so that no ray's flux enters twice. The box's footprint on the wall must not cover
// another window of the wall (that window would be a second port behind the enclosure) or
// another enclosure.
#include "system_generators.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace dayphoton::project::detail {

namespace {

constexpr double PlacementTolerance_m = 1e-6;

/// Bounding box in the window frame (u, v, w).
struct LocalBox {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
  void add(const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
};

LocalBox local_box(const WindowFrame& f, const std::vector<Surface>& surfaces) {
  LocalBox b;
  for (const Surface& s : surfaces)
    for (const Vec3& p : s.vertices) b.add(f.local(p));
  return b;
}

std::string metres(double x) { return format_number(std::round(x * 1e4) / 1e4) + " m"; }

/// Interior: inside the room; exterior: outside the wall plane (header comment).
bool check_placement(const MountedBuild& b, const LocalBox& box) {
  const WindowFrame& f = b.frame;
  const double tol = PlacementTolerance_m;
  const std::string room = "room '" + f.room->name + "'";
  if (b.spec.mount.side == MountSide::Exterior) {
    if (box.lo.z < -tol) {
      b.error("", "(exterior) reaches " + metres(-box.lo.z) + " into " + room +
                      " behind the wall plane; move it out (offset) or mount it inside");
      return false;
    }
    return true;
  }
  bool ok = true;
  auto fail = [&](const std::string& message) {
    b.error("", message);
    ok = false;
  };
  if (box.hi.z > tol)
    fail("(interior) reaches " + metres(box.hi.z) + " out of " + room +
         " through the wall plane; give it more offset or mount it outside");
  if (box.lo.z < -f.room_depth_m - tol)
    fail("(interior) reaches " + metres(-box.lo.z) + " into " + room + ", which is only " +
         metres(f.room_depth_m) + " deep");
  if (box.lo.x < f.wall_u_min - tol || box.hi.x > f.wall_u_max + tol)
    fail("(interior) is wider than the wall of " + room + ": it spans " + metres(box.lo.x) +
         " to " + metres(box.hi.x) + " from the window's left edge, the wall " +
         metres(f.wall_u_min) + " to " + metres(f.wall_u_max));
  if (box.lo.y < -tol || box.hi.y > f.room_height_m + tol)
    fail("(interior) spans heights " + metres(box.lo.y) + " to " + metres(box.hi.y) +
         ", outside the floor-to-ceiling height of " + room + " (" + metres(f.room_height_m) + ")");
  return ok;
}

/// One window's port enclosure being collected.
struct Enclosure {
  WindowFrame frame;
  LocalBox box;                      ///< systems and window, before the margin
  const SystemSpec* first = nullptr; ///< for messages
};

int enclosure_material(std::vector<MaterialSpec>& scene_materials) {
  for (std::size_t i = 0; i < scene_materials.size(); ++i)
    if (scene_materials[i].name == EnclosureMaterialName &&
        scene_materials[i].type == MaterialType::Opening)
      return static_cast<int>(i);
  MaterialSpec m;
  m.name = EnclosureMaterialName;
  m.type = MaterialType::Opening;
  scene_materials.push_back(m);
  return static_cast<int>(scene_materials.size()) - 1;
}

/// The footprint [u0, u1] x [v0, v1] of `other`'s window in frame `f` (same wall).
std::pair<Vec3, Vec3> footprint_of(const WindowFrame& f, const WindowFrame& other) {
  const Vec3 a = f.local(other.at(0, other.sill_m, 0)), c = f.local(other.at(other.width_m, other.head_m, 0));
  return {Vec3{std::min(a.x, c.x), std::min(a.y, c.y), 0}, Vec3{std::max(a.x, c.x), std::max(a.y, c.y), 0}};
}

bool overlaps(const Vec3& lo1, const Vec3& hi1, const Vec3& lo2, const Vec3& hi2) {
  const double du = std::min(hi1.x, hi2.x) - std::max(lo1.x, lo2.x);
  const double dv = std::min(hi1.y, hi2.y) - std::max(lo1.y, lo2.y);
  return du > PlacementTolerance_m && dv > PlacementTolerance_m;
}

}  // namespace

std::string MountedBuild::what() const {
  return std::string(spec.type_name()) + " '" + spec.name + "'";
}

void MountedBuild::error(const std::string& key, const std::string& message) const {
  report(diag, key.empty() ? spec.location : spec.location_of(key), what() + " " + message);
}

int MountedBuild::material(const std::string& key, const std::string& name) const {
  return materials.resolve(name, spec.location_of(key), what());
}

bool MountedBuild::check_not_dielectric(const std::string& key, int index, const std::string& use) const {
  if (index < 0) return false;
  if (materials.spec(index).type != MaterialType::Dielectric) return true;
  error(key, "cannot use the dielectric '" + materials.spec(index).name + "' for " + use +
                 " (a dielectric is the surface of a closed solid; give the part a thickness "
                 "or use another material)");
  return false;
}

bool MountedBuild::check_dielectric(const std::string& key, int index) const {
  if (index < 0) return false;
  const MaterialSpec& m = materials.spec(index);
  if (m.type == MaterialType::Dielectric) return true;
  error(key, "needs a dielectric material, but '" + m.name + "' is " + material_type_as_written(m));
  return false;
}

bool MountedBuild::covered_heights(const std::optional<double>& bottom,
                                   const std::optional<double>& top, double& v0,
                                   double& v1) const {
  v0 = bottom ? *bottom : frame.sill_m;
  v1 = top ? *top : frame.head_m;
  if (v1 > v0) return true;
  error(top ? "top" : "bottom", "covers no height: 'bottom' (" + metres(v0) +
                                    ") must be below 'top' (" + metres(v1) + ")");
  return false;
}

void generate_systems(const Project& project, MaterialLookup& materials,
                      std::vector<MaterialSpec>& scene_materials, Diagnostics& diag,
                      SystemOutput& out) {
  struct Placed {
    const RoomSpec* room;
    const WindowSpec* window;
  };
  std::map<std::string, Placed> windows;
  std::map<std::string, const RoomSpec*> rooms;
  for (const RoomSpec& room : project.geometry.rooms) {
    rooms.emplace(room.name, &room);
    for (const WindowSpec& w : room.windows) windows.emplace(w.name, Placed{&room, &w});
  }
  std::map<std::string, Enclosure> enclosures;  // by window name
  struct Pipe {
    const SystemSpec* spec;
    const LightPipeSpec* p;
  };
  std::map<std::string, std::vector<Pipe>> pipes;  // by room name

  for (const SystemSpec& sys : project.geometry.systems) {
    if (!sys.enabled) continue;
    if (const auto* pipe = std::get_if<LightPipeSpec>(&sys.params)) {
      const auto room = rooms.find(pipe->room);
      if (room == rooms.end()) {
        report(diag, sys.location_of("room"), "light_pipe '" + sys.name + "': unknown room '" + pipe->room + "'");
        continue;
      }
      bool apart = true;
      for (const Pipe& other : pipes[pipe->room]) {
        const double d = std::hypot(pipe->x_m - other.p->x_m, pipe->y_m - other.p->y_m);
        if (d < 0.5 * (pipe->diameter_m + other.p->diameter_m) + PlacementTolerance_m) {
          report(diag, sys.location, "light_pipe '" + sys.name + "' overlaps light_pipe '" +
                                         other.spec->name + "' (axes " + metres(d) + " apart)");
          apart = false;
        }
      }
      if (!apart) continue;
      if (generate_light_pipe(sys, *pipe, *room->second, materials, diag, out.surfaces,
                              out.rooms[pipe->room]))
        pipes[pipe->room].push_back({&sys, pipe});
      continue;
    }
    const auto placed = windows.find(sys.mount.window);
    if (placed == windows.end()) {
      report(diag, sys.location_of("window"), std::string(sys.type_name()) + " '" + sys.name +
                                                  "': unknown window '" + sys.mount.window + "'");
      continue;
    }
    const WindowFrame frame = window_frame(*placed->second.room, *placed->second.window);
    std::vector<Surface> parts;
    const MountedBuild b{sys, frame, materials, diag, parts};
    const bool built = std::visit(
        [&](const auto& p) {
          using T = std::decay_t<decltype(p)>;
          if constexpr (std::is_same_v<T, LightShelfSpec>) return generate_light_shelf(b, p);
          else if constexpr (std::is_same_v<T, OverhangSpec>) return generate_overhang(b, p);
          else if constexpr (std::is_same_v<T, FinsSpec>) return generate_fins(b, p);
          else if constexpr (std::is_same_v<T, BlindsSpec>) return generate_blinds(b, p);
          else if constexpr (std::is_same_v<T, PrismaticPanelSpec>) return generate_prismatic_panel(b, p);
          else if constexpr (std::is_same_v<T, LamellaPanelSpec>) return generate_lamella_panel(b, p);
          else if constexpr (std::is_same_v<T, CpcSpec>) return generate_cpc(b, p);
          else return false;  // light pipes are handled above
        },
        sys.params);
    if (!built || parts.empty()) continue;
    const LocalBox box = local_box(frame, parts);
    if (!check_placement(b, box)) continue;
    if (sys.mount.side == MountSide::Exterior && sys.mount.port == PortMode::Window) {
      // With the window as port every exterior surface is opaque to the sky (port emission
      // and shadow rays stop at any surface outside the port): right for shading devices,
      // wrong for a system that transmits light.
      bool transmits = false;
      for (const Surface& s : parts) {
        const MaterialType t = materials.spec(s.material).type;
        transmits = transmits || t == MaterialType::Dielectric || t == MaterialType::Glass ||
                    t == MaterialType::Glazing || t == MaterialType::Translucent ||
                    t == MaterialType::Opening;
      }
      if (transmits) {
        b.error("port", "(exterior, port: window) transmits light, but outside its window's "
                        "port every surface only shades: the window would be blocked; use "
                        "port: system");
        continue;
      }
    }
    if (sys.mount.side == MountSide::Exterior && sys.mount.port == PortMode::System)
      for (Surface& part : parts) part.outdoor_scatterer = true;
    if (sys.mount.side == MountSide::Exterior && sys.mount.port == PortMode::Enclosure) {
      auto [it, fresh] = enclosures.emplace(sys.mount.window, Enclosure{frame, {}, &sys});
      if (fresh) {
        it->second.box.add({0, frame.sill_m, 0});
        it->second.box.add({frame.width_m, frame.head_m, 0});
      }
      it->second.box.add(box.lo);
      it->second.box.add(box.hi);
    }
    out.surfaces.insert(out.surfaces.end(), parts.begin(), parts.end());
  }

  // Port enclosures (header comment).
  std::vector<std::pair<const Enclosure*, std::pair<Vec3, Vec3>>> built;
  for (const auto& entry : enclosures) {
    // Named references, not a structured binding: the lambda `face` below captures them, and
    // C++17 does not allow capturing structured bindings (clang rejects it).
    const std::string& window_name = entry.first;
    const Enclosure& e = entry.second;
    const WindowFrame& f = e.frame;
    const double m = EnclosureMargin_m;
    const double u0 = e.box.lo.x - m, u1 = e.box.hi.x + m, v0 = e.box.lo.y - m,
                 v1 = e.box.hi.y + m, w1 = e.box.hi.z + m;
    const Vec3 lo{u0, v0, 0}, hi{u1, v1, 0};
    const std::string what = std::string(e.first->type_name()) + " '" + e.first->name + "'";
    bool ok = true;
    for (const WindowSpec& other : f.room->windows) {
      if (other.name == window_name || other.wall != f.window->wall) continue;
      const auto fp = footprint_of(f, window_frame(*f.room, other));
      if (overlaps(lo, hi, fp.first, fp.second)) {
        report(diag, e.first->location,
               what + ": the port enclosure of window '" + window_name + "' (" + metres(u0) +
                   " to " + metres(u1) + " along the wall, heights " + metres(v0) + " to " +
                   metres(v1) + ") covers window '" + other.name +
                   "', which would be a second port behind it; use port: system or move the system");
        ok = false;
      }
    }
    for (const auto& [other, fp] : built) {
      if (other->frame.room != f.room || other->frame.window->wall != f.window->wall) continue;
      const Vec3 a = f.local(other->frame.at(fp.first.x, fp.first.y, 0));
      const Vec3 c = f.local(other->frame.at(fp.second.x, fp.second.y, 0));
      if (overlaps(lo, hi, {std::min(a.x, c.x), std::min(a.y, c.y), 0},
                   {std::max(a.x, c.x), std::max(a.y, c.y), 0})) {
        report(diag, e.first->location,
               what + ": the port enclosure of window '" + window_name +
                   "' overlaps the one of window '" + other->frame.window->name +
                   "' (ports must not overlap); use port: system for one of them");
        ok = false;
      }
    }
    if (!ok) continue;
    built.push_back({&e, {lo, hi}});
    const int mat = enclosure_material(scene_materials);
    // Plain references for the lambda: C++17 does not let a lambda capture structured
    // bindings (clang rejects it; C++20 allows it, P1091R3).
    const std::string& enclosed_window = window_name;
    const SourceLocation& system_location = e.first->location;
    auto face = [&](const char* name, std::vector<Vec3> v, const Vec3& inward) {
      Surface s;
      s.name = enclosed_window + ".enclosure." + name;
      s.material = mat;
      s.vertices = facing(std::move(v), inward);
      s.port = true;
      s.opening_normal = f.e_w;  // every face stands for the window (its plane's normal)
      s.location = system_location;
      out.surfaces.push_back(std::move(s));
    };
    face("front", {f.at(u0, v0, w1), f.at(u1, v0, w1), f.at(u1, v1, w1), f.at(u0, v1, w1)}, f.e_w * -1.0);
    face("top", {f.at(u0, v1, 0), f.at(u1, v1, 0), f.at(u1, v1, w1), f.at(u0, v1, w1)}, f.e_v * -1.0);
    face("bottom", {f.at(u0, v0, 0), f.at(u1, v0, 0), f.at(u1, v0, w1), f.at(u0, v0, w1)}, f.e_v);
    face("left", {f.at(u0, v0, 0), f.at(u0, v1, 0), f.at(u0, v1, w1), f.at(u0, v0, w1)}, f.e_u);
    face("right", {f.at(u1, v0, 0), f.at(u1, v1, 0), f.at(u1, v1, w1), f.at(u1, v0, w1)}, f.e_u * -1.0);
    out.rooms[f.room->name].windows_without_port.insert(window_name);
  }
}

}  // namespace dayphoton::project::detail
