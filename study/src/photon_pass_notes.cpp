// Photon-pass notes: see photon_pass_notes.h.
#include "photon_pass_notes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dayphoton/engine/estimate_variance.h"

namespace dayphoton::study {
namespace {

std::string percent_text(double x) { return std::to_string(static_cast<long long>(std::lround(100 * x))); }

/// Capped sources, and the least and most share of its global target any of them stored.
struct CappedCount {
  std::size_t capped = 0;
  double least = 1, most = 0;
};

CappedCount count_capped(const engine::TracedPhotons& photons, const engine::TracingOptions& tracing) {
  CappedCount c;
  for (std::size_t p = 0; p < photons.tallies.size(); ++p) {
    const engine::SourceTally& t = photons.tallies[p];
    if (!t.capped) continue;
    ++c.capped;
    const double factor = p < tracing.source_photon_factor.size() ? tracing.source_photon_factor[p] : 1.0;
    const double share = double(t.stored_global) / (double(tracing.photons_per_source) * factor);
    c.least = std::min(c.least, share);
    c.most = std::max(c.most, share);
  }
  return c;
}

}  // namespace

double capped_flux_share(const engine::TracedPhotons& photons, double below_photons) {
  std::vector<char> counted(photons.tallies.size(), 0);
  for (std::size_t p = 0; p < photons.tallies.size(); ++p)
    counted[p] = photons.tallies[p].capped && double(photons.tallies[p].stored_global) < below_photons;
  double capped = 0, all = 0;
  auto add = [&](const std::vector<engine::Photon>& list) {
    for (const engine::Photon& ph : list) {
      const double y = engine::luminance_of(ph.flux_rgb());
      all += y;
      if (ph.source < counted.size() && counted[ph.source]) capped += y;
    }
  };
  add(photons.surface);
  for (const std::vector<engine::Photon>& plane : photons.planes) add(plane);
  return all > 0 ? capped / all : 0.0;
}

LiftedCap lifted_cap_sources(const std::vector<engine::TracedPhotons>& per_source, std::size_t bandwidth,
                             bool scatterers) {
  LiftedCap lifted;
  if (!scatterers) return lifted;
  const double starved = StarvedBandwidths * double(bandwidth);
  double capped = 0, all = 0;
  for (std::size_t p = 0; p < per_source.size(); ++p) {
    const engine::TracedPhotons& t = per_source[p];
    double y = 0;
    for (const engine::Photon& ph : t.surface) y += engine::luminance_of(ph.flux_rgb());
    for (const std::vector<engine::Photon>& plane : t.planes)
      for (const engine::Photon& ph : plane) y += engine::luminance_of(ph.flux_rgb());
    all += y;
    if (!t.tallies.empty() && t.tallies[0].capped && double(t.tallies[0].stored_global) < starved) {
      lifted.sources.push_back(p);
      capped += y;
    }
  }
  lifted.flux_share = all > 0 ? capped / all : 0.0;
  if (lifted.flux_share < CappedFluxWarningShare) lifted.sources.clear();
  return lifted;
}

std::string lifted_cap_note(const LiftedCap& lifted, const engine::TracingOptions& tracing, std::size_t bandwidth,
                            const std::string& what) {
  if (lifted.sources.empty()) return "";
  return std::to_string(lifted.sources.size()) + " " + what + " capped below " +
         std::to_string(static_cast<long long>(StarvedBandwidths * double(bandwidth))) + " photons carried " +
         percent_text(lifted.flux_share) + " % of the stored photon flux: traced again with the cap in raw attempts (" +
         std::to_string(tracing.max_mainpass_attempts_per_target) +
         " per target photon, not scaled by the outdoor scatterers' share)";
}

std::string capped_warning(const engine::TracedPhotons& photons, const engine::TracingOptions& tracing,
                           std::size_t bandwidth, const std::string& what) {
  const CappedCount c = count_capped(photons, tracing);
  if (c.capped == 0) return "";
  const double starved = StarvedBandwidths * double(bandwidth);
  const double share = capped_flux_share(photons, starved);
  if (share < CappedFluxWarningShare) return "";
  return "simulation.max_attempts_per_photon: " + what + " capped at " +
         std::to_string(tracing.max_mainpass_attempts_per_target) +  " attempts per target photon that stored fewer than " +
         std::to_string(static_cast<long long>(starved)) + " photons (" + std::to_string(StarvedBandwidths) +
         " x the bandwidth; " + std::to_string(c.capped) + " capped, " +
         percent_text(c.least) + "-" + percent_text(c.most) + " % of their target) carry " + percent_text(share) +
         " % of the stored photon flux: their density estimates spread over wide discs, a kernel bias that "
         "df_stderr_percent and the photon variance do not include, so the stated uncertainty does not cover "
         "these results (a light pipe under an outdoor roof, starved this way, read 6.6 % low on average, -39 to +82 % "
         "per sensor). Raise max_attempts_per_photon or set it to 0 (no cap), or let a large outdoor scatterer only shade";
}

std::string capped_note(const engine::TracedPhotons& photons, const engine::TracingOptions& tracing,
                        const std::string& what) {
  const CappedCount c = count_capped(photons, tracing);
  if (c.capped == 0) return "";
  return std::to_string(c.capped) + " of " + std::to_string(photons.tallies.size()) + " " + what +
         " capped at " + std::to_string(tracing.max_mainpass_attempts_per_target) +
         " main-pass attempts per target photon (low yield): they stored " + percent_text(c.least) + "-" +
         percent_text(c.most) + " % of their target and carry " + percent_text(capped_flux_share(photons, std::numeric_limits<double>::infinity())) +
         " % of the stored photon flux; their total flux stays unbiased, with more relative noise";
}

std::string nothing_stored_note(const engine::TracedPhotons& photons, const std::string& what) {
  std::size_t skipped = 0, stopped = 0;
  for (const engine::SourceTally& t : photons.tallies) {
    if (t.nothing_stores) ++skipped;
    else if (t.entered > 0 && t.stored_global + t.stored_caustic + t.stored_direct == 0) ++stopped;
  }
  if (skipped > 0)
    return "not traced: nothing in the scene can store a photon (no surface has a diffuse component, and no sensor "
           "plane can receive scattered light); the photon part of every " + what.substr(0, what.size() - 1) +
           " is zero and the results are its direct component alone";
  if (stopped > 0)
    return std::to_string(stopped) + " of " + std::to_string(photons.tallies.size()) + " " + what +
           " stored no photon: their light is absorbed before it reaches anything that stores photons (the pass "
           "stopped after 65536 entering photons)";
  return "";
}

}  // namespace dayphoton::study
