// PhotonRenderer: pictures of a view lit by a sky, from the surface photon map (issue 7 item
// 3; DESIGN.md section 7 "renderings of views to EXR").
//
// Method: direct visualisation (seeds/000 section 3.1.2.1; it is what the thesis's validation
// runs use, digest section 2.2), completed by shadow rays for the zero-event light:
//   - a camera ray is followed through delta and glossy events (glass, openings, mirrors,
//     Ward lobes: one Material::sample() per event, so one path per camera sample) until it
//     leaves the scene or the path ends;
//   - at every surface with a diffuse component it meets, the diffuse part of the radiance
//     toward the camera is  L_d = (rho_d / pi) E(x, front) + (tau_d / pi) E(x, back)  with
//     rho_d, tau_d the diffuse reflectance and transmittance (docs/materials.md) and
//         E = E_direct + E_photons;
//     the glossy part continues the path with weight (f - f_d) |cos| / pdf, so no light is
//     counted twice (f_d is already in L_d) and none is lost;
//   - E_photons: density estimate of the caustic + global surface photons on that side
//     (density_estimate.h; the photon's normal filter), each photon's flux weighted by the
//     radiance of its source in this sky: the contribution estimate of seeds/001 eq. 18
//     summed over sources, from one lookup of the N nearest photons;
//   - E_direct: the light of zero-event paths (sky and ground seen through the glazing),
//     which the tracer never stores: shadow rays toward points drawn uniformly on the ports
//     (pdf 1 / total port area, i.e. d^2 / (A |cos theta_port|) per steradian), with the
//     transmittance rule of direct_component.h (sky_transmittance: only directions that pass
//     exactly one port and nothing after it count, so each direction is owned by one port and
//     the estimate is unbiased); plus, if the sky has a sun, shadow rays to points of the
//     sun disc (its radiance times its solid angle times the cosine and the transmittance);
//   - a ray that leaves the scene sees the continuous sky or ground radiance (and the sun
//     disc when it points into it);
//   - on a port's sky side, which holds no photon and sees the sky without crossing a port,
//     E comes from sky_side_irradiance instead: cosine-weighted rays to the sky and ground,
//     one diffuse reflection off the outdoor surfaces they meet, and the sun by shadow rays
//     (a diffusing pane is drawn with tau_d E / pi from there).
// So the picture uses the same split as the daylight coefficients (direct by shadow rays,
// everything scattered from photons) and, for a Lambertian surface, the luminance of a pixel
// is rho E / pi with E the illuminance the coefficients give at that point (the acceptance
// test in tests/engine/renderer_test.cpp).
//
// Final gathering (seeds/000 section 3.1.2.2) would hide the photon noise better at many
// times the cost; direct visualisation keeps a rendering of an office in seconds.
//
// Units: radiance RGB in W/(sr m^2) (RADIANCE's; luminance = 179 (0.265 R + 0.670 G + 0.065 B)
// cd/m^2), positions in metres.
//
// Determinism: sample s of pixel p draws its numbers from Rng(seed, p, s, Scattering), so the
// image does not depend on the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/density_estimate.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/photon.h"
#include "dayphoton/engine/photon_map.h"
#include "dayphoton/engine/random.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine {

/// A pinhole or angular-fisheye camera. Image x runs right, y down; pixel (i, j) covers
/// [i, i+1) x [j, j+1).
struct Camera {
  enum class Projection { Perspective, Fisheye };
  Vec3 position_m;
  Vec3 direction{0, 1, 0};  ///< view direction (need not be unit)
  Vec3 up{0, 0, 1};         ///< must not be parallel to direction
  /// Perspective: horizontal field of view, (0, 179) degrees. Fisheye: the angle across the
  /// image circle (diameter = the smaller image side), (0, 360] degrees; equidistant
  /// (angle from the view direction proportional to the distance from the centre).
  double fov_deg = 60;
  Projection projection = Projection::Perspective;
  int width = 512, height = 384;

  /// Unit direction of the ray through image point (x, y) (pixel units); nothing outside
  /// the fisheye circle. Throws std::invalid_argument for a bad camera (zero or parallel
  /// vectors, field of view out of range, non-positive size).
  std::optional<Vec3> ray_direction(double x, double y) const;
};

