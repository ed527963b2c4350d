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
#include "attempt_range_wire.h"

namespace dayphoton::study {
namespace {

using dist::ByteBuffer;

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
      return encode_attempt_range(sources[job.source].ranges->trace(job.first, job.last, job.storage));
    };
    set.deliver = [&](std::size_t j, ByteBuffer bytes) {
      SplitSource& s = sources[jobs[j].source];
      engine::AttemptRange range = decode_attempt_range(bytes);
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
