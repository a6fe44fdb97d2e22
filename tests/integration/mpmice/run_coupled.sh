#!/usr/bin/env bash
# Runs a scene with the monolithic driver (mpmice, 1 rank) and as an MPMD launch of mpm_solver
# (NMPM ranks) + ice_solver (NICE ranks); asserts that the conservation monitors (total masses,
# momentum, energies at every output time) agree to 1e-10 relative.
#   run_coupled.sh MPIRUN BIN_DIR SCENE NMPM NICE [SCHEDULE [ACCELERATION [TOL]]]
# SCHEDULE / ACCELERATION replace coupling.schedule / coupling.acceleration of the scene. TOL
# (default 1e-10): implicit schedules agree to their convergence limit only, since the
# iterations see round-off that depends on the rank layout.
set -u
mpirun=$1 bin=$2 scene=$3 nmpm=$4 nice=$5 schedule=${6:-} accel=${7:-none} tol=${8:-1e-10}
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
[ -s "$a" ] && [ -s "$b" ] || { echo "FAIL: a conservation CSV is missing"; exit 1; }
if [ "$(wc -l < "$a")" != "$(wc -l < "$b")" ] || [ "$(wc -l < "$a")" -lt 3 ]; then
  echo "FAIL: the runs wrote different numbers of rows"; cat "$a" "$b"; exit 1
fi
paste -d, "$a" "$b" | awk -F, -v tol="$tol" -v n="$(head -1 "$a" | awk -F, '{print NF}')" '
  NR == 1 { next }
  { for (i = 1; i <= n; ++i) {
      x = $i; y = $(i + n); d = x - y; if (d < 0) d = -d
      s = (x < 0 ? -x : x); t = (y < 0 ? -y : y); if (t > s) s = t
      r = d / (s > 1e-300 ? s : 1); if (d < 1e-12) r = 0
      if (r > worst) worst = r } }
  END { printf "largest relative difference of the monitors: %.3g\n", worst
        if (worst > tol) { printf "FAIL: monolithic and MPMD runs differ (tolerance %g)\n", tol; exit 1 }
        print "PASS" }'
