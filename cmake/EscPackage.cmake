# Debian packages of esc (`cpack -G DEB` in the build directory, or `cmake --build build
# --target package`): esc (the command, its standard library and scripts, docs, man page,
# bash completion) with its shared-library dependencies found by dpkg-shlibdeps, esc-dev
# (headers, static libraries, the CMake package) depending on the -dev packages its
# exported targets need, and, where the Python module is built, python3-esc. Built for and
# tested on Debian bookworm.
set(CPACK_PACKAGE_NAME esc)
set(CPACK_PACKAGE_VENDOR "esc")
set(ESC_PACKAGE_MAINTAINER "esc maintainers <maintainers@esc.invalid>" CACHE STRING
    "Maintainer field of the Debian packages")
set(CPACK_PACKAGE_CONTACT "${ESC_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME esc)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
string(CONCAT CPACK_DEBIAN_RUNTIME_DESCRIPTION
    "esc evolves neural and genetic-programming controllers for a simulated Khepera robot\n"
    "from experiments written in a small declarative language, compares them over many\n"
    "independent runs and reports the results (SQLite store, HTML report, SVG replays).")
set(esc_suggests "ffmpeg | imagemagick")
if(ESC_WITH_MPI_FOUND)
  string(PREPEND esc_suggests "openmpi-bin, ")
endif()
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "${esc_suggests}")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME esc-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
string(CONCAT CPACK_DEBIAN_DEV_DESCRIPTION
    "The libraries and headers of esc: find_package(esc) gives esc::compiler (scripts to\n"
    "experiments) and esc::runtime (evaluating genomes, running campaigns, storing and reporting results).")
# uuid-dev: the ANTLR runtime's CMake target links -luuid, which Debian's
# libantlr4-runtime-dev does not pull in (found installing esc-dev on a clean bookworm).
string(CONCAT esc_dev_depends "esc (= ${PROJECT_VERSION}), cmake, libeigen3-dev, libbullet-dev, libfmt-dev, "
       "libtbb-dev, nlohmann-json3-dev, libantlr4-runtime-dev, uuid-dev, libsqlite3-dev, zlib1g-dev, pkg-config, libboost-dev")
if(ESC_WITH_MPI_FOUND)
  string(APPEND esc_dev_depends ", libopenmpi-dev")
endif()
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "${esc_dev_depends}")

# The Python module: its extension is built for one Python minor version, and it reads the
# standard library that the esc package installs.
if(ESC_WITH_PYTHON_FOUND)
  list(APPEND CPACK_COMPONENTS_ALL python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-esc)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SHLIBDEPS ON)
  math(EXPR esc_python_next "${Python3_VERSION_MINOR} + 1")
  set(esc_python_version ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR})
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "esc (= ${PROJECT_VERSION}), python3 (>= ${esc_python_version}), python3 (<< ${Python3_VERSION_MAJOR}.${esc_python_next}), python3-numpy, python3-pandas")
  string(CONCAT CPACK_DEBIAN_PYTHON_DESCRIPTION
      "The Python module esc: compile esc's experiment scripts, read its run directories as pandas\n"
      "tables, evaluate genomes with its simulator (the fitness esc computes, on every thread) and\n"
      "step its experiments like a Gymnasium environment.")
endif()

include(CPack)
