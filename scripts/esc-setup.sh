#!/usr/bin/env bash
# One-step set-up of esc on Debian bookworm (as root, or with sudo):
#   scripts/esc-setup.sh demo   install what is missing, build (Release), run a short real
#                               experiment end to end and print its table and result path
#   scripts/esc-setup.sh test   install what is missing, build, run the whole test suite
# BUILD_DIR (default build) and JOBS (default: all cores) may be set in the environment.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in demo|test) ;; *) echo "usage: $0 demo|test" >&2; exit 2;; esac

BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}
# What esc needs to build and run: all `demo` installs.
REQUIRED=(build-essential cmake ninja-build default-jre-headless antlr4 libantlr4-runtime-dev
          libbullet-dev libeigen3-dev libfmt-dev libtbb-dev libcli11-dev nlohmann-json3-dev libnanoflann-dev
          libsqlite3-dev zlib1g-dev pkg-config libboost-math-dev libjs-chart.js uuid-dev)   # uuid-dev: the ANTLR runtime links -luuid
# `test` builds the full variant, every optional part in (docs/install.md says what each needs).
OPTIONAL=(libopenmpi-dev openmpi-bin                                                           # ESC_WITH_MPI
          libbenchmark-dev                                                                     # ESC_WITH_BENCHMARK
          pybind11-dev python3-dev python3-numpy python3-pandas python3-pytest                 # ESC_WITH_PYTHON (pytest: its tests)
          python3-matplotlib python3-deap                                                      # examples/python, run by ctest
          libgtest-dev python3 chromium file                                                   # tests (file: cpack -G DEB)
          clang libclang-rt-14-dev)                                                            # ESC_WITH_FUZZ
PACKAGES=("${REQUIRED[@]}")
if [ "$mode" = test ]; then PACKAGES+=("${OPTIONAL[@]}"); fi
installed_now=0

install_missing() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "esc-setup: installing with apt what is missing: ${missing[*]}"
  local sudo=() log start=$SECONDS
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  # apt's own output (hundreds of lines) goes to a log; its end is shown if it fails.
  log=$(mktemp /tmp/esc-setup-apt.XXXXXX)
  if ! { "${sudo[@]}" apt-get update -qq &&
         DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
       } >"$log" 2>&1; then
    tail -n 25 "$log" >&2
    echo "esc-setup: error: apt-get failed (its whole output: $log)" >&2
    exit 1
  fi
  echo "esc-setup: installed ${#missing[@]} of the packages named and what they need," \
       "$(grep -c '^Setting up ' "$log" || true) in all, in $((SECONDS - start)) s; apt's output: $log"
  installed_now=1
}

# `demo` builds esc alone (the tests, benchmarks and fuzz targets are for `test`).
build() {
  # New packages (a `test` after a `demo`): configure afresh, so that the optional parts they
  # bring are found (the object files are kept).
  if [ "$installed_now" = 1 ]; then rm -f "$BUILD_DIR/CMakeCache.txt"; fi
  # The tests need GoogleTest, which `demo` does not install; `test` turns them on again.
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DESC_BUILD_TESTS="$([ "$mode" = test ] && echo ON || echo OFF)"
  if [ "$mode" = demo ]; then
    cmake --build "$BUILD_DIR" -j "$JOBS" --target esc
  else
    cmake --build "$BUILD_DIR" -j "$JOBS"
  fi
}

install_missing
build
if [ "$mode" = test ]; then
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
else
  out="runs/demo-$(date +%Y%m%d-%H%M%S)"
  # The paper's obstacle-avoidance comparison, shortened to a few minutes on 2 cores.
  "$BUILD_DIR/cli/esc" run experiments/paper/obstacle_avoidance.esc \
      --runs 3 --generations 30 --set epochs=5 --seed 1 --out "$out"
  "$BUILD_DIR/cli/esc" report "$out"
  # esc's own lines name `esc`; the one built here is not on PATH until installed.
  echo "esc-setup: done: $out holds esc.db, summary.json, per-run CSVs, best genomes and report.html;" \
       "this esc is $BUILD_DIR/cli/esc (\`cmake --install $BUILD_DIR\` puts it on PATH as esc)"
fi
