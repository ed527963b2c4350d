// Fuzz harness: the BSDF XML reader (read_bsdf_xml_text: LBNL WINDOW / IGSDB Klems files) on
// arbitrary bytes. Contract under test (core/bsdf_xml.h): any input either reads, with every
// value finite and >= 0 and every incoming patch's T + R within the tolerance, or throws
// InputError; nothing else escapes, and the sanitizers see no memory or undefined-behaviour
// error. docs/fuzzing.md.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "dayphoton/core/bsdf_xml.h"
#include "dayphoton/core/diagnostics.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto bsdf = dayphoton::read_bsdf_xml_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.xml");
    const std::size_t n = static_cast<std::size_t>(bsdf->basis.size());
    for (const auto* m : {&bsdf->transmission_front, &bsdf->transmission_back, &bsdf->reflection_front,
                          &bsdf->reflection_back}) {
      if (m->size() != n * n) std::abort();
      for (double v : *m)
        if (!(v >= 0) || !std::isfinite(v)) std::abort();
    }
  } catch (const dayphoton::InputError& error) {
    (void)error.what();
  }
  return 0;
}
