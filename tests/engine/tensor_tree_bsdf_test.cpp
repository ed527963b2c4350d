// The tensor-tree BSDF (engine/src/tensor_tree_bsdf.h) through the `bsdf` material
// (engine::Material, the interface the photon tracer, the direct component and the renderer
// use): a constant tree is the Lambertian diffuser a constant Klems matrix is; samples match
// eval/pdf and the piecewise-constant cell distribution (chi-square over the leaf cells); the
// hemispherical transmittance by quadrature equals albedo() and the sampled mean; a
// redirecting film sends the light where its closed form says; and a smooth analytic BSDF
// written as a Klems matrix and as a tree gives the same hemispherical transmittance within
// each basis' known resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../bsdf_xml_writer.h"
#include "../tensor_tree_xml_writer.h"
#include "dayphoton/core/bsdf_xml.h"
#include "dayphoton/core/shirley_chiu.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/random.h"
#include "material_test_harness.h"

using namespace dayphoton;
using namespace dayphoton::engine;

namespace {

const Vec3 Normal = engine::test::tilted_normal();
const Vec3 Up{0, 0, 1};

struct Local : engine::test::UpLocalFrame {
  explicit Local(const Vec3& n) : UpLocalFrame(Up, n) {}
};

Material tree_material(const std::array<std::string, 4>& trees, const std::string& structure = "TensorTree3") {
  return Material::from_spec(bsdf_material_spec(
      "tt", read_bsdf_xml_text(dayphoton::test::tensor_tree_xml(trees, "LBNL/Shirley-Chiu", structure), "tt.xml"), Up));
}

std::string constant(double f) { return "{ " + dayphoton::test::bsdf_xml_number(f) + " }"; }

// The tree coordinates of local directions d (incoming) and o (outgoing), computed here from
// the documented definition (RADIANCE bsdf_t.c SDqueryTre): u0 = 1/2 - |d.xy| / 2, (u1, u2)
// the Shirley-Chiu square of o turned by -atan2(d.y, d.x).
void tree_coordinates(const Vec3& d, const Vec3& o, double& u0, double& u1, double& u2) {
  u0 = 0.5 - 0.5 * std::sqrt(d.x * d.x + d.y * d.y);
  const double p = std::atan2(d.y, d.x);
  shirley_chiu_disc_to_square(o.x * std::cos(p) + o.y * std::sin(p), -o.x * std::sin(p) + o.y * std::cos(p), u1, u2);
}

}  // namespace

