#!/usr/bin/env bash
# impm's entry script: installs what is missing (Debian packages), configures and builds in
# Release, then runs the demo or the test suite.  Idempotent: a second run only rebuilds
# what changed.
#
#   ./build.sh demo     build, run the default demo deck, say where its outputs are
#   ./build.sh test     build, run the whole ctest suite (unit, verification, MPI)
#   ./build.sh build    install dependencies and build only
#   ./build.sh benchmark  build, run the benchmarks and update doc/performance.md
#   ./build.sh sanitize   build with AddressSanitizer and UndefinedBehaviorSanitizer into its own
#                         directory (IMPM_SANITIZE_BUILD_DIR, default ./build-sanitize), run the
#                         unit tests and a deck of every problem family on 1 and 2 ranks
#
# Environment: IMPM_BUILD_DIR (default ./build), IMPM_JOBS (default: number of cores).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build_dir="${IMPM_BUILD_DIR:-$here/build}"
jobs="${IMPM_JOBS:-$(nproc)}"
demo_deck="input/colliding_disks.xml"

# Libraries and tools the build and the tests use.
build_packages=(cmake g++ make ccache trilinos-all-dev libptscotch-dev libscotch-dev
  openmpi-bin libopenmpi-dev libexodusii-dev netcdf-bin googletest libgtest-dev
  libbenchmark-dev libmuparser-dev libmumps-dev libpng-dev libtiff-dev python3)
# The tests also open the outputs in ParaView (under a virtual X server) and plot results.
test_packages=(paraview python3-paraview xvfb xauth python3-numpy python3-matplotlib
  python3-netcdf4 python3-meshio)

install_missing() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "impm: installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
}

build() {
  if [ ! -f "$build_dir/CMakeCache.txt" ]; then
    # Under CI a warning in impm's own code is an error (third-party headers are SYSTEM).
    cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
      -DIMPM_WERROR="$([ -n "${CI:-}" ] && echo ON || echo OFF)" \
      -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
  fi
  cmake --build "$build_dir" -j "$jobs"
}

cmd="${1:-demo}"
case "$cmd" in
  build)
    install_missing "${build_packages[@]}"
    build
    ;;
  demo)
    install_missing "${build_packages[@]}"
    build
    out="$build_dir/demo-output"
    cd "$here"
    "$build_dir/drivers/impm" --output-dir "$out" "$demo_deck"
    echo
    echo "impm: demo outputs are in $out"
    ls -1 "$out" | sed 's/^/  /'
    echo "Open the .exo files in ParaView (File > Open, Apply); particles appear as points,"
    echo "the grid as cells, colliding_disks_domains.exo as the deformed particle domains;"
    echo "colour by stress_yy.  The CSV files open in any spreadsheet."
    ;;
  test)
    install_missing "${build_packages[@]}" "${test_packages[@]}"
    # Configure again: a build directory made before the test packages were installed
    # (./build.sh demo) has not registered the checks that need them.
    [ -f "$build_dir/CMakeCache.txt" ] && cmake -S "$here" -B "$build_dir" >/dev/null
    build
    ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" --timeout 900
    ;;
  sanitize)
    install_missing "${build_packages[@]}"
    sanitize_dir="${IMPM_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
    cmake -S "$here" -B "$sanitize_dir" -DCMAKE_BUILD_TYPE=Release \
      -DIMPM_SANITIZE=address,undefined -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
    # The driver and the unit tests only: the tools and benchmarks are not run here.
    cmake --build "$sanitize_dir" -j "$jobs" --target impm unit_core unit_basis unit_bc \
      unit_material unit_assembly unit_solver unit_io unit_app
    # The slow unwinder: the fast one loses its way in libraries built without frame pointers,
    # and leaks of Open MPI then look like leaks of other libraries.
    export ASAN_OPTIONS="detect_leaks=1:fast_unwind_on_malloc=0:check_initialization_order=1"
    export LSAN_OPTIONS="suppressions=$here/test/sanitize/lsan.supp:print_suppressions=0"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
    # A failed test runs once more: LeakSanitizer's tracer can crash ("Tracer caught signal
    # 11") when it stops a process whose Open MPI threads are still ending; that was seen once
    # on 3 ranks of 2 cores.  A deterministic memory error fails both runs.
    ctest --test-dir "$sanitize_dir" --output-on-failure -j "$jobs" --timeout 900 \
      --repeat until-pass:2 -L "unit|sanitize"
    ;;
  benchmark)
    install_missing "${build_packages[@]}"
    build
    for b in static_bar dynamic_bar nonlinear_bar column column_grid scaling geometry \
        compressed_column; do
      python3 "$here/test/benchmark/$b.py" --impm "$build_dir/drivers/impm" \
        --write "$here/doc/performance.md"
    done
    ;;
  *)
    echo "usage: $0 [demo|test|build|benchmark|sanitize]" >&2
    exit 2
    ;;
esac
