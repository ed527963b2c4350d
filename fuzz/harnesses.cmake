# The fuzz harnesses (fuzz/fuzz_<name>.cpp, each defining LLVMFuzzerTestOneInput) and the
# libraries each one needs. Included by fuzz/CMakeLists.txt (libFuzzer binaries, clang only)
# and by tests/fuzz/CMakeLists.txt (the replay of fuzz/corpus/<name> in every build's tests).
set(DAYPHOTON_FUZZ_DIR ${CMAKE_CURRENT_LIST_DIR})
set(DAYPHOTON_FUZZ_HARNESSES project epw obj pts matrix rad hbjson bsdf)
set(DAYPHOTON_FUZZ_LIBS_project dayphoton::project)
set(DAYPHOTON_FUZZ_LIBS_epw dayphoton::weather)
set(DAYPHOTON_FUZZ_LIBS_obj dayphoton::project)
set(DAYPHOTON_FUZZ_LIBS_pts dayphoton::project)
set(DAYPHOTON_FUZZ_LIBS_matrix dayphoton::core)
set(DAYPHOTON_FUZZ_LIBS_rad dayphoton::project)
set(DAYPHOTON_FUZZ_LIBS_hbjson dayphoton::project)
set(DAYPHOTON_FUZZ_LIBS_bsdf dayphoton::core)

# An executable `target` from harness `name` plus the extra sources given after it.
function(dayphoton_fuzz_executable target name)
  add_executable(${target} ${DAYPHOTON_FUZZ_DIR}/fuzz_${name}.cpp ${ARGN})
  target_link_libraries(${target} PRIVATE ${DAYPHOTON_FUZZ_LIBS_${name}} dayphoton_warnings)
  target_compile_definitions(${target} PRIVATE
    DAYPHOTON_FUZZ_FIXTURE_DIR="${DAYPHOTON_FUZZ_DIR}/fixture")
endfunction()
