// Fuzz harness: the BSDF XML reader (read_bsdf_xml_text: LBNL WINDOW / IGSDB Klems files and
// TensorTree3/4 files) on arbitrary bytes. Contract under test (core/bsdf_xml.h): any input
// either reads, with every value finite and >= 0 and every incoming patch's (or incident
// cell's) T + R within the tolerance, or throws InputError; nothing else escapes, and the
// sanitizers see no memory or undefined-behaviour error (a tree's depth, size and tables are
// bounded before anything is allocated). docs/fuzzing.md.
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
    if (const auto& tt = bsdf->tensor_tree) {
      for (const auto& side : tt->slices)
        for (const auto& slice : side) {
          if (slice.cells.empty() || slice.cumulative.size() != slice.cells.size()) std::abort();
          if (!(slice.albedo <= 1.0 + dayphoton::BsdfAlbedoTolerance) || !(slice.transmittance >= 0)) std::abort();
        }
      for (const auto& tree : tt->trees) {
        const double pos[4] = {0.3, 0.999, 0.0, 0.5};  // ndim (3 or 4) coordinates
        if (!(tree.lookup(pos) >= 0)) std::abort();
      }
    }
  } catch (const dayphoton::InputError& error) {
    (void)error.what();
  }
  return 0;
}
