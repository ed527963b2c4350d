// Progress: what `dayphoton run` tells the user while it works (issue 5 item 2).
//
// Steps are started by name with an amount of work in their own unit ("photons", "sensors",
// "hours"); workers call advance() from any thread. Three styles:
//   - Terminal (stdout is a tty): one line redrawn with '\r' at most 10 times a second,
//       [#######.............] photons  1040000/2920000 photons  231 k photons/s  ETA 8 s
//     ending with "done in X s" and a newline when the step ends;
//   - Lines (a log file, CI): plain lines at most every `line_interval_s` seconds,
//       photons: 1040000/2920000 photons (35.6 %), 231 k photons/s, ETA 8 s
//     and once at each step's end, "photons: done in 12.6 s (2920000 photons, 232 k photons/s)";
//   - Quiet: nothing.
// A step served from the cache prints "name: cached". print_summary() prints the table of
// where the time went (step, work, unit, seconds, rate, share of the total; a cached step
// "from cache" instead of a time) and a total line.
//
// Cost for workers: advance() is one relaxed atomic add and a clock read; only when a redraw
// is due does it try_lock the mutex, and if another thread holds it, it skips the redraw,
// so workers never wait on each other or on the output stream.
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
  /// Redraw interval of the Terminal style.
  static constexpr double TerminalInterval_s = 0.1;

  /// `style` Terminal redraws one line on `out`; Lines prints plain lines, at most one per
  /// `line_interval_s` per step besides its end line.
  Progress(std::ostream& out, ProgressStyle style, double line_interval_s = 5.0);
  /// Ends an open step (so a Terminal line is terminated by a newline).
  ~Progress();

  /// Terminal if `is_tty`, else Lines; Quiet if `quiet`.
  static ProgressStyle choose_style(bool is_tty, bool quiet);

  /// Begin a step (ends the previous one if still open). `total` 0 = unknown (no bar, no
  /// ETA). Thread-safe.
  void start(const std::string& name, std::uint64_t total, const std::string& unit);
  /// Add work done to the current step. Thread-safe, cheap (an atomic add; printing is
  /// rate-limited). Work added while no step is open is ignored by the next start().
  void advance(std::uint64_t amount = 1);
  /// End the current step (records its time and the work done); no effect if none is open.
  void end();
  /// A step that was served from the cache: ends the current step, is recorded with zero
  /// work and marked "cached".
  void cached(const std::string& name);
  /// Print a plain message line (not in Quiet), e.g. "photons: 12 of 146 sources cached".
  /// On a terminal it replaces the status line, which is then redrawn below it.
  void note(const std::string& message);

  struct StepTime {
    std::string name, unit;
    std::uint64_t work = 0;
    double seconds = 0;      ///< wall time
    double cpu_seconds = 0;  ///< CPU time of the whole process (all threads) during the step
    bool cached = false;
  };
  /// CPU time (user + system) of this process so far, all threads (clock_gettime
  /// CLOCK_PROCESS_CPUTIME_ID); 0 where the clock is not available.
  static double process_cpu_seconds();
  /// The steps ended so far, in order (read it when no other thread is using the Progress).
  const std::vector<StepTime>& steps() const { return m_steps; }
  /// End the open step, if any, and print the table of step times (not in Quiet).
  void print_summary();

 private:
  using Clock = std::chrono::steady_clock;
  void draw(bool force);  ///< with m_mutex held
  void end_locked();      ///< with m_mutex held
  std::string status_text(Clock::time_point now) const;
  void put_terminal_line(const std::string& text);
  double interval_s() const;

  std::ostream& m_out;
  ProgressStyle m_style;
  double m_line_interval_s;
  std::mutex m_mutex;
  std::vector<StepTime> m_steps;
  bool m_open = false;
  std::string m_name, m_unit;
  std::uint64_t m_total = 0;
  std::atomic<std::uint64_t> m_done{0};
  Clock::time_point m_step_start;
  double m_step_cpu_start = 0;
  /// When the next redraw is due (Clock ticks), read by advance() without the lock.
  std::atomic<Clock::rep> m_next_draw{0};
  bool m_line_drawn = false;             ///< Terminal: a status line is on screen
  std::size_t m_last_line_length = 0;    ///< Terminal: to blank out a longer previous line
};

}  // namespace dayphoton::study
