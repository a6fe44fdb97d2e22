#!/usr/bin/env bash
# Integration test of the surface coupling MPM <-> OpenFOAM: `coupler run` on a tiny perpendicular
# flap (configs/flap_openfoam.yaml with a coarse MPM grid and the coarse variant of the case,
# 20 windows of 0.01 s), a real MPMD launch of mpm_solver and pimpleFoam.
#   run_flap.sh BIN_DIR WORKDIR explicit   # explicit_serial: 20 windows, finite forces, the tip moves downstream
#   run_flap.sh BIN_DIR WORKDIR implicit   # implicit_serial + IQN-ILS: converged windows, some with 2+ iterations
#   run_flap.sh BIN_DIR WORKDIR one_way    # one_way: fluid alone, then the solid relaxes under the last forces
#   run_flap.sh BIN_DIR WORKDIR bad_patch  # a patch name the case lacks: non-zero exit naming it and the valid ones
#   run_flap.sh BIN_DIR WORKDIR two_ranks  # explicit on 2 MPM ranks: the same tip as on 1 (to 1e-12 m)
set -euo pipefail
bin="$1"; work="$2"; mode="$3"
src="$(cd "$(dirname "$0")/../../.." && pwd)"
rm -rf "$work"; mkdir -p "$work"; cd "$work"
# The sanitizer build (-DMPMICE_SANITIZE=ON): pimpleFoam is not instrumented but loads the
# instrumented bridge, so the launch runs with the sanitizer runtime preloaded (MPMICE_SANITIZER_PRELOAD).
foam() { if [ -n "${MPMICE_SANITIZER_PRELOAD:-}" ]; then LD_PRELOAD="$MPMICE_SANITIZER_PRELOAD" "$@"; else "$@"; fi; }

. "$src/tests/integration/openfoam/flap_case.sh"
coarse_case "$src" case

schedule=explicit_serial; extra=""; patch=flap; ifmode=two_way; damping=0
case "$mode" in
  implicit) schedule=implicit_serial
            extra=$'  max_iterations: 20\n  acceleration: {type: iqn_ils, relaxation: 0.5}\n  convergence: [{field: interface_displacement, type: relative, limit: 1.0e-4, strict: true}]' ;;
  one_way) ifmode=one_way; damping=8 ;;
  bad_patch) patch=noSuchPatch ;;
  explicit|two_ranks) ;;
  *) echo "unknown mode $mode" >&2; exit 2 ;;
esac
flap_scene "$src" "$schedule" "$patch" "$ifmode" "$damping" "$extra" > flap.yaml

status=0
foam "$bin/coupler/coupler" run flap.yaml --bin-dir "$bin" > log.txt 2>&1 || status=$?
if [ "$mode" = two_ranks ] && [ "$status" -eq 0 ]; then
  cp out/flap_openfoam_probes.csv serial_probes.csv
  foam "$bin/coupler/coupler" run flap.yaml --bin-dir "$bin" --mpm-ranks 2 > log.txt 2>&1 || status=$?
fi
fail() { echo "FAIL ($mode): $*" >&2; grep -a -v "^GAMG\|^smooth\|^DIC\|^time step\|^Courant" log.txt | tail -40 >&2; exit 1; }

if [ "$mode" = bad_patch ]; then
  [ "$status" -ne 0 ] || fail "a patch that does not exist must stop the run"
  grep -q "unknown patch 'noSuchPatch'" log.txt || fail "the error does not name the patch"
  grep -q "valid patch names" log.txt && grep -q "flap" log.txt || fail "the error does not list the valid patches"
  echo "ok: bad patch stopped the run with status $status naming it"; exit 0
fi
[ "$status" -eq 0 ] || fail "coupler run ended with status $status"
# The solver's output is in its log (coupler/cli/launch_output.h), not on the terminal.
grep -q "^Time = " out/log.pimpleFoam || fail "out/log.pimpleFoam lacks the solver's time steps"
if grep -q "^Time = " log.txt; then fail "the solver's output reached the terminal"; fi
grep -q "^coupler: mpm_solver (" log.txt || grep -q "^mpm_solver: done: " log.txt || fail "no labelled mpm_solver summary"
csv=out/flap_openfoam_coupling.csv; probes=out/flap_openfoam_probes.csv
[ -f "$csv" ] && [ -f "$probes" ] || fail "missing $csv or $probes"
rows=$(($(wc -l < "$csv") - 1))
[ "$rows" -eq 20 ] || fail "expected 20 windows in $csv, got $rows"
# columns: window,time,dt,iterations,converged,substeps,force_x,force_y,force_z,...
awk -F, 'NR > 1 { for (i = 2; i <= 9; ++i) if ($i != $i + 0 || $i == "nan" || $i == "inf") bad = 1;
                  if (NR > 3 && $7 <= 0) bad = 1 } END { exit bad }' "$csv" || fail "non-finite values or no drag in $csv"
tip=$(tail -n1 "$probes" | cut -d, -f5)
case "$mode" in
  two_ranks)
    grep -q "2 MPM + 1 pimpleFoam rank" log.txt || fail "not launched on 2 MPM ranks"
    paste -d, serial_probes.csv "$probes" | awk -F, 'NR > 1 { for (i = 3; i <= 6; ++i) { d = $i - $(i + 6); if (d < 0) d = -d; if (d > 1e-12) bad = 1 } }
      END { exit bad }' || fail "the tip on 2 MPM ranks differs from 1 rank" ;;
  explicit)
    awk -F, 'NR > 1 && ($4 != 1 || $6 < 1) { exit 1 }' "$csv" || fail "explicit windows take one iteration and MPM sub-steps"
    awk -v u="$tip" 'BEGIN { exit !(u > 1e-3) }' || fail "tip x-displacement $tip: the flow must push the flap downstream" ;;
  implicit)
    awk -F, 'NR > 1 && $5 != 1 { exit 1 }' "$csv" || fail "an implicit window did not converge"
    awk -F, 'NR > 1 && $4 >= 2 { n++ } END { exit !(n >= 10) }' "$csv" || fail "implicit windows must iterate (2+ iterations)"
    grep -q "repeated (iteration" out/log.pimpleFoam || fail "the adapter never repeated a window (out/log.pimpleFoam)"
    awk -v u="$tip" 'BEGIN { exit !(u > 1e-3) }' || fail "tip x-displacement $tip" ;;
  one_way)
    awk -F, 'NR > 1 && $6 != 0 { exit 1 }' "$csv" || fail "the solid must not step while the fluid runs (one-way)"
    grep -q "one-way: the fluid's forces" log.txt || fail "no one-way transfer reported"
    awk -v u="$tip" 'BEGIN { exit !(u > 1e-3) }' || fail "static tip x-displacement $tip" ;;
esac
echo "ok: $mode, $rows windows, tip ux $tip"
