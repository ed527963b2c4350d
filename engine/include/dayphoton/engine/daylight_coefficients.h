// Daylight coefficients: C[s][p] = direct + caustic + global, the irradiance at sensor s per
// unit radiance of source p (DESIGN.md sections 4-5; the matrix dctimestep multiplies by a
// sky matrix).
//
//   direct  : shadow rays through the glazing (direct_component.h), the zero-event paths;
//   caustic : photons whose paths had only specular events since the port;
//   global  : photons with at least one diffuse event.
// The tracer never stores zero-event photons and the shadow rays never follow a scattered
// path, so each light path is counted once ("no double counting").
//
// Photon estimates at a sensor of a planar grid use the grid's receiver-plane photons
// (photons crossing the plane). Every other sensor (a point in mid air, a vertical or tilted
// grid, a point on a black surface) gets a final gather from its own position and normal
// (final_gather.h) over the surface photons of every class. The surface estimate (the
// surface photons on the side the sensor's normal faces, for a sensor lying on a surface
// that stores photons) remains available (GridPhotons::for_surfaces). Two estimators on
// receiver planes and surfaces:
//   - PerSource (default): for every source its own N nearest photons (one photon map per
//     source), so each coefficient has N photons behind it and its own radius; N is scaled
//     up for sources that were given more photons (GridPhotons::bandwidth_of);
//   - Contribution: seeds/001 eq. 18, the N nearest photons of all sources, binned by source.
// Boundary correction (planar grids): the kernel disc is clipped to the grid's outline (the
// room), where photons can cross, and the estimate divides by the clipped area instead of
// pi r^2 (exact for the uniform kernel; for the others the same area ratio is applied).
// Local-linear estimate (planar grids, the default): near a wall the clipped disc is
// one-sided, so a plain average over it is biased by the illuminance gradient (at the back
// of a side-lit room, toward the brighter window side). Fitting E(y) = a + b . (y - x) to the
// photons by moments over the clipped disc R (sum Phi = a A + b . m1, sum Phi (y - x) =
// a m1 + M2 b, with A, m1, M2 the area moments of R about x) gives a = E(x) free of that
// first-order bias. Away from walls m1 = 0 and a is the plain average. The moments are exact
// (ReceiverPlane::clipped_disc_moments). Where a is negative (a steep fitted gradient
// extrapolated across a wide disc, with few photons) it is set to 0, so no coefficient is
// negative.
// Local-quadratic estimate at walls (quadratic_fit_sources): the light on a work plane
// bends down towards the walls within about a metre of them (a wall hides part of the
// ceiling), and a plane fitted over a disc the wall cuts reads that concave field low, by an
// amount that grows with the disc's area. The ground bin's light enters upwards, so all of it
// reaches a work plane as photons (none is direct there), and its estimates were 7 % low at
// the back corners of the office. For the sources listed, the fit E(y) = a + b . (y - x) + (y - x)^T C (y - x) by
// moments over the same clipped disc is used where the outline cuts the disc: exact for such
// curvature. It costs 1.5-4 times the variance (its equivalent kernel has negative lobes) and
// is used for no other source and nowhere else: a sky bin's light at the walls is mostly
// direct (computed without a disc), so its photon part's curvature bias is a small share. Where the fitted total (caustic +
// global) is negative it is set to 0; each class alone is not clamped (a class with few
// photons in the disc would otherwise be biased upwards by its clamp).
// Curvature away from walls (curvature_correction): the local-linear fit over a whole disc
// of radius r reads a curved field E off by (E_xx + E_yy) r^2 / 8 (the disc's second moment
// r^2 / 4 times the Taylor term's 1/2), a bias its stated variance does not contain. Under
// an accuracy target the disc keeps its size as photons are added, so this bias never falls:
// behind a partition, where the light rises concavely away from it, the plane read 3 % low
// (4 standard errors). Two corrections (docs/photon-map.md, "Curvature away from walls"):
//   - Pilot (the default): the bias is estimated and subtracted. A quadratic fitted over the
//     pilot disc of radius R about the same centre (every photon of the source within R,
//     R = CurvaturePilotRadiusFactor r, kept inside the outline and off every cut) gives
//     E_xx + E_yy, and the estimate is the plane's minus (E_xx + E_yy) r^2 / 8. It is the
//     bias correction with a pilot bandwidth of Calonico, Cattaneo and Farrell ("On the
//     effect of bias estimation on coverage accuracy in nonparametric inference", JASA
//     113(522), 2018), whose standard error includes the bias estimate's own variance: the
//     reported variance is that of the corrected estimate, sum_j (w_lin,j - w_pilot,j)^2 y_j^2,
//     about 1.3 times the plane's at R = 2r (the pilot's 4 R^2 / r^2 times more photons
//     average its noise out), 4 times at R = r, where it is the quadratic fit itself.
//   - Quadratic: the local-quadratic fit on the disc itself, exact for every quadratic field
//     at 4 times the variance.
// Curvature at cut discs (Pilot): where the outline or the visibility clip cuts a disc (every
// disc of a shaft's or a light well's narrow floor) and the source is not one of
// quadratic_fit_sources, the same correction with the pilot disc clipped by the same walls and
// cuts (local_quadratic_fit.h, cut_curvature_pilot): the local-linear fit's bias over the cut
// disc from its moments, the curvature from a quadratic fitted over the clipped pilot, its
// noise in the reported variance (docs/photon-map.md, "Curvature at cut discs").
// Sparse sources: a source with fewer photons than the median source (a low-yield source cut
// by the photon cap, a sky patch seen through a sliver) would need a disc far wider than the
// others' for the same N, and the plane fitted over it would smear its light over the room.
// Its bandwidth is therefore scaled down with its count (bandwidth_of, never below
// MinimumSourceBandwidth), which keeps its disc about as wide as the other sources'; and on
// a receiver plane no disc is wider than MaxRadiusFactor times the radius that the median
// source's photons, spread evenly over the plane's outline, would give for the bandwidth
// (ReceiverPlane outline area): where a source has no photons that near, the estimate is the
// fixed-radius one over what is there (zero where there is nothing), so light stays where
// it falls.
// Visibility clip (visibility_clip): the light on a work plane jumps across a partition or a
// column that crosses it, and around the re-entrant corner of an L-shaped room; a disc that
// spans them would carry the lit side's light into the shadow. Where one lies within a
// sensor's widest disc, the estimate keeps to the photons the sensor's position sees in the
// plane and fits over the region it sees (plane_visibility.h): the outline clip above, with
// the boundary the cuts add.
// Sensors next to a cut (plane_cuts.h): within NearCutGather_m of a column or a partition the
// light changes faster than any disc follows, and the visibility clip alone left the plane's
// estimate -9 % in front of a column and +19 % behind it. Given the gather photons
// (GridPhotons::set_near_cut_gather), photon_coefficients estimates those sensors' photon
// part by final gather (final_gather.h) from the sensor's position and the plane's normal,
// with its own variance, as a point sensor is, and the others by the plane; the direct part
// (shadow rays) is the same for both. The rows stay the grid's rows, in its order.
// Caustic map (caustic_bandwidth > 0): caustic photons get a lookup of their own, among
// caustic photons only, with their own bandwidth, as Jensen's separate caustic map
// (seeds/000 section 3.1.3). A sharp caustic (a mirror shelf's reflection on the ceiling,
// a prism's beam) is then resolved by the caustic photons' own spacing instead of a disc
// that the (sparser) global photons set. Otherwise both classes share one disc, from one
// lookup over both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/density_estimate.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/final_gather.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/photon.h"
#include "dayphoton/engine/photon_map.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_range.h"
#include "dayphoton/engine/sky_ratios.h"

