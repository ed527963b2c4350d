// The Klems BSDF model (engine/src/klems_bsdf.h): energy (a white furnace per incoming patch),
// sampling against evaluation (weight == eval |cos| / pdf; the outgoing patches' frequencies
// against f Lambda / A by chi-square; the mean weight against the albedo), and orientation
// (which matrix each side uses, the diagonal of a clear pane, the up vector's azimuth).
#include "../../engine/src/klems_bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "../bsdf_xml_writer.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/random.h"
#include "material_test_harness.h"

using namespace dayphoton;
using namespace dayphoton::engine;

namespace {

// A BSDF with structure everywhere: a peak in the straight-through patch, a spread part, and
// sides that differ; T + R < 1 for every incoming patch.
std::shared_ptr<const KlemsBsdfData> structured() {
  const KlemsBasis b = KlemsBasis::full();
  auto peak = [b](double share) {
    return [share, b](int i, int o) {
      return (i == o ? share / b.projected_solid_angle(o) : 0.0) + 0.1 / Pi * (1 + 0.5 * std::sin(o));
    };
  };
  return std::make_shared<KlemsBsdfData>(dayphoton::test::klems_from(
      b, peak(0.5), peak(0.2), [](int i, int o) { return 0.05 / Pi * (1 + ((i + o) % 3)) / 2; },
      [](int, int o) { return o < 20 ? 0.3 / Pi : 0.0; }));
}

const Vec3 Normal = engine::test::tilted_normal();
const Vec3 Up{0, 0, 1};

struct Local : engine::test::UpLocalFrame {
  explicit Local(const Vec3& n) : UpLocalFrame(Up, n) {}
};

}  // namespace

TEST(KlemsBsdf, FurnaceAlbedoIsTheMatrixSumOfTheSideHit) {
  // Per incoming direction: the albedo equals sum_j (T + R)(i, j) Lambda_j of the side the
  // light arrives from (front: moving along the normal, from the side it points away from),
  // i the Klems patch of the propagation direction. A Lambertian diffuser (tau / pi,
  // rho / pi) gives tau + rho exactly.
  const auto d = structured();
  const KlemsBsdf m(d, Up);
  const KlemsBsdf lambertian(std::make_shared<KlemsBsdfData>(dayphoton::test::klems_from(
                                 KlemsBasis::full(), [](int, int) { return 0.6 / Pi; }, [](int, int) { return 0.5 / Pi; },
                                 [](int, int) { return 0.25 / Pi; }, [](int, int) { return 0.1 / Pi; })),
                             Up);
  const Local frame(Normal);
  int checked = 0;
  for (double theta : {0.0, 10.0, 33.0, 62.0, 86.0})
    for (double phi : {0.0, 100.0, 250.0})
      for (bool back : {false, true}) {
        const Vec3 in = engine::test::incident_direction(Normal, theta, phi, back);
        const bool front = dot(in, Normal) > 0;
        const int i = d->basis.patch(frame.to_local(in));
        const double expected = front ? d->hemispherical(d->transmission_front, i) + d->hemispherical(d->reflection_front, i)
                                      : d->hemispherical(d->transmission_back, i) + d->hemispherical(d->reflection_back, i);
        EXPECT_NEAR(m.albedo(in, Normal), expected, 1e-12) << theta << " " << phi << " " << back;
        EXPECT_NEAR(m.transmittance(in, Normal),
                    d->hemispherical(front ? d->transmission_front : d->transmission_back, i), 1e-12);
        EXPECT_LT(m.albedo(in, Normal), 1.0);
        EXPECT_NEAR(lambertian.albedo(in, Normal), front ? 0.85 : 0.6, 1e-12);
        // And the same sum through eval() at a direction inside every outgoing patch.
        double sum = 0;
        for (int j = 0; j < d->basis.size(); ++j)
          for (double s : {1.0, -1.0}) {
            Vec3 l = d->basis.sample(j, 0.3, 0.6);
            l.z *= s;
            sum += m.eval(in, frame.world(l), Normal) * d->basis.projected_solid_angle(j);
          }
        EXPECT_NEAR(sum, expected, 1e-12);
        ++checked;
      }
  EXPECT_EQ(checked, 30);
}

