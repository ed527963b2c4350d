// Fuzz harness: the RADIANCE scene reader (project::read_radiance_scene_from_string) on
// arbitrary bytes. Contract under test (radiance_scene.h): every problem goes to the
// Diagnostics, nothing is thrown, no command is ever run, and the sanitizers see no memory or
// undefined-behaviour error. The scene's path lies in a folder that does not exist, so an
// `!xform` with a relative file reads nothing. docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/radiance_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dayphoton::Diagnostics diagnostics;
  for (bool skip : {false, true}) {
    dayphoton::project::RadianceSceneOptions options;
    options.skip_unsupported = skip;
    (void)dayphoton::project::read_radiance_scene_from_string(text, "/nonexistent-fuzz-folder/fuzz.rad", options,
                                                              diagnostics);
  }
  (void)diagnostics.format();
  return 0;
}
