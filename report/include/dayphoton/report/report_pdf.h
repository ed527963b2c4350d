// report.pdf: report.html printed by headless Chromium (Debian package `chromium`), the
// browser's own print of the page with the report's @media print rules (one plot per page
// piece, exact colours, no navigation), A4 or Letter as Chromium's default paper, without the
// browser's header and footer lines (--no-pdf-header-footer).
//
// Chromium runs as a child process with a time limit (killed with its process group when it
// runs over), a throw-away profile, HOME and XDG folders in a temporary folder beside the PDF
// (removed afterwards), so nothing is written outside the PDF's folder. It prints into a
// temporary file there, which is checked to be a PDF ("%PDF-" first) and renamed over the
// target: a failed or killed print leaves the previous PDF, or none. The renderer's sandbox is
// off (--no-sandbox): the page is the report dayphoton itself wrote, and the sandbox needs
// kernel features containers and root accounts often lack.
#pragma once

#include <stdexcept>
#include <string>

namespace dayphoton::report {

/// Headless Chromium is not on this machine: the message names the Debian package.
class PdfPrinterMissing : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PdfSettings {
  std::string browser;      ///< the executable; empty: `chromium`, then `chromium-browser`, on PATH
  double timeout_s = 120;   ///< Chromium is killed after this long (a whole report prints in seconds)
};

/// The executable `settings.browser` names (searched on PATH if it has no '/'), or the first
/// of chromium / chromium-browser on PATH; "" if there is none.
std::string find_pdf_printer(const PdfSettings& settings = {});

/// Print `html_path` to `pdf_path` (atomically; temporaries in pdf_path's folder) and return
/// pdf_path. PdfPrinterMissing if there is no Chromium; std::runtime_error naming the
/// browser's last log lines if it fails, runs over the time limit, or writes no PDF.
std::string print_pdf(const std::string& html_path, const std::string& pdf_path, const PdfSettings& settings = {});

/// The number of pages of a PDF's text as Chromium writes it (the /Count of its root
/// /Pages object); 0 if there is none.
int pdf_page_count(const std::string& pdf_bytes);

}  // namespace dayphoton::report
