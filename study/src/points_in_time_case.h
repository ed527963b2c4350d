// The point-in-time cases of one case of a run (point_in_time.h): their skies, the sun bins
// and direct sun of their suns (sun_bin_steps.h), and per grid point_in_time.csv.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/study/sub_patch_shares.h"
#include "run_context.h"

namespace dayphoton::study {

/// The point-in-time cases of one case (point_in_time.h) at every grid: point_in_time.csv per
/// grid and each grid's summary.json `point_in_time` entries (`grids_json[g]`).
/// `direct_parts`: per grid, the sky coefficients' direct part with its continuous skies
/// (engine::DaylightCoefficients::direct_on_skies): a CIE case's direct part is taken from its
/// continuous sky (SimulationPlan::point_in_time_sky) instead of the patch means, as the
/// daylight factor's is. `shares`, `photon_shares`: per grid, the sub-patch shares of the
/// whole coefficients and of their photon part alone (sub_patch_shares.h): a weather case
/// takes the whole coefficients on sub-patches with its hour's quadrant deltas, as the annual
/// product does, a CIE general case its photon part with its own sky's
/// (point_in_time_cie_quadrant_deltas). `df_photon_corrections_lux`: per grid, what the basis
/// misses of the DF's photon part (continuous_sky_photon_correction_lux), which a cie_overcast
/// case, of the DF sky's shape, takes scaled to its own sky, so it stays DF x E_h / 100.
/// `sky_stop`: per grid, with an accuracy target, the sky rounds' stop for that grid ("target
/// met" where the grid met the DF's target); empty without one. With a target each case is
/// stated against it (point_in_time_accuracy.h): its sun rounds measure the cases (SunRoundCase)
/// and its direct sun's shadow rays are raised where the penumbra keeps it above the target.
void run_points_in_time(const project::Project& project, const std::string& prefix, const CaseScene& cs,
                        const std::vector<RadianceMatrix>& sky_coefficients,
                        const std::vector<engine::DaylightCoefficients>& direct_parts,
                        const std::vector<SubPatchShares>& shares, const std::vector<SubPatchShares>& photon_shares,
                        const std::vector<std::vector<double>>& df_photon_corrections_lux,
                        const std::vector<std::string>& sky_stop, const std::vector<std::string>& folders,
                        nlohmann::json& grids_json, RunContext& ctx);

}  // namespace dayphoton::study