TEST(TensorTreeBsdf, ConstantTreeIsTheLambertianDiffuserOfAConstantKlemsMatrix) {
  // tau / pi and rho / pi per block, as a tree and as a Klems matrix: the same albedo
  // (tau + rho of the side hit, exactly), the same eval, and Lambertian sampling: the
  // harness' chi-square in (cos theta, phi) (the density |cos| A / pi is smooth), and
  // E[|cos theta_o|] = 2/3 with variance 1/2 - 4/9 = 1/18 per sample.
  const Material tree = tree_material({constant(0.6 / Pi), constant(0.5 / Pi), constant(0.25 / Pi), constant(0.1 / Pi)});
  const Material klems = Material::from_spec(bsdf_material_spec(
      "klems",
      std::make_shared<KlemsBsdfData>(dayphoton::test::klems_from(
          KlemsBasis::full(), [](int, int) { return 0.6 / Pi; }, [](int, int) { return 0.5 / Pi; },
          [](int, int) { return 0.25 / Pi; }, [](int, int) { return 0.1 / Pi; })),
      Up));
  std::uint64_t seed = 11;
  for (double theta : {0.0, 40.0, 85.0})
    for (bool back : {false, true}) {
      const Vec3 in = engine::test::incident_direction(Normal, theta, 25.0, back);
      const std::string label = "theta " + std::to_string(int(theta)) + (back ? " back" : " front");
      // WINDOW's front is the side the normal points away from: light moving along the normal.
      EXPECT_NEAR(tree.albedo(in, Normal).x, dot(in, Normal) > 0 ? 0.85 : 0.6, 1e-7) << label;
      EXPECT_NEAR(tree.albedo(in, Normal).x, klems.albedo(in, Normal).x, 1e-7) << label;
      for (double t : {10.0, 50.0, 80.0})
        for (bool flip : {false, true}) {
          const Vec3 out = engine::test::incident_direction(Normal, t, 130.0, flip);
          EXPECT_NEAR(tree.eval(in, out, Normal).x, klems.eval(in, out, Normal).x, 1e-8) << label;
        }
      const engine::test::SamplingReport r = engine::test::measure_sampling(tree, tree, in, Normal, seed++, label, 40000);
      EXPECT_LT(r.max_consistency_error, 1e-9) << label;
      EXPECT_GT(r.p_value, 1e-3) << label << " chi2 " << r.chi2 << " dof " << r.dof;
      EXPECT_NEAR(r.mean_weight.x, r.albedo.x, 4 * r.weight_sigma_of_mean.x + 1e-12) << label;
      const int n = 40000;
      double sum = 0;
      for (int k = 0; k < n; ++k) {
        Rng rng(5, seed, static_cast<std::uint64_t>(k), RandomStream::Scattering);
        const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        const std::optional<ScatterSample> s = tree.sample(in, Normal, u0, u1, u2);
        ASSERT_TRUE(s);
        sum += std::fabs(dot(s->direction, Normal));
      }
      EXPECT_NEAR(sum / n, 2.0 / 3.0, 4 * std::sqrt(1.0 / 18.0 / n)) << label;
    }
}

namespace {
// A structured tree, one leaf of 8 x 8 x 8 cells per block; T + R < 1 everywhere.
double tf(double u0, double u1, double u2) { return (0.2 + 0.6 * u1 * u2 + 0.2 * u0) / Pi; }
double tb(double u0, double u1, double u2) { return (0.1 + 0.5 * u1 * (1 - u2) + 0.3 * u0) / Pi; }
double rf(double, double u1, double) { return (0.05 + 0.2 * (1 - u1)) / Pi; }
double rb(double u0, double, double u2) { return (0.1 * u0 + 0.2 * u2) / Pi; }
double cell_centre(double u) { return (std::floor(std::min(u, 1 - 1e-12) * 8) + 0.5) / 8; }
}  // namespace

