// RADIANCE modifier -> MaterialSpec (project/radiance_material.h): each mapped type against
// the reference manual's argument meanings, glass against closed forms, and every refusal.
#include "dayphoton/project/radiance_material.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dayphoton::project {
namespace {

using Role = RadianceModifierRole;

// The RADIANCE reference manual's conversion for n = 1.52, normal transmittance Tn ->
// transmissivity tn (its `glass` entry), written out independently of the code under test.
double manual_transmissivity(double tn_normal) {
  return (std::sqrt(0.8402528435 + 0.0072522239 * tn_normal * tn_normal) - 0.9166530661) /
         0.0036261119 / tn_normal;
}

TEST(RadianceMaterial, GlassTransmissivityBecomesNormalTransmittance) {
  // The reference office's glazing: tn 0.654 is Tn 0.60 (to the 3 digits tn is written with).
  const auto r = radiance_material("glass", "glass_mat", {0.654, 0.654, 0.654});
  ASSERT_TRUE(r.mapped()) << r.reason;
  EXPECT_EQ(r.material.type, MaterialType::Glass);
  EXPECT_EQ(r.material.name, "glass_mat");
  EXPECT_DOUBLE_EQ(r.material.refractive_index, 1.52);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.material.transmittance[c], 0.60, 1e-4);
  EXPECT_TRUE(r.notes.empty());
}

TEST(RadianceMaterial, GlassConversionInvertsTheManualsFormula) {
  for (double tn_normal : {0.05, 0.3, 0.6, 0.8, 0.88, 0.9}) {
    const double tn = manual_transmissivity(tn_normal);
    // The manual's constants have 10 digits, and its formula subtracts two numbers near
    // 0.9167 before dividing by 0.0036 Tn: its rounding is about 2e-8 / Tn.
    EXPECT_NEAR(radiance_glass_normal_transmittance(tn, 1.52), tn_normal, 2e-8 / tn_normal)
        << tn_normal;
  }
}

TEST(RadianceMaterial, GlassClosedFormLimits) {
  // n = 1: no reflection, Tn = tn. tn = 1: a clear pane, (1 - r0) / (1 + r0).
  EXPECT_DOUBLE_EQ(radiance_glass_normal_transmittance(0.7, 1.0), 0.7);
  const double r0 = std::pow(0.52 / 2.52, 2);
  EXPECT_NEAR(radiance_glass_normal_transmittance(1.0, 1.52), (1 - r0) / (1 + r0), 1e-15);
  EXPECT_NEAR(radiance_glass_normal_transmittance(1.0, 1.52), 0.9183, 1e-4);
  EXPECT_DOUBLE_EQ(radiance_glass_normal_transmittance(0.0, 1.52), 0.0);
}

TEST(RadianceMaterial, GlassColourAndFourthArgumentIndex) {
  const auto r = radiance_material("glass", "tinted", {0.5, 0.7, 0.9, 1.7});
  ASSERT_TRUE(r.mapped()) << r.reason;
  EXPECT_DOUBLE_EQ(r.material.refractive_index, 1.7);
  const double r0 = std::pow(0.7 / 2.7, 2);
  const double t[3] = {0.5, 0.7, 0.9};
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(r.material.transmittance[c],
                (1 - r0) * (1 - r0) * t[c] / (1 - r0 * r0 * t[c] * t[c]), 1e-15);
}

TEST(RadianceMaterial, GlassAboveOneOrWrongCountsIsRefused) {
  const auto above = radiance_material("glass", "g", {0.9, 1.05, 0.9});
  EXPECT_EQ(above.role, Role::Invalid);
  EXPECT_NE(above.reason.find("glass 'g': transmissivity 1.05 (green) is above 1"), std::string::npos)
      << above.reason;
  EXPECT_EQ(radiance_material("glass", "g", {0.9, 0.9}).role, Role::Invalid);
  EXPECT_EQ(radiance_material("glass", "g", {0.9, 0.9, 0.9, 1.52, 0}).role, Role::Invalid);
  EXPECT_EQ(radiance_material("glass", "g", {0.9, 0.9, 0.9, 0.8}).role, Role::Invalid);
}

