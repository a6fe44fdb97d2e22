#!/usr/bin/env bash
# The same Sod shock tube in OpenFOAM's rhoCentralFoam and in ice_solver, side by side: wall time
# (median of 3 runs, one core) and L1 density error against the exact solution at t = 0.2.
#
#   benchmarks/ice/sod_vs_rhocentralfoam.sh [cells=1000] [build-dir=build]
#
# OpenFOAM: the shockTube tutorial of rhoCentralFoam copied to a temp dir, its mesh changed to 1D
# [0, 1] with the same cells, Sod's states set with setFields (scaled to the tutorial's units: same
# density profile), the matching end time; everything else (Kurganov fluxes, van Leer, maxCo 0.2)
# as in the tutorial, in the tutorial's dimensional units (see below). ICE: configs/ice_sod.yaml with the same cells (second order, explicit,
# CFL 0.4). Errors: ice_sod_l1 (benchmarks/ice/sod_l1.cpp) with the exact Riemann solver of the
# tests. Prints a markdown table (docs/ice.md keeps the results).
set -euo pipefail
N=${1:-1000}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${2:-$ROOT/build}
[[ "$BUILD" = /* ]] || BUILD=$ROOT/$BUILD
ICE=$BUILD/ice_solver/ice_solver
L1=$BUILD/benchmarks/ice/ice_sod_l1
TUT=/usr/share/doc/openfoam-examples/examples/compressible/rhoCentralFoam/shockTube
for f in "$ICE" "$L1"; do [ -x "$f" ] || { echo "missing $f (build the targets ice_solver ice_sod_l1)" >&2; exit 1; }; done
[ -d "$TUT" ] || { echo "missing $TUT (apt-get install openfoam-examples)" >&2; exit 1; }
export WM_PROJECT_DIR=/usr/share/openfoam
WORK=$(mktemp -d /tmp/sod_vs_foam.XXXXXX)
if [ "${KEEP:-0}" = 1 ]; then echo "work dir: $WORK"; else trap 'rm -rf "$WORK"' EXIT; fi

now() { date +%s.%N; }
median3() { printf '%s\n' "$@" | sort -g | sed -n 2p; }

# ---- OpenFOAM case
FOAM=$WORK/foam
cp -r "$TUT" "$FOAM"
chmod -R u+w "$FOAM"
cp -r "$FOAM/0.orig" "$FOAM/0"
sed -i -e 's/(-5 -1 -1)/(0 -0.05 -0.05)/; s/(5 -1 -1)/(1 -0.05 -0.05)/; s/(5 1 -1)/(1 0.05 -0.05)/' \
       -e 's/(-5 1 -1)/(0 0.05 -0.05)/; s/(-5 -1 1)/(0 -0.05 0.05)/; s/(5 -1 1)/(1 -0.05 0.05)/' \
       -e 's/(5 1 1)/(1 0.05 0.05)/; s/(-5 1 1)/(0 0.05 0.05)/' \
       -e "s/(100 1 1)/($N 1 1)/" "$FOAM/system/blockMeshDict"
# Dimensional Sod (the tutorial's own gas, air with R = 8314.46/28.96, Cp = 3.5 R so gamma = 1.4):
# p = 1e5 | 1e4 Pa, rho = 1 | 0.125 kg/m^3, so velocities scale by sqrt(1e5) and the density profile
# at t = 0.2 / sqrt(1e5) s is Sod's dimensionless one at t = 0.2.
R=$(echo "8314.46261815324 / 28.96" | bc -l)
CP=$(echo "3.5 * $R" | bc -l)
TL=$(echo "100000 / $R" | bc -l)
TR=$(echo "10000 / (0.125 * $R)" | bc -l)
TEND=$(echo "0.2 / sqrt(100000)" | bc -l)
sed -i -e "s/Cp .*;/Cp              $CP;/" -e 's/molWeight .*;/molWeight       28.96;/' \
       "$FOAM/constant/thermophysicalProperties"
cat > "$FOAM/system/setFieldsDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setFieldsDict; }
defaultFieldValues ( volVectorFieldValue U (0 0 0) volScalarFieldValue T $TL volScalarFieldValue p 100000 );
regions ( boxToCell { box (0.5 -1 -1) (2 1 1); fieldValues ( volScalarFieldValue T $TR volScalarFieldValue p 10000 ); } );
DICT
sed -i -e "s/^endTime .*/endTime         $TEND;/" -e 's/^deltaT .*/deltaT          1e-09;/' \
       -e "s/^writeInterval .*/writeInterval   $TEND;/" -e 's/^writePrecision .*/writePrecision  12;/' \
       -e 's/^timePrecision .*/timePrecision   12;/' "$FOAM/system/controlDict"
(cd "$FOAM" && blockMesh > log.blockMesh 2>&1 && setFields > log.setFields 2>&1)
foam_times=()
for run in 1 2 3; do
  find "$FOAM" -maxdepth 1 -name '0.0*' -exec rm -rf {} +
  t0=$(now)
  (cd "$FOAM" && rhoCentralFoam > log.rhoCentralFoam 2>&1)
  foam_times+=("$(echo "$(now) - $t0" | bc -l)")
done
foam_steps=$(grep -c '^Time = ' "$FOAM/log.rhoCentralFoam" || true)
foam_last=$(cd "$FOAM" && ls -d 0.0* | sort -g | tail -1)
foam_err=$("$L1" --foam "$FOAM/$foam_last/rho")

# ---- ICE case
SCENE=$WORK/ice_sod.yaml
sed -e "s/cells: \[400\]/cells: [$N]/" -e "s#directory: output/ice_sod#directory: $WORK/ice#" \
    -e 's/interval: 0.05/interval: 0/' "$ROOT/configs/ice_sod.yaml" > "$SCENE"
ice_times=()
for run in 1 2 3; do
  rm -rf "$WORK/ice"
  t0=$(now)
  "$ICE" "$SCENE" > "$WORK/ice.log" 2>&1
  ice_times+=("$(echo "$(now) - $t0" | bc -l)")
done
ice_steps=$(sed -n 's/.*done: \([0-9]*\) steps.*/\1/p' "$WORK/ice.log")
last=$(ls "$WORK"/ice/*.h5 | sort | tail -1)
ice_err=$("$L1" --ice "$last")

fw=$(median3 "${foam_times[@]}"); iw=$(median3 "${ice_times[@]}")
echo "Sod, $N cells, t = 0.2, one core (wall: median of 3 runs, whole program)"
echo
echo "| solver | steps | wall [s] | cell-steps/s | L1(rho) |"
echo "|---|---|---|---|---|"
printf '| rhoCentralFoam (Kurganov, van Leer, maxCo 0.2) | %s | %.3f | %.3g | %s |\n' "$foam_steps" "$fw" \
  "$(echo "$N * $foam_steps / $fw" | bc -l)" "$foam_err"
printf '| ice_solver (second order, van Leer, CFL 0.4) | %s | %.3f | %.3g | %s |\n' "$ice_steps" "$iw" \
  "$(echo "$N * $ice_steps / $iw" | bc -l)" "$ice_err"
