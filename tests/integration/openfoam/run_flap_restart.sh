#!/usr/bin/env bash
# Restart of MPM + OpenFOAM (`coupler run --restart`) equals the uninterrupted run: the coarse
# flap of run_flap.sh (20 windows of 0.01 s, output.checkpoint_interval 0.05 s: checkpoints at
# windows 5, 10, 15, 20) runs to its end in WORK/full; its output directory (with the case copy
# the fluid ran in) is copied to WORK/resumed as a run killed after the checkpoint of window 10
# would leave it: the MPM output files written after that checkpoint and the later checkpoints
# removed, and the case copy's time directories after t = 0.1 removed, so the fluid must write
# them again (the CSVs keep the rows written after it: the resumed run cuts them); then
# `coupler run --restart` (MODE file: the checkpoint file of window 10; dir: the output directory)
# resumes both sides, mpm_solver from its checkpoint and pimpleFoam from the time directory 0.1.
# Compared after the end (compare_restart.py): every array of every MPM HDF5 file (output steps
# and checkpoints: every particle array), the probes and coupling CSVs (without the wall-time
# columns), the XDMF index byte for byte, and every file of the fluid's last time directory
# (fields, mesh points, clock) number by number.
# Tolerance, max |a - b| <= tol * max |a| per array, CSV column or fluid file (compare_restart.py):
#   explicit 1e-10: the time directories are written with 17 significant digits (`coupler run`
#     sets writePrecision 17 when checkpoints are on), which read back every double exactly, and
#     hold what the next window reads (fields, moved points, the displacements the solid sent last
#     as pointDisplacement's patch value); the clock resumes exactly (startTime to 17 digits). The
#     restart is not bit for bit: measured 1.0e-14 in the fluid (p), 2.5e-13 in the particles'
#     stress, 7e-13 in the probes' 12 printed digits (round-off of state OpenFOAM rebuilds on
#     reading, not found); 1e-10 leaves a margin of 400 over that.
#   implicit 1e-9: measured 5.8e-15 in the fluid (p), 2.5e-11 in the particles and the IQN-ILS
#     columns, 2.1e-11 in the residual column (the acceleration's least squares amplify round-off).
#     Before the adapter dropped GAMG's cached agglomeration after each step (mpmiceAdapter.C) the
#     runs differed at 1.3e-4 (p) from the first window after the restart on.
#   run_flap_restart.sh BIN_DIR WORKDIR explicit|implicit file|dir
set -euo pipefail
bin="$1"; work="$2"; mode="$3"; from="$4"
src="$(cd "$(dirname "$0")/../../.." && pwd)"
rm -rf "$work"; mkdir -p "$work/full" "$work/resumed"; cd "$work"
foam() { if [ -n "${MPMICE_SANITIZER_PRELOAD:-}" ]; then LD_PRELOAD="$MPMICE_SANITIZER_PRELOAD" "$@"; else "$@"; fi; }
fail() { echo "FAIL ($mode, $from): $*" >&2; for f in full.log resumed.log; do [ -f "$f" ] && { echo "== $f" >&2;
  grep -a -v "^GAMG\|^smooth\|^DIC\|^time step\|^Courant" "$f" | tail -25 >&2; }; done; exit 1; }

. "$src/tests/integration/openfoam/flap_case.sh"
coarse_case "$src" case
schedule=explicit_serial; extra=""
if [ "$mode" = implicit ]; then
  schedule=implicit_serial
  extra=$'  max_iterations: 20\n  acceleration: {type: iqn_ils, relaxation: 0.5}\n  convergence: [{field: interface_displacement, type: relative, limit: 1.0e-4, strict: true}]'
fi
flap_scene "$src" "$schedule" flap two_way 0 "$extra" | sed 's/^  interval: 0.1/  interval: 0.05\n  checkpoint_interval: 0.05/' > flap.yaml
grep -q "checkpoint_interval: 0.05" flap.yaml || fail "the scene has no checkpoint_interval"

(cd full && foam "$bin/coupler/coupler" run ../flap.yaml --bin-dir "$bin") > full.log 2>&1 || fail "the full run failed"
base=flap_openfoam
mapfile -t cks < <(cd full/out && ls ${base}_checkpoint_*.h5 | sort)
[ "${#cks[@]}" -eq 4 ] || fail "the full run wrote ${#cks[@]} checkpoints, expected 4 (windows 5, 10, 15, 20)"
ck=${cks[1]}
[ "$ck" = ${base}_checkpoint_000010.h5 ] || fail "the second checkpoint is $ck, expected window 10"
grep -q "restart state written at t = 0.1 " full/out/log.pimpleFoam || fail "the fluid did not write its state at t = 0.1"

cp -r full/out resumed/out
removed=0
for f in $(cd full/out && find . -maxdepth 1 -name "${base}_*.h5" -newer "$ck" | sort); do  # written after $ck
  rm "resumed/out/$f"; removed=$((removed + 1))
done
[ "$removed" -ge 3 ] || fail "only $removed MPM files written after $ck to recompute"
for d in resumed/out/case/[0-9]*; do
  if awk -v t="$(basename "$d")" 'BEGIN { exit !(t > 0.1 + 1e-9) }'; then rm -r "$d"; fi
done
[ ! -d resumed/out/case/0.2 ] && [ -d resumed/out/case/0.1 ] || fail "the case copy's time directories were not cut at 0.1"
where=out; [ "$from" = file ] && where=out/$ck
(cd resumed && foam "$bin/coupler/coupler" run --restart "$where" ../flap.yaml --bin-dir "$bin") > resumed.log 2>&1 ||
  fail "the resumed run failed"
grep -q "^coupler: pimpleFoam resumes from .*/out/case/0.1 " resumed.log || fail "the fluid did not resume from 0.1"
grep -q "restart: out/${ck}" resumed/out/log.mpm_solver || fail "mpm_solver did not resume from $ck"

last=$(cd full/out/case && ls -d [0-9]* | sort -g | tail -1)
[ "$last" = 0.2 ] || fail "the full run's last time directory is $last, expected 0.2"
tol=1e-10; [ "$mode" = implicit ] && tol=1e-9
"$src/scripts/python" "$src/tests/integration/openfoam/compare_restart.py" full/out resumed/out "$last" "$tol" > compare.txt 2>&1 ||
  { cat compare.txt >&2; fail "the resumed run differs from the uninterrupted one"; }
cat compare.txt
for f in U p phi pointDisplacement polyMesh/points; do
  [ -f "full/out/case/$last/$f" ] || fail "the fluid's time directory $last lacks $f"
done
echo "ok: $mode from $where: the resumed run equals the uninterrupted one to $tol of each array's largest value"
