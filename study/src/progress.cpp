// Progress: rate-limited progress display and the step-time summary of `dayphoton run`
// (progress.h).
#include "dayphoton/study/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace dayphoton::study {

namespace {

constexpr int BarWidth = 20;

// "12.3 s", "4 min 05 s", "2 h 07 min": precise enough to plan a coffee, short enough for
// one line.
std::string format_duration(double s) {
  char buf[64];
  if (!(s >= 0) || !std::isfinite(s)) return "?";
  if (s < 60) {
    std::snprintf(buf, sizeof buf, s < 10 ? "%.1f s" : "%.0f s", s);
  } else if (s < 3600) {
    const long t = std::lround(s);
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", t / 60, t % 60);
  } else {
    const long t = std::lround(s / 60);
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", t / 60, t % 60);
  }
  return buf;
}

// Three significant digits with an SI prefix: "8.13", "950", "23.4 k", "1.05 M".
std::string format_amount(double v) {
  char buf[64];
  const char* prefix = "";
  for (const char* p : {" k", " M", " G", " T"}) {
    if (v < 999.5) break;
    v /= 1000;
    prefix = p;
  }
  std::snprintf(buf, sizeof buf, v < 9.995 ? "%.2f%s" : (v < 99.95 ? "%.1f%s" : "%.0f%s"), v, prefix);
  return buf;
}

double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

double Progress::process_cpu_seconds() {
  timespec t{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) != 0) return 0;
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

Progress::Progress(std::ostream& out, ProgressStyle style, double line_interval_s)
    : m_out(out), m_style(style), m_line_interval_s(line_interval_s) {}

Progress::~Progress() {
  try {
    std::lock_guard<std::mutex> lock(m_mutex);
    end_locked();
  } catch (...) {
    // A failing output stream must not turn into std::terminate during unwinding.
  }
}

ProgressStyle Progress::choose_style(bool is_tty, bool quiet) {
  if (quiet) return ProgressStyle::Quiet;
  return is_tty ? ProgressStyle::Terminal : ProgressStyle::Lines;
}

double Progress::interval_s() const {
  return m_style == ProgressStyle::Terminal ? TerminalInterval_s : m_line_interval_s;
}

void Progress::start(const std::string& name, std::uint64_t total, const std::string& unit) {
  std::lock_guard<std::mutex> lock(m_mutex);
  end_locked();
  m_name = name;
  m_unit = unit;
  m_total = total;
  m_done.store(0);
  m_step_start = Clock::now();
  m_step_cpu_start = process_cpu_seconds();
  m_open = true;
  m_next_draw.store((m_step_start + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(interval_s())))
                        .time_since_epoch()
                        .count());
  // A terminal shows the step at once; a log gets its first line after one interval.
  if (m_style == ProgressStyle::Terminal) draw(true);
}

void Progress::advance(std::uint64_t amount) {
  m_done.fetch_add(amount, std::memory_order_relaxed);
  if (m_style == ProgressStyle::Quiet) return;
  if (Clock::now().time_since_epoch().count() < m_next_draw.load(std::memory_order_relaxed)) return;
  std::unique_lock<std::mutex> lock(m_mutex, std::try_to_lock);
  if (!lock.owns_lock()) return;  // someone else is drawing (or starting/ending a step)
  draw(false);
}

void Progress::draw(bool force) {
  if (!m_open || m_style == ProgressStyle::Quiet) return;
  const Clock::time_point now = Clock::now();
  if (!force && now.time_since_epoch().count() < m_next_draw.load()) return;
  m_next_draw.store((now + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(interval_s())))
                        .time_since_epoch()
                        .count());
  if (m_style == ProgressStyle::Terminal) {
    put_terminal_line(status_text(now));
  } else {
    m_out << status_text(now) << '\n' << std::flush;
  }
}

std::string Progress::status_text(Clock::time_point now) const {
  const std::uint64_t done = m_done.load(std::memory_order_relaxed);
  const double elapsed = seconds_between(m_step_start, now);
  const double rate = elapsed > 0 ? double(done) / elapsed : 0;
  std::string rate_text = rate > 0 ? format_amount(rate) + " " + m_unit + "/s" : "- " + m_unit + "/s";
  std::string eta;
  if (m_total > 0) {
    eta = "ETA " + (rate > 0 ? format_duration(double(m_total - std::min(done, m_total)) / rate)
                             : std::string("?"));
  }
  const std::string count =
      m_total > 0 ? std::to_string(done) + "/" + std::to_string(m_total) : std::to_string(done);

  if (m_style == ProgressStyle::Terminal) {
    std::string text;
    if (m_total > 0) {
      const double fraction = std::min(1.0, double(done) / double(m_total));
      const int filled = static_cast<int>(fraction * BarWidth);
      text = "[" + std::string(filled, '#') + std::string(BarWidth - filled, '.') + "] ";
    }
    text += m_name + "  " + count + " " + m_unit + "  " + rate_text;
    if (!eta.empty()) text += "  " + eta;
    return text;
  }
  std::string text = m_name + ": " + count + " " + m_unit;
  if (m_total > 0) {
    char percent[32];
    std::snprintf(percent, sizeof percent, " (%.1f %%)", 100.0 * double(done) / double(m_total));
    text += percent;
  }
  text += ", " + rate_text;
  if (!eta.empty()) text += ", " + eta;
  return text;
}

