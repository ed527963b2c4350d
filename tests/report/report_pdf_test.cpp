// report.pdf (report/report_pdf.h): a tiny daylight-factor run's report printed by headless
// Chromium is a PDF of more than one page (the summary, then each grid on a page of its own)
// with no temporary left beside it; a missing browser names the Debian package; a browser that
// hangs is stopped at the time limit and one that prints nothing leaves no PDF. The Chromium
// test is skipped, saying so, when Chromium is not installed (scripts/setup.sh installs it).
#include "dayphoton/report/report_pdf.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dayphoton/project/project.h"
#include "dayphoton/report/report_html.h"
#include "dayphoton/study/cache_folder.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "../temp_folder.h"
#include "run_with_report.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

const char* const Project =
    "site: {latitude: 51.5, longitude: -0.12, time_zone: 0}\n"
    "study: daylight_factor\n"
    "materials:\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "  glazing: {type: glass, transmittance: 0.7}\n"
    "geometry:\n"
    "  rooms:\n"
    "    - name: room\n"
    "      size: [3, 4, 3]\n"
    "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
    "      windows: [{name: win, wall: south, width: 2, height: 1.2, sill: 1.0, offset: 0.5, material: glazing}]\n"
    "sensors:\n"
    "  grids: [{name: floor, room: room, height: 0.8, spacing: 0.5}]\n"
    "simulation: {photons_per_bin: 100, seed: 5}\n";

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}


/// An executable shell script `body` in `dir`.
std::string script(const fs::path& dir, const std::string& body) {
  const fs::path p = dir / "fake_browser.sh";
  std::ofstream(p) << "#!/bin/sh\n" << body << "\n";
  ::chmod(p.c_str(), 0755);
  return p.string();
}

/// Names in `dir` other than `keep`.
std::vector<std::string> others(const fs::path& dir, const std::vector<std::string>& keep) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (std::find(keep.begin(), keep.end(), n) == keep.end()) out.push_back(n);
  }
  return out;
}

}  // namespace

TEST(ReportPdf, ChromiumPrintsTheReportOnSeveralPages) {
  if (report::find_pdf_printer().empty())
    GTEST_SKIP() << "chromium is not installed (Debian package 'chromium'; scripts/setup.sh installs it)";
  const fs::path root = test::empty_dir("report_pdf_chromium");
  std::ofstream(root / "project.yaml") << Project;
  const project::Project project = project::load_project((root / "project.yaml").string());
  const fs::path out = root / "run";
  test::run_with_report(project, out);
  ASSERT_TRUE(fs::exists(out / "report.html"));

  const std::string pdf = report::print_pdf((out / "report.html").string(), (out / "report.pdf").string());
  EXPECT_EQ(pdf, (out / "report.pdf").string());
  const std::string bytes = read_bytes(out / "report.pdf");
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(0, 5), "%PDF-");
  // The summary, then the grid's section on a new page (the report's print rules).
  const int pages = report::pdf_page_count(bytes);
  EXPECT_GE(pages, 2);
  EXPECT_LE(pages, 40);
  // Nothing else was left in the folder: no profile, no temporary.
  const std::vector<std::string> left =
      others(out, {"report.html", "report.pdf", "results.json", "summary.json", "run.log", "timings.json", "floor"});
  EXPECT_TRUE(left.empty()) << left.front();
}

TEST(ReportPdf, PageCountReadsTheRootPageTree) {
  EXPECT_EQ(report::pdf_page_count("%PDF-1.4\n1 0 obj\n<</Type /Pages\n/Count 7\n/Kids [2 0 R]>>\nendobj\n"
                                   "2 0 obj\n<</Type /Pages\n/Count 3\n/Parent 1 0 R>>\nendobj\n"),
            7);
  EXPECT_EQ(report::pdf_page_count("%PDF-1.4\n<</Type /Page>>"), 0);
}

TEST(ReportPdf, AMissingBrowserNamesTheDebianPackage) {
  report::PdfSettings settings;
  settings.browser = (test::empty_dir("report_pdf_missing") / "no-such-chromium").string();
  EXPECT_EQ(report::find_pdf_printer(settings), "");
  const fs::path dir = test::empty_dir("report_pdf_missing_html");
  std::ofstream(dir / "report.html") << "<html></html>";
  try {
    report::print_pdf((dir / "report.html").string(), (dir / "report.pdf").string(), settings);
    FAIL() << "no error";
  } catch (const report::PdfPrinterMissing& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-chromium"), std::string::npos) << e.what();
  }
  // Without a named browser, the message names the package (checked on the text itself, as
  // this machine may have Chromium).
  const char* const path = std::getenv("PATH");
  const std::string saved = path ? path : "";
  ::setenv("PATH", dir.c_str(), 1);
  try {
    report::print_pdf((dir / "report.html").string(), (dir / "report.pdf").string());
    ADD_FAILURE() << "no error";
  } catch (const report::PdfPrinterMissing& e) {
    EXPECT_NE(std::string(e.what()).find("Debian package 'chromium'"), std::string::npos) << e.what();
  }
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_FALSE(fs::exists(dir / "report.pdf"));
}

TEST(ReportPdf, AHangingBrowserIsStoppedAtTheTimeLimit) {
  const fs::path dir = test::empty_dir("report_pdf_hang");
  std::ofstream(dir / "report.html") << "<html></html>";
  std::ofstream(dir / "report.pdf") << "%PDF-1.4 the previous one";
  report::PdfSettings settings;
  settings.browser = script(dir, "echo starting; sleep 30");
  settings.timeout_s = 0.5;
  const auto start = std::chrono::steady_clock::now();
  try {
    report::print_pdf((dir / "report.html").string(), (dir / "report.pdf").string(), settings);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("did not finish within 0.5 s"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("starting"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  // The previous PDF stays; no temporary is left.
  EXPECT_EQ(read_bytes(dir / "report.pdf"), "%PDF-1.4 the previous one");
  EXPECT_TRUE(others(dir, {"report.html", "report.pdf", "fake_browser.sh"}).empty());
}

TEST(ReportPdf, ABrowserThatPrintsNothingLeavesNoPdf) {
  const fs::path dir = test::empty_dir("report_pdf_nothing");
  std::ofstream(dir / "report.html") << "<html></html>";
  report::PdfSettings settings;
  settings.browser = script(dir, "echo cannot print >&2; exit 0");
  try {
    report::print_pdf((dir / "report.html").string(), (dir / "report.pdf").string(), settings);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("wrote no PDF"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot print"), std::string::npos) << e.what();
  }
  settings.browser = script(dir, "exit 3");
  EXPECT_THROW(report::print_pdf((dir / "report.html").string(), (dir / "report.pdf").string(), settings),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "report.pdf"));
  EXPECT_TRUE(others(dir, {"report.html", "fake_browser.sh"}).empty());
}
