// The annual product's sub-patch correction (docs/direct-component.md, "Continuous skies";
// engine/direct_component.h, "Sub-patch shares"). A sky matrix holds one value L_p(t) per
// patch and hour, and the patch-uniform product sum_p C[s][p] L_p(t) misses the sky's
// variation inside a patch where the sensor weights it by its cosine or sees part of it
// through an opening. The direct part's coefficient is split into the luminances Q[s][p][q]
// of its parts in the patch's four quadrants, and the annual product adds
//
//   179 sum_p sum_q Q[s][p][q] (L_pq(t) - L_p(t))  lux,
//
// L_pq the sky's mean luminance over quadrant q (sky::SkyMatrix::quadrant_deltas gives
// L_pq - L_p), so the direct part sees a sky uniform over each quadrant instead of each
// patch. The photon part's shares (engine::DaylightCoefficients::photon_quadrants, from the
// quadrant each sky photon was emitted into) are added to the direct part's, so the whole
// coefficient sees the quadrants. Only the first three Q are stored (engine::StoredQuadrants):
// the fourth is the coefficient's luminance less their sum.
#pragma once

#include <cstddef>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/daylight_coefficients.h"

namespace dayphoton::study {

/// Per sensor and sky bin, what the correction multiplies: [s * bins * ValuesPerBin + p *
/// ValuesPerBin + k], k = 0 the luminance of the coefficient C[s][p] (direct + photon; the direct
/// part alone when the photon part has no shares), k = 1..3 the luminances Q[s][p][0..2] of
/// the same parts (W/m^2 per unit radiance). Empty: no correction (coefficients
/// without shares: a basis-less source set, or coefficients read from a file).
struct SubPatchShares {
  static constexpr std::size_t ValuesPerBin = 4;
  std::size_t sensors = 0, bins = 0;
  std::vector<float> values;
  bool empty() const { return values.empty(); }
  /// Rows [begin, end) (a block of a grid's sensors).
  SubPatchShares rows(std::size_t begin, std::size_t end) const;
};

/// The export beside coefficients_sky.mtx (docs/outputs.md): a RADIANCE matrix of sensors x
/// bins x ValuesPerBin components, SubPatchShares::values as they are.
inline constexpr const char* SubPatchSharesFileName = "coefficients_sky_quadrants.mtx";
RadianceMatrix sub_patch_shares_matrix(const SubPatchShares& shares);
/// The shares of a matrix read from SubPatchSharesFileName; std::invalid_argument unless it
/// has `sensors` rows, `bins` columns and ValuesPerBin components.
SubPatchShares sub_patch_shares_of(const RadianceMatrix& m, std::size_t sensors, std::size_t bins);

/// What `dayphoton annual` says of exported coefficients (coefficients.mtx holds the total
/// per patch, not its shares): its table is the patch-uniform product.
inline constexpr const char* SubPatchSharesMissingWarning =
    "no coefficients_sky_quadrants.mtx beside the coefficients (the coefficients' sub-patch shares), so "
    "this annual table is the patch-uniform product: the run's own table adds the sub-patch "
    "correction and differs from it (docs/outputs.md, \"Which sky the annual files use\")";
/// And of a sky matrix file, which has no quadrant deltas.
inline constexpr const char* SkyMatrixFileQuadrantsWarning =
    "a sky matrix file has no quadrant deltas, so this annual table is the patch-uniform product (the "
    "sub-patch shares of coefficients_sky_quadrants.mtx are not used): a run's own table adds the "
    "sub-patch correction (docs/outputs.md, \"Which sky the annual files use\")";

/// And of one sky vector (`annual --sky-vector`): coefficients x patch values, what dctimestep
/// computes, which has neither the sub-patches nor the continuous sky of the run's daylight factor.
inline constexpr const char* SkyVectorPatchUniformNote =
    "the coefficients times one sky vector is the patch-uniform product (as dctimestep computes it): under the "
    "CIE overcast sky it differs from the run's daylight factor x E_h / 100, which takes the continuous sky "
    "(measured on the reference office's work plane: +0.55 % on average, up to 1.5 %; docs/outputs.md, "
    "\"daylight_factor.csv\")";

/// Which parts of a coefficient the shares are of.
enum class SharesOf {
  /// The whole coefficient (direct + photon; the direct part alone when the photon part has
  /// no shares): the annual product's and a weather point-in-time case's.
  Coefficient,
  /// The photon part alone (caustic + global and DaylightCoefficients::photon_quadrants): a
  /// CIE point-in-time case's, whose direct part comes from its continuous sky.
  PhotonPart,
};

/// The shares of coefficients `c` (empty when c.direct_quadrants is, or for PhotonPart when
/// c.photon_quadrants is). Throws std::invalid_argument when the shares do not match the
/// coefficients' shape.
SubPatchShares sub_patch_shares(const engine::DaylightCoefficients& c, SharesOf of = SharesOf::Coefficient);

/// Per sensor, the sub-patch correction of one sky column (lux): 179 sum_p sum_q Q[s][p][q]
/// d_pq, d = `quadrant_deltas` ((4 x bins) x steps x 1, sky::SkyMatrix::quadrant_deltas'
/// layout) at `column`, the same sum annual_illuminance adds with these shares. Zeros for
/// empty shares; std::invalid_argument if the shapes do not match.
std::vector<double> sub_patch_correction_lux(const SubPatchShares& shares, const RadianceMatrix& quadrant_deltas,
                                             std::size_t column);

}  // namespace dayphoton::study