TEST(TensorTreeBsdf, SamplesMatchEvalPdfTheCellDistributionAndTheQuadrature) {
  using dayphoton::test::tensor_tree_leaf;
  const Material m = tree_material({tensor_tree_leaf(3, tf), tensor_tree_leaf(3, tb), tensor_tree_leaf(3, rf),
                                    tensor_tree_leaf(3, rb)});
  const Local frame(Normal);
  const int samples = 40000;
  std::uint64_t case_index = 0;
  for (double theta : {0.0, 27.0, 58.0, 84.0})
    for (bool back : {false, true}) {
      const Vec3 in = engine::test::incident_direction(Normal, theta, 40.0 + 50 * theta, back);
      const std::string label = "theta " + std::to_string(int(theta)) + (back ? " back" : " front");
      const Vec3 d = frame.to_local(in);
      const bool front = d.z > 0;  // moving along the normal: WINDOW's front
      double (*t)(double, double, double) = front ? tf : tb;
      double (*r)(double, double, double) = front ? rf : rb;
      const double u0 = cell_centre(std::min(0.5 - 0.5 * std::sqrt(d.x * d.x + d.y * d.y), 0.5 - 1e-12));
      // Closed form: each of the 64 cells of the square has projected solid angle pi / 64.
      std::vector<double> expected(128);
      double a = 0, tt = 0;
      for (int c = 0; c < 64; ++c) {
        const double u1 = (c / 8 + 0.5) / 8, u2 = (c % 8 + 0.5) / 8;
        expected[static_cast<std::size_t>(c)] = t(u0, u1, u2) * Pi / 64;
        expected[static_cast<std::size_t>(64 + c)] = r(u0, u1, u2) * Pi / 64;
        tt += expected[static_cast<std::size_t>(c)];
        a += expected[static_cast<std::size_t>(c)] + expected[static_cast<std::size_t>(64 + c)];
      }
      EXPECT_NEAR(m.albedo(in, Normal).x, a, 1e-6) << label;
      // eval() at scattered directions against the closed form at the tree coordinates
      // computed here (the outgoing direction turned by the incident azimuth).
      for (int q = 0; q < 200; ++q) {
        Rng rng(3, case_index, static_cast<std::uint64_t>(q), RandomStream::Scattering);
        const double cz = 2 * rng.uniform() - 1, ph = 2 * Pi * rng.uniform(), sz = std::sqrt(1 - cz * cz);
        const Vec3 o{sz * std::cos(ph), sz * std::sin(ph), cz};
        double w0 = 0, w1 = 0, w2 = 0;
        tree_coordinates(d, o, w0, w1, w2);
        const double expected_f = ((o.z > 0) == front ? t : r)(u0, cell_centre(w1), cell_centre(w2));
        EXPECT_NEAR(m.eval(in, frame.world(o), Normal).x, expected_f, 1e-6) << label << " " << q;
      }
      // Quadrature through eval(): a 64 x 64 midpoint rule over the square of each
      // hemisphere (exact for cells of 1/8: every midpoint is inside one cell).
      double quad_t = 0, quad_a = 0;
      for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
          double x = 0, y = 0;
          shirley_chiu_square_to_disc((i + 0.5) / 64, (j + 0.5) / 64, x, y);
          const double z = std::sqrt(std::max(0.0, 1 - x * x - y * y));
          for (double s : {1.0, -1.0}) {
            const double f = m.eval(in, frame.world({x, y, s * z}), Normal).x * Pi / 4096;
            quad_a += f;
            if ((s > 0) == (d.z > 0)) quad_t += f;
          }
        }
      EXPECT_NEAR(quad_a, a, 1e-6) << label;
      EXPECT_NEAR(quad_t, tt, 1e-6) << label;
      std::vector<double> counts(128, 0.0);
      double weight_t = 0, weight_t2 = 0;
      for (int k = 0; k < samples; ++k) {
        Rng rng(9, case_index, static_cast<std::uint64_t>(k), RandomStream::Scattering);
        const double v0 = rng.uniform(), v1 = rng.uniform(), v2 = rng.uniform();
        const std::optional<ScatterSample> s = m.sample(in, Normal, v0, v1, v2);
        ASSERT_TRUE(s);
        const double pdf = m.pdf(in, s->direction, Normal);
        ASSERT_GT(pdf, 0) << label;
        const double cos_o = std::fabs(dot(s->direction, Normal));
        ASSERT_NEAR(s->weight.x, m.eval(in, s->direction, Normal).x * cos_o / pdf, 1e-9 * s->weight.x) << label;
        ASSERT_NEAR(s->weight.x, a, 1e-6) << label;
        const bool transmitted = s->type == ScatterType::GlossyTransmission;
        ASSERT_EQ(transmitted, (dot(s->direction, Normal) > 0) == (dot(in, Normal) > 0)) << label;
        double w0 = 0, w1 = 0, w2 = 0;
        tree_coordinates(d, frame.to_local(s->direction), w0, w1, w2);
        const int c = std::min(7, int(w1 * 8)) * 8 + std::min(7, int(w2 * 8));
        counts[static_cast<std::size_t>(transmitted ? c : 64 + c)] += 1;
        const double wt = transmitted ? s->weight.x : 0.0;
        weight_t += wt;
        weight_t2 += wt * wt;
      }
      double chi2 = 0;
      int cells = 0;
      for (std::size_t c = 0; c < 128; ++c) {
        const double e = samples * expected[c] / a;
        if (e < 5) continue;  // none here: every cell expects > 5
        chi2 += (counts[c] - e) * (counts[c] - e) / e;
        ++cells;
      }
      EXPECT_EQ(cells, 128) << label;
      EXPECT_GT(engine::test::chi2_p_value(chi2, cells - 1), 1e-3) << label << " chi2 " << chi2;
      // The sampled directional-hemispherical transmittance (mean transmitted weight) against
      // the quadrature, within 4 sigma of its own spread.
      const double mean = weight_t / samples, var = weight_t2 / samples - mean * mean;
      EXPECT_NEAR(mean, quad_t, 4 * std::sqrt(var / samples)) << label;
      ++case_index;
    }
}

