#!/usr/bin/env bash
# ctest of what `cmake --install` and CPack produce (tests/install/CMakeLists.txt):
#   install_test.sh prefix    SOURCE BUILD WORK   install into WORK/staged, then move it to
#                                                 WORK/prefix (the tree must not care where it is)
#   install_test.sh installed SOURCE BUILD WORK   the installed esc, run from / with ESC_PATH
#                                                 unset: no build path inside it, its own library,
#                                                 ESC_PATH, check, a short run and a replay
#   install_test.sh embed     SOURCE BUILD WORK   examples/embed built against the installed package
#   install_test.sh package   SOURCE BUILD WORK   the .deb files and what they declare
# With $ESC_PYTHON (the interpreter the Python module is built for), the module too.
# Exit 0: passed; 77: skipped (a tool it needs is missing); anything else: failed.
set -euo pipefail
mode=$1 source_dir=$2 build_dir=$3 work=$4
prefix=$work/prefix
fail() { echo "FAIL: $*" >&2; exit 1; }

case $mode in
prefix)
  rm -rf "$work"
  mkdir -p "$work"
  cmake --install "$build_dir" --prefix "$work/staged" >"$work/install.log"
  mv "$work/staged" "$prefix"
  ;;

installed)
  esc=$prefix/bin/esc
  library=$prefix/share/esc/experiments
  [ -x "$esc" ] || fail "no $esc"
  for f in lib/khepera.esc paper/obstacle_avoidance.esc paper/energy.esc gp/nn_vs_gp.esc examples/quick_start.esc; do
    [ -f "$library/$f" ] || fail "$library/$f not installed"
  done
  [ -f "$prefix/share/man/man1/esc.1" ] || fail "no man page"
  [ -f "$prefix/share/doc/esc/language.md" ] || fail "no docs"
  # Every figure an installed page links to is installed beside it.
  for f in $(cd "$prefix/share/doc/esc" && grep -oh '(figures/[^)]*\.svg)' *.md | tr -d '()' | sort -u); do
    [ -f "$prefix/share/doc/esc/$f" ] || fail "docs link to $f, which is not installed"
  done
  bash -n "$prefix/share/bash-completion/completions/esc" || fail "bash completion does not parse"
  # No path of the machine that built it.
  if strings "$esc" | grep -F -e "$source_dir" -e "$build_dir"; then fail "esc holds a build path"; fi
  cd /
  unset ESC_PATH
  "$esc" --version | tee "$work/version.txt"
  grep -qxF "standard library: $library" "$work/version.txt" || fail "esc does not use its installed library"
  "$esc" check "$library"/paper/*.esc "$library"/gp/*.esc "$library"/examples/*.esc >/dev/null
  # A user's script importing from the standard library, and from $ESC_PATH.
  mkdir -p "$work/user/mylib"
  printf 'import "lib/khepera.esc"\nimport "extra.esc"\n' >"$work/user/uses_libs.esc"
  printf 'behavior spin_left() { wheels(-0.5, 0.5) }\n' >"$work/user/mylib/extra.esc"
  if "$esc" check "$work/user/uses_libs.esc" >"$work/no_path.log" 2>&1; then fail "extra.esc found without ESC_PATH"; fi
  grep -q "cannot find \`extra.esc\`" "$work/no_path.log" || fail "no clear error without ESC_PATH: $(cat "$work/no_path.log")"
  ESC_PATH=$work/user/mylib "$esc" check "$work/user/uses_libs.esc"
  # A short run of a shipped paper script, and its replay.
  rm -rf "$work/run"
  "$esc" run "$library/paper/obstacle_avoidance.esc" --runs 1 --generations 1 --set epochs=1 --set steps=20 \
      --threads 2 --out "$work/run" >"$work/run.log"
  [ -f "$work/run/summary.json" ] || fail "no summary.json"
  "$esc" replay "$work/run" --controller SC_8_14_6
  grep -q "<svg" "$work/run/replay-SC_8_14_6-run-01.svg" || fail "no replay SVG"
  # The Python module, where it is built ($ESC_PYTHON: its interpreter): importable from the
  # prefix, reading the installed library, holding no build path; it reads the run above.
  if [ -n "${ESC_PYTHON:-}" ]; then
    packages=$prefix/lib/python3/dist-packages
    [ -f "$packages/esc/__init__.py" ] || fail "no Python package in $packages/esc"
    if strings "$packages"/esc/_esc*.so | grep -F -e "$source_dir" -e "$build_dir"; then fail "esc._esc holds a build path"; fi
    PYTHONPATH=$packages PYTHONDONTWRITEBYTECODE=1 "$ESC_PYTHON" - "$library" "$work/run" <<'PY'
import sys
import esc
from esc._library import standard_library
library, run = sys.argv[1:]
assert standard_library() == library, standard_library()
script = esc.compile('import "paper/obstacle_avoidance.esc"\n', {"epochs": 1, "steps": 20})
best = esc.open(run).best("SC_8_14_6", 1)
print("python: esc", esc.__version__, "from", esc.__file__, script.experiments, "fitness", best.fitness)
PY
  fi
  ;;

embed)
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  rm -rf "$work/embed"
  cmake -S "$source_dir/examples/embed" -B "$work/embed" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" ${ESC_TEST_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$ESC_TEST_LAUNCHER} >"$work/embed.log"
  cmake --build "$work/embed" >>"$work/embed.log"
  cd /
  "$work/embed/embed" | tee "$work/embed.out"
  grep -q "^genome of 66 weights: fitness" "$work/embed.out" || fail "no evaluation"
  grep -q "^run 2: best fitness" "$work/embed.out" || fail "no campaign"
  "$work/embed/embed_study" | tee "$work/embed_study.out"
  grep -q "^running study inertia (2 conditions: with_inertia, without)" "$work/embed_study.out" || fail "no study"
  grep -q "^condition without CC: best fitness" "$work/embed_study.out" || fail "no study outcome"
  ;;

package)
  command -v dpkg-deb >/dev/null && command -v dpkg-shlibdeps >/dev/null || exit 77
  rm -rf "$work/package"
  (cd "$build_dir" && cpack -G DEB -B "$work/package" >"$work/cpack.log")
  deb=$(ls "$work"/package/esc_*.deb)
  dev=$(ls "$work"/package/esc-dev_*.deb)
  depends=$(dpkg-deb -f "$deb" Depends)
  echo "esc Depends: $depends"
  for lib in libbullet libtbb libsqlite3 libantlr4-runtime libfmt libstdc++6; do
    grep -q "$lib" <<<"$depends" || fail "esc does not declare $lib"
  done
  files=$(dpkg-deb -c "$deb")
  dev_files=$(dpkg-deb -c "$dev")
  grep -q "\./usr/bin/esc$" <<<"$files" || fail "no /usr/bin/esc"
  grep -q "\./usr/share/esc/experiments/lib/khepera.esc$" <<<"$files" || fail "no standard library"
  grep -q "\./usr/share/man/man1/esc.1" <<<"$files" || fail "no man page"
  grep -q "esc (= " <<<"$(dpkg-deb -f "$dev" Depends)" || fail "esc-dev does not depend on esc"
  grep -q "\./usr/lib/.*cmake/esc/escConfig.cmake$" <<<"$dev_files" || fail "no CMake package"
  grep -q "\./usr/include/esc/compiler/compiler.hpp$" <<<"$dev_files" || fail "no headers"
  if [ -n "${ESC_PYTHON:-}" ]; then
    python=$(ls "$work"/package/python3-esc_*.deb)
    python_depends=$(dpkg-deb -f "$python" Depends)
    echo "python3-esc Depends: $python_depends"
    for dep in "esc (= " python3-numpy python3-pandas "python3 (>= " libtbb; do
      grep -qF "$dep" <<<"$python_depends" || fail "python3-esc does not declare $dep"
    done
    python_files=$(dpkg-deb -c "$python")
    for f in __init__.py _paths.py '_esc\..*\.so'; do
      grep -q "\./usr/lib/python3/dist-packages/esc/$f$" <<<"$python_files" || fail "python3-esc has no esc/$f"
    done
  fi
  ;;

*) fail "unknown mode $mode" ;;
esac
echo "ok: $mode"
