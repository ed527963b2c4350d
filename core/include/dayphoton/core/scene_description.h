// SceneDescription: the typed, file-format-free description of what the engine must build.
// Produced by the project library from a project file (project/), consumed by the engine
// (engine/Scene). Materials are given by their physical parameters; surfaces are planar
// polygons in world coordinates (metres, +X east, +Y north, +Z up, after the site's north
// rotation); sensors are points with normals. Every element keeps its source location so
// that errors found later (e.g. by geometry validation) can still name the input line.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton {

enum class MaterialType {
  Lambertian,   ///< RADIANCE plastic: diffuse RGB reflectance + specular lobe (specularity, roughness)
  Metal,        ///< RADIANCE metal: specular lobe tinted by the RGB reflectance
  Mirror,       ///< perfect specular reflector, RGB reflectance
  Glass,        ///< thin glass: normal transmittance per RGB channel, Fresnel angular behaviour
  Dielectric,   ///< thick refracting interface (prisms): refractive index, RGB transmission
  Translucent,  ///< RADIANCE trans: plastic with diffuse/specular transmission
  Opening,      ///< fully transparent aperture (an "invisible" photon port); no scattering
  Glazing,      ///< glazing system: panes combined by the multi-layer formulas (docs/materials.md)
  /// Any other model: named by MaterialSpec::model, its parameters in
  /// MaterialSpec::parameters, everything else from its entry in the material registry
  /// (engine/material_registry.h). New models use this; they add nothing to this enum.
  Registered,
};

/// Name used in project files and messages ("lambertian", "metal", ...).
const char* material_type_name(MaterialType type);

/// One pane of a glazing system (MaterialType::Glazing), listed from the outside in. Its
/// normal-incidence optics come from exactly one of three forms (`optics`).
struct GlazingPaneSpec {
  enum class Optics {
    Transmittance,  ///< uncoated: normal transmittance `transmittance` and index n
    Absorption,     ///< uncoated: absorption coefficient `absorption_per_m` over `thickness_m`
    Coated,         ///< coated: measured normal `transmittance` and face reflectances
  };
  Optics optics = Optics::Transmittance;
  /// Transmittance / Coated: normal-incidence transmittance per RGB channel, [0,1].
  Vec3 transmittance{0, 0, 0};
  /// Absorption: absorption coefficient of the glass per RGB channel, 1/m (>= 0).
  Vec3 absorption_per_m{0, 0, 0};
  /// Pane thickness, metres (0 = not given; needed by Absorption).
  double thickness_m = 0;
  /// Uncoated panes: refractive index of the glass.
  double refractive_index = 1.52;
  /// Coated: normal-incidence reflectance of the pane's outer face (toward pane 1 / the
  /// outside) and of its inner face, per RGB channel.
  Vec3 outer_reflectance{0, 0, 0}, inner_reflectance{0, 0, 0};
  /// Coated: which face carries the coating (for messages and `check`): true = the inner face.
  bool coating_on_inner_face = false;
};

/// A material's role as a shading device (MaterialSpec::shading).
enum class ShadingRole {
  Unstated,  ///< not said: a BSDF whose file names a shading device is taken as operable
  Operable,  ///< `shading: operable`: a blind, shade or screen that is moved
  Fixed,     ///< `shading: fixed`: part of the building (a fixed screen, a fritted or diffusing glazing)
};

/// The parameters of a MaterialType::Registered model, as its registry entry's parser made
/// them from the project file. Each model derives its own struct from this one and reads it
/// back with dynamic_cast in its factory; immutable once made (shared by copies of a spec).
struct MaterialParameters {
  virtual ~MaterialParameters() = default;
};

/// A scene material. The built-in models (every MaterialType but Registered) keep their
/// parameters in the flat fields below, which several of them share; a registered model
/// keeps its own in `parameters`. The fields common to every model are the name, the type,
/// the location and `transmittance_factor`.
struct MaterialSpec {
  std::string name;
  MaterialType type = MaterialType::Lambertian;
  SourceLocation location;