TEST(TensorTreeBsdf, RedirectingFilmSendsLightWhereTheClosedFormSays) {
  // A film that turns transmitted light up by delta = 20 degrees in its plane of incidence:
  // incidence at theta_i (d along +x after the azimuth fold) leaves along
  // o* = (sin(theta_i - delta), 0, cos(theta_i - delta)), 80 % of it. Written as one leaf of
  // 32^3 cells: f = 0.8 / (pi s^2) in the cell of o* for the incident cell's centre, 0
  // elsewhere. Every transmitted sample must lie in that cell's pre-image (within the disc
  // distance of the cell's farthest corner from o*'s disc point), the transmittance must be
  // 0.8, and the mean outgoing polar angle theta_i - delta within the cell's extent.
  const int l = 5, n = 1 << l;
  const double delta = deg_to_rad(20.0), s = 1.0 / n;
  auto target = [&](double u0, double& u1, double& u2) {
    const double theta_i = std::asin(std::max(0.0, 1 - 2 * u0));
    shirley_chiu_disc_to_square(std::sin(theta_i - delta), 0.0, u1, u2);
  };
  auto film = [&](double u0, double u1, double u2) {
    double t1 = 0, t2 = 0;
    target(u0, t1, t2);
    return int(t1 * n) == int(u1 * n) && int(t2 * n) == int(u2 * n) ? 0.8 / (Pi * s * s) : 0.0;
  };
  const Material m = tree_material({dayphoton::test::tensor_tree_leaf(l, film), constant(0.1 / Pi),
                                    constant(0.05 / Pi), constant(0.05 / Pi)});
  const Local frame(Normal);
  int checked = 0;
  for (int k : {3, 6, 9, 12})
    for (double phi_deg : {0.0, 70.0, 200.0}) {
      const double u0 = (k + 0.5) / n;  // an incident cell's centre
      const double theta_i = std::asin(1 - 2 * u0);
      const double phi = deg_to_rad(phi_deg);
      const Vec3 d{std::sin(theta_i) * std::cos(phi), std::sin(theta_i) * std::sin(phi), std::cos(theta_i)};
      const Vec3 in = frame.world(d);
      double t1 = 0, t2 = 0;
      target(u0, t1, t2);
      // The target cell's corners on the disc, turned back by phi: the farthest from o*.
      double x0 = 0, y0 = 0;
      shirley_chiu_square_to_disc(t1, t2, x0, y0);
      double reach = 0;
      for (int corner = 0; corner < 4; ++corner) {
        double x = 0, y = 0;
        shirley_chiu_square_to_disc((std::floor(t1 * n) + (corner & 1)) * s, (std::floor(t2 * n) + (corner >> 1)) * s, x, y);
        reach = std::max(reach, std::hypot(x - x0, y - y0));
      }
      const Vec3 o_star{std::sin(theta_i - delta) * std::cos(phi), std::sin(theta_i - delta) * std::sin(phi),
                        std::cos(theta_i - delta)};
      const double a = m.albedo(in, Normal).x;
      EXPECT_NEAR(a, 0.8 + 0.05, 1e-6);
      {  // eval at the target cell's centre (o* itself lies on a cell edge: y = 0)
        double cx = 0, cy = 0;
        shirley_chiu_square_to_disc((std::floor(t1 * n) + 0.5) * s, (std::floor(t2 * n) + 0.5) * s, cx, cy);
        const Vec3 centre{cx * std::cos(phi) - cy * std::sin(phi), cx * std::sin(phi) + cy * std::cos(phi),
                          std::sqrt(1 - cx * cx - cy * cy)};
        EXPECT_NEAR(m.eval(in, frame.world(centre), Normal).x, 0.8 / (Pi * s * s), 1e-3) << k << " " << phi_deg;
      }
      const int samples = 4000;
      int transmitted = 0;
      double theta_sum = 0;
      for (int i = 0; i < samples; ++i) {
        Rng rng(13, static_cast<std::uint64_t>(checked), static_cast<std::uint64_t>(i), RandomStream::Scattering);
        const double v0 = rng.uniform(), v1 = rng.uniform(), v2 = rng.uniform();
        const std::optional<ScatterSample> smp = m.sample(in, Normal, v0, v1, v2);
        ASSERT_TRUE(smp);
        if (smp->type != ScatterType::GlossyTransmission) continue;
        ++transmitted;
        const Vec3 o = frame.to_local(smp->direction);
        ASSERT_LE(std::hypot(o.x - o_star.x, o.y - o_star.y), reach + 1e-9) << k << " " << phi_deg;
        theta_sum += std::acos(o.z);
      }
      const double p = 0.8 / a;
      EXPECT_NEAR(double(transmitted) / samples, p, 4 * std::sqrt(p * (1 - p) / samples));
      // The cell spans at most `reach` on the disc; |d theta| <= reach / cos(theta) there.
      EXPECT_NEAR(theta_sum / transmitted, std::fabs(theta_i - delta), reach / std::cos(std::fabs(theta_i - delta) + reach))
          << k << " " << phi_deg;
      ++checked;
    }
  EXPECT_EQ(checked, 12);
}

