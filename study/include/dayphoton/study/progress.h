// Progress: what `dayphoton run` tells the user while it works (issue 5 item 2).
//
// Steps are started by name with an amount of work in their own unit ("photons", "sensors",
// "hours"); workers call advance() from any thread. On a terminal (isatty) a single line is
// redrawn at most 10 times a second: a bar, the step name, done/total, the rate and the ETA.
// When the output is not a terminal, plain lines are printed at most every `line_interval`
// seconds and once at each step's end. Quiet prints nothing. finish() prints the table of
// where the time went (step, work, seconds, rate, share of the total).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

namespace dayphoton::study {

enum class ProgressStyle { Terminal, Lines, Quiet };

class Progress {
 public:
  /// `style` Terminal redraws one line on `out`; Lines prints plain lines.
  Progress(std::ostream& out, ProgressStyle style, double line_interval_s = 5.0);
  ~Progress();

  /// Terminal if `is_tty`, else Lines; Quiet if `quiet`.
  static ProgressStyle choose_style(bool is_tty, bool quiet);

  /// Begin a step (ends the previous one if still open). Thread-safe.
  void start(const std::string& name, std::uint64_t total, const std::string& unit);
  /// Add work done to the current step. Thread-safe, cheap (an atomic add; printing is
  /// rate-limited).
  void advance(std::uint64_t amount = 1);
  /// End the current step (records its time).
  void end();
  /// A step that was served from the cache: recorded with zero work and marked "cached".
  void cached(const std::string& name);
  /// Print a plain message line (not in Quiet), e.g. "photons: 12 of 146 sources cached".
  void note(const std::string& message);

  struct StepTime {
    std::string name, unit;
    std::uint64_t work = 0;
    double seconds = 0;
    bool cached = false;
  };
  const std::vector<StepTime>& steps() const { return m_steps; }
  /// Print the table of step times (not in Quiet).
  void print_summary();

 private:
  void draw(bool force);
  std::ostream& m_out;
  ProgressStyle m_style;
  double m_line_interval_s;
  std::mutex m_mutex;
  std::vector<StepTime> m_steps;
  bool m_open = false;
  std::string m_name, m_unit;
  std::uint64_t m_total = 0;
  std::atomic<std::uint64_t> m_done{0};
  std::chrono::steady_clock::time_point m_step_start, m_last_draw;
};

}  // namespace dayphoton::study
