#!/usr/bin/env bash
# The sanitizer build (AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer) and its
# test suites: configures build-sanitize with -DMPMICE_SANITIZE=ON, builds it (-j2, ccache), and
# runs the unit, verification and integration suites under ctest, one label after the other, each
# with its wall time. Any sanitizer report in our code fails its test (halt_on_error); the
# third-party runtimes' own leaks are suppressed by scripts/lsan.supp (Open MPI, PMIx, hwloc,
# HDF5, OpenFOAM; never a frame of this project). The OpenFOAM adapter tests run their
# uninstrumented solvers with libasan/libubsan preloaded. At the end the logs are searched for
# any sanitizer report ("ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "runtime error:"),
# and the script exits non-zero if a suite failed or a report was found.
#   scripts/sanitize.sh [extra ctest args]      e.g. scripts/sanitize.sh -R LaunchWatchdog
# Environment: MPMICE_SANITIZE_BUILD_DIR (default <repo>/build-sanitize), JOBS (default 2),
#   LABELS (default "unit verification integration"), TIMEOUT_FACTOR (default 10: every ctest
#   TIMEOUT is multiplied by it, instrumented code being several times slower; the bounds a test
#   asserts are unchanged), BUILD_ONLY=1 (configure and build, run nothing).
# Optimisation -O1 -g1 (not RelWithDebInfo's -O2 -g): the instrumented compile costs half the CPU
# (src/core/io/output_selection.cpp: 12.8 s user at -O2 -g, 5.9 s at -O1 -g1), and -g1 keeps the
# file:line of every frame in a report. Takes long: README.md (Building by hand) gives measured times.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build="${MPMICE_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
jobs="${JOBS:-2}"
labels="${LABELS:-unit verification integration}"
factor="${TIMEOUT_FACTOR:-10}"
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DMPMICE_SANITIZE=ON -DMPMICE_SANITIZER_TIMEOUT_FACTOR="$factor" -DMPMICE_WERROR=ON \
  -DMPMICE_BUILD_BENCHMARKS=OFF "${launcher[@]}"
cmake --build "$build" -j "$jobs"
[ "${BUILD_ONLY:-0}" = 1 ] && exit 0
cd "$build"
status=0
for label in $labels; do
  start=$(date +%s)
  ctest --output-on-failure -j "$jobs" -L "^${label}\$" "$@" 2>&1 | tee "sanitize-$label.log" \
    || status=1
  echo "sanitize.sh: label $label: $(( $(date +%s) - start )) s wall" | tee -a "sanitize-$label.log"
  cp Testing/Temporary/LastTest.log "sanitize-$label-all-output.log"
done
# A report inside a test that still passed (e.g. a child process whose status was not checked)
# must not go unseen: search ctest's full output of every test too.
reports=$(grep -l -E 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:' \
            sanitize-*.log 2>/dev/null || true)
if [ -n "$reports" ]; then
  echo "sanitize.sh: sanitizer reports in: $reports" >&2
  status=1
else
  echo "sanitize.sh: no sanitizer report in any log"
fi
exit "$status"
