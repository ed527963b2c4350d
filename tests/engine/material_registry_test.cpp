// The material registry (engine/material_registry.h) and the MaterialModel interface
// (engine/material_model.h): every built-in type has exactly one entry and builds through
// it; a registered type with no entry is an error naming the material; and a model written
// against the interface alone works as a Material.
#include "dayphoton/engine/material_registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/material.h"

namespace dayphoton::engine {
namespace {

const MaterialType BuiltIn[] = {MaterialType::Lambertian, MaterialType::Metal,       MaterialType::Mirror,
                                MaterialType::Glass,      MaterialType::Dielectric,  MaterialType::Translucent,
                                MaterialType::Opening,    MaterialType::Glazing};

TEST(MaterialRegistry, EveryBuiltInTypeHasOneEntryThatBuildsIt) {
  std::set<std::string> names;
  for (const MaterialModelEntry& e : material_models()) {
    EXPECT_TRUE(names.insert(e.type_name).second) << "duplicate type name " << e.type_name;
    EXPECT_NE(e.make, nullptr) << e.type_name;
  }
  for (MaterialType type : BuiltIn) {
    const MaterialModelEntry* e = find_material_model(material_type_name(type));
    ASSERT_NE(e, nullptr) << material_type_name(type);
    EXPECT_EQ(e->parse, nullptr) << "built-ins are read by the project schema's own sections";
    MaterialSpec spec;
    spec.name = "m";
    spec.type = type;
    spec.reflectance = {0.5, 0.5, 0.5};
    spec.transmittance = {0.8, 0.8, 0.8};
    spec.refractive_index = 1.5;
    if (type == MaterialType::Glazing) spec.panes.resize(1, GlazingPaneSpec{});
    if (type == MaterialType::Glazing) spec.panes[0].transmittance = {0.8, 0.8, 0.8};
    EXPECT_EQ(&material_model_of(spec), e);
    EXPECT_NO_THROW(Material::from_spec(spec)) << material_type_name(type);
  }
}

TEST(MaterialRegistry, OnlyStraightTransmittersTakeATransmittanceFactor) {
  for (MaterialType type : BuiltIn) {
    const bool expected = type == MaterialType::Glass || type == MaterialType::Glazing || type == MaterialType::Opening;
    EXPECT_EQ(find_material_model(material_type_name(type))->takes_transmittance_factor, expected)
        << material_type_name(type);
  }
}

TEST(MaterialRegistry, UnknownRegisteredModelIsAnErrorNamingTheMaterial) {
  MaterialSpec spec;
  spec.name = "louvre";
  spec.type = MaterialType::Registered;
  spec.model = "no_such_model";
  EXPECT_EQ(find_material_model("no_such_model"), nullptr);
  try {
    Material::from_spec(spec);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "material 'louvre': unknown material type 'no_such_model'");
  }
  // A built-in name is not a registered model either (its parameters are the flat fields).
  spec.model = "glass";
  EXPECT_THROW(Material::from_spec(spec), std::invalid_argument);
}

// A model written against the interface alone: a grey Lambertian reflector of albedo 0.25.
class QuarterLambertian final : public MaterialModel {
 public:
  std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3& normal, double, double, double) const override {
    const Vec3 n = dot(incoming, normal) < 0 ? normal : -normal;
    return ScatterSample{n, {0.25, 0.25, 0.25}, ScatterType::DiffuseReflection, false};
  }
  Vec3 eval(const Vec3&, const Vec3&, const Vec3&) const override { return Vec3{0.25, 0.25, 0.25} / Pi; }
  double pdf(const Vec3&, const Vec3& outgoing, const Vec3& normal) const override {
    return std::fabs(dot(outgoing, normal)) / Pi;
  }
  Vec3 albedo(const Vec3&, const Vec3&) const override { return {0.25, 0.25, 0.25}; }
  bool stores_photons() const override { return true; }
  Vec3 diffuse_reflectance() const override { return {0.25, 0.25, 0.25}; }
};

TEST(MaterialModel, AModelBuiltOutsideTheRegistryWorksAsAMaterialWithTheInterfaceDefaults) {
  MaterialSpec spec;
  spec.name = "quarter";
  spec.type = MaterialType::Registered;
  spec.model = "quarter";
  const Material m(spec, std::make_shared<QuarterLambertian>());
  const Material copy = m;  // copies share the immutable model
  EXPECT_EQ(&copy.model(), &m.model());
  EXPECT_EQ(copy.spec().model, "quarter");
  EXPECT_EQ(material_type_as_written(copy.spec()), "quarter");
  const Vec3 n{0, 0, 1}, in{0, 0, -1};
  EXPECT_DOUBLE_EQ(m.albedo(in, n).x, 0.25);
  EXPECT_TRUE(m.stores_photons());
  EXPECT_DOUBLE_EQ(m.diffuse_reflectance().y, 0.25);
  // The interface's defaults: opaque to shadow rays, no diffuse transmission, no absorption inside.
  EXPECT_EQ(m.straight_transmittance(in, n), (Vec3{0, 0, 0}));
  EXPECT_EQ(m.diffuse_transmittance(), (Vec3{0, 0, 0}));
  EXPECT_EQ(m.interior_transmittance_per_m(), (Vec3{1, 1, 1}));
  EXPECT_FALSE(m.absorbs_inside());
  EXPECT_THROW(Material(spec, nullptr), std::invalid_argument);
}

TEST(MaterialModel, OnlyAnAbsorbingDielectricAttenuatesInside) {
  MaterialSpec d;
  d.name = "prism";
  d.type = MaterialType::Dielectric;
  d.refractive_index = 1.5;
  d.transmittance = {1, 1, 1};
  EXPECT_FALSE(Material::from_spec(d).absorbs_inside());  // pow(1, t) == 1: nothing to do
  d.transmittance = {1, 0.9, 1};
  EXPECT_TRUE(Material::from_spec(d).absorbs_inside());
  MaterialSpec w;
  w.name = "wall";
  w.reflectance = {0.5, 0.5, 0.5};
  EXPECT_FALSE(Material::from_spec(w).absorbs_inside());
}

}  // namespace
}  // namespace dayphoton::engine
