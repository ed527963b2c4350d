// A side-lit test room as a project file: one room with a south window of glass, a work-plane
// grid at 0.8 m with 1 m spacing (or a grid given), a daylight-factor study (no weather file).
// For the tests that need a real scene and the plan's own options, e.g. to trace a few photon
// steps.
#pragma once

#include <string>

namespace dayphoton::test {

/// `size_m` the room's "[width, depth, height]", `window_width_m` the window's width (1.5 m
/// high on a 0.9 m sill, named w), `photons_per_bin` the simulation's photon count; `grid` the
/// one grid (a flow mapping), `system` an optional shading system (a flow mapping, e.g. an
/// overhang on window w).
inline std::string side_lit_room_yaml(const std::string& size_m, const std::string& window_width_m,
                                      int photons_per_bin,
                                      const std::string& grid =
                                          "{name: workplane, room: office, height: 0.8, spacing: 1}",
                                      const std::string& system = "") {
  return "site: {latitude: 51.5, longitude: -0.12, time_zone: 0}\n"
         "study: daylight_factor\n"
         "materials:\n"
         "  walls: {type: lambertian, reflectance: 0.5}\n"
         "  glass: {type: glass, transmittance: 0.6}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: " + size_m + "\n"
         "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
         "      windows: [{name: w, wall: south, width: " + window_width_m +
         ", height: 1.5, sill: 0.9, material: glass}]\n" +
         (system.empty() ? std::string() : "  systems:\n    - " + system + "\n") +
         "sensors:\n"
         "  grids:\n"
         "    - " + grid + "\n"
         "simulation:\n"
         "  photons_per_bin: " + std::to_string(photons_per_bin) + "\n";
}

}  // namespace dayphoton::test
