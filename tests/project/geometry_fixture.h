// Shared fixtures for the geometry-stage tests: the reference office of
// ../shared/refdata/scenes/office.rad (6 x 8 x 3 m, one 4 x 1.5 m window centred in the
// south wall, sill 0.9 m) built directly as a Project struct (no YAML), and temp files.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"

namespace dayphoton::project::testing {

inline MaterialSpec lambertian(const std::string& name, double reflectance) {
  MaterialSpec m;
  m.name = name;
  m.type = MaterialType::Lambertian;
  m.reflectance = {reflectance, reflectance, reflectance};
  return m;
}

inline MaterialSpec glass(const std::string& name, double transmittance) {
  MaterialSpec m;
  m.name = name;
  m.type = MaterialType::Glass;
  m.transmittance = {transmittance, transmittance, transmittance};
  return m;
}

inline Project office_project() {
  Project p;
  p.path = "office.yaml";
  p.materials = {lambertian("floor_mat", 0.2), lambertian("ceiling_mat", 0.8),
                 lambertian("wall_mat", 0.5), glass("glass_mat", 0.6)};
  RoomSpec room;
  room.name = "office";
  room.origin = {0, 0, 0};
  room.size_m = {6, 8, 3};
  room.floor_material = "floor_mat";
  room.ceiling_material = "ceiling_mat";
  for (auto& w : room.wall_material) w = "wall_mat";
  room.location = {"office.yaml", 10, 5};
  WindowSpec window;
  window.name = "window";
  window.wall = Wall::South;
  window.width_m = 4;
  window.height_m = 1.5;
  window.sill_m = 0.9;
  window.material = "glass_mat";
  window.location = {"office.yaml", 20, 9};
  room.windows.push_back(window);
  p.geometry.rooms.push_back(room);
  GridSpec grid;
  grid.name = "workplane";
  grid.room = "office";
  grid.height_m = 0.8;
  grid.spacing_m = 0.5;
  grid.inset_m = 0.5;
  grid.location = {"office.yaml", 30, 5};
  p.sensors.grids.push_back(grid);
  return p;
}

/// A file under the test temp folder, removed when the object goes out of scope.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& contents)
      : m_path(::testing::TempDir() + name) {
    std::ofstream out(m_path, std::ios::binary);
    out << contents;
  }
  ~TempFile() { std::remove(m_path.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return m_path; }

 private:
  std::string m_path;
};

/// The text of the InputError thrown by build_scene_description, or "" if none.
inline std::string build_error(const Project& p) {
  try {
    build_scene_description(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace dayphoton::project::testing
