// `dayphoton render PROJECT.yaml --view x,y,z --direction dx,dy,dz -o out.exr`: a picture of
// the model lit by a sky (issue 7 item 3). Traces the project's photons with the surface
// photons kept (the study's receiver-plane pass drops them), then renders by direct
// visualisation (engine/renderer.h) under the sky of --sky (study/render_sky.h). Writes the
// radiance as a float EXR and a tone-mapped PNG beside it (study/tone_map.h). docs/report.md.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <ostream>
#include <sstream>

#include <tbb/global_control.h>

#include "commands.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/renderer.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/image_files.h"
#include "dayphoton/study/render_sky.h"
#include "dayphoton/study/simulation_plan.h"
#include "dayphoton/study/tone_map.h"

namespace dayphoton::app {

namespace {

Vec3 parse_vector(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  Vec3 v;
  char c1 = 0, c2 = 0;
  if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof() || !is_finite(v))
    throw UsageError(option + " must be three numbers x,y,z, not '" + text + "'");
  return v;
}

/// x,y,z: 6 significant digits, millimetres beyond 100 km (a view in survey coordinates).
std::string vector_text(const Vec3& v) {
  return format_coordinate(v.x) + ',' + format_coordinate(v.y) + ',' + format_coordinate(v.z);
}

}  // namespace