namespace dayphoton::engine {

enum class PhotonEstimator { PerSource, Contribution };

/// The pilot disc of the curvature correction is at most this many times the kernel disc's
/// radius (header comment, "Curvature away from walls"): wider averages the bias estimate's
/// noise further (its variance falls as (r / R)^6) at the cost of the pilot's lookup, and
/// reads the curvature over a wider field.
constexpr double CurvaturePilotRadiusFactor = 2.0;

/// How a whole disc's curvature bias is treated on a receiver plane (header comment).
enum class CurvatureCorrection : std::uint8_t {
  None,       ///< the local-linear fit alone; its bias stays
  Pilot,      ///< the plane's estimate minus the bias a wider pilot disc's quadratic estimates
  Quadratic,  ///< the local-quadratic fit on the disc itself
};

/// Per-source bandwidths are never scaled below this many photons (sparse sources, above).
constexpr std::size_t MinimumSourceBandwidth = 8;
/// On a receiver plane, kernel discs are at most this many times the median source's
/// even-spread radius (sparse sources, above).
constexpr double MaxRadiusFactor = 4.0;

struct CoefficientOptions {
  DensityEstimateOptions density;  ///< bandwidth (photons per estimate), max radius, kernel
  /// Photons per caustic estimate, from caustic photons only (header comment); 0: caustic
  /// and global photons share the disc of density.bandwidth photons of both classes.
  std::size_t caustic_bandwidth = 0;
  PhotonEstimator estimator = PhotonEstimator::PerSource;
  bool boundary_correction = true;
  /// Planar grids, PerSource, uniform kernel: local-linear density estimate instead of the
  /// clipped-disc average (see the header comment); removes the first-order bias of a
  /// gradient across a disc that a wall cuts, so larger bandwidths stay unbiased.
  bool local_linear = true;
  /// With local_linear: the sources (indices, any order) whose discs get the local-quadratic
  /// fit (local_quadratic_fit.h) where the outline cuts them (see the header comment). Empty:
  /// none. The study lists the ground bin of the sky's sources (SimulationPlan).
  std::vector<std::size_t> quadratic_fit_sources;
  /// With local_linear: the correction of the curvature bias on every whole disc (none of it
  /// cut by the outline or the visibility clip) that holds its whole bandwidth, for every
  /// source (see the header comment, "Curvature away from walls"); with Pilot, on cut discs
  /// too, by a pilot clipped as the disc ("Curvature at cut discs"), except for
  /// quadratic_fit_sources, whose cut discs keep the quadratic. Its variance is reported, so
  /// accuracy rounds trace what it needs.
  CurvatureCorrection curvature_correction = CurvatureCorrection::Pilot;
  /// Receiver planes: where an interior cut (a partition, a column: plane_cuts.h, set on the
  /// plane) or a re-entrant corner of the outline lies within a sensor's widest disc, count
  /// only the photons the sensor's position sees in the plane, over the region it sees
  /// (plane_visibility.h). Off: the outline clip alone (the disc spans partitions).
  bool visibility_clip = true;
  /// Bias-compensating operator (seeds/000 chapter 5, density_estimate.h) instead of the
  /// fixed bandwidth: per source (PerSource) or on the total (Contribution), with
  /// n_min = the bandwidth and n_max = bias_compensation_max_factor x n_min.
  bool bias_compensation = false;
  std::size_t bias_compensation_max_factor = 10;
  std::uint64_t seed = 1;  ///< for the operator's random numbers
  DirectOptions direct;
  GatherOptions gather;    ///< sensors estimated by final gather (GridPhotons::for_gather)
  /// The bin radiances L_p the photons' sky ratios were taken against (sky_ratios.h), RGB
  /// W/(sr m^2), one per source: daylight_coefficients then also gives the photon part under
  /// the ratios' continuous sky (DaylightCoefficients::photon_on_sky, photon_part_on_sky.h).
  /// Empty: not estimated.
  std::vector<Vec3> photon_sky_bin_radiance_rgb;
  /// With photon_sky_bin_radiance_rgb: the sky ratios the photons were traced with
  /// (TracingOptions::sky_ratios), which the rows a final gather estimates need for their paths
  /// that leave to the sky (final_gather.h, "The continuous sky"). Null: those rows keep the
  /// basis sum (PhotonOnSky::basis_rows).
  std::shared_ptr<const SkyRatios> photon_sky_ratios;
  /// Also estimate the photon part's sub-patch shares (DaylightCoefficients::photon_quadrants):
  /// the same estimate with each flux times the indicator of its sky quadrant (photon.h), from
  /// the same lookups. For the bins of a basis (the photons' quadrants are those of their bins).
  bool photon_quadrants = false;
};

/// The photon part (caustic + global) of every sensor under the continuous sky its photons'
/// sky ratios come from (photon_part_on_sky.h): [row], RGB W/m^2, and the variance of its
/// luminance. Empty when not estimated.
struct PhotonOnSky {
  std::vector<Vec3> irradiance;
  std::vector<double> variance;
  /// Rows a final gather estimated without the sky ratios (CoefficientOptions::
  /// photon_sky_ratios not given), which keep the sum over the basis (photon_part_on_sky.h):
  /// how many.
  std::size_t basis_rows = 0;
  bool empty() const { return irradiance.empty(); }
};

/// The three parts of C, each [sensor * sources + source], RGB W/m^2 per unit radiance.
struct DaylightCoefficients {
  std::size_t sensors = 0, sources = 0;
  std::vector<Vec3> direct, caustic, global;
  /// The Monte Carlo variance of each entry's luminance (estimate_variance.h), same layout:
  /// of the direct part (shadow rays) and of the photon part (caustic + global). The sources
  /// are independent, so the variance of any sky-weighted sum at a sensor is
  /// sum_p L_p^2 variance(s, p). Empty when not estimated.
  std::vector<double> direct_variance, photon_variance;
  /// The direct part under each continuous sky of CoefficientOptions::direct.skies, from the
  /// same shadow rays (direct_component.h, "Continuous skies"): [sensor * skies + k], with
  /// its variance; empty without skies.
  DirectOnSkies direct_on_skies;
  /// The direct part's sub-patch shares (direct_component.h, "Sub-patch shares"): [sensor *
  /// sources * StoredQuadrants + p * StoredQuadrants + q], the luminance of direct[s][p]'s part
  /// in quadrant q of sky bin p; empty when the sources are not a basis's bins.
  std::vector<float> direct_quadrants;
  /// The photon part's sub-patch shares (CoefficientOptions::photon_quadrants), same layout:
  /// the luminance of (caustic + global)[s][p]'s part that photons emitted into quadrant q of
  /// sky bin p carry (and, for a final gather, specular paths leaving through it); empty when
  /// not estimated. The annual product adds them to the direct part's (study/sub_patch_shares.h).
  std::vector<float> photon_quadrants;
  /// The photon part under the daylight factor's continuous sky (photon_part_on_sky.h), when
  /// the photons carry its sky ratios; empty otherwise.
  PhotonOnSky photon_on_sky;