  /// Lambertian/Metal/Mirror/Translucent: RGB reflectance in [0,1].
  Vec3 reflectance{0, 0, 0};
  /// Lambertian/Metal/Translucent: fraction of reflection that is specular, [0,1].
  double specularity = 0;
  /// Lambertian/Metal/Translucent: RMS facet slope (0 = perfectly smooth), [0,1].
  double roughness = 0;
  /// Glass: normal-incidence visible transmittance per RGB channel, [0,1] (not RADIANCE's
  /// transmissivity; the engine converts). Dielectric: RGB transmission per metre = 1 - absorption.
  Vec3 transmittance{0, 0, 0};
  /// Glass/Dielectric: refractive index (glass default 1.52).
  double refractive_index = 1.52;
  /// Translucent: fraction of the non-specularly-reflected light that is transmitted, [0,1].
  double transmissivity = 0;
  /// Translucent: fraction of the transmitted light that is transmitted specularly, [0,1].
  double transmitted_specular = 0;
  /// Glazing: the panes, from the outside in. Pane 1 faces the side the surface's normal
  /// points away from (for a port, the outside; port normals face into the room).
  std::vector<GlazingPaneSpec> panes;
  /// Glass/Glazing/Opening: factor on the transmitted light, (0,1]; the rest is absorbed.
  /// A room window's frame factor times its maintenance factor (docs/materials.md); 1 for
  /// every material of the project file.
  double transmittance_factor = 1.0;
  /// The type as the project file wrote it when it differs from material_type_name(type)
  /// ("plastic" is a Lambertian with a specular lobe); empty otherwise.
  std::string type_as_written;
  /// MaterialType::Registered: the model's type name in the material registry (as the
  /// project file writes it); empty for the built-in models.
  std::string model;
  /// MaterialType::Registered: the model's parameters, made by its registry entry's parser.
  std::shared_ptr<const MaterialParameters> parameters;
  /// Translucent materials and registered models that take a transmittance factor (`bsdf`):
  /// the project's `shading` key, whether the material stands for a shading device that is
  /// moved (a blind, a roller shade) or a fixed one. LM-83 takes ASE with every operable
  /// shading device retracted (study/shading_materials.h); Unstated lets a BSDF file's
  /// DeviceType decide.
  ShadingRole shading = ShadingRole::Unstated;
};

/// Which side of a port is the room (the engine's Port::normal points into it).
enum class PortFacing {
  Winding,  ///< by construction: the winding normal points into the room (generated windows,
            ///< enclosures, collectors); not tested
  Auto,     ///< decided from the scene: the side whose rays escape to the sky is outside
  In,       ///< declared: the winding normal points into the room (tested against the scene)
  Out,      ///< declared: the winding normal points out of the room (tested against the scene)
};

/// Name used in project files and messages ("auto", "in", "out"; "winding" for generated ports).
const char* port_facing_name(PortFacing facing);

/// The input element a surface was generated from. The warning about outdoor geometry that
/// only shades the ports (study/placement_check.h) names it and what makes its light traced.
enum class SurfaceOrigin {
  Other,     ///< made by code, not by a project element (tests, tools)
  Room,      ///< a room generator's wall, floor, ceiling or light well
  Polygon,   ///< geometry.polygons
  Box,       ///< geometry.boxes
  Mesh,      ///< geometry.meshes (an OBJ face; its name is the mesh's, ':', the face's)
  Radiance,  ///< geometry.radiance (a RADIANCE primitive)
  Honeybee,  ///< geometry.honeybee (an HBJSON face, aperture, door or shade)
  System,    ///< a daylight system's part (its `port` says how its light is traced)
};

/// A planar polygon with a material. Ports are openings through which photons from distant
/// sources enter (windows become ports automatically).
struct Surface {
  std::string name;
  int material = -1;           ///< index into SceneDescription::materials
  std::vector<Vec3> vertices;  ///< planar, simple; normal by winding (counter-clockwise)
  bool port = false;           ///< photons from the sky/sun enter through this surface
  SourceLocation location;
  /// An outdoor surface whose reflected and transmitted light is traced (an exterior daylight
  /// system's part): photons from the sky and sun also start where they land on it directly
  /// (either side), and scatter from there. Never also a port.
  bool outdoor_scatterer = false;
  PortFacing facing = PortFacing::Winding;  ///< ports: which side is the room
  /// A face of a closed solid drawn with outward normals (boxes, OBJ meshes): a sensor that
  /// sees the back of such faces all round lies inside a solid (engine/sensor_placement.h).
  bool solid_face = false;
  /// A port candidate (an imported scene's glazing under `ports: auto`): engine::Scene::build
  /// makes it a port (facing auto) when its facing test finds decisively that one side sees
  /// the sky (engine/port_facing.h), and an ordinary surface otherwise (interior glazing, a
  /// free-standing pane, the inner pane of a double glazing). `port` must be false.
  bool port_if_outdoors = false;
  SurfaceOrigin origin = SurfaceOrigin::Other;
  /// A port that stands for another daylight opening (a face of the box of openings around
  /// a window's exterior system): a normal of that opening's plane. Zero: the port's own
  /// plane is the opening's (study/daylight_openings.h, EN 17037's horizontal openings).
  Vec3 opening_normal{0, 0, 0};
};

