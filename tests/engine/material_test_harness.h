// Checks shared by the material tests (tests/engine/material*_test.cpp), following
// STYLE.md A.10 (b)-(c) (pbrt's Chi2Test, appleseed's check_consistency) and the BRDF
// verification suite of seed 002 (digest of seeds 002-004, section 1.6 and section 4 checks
// #14-#17): for one material and one incident direction, draw N samples and
//   - check each non-delta sample's weight against eval * |cos| / pdf (1e-9 relative),
//   - histogram the non-delta directions in (cos theta, phi) cells about the normal and run a
//     chi-square goodness-of-fit test against pdf() integrated over each cell,
//   - compare the mean weight per channel with albedo() (4 sigma, sigma from the samples).
//
// Chi-square details: 20 x 20 cells (cos theta in [-1, 1], 10 bins per hemisphere; phi in
// [0, 2 pi)), plus one cell for everything that is not a non-delta direction (delta events and
// absorbed samples), whose expected share is 1 - sum of the integrated pdf. Expected counts
// come from an adaptive midpoint rule inside each cell (integrate_cell). Cells expecting fewer than 5 samples are
// pooled, smallest first, until the pool expects at least 5 (pbrt's CHI2_MINFREQ rule). The
// p-value uses the Wilson-Hilferty normal approximation of the chi-square distribution; the
// tests require p > 1e-3. Seeds are fixed, so the outcome is deterministic: 1e-3 is the chance
// that a correct sampler would have failed for a random seed.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/random.h"

