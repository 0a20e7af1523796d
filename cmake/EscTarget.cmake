# Warnings and include root shared by every esc target, set per target (no global flags).
# Headers are included from the project root ("runtime/eval/evaluator.hpp"); installed, from
# include/esc. Source paths are mapped to `.` so that no binary holds the build machine's.
function(esc_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion -ffile-prefix-map=${PROJECT_SOURCE_DIR}/=)
endfunction()

# Code that runs once per command or per generation (parsing, lowering, storage, reports, the
# command line), not per simulated step, is optimized at -O1: that cuts those files' compile
# time by a third to a half, the `esc` build's by about a tenth (docs/decisions.md,
# "Optimization levels"), and their run time is lost in the simulation's. IEEE results do not depend on the level (SSE2, no fast-math, no FMA).
function(esc_per_command_code target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
endfunction()

# A GoogleTest suite named after the module it tests, registered with ctest.
function(esc_add_test name)
  add_executable(${name} ${ARGN})
  esc_target_defaults(${name})
  target_link_libraries(${name} PRIVATE GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE ESC_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(${name} TEST_PREFIX "${name}." DISCOVERY_TIMEOUT 60 PROPERTIES LABELS ${name} TIMEOUT 300)
endfunction()
