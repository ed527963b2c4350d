// Fuzz harness: the project loader on arbitrary bytes written as a project file, together with
// the files a project names. The input is written to project.yaml in a private temporary folder
// that also holds a one-day EPW (weather.epw), a sensor point file (points.pts) and an OBJ mesh
// (mesh.obj), copied from fuzz/fixture/ at start-up, so that the seeds of fuzz/corpus/project
// (the example projects, renamed to these files) reach every stage: project::load_project, then
// project::build_scene_description, which reads the .pts and .obj files and builds the scene
// (of the base project and of every variant).
// Contract under test (project.h): both either succeed or throw InputError; nothing else
// escapes, and the sanitizers see no memory or undefined-behaviour error. docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"

#ifndef DAYPHOTON_FUZZ_FIXTURE_DIR
#error "DAYPHOTON_FUZZ_FIXTURE_DIR (fuzz/fixture) must be defined by the build"
#endif

namespace fs = std::filesystem;

namespace {

/// A temporary folder holding a copy of fuzz/fixture/, removed at exit.
class FixtureFolder {
 public:
  FixtureFolder() {
    std::string pattern = (fs::temp_directory_path() / "dayphoton-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create " + pattern);
    m_path = pattern;
    fs::copy(DAYPHOTON_FUZZ_FIXTURE_DIR, m_path, fs::copy_options::recursive);
  }
  ~FixtureFolder() {
    std::error_code ignored;
    fs::remove_all(m_path, ignored);
  }
  FixtureFolder(const FixtureFolder&) = delete;
  FixtureFolder& operator=(const FixtureFolder&) = delete;

  const fs::path& path() const { return m_path; }

 private:
  fs::path m_path;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const FixtureFolder folder;
  const std::string project_path = (folder.path() / "project.yaml").string();
  {
    std::ofstream out(project_path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) throw std::runtime_error("cannot write " + project_path);
  }
  try {
    const dayphoton::project::Project project = dayphoton::project::load_project(project_path);
    (void)dayphoton::project::build_scene_description(project);
    for (const dayphoton::project::VariantSpec& variant : project.variants)
      (void)dayphoton::project::build_scene_description(
          dayphoton::project::apply_variant(project, variant));
  } catch (const dayphoton::InputError& error) {
    (void)error.what();
  }
  return 0;
}
