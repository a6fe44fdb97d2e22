#!/usr/bin/env bash
# Sets up (installs what is missing), builds, and runs the main job.
#   scripts/run.sh [scene.yaml]
# The main job is the default scene of the most complete program that exists; it prints what it
# does and writes HDF5/XDMF output under output/.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
build="${MPMICE_BUILD_DIR:-$here/build}"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)"
cd "$here"
scene="${1:-}"
if [ -x "$build/ice_solver/ice_solver" ] && [ -x "$build/mpm_solver/mpm_solver" ] && [ -x "$build/coupler/coupler" ] \
   && "$build/coupler/coupler" --help 2>/dev/null | grep -q '^ *run'; then
  exec "$build/coupler/coupler" run "${scene:-configs/pressurized_cylinder.yaml}"
elif [ -x "$build/ice_solver/ice_solver" ]; then
  exec "$here/scripts/mpirun" -np 2 "$build/ice_solver/ice_solver" "${scene:-configs/ice_sod.yaml}"
else
  exec "$build/coupler/coupler" check "${scene:-configs/pressurized_cylinder.yaml}"
fi