TEST(KlemsBsdf, SamplesMatchEvalPdfAndThePatchDistribution) {
  // For each incident direction, N samples: every weight equals eval |cos| / pdf and the
  // albedo; the frequencies of the (outgoing patch, transmitted or reflected) events match
  // f Lambda / A by chi-square (cells expecting < 5 pooled); the transmitted fraction matches
  // T / A within 4 binomial sigma.
  const auto d = structured();
  const KlemsBsdf m(d, Up);
  const Local frame(Normal);
  const int n = d->basis.size();
  const int samples = 40000;
  int case_index = 0;
  for (double theta : {0.0, 27.0, 58.0, 84.0})
    for (bool back : {false, true}) {
      const Vec3 in = engine::test::incident_direction(Normal, theta, 40.0, back);
      const double a = m.albedo(in, Normal);
      const bool front = dot(in, Normal) > 0;
      const int i = d->basis.patch(frame.to_local(in));
      std::vector<double> counts(static_cast<std::size_t>(2 * n), 0.0), expected(static_cast<std::size_t>(2 * n));
      for (int j = 0; j < n; ++j) {
        const double lambda = d->basis.projected_solid_angle(j);
        expected[static_cast<std::size_t>(j)] =
            samples * d->value(front ? d->transmission_front : d->transmission_back, i, j) * lambda / a;
        expected[static_cast<std::size_t>(n + j)] =
            samples * d->value(front ? d->reflection_front : d->reflection_back, i, j) * lambda / a;
      }
      double transmitted = 0;
      for (int k = 0; k < samples; ++k) {
        Rng rng(7, static_cast<std::uint64_t>(case_index), static_cast<std::uint64_t>(k), RandomStream::Scattering);
        const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        const std::optional<KlemsBsdf::Sample> s = m.sample(in, Normal, u0, u1, u2);
        ASSERT_TRUE(s);
        const double cos_o = std::fabs(dot(s->direction, Normal));
        const double pdf = m.pdf(in, s->direction, Normal);
        ASSERT_GT(pdf, 0);
        ASSERT_NEAR(s->weight, m.eval(in, s->direction, Normal) * cos_o / pdf, 1e-9 * s->weight);
        ASSERT_NEAR(s->weight, a, 1e-12);
        // Transmitted light keeps moving the same way through the surface.
        ASSERT_EQ(s->transmitted, (dot(s->direction, Normal) > 0) == (dot(in, Normal) > 0));
        const int j = d->basis.patch(frame.to_local(s->direction));
        counts[static_cast<std::size_t>(s->transmitted ? j : n + j)] += 1;
        transmitted += s->transmitted;
      }
      // Chi-square with pooling of small cells.
      double chi2 = 0, pool_e = 0, pool_o = 0;
      int cells = 0;
      for (std::size_t c = 0; c < counts.size(); ++c) {
        if (expected[c] < 5) {
          pool_e += expected[c];
          pool_o += counts[c];
          continue;
        }
        chi2 += (counts[c] - expected[c]) * (counts[c] - expected[c]) / expected[c];
        ++cells;
      }
      if (pool_e > 0) {
        chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        ++cells;
      }
      const double p = engine::test::chi2_p_value(chi2, cells - 1);
      EXPECT_GT(p, 1e-3) << "theta " << theta << " back " << back << " chi2 " << chi2 << " cells " << cells;
      const double t_share = (front ? d->hemispherical(d->transmission_front, i) : d->hemispherical(d->transmission_back, i)) / a;
      EXPECT_NEAR(transmitted / samples, t_share, 4 * std::sqrt(t_share * (1 - t_share) / samples));
      ++case_index;
    }
}