TEST(TensorTreeBsdf, KlemsAndTreeAgreeOnHemisphericalTransmittanceWithinTheirResolution) {
  // f_T = c (1 + k cos theta_o), the same both sides; f_R = 0.05 / pi. Closed form:
  // T = c (pi + 2 pi k / 3). The Klems matrix holds f at each patch's ring middle, the tree at
  // each cell's centre; each sum differs from the integral by at most
  // c k sum_cells Omega_cell max |cos - cos_centre| over the cell (the basis' blur), computed
  // here for both bases, so the two agree within the sum of the two bounds.
  const double c = 0.1, k = 1.5;
  const double closed = c * (Pi + 2 * Pi * k / 3);
  const KlemsBasis basis = KlemsBasis::full();
  auto klems_f = [&](int, int o) { return c * (1 + k * std::cos(basis.centre_theta_rad(o))); };
  const Material klems = Material::from_spec(bsdf_material_spec(
      "klems",
      std::make_shared<KlemsBsdfData>(dayphoton::test::klems_from(basis, klems_f, klems_f, [](int, int) { return 0.05 / Pi; },
                                                                  [](int, int) { return 0.05 / Pi; })),
      Up));
  double klems_bound = 0;
  for (int j = 0; j < basis.size(); ++j) {
    const KlemsRing& ring = basis.rings()[static_cast<std::size_t>(basis.ring_of(j))];
    const double cc = std::cos(basis.centre_theta_rad(j));
    klems_bound += basis.projected_solid_angle(j) * c * k *
                   std::max(std::cos(ring.lower_theta_rad) - cc, cc - std::cos(ring.upper_theta_rad));
  }
  const int l = 5, n = 1 << l;
  auto cos_of_square = [](double u1, double u2) {
    double x = 0, y = 0;
    shirley_chiu_square_to_disc(u1, u2, x, y);
    return std::sqrt(std::max(0.0, 1 - x * x - y * y));
  };
  auto tree_f = [&](double, double u1, double u2) { return c * (1 + k * cos_of_square(u1, u2)); };
  const Material tree = tree_material({dayphoton::test::tensor_tree_leaf(l, tree_f), dayphoton::test::tensor_tree_leaf(l, tree_f),
                                       constant(0.05 / Pi), constant(0.05 / Pi)});
  // On the square, the disc radius is max(|a|, |b|) (a = 2u - 1, b = 2v - 1): its range over
  // a cell gives the range of cos.
  double tree_bound = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a0 = 2.0 * i / n - 1, a1 = 2.0 * (i + 1) / n - 1, b0 = 2.0 * j / n - 1, b1 = 2.0 * (j + 1) / n - 1;
      auto min_abs = [](double lo, double hi) { return lo < 0 && hi > 0 ? 0.0 : std::min(std::fabs(lo), std::fabs(hi)); };
      const double r_min = std::max(min_abs(a0, a1), min_abs(b0, b1));
      const double r_max = std::max(std::max(std::fabs(a0), std::fabs(a1)), std::max(std::fabs(b0), std::fabs(b1)));
      const double cc = cos_of_square((i + 0.5) / n, (j + 0.5) / n);
      const double spread = std::max(std::sqrt(1 - r_min * r_min) - cc, cc - std::sqrt(std::max(0.0, 1 - r_max * r_max)));
      tree_bound += Pi / (n * n) * c * k * spread;
    }
  for (double theta : {0.0, 30.0, 60.0, 80.0})
    for (bool back : {false, true}) {
      const Vec3 in = engine::test::incident_direction(Normal, theta, 15.0, back);
      const double t_tree = tree.albedo(in, Normal).x - 0.05, t_klems = klems.albedo(in, Normal).x - 0.05;
      EXPECT_NEAR(t_klems, closed, klems_bound) << theta;
      EXPECT_NEAR(t_tree, closed, tree_bound) << theta;
      EXPECT_NEAR(t_tree, t_klems, klems_bound + tree_bound) << theta;
    }
  // The bounds are the bases' resolutions: the tree's (1/32 cells) is the finer.
  EXPECT_LT(tree_bound, klems_bound);
}

