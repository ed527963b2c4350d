// Fuzz harness: the Honeybee model reader (project::read_honeybee_model_from_string) on
// arbitrary bytes. Contract under test (honeybee_model.h): bad input throws InputError and
// nothing else, and the sanitizers see no memory or undefined-behaviour error (the nesting
// limit keeps the located scan's recursion bounded). docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/honeybee_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)dayphoton::project::read_honeybee_model_from_string(text, "fuzz.hbjson");
  } catch (const dayphoton::InputError& e) {
    (void)e.what();
  }
  return 0;
}
