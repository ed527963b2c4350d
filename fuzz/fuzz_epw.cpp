// Fuzz harness: the EPW reader (weather::read_epw) on arbitrary bytes read as a weather file.
// Contract under test (epw_reader.h): any input either reads or throws InputError with located
// messages; nothing else escapes, and the sanitizers see no memory or undefined-behaviour error.
// Built for libFuzzer by fuzz/CMakeLists.txt and replayed over fuzz/corpus/epw by CTest
// (tests/fuzz/); docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/weather/epw_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const dayphoton::weather::EpwFile file = dayphoton::weather::read_epw(in, "fuzz.epw");
    for (const dayphoton::Diagnostic& warning : file.warnings) (void)warning.format();
  } catch (const dayphoton::InputError& error) {
    (void)error.what();
  }
  return 0;
}
