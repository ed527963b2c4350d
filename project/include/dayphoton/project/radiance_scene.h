// RADIANCE scene reader: scene description files (.rad) -> mapped materials and planar
// surfaces in model coordinates (metres), for `geometry.radiance` (docs/radiance-import.md).
//
// Syntax (G. Ward, "The RADIANCE 5.x Synthetic Imaging System", reference manual, section
// "Scene Description"): every primitive is
//     modifier type identifier
//     N string arguments...   M integer arguments...   K real arguments...
// in free format (words separated by any white space; a string in double quotes may hold
// spaces). Between primitives, `#` starts a comment to the end of the line and `!` a command
// that RADIANCE would run in a shell. Files are read in order, as oconv reads them: a
// modifier must be defined before a primitive uses it, and a later definition of a name
// replaces the earlier one for the primitives after it.
//
// Read:
//   - modifiers: the materials of radiance_material.h (plastic, metal, trans, mirror, glass,
//     dielectric), `void` (surfaces skipped: RADIANCE traces through them), light sources
//     (light, glow, spotlight, illum: surfaces skipped; an illum with an alternate material
//     takes that material, as every ray but a source sample sees it), `alias` (void, inherit
//     or a material modifier, naming an earlier modifier);
//   - surfaces: polygon; ring, cylinder/tube, cone/cup, sphere/bubble tessellated so that no
//     point of the true surface is further than RadianceTessellationTolerance_m from the
//     facets (chord sagitta), with RadianceMinSegments..RadianceMaxSegments segments per full
//     circle; tube, cup and bubble face inward as in RADIANCE; spheres are closed solids
//     (Surface::solid_face); `source` (a distant source) is skipped with a note;
//   - `!xform` commands with only -t, -rx, -ry, -rz, -s, -i and -n, files relative to the file
//     that names them: read in place, transformed (xform's semantics: transforms apply in the
//     order written; -i N repeats the transforms that follow it, up to the next -i, N times).
// Refused, as located errors (file:line:column, naming the primitive): any other `!` line
// (never executed: expand it first and read its output), other xform options, compiled
// meshes and instances, patterns/textures/mixtures/BSDFs and other modifiers dayphoton does
// not model (radiance_material.h says why), unknown types, bad argument counts or values,
// undefined modifiers. With skip_unsupported, modifiers and primitives that are valid
// RADIANCE but not modelled (Unsupported) are skipped with a warning instead; syntax errors
// and bad values stay errors.
// Units: the scene's unit is the metre unless RadianceSceneOptions::metres_per_unit says
// otherwise (the project's `units` key); the result is in metres either way.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project {

/// Largest distance, metres, between a tessellated curved surface and its facets.
constexpr double RadianceTessellationTolerance_m = 0.005;
/// Segments per full circle of a tessellated ring, cylinder, cone or sphere: at least (so a
/// small cylinder stays round) and at most (so a huge ring stays a reasonable number of
/// facets; its deviation then exceeds the tolerance, noted).
constexpr int RadianceMinSegments = 12;
constexpr int RadianceMaxSegments = 256;
/// Nesting depth of `!xform` files (a file that includes itself is refused at once).
constexpr int RadianceMaxXformDepth = 16;
/// Largest `-i` count of an `!xform` (each repetition is a matrix product).
constexpr long long RadianceMaxXformIterations = 10000;
/// Warnings kept per scene (the rest are counted in one more).
constexpr int RadianceMaxWarnings = 20;

struct RadianceSceneOptions {
  bool skip_unsupported = false;  ///< `unsupported: skip`
  /// Metres per unit of the scene (`units`, project/length_units.h): every coordinate, radius
  /// and `!xform -t` is scaled by it, and lengths in materials are converted
  /// (radiance_material_in_metres), as if the files were read under `!xform -s` of it.
  double metres_per_unit = 1.0;
};

/// One planar facet read from the scene.
struct RadianceSurface {
  std::string name;            ///< the primitive's identifier; tessellated pieces "<id>.<k>"
  std::string modifier;        ///< the modifier named on the primitive
  std::string material_modifier;  ///< the RADIANCE name of the material it resolved to
  int material = -1;           ///< index into RadianceScene::materials
  std::vector<Vec3> vertices;  ///< model coordinates, metres; winding = RADIANCE's normal
  bool solid_face = false;     ///< a face of a closed solid drawn outward (sphere)
  SourceLocation location;     ///< the primitive
};

struct RadianceScene {
  /// Mapped materials, each named after its modifier; a redefinition of a name with
  /// different parameters is "<name>@<file>:<line>" (the first keeps the plain name).
  /// `location` is the definition.
  std::vector<MaterialSpec> materials;
  std::vector<RadianceSurface> surfaces;
  /// Every modifier name defined (any type), for checking a ports list.
  std::vector<std::string> modifier_names;
};

/// Read `files` in order, as one scene (paths as they should be opened and printed).
/// Problems go to `diag` (errors and warnings, located); what could be read is returned. A
/// file that cannot be opened is reported at its entry of `referenced_from` (where the
/// project names it) when there is one.
RadianceScene read_radiance_scene(const std::vector<std::string>& files,
                                  const RadianceSceneOptions& options, Diagnostics& diag,
                                  const std::vector<SourceLocation>& referenced_from = {});

/// Same, from text in memory; `path` is used in messages and to resolve `!xform` files.
RadianceScene read_radiance_scene_from_string(const std::string& text, const std::string& path,
                                              const RadianceSceneOptions& options,
                                              Diagnostics& diag);

/// Segments per full circle for radius `radius_m` (RadianceTessellationTolerance_m, clamped).
int radiance_circle_segments(double radius_m);

}  // namespace dayphoton::project
