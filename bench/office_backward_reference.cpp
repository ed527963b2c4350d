// Independent check of the office's daylight coefficients: brute-force BACKWARD Monte Carlo,
// the method of RADIANCE's rcontrib (refdata b_dc_classic), on dayphoton's own scene and
// materials but without photons, kernels or the direct component's shadow rays.
//
// From each sensor, cosine-distributed paths scatter through the room by the materials'
// sample() (all materials of the office are reciprocal: Lambertian surfaces and thin glass,
// whose straight transmission and reflection are the same both ways); a path leaving the
// scene adds pi x its throughput to the bin it escapes through (PatchBasis::find_bin,
// ground bin 0 below the horizon), i.e. irradiance per unit bin radiance, the coefficient's
// definition. Russian roulette on the throughput after the second event keeps it unbiased.
// This is the estimator of seeds/000 section 3.1 (path tracing) with no next-event estimate.
//
// Usage: office_backward_reference [paths_per_sensor=200000] [first_row=13] [last_row=14]
//                                  [our_coefficients=projects/office/results/workplane/coefficients_sky.mtx]
//                                  [write_matrix=FILE]
// Rows are the office grid's 15 rows (y = 0.5 + 0.5 r m). For the chosen rows it prints, with
// RADIANCE's CIE overcast sky vector, the mean DF of this estimate (with its standard error),
// of our photon-map coefficients, of RADIANCE's rfluxmtx matrix and of rtrace, then the
// same per 12-degree sky band, so that a difference can be placed in the sky. With all rows
// (0 14) and write_matrix, it writes its coefficients as a 165 x 146 RADIANCE matrix, which
// `dayphoton annual --coefficients` turns into annual metrics like any exported matrix
// (scripts/validate_office.py --backward FILE compares those with RADIANCE's).
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "../tests/reference_data.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/random.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"

