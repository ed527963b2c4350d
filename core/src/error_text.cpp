#include "dayphoton/core/error_text.h"

#include <string.h>

namespace dayphoton {

namespace {
// strerror_r comes in two forms (POSIX.1-2017, strerror_r; glibc's strerror_r(3)): the XSI
// one returns 0 and fills the buffer, the GNU one returns the text (maybe not in the buffer).
// Overloading on the result takes whichever the C library declares.
[[maybe_unused]] std::string text_of(int result, const char* buffer, int code) {
  return result == 0 ? std::string(buffer) : "unknown error " + std::to_string(code);
}
[[maybe_unused]] std::string text_of(const char* result, const char*, int code) {
  return result ? std::string(result) : "unknown error " + std::to_string(code);
}
}  // namespace

std::string error_text(int code) {
  char buffer[256] = "";
  return text_of(strerror_r(code, buffer, sizeof buffer), buffer, code);
}

}  // namespace dayphoton
