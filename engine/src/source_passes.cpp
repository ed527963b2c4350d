// The photon-count control of one source: see source_passes.h, and photon_tracer.h for the
// scheme (seeds/000 section 4.1.4, Alg. 4.1/4.2) and its refinements.
#include "dayphoton/engine/source_passes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dayphoton::engine {
namespace {

/// Entries without a stored photon after which a pre-pass stops (see record()).
constexpr std::uint64_t NothingStoredEntries = 65536;

}  // namespace

SourcePasses::SourcePasses(const Scene& scene, const std::vector<Material>& materials, const PortEmitter& emitter,
                           const std::vector<ReceiverPlane>& planes, const TracingOptions& options,
                           std::size_t source)
    : m_prepass_fraction(options.prepass_fraction),
      m_max_prepass_per_target(options.max_prepass_attempts_per_target),
      m_max_mainpass_per_target(options.max_mainpass_attempts_per_target),
      m_planes(planes.size()),
      m_raw_cap(source < options.raw_attempt_cap.size() && options.raw_attempt_cap[source] != 0) {
  const auto s = static_cast<std::uint32_t>(source);
  m_tally.bound_flux = emitter.bound_flux(s);
  if (!can_store_photons(scene, materials, planes)) {
    m_tally.nothing_stores = true;  // no photon of any source could ever be stored
    return;
  }
  if (m_tally.bound_flux <= 0) return;

  const double factor = source < options.source_photon_factor.size() ? options.source_photon_factor[source] : 1.0;
  auto scaled = [factor](std::size_t n) {
    return static_cast<std::size_t>(std::llround(double(n) * std::max(0.0, factor)));
  };
  m_target_g = scaled(options.photons_per_source);
  m_target_c = scaled(options.caustic_photons_per_source);
  // Direct photons on surfaces (for a final gather) get the global photons' target, so that
  // their count stays bounded however few global photons a dark room stores.
  m_target_d = options.store_direct_on_surfaces ? m_target_g : 0;
  std::size_t smallest = m_target_g;
  if (m_target_c > 0) smallest = std::min(smallest, m_target_c);
  m_largest = std::max(m_target_g, m_target_c);
  if (m_largest == 0) return;

  m_port_share = emitter.port_bound_flux(s) / m_tally.bound_flux;
  m_initial = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::ceil(m_prepass_fraction * double(smallest))));
  m_prepass = m_initial;
  m_pass = AttemptPass{0, m_initial, StorageProbabilities{}};
  m_stage = Stage::PrePass;
  m_normalised = true;
}

std::optional<AttemptPass> SourcePasses::next() const {
  if (m_stage == Stage::Done) return std::nullopt;
  return m_pass;
}

// Attempt limits in port-equivalent attempts (photon_tracer.h, "Outdoor scatterers"): an
// attempt on a port counts fully; of the attempts on outdoor scatterers only those whose light
// enters a room count (an upper 95 % bound on their share, from the attempts so far).
double SourcePasses::useful_share(std::uint64_t attempts) const {
  if (m_port_share >= 1.0 || attempts == 0) return 1.0;
  return std::min(1.0, m_port_share + (double(m_scattered_indoors) + 3.0) / double(attempts));
}

std::uint64_t SourcePasses::scaled_limit(std::size_t per_target, std::uint64_t attempts) const {
  return std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::ceil(double(per_target) * double(m_largest) * useful_share(attempts))));
}

