// PhotonRenderer: direct visualisation of the surface photon map plus shadow rays for the
// zero-event light; see renderer.h for the method and its references.
#include "dayphoton/engine/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "material_common.h"

namespace dayphoton::engine {

namespace {

double max_component(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

Vec3 clamp_non_negative(const Vec3& v) { return {std::max(0.0, v.x), std::max(0.0, v.y), std::max(0.0, v.z)}; }

/// Orthonormal frame around a unit vector (Duff et al., JCGT 6(1), 2017).
void frame(const Vec3& n, Vec3& a, Vec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double p = -1.0 / (sign + n.z);
  const double q = n.x * n.y * p;
  a = {1.0 + sign * n.x * n.x * p, sign * q, -sign * n.x};
  b = {q, sign + n.y * n.y * p, -n.y};
}

/// The surface photons with their flux weighted by their source's radiance in this sky.
std::vector<Photon> weighted_photons(const std::vector<Photon>& photons, const std::vector<Vec3>& source_radiance) {
  std::vector<Photon> out;
  out.reserve(photons.size());
  for (const Photon& p : photons) {
    if (p.source >= source_radiance.size())
      throw std::invalid_argument("PhotonRenderer: photon of source " + std::to_string(p.source) + " but the sky has " +
                                  std::to_string(source_radiance.size()) + " source radiances");
    Photon w = p;
    const Vec3 f = mul(p.flux_rgb(), source_radiance[p.source]);
    w.flux = {static_cast<float>(f.x), static_cast<float>(f.y), static_cast<float>(f.z)};
    out.push_back(w);
  }
  return out;
}

}  // namespace

std::optional<Vec3> Camera::ray_direction(double x, double y) const {
  if (width <= 0 || height <= 0) throw std::invalid_argument("camera: image size must be positive");
  if (!(length(direction) > 0) || !is_finite(direction)) throw std::invalid_argument("camera: zero view direction");
  const Vec3 forward = normalize(direction);
  const Vec3 side = cross(forward, up);
  if (!(length(side) > 1e-9)) throw std::invalid_argument("camera: the up vector is parallel to the view direction");
  const Vec3 right = normalize(side);
  const Vec3 true_up = cross(right, forward);
  if (projection == Projection::Perspective) {
    if (!(fov_deg > 0 && fov_deg < 179)) throw std::invalid_argument("camera: perspective field of view must be in (0, 179) deg");
    const double t = std::tan(0.5 * deg_to_rad(fov_deg));
    const double sx = (2.0 * x / width - 1.0) * t;
    const double sy = (1.0 - 2.0 * y / height) * t * height / width;
    return normalize(forward + right * sx + true_up * sy);
  }
  if (!(fov_deg > 0 && fov_deg <= 360)) throw std::invalid_argument("camera: fisheye field of view must be in (0, 360] deg");
  const double radius_px = 0.5 * std::min(width, height);
  const double dx = (x - 0.5 * width) / radius_px, dy = (0.5 * height - y) / radius_px;
  const double r = std::sqrt(dx * dx + dy * dy);
  if (r > 1.0) return std::nullopt;
  const double theta = r * 0.5 * deg_to_rad(fov_deg);
  const double c = r > 0 ? dx / r : 0, s = r > 0 ? dy / r : 0;
  return normalize(forward * std::cos(theta) + (right * c + true_up * s) * std::sin(theta));
}

Vec3 PhotonRenderer::diffuse_reflectance(const MaterialSpec& spec) { return engine::diffuse_reflectance(spec); }

Vec3 PhotonRenderer::diffuse_transmittance(const MaterialSpec& spec) { return engine::diffuse_transmittance(spec); }

PhotonRenderer::PhotonRenderer(const Scene& scene, const std::vector<Material>& materials,
                               const std::vector<Photon>& surface_photons, RenderSky sky, RenderOptions options)
    : m_scene(&scene),
      m_materials(&materials),
      m_map(weighted_photons(surface_photons, sky.source_radiance)),
      m_sky(std::move(sky)),
      m_options(options) {
  if (materials.size() < scene.description().materials.size())
    throw std::invalid_argument("PhotonRenderer: fewer materials than the scene has");
  if (!m_sky.radiance) throw std::invalid_argument("PhotonRenderer: the sky has no radiance function");
  if (m_options.samples_per_pixel < 1 || m_options.direct_samples < 1 || m_options.max_path_events < 1 ||
      m_options.density.bandwidth < 1 || !(m_options.density.max_radius_m > 0))
    throw std::invalid_argument("PhotonRenderer: samples, events and bandwidth must be >= 1, the radius > 0");
  for (const Port& p : scene.ports().ports()) {
    m_port_area_m2 += p.area_m2;
    m_port_cumulative_m2.push_back(m_port_area_m2);
  }
  if (m_sky.sun) {
    m_sky.sun->direction = normalize(m_sky.sun->direction);
    m_sun_cos_half_angle = std::cos(m_sky.sun->half_angle_rad);
  }
}

Vec3 PhotonRenderer::escaped(const Vec3& direction) const {
  Vec3 l = m_sky.radiance(direction);
  if (m_sky.sun && dot(direction, m_sky.sun->direction) >= m_sun_cos_half_angle) l += m_sky.sun->radiance;
  return l;
}

Vec3 PhotonRenderer::photon_irradiance(const Vec3& point, const Vec3& side_normal) const {
  PhotonFilter filter;
  filter.check_normal = true;
  filter.normal = side_normal;
  return estimate_irradiance(m_map, point, filter, m_options.density).irradiance;
}

Vec3 PhotonRenderer::direct_irradiance(const Vec3& point, const Vec3& side_normal, Rng& rng, int samples) const {
  Vec3 sum;
  const PortSet& ports = m_scene->ports();
  if (m_port_area_m2 > 0) {
    for (int i = 0; i < samples; ++i) {
      // Port chosen by area, point uniform on it: pdf 1 / (total port area) per m^2.
      const double u = rng.uniform() * m_port_area_m2;
      const std::size_t k = static_cast<std::size_t>(
          std::min<std::ptrdiff_t>(std::upper_bound(m_port_cumulative_m2.begin(), m_port_cumulative_m2.end(), u) -
                                       m_port_cumulative_m2.begin(),
                                   static_cast<std::ptrdiff_t>(m_port_cumulative_m2.size()) - 1));
      const double u1 = rng.uniform(), u2 = rng.uniform();
      const PortSample s = ports.sample(k, u1, u2);
      const Vec3 to = s.position - point;
      const double d2 = dot(to, to);
      if (!(d2 > 0)) continue;
      const Vec3 w = to / std::sqrt(d2);
      const double cos_x = dot(w, side_normal);
      const double cos_port = std::abs(dot(w, s.normal));
      if (cos_x <= 0 || cos_port <= 0) continue;
      // Only directions crossing exactly one port and nothing after it carry light
      // (sky_transmittance), so this direction belongs to port k alone.
      const Vec3 t = sky_transmittance(*m_scene, *m_materials, m_scene->offset_ray_origin(point, side_normal, w), w);
      if (max_component(t) <= 0) continue;
      const double pdf_sr = d2 / (m_port_area_m2 * cos_port);
      sum += mul(t, m_sky.radiance(w)) * (cos_x / pdf_sr);
    }
    sum = sum / static_cast<double>(samples);
  }
  return sum + sun_irradiance(point, side_normal, rng, samples, SunPath::ThroughPorts);
}

Vec3 PhotonRenderer::surface_irradiance(const Hit& hit, const Vec3& side_normal, Rng& rng) const {
  // The sky side of a port holds no photon (the tracer starts its photons on the ports) and
  // sees the sky without crossing a port, so neither estimate below reaches it.
  if (hit.port >= 0 && dot(side_normal, m_scene->ports()[static_cast<std::size_t>(hit.port)].normal) < 0)
    return sky_side_irradiance(hit.position, side_normal, rng, m_options.direct_samples, /*reflections=*/1);
  return photon_irradiance(hit.position, side_normal) + direct_irradiance(hit.position, side_normal, rng, m_options.direct_samples);
}

Vec3 PhotonRenderer::sun_irradiance(const Vec3& point, const Vec3& side_normal, Rng& rng, int samples, SunPath path) const {
  if (!m_sky.sun || !(dot(m_sky.sun->direction, side_normal) > -std::sin(m_sky.sun->half_angle_rad))) return {};
  // The sun disc sampled uniformly in solid angle (cone about its centre).
  const RenderSky::Sun& sun = *m_sky.sun;
  const double one_minus_cos = 2.0 * std::pow(std::sin(0.5 * sun.half_angle_rad), 2);
  const double solid_angle_sr = 2.0 * Pi * one_minus_cos;
  Vec3 a, b;
  frame(sun.direction, a, b);
  Vec3 sum;
  for (int i = 0; i < samples; ++i) {
    const double cos_t = 1.0 - rng.uniform() * one_minus_cos;
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    const double phi = 2.0 * Pi * rng.uniform();
    const Vec3 w = normalize(sun.direction * cos_t + (a * std::cos(phi) + b * std::sin(phi)) * sin_t);
    const double cos_x = dot(w, side_normal);
    if (cos_x <= 0) continue;
    const Vec3 origin = m_scene->offset_ray_origin(point, side_normal, w);
    if (path == SunPath::ThroughPorts) {
      sum += mul(sky_transmittance(*m_scene, *m_materials, origin, w), sun.radiance) * (cos_x * solid_angle_sr);
    } else if (!m_scene->occluded(Ray{origin, w, 0.0, std::numeric_limits<double>::infinity()})) {
      sum += sun.radiance * (cos_x * solid_angle_sr);
    }
  }
  return sum / static_cast<double>(samples);
}

Vec3 PhotonRenderer::sky_side_irradiance(const Vec3& point, const Vec3& side_normal, Rng& rng, int samples,
                                         int reflections) const {
  // E = pi / N sum_i L(w_i) for cosine-weighted w_i (Pharr, Jakob & Humphreys, "Physically
  // Based Rendering", 4th ed., section 13.6.3, the cosine-weighted estimator): a ray that
  // escapes sees the continuous sky or the ground (m_sky.radiance, without the sun disc, whose
  // light comes from the sun's own shadow rays); a ray that meets an outdoor surface sees its
  // diffuse reflection of the sky and sun, L = rho_d / pi E, with E estimated the same way
  // without further reflections (the light reflected twice outdoors is left out, and so is
  // an outdoor surface's non-diffuse reflection).
  Vec3 sum;
  for (int i = 0; i < samples; ++i) {
    const Vec3 w = detail::sample_cosine(side_normal, rng.uniform(), rng.uniform());
    const Ray ray{m_scene->offset_ray_origin(point, side_normal, w), w, 0.0, std::numeric_limits<double>::infinity()};
    const std::optional<Hit> hit = m_scene->intersect(ray);
    if (!hit) {
      sum += m_sky.radiance(w) * Pi;
      continue;
    }
    if (reflections <= 0) continue;
    const Vec3 rho_d = (*m_materials)[static_cast<std::size_t>(hit->material)].diffuse_reflectance();
    if (max_component(rho_d) <= 0) continue;
    const Vec3 facing = hit->front_face ? hit->normal : hit->normal * -1.0;
    sum += mul(rho_d, sky_side_irradiance(hit->position, facing, rng, OutdoorReflectionSamples, reflections - 1));
  }
  return sum / static_cast<double>(samples) + sun_irradiance(point, side_normal, rng, samples, SunPath::Unobstructed);
}

Vec3 PhotonRenderer::radiance(const Ray& first, Rng& rng) const {
  Vec3 result;
  Vec3 throughput{1, 1, 1};
  Ray ray = first;
  for (int event = 0; event < m_options.max_path_events; ++event) {
    const std::optional<Hit> hit = m_scene->intersect(ray);
    if (!hit) {
      result += mul(throughput, escaped(normalize(ray.direction)));
      break;
    }
    const Material& material = (*m_materials)[static_cast<std::size_t>(hit->material)];
    if (!hit->front_face && material.absorbs_inside()) {
      // The segment ran inside the dielectric: Beer-Lambert, as the photon tracer does.
      const Vec3 tpm = material.interior_transmittance_per_m();
      throughput = mul(throughput, {std::pow(tpm.x, hit->t), std::pow(tpm.y, hit->t), std::pow(tpm.z, hit->t)});
    }
    // The side the ray arrives on: reflected light leaves toward the camera from there.
    const Vec3 side = hit->front_face ? hit->normal : hit->normal * -1.0;
    const Vec3 rho_d = material.diffuse_reflectance();
    const Vec3 tau_d = material.diffuse_transmittance();
    if (max_component(rho_d) > 0)
      result += mul(mul(throughput, rho_d), surface_irradiance(*hit, side, rng)) * (1.0 / Pi);
    if (max_component(tau_d) > 0)
      result += mul(mul(throughput, tau_d), surface_irradiance(*hit, side * -1.0, rng)) * (1.0 / Pi);
    // Specular and glossy parts: continue the path.
    const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    const std::optional<ScatterSample> s = material.sample(ray.direction, hit->normal, u0, u1, u2);
    if (!s) break;
    if (s->delta) {
      throughput = mul(throughput, s->weight);
    } else {
      const double pdf = material.pdf(ray.direction, s->direction, hit->normal);
      if (!(pdf > 0)) break;
      const bool reflected = dot(s->direction, side) > 0;
      const Vec3 f_diffuse = (reflected ? rho_d : tau_d) * (1.0 / Pi);
      const Vec3 f = material.eval(ray.direction, s->direction, hit->normal);
      const Vec3 glossy = clamp_non_negative(f - f_diffuse);
      // A Lambertian surface leaves f - f_d at rounding level: no glossy part, the path ends.
      if (!(max_component(glossy) > 1e-9 * max_component(f))) break;
      throughput = mul(throughput, glossy) * (std::abs(dot(s->direction, hit->normal)) / pdf);
    }
    if (!(max_component(throughput) > 0)) break;
    ray = Ray{m_scene->offset_ray_origin(hit->position, hit->normal, s->direction), s->direction, 0.0,
              std::numeric_limits<double>::infinity()};
  }
  return result;
}

RenderedImage PhotonRenderer::render(const Camera& camera) const {
  (void)camera.ray_direction(0.5 * camera.width, 0.5 * camera.height);  // validates the camera
  RenderedImage image;
  image.width = camera.width;
  image.height = camera.height;
  const std::size_t pixels = static_cast<std::size_t>(camera.width) * static_cast<std::size_t>(camera.height);
  image.radiance.assign(pixels, Vec3{});
  image.variance.assign(pixels, Vec3{});
  image.inside.assign(pixels, 0);
  const int n = m_options.samples_per_pixel;
  tbb::parallel_for(tbb::blocked_range<int>(0, camera.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < camera.width; ++x) {
        const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(camera.width) + static_cast<std::size_t>(x);
        if (!camera.ray_direction(x + 0.5, y + 0.5)) continue;  // outside the fisheye circle
        image.inside[p] = 1;
        Vec3 sum, sum_sq;
        int taken = 0;
        for (int s = 0; s < n; ++s) {
          Rng rng(m_options.seed, p, static_cast<std::uint64_t>(s), RandomStream::Scattering);
          const double jx = n == 1 ? 0.5 : rng.uniform(), jy = n == 1 ? 0.5 : rng.uniform();
          const std::optional<Vec3> d = camera.ray_direction(x + jx, y + jy);
          Vec3 l;
          if (d) l = radiance(Ray{camera.position_m, *d, 0.0, std::numeric_limits<double>::infinity()}, rng);
          sum += l;
          sum_sq += mul(l, l);
          ++taken;
        }
        const Vec3 mean = sum / static_cast<double>(taken);
        image.radiance[p] = mean;
        if (taken > 1)
          image.variance[p] = clamp_non_negative((sum_sq - mul(mean, mean) * static_cast<double>(taken)) /
                                                 (static_cast<double>(taken) * (taken - 1)));
      }
  });
  return image;
}

}  // namespace dayphoton::engine
