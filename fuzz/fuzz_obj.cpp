// Fuzz harness: the Wavefront OBJ reader (project::read_obj_from_string) on arbitrary bytes.
// Contract under test (obj_reader.h): every problem goes to the Diagnostics, nothing is thrown,
// and the sanitizers see no memory or undefined-behaviour error. docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/obj_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dayphoton::Diagnostics diagnostics;
  (void)dayphoton::project::read_obj_from_string(text, "fuzz.obj", diagnostics);
  (void)diagnostics.format();
  return 0;
}
