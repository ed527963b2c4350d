// report.pdf through headless Chromium's print; see report_pdf.h.
#include "dayphoton/report/report_pdf.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "dayphoton/core/error_text.h"

extern char** environ;

namespace dayphoton::report {

namespace fs = std::filesystem;

namespace {

bool executable(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

std::string on_path(const std::string& name) {
  if (name.find('/') != std::string::npos) return executable(name) ? name : std::string();
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && executable(fs::path(dir) / name)) return (fs::path(dir) / name).string();
  return {};
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The last `n` lines of a log on one line, for an error message; Chromium's complaints
/// about a missing D-Bus (normal in a headless machine) left out.
std::string log_tail(const fs::path& log, int n) {
  const std::string text = read_all(log);
  std::vector<std::string> lines;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);)
    if (!line.empty() && line.find("dbus") == std::string::npos && line.find("DBus") == std::string::npos)
      lines.push_back(line);
  std::string out;
  for (std::size_t i = lines.size() > static_cast<std::size_t>(n) ? lines.size() - n : 0; i < lines.size(); ++i)
    out += (out.empty() ? " " : " | ") + lines[i];
  return out.empty() ? " (none)" : out;
}

/// Removes the temporary folder however print_pdf leaves.
struct TemporaryFolder {
  fs::path path;
  ~TemporaryFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

}  // namespace

std::string find_pdf_printer(const PdfSettings& settings) {
  if (!settings.browser.empty()) return on_path(settings.browser);
  for (const char* name : {"chromium", "chromium-browser"})
    if (std::string p = on_path(name); !p.empty()) return p;
  return {};
}

std::string print_pdf(const std::string& html_path, const std::string& pdf_path, const PdfSettings& settings) {
  const std::string browser = find_pdf_printer(settings);
  if (browser.empty())
    throw PdfPrinterMissing(
        settings.browser.empty()
            ? std::string("printing the PDF needs headless Chromium, and neither 'chromium' nor 'chromium-browser' is "
                          "on PATH: install the Debian package 'chromium' (apt-get install chromium)")
            : "printing the PDF: '" + settings.browser + "' is not an executable file");
  std::error_code ec;
  const fs::path html = fs::absolute(html_path, ec);
  if (ec || !fs::is_regular_file(html)) throw std::runtime_error(html_path + ": no report to print");
  const fs::path pdf = fs::absolute(pdf_path);
  const fs::path folder = pdf.parent_path();

  // The temporary folder beside the PDF: profile, HOME, log and the printed file.
  TemporaryFolder temp{folder / (".report-pdf.tmp." + std::to_string(::getpid()))};
  fs::remove_all(temp.path, ec);
  fs::create_directories(temp.path / "home");
  const fs::path printed = temp.path / "print.pdf", log = temp.path / "chromium.log";

  const std::vector<std::string> args{browser,
                                      "--headless",
                                      "--disable-gpu",
                                      "--no-sandbox",
                                      "--no-first-run",
                                      "--no-default-browser-check",
                                      "--disable-extensions",
                                      "--disable-dev-shm-usage",
                                      "--user-data-dir=" + (temp.path / "profile").string(),
                                      "--no-pdf-header-footer",
                                      "--print-to-pdf=" + printed.string(),
                                      "file://" + html.string()};
  std::vector<std::string> env_text;
  for (char** e = environ; *e; ++e) {
    const std::string v = *e;
    if (v.rfind("HOME=", 0) != 0 && v.rfind("XDG_CONFIG_HOME=", 0) != 0 && v.rfind("XDG_CACHE_HOME=", 0) != 0)
      env_text.push_back(v);
  }
  env_text.push_back("HOME=" + (temp.path / "home").string());
  env_text.push_back("XDG_CONFIG_HOME=" + (temp.path / "home" / ".config").string());
  env_text.push_back("XDG_CACHE_HOME=" + (temp.path / "home" / ".cache").string());
  std::vector<char*> argv, envp;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for (const std::string& e : env_text) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);

  // Child in its own process group (so that a time-out kills Chromium's helpers too), stdin
  // from /dev/null, stdout and stderr into the log.
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  posix_spawn_file_actions_init(&actions);
  posix_spawnattr_init(&attributes);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, browser.c_str(), &actions, &attributes, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) throw std::runtime_error("printing the PDF: cannot start " + browser + ": " + error_text(spawned));

  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  bool timed_out = false;
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > settings.timeout_s) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  // Helpers left in the group (Chromium's zygote) go with it.
  ::kill(-pid, SIGKILL);
  if (timed_out) {
    std::ostringstream limit;
    limit << settings.timeout_s;
    throw std::runtime_error("printing the PDF: " + browser + " did not finish within " + limit.str() +
                             " s and was stopped; its last lines:" + log_tail(log, 3));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("printing the PDF: " + browser + " failed (" +
                             (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                                : "signal " + std::to_string(WTERMSIG(status))) +
                             "); its last lines:" + log_tail(log, 3));
  std::ifstream in(printed, std::ios::binary);
  char head[5] = {};
  if (!in.read(head, 5) || std::memcmp(head, "%PDF-", 5) != 0)
    throw std::runtime_error("printing the PDF: " + browser + " wrote no PDF; its last lines:" + log_tail(log, 3));
  in.close();
  fs::rename(printed, pdf, ec);
  if (ec) throw std::runtime_error(pdf.string() + ": cannot write: " + ec.message());
  return pdf_path;
}

int pdf_page_count(const std::string& pdf) {
  int count = 0;
  const std::string key = "/Type /Pages";
  for (std::size_t at = pdf.find(key); at != std::string::npos; at = pdf.find(key, at + key.size())) {
    // The dictionary around the key (a page tree node holds no nested dictionary).
    const std::size_t open = pdf.rfind("<<", at), close = pdf.find(">>", at);
    if (open == std::string::npos || close == std::string::npos) continue;
    const std::string dict = pdf.substr(open, close - open);
    const std::size_t c = dict.find("/Count");
    if (c == std::string::npos) continue;
    count = std::max(count, std::atoi(dict.c_str() + c + 6));
  }
  return count;
}

}  // namespace dayphoton::report
