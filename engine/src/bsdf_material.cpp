// Measured BSDF (type `bsdf`): scattering by a Klems BSDF matrix or a tensor tree
// (TensorTree3 or TensorTree4) read from an LBNL WINDOW / IGSDB / RADIANCE BSDF XML file (core/bsdf_xml.h),
// through KlemsBsdf (klems_bsdf.h) or TensorTreeBsdf (tensor_tree_bsdf.h). Parameters:
//   file  the XML file, relative to the project file's folder (required)
//   up    the BSDF's up vector in world coordinates, default [0, 0, 1]
// Example:  blind: {type: bsdf, file: blind_45deg.xml, up: [0, 0, 1]}
// The events are glossy (not delta, not diffuse): no straight component for shadow rays, no
// photons stored on the surface itself; a room window's frame and maintenance factors scale
// the transmitted light. Orientation, sampling, what is read and refused: docs/materials.md,
// "Measured BSDF (Klems)".
#include "dayphoton/engine/bsdf_material.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "dayphoton/core/bsdf_xml.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/material_registry.h"
#include "klems_bsdf.h"
#include "tensor_tree_bsdf.h"

namespace dayphoton::engine {
namespace {

// The measured BSDF behind the material: a Klems matrix or a tensor tree, with one interface.
class MeasuredBsdf {
 public:
  MeasuredBsdf(const std::shared_ptr<const KlemsBsdfData>& data, const Vec3& up) {
    if (data && data->tensor_tree)
      m_tree.emplace(data, up);
    else
      m_klems.emplace(data, up);
  }
  std::optional<KlemsBsdf::Sample> sample(const Vec3& in, const Vec3& n, double u0, double u1, double u2) const {
    return m_tree ? m_tree->sample(in, n, u0, u1, u2) : m_klems->sample(in, n, u0, u1, u2);
  }
  double eval(const Vec3& in, const Vec3& out, const Vec3& n) const {
    return m_tree ? m_tree->eval(in, out, n) : m_klems->eval(in, out, n);
  }
  double pdf(const Vec3& in, const Vec3& out, const Vec3& n) const {
    return m_tree ? m_tree->pdf(in, out, n) : m_klems->pdf(in, out, n);
  }
  double albedo(const Vec3& in, const Vec3& n) const { return m_tree ? m_tree->albedo(in, n) : m_klems->albedo(in, n); }
  double transmittance(const Vec3& in, const Vec3& n) const {
    return m_tree ? m_tree->transmittance(in, n) : m_klems->transmittance(in, n);
  }

 private:
  std::optional<KlemsBsdf> m_klems;
  std::optional<TensorTreeBsdf> m_tree;
};

class BsdfMaterial final : public MaterialModel {
 public:
  BsdfMaterial(const BsdfMaterialParameters& p, double transmittance_factor)
      : m_bsdf(p.data, p.up), m_factor(transmittance_factor) {}

  std::optional<ScatterSample> sample(const Vec3& incoming, const Vec3& normal, double u_component, double u1,
                                      double u2) const override {
    const std::optional<KlemsBsdf::Sample> s = m_bsdf.sample(incoming, normal, u_component, u1, u2);
    if (!s) return std::nullopt;
    // eval * |cos| / pdf: the factor scales the transmitted part of eval, not the pdf.
    const double w = s->weight * (s->transmitted ? m_factor : 1.0);
    return ScatterSample{s->direction, Vec3{w, w, w},
                         s->transmitted ? ScatterType::GlossyTransmission : ScatterType::GlossyReflection, false};
  }
  Vec3 eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const override {
    const bool transmitted = (dot(incoming, normal) > 0) == (dot(outgoing, normal) > 0);
    const double f = m_bsdf.eval(incoming, outgoing, normal) * (transmitted ? m_factor : 1.0);
    return {f, f, f};
  }
  double pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const override {
    return m_bsdf.pdf(incoming, outgoing, normal);
  }
  Vec3 albedo(const Vec3& incoming, const Vec3& normal) const override {
    const double a = m_factor == 1.0 ? m_bsdf.albedo(incoming, normal)
                                     : m_factor * m_bsdf.transmittance(incoming, normal) +
                                           (m_bsdf.albedo(incoming, normal) - m_bsdf.transmittance(incoming, normal));
    return {a, a, a};
  }