struct SensorPoint {
  Vec3 position;  ///< metres
  Vec3 normal;    ///< unit vector the sensor faces
};

/// A named set of sensors. Grids generated on a plane also give the plane, so the engine can
/// place a virtual photon receiver there (DESIGN.md section 5).
struct SensorGrid {
  std::string name;
  std::vector<SensorPoint> points;
  /// A receiver plane: a horizontal room or polygon grid (all points on one plane, facing
  /// straight up or down). Wall and rectangle grids are not, even when horizontal.
  bool planar = false;
  Vec3 plane_normal{0, 0, 1};    ///< generated grids: the sensors' normal
  /// Generated grids: signed distance of the sensors' plane along plane_normal (0 for
  /// non-planar room/polygon grids).
  double plane_height_m = 0;
  /// Generated grids: the polygon the grid covers, in the sensors' plane (room floor, polygon,
  /// or the 4 corners of a wall or rectangle moved by the grid's offset).
  std::vector<Vec3> outline;
  double spacing_m = 0;          ///< for generated grids
  /// Sensors outside every room or inside a solid are dropped (counted) instead of being an
  /// error (the set's `drop_occluded` key).
  bool drop_occluded = false;
  /// For generated grids that are a full lattice (row-major, rows outer): room grids and wall
  /// and rectangle grids with no point left out; 0 otherwise.
  int columns = 0, rows = 0;
  /// The floor area each sensor stands for (m^2), one per point, when the sensors stand for
  /// unequal areas: the faces of a Honeybee grid's mesh, or a generated grid's cells cut by
  /// its outline. Empty: every sensor an equal share. Every area share and spatial mean of the
  /// grid is weighted by these (docs/metrics.md, "Sensor areas").
  std::vector<double> area_m2;
  SourceLocation location;
};

/// The type as the project file wrote it ("plastic"), for messages: type_as_written, or
/// `model` for a registered model, or material_type_name(type).
std::string material_type_as_written(const MaterialSpec& material);

/// Every position of a SceneDescription (surfaces' vertices, sensors, grid outlines and
/// planes) is held relative to `world_origin_m`: world = position + world_origin_m. The
/// engine works in the description's frame (photon positions are floats, photon.h); what a
/// user reads (result files, results.json, messages, images) is in world coordinates, through
/// world_of / world_grid. project::build_scene_description chooses the origin
/// (project/local_origin.h); (0, 0, 0) for a model drawn near the origin.
struct SceneDescription {
  std::vector<MaterialSpec> materials;
  std::vector<Surface> surfaces;
  std::vector<SensorGrid> grids;
  /// The world point at the description's (0, 0, 0), metres (whole kilometres).
  Vec3 world_origin_m{0, 0, 0};
  /// Non-fatal findings of the geometry stage, located (e.g. what a RADIANCE import left
  /// out or approximated), for `check` and the run log; Severity::Note for what is done
  /// as the user would expect but worth saying (a Honeybee grid weighted by its mesh).
  std::vector<Diagnostic> warnings;

  int find_material(const std::string& name) const;
  /// A position of the description in world coordinates (itself, bit for bit, -0 included,
  /// where the origin is (0, 0, 0)).
  Vec3 world_of(const Vec3& position_m) const {
    return world_origin_m == Vec3{0, 0, 0} ? position_m : position_m + world_origin_m;
  }
  /// A grid of the description (or one made from its sensors) in world coordinates: its
  /// sensors' positions, its outline and its plane height (normals unchanged).
  SensorGrid world_grid(const SensorGrid& grid) const;
  /// Sensors of the description in world coordinates.
  std::vector<SensorPoint> world_points(const std::vector<SensorPoint>& points) const;
};

}  // namespace dayphoton
