#!/usr/bin/env bash
# Runs a scene with the monolithic driver (mpmice, 1 rank) and as an MPMD launch of mpm_solver
# (NMPM ranks) + ice_solver (NICE ranks); asserts that the conservation monitors (total masses,
# momentum, energies at every output time) agree to 1e-10 relative.
#   run_coupled.sh MPIRUN BIN_DIR SCENE NMPM NICE [SCHEDULE [ACCELERATION [TOL [LAST]]]]
# SCHEDULE / ACCELERATION replace coupling.schedule / coupling.acceleration of the scene. TOL
# (default 1e-10): implicit schedules agree to their convergence limit only, since the
# iterations see round-off that depends on the rank layout. LAST: compare the columns up to this
# one only (compare_monitors.sh).
set -u
mpirun=$1 bin=$2 scene=$3 nmpm=$4 nice=$5 schedule=${6:-} accel=${7:-none} tol=${8:-1e-10} last=${9:-0}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/mono" "$work/mpmd"
if [ -n "$schedule" ]; then
  sed -e "s/schedule: monolithic/schedule: $schedule/" "$scene" > "$work/scene.yaml"
  [ "$accel" = none ] || sed -i "s/^  fluid: ice$/  fluid: ice\n  acceleration: $accel/" "$work/scene.yaml"
  scene="$work/scene.yaml"
fi
(cd "$work/mono" && "$mpirun" -np 1 "$bin/coupler/mpmice" "$scene") > "$work/mono.log" 2>&1 || {
  cat "$work/mono.log"; echo "FAIL: mpmice failed"; exit 1; }
(cd "$work/mpmd" && "$mpirun" -np "$nmpm" "$bin/mpm_solver/mpm_solver" "$scene" : \
                              -np "$nice" "$bin/ice_solver/ice_solver" "$scene") > "$work/mpmd.log" 2>&1 || {
  cat "$work/mpmd.log"; echo "FAIL: the MPMD launch failed"; exit 1; }
grep -h "^done" "$work/mono.log" "$work/mpmd.log"
a=$(ls "$work"/mono/output/*_conservation.csv) b=$(ls "$work"/mpmd/output/*_conservation.csv)
exec "$(dirname "$0")/compare_monitors.sh" "$a" "$b" "$tol" "MPMD against mpmice" "$last"