  Vec3 total(std::size_t s, std::size_t p) const {
    const std::size_t i = s * sources + p;
    return direct[i] + caustic[i] + global[i];
  }
  bool has_variance() const {
    return direct_variance.size() == sensors * sources && photon_variance.size() == sensors * sources;
  }
  /// Variance of total(s, p)'s luminance: the two parts are independent.
  double variance(std::size_t s, std::size_t p) const {
    const std::size_t i = s * sources + p;
    return direct_variance[i] + photon_variance[i];
  }
  /// rows = sensors, columns = sources, 3 components (RADIANCE matrix layout).
  RadianceMatrix to_matrix() const;
};

/// The photons one grid's estimates use, arranged for lookups.
class GridPhotons {
 public:
  /// Photons of a planar grid's receiver plane (`plane_photons`, all sources).
  static GridPhotons for_plane(const ReceiverPlane& plane, std::vector<Photon> plane_photons,
                               std::size_t source_count);
  /// Surface photons (for sensors lying on surfaces); Direct photons, if any, are dropped.
  static GridPhotons for_surfaces(std::vector<Photon> surface_photons, std::size_t source_count);
  /// Surface photons of every class, Direct included, for a final gather (final_gather.h).
  static GridPhotons for_gather(std::vector<Photon> surface_photons, std::size_t source_count);

