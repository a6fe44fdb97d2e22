#!/usr/bin/env bash
# Sets up (installs what is missing), builds, and runs the main job:
#   scripts/run.sh [scene.yaml]
# The main job is the seed's validation: the pressurized steel cylinder in air
# (configs/pressurized_cylinder.yaml), mpm_solver + ice_solver in one MPMD launch (coupler run),
# then its Eq. 13 error against the Lame solution and a plot of the radial and hoop stresses
# (output/pressurized_cylinder/lame.png). A scene given as argument runs with the program its
# materials call for: solids and fluids -> coupler run (MPMD), solids -> mpm_solver, fluids ->
# ice_solver.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
build="${MPMICE_BUILD_DIR:-$here/build}"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)"
cd "$here"
scene="${1:-configs/pressurized_cylinder.yaml}"
"$build/coupler/coupler" check --quiet "$scene"
solids=$(grep -cE '^\s*kind:\s*solid' "$scene" || true)
fluids=$(grep -cE '^\s*kind:\s*fluid' "$scene" || true)
if [ "$scene" = configs/pressurized_cylinder.yaml ]; then
  "$build/coupler/coupler" run --bin-dir "$build" "$scene"
  exec "$build/benchmarks/coupled/cylinder_lame" output/pressurized_cylinder/pressurized_cylinder \
       output/pressurized_cylinder/lame --scene "$scene"
elif [ "$solids" -gt 0 ] && [ "$fluids" -gt 0 ]; then
  exec "$build/coupler/coupler" run --bin-dir "$build" "$scene"
elif [ "$solids" -gt 0 ]; then
  exec "$here/scripts/mpirun" -np 2 "$build/mpm_solver/mpm_solver" "$scene"
else
  exec "$here/scripts/mpirun" -np 2 "$build/ice_solver/ice_solver" "$scene"
fi