TEST(RadianceMaterial, PlasticMetalAndTransKeepTheirParameters) {
  const auto p = radiance_material("plastic", "wall", {0.5, 0.4, 0.3, 0.02, 0.05});
  ASSERT_TRUE(p.mapped()) << p.reason;
  EXPECT_EQ(p.material.type, MaterialType::Lambertian);
  EXPECT_EQ(p.material.type_as_written, "plastic");
  EXPECT_EQ(p.material.reflectance, Vec3(0.5, 0.4, 0.3));
  EXPECT_DOUBLE_EQ(p.material.specularity, 0.02);
  EXPECT_DOUBLE_EQ(p.material.roughness, 0.05);

  const auto m = radiance_material("metal", "louvre", {0.8, 0.8, 0.8, 0.9, 0.0});
  ASSERT_TRUE(m.mapped()) << m.reason;
  EXPECT_EQ(m.material.type, MaterialType::Metal);
  EXPECT_DOUBLE_EQ(m.material.specularity, 0.9);

  const auto t = radiance_material("trans", "blind", {0.7, 0.7, 0.7, 0.0, 0.0, 0.4, 0.1});
  ASSERT_TRUE(t.mapped()) << t.reason;
  EXPECT_EQ(t.material.type, MaterialType::Translucent);
  EXPECT_DOUBLE_EQ(t.material.transmissivity, 0.4);
  EXPECT_DOUBLE_EQ(t.material.transmitted_specular, 0.1);
}

TEST(RadianceMaterial, ReflectanceOutsideUnitRangeIsRefused) {
  const auto r = radiance_material("plastic", "hot", {1.2, 0.5, 0.5, 0, 0});
  EXPECT_EQ(r.role, Role::Invalid);
  EXPECT_NE(r.reason.find("plastic 'hot': reflectance 1.2 (red) is outside [0, 1]"), std::string::npos)
      << r.reason;
  EXPECT_EQ(radiance_material("plastic", "p", {0.5, 0.5, 0.5, 0, 1.5}).role, Role::Invalid);
  EXPECT_EQ(radiance_material("plastic", "p", {0.5, 0.5, 0.5, NAN, 0}).role, Role::Invalid);
  EXPECT_EQ(radiance_material("plastic", "p", {0.5, 0.5, 0.5}).role, Role::Invalid);
  EXPECT_EQ(radiance_material("plastic", "p", {0.5, 0.5, 0.5, 0, 0}, {"x"}).role, Role::Invalid);
  EXPECT_EQ(radiance_material("plastic", "p", {0.5, 0.5, 0.5, 0, 0}, {}, 1).role, Role::Invalid);
  EXPECT_TRUE(radiance_material("plastic", "p", {0.5, 0.5, 0.5, 0, 0}).material.location.file.empty());
}

TEST(RadianceMaterial, MirrorAndItsAlternateMaterial) {
  const auto plain = radiance_material("mirror", "m", {0.9, 0.9, 0.9});
  ASSERT_TRUE(plain.mapped());
  EXPECT_EQ(plain.material.type, MaterialType::Mirror);
  EXPECT_EQ(plain.material.reflectance, Vec3(0.9, 0.9, 0.9));
  EXPECT_TRUE(plain.notes.empty());
  const auto alt = radiance_material("mirror", "m", {0.9, 0.9, 0.9}, {"white"});
  ASSERT_TRUE(alt.mapped());
  EXPECT_EQ(alt.alternate_material, "white");
  ASSERT_EQ(alt.notes.size(), 1u);
  EXPECT_NE(alt.notes[0].find("alternate material 'white' ignored"), std::string::npos);
}

TEST(RadianceMaterial, DielectricIgnoresDispersionWithANote) {
  const auto r = radiance_material("dielectric", "acrylic", {0.98, 0.98, 0.98, 1.49, 0});
  ASSERT_TRUE(r.mapped()) << r.reason;
  EXPECT_EQ(r.material.type, MaterialType::Dielectric);
  EXPECT_DOUBLE_EQ(r.material.refractive_index, 1.49);
  EXPECT_EQ(r.material.transmittance, Vec3(0.98, 0.98, 0.98));
  EXPECT_TRUE(r.notes.empty());
  const auto h = radiance_material("dielectric", "acrylic", {0.98, 0.98, 0.98, 1.49, 0.1});
  ASSERT_TRUE(h.mapped());
  ASSERT_EQ(h.notes.size(), 1u);
  EXPECT_NE(h.notes[0].find("Hartmann constant 0.1 ignored"), std::string::npos);
}

TEST(RadianceMaterial, VoidIsInvisibleAndEmittersAreSources) {
  EXPECT_EQ(radiance_material("void", "void", {}).role, Role::Invisible);
  EXPECT_EQ(radiance_material("light", "lamp", {100, 100, 100}).role, Role::LightSource);
  EXPECT_EQ(radiance_material("glow", "sky_glow", {1, 1, 1, 0}).role, Role::LightSource);
  EXPECT_EQ(radiance_material("spotlight", "s", {1, 1, 1, 30, 0, 0, -1}).role, Role::LightSource);
  EXPECT_EQ(radiance_material("glow", "g", {1, 1, 1}).role, Role::Invalid);
  const auto illum = radiance_material("illum", "win_illum", {1, 1, 1}, {"glass_mat"});
  EXPECT_EQ(illum.role, Role::LightSource);
  EXPECT_EQ(illum.alternate_material, "glass_mat");
  EXPECT_EQ(radiance_material("illum", "i", {1, 1, 1}, {"void"}).alternate_material, "");
}