namespace dayphoton::engine::test {

/// Orthonormal frame about a unit normal (built independently of the engine's BsdfFrame).
struct TestFrame {
  Vec3 t, b, n;
  explicit TestFrame(const Vec3& normal) : n(normal) {
    const Vec3 helper = std::fabs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    t = normalize(cross(helper, normal));
    b = cross(normal, t);
  }
  Vec3 world(double cos_theta, double phi) const {
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return t * (sin_theta * std::cos(phi)) + b * (sin_theta * std::sin(phi)) + n * cos_theta;
  }
  double phi(const Vec3& v) const {
    const double p = std::atan2(dot(v, b), dot(v, t));
    return p < 0 ? p + 2 * Pi : p;
  }
};

/// A measured BSDF's documented frame (docs/materials.md, "Measured BSDF (Klems)"), built here
/// independently of the engine: z = n, x = up x n (normalised), y = z x x.
struct UpLocalFrame {
  Vec3 x, y, z;
  UpLocalFrame(const Vec3& up, const Vec3& n) : z(n) {
    x = normalize(cross(up, n));
    y = cross(z, x);
  }
  Vec3 to_local(const Vec3& v) const { return {dot(v, x), dot(v, y), dot(v, z)}; }
  Vec3 world(const Vec3& l) const { return x * l.x + y * l.y + z * l.z; }
};

/// A tilted unit normal, so that no test relies on the normal being an axis.
inline Vec3 tilted_normal() { return normalize(Vec3{0.3, -0.5, 0.8}); }

/// Propagation direction of light arriving at `theta_deg` from the normal on the front side
/// (against `normal`) or, with back_side, on the back side.
inline Vec3 incident_direction(const Vec3& normal, double theta_deg, double phi_deg,
                               bool back_side = false) {
  const TestFrame frame(normal);
  const Vec3 from_surface = frame.world(std::cos(deg_to_rad(theta_deg)), deg_to_rad(phi_deg));
  return back_side ? from_surface : -from_surface;
}

/// Upper-tail probability of the chi-square distribution (Wilson-Hilferty approximation).
inline double chi2_p_value(double statistic, int dof) {
  const double k = dof;
  const double a = 2.0 / (9.0 * k);
  const double z = (std::cbrt(statistic / k) - (1.0 - a)) / std::sqrt(a);
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

/// Integral of density(cos_theta, phi) over a (cos theta, phi) cell: a 4 x 4 midpoint rule,
/// compared with the same rule on the four quarter cells; cells whose two estimates differ by
/// more than 1e-8 in probability (1e-3 samples out of 1e5) are split, down to 2^-10 of the
/// cell side. Sharp glossy lobes need this: a fixed grid misses them near the mirror direction.
template <class Density>
double midpoint_4x4(const Density& density, double c0, double c1, double p0, double p1) {
  double sum = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      sum += density(c0 + (c1 - c0) * (a + 0.5) / 4, p0 + (p1 - p0) * (b + 0.5) / 4);
  return sum * (c1 - c0) * (p1 - p0) / 16;
}

template <class Density>
double integrate_cell(const Density& density, double c0, double c1, double p0, double p1,
                      int depth, double coarse = -1) {
  if (coarse < 0) coarse = midpoint_4x4(density, c0, c1, p0, p1);
  const double cm = 0.5 * (c0 + c1), pm = 0.5 * (p0 + p1);
  const double q[4] = {midpoint_4x4(density, c0, cm, p0, pm), midpoint_4x4(density, cm, c1, p0, pm),
                       midpoint_4x4(density, c0, cm, pm, p1), midpoint_4x4(density, cm, c1, pm, p1)};
  const double fine = q[0] + q[1] + q[2] + q[3];
  if (std::fabs(fine - coarse) < 1e-8 || depth >= 10) return fine;
  return integrate_cell(density, c0, cm, p0, pm, depth + 1, q[0]) +
         integrate_cell(density, cm, c1, p0, pm, depth + 1, q[1]) +
         integrate_cell(density, c0, cm, pm, p1, depth + 1, q[2]) +
         integrate_cell(density, cm, c1, pm, p1, depth + 1, q[3]);
}

struct SamplingReport {
  int samples = 0;
  int delta = 0;
  int absorbed = 0;
  Vec3 mean_weight, weight_sigma_of_mean, albedo;
  double chi2 = 0;
  int dof = 0;
  double p_value = 1;
  double max_consistency_error = 0;  ///< relative |weight - eval cos / pdf|
};

/// Draws `samples` events from `material` and measures them against the eval/pdf/albedo of
/// `model` (the same material for the real checks; a different one for the negative
/// controls that show the chi-square test can fail). Records no expectations itself except
/// unit-length directions.
inline SamplingReport measure_sampling(const Material& material, const Material& model,
                                       const Vec3& incoming, const Vec3& normal,
                                       std::uint64_t seed, const std::string& label,
                                       int samples) {
  constexpr int CosBins = 20, PhiBins = 20;
  const TestFrame frame(normal);
  Rng rng(seed, 0, 0, RandomStream::Scattering);
  std::vector<double> observed(CosBins * PhiBins + 1, 0.0);
  const int other_cell = CosBins * PhiBins;
  double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
  SamplingReport report;
  report.samples = samples;
  for (int s = 0; s < samples; ++s) {
    const double uc = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    const std::optional<ScatterSample> out = material.sample(incoming, normal, uc, u1, u2);
    if (!out) {
      ++report.absorbed;
      observed[other_cell] += 1;
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      sum[c] += out->weight[c];
      sum2[c] += out->weight[c] * out->weight[c];
    }
    EXPECT_NEAR(length(out->direction), 1.0, 1e-12) << label;
    if (out->delta) {
      ++report.delta;
      observed[other_cell] += 1;
      continue;
    }
    const Vec3 f = model.eval(incoming, out->direction, normal);
    const double density = model.pdf(incoming, out->direction, normal);
    const double cos_o = std::fabs(dot(out->direction, normal));
    for (int c = 0; c < 3; ++c) {
      const double expected = density > 0 ? f[c] * cos_o / density : 0.0;
      const double scale = std::max(std::fabs(expected), 1e-300);
      report.max_consistency_error =
          std::max(report.max_consistency_error, std::fabs(out->weight[c] - expected) / scale);
    }
    const double cos_theta = std::clamp(dot(out->direction, normal), -1.0, 1.0);
    const int ci = std::min(CosBins - 1, static_cast<int>((cos_theta + 1.0) * 0.5 * CosBins));
    const int pi = std::min(PhiBins - 1, static_cast<int>(frame.phi(out->direction) / (2 * Pi) * PhiBins));
    observed[static_cast<std::size_t>(ci * PhiBins + pi)] += 1;
  }
  for (int c = 0; c < 3; ++c) {
    const double mean = sum[c] / samples;
    report.mean_weight[c] = mean;
    const double variance = std::max(0.0, sum2[c] / samples - mean * mean);
    report.weight_sigma_of_mean[c] = std::sqrt(variance / (samples - 1.0));
  }
  report.albedo = model.albedo(incoming, normal);

  // Expected counts: pdf() integrated over each cell adaptively (see integrate_cell).
  std::vector<double> expected(observed.size(), 0.0);
  double total_probability = 0;
  const double dcos = 2.0 / CosBins, dphi = 2 * Pi / PhiBins;
  const auto density = [&](double cos_theta, double phi) {
    return model.pdf(incoming, frame.world(cos_theta, phi), normal);
  };
  for (int ci = 0; ci < CosBins; ++ci)
    for (int pi = 0; pi < PhiBins; ++pi) {
      const double integral = integrate_cell(density, -1.0 + dcos * ci, -1.0 + dcos * (ci + 1),
                                             dphi * pi, dphi * (pi + 1), 0);
      expected[static_cast<std::size_t>(ci * PhiBins + pi)] = integral * samples;
      total_probability += integral;
    }
  expected[other_cell] = std::max(0.0, 1.0 - total_probability) * samples;

  // Pool cells expecting fewer than 5, smallest first.
  std::vector<std::size_t> order(expected.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
  double pool_expected = 0, pool_observed = 0;
  int cells = 0;
  double chi2 = 0;
  for (std::size_t idx : order) {
    if (pool_expected < 5.0) {
      pool_expected += expected[idx];
      pool_observed += observed[idx];
      continue;
    }
    const double d = observed[idx] - expected[idx];
    chi2 += d * d / expected[idx];
    ++cells;
  }
  if (pool_expected > 0) {
    chi2 += (pool_observed - pool_expected) * (pool_observed - pool_expected) / pool_expected;
    ++cells;
  } else if (pool_observed > 0) {
    chi2 = 1e300;  // samples where pdf() says none can be
  }
  report.chi2 = chi2;
  report.dof = std::max(1, cells - 1);
  report.p_value = cells > 1 ? chi2_p_value(chi2, report.dof) : (chi2 > 0 ? 0.0 : 1.0);
  if (std::getenv("DAYPHOTON_TEST_VERBOSE"))  // numbers for docs and reports
    std::printf("%-34s chi2 %8.1f dof %3d p %.3g | E[w] %.5f albedo %.5f sigma %.1e | delta %d absorbed %d\n",
                label.c_str(), chi2, report.dof, report.p_value, report.mean_weight.y,
                report.albedo.y, report.weight_sigma_of_mean.y, report.delta, report.absorbed);
  return report;
}

/// Runs the checks above and reports them with gtest expectations tagged by `label`.
inline SamplingReport check_sampling(const Material& material, const Vec3& incoming,
                                     const Vec3& normal, std::uint64_t seed,
                                     const std::string& label, int samples = 100000) {
  const SamplingReport report =
      measure_sampling(material, material, incoming, normal, seed, label, samples);

  EXPECT_LT(report.max_consistency_error, 1e-9) << label;
  EXPECT_GT(report.p_value, 1e-3) << label << ": chi2 " << report.chi2 << " dof " << report.dof;
  for (int c = 0; c < 3; ++c) {
    // 4 sigma of the sample mean. The 1e-10 absolute term covers zero-variance cases (a pure
    // Lambertian or a mirror, whose weight is the constant albedo): summing 1e5 terms in
    // double precision can drift by up to N * 2^-53 ~ 1e-11 relative.
    EXPECT_NEAR(report.mean_weight[c], report.albedo[c],
                4.0 * report.weight_sigma_of_mean[c] + 1e-10)
        << label << " channel " << c;
    EXPECT_LE(report.albedo[c], 1.0 + 1e-12) << label << " channel " << c;
  }
  return report;
}

/// Helmholtz reciprocity in propagation-direction form: f(d -> o) == f(-o -> -d), for random
/// pairs of directions around `normal`, relative 1e-12.
inline void check_reciprocity(const Material& material, const Vec3& normal, std::uint64_t seed,
                              const std::string& label, int pairs = 2000) {
  const TestFrame frame(normal);
  Rng rng(seed, 0, 1, RandomStream::Scattering);
  for (int k = 0; k < pairs; ++k) {
    const Vec3 d = frame.world(2 * rng.uniform() - 1, 2 * Pi * rng.uniform());
    const Vec3 o = frame.world(2 * rng.uniform() - 1, 2 * Pi * rng.uniform());
    const Vec3 forward = material.eval(d, o, normal);
    const Vec3 backward = material.eval(-o, -d, normal);
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(forward[c], backward[c], 1e-12 * std::max(1.0, std::fabs(forward[c])))
          << label << " pair " << k;
  }
}

inline MaterialSpec make_spec(MaterialType type, Vec3 reflectance = {0, 0, 0},
                              double specularity = 0, double roughness = 0) {
  MaterialSpec spec;
  spec.name = "test";
  spec.type = type;
  spec.reflectance = reflectance;
  spec.specularity = specularity;
  spec.roughness = roughness;
  return spec;
}

}  // namespace dayphoton::engine::test
