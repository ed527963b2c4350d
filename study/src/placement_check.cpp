// Placement check: see placement_check.h.
#include "dayphoton/study/placement_check.h"

#include <cmath>
#include <sstream>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/port_facing.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_placement.h"
#include "dayphoton/project/north_rotation.h"

namespace dayphoton::study {
namespace {

void report(Diagnostics& diag, const SourceLocation& where, const std::string& message) {
  std::string line;
  if (where.known() && !diag.at_cap()) line = read_source_line(where.file, where.line);
  diag.error(where, message, line);
}

std::string percent(double fraction) {
  std::ostringstream s;
  s << std::lround(100.0 * fraction) << " %";
  return s.str();
}

std::string point_text(const Vec3& p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + ")";
}

std::string sky_fractions(const engine::Port& port) {
  return "sky seen by " + percent(port.sky_fraction_winding) + " of the test rays on the side its vertex order "
         "faces, " + percent(port.sky_fraction_opposite) + " on the other";
}

}  // namespace

std::size_t PlacementCheck::dropped() const {
  std::size_t n = 0;
  for (const SensorSetPlacement& s : sets)
    if (s.dropped) n += s.outside + s.inside_solid;
  return n;
}

std::string describe_port_facing(const engine::Scene& scene, std::size_t index) {
  const engine::Port& port = scene.ports()[index];
  const std::string side = port.against_winding ? "against its vertex order" : "along its vertex order";
  switch (port.side_reason) {
    case engine::PortSideReason::Generated: return "into the room (generated)";
    case engine::PortSideReason::Sky:
      return "into the room " + side + " (facing: auto; " + sky_fractions(port) + ")";
    case engine::PortSideReason::Declared:
      return "into the room " + side + " (facing: " + (port.against_winding ? "out" : "in") + "; " +
             sky_fractions(port) + ")";
    case engine::PortSideReason::Ambiguous: return "undecided (" + sky_fractions(port) + ")";
    case engine::PortSideReason::Contradicted: return "contradicted (" + sky_fractions(port) + ")";
  }
  return "";
}

PlacementCheck check_placement(const engine::Scene& scene, std::vector<SensorGrid>& grids,
                               const project::Project& proj) {
  Diagnostics diag;
  const SourceLocation project{proj.path, 1, 1};
  const double north_deg = proj.site.rotation_to_true_north_deg();
  const SceneDescription& description = scene.description();
  if (scene.ports().empty())
    report(diag, project,
           "the project has no photon port: no light can enter (add a window to a room, a polygon or mesh with "
           "'port: true', or a daylight system with its own port)");
  for (std::size_t k = 0; k < scene.ports().size(); ++k) {
    const engine::Port& port = scene.ports()[k];
    const Surface& surface = description.surfaces[static_cast<std::size_t>(port.surface)];
    if (port.side_reason == engine::PortSideReason::Ambiguous) {
      const bool both = port.sky_fraction_winding > 0 && port.sky_fraction_opposite > 0;
      report(diag, surface.location,
             "port '" + surface.name + "': cannot tell which side is the room: " +
                 (both ? "both sides see the sky" : "neither side sees the sky") + " (" + sky_fractions(port) +
                 "); say 'facing: in' (its normal by the vertex order points into the room) or 'facing: out'");
    } else if (port.side_reason == engine::PortSideReason::Contradicted) {
      report(diag, surface.location,
             "port '" + surface.name + "': 'facing: " + (port.against_winding ? "out" : "in") +
                 "' puts the room on the side that sees the sky (" + sky_fractions(port) + "); use 'facing: " +
                 (port.against_winding ? "in" : "out") + "' or 'facing: auto'");
    }
  }

  PlacementCheck out;
  for (SensorGrid& grid : grids) {
    SensorSetPlacement set;
    set.name = grid.name;
    set.sensors = grid.points.size();
    const std::vector<engine::SensorPlacementTest> tests = engine::test_sensor_placements(scene, grid.points);
    std::vector<std::size_t> bad;
    for (std::size_t i = 0; i < tests.size(); ++i) {
      if (tests[i].placement == engine::SensorPlacement::InRoom) continue;
      (tests[i].placement == engine::SensorPlacement::OutsideRooms ? set.outside : set.inside_solid)++;
      bad.push_back(i);
    }
    if (!bad.empty()) {
      std::ostringstream m;
      m << "sensor set '" << grid.name << "': " << bad.size() << " of " << grid.points.size() << " sensors lie ";
      if (set.outside > 0 && set.inside_solid > 0)
        m << "outside every room (" << set.outside << ") or inside a solid (" << set.inside_solid << ")";
      else
        m << (set.outside > 0 ? "outside every room" : "inside a solid");
      m << " (";
      for (std::size_t j = 0; j < bad.size() && j < PlacementExamples; ++j) {
        const std::size_t i = bad[j];
        const engine::SensorPlacementTest& t = tests[i];
        if (j > 0) m << "; ";
        m << "sensor " << i << " at " << point_text(project::world_to_model(grid.points[i].position, north_deg))
          << " m ";
        if (t.placement == engine::SensorPlacement::OutsideRooms) {
          m << "sees the sky without a port in " << percent(double(t.sky_without_port) / t.rays) << " of its "
            << "hemisphere";
        } else {
          m << "sees only the back of '" << description.surfaces[static_cast<std::size_t>(t.solid_surface)].name
            << "' and other solids' faces";
        }
      }
      if (bad.size() > PlacementExamples) m << "; ...";
      m << ")";
      set.description = m.str();
      if (grid.drop_occluded) {
        set.dropped = true;
        set.description += ": dropped (drop_occluded)";
        std::vector<SensorPoint> kept;
        kept.reserve(grid.points.size() - bad.size());
        std::size_t j = 0;
        for (std::size_t i = 0; i < grid.points.size(); ++i) {
          if (j < bad.size() && bad[j] == i) {
            ++j;
            continue;
          }
          kept.push_back(grid.points[i]);
        }
        grid.points = std::move(kept);
        grid.columns = grid.rows = 0;
        if (grid.points.empty())
          report(diag, grid.location,
                 set.description + "; no sensor is left: a set needs at least one sensor in a room");
      } else {
        report(diag, grid.location,
               set.description + "; they would read (almost) no light. Move them into a room, or give the set "
               "'drop_occluded: true' to leave them out");
      }
    }
    out.sets.push_back(std::move(set));
  }
  if (grids.empty())
    report(diag, project, "the project has no sensors: add a grid or a point set under 'sensors'");
  diag.throw_if_errors();
  return out;
}

void check_project_placement(const project::Project& project) {
  auto check_case = [](const project::Project& p) {
    SceneDescription description = project::build_scene_description(p);
    const engine::Scene scene = engine::Scene::build(description);
    check_placement(scene, description.grids, p);
  };
  check_case(project);
  for (const project::VariantSpec& v : project.variants) check_case(project::apply_variant(project, v));
}

}  // namespace dayphoton::study