void Progress::put_terminal_line(const std::string& text) {
  // Pad with blanks over whatever of a longer previous line would otherwise remain.
  const std::size_t pad = m_last_line_length > text.size() ? m_last_line_length - text.size() : 0;
  m_out << '\r' << text << std::string(pad, ' ') << std::flush;
  m_last_line_length = text.size();
  m_line_drawn = true;
}

void Progress::end_locked() {
  if (!m_open) return;
  const Clock::time_point now = Clock::now();
  StepTime step;
  step.name = m_name;
  step.unit = m_unit;
  step.work = m_done.load();
  step.seconds = seconds_between(m_step_start, now);
  step.cpu_seconds = std::max(0.0, process_cpu_seconds() - m_step_cpu_start);
  m_steps.push_back(step);
  m_open = false;

  const std::string rate =
      step.seconds > 0 ? format_amount(double(step.work) / step.seconds) + " " + m_unit + "/s"
                       : "- " + m_unit + "/s";
  if (m_style == ProgressStyle::Terminal) {
    std::string text;
    if (m_total > 0) {
      const double fraction = std::min(1.0, double(step.work) / double(m_total));
      const int filled = static_cast<int>(fraction * BarWidth);
      text = "[" + std::string(filled, '#') + std::string(BarWidth - filled, '.') + "] ";
    }
    text += m_name + "  " + std::to_string(step.work) + " " + m_unit + "  " + rate + "  done in " +
            format_duration(step.seconds);
    put_terminal_line(text);
    m_out << '\n' << std::flush;
    m_line_drawn = false;
    m_last_line_length = 0;
  } else if (m_style == ProgressStyle::Lines) {
    m_out << m_name << ": done in " << format_duration(step.seconds) << " (" << step.work << " "
          << m_unit << ", " << rate << ")\n"
          << std::flush;
  }
}

void Progress::end() {
  std::lock_guard<std::mutex> lock(m_mutex);
  end_locked();
}

void Progress::cached(const std::string& name) {
  std::lock_guard<std::mutex> lock(m_mutex);
  end_locked();
  StepTime step;
  step.name = name;
  step.cached = true;
  m_steps.push_back(step);
  if (m_style != ProgressStyle::Quiet) m_out << name << ": cached\n" << std::flush;
}

void Progress::note(const std::string& message) {
  std::lock_guard<std::mutex> lock(m_mutex);
  if (m_style == ProgressStyle::Quiet) return;
  if (m_style == ProgressStyle::Terminal && m_line_drawn) {
    // Put the message where the status line was, then redraw the status below it.
    put_terminal_line(message);
    m_out << '\n';
    m_line_drawn = false;
    m_last_line_length = 0;
    draw(true);
    return;
  }
  m_out << message << '\n' << std::flush;
}

void Progress::print_summary() {
  std::lock_guard<std::mutex> lock(m_mutex);
  end_locked();
  if (m_style == ProgressStyle::Quiet) return;

  double total_s = 0;
  std::size_t name_width = 5, unit_width = 4;
  for (const StepTime& s : m_steps) {
    total_s += s.seconds;
    name_width = std::max(name_width, s.name.size());
    unit_width = std::max(unit_width, s.unit.size());
  }
  const int nw = static_cast<int>(name_width), uw = static_cast<int>(unit_width);
  char line[512];
  auto put = [&](const std::string& name, const std::string& work, const std::string& unit,
                 const std::string& seconds, const std::string& rate, const std::string& share) {
    std::snprintf(line, sizeof line, "%-*s  %12s  %-*s  %10s  %12s  %7s", nw, name.c_str(),
                  work.c_str(), uw, unit.c_str(), seconds.c_str(), rate.c_str(), share.c_str());
    std::string text = line;
    text.erase(text.find_last_not_of(' ') + 1);
    m_out << text << '\n';
  };
  auto fixed = [](double v, const char* format) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return std::string(buf);
  };
  auto share = [&](double seconds) {
    return fixed(total_s > 0 ? 100.0 * seconds / total_s : 0.0, "%.1f %%");
  };

  put("step", "work", "unit", "seconds", "rate /s", "share");
  for (const StepTime& s : m_steps) {
    if (s.cached) {
      put(s.name, "", "", "from cache", "", "-");  // no time: nothing was computed (never "0.00")
    } else {
      put(s.name, std::to_string(s.work), s.unit, fixed(s.seconds, "%.2f"),
          s.seconds > 0 ? format_amount(double(s.work) / s.seconds) : "-", share(s.seconds));
    }
  }
  put("total", "", "", fixed(total_s, "%.2f"), "", total_s > 0 ? share(total_s) : "");
  m_out << std::flush;
}

}  // namespace dayphoton::study
