// timings.json: where the time of one `dayphoton run` went, step by step (docs/outputs.md,
// "timings.json"). The run's history, like run.log: it differs from run to run (machine, load,
// what the cache held), so it is kept out of results.json and summary.json, which a repeated
// run writes byte for byte, and out of summary.json's list of outputs. Written once by the run
// from its typed step times (Progress::steps), just before the images and the report; read
// back only through read_run_timings (the report's appendix).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dayphoton/study/progress.h"

namespace dayphoton::study {

constexpr const char* TimingsFileName = "timings.json";
/// Raised when a field changes meaning or a required one is added.
constexpr int TimingsSchemaVersion = 1;

/// One step of the run, as its progress line and run.log name it ("sky matrix", "photons",
/// "coefficients workplane", "tinted: sun photons", "annual workplane" ...).
struct StepTiming {
  std::string name;
  std::string unit;          ///< the unit of `work` ("sources", "sensors", "hours", ...)
  std::uint64_t work = 0;    ///< work done; 0 for a step from the cache
  double wall_s = 0;         ///< elapsed time; 0 for a step from the cache
  double cpu_s = 0;          ///< CPU time of the process (all threads) during the step
  bool cached = false;       ///< the step's results came from the cache: nothing was computed
  bool operator==(const StepTiming& o) const;
};

struct RunTimings {
  std::vector<StepTiming> steps;  ///< in the order they ran
  double total_wall_s = 0;  ///< from the start of the run to the writing of timings.json
  double total_cpu_s = 0;   ///< CPU time of the process over the same span
  unsigned threads = 0;     ///< worker threads the run could use
  bool operator==(const RunTimings& o) const;
};

/// The typed timings from the run's step times; totals over [start, now] of the process.
RunTimings run_timings_of(const std::vector<Progress::StepTime>& steps, double total_wall_s, double total_cpu_s,
                          unsigned threads);

/// Write <output_dir>/timings.json atomically; returns its path.
std::string write_run_timings(const RunTimings& timings, const std::string& output_dir);

/// The timings of the run in `results_dir`; nullopt when it has no timings.json (a results
/// folder of a dayphoton before it was written). InputError naming the file and the key for a
/// malformed file or another schema version.
std::optional<RunTimings> read_run_timings(const std::string& results_dir);

/// The same from text (`path` names it in errors).
RunTimings parse_run_timings(const std::string& text, const std::string& path);

}  // namespace dayphoton::study