namespace {
// An anisotropic tree: one TensorTree4 leaf of 4^4 cells per transmission block.
double tf4(double u0, double u1, double u2, double u3) { return (0.1 + 0.4 * u0 * u2 + 0.2 * u1 * (1 - u3)) / Pi; }
double rf4(double, double, double, double u3) { return (0.05 + 0.1 * u3) / Pi; }
double tb4(double, double u1, double u2, double) { return (0.2 + 0.2 * u1 * u2) / Pi; }
double quarter_centre(double u) { return (std::floor(std::min(u, 1 - 1e-12) * 4) + 0.5) / 4; }
}  // namespace

TEST(TensorTreeBsdf, AnisotropicTreeFollowsItsClosedFormAtEveryAzimuth) {
  // TensorTree4 (RADIANCE bsdf_t.c SDqueryTre, ndim 4): (u0, u1) the Shirley-Chiu square of
  // the incoming propagation direction's (x, y), (u2, u3) the outgoing direction's, no
  // azimuth fold. Computed here from that definition: albedo() is the sum over the 16
  // outgoing cells of f pi / 16 at the incident cell's centre (different per azimuth), eval()
  // the closed form at scattered directions, samples weigh A and fill the 32 cells
  // (transmitted, reflected) by chi-square.
  using dayphoton::test::tensor_tree_leaf4;
  const Material m = tree_material({tensor_tree_leaf4(2, tf4), tensor_tree_leaf4(2, tb4), tensor_tree_leaf4(2, rf4),
                                    constant(0.05 / Pi)},
                                   "TensorTree4");
  const Local frame(Normal);
  const int samples = 20000;
  std::uint64_t case_index = 0;
  std::vector<double> albedos;
  for (double theta : {20.0, 55.0})
    for (double phi : {10.0, 100.0, 190.0, 280.0})
      for (bool back : {false, true}) {
        const Vec3 in = engine::test::incident_direction(Normal, theta, phi, back);
        const std::string label = "theta " + std::to_string(int(theta)) + " phi " + std::to_string(int(phi)) + (back ? " back" : " front");
        const Vec3 d = frame.to_local(in);
        const bool front = d.z > 0;
        double a0 = 0, a1 = 0;
        shirley_chiu_disc_to_square(d.x, d.y, a0, a1);
        a0 = quarter_centre(a0);
        a1 = quarter_centre(a1);
        auto f = [&](bool transmitted, double u2, double u3) {
          if (front) return transmitted ? tf4(a0, a1, u2, u3) : rf4(a0, a1, u2, u3);
          return transmitted ? tb4(a0, a1, u2, u3) : 0.05 / Pi;
        };
        std::vector<double> expected(32);
        double a = 0;
        for (int c = 0; c < 32; ++c) {
          expected[static_cast<std::size_t>(c)] = f(c < 16, ((c % 16) / 4 + 0.5) / 4, (c % 4 + 0.5) / 4) * Pi / 16;
          a += expected[static_cast<std::size_t>(c)];
        }
        EXPECT_NEAR(m.albedo(in, Normal).x, a, 1e-6) << label;
        albedos.push_back(a);
        for (int q = 0; q < 100; ++q) {
          Rng rng(17, case_index, static_cast<std::uint64_t>(q), RandomStream::Scattering);
          const double cz = 2 * rng.uniform() - 1, ph = 2 * Pi * rng.uniform(), sz = std::sqrt(1 - cz * cz);
          const Vec3 o{sz * std::cos(ph), sz * std::sin(ph), cz};
          double u2 = 0, u3 = 0;
          shirley_chiu_disc_to_square(o.x, o.y, u2, u3);
          EXPECT_NEAR(m.eval(in, frame.world(o), Normal).x, f((o.z > 0) == front, quarter_centre(u2), quarter_centre(u3)), 1e-6)
              << label << " " << q;
        }
        std::vector<double> counts(32, 0.0);
        for (int k = 0; k < samples; ++k) {
          Rng rng(19, case_index, static_cast<std::uint64_t>(k), RandomStream::Scattering);
          const double v0 = rng.uniform(), v1 = rng.uniform(), v2 = rng.uniform();
          const std::optional<ScatterSample> s = m.sample(in, Normal, v0, v1, v2);
          ASSERT_TRUE(s);
          const double pdf = m.pdf(in, s->direction, Normal);
          ASSERT_GT(pdf, 0) << label;
          ASSERT_NEAR(s->weight.x, m.eval(in, s->direction, Normal).x * std::fabs(dot(s->direction, Normal)) / pdf,
                      1e-9 * s->weight.x);
          ASSERT_NEAR(s->weight.x, a, 1e-6) << label;
          const Vec3 o = frame.to_local(s->direction);
          double u2 = 0, u3 = 0;
          shirley_chiu_disc_to_square(o.x, o.y, u2, u3);
          const int c = std::min(3, int(u2 * 4)) * 4 + std::min(3, int(u3 * 4));
          counts[static_cast<std::size_t>(s->type == ScatterType::GlossyTransmission ? c : 16 + c)] += 1;
        }
        double chi2 = 0;
        for (std::size_t c = 0; c < 32; ++c) {
          const double e = samples * expected[c] / a;
          chi2 += (counts[c] - e) * (counts[c] - e) / e;
        }
        EXPECT_GT(engine::test::chi2_p_value(chi2, 31), 1e-3) << label << " chi2 " << chi2;
        ++case_index;
      }
  // Anisotropic: the front albedo differs between azimuths (the closed form says by how much).
  EXPECT_GT(std::fabs(albedos[0] - albedos[4]), 0.01);
}