  bool planar() const { return m_plane.has_value(); }
  bool gather() const { return m_gather; }
  const ReceiverPlane* plane() const { return m_plane ? &*m_plane : nullptr; }
  /// The photons of every source in one map (the contribution estimate, the final gather).
  /// Built on first use for plane and surface photons: the default per-source estimate
  /// never needs it (thread-safe).
  const PhotonMap& all() const;
  /// Gather photons: which of all() come from the same paths (final_gather.h, "Variance").
  const PhotonGroups& groups() const { return m_groups; }
  const PhotonMap& of_source(std::size_t p) const { return m_by_source[p]; }
  std::size_t source_count() const { return m_source_count; }
  /// PerSource bandwidth of `source`: `bandwidth` x (its photon count / the median count
  /// over sources with photons), never less than min(bandwidth, MinimumSourceBandwidth).
  /// Sources given more photons (TracingOptions::source_photon_factor) thus get the same
  /// kernel radius as the others and a proportionally less noisy estimate, and sparse
  /// sources a disc no wider than the others' (header comment).
  std::size_t bandwidth_of(std::size_t source, std::size_t bandwidth) const;
  /// The same for the photons of one class (the caustic map and its global counterpart):
  /// scaled by the source's count of that class against the median over sources that have
  /// any. A caustic target of their own makes caustic counts unlike global ones, so the
  /// total would give the global lookups of sun-lit sources needlessly wide discs.
  std::size_t bandwidth_of(std::size_t source, std::size_t bandwidth, PathClass path_class) const;
  /// Receiver planes: the widest kernel disc for `bandwidth` photons of the median source,
  /// MaxRadiusFactor x sqrt(bandwidth x outline area / (pi x median count)); infinity
  /// elsewhere or without photons.
  double max_radius_m(std::size_t bandwidth) const;
  /// Accuracy rounds (photon_rounds.h): `scale[p]` is source p's photon count relative to
  /// the reference count the bandwidth is meant for. The typical counts then become the
  /// median over sources of (count / scale), the count at the reference, so a source with
  /// scale 2 gets twice the bandwidth over the same disc (half the variance), and the same
  /// when every source is scaled alike. Without it (the default) the typical count is the
  /// median count, and scaling every source alike only shrinks the discs.
  void set_source_scale(const std::vector<double>& scale);
  /// Receiver planes: the gather photons (for_gather, of the same sources) that the plane's
  /// sensors nearer than NearCutGather_m to an interior cut (plane_cuts.h, "Sensors next to a
  /// cut") are estimated from, by final gather as a point sensor is (header comment, "Sensors
  /// next to a cut"); shared, e.g. with the case's gathered grids. Null: every sensor by the
  /// plane. Throws std::invalid_argument on surface or gather photons, or for photons that are
  /// not gather photons of as many sources.
  void set_near_cut_gather(std::shared_ptr<const GridPhotons> gather);
  const GridPhotons* near_cut_gather() const { return m_near_cut_gather.get(); }

