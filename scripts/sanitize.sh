#!/usr/bin/env bash
# The sanitizer build (AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer) and its
# test suites: configures build-sanitize with -DMPMICE_SANITIZE=ON, builds it (-j2, ccache), and
# runs the unit, verification and integration suites under ctest. Any sanitizer report in our
# code fails its test (halt_on_error); the third-party runtimes' own leaks are suppressed by
# scripts/lsan.supp (Open MPI, PMIx, hwloc, HDF5, OpenFOAM; never a frame of this project). The
# OpenFOAM adapter tests run their uninstrumented solvers with libasan/libubsan preloaded.
#   scripts/sanitize.sh [extra ctest args]      e.g. scripts/sanitize.sh -R LaunchWatchdog
# Environment: MPMICE_SANITIZE_BUILD_DIR (default <repo>/build-sanitize), JOBS (default 2).
# Takes long: the instrumented build is about twice the normal one, the tests 2-4x slower.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build="${MPMICE_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
jobs="${JOBS:-2}"
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMPMICE_SANITIZE=ON -DMPMICE_WERROR=ON \
  -DMPMICE_BUILD_BENCHMARKS=OFF "${launcher[@]}"
cmake --build "$build" -j "$jobs"
cd "$build"
ctest --output-on-failure -j 2 -L 'unit|verification|integration' "$@"
