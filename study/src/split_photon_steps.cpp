// Photon steps traced in attempt ranges over the ranks: see split_photon_steps.h.
#include "dayphoton/study/split_photon_steps.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "dayphoton/dist/distribute_jobs.h"
#include "dayphoton/engine/source_passes.h"
#include "dayphoton/study/photon_range_step.h"
#include "dayphoton/study/plan_policy.h"

namespace dayphoton::study {
namespace {

using dist::ByteBuffer;

// One range's result as a message: its counts, then per photon list (the surface's, then
// each plane's) the count and the 32-byte records as this build lays them out (every rank
// runs the same build, as for the rest of the run's messages).
static_assert(std::is_trivially_copyable_v<engine::Photon>, "photon records travel as bytes");

void put_bytes(ByteBuffer& out, const void* data, std::size_t n) {
  const std::size_t at = out.size();
  out.resize(at + n);
  if (n > 0) std::memcpy(out.data() + at, data, n);
}

void put_u64(ByteBuffer& out, std::uint64_t v) { put_bytes(out, &v, sizeof v); }

std::uint64_t get_u64(const ByteBuffer& in, std::size_t& at) {
  std::uint64_t v = 0;
  if (in.size() - at < sizeof v) throw std::runtime_error("photon range: truncated message");
  std::memcpy(&v, in.data() + at, sizeof v);
  at += sizeof v;
  return v;
}

void put_photons(ByteBuffer& out, const std::vector<engine::Photon>& photons) {
  put_u64(out, photons.size());
  put_bytes(out, photons.data(), photons.size() * sizeof(engine::Photon));
}

std::vector<engine::Photon> get_photons(const ByteBuffer& in, std::size_t& at) {
  const std::uint64_t n = get_u64(in, at);
  if (n > (in.size() - at) / sizeof(engine::Photon)) throw std::runtime_error("photon range: truncated message");
  std::vector<engine::Photon> photons(n);
  if (n > 0) std::memcpy(photons.data(), in.data() + at, n * sizeof(engine::Photon));
  at += n * sizeof(engine::Photon);
  return photons;
}

ByteBuffer encode_range(const engine::AttemptRange& r) {
  ByteBuffer out;
  const engine::AttemptCounts& c = r.counts;
  for (std::uint64_t v : {c.entered, c.stored_global, c.stored_caustic, c.stored_direct, c.rays, c.scattered_indoors})
    put_u64(out, v);
  put_photons(out, r.surface);
  put_u64(out, r.planes.size());
  for (const std::vector<engine::Photon>& plane : r.planes) put_photons(out, plane);
  return out;
}

engine::AttemptRange decode_range(const ByteBuffer& in) {
  engine::AttemptRange r;
  std::size_t at = 0;
  engine::AttemptCounts& c = r.counts;
  for (std::uint64_t* v : {&c.entered, &c.stored_global, &c.stored_caustic, &c.stored_direct, &c.rays,
                           &c.scattered_indoors})
    *v = get_u64(in, at);
  r.surface = get_photons(in, at);
  const std::uint64_t planes = get_u64(in, at);
  if (planes > in.size()) throw std::runtime_error("photon range: malformed message");
  r.planes.resize(planes);
  for (std::vector<engine::Photon>& plane : r.planes) plane = get_photons(in, at);
  if (at != in.size()) throw std::runtime_error("photon range: malformed message");
  return r;
}

/// One split source between rounds.
struct SplitSource {
  std::size_t step = 0;  ///< index into the batch
  const PhotonRanges* ranges = nullptr;
  std::optional<engine::SourcePasses> passes;
  engine::AttemptRange photons;     ///< every range so far, in attempt order
  engine::AttemptCounts pass_counts;  ///< the current pass's ranges, summed
  bool delivered = false;
};

/// One job of a round: attempts [first, last) of a split source's current pass.
struct RangeJob {
  std::size_t source = 0;  ///< index into the split sources
  std::uint64_t first = 0, last = 0;
  engine::StorageProbabilities storage;
};

}  // namespace

std::vector<std::size_t> photon_steps_to_split(const std::vector<Step>& steps, const std::vector<std::size_t>& misses,
                                               int ranks) {
  std::vector<std::size_t> split;
  if (ranks <= 1) return split;
  double total = 0;
  for (std::size_t k : misses) total += steps[k].ranges ? steps[k].ranges->cost : 1.0;
  for (std::size_t k : misses)
    if (steps[k].ranges && steps[k].ranges->cost * double(ranks) * SplitSourceFactor > total) split.push_back(k);
  return split;
}

std::vector<SplitSourceRanges> run_split_photon_steps(
    dist::Communicator& comm, const std::vector<Step>& steps, const std::vector<std::size_t>& split,
    const std::function<void(std::size_t, const std::vector<std::string>&)>& deliver, std::uint64_t min_range_attempts) {
  std::vector<SplitSource> sources(split.size());
  std::vector<SplitSourceRanges> traced_in(split.size());
  for (std::size_t s = 0; s < split.size(); ++s) {
    traced_in[s].step = split[s];
    const Step& step = steps[split[s]];
    if (!step.ranges) throw std::logic_error("run_split_photon_steps: a step without ranges");
    sources[s].step = split[s];
    sources[s].ranges = step.ranges.get();
    sources[s].passes.emplace(step.ranges->passes());
  }
  const auto ranks = static_cast<std::uint64_t>(std::max(1, comm.size()));
  for (;;) {
    // The finished sources first (a source may have nothing to trace at all).
    for (SplitSource& s : sources) {
      if (s.delivered || s.passes->next()) continue;
      const engine::TracedPhotons traced = s.passes->finish(std::move(s.photons));
      deliver(s.step, {s.ranges->encode(traced)});
      s.delivered = true;
    }
    // This round's ranges: each live source's next pass, cut into at most one range per rank.
    std::vector<RangeJob> jobs;
    for (std::size_t s = 0; s < sources.size(); ++s) {
      if (sources[s].delivered) continue;
      const engine::AttemptPass pass = *sources[s].passes->next();
      const std::uint64_t length = pass.last - pass.first;
      const std::uint64_t pieces = std::clamp<std::uint64_t>(length / std::max<std::uint64_t>(1, min_range_attempts), 1, ranks);
      for (std::uint64_t i = 0; i < pieces && length > 0; ++i) {
        const std::uint64_t first = pass.first + length * i / pieces, last = pass.first + length * (i + 1) / pieces;
        jobs.push_back({s, first, last, pass.storage});
      }
      if (length > 0) {
        traced_in[s].ranges += pieces;
        ++traced_in[s].passes;
        traced_in[s].attempts += length;
      }
    }
    bool live = false;
    for (const SplitSource& s : sources) live = live || !s.delivered;
    if (!live) return traced_in;

    dist::JobSet set;
    set.count = jobs.size();
    set.cost_of = [&](std::size_t j) { return double(jobs[j].last - jobs[j].first); };
    set.compute = [&](std::size_t j) {
      const RangeJob& job = jobs[j];
      return encode_range(sources[job.source].ranges->trace(job.first, job.last, job.storage));
    };
    set.deliver = [&](std::size_t j, ByteBuffer bytes) {
      SplitSource& s = sources[jobs[j].source];
      engine::AttemptRange range = decode_range(bytes);
      s.pass_counts += range.counts;
      engine::append_attempt_range(s.photons, std::move(range));
    };
    set.name_of = [&](std::size_t j) {
      const RangeJob& job = jobs[j];
      const Step& step = steps[sources[job.source].step];
      return std::string(step_kind_name(step.kind)) + " " + std::to_string(step.index) + ", attempts " +
             std::to_string(job.first) + " to " + std::to_string(job.last);
    };
    set.delivery = dist::Delivery::every_rank;
    if (!jobs.empty()) dist::distribute_jobs(comm, set);
    // Every rank has every range: the passes' summed counts decide the next passes.
    for (SplitSource& s : sources) {
      if (s.delivered) continue;
      s.passes->record(s.pass_counts);
      s.pass_counts = engine::AttemptCounts{};
    }
  }
}

std::string split_sources_line(const std::vector<Step>& steps, const std::vector<SplitSourceRanges>& split, int ranks) {
  constexpr std::size_t MostNamed = 8;
  std::string line = "photons: " + std::to_string(split.size()) + (split.size() == 1 ? " source" : " sources") +
                     " split into attempt ranges over " + std::to_string(ranks) + " ranks: ";
  for (std::size_t i = 0; i < split.size() && i < MostNamed; ++i) {
    const Step& step = steps[split[i].step];
    line += (i == 0 ? "" : ", ") + std::string(step_kind_name(step.kind)) + " " + std::to_string(step.index) + " (" +
            std::to_string(split[i].ranges) + (split[i].ranges == 1 ? " range" : " ranges") + " in " +
            std::to_string(split[i].passes) + (split[i].passes == 1 ? " pass, " : " passes, ") +
            std::to_string(split[i].attempts) + " attempts)";
  }
  if (split.size() > MostNamed) line += " and " + std::to_string(split.size() - MostNamed) + " more";
  return line;
}

}  // namespace dayphoton::study
