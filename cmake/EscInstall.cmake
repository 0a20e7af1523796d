# Where `cmake --install` puts esc, and the CMake package that lets other projects use its
# libraries (find_package(esc)). Two components: `runtime` (the esc command, its standard
# library and shipped scripts, docs, man page, bash completion) and `dev` (headers, static
# libraries, the package files); a third, `python` (the Python module esc), where it is built.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(ESC_INSTALL_STDLIB_DIR ${CMAKE_INSTALL_DATADIR}/esc/experiments)
set(ESC_INSTALL_INCLUDE_DIR ${CMAKE_INSTALL_INCLUDEDIR}/esc)
set(ESC_INSTALL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/esc)
# The standard library relative to the esc binary: how esc finds it wherever the tree is
# installed or moved, and the build tree stages experiments/ at the same place.
file(RELATIVE_PATH ESC_STDLIB_FROM_BINARY ${CMAKE_INSTALL_FULL_BINDIR}
     ${CMAKE_INSTALL_PREFIX}/${ESC_INSTALL_STDLIB_DIR})
# The Python package: where Debian's python3 looks for packages of Debian's own (never the
# multiarch libdir), and the standard library relative to it, which the package reads the
# same way (python/esc/_paths.py.in).
set(ESC_INSTALL_PYTHON_DIR lib/python3/dist-packages CACHE STRING "Where the Python package esc is installed, under the prefix")
file(RELATIVE_PATH ESC_STDLIB_FROM_PYTHON ${CMAKE_INSTALL_PREFIX}/${ESC_INSTALL_PYTHON_DIR}/esc
     ${CMAKE_INSTALL_PREFIX}/${ESC_INSTALL_STDLIB_DIR})

# Exports library targets as esc::<name without the esc_ prefix> (with the same aliases in
# the build tree); their headers keep their paths under include/esc.
function(esc_install_libraries)
  foreach(target ${ARGN})
    string(REGEX REPLACE "^esc_" "" name ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
    add_library(esc::${name} ALIAS ${target})
  endforeach()
  install(TARGETS ${ARGN} EXPORT escTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
          INCLUDES DESTINATION ${ESC_INSTALL_INCLUDE_DIR})
endfunction()

# The esc command and everything it reads or documents.
function(esc_install_program target)
  install(TARGETS ${target} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/experiments/ DESTINATION ${ESC_INSTALL_STDLIB_DIR} COMPONENT runtime)
  install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime
          FILES_MATCHING PATTERN "*.md" PATTERN "*.svg")
  install(FILES ${PROJECT_SOURCE_DIR}/docs/esc.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT runtime)
  install(FILES ${PROJECT_SOURCE_DIR}/scripts/esc-completion.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
          RENAME esc COMPONENT runtime)
endfunction()

install(DIRECTORY ${PROJECT_SOURCE_DIR}/compiler ${PROJECT_SOURCE_DIR}/runtime ${PROJECT_SOURCE_DIR}/app DESTINATION ${ESC_INSTALL_INCLUDE_DIR}
        COMPONENT dev FILES_MATCHING PATTERN "*.hpp" PATTERN assets EXCLUDE)
install(EXPORT escTargets NAMESPACE esc:: DESTINATION ${ESC_INSTALL_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/escConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/escConfig.cmake
                              INSTALL_DESTINATION ${ESC_INSTALL_CMAKE_DIR}
                              PATH_VARS ESC_INSTALL_STDLIB_DIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/escConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/escConfig.cmake ${PROJECT_BINARY_DIR}/escConfigVersion.cmake
        DESTINATION ${ESC_INSTALL_CMAKE_DIR} COMPONENT dev)