/// The sky a picture is lit by.
struct RenderSky {
  /// Radiance (RGB, W/(sr m^2)) along a direction toward the sky: the continuous sky above
  /// the horizon, the ground below it; without the sun disc.
  std::function<Vec3(const Vec3&)> radiance;
  /// Per photon source (SourceSet index): the radiance that weights its photons (the sky
  /// vector of the same sky: bin means, the ground bin, the sun's light put into its bin).
  std::vector<Vec3> source_radiance;
  struct Sun {
    Vec3 direction;                ///< unit, toward the sun
    double half_angle_rad = 0;     ///< angular radius of the disc
    Vec3 radiance;                 ///< RGB, W/(sr m^2), uniform over the disc
  };
  std::optional<Sun> sun;
};

struct RenderOptions {
  int samples_per_pixel = 4;  ///< camera samples per pixel (jittered), >= 1
  int direct_samples = 16;    ///< port shadow rays (and sun shadow rays) per diffuse hit, >= 1
  /// Photons per estimate and kernel (density_estimate.h); the photon map holds all sources.
  DensityEstimateOptions density{200, 1e30, KernelType::Uniform, KernelRadius::NextNeighbour};
  int max_path_events = 16;   ///< delta/glossy events followed per camera sample
  std::uint64_t seed = 1;
};

/// A rendered picture: per pixel the mean radiance of its samples and the variance of that
/// mean (sample variance / n, per channel; 0 for one sample).
struct RenderedImage {
  int width = 0, height = 0;
  std::vector<Vec3> radiance;   ///< row-major, row 0 at the top
  std::vector<Vec3> variance;
  std::vector<char> inside;     ///< 0 outside the fisheye circle (radiance 0 there)
};

class PhotonRenderer {
 public:
  /// `surface_photons`: TracedPhotons::surface of a pass with keep_surface_photons. Throws
  /// std::invalid_argument if a photon's source has no entry in sky.source_radiance, the
  /// materials do not match the scene, the sky has no radiance function, or an option is out
  /// of range.
  PhotonRenderer(const Scene& scene, const std::vector<Material>& materials,
                 const std::vector<Photon>& surface_photons, RenderSky sky, RenderOptions options);

  /// Render every pixel (parallel over rows, oneTBB; deterministic).
  RenderedImage render(const Camera& camera) const;

  /// One sample of the radiance arriving at the camera along `ray` (propagation direction).
  Vec3 radiance(const Ray& ray, Rng& rng) const;

  /// Irradiance at `point` on the side `side_normal` faces (unit), W/m^2 RGB: photon part
  /// (deterministic) and one estimate of the direct part from `samples` port (and sun)
  /// shadow rays.
  Vec3 photon_irradiance(const Vec3& point, const Vec3& side_normal) const;
  Vec3 direct_irradiance(const Vec3& point, const Vec3& side_normal, Rng& rng, int samples) const;

  /// Diffuse reflectance and transmittance of a material (docs/materials.md: plastic, metal
  /// and trans put colour (1 - s)(1 - t) into diffuse reflection and colour (1 - s) t (1 - ts)
  /// into diffuse transmission; the other models have none).
  static Vec3 diffuse_reflectance(const MaterialSpec& spec);
  static Vec3 diffuse_transmittance(const MaterialSpec& spec);

 private:
  Vec3 escaped(const Vec3& direction) const;
  /// E on `side_normal`'s side of the surface hit: photons plus port shadow rays, or on a
  /// port's sky side sky_side_irradiance.
  Vec3 surface_irradiance(const Hit& hit, const Vec3& side_normal, Rng& rng) const;
  /// Irradiance outdoors (a port's sky side): cosine-weighted rays to the sky and ground,
  /// `reflections` diffuse reflections off outdoor surfaces, and the sun by shadow rays.
  Vec3 sky_side_irradiance(const Vec3& point, const Vec3& side_normal, Rng& rng, int samples, int reflections) const;
  /// The sun's irradiance from `samples` shadow rays to its disc: through the ports with
  /// sky_transmittance (indoors), or where nothing is in the way (outdoors).
  enum class SunPath { ThroughPorts, Unobstructed };
  Vec3 sun_irradiance(const Vec3& point, const Vec3& side_normal, Rng& rng, int samples, SunPath path) const;
  /// Rays per estimate of the irradiance on an outdoor surface seen from a port's sky side.
  static constexpr int OutdoorReflectionSamples = 4;

  const Scene* m_scene;
  const std::vector<Material>* m_materials;
  PhotonMap m_map;  ///< flux already weighted by the source radiance
  RenderSky m_sky;
  RenderOptions m_options;
  double m_port_area_m2 = 0;
  std::vector<double> m_port_cumulative_m2;
  double m_sun_cos_half_angle = 1;
};

}  // namespace dayphoton::engine