 private:
  MeasuredBsdf m_bsdf;
  double m_factor;
};

std::shared_ptr<const MaterialModel> make_bsdf(const MaterialSpec& spec) {
  const BsdfMaterialParameters* p = bsdf_parameters(spec);
  if (!p || !p->data) throw std::invalid_argument("material '" + spec.name + "': a bsdf material needs its BSDF data");
  if (!(length(p->up) > 0)) throw std::invalid_argument("material '" + spec.name + "': the up vector is zero");
  if (!(spec.transmittance_factor > 0.0 && spec.transmittance_factor <= 1.0))
    throw std::invalid_argument("material '" + spec.name + "': transmittance factor outside (0, 1]");
  return std::make_shared<BsdfMaterial>(*p, spec.transmittance_factor);
}

std::shared_ptr<const MaterialParameters> parse_bsdf(MaterialKeyReader& r, const MaterialSpec& spec) {
  // Every key is read before any early return, so none is reported as unknown.
  std::string path;
  const bool have_file = r.read_path("file", path);
  auto p = std::make_shared<BsdfMaterialParameters>();
  if (r.has("up") && !r.read_rgb("up", p->up)) return nullptr;
  if (!have_file) return nullptr;
  if (!(length(p->up) > 0)) {
    r.error(r.location_of("up"), "material '" + spec.name + "': the up vector is zero");
    return nullptr;
  }
  try {
    p->data = read_bsdf_xml(path, path, r.location_of("file"));
  } catch (const InputError& e) {
    // Errors inside the XML file carry its own lines; a missing file is at the `file` key.
    for (const Diagnostic& d : e.diagnostics()) {
      if (d.source_line.empty())
        r.error(d.location, d.message);
      else
        r.forward(d);
    }
    return nullptr;
  }
  return p;
}

void bsdf_cache_key(const MaterialSpec& spec, std::string& out) {
  const BsdfMaterialParameters* p = bsdf_parameters(spec);
  if (!p || !p->data) return;
  char up[96];
  std::snprintf(up, sizeof up, " up %.17g %.17g %.17g", p->up.x, p->up.y, p->up.z);
  out += "bsdf " + p->data->content_sha256 + up;
}

std::string bsdf_summary(const MaterialSpec& spec) {
  const BsdfMaterialParameters* p = bsdf_parameters(spec);
  if (!p || !p->data) return "bsdf";
  const KlemsBsdfData& d = *p->data;
  char text[200];
  if (d.tensor_tree) {
    const TensorTreeBsdfData& t = *d.tensor_tree;
    const TensorTreeBsdfData::Slice& f = t.slices[0][static_cast<std::size_t>(t.slice_of(0, {0, 0, 1}))];
    const TensorTreeBsdfData::Slice& b = t.slices[1][static_cast<std::size_t>(t.slice_of(1, {0, 0, -1}))];
    std::snprintf(text, sizeof text,
                  "tensor-tree BSDF (TensorTree%d, cells down to 1/%d), normal incidence front T %.3f R %.3f, back T "
                  "%.3f R %.3f",
                  t.ndim, 1 << std::max({t.trees[0].max_log2, t.trees[1].max_log2, t.trees[2].max_log2, t.trees[3].max_log2}),
                  f.transmittance, f.albedo - f.transmittance, b.transmittance, b.albedo - b.transmittance);
    return std::string(text) + ", " + d.file;
  }
  std::snprintf(text, sizeof text, "Klems BSDF %d x %d, normal incidence front T %.3f R %.3f, back T %.3f R %.3f",
                d.basis.size(), d.basis.size(), d.hemispherical(d.transmission_front, 0),
                d.hemispherical(d.reflection_front, 0), d.hemispherical(d.transmission_back, 0),
                d.hemispherical(d.reflection_back, 0));
  return std::string(text) + ", " + d.file;
}

}  // namespace

MaterialSpec bsdf_material_spec(const std::string& name, std::shared_ptr<const KlemsBsdfData> data, const Vec3& up) {
  MaterialSpec spec;
  spec.name = name;
  spec.type = MaterialType::Registered;
  spec.model = BsdfMaterialType;
  auto p = std::make_shared<BsdfMaterialParameters>();
  p->data = std::move(data);
  p->up = up;
  spec.parameters = std::move(p);
  return spec;
}

const BsdfMaterialParameters* bsdf_parameters(const MaterialSpec& spec) {
  if (spec.type != MaterialType::Registered || spec.model != BsdfMaterialType) return nullptr;
  return dynamic_cast<const BsdfMaterialParameters*>(spec.parameters.get());
}

MaterialModelEntry bsdf_material_entry() {
  MaterialModelEntry e;
  e.type_name = BsdfMaterialType;
  e.help = "measured BSDF: a Klems matrix or a tensor tree (TensorTree3/4) from a BSDF XML file (docs/materials.md)";
  e.make = &make_bsdf;
  e.takes_transmittance_factor = true;
  MaterialParameterSchema file;
  file.key = "file";
  file.kind = MaterialParameterSchema::Kind::Path;
  file.help = "the BSDF XML file (Klems basis or TensorTree3/4), relative to the project file";
  file.required = true;
  MaterialParameterSchema up;
  up.key = "up";
  up.kind = MaterialParameterSchema::Kind::Rgb;
  up.help = "the BSDF's up vector [x, y, z] in world coordinates (not parallel to the surface's normal)";
  up.default_text = "[0, 0, 1]";
  e.parameters = {file, up};
  e.parse = &parse_bsdf;
  e.cache_key = &bsdf_cache_key;
  e.summary = &bsdf_summary;
  return e;
}

}  // namespace dayphoton::engine
