// The low-yield cap's warning (photon_pass_notes.h, docs/photon-tracing.md "Low-yield cap"):
// a light-pipe room whose 24 m2 roof is drawn as outdoor scatterers takes nearly every
// emission attempt on the roof, the cap (counted in port-equivalent attempts) cuts every sky
// bin to a few per cent of its target, and the starved sources' wide discs bias the daylight
// factors far beyond the stated standard error. The run must say so, located at the
// `simulation` section, in run.log; with the cap off it must not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "dayphoton/project/project.h"
#include "../temp_folder.h"
#include "fresh_run.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

const std::string FakePath = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/light_pipe/test.yaml";

// projects/light_pipe with its roof as five 2 cm slabs 1 cm above the ceiling, around the two
// pipes, marked outdoor: true; fewer photons so that the uncapped run is short.
std::string roof_project(long long max_attempts) {
  return "version: 1\n"
         "study: daylight_factor\n"
         "site: {name: Oakland, latitude: 37.72, longitude: -122.22, time_zone: -8, elevation: 2, north: 0}\n"
         "materials:\n"
         "  floor: {type: lambertian, reflectance: 0.3}\n"
         "  walls: {type: lambertian, reflectance: 0.6}\n"
         "  ceiling: {type: lambertian, reflectance: 0.8}\n"
         "  roof: {type: lambertian, reflectance: 0.3}\n"
         "  dome_glass: {type: glass, transmittance: 0.88}\n"
         "  reflective_film: {type: mirror, reflectance: 0.95}\n"
         "  opal: {type: translucent, reflectance: 0.85, transmissivity: 0.7, transmitted_specular: 0.05}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - {name: core_room, size: [4, 6, 2.7], materials: {floor: floor, ceiling: ceiling, walls: walls}}\n"
         "  boxes:\n"
         "    - {name: roof_w, origin: [0, 0, 2.71], size: [1.8, 6, 0.02], material: roof, outdoor: true}\n"
         "    - {name: roof_e, origin: [2.2, 0, 2.71], size: [1.8, 6, 0.02], material: roof, outdoor: true}\n"
         "    - {name: roof_s, origin: [1.8, 0, 2.71], size: [0.4, 1.6, 0.02], material: roof, outdoor: true}\n"
         "    - {name: roof_m, origin: [1.8, 2.0, 2.71], size: [0.4, 2.0, 0.02], material: roof, outdoor: true}\n"
         "    - {name: roof_n, origin: [1.8, 4.4, 2.71], size: [0.4, 1.6, 0.02], material: roof, outdoor: true}\n"
         "  systems:\n"
         "    - {type: light_pipe, name: pipe, room: core_room, x: 2, y: 1.8, diameter: 0.35, length: 1.5,\n"
         "       sides: 8, collector: dome, dome_rings: 2, tube_material: reflective_film,\n"
         "       diffuser_material: opal, collector_material: dome_glass}\n"
         "    - {type: light_pipe, name: pipe_2, room: core_room, x: 2, y: 4.2, diameter: 0.35, length: 1.5,\n"
         "       sides: 12, collector: flat, tube_material: reflective_film, diffuser_material: opal,\n"
         "       collector_material: dome_glass}\n"
         "sensors:\n"
         "  grids:\n"
         "    - {name: workplane, room: core_room, height: 0.8, spacing: 1, inset: 0.5}\n"
         "simulation:\n"  // line 31, its first key at 32:3
         "  basis: tregenza\n"
         "  photons_per_bin: 300\n"
         "  bandwidth: 20\n"
         "  seed: 8\n"
         "  max_attempts_per_photon: " +
         std::to_string(max_attempts) +
         "\n"
         "outputs: {folder: results, images: false}\n";
}

std::string run_log_of(long long max_attempts) {
  const fs::path out = test::process_temp_dir() / ("capped_flux_" + std::to_string(max_attempts));
  test::run_in_fresh_folder(project::load_project_from_string(roof_project(max_attempts), FakePath), out);
  std::ifstream in(out / "run.log");
  std::stringstream text;
  text << in.rdbuf();
  fs::remove_all(out);
  return text.str();
}

TEST(CappedFluxWarning, StarvedCappedSourcesAreALocatedWarning) {
  const std::string capped = run_log_of(256);
  // The note (every capped source, its share of the flux) and the located warning.
  EXPECT_NE(capped.find("sources capped at 256 main-pass attempts per target photon"), std::string::npos) << capped;
  const std::string located = "warning: " + FakePath + ":32:3: simulation.max_attempts_per_photon: sources capped";
  const std::size_t at = capped.find(located);
  ASSERT_NE(at, std::string::npos) << capped;
  const std::string line = capped.substr(at, capped.find('\n', at) - at);
  EXPECT_NE(line.find("fewer than 80 photons (4 x the bandwidth"), std::string::npos) << line;
  EXPECT_NE(line.find("the stated uncertainty does not cover these results"), std::string::npos) << line;
  // Nearly all the light comes through sources starved by the cap (every sky bin).
  EXPECT_NE(line.find("carry 100 % of the stored photon flux"), std::string::npos) << line;

  // Without the cap every source reaches its target: no note, no warning.
  const std::string uncapped = run_log_of(0);
  EXPECT_EQ(uncapped.find("main-pass attempts per target photon"), std::string::npos) << uncapped;
  EXPECT_EQ(uncapped.find("max_attempts_per_photon"), std::string::npos) << uncapped;
  EXPECT_NE(uncapped.find("photon cap: 0 source(s)"), std::string::npos) << uncapped;
}

}  // namespace
}  // namespace dayphoton::study