void SourcePasses::record(const AttemptCounts& counts) {
  if (m_stage == Stage::Done) return;
  m_tally.entered += counts.entered;
  m_tally.stored_global += counts.stored_global;
  m_tally.stored_caustic += counts.stored_caustic;
  m_tally.stored_direct += counts.stored_direct;
  m_tally.rays += counts.rays;
  m_scattered_indoors += counts.scattered_indoors;
  SourceTally& tally = m_tally;

  if (m_stage == Stage::PrePass) {
    // Pre-pass (Alg. 4.1), every photon stored. The thesis doubles it while a map is empty;
    // here it doubles until every targeted class has enough photons for its yield to be
    // known to ~10 % (min(100, k * target) stored), or, if a class stays empty while another
    // has enough after 64 doublings' worth of attempts, that class is taken as absent (e.g.
    // caustics in an all-diffuse room), or the attempts reach the give-up limit (a source the
    // ports see but whose light is blocked).
    auto enough = [&](std::size_t target, std::uint64_t stored) {
      return target == 0 || double(stored) >= std::min(100.0, std::ceil(m_prepass_fraction * double(target)));
    };
    const bool g_ok = enough(m_target_g, tally.stored_global);
    const bool c_ok = enough(m_target_c, tally.stored_caustic);
    const bool d_ok = enough(m_target_d, tally.stored_direct);
    const bool g_found = m_target_g > 0 && tally.stored_global > 0 && g_ok;
    const bool c_found = m_target_c > 0 && tally.stored_caustic > 0 && c_ok;
    const bool d_found = m_target_d > 0 && tally.stored_direct > 0 && d_ok;
    bool stop = (g_ok && c_ok && d_ok) || ((g_found || c_found || d_found) && m_prepass >= 64 * m_initial) ||
                m_prepass >= std::max(m_initial, scaled_limit(m_max_prepass_per_target, m_prepass));
    // Light enters but nothing is stored (every surface it reaches absorbs it before it
    // scatters onto anything that stores, e.g. a black room): after 2^16 entries the stored
    // fraction of the entering flux is below 5e-5 (95 % confidence: 3 / 65536); stop.
    stop = stop || (tally.entered >= NothingStoredEntries &&
                    tally.stored_global + tally.stored_caustic + tally.stored_direct == 0);
    // Nothing entered at all: the ports do not see this source (a sun disc's emission bound
    // is a little above zero just behind a port's plane; a sky bin's is exact, see
    // port_emission.h) or it is blocked. After 2^16 attempts its flux is below 5e-5 of the
    // bound (95 % confidence: 3 / 65536) and is dropped.
    stop = stop || (tally.entered == 0 && m_prepass >= 65536);
    if (!stop) {
      m_pass = AttemptPass{m_prepass, 2 * m_prepass, StorageProbabilities{}};
      m_prepass *= 2;
      return;
    }
    tally.prepass_attempts = m_prepass;
    start_main_pass();
    return;
  }

  if (m_stage == Stage::MainPass) {
    tally.mainpass_attempts = m_main;
    // Top-up (not in the thesis): the pre-pass yield has the noise of a few hundred photons,
    // so the main pass can fall short by several per cent; its own yield (thousands of
    // photons) sizes one more run of attempts with the same storage probabilities. Every
    // attempt still carries bound_flux / attempts, so the flux stays unbiased.
    auto need = [&](std::size_t target, std::uint64_t stored, std::uint64_t before) {
      const double yield = double(stored - before) / double(m_main);
      if (target == 0 || stored >= target || yield <= 0) return 0.0;
      return double(target - stored) / yield;
    };
    const double extra = std::max({need(m_target_g, tally.stored_global, m_g0),
                                   need(m_target_c, tally.stored_caustic, m_c0),
                                   need(m_target_d, tally.stored_direct, m_d0)});
    std::uint64_t topup = std::min<std::uint64_t>(m_main, static_cast<std::uint64_t>(std::ceil(extra)));
    if (topup > m_cap - m_main) {
      topup = m_cap - m_main;
      tally.capped = true;
    }
    if (topup == 0) {
      m_stage = Stage::Done;
      return;
    }
    const std::uint64_t end = m_prepass + m_main;
    m_pass = AttemptPass{end, end + topup, m_pass.storage};
    m_stage = Stage::TopUp;
    return;
  }

  // The top-up.
  tally.mainpass_attempts += m_pass.last - m_pass.first;
  m_stage = Stage::Done;
}

void SourcePasses::start_main_pass() {
  SourceTally& tally = m_tally;
  // Main pass (Alg. 4.2, eqs. 4.8-4.10): r_j = n_j / N_j - 1 from the pre-pass yields.
  auto shortfall = [](std::size_t target, std::uint64_t stored) {
    if (target == 0 || stored == 0) return 0.0;
    return std::max(double(target) / double(stored), 1.0) - 1.0;
  };
  const double r_g = shortfall(m_target_g, tally.stored_global);
  const double r_c = shortfall(m_target_c, tally.stored_caustic);
  const double r_d = shortfall(m_target_d, tally.stored_direct);
  const double r_max = std::max({r_g, r_c, r_d});
  m_stage = Stage::Done;
  if (!(r_max > 0)) return;
  tally.storage_probability_global = r_g / r_max;
  tally.storage_probability_caustic = m_target_c > 0 ? r_c / r_max : r_g / r_max;
  if (m_target_d > 0) tally.storage_probability_direct = r_d / r_max;
  // The low-yield cap (photon_tracer.h): fixed before any of these attempts is traced; in raw
  // attempts where the pipeline lifted the useful-share scaling (TracingOptions::raw_attempt_cap).
  m_cap = m_max_mainpass_per_target == 0 ? std::numeric_limits<std::uint64_t>::max()
          : m_raw_cap ? static_cast<std::uint64_t>(m_max_mainpass_per_target) * m_largest
                      : scaled_limit(m_max_mainpass_per_target, m_prepass);
  const double planned = std::ceil(double(m_prepass) * r_max);
  tally.capped = planned > double(m_cap);
  m_main = tally.capped ? m_cap : static_cast<std::uint64_t>(planned);
  m_g0 = tally.stored_global;
  m_c0 = tally.stored_caustic;
  m_d0 = tally.stored_direct;
  m_pass = AttemptPass{m_prepass, m_prepass + m_main,
                       StorageProbabilities{tally.storage_probability_global, tally.storage_probability_caustic,
                                            tally.storage_probability_direct}};
  m_stage = Stage::MainPass;
}

TracedPhotons SourcePasses::finish(AttemptRange&& traced) const {
  TracedPhotons out;
  out.surface = std::move(traced.surface);
  out.planes = std::move(traced.planes);
  out.planes.resize(m_planes);
  out.tallies.push_back(m_tally);
  if (!m_normalised) return out;
  // Normalise (eqs. 4.11-4.12, per class: see photon_tracer.h).
  SourceTally& tally = out.tallies[0];
  tally.flux_per_attempt = tally.bound_flux / double(tally.prepass_attempts + tally.mainpass_attempts);
  float scale[3];  // indexed by PathClass
  for (PathClass c : {PathClass::Direct, PathClass::Caustic, PathClass::Global})
    scale[static_cast<int>(c)] = static_cast<float>(tally.stored_photon_flux(c));
  auto rescale = [&scale](std::vector<Photon>& photons) {
    for (Photon& p : photons)
      for (float& f : p.flux) f *= scale[static_cast<int>(p.path_class)];
  };
  rescale(out.surface);
  for (auto& plane : out.planes) rescale(plane);
  return out;
}

}  // namespace dayphoton::engine
