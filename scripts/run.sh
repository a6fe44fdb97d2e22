#!/usr/bin/env bash
# Sets up (installs what is missing), builds, and runs the main job:
#   scripts/run.sh [scene.yaml]
# Today the main job is the Lame thick cylinder with MPM alone on 2 ranks (the verified solid
# side of the seed problem; output under output/mpm_lame_cylinder). The coupled MPM-ICE cylinder
# (configs/pressurized_cylinder.yaml through `coupler run`) becomes the main job once its
# long run is stable (see docs/coupling.md). A scene given as argument runs with the program its
# materials call for: solids and fluids -> coupler run (MPMD), solids -> mpm_solver, fluids ->
# ice_solver.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
build="${MPMICE_BUILD_DIR:-$here/build}"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)"
cd "$here"
scene="${1:-configs/mpm_lame_cylinder.yaml}"
"$build/coupler/coupler" check --quiet "$scene"
solids=$(grep -cE '^\s*kind:\s*solid' "$scene" || true)
fluids=$(grep -cE '^\s*kind:\s*fluid' "$scene" || true)
if [ "$solids" -gt 0 ] && [ "$fluids" -gt 0 ]; then
  exec "$build/coupler/coupler" run --bin-dir "$build" "$scene"
elif [ "$solids" -gt 0 ]; then
  exec "$here/scripts/mpirun" -np 2 "$build/mpm_solver/mpm_solver" "$scene"
else
  exec "$here/scripts/mpirun" -np 2 "$build/ice_solver/ice_solver" "$scene"
fi