using namespace dayphoton;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Cosine-weighted direction about `n` from two uniforms (Malley's method).
Vec3 cosine_direction(const Vec3& n, double u1, double u2) {
  const double r = std::sqrt(u1), phi = 2 * kPi * u2;
  const Vec3 a = std::fabs(n.x) > 0.5 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  const Vec3 t = normalize(cross(a, n));
  const Vec3 b = cross(n, t);
  return normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(1 - u1));
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t paths = argc > 1 ? std::stoul(argv[1]) : 200000;
  const int first_row = argc > 2 ? std::stoi(argv[2]) : 13;
  const int last_row = argc > 3 ? std::stoi(argv[3]) : 14;
  const std::string source_dir = DAYPHOTON_BENCH_SOURCE_DIR;
  const std::string ours_path =
      argc > 4 ? argv[4] : source_dir + "/projects/office/results/workplane/coefficients_sky.mtx";
  const std::string shared = source_dir + "/../shared";
  const std::string write_path = argc > 5 ? argv[5] : "";

  const project::Project proj = project::load_project(source_dir + "/projects/office/project.yaml");
  const SceneDescription description = project::build_scene_description(proj);
  const engine::Scene scene = engine::Scene::build(description);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : description.materials) materials.push_back(engine::Material::from_spec(m));
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  const std::size_t bins = std::size_t(basis.bin_count());
  const SensorGrid& grid = description.grids.at(0);
  const std::size_t columns = 11;  // the office grid: 11 sensors per row, 15 rows

  std::vector<std::size_t> sensors;
  for (int r = first_row; r <= last_row; ++r)
    for (std::size_t c = 0; c < columns; ++c) sensors.push_back(std::size_t(r) * columns + c);

  // RADIANCE's overcast sky vector (gensky -c -B 55.866 -g 0.2 | genskyvec -m 1), photometric.
  const RadianceMatrix sv = RadianceMatrix::read_file(shared + "/refdata/results/a_daylight_factor/skyvec_overcast_m1.vec");
  std::vector<Vec3> sky_rgb(bins);
  for (std::size_t p = 0; p < bins; ++p) sky_rgb[p] = {sv.at(p, 0, 0), sv.at(p, 0, 1), sv.at(p, 0, 2)};

  // Per sensor: per-bin sums of pi x throughput, and the DF estimate's first two moments.
  std::vector<Vec3> coeff(sensors.size() * bins, Vec3{0, 0, 0});
  std::vector<double> df_sum(sensors.size(), 0), df_sum2(sensors.size(), 0);
  std::atomic<std::uint64_t> rays{0};
  const auto t0 = Clock::now();
  tbb::parallel_for(std::size_t(0), sensors.size(), [&](std::size_t k) {
    const SensorPoint& sp = grid.points[sensors[k]];
    std::uint64_t local_rays = 0;
    for (std::size_t i = 0; i < paths; ++i) {
      engine::Rng rng(7, sensors[k], i, engine::RandomStream::Scattering);
      Vec3 w{1, 1, 1};
      engine::Ray ray{sp.position, cosine_direction(sp.normal, rng.uniform(), rng.uniform())};
      double x = 0;
      for (int depth = 0; depth < 1000; ++depth) {
        ++local_rays;
        const std::optional<engine::Hit> hit = scene.intersect(ray);
        if (!hit) {
          const int bin = basis.find_bin(ray.direction);
          coeff[k * bins + std::size_t(bin)] = coeff[k * bins + std::size_t(bin)] + w * kPi;
          x = kPi * rgb_to_photometric(mul(w, sky_rgb[std::size_t(bin)]));
          break;
        }
        const auto s = materials[std::size_t(hit->material)].sample(ray.direction, hit->normal, rng.uniform(),
                                                                    rng.uniform(), rng.uniform());
        if (!s) break;
        w = mul(w, s->weight);
        if (depth >= 2) {  // roulette on the throughput: survive with q, divide by q
          const double q = std::min(1.0, std::max(w.x, std::max(w.y, w.z)));
          if (rng.uniform() >= q) break;
          w = w * (1 / q);
        }
        ray = engine::Ray{scene.offset_ray_origin(hit->position, hit->normal, s->direction), s->direction};
      }
      df_sum[k] += x;
      df_sum2[k] += x * x;
    }
    rays += local_rays;
  });
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();

  if (!write_path.empty()) {
    RadianceMatrix out(grid.points.size(), bins, 3);
    for (std::size_t k = 0; k < sensors.size(); ++k)
      for (std::size_t p = 0; p < bins; ++p)
        for (int c = 0; c < 3; ++c)
          out.at(sensors[k], p, c) = float(coeff[k * bins + p][c] / double(paths));
    out.header_lines().push_back("office_backward_reference " + std::to_string(paths) + " paths per sensor, rows " +
                                 std::to_string(first_row) + "-" + std::to_string(last_row));
    out.write_file(write_path, MatrixFormat::Float);
  }
  const std::vector<double> ref = test::read_reference_df(shared + "/refdata/results/a_daylight_factor/df_office.csv");
  const RadianceMatrix dc = test::read_gzip_matrix(shared + "/refdata/results/b_dc_classic/office_dc_classic.mtx.gz");
  const RadianceMatrix dc2 = test::read_gzip_matrix(shared + "/refdata/results/b_dc_classic/office_dc_classic_ad131k.mtx.gz");
  const RadianceMatrix ours = RadianceMatrix::read_file(ours_path);
  auto matrix_df = [&](const RadianceMatrix& m, std::size_t s, std::size_t p0, std::size_t p1) {
    double e = 0;
    for (std::size_t p = p0; p < p1; ++p)
      e += rgb_to_photometric(mul(Vec3{m.at(s, p, 0), m.at(s, p, 1), m.at(s, p, 2)}, sky_rgb[p]));
    return e / 10000 * 100;  // the vector is for 10 000 lux horizontal: DF in %
  };

  std::printf("office backward reference: %zu paths per sensor, rows %d-%d (%zu sensors), %.1f s, %.3g rays/s\n",
              paths, first_row, last_row, sensors.size(), seconds, double(rays) / seconds);
  std::printf("row  y(m)   backward DF %% (+-1 se)   ours/bw   rfluxmtx65k/bw  rfluxmtx131k/bw  rtrace/bw\n");
  for (int r = first_row; r <= last_row; ++r) {
    double bw = 0, var = 0, o = 0, a = 0, a2 = 0, rt = 0;
    for (std::size_t k = 0; k < sensors.size(); ++k) {
      if (sensors[k] / columns != std::size_t(r)) continue;
      const std::size_t s = sensors[k];
      const double mean = df_sum[k] / double(paths);
      const double v = (df_sum2[k] / double(paths) - mean * mean) / double(paths);
      bw += mean / 100;  // lux -> DF %
      var += v / 1e4;
      o += matrix_df(ours, s, 0, bins);
      a += matrix_df(dc, s, 0, bins);
      a2 += matrix_df(dc2, s, 0, bins);
      rt += ref[s];
    }
    std::printf("%3d  %4.1f   %8.4f (+-%.4f)     %.4f    %.4f          %.4f           %.4f\n", r,
                0.5 + 0.5 * r, bw / double(columns), std::sqrt(var) / double(columns), o / bw, a / bw, a2 / bw,
                rt / bw);
  }
  // Per 12-degree band (ground, rows 0..6 of the sky, zenith cap), all chosen sensors.
  std::printf("band     share of bw   ours/bw   rfluxmtx65k/bw  rfluxmtx131k/bw\n");
  std::vector<std::pair<std::size_t, std::size_t>> bands{{0, 1}};
  std::size_t next = 1;
  for (int r = 0; r < basis.row_count(); ++r) {
    bands.push_back({next, next + std::size_t(basis.row(r).patch_count)});
    next += std::size_t(basis.row(r).patch_count);
  }
  double total = 0;
  for (std::size_t k = 0; k < sensors.size(); ++k)
    for (std::size_t p = 0; p < bins; ++p) total += rgb_to_photometric(mul(coeff[k * bins + p], sky_rgb[p])) / double(paths);
  for (std::size_t b = 0; b < bands.size(); ++b) {
    double bw = 0, o = 0, a = 0, a2 = 0;
    for (std::size_t k = 0; k < sensors.size(); ++k) {
      for (std::size_t p = bands[b].first; p < bands[b].second; ++p)
        bw += rgb_to_photometric(mul(coeff[k * bins + p], sky_rgb[p])) / double(paths);
      o += matrix_df(ours, sensors[k], bands[b].first, bands[b].second);
      a += matrix_df(dc, sensors[k], bands[b].first, bands[b].second);
      a2 += matrix_df(dc2, sensors[k], bands[b].first, bands[b].second);
    }
    bw /= 100;  // DF %
    const std::string name = b == 0 ? "ground" : "sky row " + std::to_string(b - 1);
    std::printf("%-9s  %6.1f %%     %.4f    %.4f          %.4f\n", name.c_str(), 100 * bw * 100 / total, o / bw,
                a / bw, a2 / bw);
  }
  return 0;
}
