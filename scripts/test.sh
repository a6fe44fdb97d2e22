#!/usr/bin/env bash
# Sets up (installs what is missing), builds with warnings as errors, and runs the whole test suite.
#   scripts/test.sh [extra ctest args]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
bash "$here/scripts/openfoam_headers.sh" >/dev/null || echo "test.sh: OpenFOAM headers unavailable; the OpenFOAM adapter and its tests will be skipped" >&2
build="${MPMICE_BUILD_DIR:-$here/build}"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DMPMICE_WERROR=ON
cmake --build "$build" -j "$(nproc)"
cd "$build"
ctest --output-on-failure -j 2 "$@"
