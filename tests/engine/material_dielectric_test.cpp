// Dielectric interface (prisms, RADIANCE `dielectric`): front side outside (index 1), back
// side inside (index n). Checks: Snell's law and the plane of incidence for refraction, the
// mirror law for reflection, the unpolarised Fresnel split (reflection frequency against R of
// fresnel.h, 4 binomial sigma), total internal reflection beyond the critical angle (digest of
// seeds 002-004 section 4 check #5), reversibility of the refracted path, and the sampling
// harness (E[weight] == albedo == 1). Numbers for the 004 Dove prism (digest section 3.1):
// n = 1.7, 45 deg incidence refracts to 24.6 deg, base TIR at 69.6 deg (critical 36.0 deg).
#include <gtest/gtest.h>

#include <cmath>

#include "../../engine/src/fresnel.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/material.h"
#include "material_test_harness.h"

namespace dayphoton::engine {
namespace {

using test::check_sampling;
using test::incident_direction;
using test::make_spec;
using test::tilted_normal;

Material dielectric(double index, Vec3 per_metre = {0.9, 0.9, 0.9}) {
  MaterialSpec spec = make_spec(MaterialType::Dielectric);
  spec.refractive_index = index;
  spec.transmittance = per_metre;
  return Material::from_spec(spec);
}

double angle_deg(const Vec3& a, const Vec3& b) {
  return rad_to_deg(std::acos(std::clamp(dot(a, b), -1.0, 1.0)));
}

TEST(MaterialDielectric, RefractionFollowsSnellFromOutsideAndInside) {
  const Vec3 n = tilted_normal();
  const Material m = dielectric(1.5);
  for (double theta : {0.0, 20.0, 45.0, 80.0}) {
    // Outside -> inside: 1 * sin(theta_i) = 1.5 sin(theta_t), continuing to the back side.
    const Vec3 d = incident_direction(n, theta, 30);
    const auto s = m.sample(d, n, 0.999, 0.5, 0.5);  // u above R: refraction
    ASSERT_TRUE(s);
    EXPECT_EQ(s->type, ScatterType::SpecularTransmission);
    EXPECT_TRUE(s->delta);
    EXPECT_EQ(s->weight, (Vec3{1, 1, 1}));
    EXPECT_LT(dot(s->direction, n), 0.0);
    const double theta_t = angle_deg(s->direction, -n);
    EXPECT_NEAR(std::sin(deg_to_rad(theta)), 1.5 * std::sin(deg_to_rad(theta_t)), 1e-12) << theta;
    EXPECT_NEAR(dot(cross(d, n), s->direction), 0.0, 1e-12) << "stays in the plane of incidence";
    // Reversibility: the reversed ray refracts back along -d (from the inside, back side).
    const auto back = m.sample(-s->direction, n, 0.999, 0.5, 0.5);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->type, ScatterType::SpecularTransmission);
    EXPECT_NEAR(length(back->direction + d), 0.0, 1e-12) << theta;
  }
  // Inside -> outside below the critical angle: 1.5 sin(theta_i) = sin(theta_t).
  const Vec3 d = incident_direction(n, 30, 0, true);
  const auto s = m.sample(d, n, 0.999, 0.5, 0.5);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->type, ScatterType::SpecularTransmission);
  EXPECT_GT(dot(s->direction, n), 0.0);
  EXPECT_NEAR(1.5 * std::sin(deg_to_rad(30)), std::sin(deg_to_rad(angle_deg(s->direction, n))), 1e-12);
}

TEST(MaterialDielectric, TotalInternalReflectionBeyondTheCriticalAngle) {
  const Vec3 n = tilted_normal();
  for (double index : {1.5, 1.52, 1.7}) {
    const Material m = dielectric(index);
    const double critical = rad_to_deg(std::asin(1.0 / index));
    for (double theta : {critical + 0.05, critical + 10, 89.0}) {
      const Vec3 d = incident_direction(n, theta, 0, true);  // from inside
      for (double u : {0.0, 0.5, 0.999999}) {
        const auto s = m.sample(d, n, u, 0.5, 0.5);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->type, ScatterType::SpecularReflection) << index << " " << theta;
        EXPECT_EQ(s->weight, (Vec3{1, 1, 1}));
        EXPECT_NEAR(dot(s->direction, n), -dot(d, n), 1e-12);
      }
    }
    // Just inside the critical angle some light gets out.
    const auto out = m.sample(incident_direction(n, critical - 0.5, 0, true), n, 0.999, 0.5, 0.5);
    ASSERT_TRUE(out);
    EXPECT_EQ(out->type, ScatterType::SpecularTransmission) << index;
  }
}