 private:
  static std::size_t median_count(const std::vector<PhotonMap>& maps);
  std::optional<ReceiverPlane> m_plane;
  bool m_gather = false;
  std::size_t m_source_count = 0;
  /// all(): the photons until first use, then their map.
  struct AllPhotons {
    std::once_flag built;
    std::vector<Photon> photons;
    PhotonMap map;
  };
  std::shared_ptr<AllPhotons> m_all = std::make_shared<AllPhotons>();
  PhotonGroups m_groups;  ///< gather photons only
  std::vector<PhotonMap> m_by_source;
  std::size_t m_typical_count = 0;
  std::vector<std::size_t> m_class_counts[2];   ///< per source: caustic [0], global [1]
  std::size_t m_typical_class_count[2] = {0, 0};
  std::shared_ptr<const GridPhotons> m_near_cut_gather;
  void count_classes();
};

/// `rows` (the three functions below): only those sensors' rows are estimated, and `out` holds
/// rows.size() sensors (sensor_range.h: random numbers by the index in the whole of `sensors`,
/// so they are the whole grid's rows bit for bit; a block of an MPI rank, docs/cluster.md).

/// Photon part (caustic, global) of the coefficients at `sensors` from receiver-plane or
/// surface photons; parallel over sensors, deterministic. `out` must be sized (sensors x
/// sources) in caustic/global; its photon_variance is filled (estimate_variance.h: the sum
/// of the squared luminance terms of the photons each estimate sums, through the
/// local-linear fit's weights on a receiver plane). Throws std::invalid_argument for gather photons (they need
/// the scene: daylight_coefficients or photon_coefficients). With `weighted`, the same estimate
/// with every flux times its sky ratio (PhotonFlux::TimesSkyRatio, photon_part_on_sky.h) is made
/// into it (its caustic, global and photon_variance, sized here), on the local-linear plane from
/// the same lookups: each value bit for bit that of a call with options.density.flux =
/// TimesSkyRatio.
void estimate_photon_coefficients(const GridPhotons& photons,
                                  const std::vector<SensorPoint>& sensors,
                                  const CoefficientOptions& options, DaylightCoefficients& out,
                                  SensorRange rows = {}, DaylightCoefficients* weighted = nullptr);

/// The photon part for any kind of GridPhotons (a final gather for for_gather photons, and at
/// a receiver plane's sensors next to a cut when it has near-cut gather photons). With
/// `weighted` (not for gather photons), estimate_photon_coefficients' ratio-weighted estimate
/// too, of every row the plane estimates (the rows a gather replaces in `out` keep it there).
/// With options.photon_sky_bin_radiance_rgb, out.photon_on_sky as well (photon_part_on_sky.h),
/// from the same lookups.
void photon_coefficients(const Scene& scene, const std::vector<Material>& materials,
                         const SourceSet& sources, const GridPhotons& photons,
                         const std::vector<SensorPoint>& sensors,
                         const CoefficientOptions& options, DaylightCoefficients& out,
                         SensorRange rows = {});

/// Everything: direct by shadow rays plus the photon estimates.
DaylightCoefficients daylight_coefficients(const Scene& scene,
                                           const std::vector<Material>& materials,
                                           const SourceSet& sources, const GridPhotons& photons,
                                           const std::vector<SensorPoint>& sensors,
                                           const CoefficientOptions& options,
                                           SensorRange rows = {});

}  // namespace dayphoton::engine
