#!/usr/bin/env bash
# The closed box through the MPMD launch: its conservation monitor equals mpmice's (every column,
# 1e-10), and in the MPMD launch's monitor the balance column (total energy less what MPM's
# numerics created) keeps its first value to 1e-11 of the fluid energy, and the masses stay.
#   check_energy_budget.sh MPIRUN BIN_DIR SCENE
set -u
mpirun=$1 bin=$2 scene=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/mpmd"
(cd "$work/mpmd" && "$mpirun" -np 1 "$bin/mpm_solver/mpm_solver" "$scene" : \
                              -np 1 "$bin/ice_solver/ice_solver" "$scene") > "$work/mpmd.log" 2>&1 || {
  cat "$work/mpmd.log"; echo "FAIL: the MPMD launch failed"; exit 1; }
csv=$(ls "$work"/mpmd/output/*_conservation.csv)
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  NR == 2 { b0 = $c["balance"]; f0 = $c["fluid_energy"]; s0 = $c["solid_mass"]; m0 = $c["fluid_mass"]; next }
  { d = $c["balance"] - b0; if (d < 0) d = -d; if (d > worst) worst = d
    if ($c["solid_mass"] != s0) badmass = 1
    dm = $c["fluid_mass"] - m0; if (dm < 0) dm = -dm; if (dm > 1e-12 * m0) badmass = 1; rows++ }
  END { printf "MPMD closed box: %d rows, balance moved by %.3g J of %.6g J fluid energy\n", rows, worst, f0
        if (rows < 2 || worst > 1e-11 * f0 + 1e-4 || badmass) { print "FAIL"; exit 1 }
        print "PASS" }' "$csv" || exit 1
exec "$(dirname "$0")/../../integration/mpmice/run_coupled.sh" "$mpirun" "$bin" "$scene" 1 1
