// The building section: rooms and windows, materials, sensor grids; see report_sections.h.
// Everything is the base case's as the run recorded it in the results model (a variant's
// differences are in the variants section).
#include <algorithm>
#include <sstream>

#include "dayphoton/report/report_format.h"
#include "report_sections.h"

namespace dayphoton::report {

std::string building_section(const study::ResultsModel& m) {
  std::ostringstream s;
  s << "<section id=\"building\"><h2>Building, materials and sensors</h2>";
  if (m.cases.empty()) return s.str() + "<p class=\"na\">no case in the results.</p></section>";
  const study::CaseResult& base = m.cases.front();

  s << "<h3 id=\"rooms\">Rooms and windows</h3>";
  if (base.rooms.empty()) {
    s << "<p class=\"na\">The geometry is not made of generated rooms (polygons, meshes or an imported scene), so no "
         "room dimensions are recorded. Total area of the openings (windows and other photon ports): "
      << format_value(base.opening_area_m2, Precision::Area) << " m&#178;.</p>";
  } else {
    s << "<table class=\"rooms-table\"><tr><th>room</th><th>width x depth x height (m)</th><th>floor area (m&#178;)</th>"
         "<th>window area (m&#178;)</th><th>roof-light area (m&#178;)</th><th>window-to-wall ratio</th>"
         "<th>glazing-to-floor ratio</th></tr>";
    for (const study::RoomSummary& r : base.rooms)
      s << "<tr><td>" << esc(r.name) << "</td><td class=\"n\">" << format_value(r.width_m, Precision::Length) << " x "
        << format_value(r.depth_m, Precision::Length) << " x " << format_value(r.height_m, Precision::Length)
        << "</td><td class=\"n\">" << format_value(r.floor_area_m2, Precision::Area) << "</td><td class=\"n\">"
        << format_value(r.window_area_m2, Precision::Area) << "</td><td class=\"n\">"
        << format_value(r.roof_light_area_m2, Precision::Area) << "</td><td class=\"n\">"
        << (r.glazed_wall_area_m2 > 0 ? format_value(r.window_to_wall_ratio(), Precision::Ratio) : "-")
        << "</td><td class=\"n\">" << format_value(r.window_to_floor_ratio(), Precision::Ratio) << "</td></tr>";
    s << "</table><p class=\"note\">Window-to-wall ratio: window area over the gross area (wall length x room height) "
         "of the walls that hold windows. Glazing-to-floor ratio: windows and roof lights over the floor area. Areas "
         "are of the openings; the glazed part is the opening times the frame factor.</p>";
    s << "<table class=\"windows-table\"><tr><th>room</th><th>window</th><th>wall</th><th>width x height (m)</th>"
         "<th>sill (m)</th><th>area (m&#178;)</th><th>glazing</th><th>frame factor</th><th>maintenance factor</th></tr>";
    for (const study::RoomSummary& r : base.rooms)
      for (const study::WindowSummary& w : r.windows)
        s << "<tr><td>" << esc(r.name) << "</td><td>" << esc(w.name) << "</td><td>"
          << esc(w.wall == "roof" ? "roof light" : w.wall) << "</td><td class=\"n\">"
          << format_value(w.width_m, Precision::Length) << " x " << format_value(w.height_m, Precision::Length)
          << "</td><td class=\"n\">" << (w.wall == "roof" ? "-" : format_value(w.sill_m, Precision::Length))
          << "</td><td class=\"n\">" << format_value(w.area_m2, Precision::Area) << "</td><td>" << esc(w.material)
          << "</td><td class=\"n\">" << format_value(w.frame_factor, Precision::Fraction) << "</td><td class=\"n\">"
          << format_value(w.maintenance_factor, Precision::Fraction) << "</td></tr>";
    s << "</table><p class=\"note\">Wall names are the model's directions (south = the wall at the room's smallest "
         "y); roof lights: width along x, length along y.</p>";
  }

  s << "<h3 id=\"materials\">Materials</h3><table class=\"materials-table\"><tr><th>material</th><th>type</th>"
       "<th>reflectance</th><th>specular share</th><th>visible transmittance (normal incidence)</th>"
       "<th>area (m&#178;)</th></tr>";
  for (const study::MaterialSummary& mat : base.materials)
    s << "<tr><td>" << esc(mat.name) << "</td><td>" << esc(mat.type) << "</td><td class=\"n\">"
      << format_value(mat.reflectance, Precision::Fraction) << "</td><td class=\"n\">"
      << (mat.reflectance ? format_value(mat.specularity, Precision::Fraction) : "-") << "</td><td class=\"n\">"
      << format_value(mat.transmittance, Precision::Fraction) << "</td><td class=\"n\">"
      << format_value(mat.area_m2, Precision::Area) << "</td></tr>";
  s << "</table><p class=\"note\">Photometric values (RGB weighted by RADIANCE's luminance weights 0.265, 0.670, "
       "0.065). Transmittance of glazing at normal incidence including its frame and maintenance factors; \"-\": "
       "opaque, or not a reflectance of that type. Area: one side of the surfaces with that material.</p>";

  s << "<h3 id=\"grids\">Sensor grids</h3><table class=\"grids-table\"><tr><th>grid</th><th>orientation</th>"
       "<th>sensors</th><th>spacing (m)</th><th>lattice (columns x rows)</th><th>height of the sensors (m)</th>"
       "<th>sensors left out</th></tr>";
  for (const study::GridResult& g : base.grids) {
    double spacing = g.spacing_m > 0 ? g.spacing_m : g.lattice.regular ? g.lattice.spacing_m : 0;
    std::string height = "-";
    if (g.orientation == study::GridOrientation::Horizontal && !g.positions_m.empty()) {
      double lo = g.positions_m.front().z, hi = lo;
      for (const Vec3& p : g.positions_m) {
        lo = std::min(lo, p.z);
        hi = std::max(hi, p.z);
      }
      height = format_value(lo, Precision::Length) + (hi - lo > 1e-6 ? "&#8211;" + format_value(hi, Precision::Length) : "");
    }
    const std::size_t dropped =
        g.dropped_outside_rooms + g.dropped_inside_solid + g.dropped_on_cut_surface + g.dropped_enclosed;
    s << "<tr><td>" << esc(g.name) << "</td><td>" << study::orientation_name(g.orientation) << "</td><td class=\"n\">"
      << g.positions_m.size() << "</td><td class=\"n\">" << (spacing > 0 ? format_value(spacing, Precision::Length) : "-")
      << "</td><td class=\"n\">"
      << (g.lattice.regular ? std::to_string(g.lattice.columns) + " x " + std::to_string(g.lattice.rows) : "-")
      << "</td><td class=\"n\">" << height << "</td><td class=\"n\">" << dropped << "</td></tr>";
  }
  s << "</table><p class=\"note\">Heights are world z of the sensors (the model's floor at its own z). Sensors left "
       "out: outside every room, inside a solid or on a surface crossing the work plane, dropped at the project's request.</p></section>";
  return s.str();
}

}  // namespace dayphoton::report