TEST(MaterialDielectric, ReflectionFrequencyIsTheFresnelReflectance) {
  const Vec3 n = tilted_normal();
  const Material m = dielectric(1.7);
  int k = 0;
  for (double theta : {0.0, 45.0, 75.0}) {
    for (bool back : {false, true}) {
      if (back && theta > 30) continue;  // inside beyond 36 deg is TIR (tested above)
      const Vec3 d = incident_direction(n, theta, 10, back);
      const double r =
          fresnel_dielectric(std::cos(deg_to_rad(theta)), back ? 1 / 1.7 : 1.7).unpolarised();
      Rng rng(1000 + static_cast<std::uint64_t>(k++), 0, 0, RandomStream::Scattering);
      const int trials = 40000;
      int reflected = 0;
      for (int i = 0; i < trials; ++i) {
        const auto s = m.sample(d, n, rng.uniform(), rng.uniform(), rng.uniform());
        ASSERT_TRUE(s);
        if (s->type == ScatterType::SpecularReflection) {
          ++reflected;
          EXPECT_NEAR(dot(s->direction, n), -dot(d, n), 1e-12);
        }
      }
      // Binomial: 4 sigma = 4 sqrt(N R (1 - R)).
      EXPECT_NEAR(reflected, trials * r, 4 * std::sqrt(trials * r * (1 - r))) << theta;
      check_sampling(m, d, n, 1100 + static_cast<std::uint64_t>(k),
                     "dielectric 1.7 theta " + std::to_string(theta) + (back ? " back" : ""));
    }
  }
}

TEST(MaterialDielectric, DovePrismNumbers) {
  // Digest section 3.1: entering the 45 deg face of the n = 1.7 prism refracts to 24.6 deg,
  // loses (unpolarised) R = 0.0789 per face; the base is hit at 69.6 deg, beyond the 36.0 deg
  // critical angle.
  const Vec3 n = tilted_normal();
  const Material m = dielectric(1.7);
  const auto s = m.sample(incident_direction(n, 45, 0), n, 0.999, 0.5, 0.5);
  ASSERT_TRUE(s);
  EXPECT_NEAR(angle_deg(s->direction, -n), 24.6, 0.05);
  EXPECT_NEAR(fresnel_dielectric(std::cos(deg_to_rad(45)), 1.7).unpolarised(), 0.0789, 2e-4);
  EXPECT_NEAR(rad_to_deg(std::asin(1 / 1.7)), 36.0, 0.05);
  const auto base = m.sample(incident_direction(n, 69.6, 0, true), n, 0.0, 0.5, 0.5);
  ASSERT_TRUE(base);
  EXPECT_EQ(base->type, ScatterType::SpecularReflection);
}

TEST(MaterialDielectric, InterfaceProperties) {
  const Vec3 n = tilted_normal();
  const Material m = dielectric(1.5, {0.9, 0.8, 0.7});
  const Vec3 d = incident_direction(n, 30, 0);
  EXPECT_EQ(m.albedo(d, n), (Vec3{1, 1, 1}));
  EXPECT_EQ(m.eval(d, -d, n), (Vec3{0, 0, 0}));
  EXPECT_EQ(m.pdf(d, -d, n), 0.0);
  EXPECT_EQ(m.straight_transmittance(d, n), (Vec3{0, 0, 0}));
  EXPECT_FALSE(m.stores_photons());
  EXPECT_EQ(m.interior_transmittance_per_m(), (Vec3{0.9, 0.8, 0.7}));
  EXPECT_THROW(dielectric(0.0), std::invalid_argument);
  EXPECT_THROW(dielectric(1.5, {1.2, 0.5, 0.5}), std::invalid_argument);
}

}  // namespace
}  // namespace dayphoton::engine