TEST(KlemsBsdf, ClearPaneIsDiagonalStraightThroughAndMirror) {
  // T(i, i) = tau / Lambda_i, R(i, i) = rho / Lambda_i: light leaves in the straight-through
  // patch when transmitted and in the mirror patch when reflected.
  const KlemsBasis b = KlemsBasis::full();
  const auto d = std::make_shared<KlemsBsdfData>(dayphoton::test::klems_from(
      b, [b](int i, int o) { return i == o ? 0.8 / b.projected_solid_angle(o) : 0.0; },
      [b](int i, int o) { return i == o ? 0.8 / b.projected_solid_angle(o) : 0.0; },
      [b](int i, int o) { return i == o ? 0.1 / b.projected_solid_angle(o) : 0.0; },
      [b](int i, int o) { return i == o ? 0.1 / b.projected_solid_angle(o) : 0.0; }));
  const KlemsBsdf m(d, Up);
  const Local frame(Normal);
  for (double theta : {3.0, 20.0, 47.0, 70.0, 85.0})
    for (double phi : {10.0, 130.0, 290.0})
      for (bool back : {false, true}) {
        const Vec3 in = engine::test::incident_direction(Normal, theta, phi, back);
        const Vec3 mirror = in - Normal * (2 * dot(in, Normal));
        for (double u0 : {0.05, 0.5, 0.95}) {
          const auto s = m.sample(in, Normal, u0, 0.37, 0.71);
          ASSERT_TRUE(s);
          EXPECT_NEAR(s->weight, 0.9, 1e-12);
          EXPECT_EQ(s->transmitted, u0 < 0.8 / 0.9);
          EXPECT_EQ(b.patch(frame.to_local(s->direction)), b.patch(frame.to_local(s->transmitted ? in : mirror)));
        }
      }
}

TEST(KlemsBsdf, FrontIsTheSideTheNormalPointsAwayFrom) {
  // Only Transmission Front is non-zero: light moving along the normal (coming from the side
  // it points away from: a window's outside, the normal facing the room) passes; light from
  // the other side is absorbed.
  const KlemsBsdf m(std::make_shared<KlemsBsdfData>(dayphoton::test::klems_from(
                        KlemsBasis::full(), [](int, int) { return 0.5 / Pi; }, [](int, int) { return 0.0; },
                        [](int, int) { return 0.0; }, [](int, int) { return 0.0; })),
                    Up);
  const Vec3 n{0, -1, 0};  // a window whose room lies to the south of it
  const Vec3 moving_along_normal = normalize(Vec3{0.1, -1, -0.3});
  EXPECT_NEAR(m.albedo(moving_along_normal, n), 0.5, 1e-12);
  EXPECT_EQ(m.albedo(moving_along_normal * -1.0, n), 0.0);
  EXPECT_FALSE(m.sample(moving_along_normal * -1.0, n, 0.5, 0.5, 0.5));
}

TEST(KlemsBsdf, UpVectorOrientsTheAzimuth) {
  // Light leaves only into the outgoing patches of ring 2 centred on azimuth 90 degrees, i.e.
  // along local +y, the up vector projected onto the surface: on a vertical window it goes up.
  const KlemsBasis b = KlemsBasis::full();
  const int up_patch = b.first_of_ring(1) + 2;  // 8 sectors: sector 2 is centred on 90 degrees
  const KlemsBsdf m(std::make_shared<KlemsBsdfData>(dayphoton::test::klems_from(
                        b, [up_patch, b](int, int o) { return o == up_patch ? 0.5 / b.projected_solid_angle(o) : 0.0; },
                        [](int, int) { return 0.0; }, [](int, int) { return 0.0; }, [](int, int) { return 0.0; })),
                    Up);
  const Vec3 n{0, 1, 0};
  for (double u : {0.1, 0.5, 0.9}) {
    const auto s = m.sample(Vec3{0, 1, 0}, n, 0.5, u, 0.5);
    ASSERT_TRUE(s);
    EXPECT_GT(s->direction.z, std::sin(deg_to_rad(5)) * std::cos(deg_to_rad(22.5)) - 1e-12);
    EXPECT_NEAR(s->direction.x, 0.0, std::sin(deg_to_rad(15)) * std::sin(deg_to_rad(22.5)) + 1e-12);
  }
  EXPECT_TRUE(KlemsBsdf::frame_defined(Up, n));
  EXPECT_FALSE(KlemsBsdf::frame_defined(Up, Vec3{0, 0, -1}));
}
