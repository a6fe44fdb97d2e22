#!/usr/bin/env bash
# The closing line `fluid viscous heat: X J` of a viscous coupled run: printed by the monolithic
# driver (mpmice, 1 rank) and by the MPMD launch (mpm_solver 1 rank + ice_solver 2 ranks, the sum
# over the fluid's ranks) with the same X to 6 digits, and X > 0; and ice_solver alone on ICE_SCENE
# with a viscosity given to its first fluid, `viscous heat X J` on 1 and on 2 ranks, likewise.
#   viscous_heat_line.sh MPIRUN BIN_DIR SCENE ICE_SCENE
set -u
mpirun=$1 bin=$2 scene=$3 ice_scene=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/mono" "$work/mpmd" "$work/ice1" "$work/ice2"
(cd "$work/mono" && "$mpirun" -np 1 "$bin/coupler/mpmice" "$scene") > "$work/mono.log" 2>&1 || {
  cat "$work/mono.log"; echo "FAIL: mpmice failed"; exit 1; }
(cd "$work/mpmd" && "$mpirun" -np 1 "$bin/mpm_solver/mpm_solver" "$scene" : \
                              -np 2 "$bin/ice_solver/ice_solver" "$scene") > "$work/mpmd.log" 2>&1 || {
  cat "$work/mpmd.log"; echo "FAIL: the MPMD launch failed"; exit 1; }
# ICE alone: the first `specific_heat:` line gains a viscosity below it.
sed -e '0,/^\( *\)specific_heat: \(.*\)$/s//\1specific_heat: \2\n\1viscosity: 1.0e-3/' "$ice_scene" > "$work/ice.yaml"
for n in 1 2; do
  (cd "$work/ice$n" && "$mpirun" -np $n "$bin/ice_solver/ice_solver" "$work/ice.yaml") > "$work/ice$n.log" 2>&1 || {
    cat "$work/ice$n.log"; echo "FAIL: ice_solver on $n ranks failed"; exit 1; }
done
heat() { sed -n "s/$1 \([^ ]*\) J.*/\1/p" "$2"; }  # heat PATTERN LOG: the figure after PATTERN
same() {  # same WHAT A B: both present, positive, equal to 1e-6
  echo "$1: '$2' J against '$3' J"
  [ -n "$2" ] && [ -n "$3" ] || { echo "FAIL: no '$1' line"; exit 1; }
  awk -v a="$2" -v b="$3" 'BEGIN { d = a - b; if (d < 0) d = -d;
    if (!(a > 0)) { print "FAIL: the heat is not positive"; exit 1 }
    if (d > 1e-6 * a) { print "FAIL: the two launches differ"; exit 1 } }' || exit 1
}
same "fluid viscous heat: (mpmice, MPMD)" "$(heat '.*fluid viscous heat:' "$work/mono.log")" "$(heat '.*fluid viscous heat:' "$work/mpmd.log")"
same "viscous heat (ice_solver 1 rank, 2 ranks)" "$(heat '^viscous heat' "$work/ice1.log")" "$(heat '^viscous heat' "$work/ice2.log")"
