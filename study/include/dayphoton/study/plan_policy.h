// The run's policy constants, each declared once: the photon allocation between sources,
// the sun bins' share of photons and bandwidth, the shadow rays of the direct sun and the
// daylight-factor sky. `dayphoton run`, `annual` and `render` read them from here (through
// SimulationPlan, simulation_plan.h, or directly); summary.json `simulation` records those a
// user may want to audit (docs/outputs.md). Changing one changes results: the cache keys
// include each through the options it sets (cache_keys.h).
#pragma once

#include <cstddef>
#include <cstdint>

namespace dayphoton::study {

/// Photons per source relative to a sky bin for the ground bin 0: Neyman allocation for the
/// CIE overcast sky (the ground brings ~20 % of the light through a vertical window, a
/// Tregenza sky bin ~1 %); see engine::TracingOptions::source_photon_factor. Measured on the
/// office: per-sensor DF RMS 2.95 % -> 1.56 % at +20 % photons (docs/photon-tracing.md).
constexpr double GroundPhotonFactor = 16.0;

/// The daylight-factor sky: CIE overcast of this horizontal illuminance (the DF does not
/// depend on it).
constexpr double OvercastHorizontalLux = 10000.0;

/// Shadow rays per hour and sensor for the direct sun. The disc is 1/800 of a Tregenza
/// patch, so T cos is constant over it except at a shadow edge; a 4 x 4 stratification puts
/// the penumbra (about 3 cm wide 3 m behind a window edge) into 4 stripes. A sensor in a
/// penumbra then errs by at most one stratum's share, 1/4 of the edge strata it crosses.
constexpr int SunDirectSamples = 16;

/// Shadow rays per bin (per sensor and sky source) up to which the accuracy rounds may raise
/// a grid's direct component when its shadow-ray variance is what keeps the grid above the
/// target (docs/photon-tracing.md "Accuracy target"). 256 = 16 x 16 strata, 16 times the
/// default direct_samples_per_bin: at an edge the direct variance falls as n^(-3/2)
/// (direct_component.h), so the limit removes 98 % of the default's variance there, for
/// about 70 000 shadow rays per sensor with the Tregenza sky (145 patches and the ground,
/// plus the port points): 0.7 billion for a 10 000-sensor grid, which the rounds only trace
/// when it costs fewer rays than the photons that would do the same. A project that sets
/// direct_samples_per_bin above it keeps its own count.
constexpr int MaxDirectSamplesPerBin = 256;

/// Stored photons of a sun bin relative to a sky bin (photons_per_bin). The sun bins are
/// many (about 1000 for MF 6 in the office) and an hour's sun averages up to 4 of them, so
/// each needs fewer photons than a sky bin for the same hourly noise; the measured trade
/// of time against the error of the annual illuminance is in docs/sun.md.
constexpr double SunBinPhotonFraction = 0.1;

/// A sun bin is traced only if its emission bound (engine::PortEmitter::bound_flux, an upper
/// bound of the flux its disc sends through the ports per unit radiance) is at least this
/// fraction of the largest bin's. The others get zero coefficients: the light they could
/// bring in is below 1 % of the brightest bin's, and what they do bring arrives at grazing
/// incidence. Without the rule, the bins whose disc straddles a window's plane (azimuth
/// exactly along a facade: bound 2.4e-6 against 2.4e-4, and glass that reflects nearly all of
/// it) take 10-50 s each in the office: 2e8 emission attempts for 10^4 stored photons.
constexpr double SunBinMinimumBoundFraction = 0.01;

/// Nearest photons per sun-bin estimate relative to the project's bandwidth (at least
/// SunBinMinimumBandwidth). A sun bin has a tenth of a sky bin's photons, so with the sky's
/// bandwidth its kernel would be sqrt(10) times wider; in the office that bias reached +5 %
/// in the middle of the room and -9 % at the back wall (a convex decay, which a local-linear
/// fit over a one-sided disc underestimates). A quarter of the bandwidth keeps the kernel
/// 1.6 times the sky's: per-row bias -2.4 to +3.5 % against 10 times the photons, for
/// 25 % more noise per hour, which the annual sums average out (docs/sun.md).
constexpr double SunBinBandwidthFraction = 0.25;
constexpr std::size_t SunBinMinimumBandwidth = 16;

/// Under MPI (docs/cluster.md), a missing photon step of a batch is traced in attempt ranges
/// over the ranks (photon_range_step.h) when its predicted cost exceeds 1/SplitSourceFactor of
/// one rank's share of the batch: cost x ranks x SplitSourceFactor > the batch's total cost.
/// The steps left whole are then each at most 1/8 of a rank's share, and a list schedule's
/// makespan is at most the perfect share plus its largest job (R. L. Graham, "Bounds on
/// multiprocessing timing anomalies", SIAM J. Appl. Math. 17(2), 1969), so within 12.5 % of
/// it. This splits every source of a batch with fewer than 8 sources per rank, and the ground
/// bin (16 sky bins' photons) of the 146 Tregenza sources from 2 ranks on.
constexpr double SplitSourceFactor = 8.0;

/// The smallest attempt range of a split pass: four of the tracer's 1024-attempt blocks, so a
/// rank's threads have blocks to share. A pass shorter than two of these is not split.
constexpr std::uint64_t MinSplitRangeAttempts = 4096;

/// Sensors per block when a grid's estimates (sky and sun coefficients, direct sun) are shared
/// out over the ranks of an MPI run (sensor_blocks.h, docs/cluster.md "Sensor blocks"). Small
/// enough that the office's 165-sensor grid makes 11 blocks for 2 or 3 ranks to balance
/// (a rank's share differs from an even one by at most one block), large enough that the
/// 10,000-sensor open plan makes 625 messages, not 10,000. Changes no result: every block's
/// rows are those of the whole grid (engine/sensor_range.h), so it is no part of a cache key.
constexpr std::size_t SensorBlockSize = 16;

}  // namespace dayphoton::study
