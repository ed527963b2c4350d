// Honeybee's Radiance modifiers and modifier sets (honeybee-schema radiance/material.py and
// radiance/modifierset.py; honeybee-radiance modifierset.py). A modifier is a RADIANCE
// material given as named JSON fields; it is turned into the RADIANCE type and real
// arguments and mapped by project::radiance_material, the one mapping of RADIANCE materials.
// A modifier set names, per kind of object and boundary condition, the modifier it gets when
// the object names none; a slot the set leaves empty, and every slot when no set applies,
// takes Honeybee's default generic modifier set.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project::detail {

/// A problem with one field of a modifier, reported (located at the field) only when an
/// object uses the modifier, as the modifier's other problems are.
struct ModifierFieldProblem {
  std::string path;            ///< JSON path of the field
  std::string message;
  bool error = true;           ///< else a warning
};

/// A RADIANCE material: type and real arguments, as a .rad file would give them.
struct RadianceModifier {
  std::string identifier;
  std::string type;            ///< RADIANCE type: plastic, metal, trans, glass, mirror, BSDF, ...
  std::vector<double> args;    ///< the real arguments
  std::string path;            ///< JSON path, for messages ("" for a generic default)
  SourceLocation location;
  /// BSDF (honeybee-schema radiance/modifier.py `BSDF`): the Klems XML given inline as
  /// `bsdf_data`, where that field is written (the XML's errors are reported there), and the
  /// `up_orientation` (model coordinates; the schema's default (0.01, 0.01, 1)).
  std::string bsdf_xml;
  SourceLocation bsdf_data_location;
  Vec3 bsdf_up{0.01, 0.01, 1.0};
  std::vector<ModifierFieldProblem> field_problems;
};

/// Honeybee's generic modifiers, as in honeybee-radiance's library of default modifiers
/// (lib/data/modifiers/default.mat): generic_floor_0.20, generic_wall_0.50,
/// generic_ceiling_0.80, generic_opaque_door_0.50, generic_interior_shade_0.50,
/// generic_exterior_shade_0.35, generic_context_0.20, generic_interior_window_vis_0.88 and
/// generic_exterior_window_vis_0.64 (glass transmissivities 0.9584 and 0.6976: visible
/// transmittances 0.88 and 0.64), air_boundary.
const std::vector<RadianceModifier>& honeybee_generic_modifiers();

/// Slots of a modifier set, as "<subset>.<field>": wall_set.exterior_modifier, ...,
/// aperture_set.window_modifier, door_set.exterior_glass_modifier, shade_set.interior_modifier,
/// air_boundary_modifier, context_modifier (detached shades, as honeybee-radiance's
/// GlobalModifierSet gives it).
const std::vector<std::string>& modifier_set_slots();

/// The generic set's modifier for `slot` (Honeybee's default generic modifier set:
/// honeybee-radiance modifierset.py, the defaults of its Wall/Floor/RoofCeiling/Aperture/
/// Door/ShadeModifierSet classes).
const std::string& generic_modifier_for(const std::string& slot);

/// A modifier set of the model: slot -> modifier identifier, only the slots it fills.
struct ModifierSet {
  std::string identifier;
  std::map<std::string, std::string> slots;
  std::string path;
  SourceLocation location;

  /// The modifier for `slot`: this set's, else the generic set's.
  const std::string& modifier_for(const std::string& slot) const;
};

}  // namespace dayphoton::project::detail

namespace dayphoton {
class Diagnostics;
struct MaterialSpec;
}  // namespace dayphoton

namespace dayphoton::project::detail {

/// The engine material of `modifier` (named by its identifier, located at it), mapped by
/// project::radiance_material; false after reporting why it cannot be (an unsupported type,
/// wrong arguments), located at `where` (where the modifier is used when it has no location
/// of its own, i.e. a generic default).
bool honeybee_modifier_material(const RadianceModifier& modifier, const SourceLocation& where,
                                Diagnostics& diag, MaterialSpec& out);

}  // namespace dayphoton::project::detail