int run_render(const RenderOptions& options, std::ostream& out) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  std::unique_ptr<tbb::global_control> threads;
  if (options.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    static_cast<std::size_t>(options.threads));
  engine::Camera camera;
  camera.position_m = parse_vector(options.view, "--view");
  camera.direction = parse_vector(options.direction, "--direction");
  camera.up = parse_vector(options.up, "--up");
  camera.fov_deg = options.fov_deg;
  camera.projection = options.fisheye ? engine::Camera::Projection::Fisheye : engine::Camera::Projection::Perspective;
  camera.width = options.width;
  camera.height = options.height;
  if (!(length(camera.direction) > 0)) throw UsageError("--direction must not be zero");
  if (!(length(cross(normalize(camera.direction), camera.up)) > 1e-6))
    throw UsageError("--up must not be parallel to --direction (give another --up)");
  if (!options.fisheye && options.fov_deg >= 179) throw UsageError("--fov of a perspective view must be below 179 degrees (or use --fisheye)");
  const std::filesystem::path exr_path(options.output_path);
  if (exr_path.extension() != ".exr") throw UsageError("-o must name an .exr file, not '" + options.output_path + "'");
  std::filesystem::path png_path = exr_path;
  png_path.replace_extension(".png");

  // Model, sky (checked before the long photon pass), photons.
  const project::Project project = project::load_project(
      options.project_path, {/*output_folder_overridden=*/true});  // writes -o, not outputs.folder
  const SceneDescription description = project::build_scene_description(project);
  const engine::Scene scene = engine::Scene::build(description);
  const std::vector<engine::Material> materials = engine::materials_of(description.materials);
  const sky::PatchBasis basis = study::basis_of(project.simulation);
  study::RenderSkySettings sky_settings;
  sky_settings.spec = options.sky;
  sky_settings.horizontal_illuminance_lux = options.horizontal_illuminance_lux;
  sky_settings.sun_altitude_deg = options.sun_altitude_deg;
  sky_settings.sun_azimuth_deg = options.sun_azimuth_deg;
  study::RenderSkyResult sky;
  try {
    sky = study::make_render_sky(sky_settings, project, basis);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (options.photons_per_bin > 0) {
    // The project's own photons_per_bin was checked by the loader; --photons is checked here,
    // before anything is traced, against the same limit.
    const double photons = double(options.photons_per_bin) * double(basis.bin_count());
    if (photons > double(project.limits.photons))
      throw UsageError("--photons " + std::to_string(options.photons_per_bin) + " would store " +
                       format_number(photons) + " photons (" + std::to_string(basis.bin_count()) + " sky bins), " +
                       over_limit_text(project.limits.photons, "limits.photons in the project"));
  }
  engine::SourceSet sources = engine::SourceSet::sky_bins(basis);
  engine::TracingOptions tracing;
  tracing.photons_per_source = static_cast<std::size_t>(
      options.photons_per_bin > 0 ? options.photons_per_bin : project.simulation.photons_per_bin);
  tracing.seed = project.simulation.seed;
  // The ground bin's share as `dayphoton run` gives it (study/plan_policy.h).
  tracing.source_photon_factor = study::sky_photon_factors(sources.size());
  study::add_sun_source(sky.sky, sources, tracing.source_photon_factor);
  tracing.keep_surface_photons = true;
  if (!options.quiet)
    out << "render: tracing " << tracing.photons_per_source << " photons per sky bin (" << basis.bin_count() << " bins"
        << (sky.sky.sun ? ", and the sun" : "") << ")\n" << std::flush;
  engine::TracedPhotons photons = engine::trace_photons(scene, materials, sources, {}, tracing);
  const auto traced = Clock::now();

  engine::RenderOptions render_options;
  render_options.samples_per_pixel = options.samples_per_pixel;
  render_options.direct_samples = options.direct_samples;
  render_options.density.bandwidth = static_cast<std::size_t>(options.bandwidth);
  render_options.seed = project.simulation.seed;
  const std::size_t surface_photons = photons.surface.size();
  const engine::PhotonRenderer renderer(scene, materials, photons.surface, sky.sky, render_options);
  photons = engine::TracedPhotons{};
  if (!options.quiet) out << "render: " << surface_photons << " surface photons; sky: " << sky.description << "\n" << std::flush;
  // The view is in world coordinates (the EXR header keeps it so); the scene is held around
  // its local origin (SceneDescription::world_origin_m).
  engine::Camera scene_camera = camera;
  scene_camera.position_m = camera.position_m - description.world_origin_m;
  const engine::RenderedImage image = renderer.render(scene_camera);
  const auto rendered = Clock::now();

  study::FloatImage exr(image.width, image.height, {"R", "G", "B"});
  if (options.fisheye) exr = study::FloatImage(image.width, image.height, {"R", "G", "B", "A"});
  std::size_t bad = 0;
  double luminance_sum = 0;
  std::size_t inside = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x);
      const Vec3& l = image.radiance[p];
      if (!is_finite(l) || l.x < 0 || l.y < 0 || l.z < 0) ++bad;
      exr.at(0, x, y) = static_cast<float>(l.x);
      exr.at(1, x, y) = static_cast<float>(l.y);
      exr.at(2, x, y) = static_cast<float>(l.z);
      if (options.fisheye) exr.at(3, x, y) = image.inside[p] ? 1.0f : 0.0f;
      if (image.inside[p]) {
        luminance_sum += rgb_to_photometric(l);
        ++inside;
      }
    }
  if (bad > 0) throw std::runtime_error(std::to_string(bad) + " pixels are not finite or negative (a bug)");
  exr.string_attributes["dayphoton:project"] = options.project_path;
  exr.string_attributes["dayphoton:view"] = vector_text(camera.position_m);
  exr.string_attributes["dayphoton:direction"] = vector_text(camera.direction);
  exr.string_attributes["dayphoton:up"] = vector_text(camera.up);
  exr.string_attributes["dayphoton:projection"] = options.fisheye ? "angular fisheye" : "perspective";
  exr.float_attributes["dayphoton:fov_deg"] = static_cast<float>(options.fov_deg);
  exr.string_attributes["dayphoton:sky"] = sky.description;
  exr.string_attributes["dayphoton:method"] =
      "direct visualisation of the surface photon map (seeds/000 3.1.2.1) + shadow rays through the ports";
  exr.float_attributes["dayphoton:samples_per_pixel"] = static_cast<float>(options.samples_per_pixel);
  exr.float_attributes["dayphoton:photons_per_bin"] = static_cast<float>(tracing.photons_per_source);
  exr.float_attributes["dayphoton:bandwidth"] = static_cast<float>(options.bandwidth);
  exr.string_attributes["dayphoton:luminance"] = "179 * (0.265 R + 0.670 G + 0.065 B) cd/m2";
  if (!exr_path.parent_path().empty()) std::filesystem::create_directories(exr_path.parent_path());
  study::write_exr(exr, "radiance", "W/(sr m2)", exr_path.string());
  study::write_png(study::tone_map(exr), png_path.string());
  if (!options.quiet) {
    const double trace_s = std::chrono::duration<double>(traced - start).count();
    const double render_s = std::chrono::duration<double>(rendered - traced).count();
    out << "render: " << image.width << " x " << image.height << " pixels, " << options.samples_per_pixel
        << " samples each; mean luminance " << std::round(luminance_sum / std::max<std::size_t>(1, inside))
        << " cd/m2; photons " << std::round(trace_s * 10) / 10 << " s, picture " << std::round(render_s * 10) / 10
        << " s\n";
    out << "wrote " << exr_path.string() << "\nwrote " << png_path.string() << "\n";
  }
  require_written(out, "standard output");
  return ExitOk;
}

}  // namespace dayphoton::app