TEST(RadianceMaterial, BsdfNamesItsFileAndUpVector) {
  // BSDF: thick file ux uy uz funcfile; the file is read by the caller.
  const auto r = radiance_material("BSDF", "blind", {}, {"0", "blind.xml", "0", "0.1", "1", "."});
  ASSERT_EQ(r.role, Role::Material) << r.reason;
  EXPECT_EQ(r.bsdf_file, "blind.xml");
  EXPECT_EQ(r.bsdf_up, Vec3(0, 0.1, 1));
  EXPECT_TRUE(r.notes.empty());
  // Zero extra diffuse components are accepted; a thickness is ignored with a note; aBSDF
  // (no thickness) is read as BSDF with a note.
  EXPECT_EQ(radiance_material("BSDF", "b", {0, 0, 0, 0, 0, 0}, {"0", "f.xml", "0", "0", "1", "."}).role, Role::Material);
  const auto thick = radiance_material("BSDF", "b", {}, {"0.05", "f.xml", "0", "0", "1", "."});
  ASSERT_EQ(thick.notes.size(), 1u);
  EXPECT_NE(thick.notes[0].find("thickness 0.05 ignored"), std::string::npos) << thick.notes[0];
  const auto a = radiance_material("aBSDF", "b", {}, {"f.xml", "1", "0", "0", "."});
  ASSERT_EQ(a.role, Role::Material) << a.reason;
  EXPECT_EQ(a.bsdf_file, "f.xml");
  EXPECT_EQ(a.bsdf_up, Vec3(1, 0, 0));
  EXPECT_EQ(a.notes.size(), 1u);
}

TEST(RadianceMaterial, BsdfArgumentsItCannotReadAreRefused) {
  const std::vector<std::string> good = {"0", "f.xml", "0", "0", "1", "."};
  auto reason = [](const std::vector<double>& reals, const std::vector<std::string>& strings) {
    const auto r = radiance_material("BSDF", "blind", reals, strings);
    EXPECT_EQ(r.role, Role::Invalid);
    EXPECT_TRUE(r.bsdf_file.empty());
    return r.reason;
  };
  EXPECT_NE(reason({}, {"0", "f.xml", "0", "0", "1"}).find("takes 6 or more string arguments"), std::string::npos);
  EXPECT_NE(reason({}, {"0", "f.xml", "0", "0", "1", ".", "-rz", "90"}).find("a transform after the function file"),
            std::string::npos);
  EXPECT_NE(reason({}, {"0", "f.xml", "Ux", "Uy", "Uz", "up.cal"}).find("function file 'up.cal' is not read"),
            std::string::npos);
  EXPECT_NE(reason({}, {"0", "f.xml", "Ux", "0", "1", "."}).find("up vector component 'Ux' is not a number"),
            std::string::npos);
  EXPECT_NE(reason({}, {"0", "f.xml", "0", "0", "0", "."}).find("the up vector is zero"), std::string::npos);
  EXPECT_NE(reason({0.1, 0.1, 0.1}, good).find("extra diffuse components (real arguments) are not supported"),
            std::string::npos);
  EXPECT_NE(reason({0, 0}, good).find("takes 0, 3, 6 or 9 real arguments"), std::string::npos);
  EXPECT_NE(reason({}, {"thick", "f.xml", "0", "0", "1", "."}).find("thickness 'thick' is not a number"),
            std::string::npos);
}

TEST(RadianceMaterial, UnsupportedTypesSayWhy) {
  for (const char* type : {"brightfunc", "colorpict", "texfunc", "mixfunc", "antimatter",
                           "plastic2", "interface", "mist", "prism1", "plasfunc", "alias"}) {
    const auto r = radiance_material(type, "x", {});
    EXPECT_EQ(r.role, Role::Unsupported) << type;
    EXPECT_FALSE(r.reason.empty()) << type;
    EXPECT_TRUE(is_radiance_modifier_type(type)) << type;
  }
}

TEST(RadianceMaterial, UnknownTypeIsInvalidWithAHint) {
  const auto r = radiance_material("plastik", "wall", {0.5, 0.5, 0.5, 0, 0});
  EXPECT_EQ(r.role, Role::Invalid);
  EXPECT_NE(r.reason.find("did you mean 'plastic'?"), std::string::npos) << r.reason;
  EXPECT_FALSE(is_radiance_modifier_type("polygon"));
}

TEST(RadianceMaterial, GreyUsesRadiancesLuminanceWeights) {
  EXPECT_DOUBLE_EQ(radiance_grey({1, 0, 0}), 0.265);
  EXPECT_DOUBLE_EQ(radiance_grey({0, 1, 0}), 0.670);
  EXPECT_NEAR(radiance_grey({0.5, 0.5, 0.5}), 0.5, 1e-15);
}

}  // namespace
}  // namespace dayphoton::project
