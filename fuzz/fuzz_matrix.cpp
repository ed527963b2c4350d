// Fuzz harness: the RADIANCE matrix reader (RadianceMatrix::read: ascii, float and double, either
// byte order) on arbitrary bytes. Contract under test (radiance_matrix.h): any input either
// reads or throws InputError; nothing else escapes, and the sanitizers see no memory or
// undefined-behaviour error. docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/radiance_matrix.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    (void)dayphoton::RadianceMatrix::read(in, "fuzz.mtx");
  } catch (const dayphoton::InputError& error) {
    (void)error.what();
  }
  return 0;
}
