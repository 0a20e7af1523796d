# Optional parts of esc. Each is a cache variable set to AUTO (used when found, the default),
# ON (required: configuring fails without it) or OFF (left out). A build without them passes
# its own tests; esc_report_optional_parts() says at the end of configuring what was left out.

# Declares the option `var`, then finds `package` (with the find_package arguments in ARGN)
# as the option asks; `var`_FOUND says whether the part is built.
macro(esc_optional_package var doc package)
  esc_optional_mode(${var} "${doc}")
  if(_esc_mode STREQUAL "ON")
    find_package(${package} ${ARGN} REQUIRED)
  elseif(_esc_mode STREQUAL "AUTO")
    find_package(${package} ${ARGN} QUIET)
  endif()
  set(${var}_FOUND OFF)
  if(NOT _esc_mode STREQUAL "OFF" AND ${package}_FOUND)
    set(${var}_FOUND ON)
  endif()
endmacro()

# The same for a program: `var`_FOUND, and the program's path in `var`_PROGRAM.
macro(esc_optional_program var doc)
  esc_optional_mode(${var} "${doc}")
  set(${var}_FOUND OFF)
  if(NOT _esc_mode STREQUAL "OFF")
    find_program(${var}_PROGRAM NAMES ${ARGN})
    if(${var}_PROGRAM)
      set(${var}_FOUND ON)
    elseif(_esc_mode STREQUAL "ON")
      message(FATAL_ERROR "${var} is ON but none of ${ARGN} was found")
    endif()
  endif()
endmacro()

# ESC_WITH_FUZZ: the libFuzzer targets (tests/fuzz), found when a clang++ links a fuzz
# target with -fsanitize=fuzzer,address,undefined (Debian: clang libclang-rt-14-dev). Sets
# ESC_WITH_FUZZ_FOUND and ESC_WITH_FUZZ_CLANG.
macro(esc_optional_fuzzer)
  esc_optional_mode(ESC_WITH_FUZZ "Fuzz the compiler with libFuzzer (Debian: clang libclang-rt-14-dev)")
  set(ESC_WITH_FUZZ_FOUND OFF)
  if(NOT _esc_mode STREQUAL "OFF")
    find_program(ESC_WITH_FUZZ_CLANG NAMES clang++ clang++-16 clang++-15 clang++-14)
    if(ESC_WITH_FUZZ_CLANG)
      set(_probe ${CMAKE_BINARY_DIR}/fuzz-probe)
      file(WRITE ${_probe}/probe.cpp "#include <cstddef>\n#include <cstdint>\n"
                 "extern \"C\" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }\n")
      execute_process(COMMAND ${ESC_WITH_FUZZ_CLANG} -fsanitize=fuzzer,address,undefined probe.cpp -o probe
                      WORKING_DIRECTORY ${_probe} RESULT_VARIABLE _esc_rc OUTPUT_QUIET ERROR_QUIET)
      if(_esc_rc EQUAL 0)
        set(ESC_WITH_FUZZ_FOUND ON)
      endif()
    endif()
    if(NOT ESC_WITH_FUZZ_FOUND AND _esc_mode STREQUAL "ON")
      message(FATAL_ERROR "ESC_WITH_FUZZ is ON but no clang++ links with -fsanitize=fuzzer (Debian: clang "
                          "libclang-rt-14-dev)")
    endif()
  endif()
endmacro()

# Declares the option and sets _esc_mode to AUTO, ON or OFF.
macro(esc_optional_mode var doc)
  set(${var} AUTO CACHE STRING "${doc}: AUTO (when found), ON (required) or OFF")
  set_property(CACHE ${var} PROPERTY STRINGS AUTO ON OFF)
  string(TOUPPER "${${var}}" _esc_mode)
  if(_esc_mode MATCHES "^(YES|TRUE|1)$")
    set(_esc_mode ON)
  elseif(_esc_mode MATCHES "^(NO|FALSE|0)$")
    set(_esc_mode OFF)
  elseif(NOT _esc_mode MATCHES "^(AUTO|ON|OFF)$")
    message(FATAL_ERROR "${var} is `${${var}}`: it must be AUTO, ON or OFF")
  endif()
endmacro()

# One line per optional part: built in, or what it needs.
function(esc_report_optional_parts)
  message(STATUS "esc optional parts:")
  if(ESC_WITH_MPI_FOUND)
    message(STATUS "  MPI (ESC_WITH_MPI)                  yes: esc shares evaluations among mpirun ranks")
  else()
    message(STATUS "  MPI (ESC_WITH_MPI)                  no: esc runs as one process (needs libopenmpi-dev)")
  endif()
  if(ESC_WITH_BENCHMARK_FOUND)
    message(STATUS "  Google Benchmark (ESC_WITH_BENCHMARK) yes: esc bench")
  else()
    message(STATUS "  Google Benchmark (ESC_WITH_BENCHMARK) no: esc bench measures nothing, esc bench --campaign "
                   "still estimates (needs libbenchmark-dev)")
  endif()
  if(ESC_BUILD_TESTS AND ESC_WITH_FUZZ_FOUND)
    message(STATUS "  fuzz targets (ESC_WITH_FUZZ)        yes: ctest fuzz.compile, fuzz.set (${ESC_WITH_FUZZ_CLANG})")
  elseif(ESC_BUILD_TESTS)
    message(STATUS "  fuzz targets (ESC_WITH_FUZZ)        no: needs clang and libclang-rt-14-dev")
  endif()
  if(NOT ESC_BUILD_TESTS)
    message(STATUS "  tests (ESC_BUILD_TESTS)             no")
  elseif(ESC_WITH_CHROMIUM_FOUND)
    message(STATUS "  report test in Chromium (ESC_WITH_CHROMIUM) yes: ${ESC_WITH_CHROMIUM_PROGRAM}")
  else()
    message(STATUS "  report test in Chromium (ESC_WITH_CHROMIUM) no: the page is checked without a browser "
                   "(needs chromium)")
  endif()
endfunction()
