// The material registry: one entry per scattering model, keyed by the type name project files
// write (`type: glass`). An entry gives everything the rest of the program needs to know about
// a model, so that adding one is one file plus one registration line:
//   - `make`: the factory, MaterialSpec -> MaterialModel (material_model.h);
//   - for a registered model (MaterialType::Registered, i.e. every model added after the
//     built-ins): its project-file parameters (`parameters`, the schema the loader validates
//     against, lists in `--help` and documents), its parser (`parse`, from the YAML map to
//     the model's MaterialParameters, with located errors), the text its parameters add to
//     the scene cache key (`cache_key`) and its line in `check` (`summary`).
// The built-in models (lambertian, metal, mirror, glass, dielectric, translucent, opening,
// glazing) keep their parameters in MaterialSpec's flat fields and their keys in the project
// schema's built-in sections, as before the registry; their entries give only the factory
// and the transmittance-factor flag.
//
// Adding a model `foo` (docs/materials.md, "Adding a material model"):
//   1. engine/src/foo_material.cpp: a class deriving from MaterialModel in an anonymous
//      namespace, a `struct FooParameters : MaterialParameters`, and the entry function
//          MaterialModelEntry foo_material_entry() {
//            MaterialModelEntry e;
//            e.type_name = "foo";  e.help = "...";  e.make = &make_foo;
//            e.parameters = {...};  e.parse = &parse_foo;
//            e.cache_key = &foo_cache_key;  e.summary = &foo_summary;
//            return e;
//          }
//   2. engine/src/material_registry.cpp: one line in the list, `foo_material_entry(),`
//      (with its one-line declaration above the list).
// No static self-registration and no dynamic loading: the list is explicit and greppable.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/material_model.h"

namespace dayphoton::engine {

/// Reads a registered model's keys from its map in the project file. The project loader
/// implements it over its YAML reader: every read marks the key as used (keys left unread
/// are reported as unknown), checks the value's type and the range its MaterialParameterSchema
/// declares, reports bad input as `file:line:column: error: ...` naming the key and returns
/// false. A missing key that is not required leaves `out` unchanged (set the default first).
class MaterialKeyReader {
 public:
  virtual ~MaterialKeyReader() = default;
  virtual bool has(const std::string& key) const = 0;
  virtual bool read_number(const std::string& key, double& out) = 0;
  /// A grey number or [r, g, b].
  virtual bool read_rgb(const std::string& key, Vec3& out) = 0;
  virtual bool read_string(const std::string& key, std::string& out) = 0;
  /// A file path, resolved against the project file's folder; reports a missing file.
  virtual bool read_path(const std::string& key, std::string& resolved_path) = 0;
  /// Where the key's value is (the map's location if the key is absent).
  virtual SourceLocation location_of(const std::string& key) const = 0;
  /// A located error of the model's own checks (e.g. a value the schema's range cannot
  /// express, or a file that does not parse).
  virtual void error(const SourceLocation& at, const std::string& message) = 0;
  /// An error found in another file the model reads (a BSDF XML file), with that file's own
  /// line under the caret.
  virtual void forward(const Diagnostic& diagnostic) = 0;
};

/// One project-file key of a registered model: drives the loader's validation, `--help`
/// and the generated key tables of docs/project-format.md.
struct MaterialParameterSchema {
  enum class Kind { Number, Rgb, String, Path };
  std::string key;
  Kind kind = Kind::Number;
  std::string help;  ///< one line
  std::string unit;  ///< "" for none, e.g. "m", "1/sr"
  double min = -std::numeric_limits<double>::infinity();  ///< inclusive bounds (Number, Rgb)
  double max = std::numeric_limits<double>::infinity();
  bool required = false;
  std::string default_text;  ///< as written in docs, "" if required or none
};

struct MaterialModelEntry {
  /// The project file's `type:` value; unique.
  std::string type_name;
  /// Builds the model; throws std::invalid_argument("material '<name>': ...") for parameters
  /// it cannot use (the loader has already checked what the schema can express).
  std::shared_ptr<const MaterialModel> (*make)(const MaterialSpec& spec) = nullptr;
  /// True if the model transmits straight through and may carry a room window's frame and
  /// maintenance factors (MaterialSpec::transmittance_factor != 1), applying the factor to
  /// its transmitted light (straight_transmittance(), sample(), albedo()).
  bool takes_transmittance_factor = false;

  // ---- Registered models only (null / empty for the built-ins) --------------------------
  /// One line for the project schema's list of material types.
  std::string help;
  /// The model's keys besides `type`.
  std::vector<MaterialParameterSchema> parameters;
  /// Reads the keys into the model's parameters (spec.name, .location are set). Returns
  /// nullptr after reporting an error through the reader.
  std::shared_ptr<const MaterialParameters> (*parse)(MaterialKeyReader& reader, const MaterialSpec& spec) = nullptr;
  /// Appends every parameter that changes results to `out` (hashed into the scene's cache
  /// key), e.g. numbers with "%.17g" and a file's content hash; never names or locations.
  void (*cache_key)(const MaterialSpec& spec, std::string& out) = nullptr;
  /// The material's one-line description for `check` (e.g. "Klems BSDF, 145 x 145, file.xml").
  std::string (*summary)(const MaterialSpec& spec) = nullptr;
};

/// Every model, the built-ins first, in registration order.
const std::vector<MaterialModelEntry>& material_models();

/// The entry for a project file's type name, or nullptr.
const MaterialModelEntry* find_material_model(const std::string& type_name);

/// The entry a spec's model comes from: `spec.model` for MaterialType::Registered, else the
/// built-in type's name. Throws std::invalid_argument naming the material if there is none.
const MaterialModelEntry& material_model_of(const MaterialSpec& spec);

}  // namespace dayphoton::engine
