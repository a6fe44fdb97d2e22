#!/usr/bin/env bash
# Integration test of adapters/openfoam: runs Debian's icoFoam on the cavity tutorial with the
# mpmiceAdapter function object loaded.
#   run_cavity.sh LIB WORKDIR good   # patch movingWall: forces.csv has one finite row per step
#   run_cavity.sh LIB WORKDIR bad    # patch noSuchPatch: icoFoam exits non-zero naming the patch
set -euo pipefail
lib="$1"; work="$2"; mode="$3"
steps=5
tutorial=/usr/share/doc/openfoam-examples/examples/incompressible/icoFoam/cavity/cavity
export WM_PROJECT_DIR=/usr/share/openfoam

rm -rf "$work"; mkdir -p "$work"
cp -r "$tutorial"/. "$work"/
find "$work" -name '*.gz' -exec gunzip -f {} +
cd "$work"

patch=movingWall
[ "$mode" = bad ] && patch=noSuchPatch
# a few steps, no field writes; then the function object
sed -i -e 's/^endTime .*/endTime         0.025;/' -e 's/^writeInterval .*/writeInterval   1000;/' system/controlDict
cat >> system/controlDict <<EOD

libs ("$lib");

functions
{
    mpmiceAdapter
    {
        type    mpmiceAdapter;
        patch   $patch;
    }
}
EOD

# The sanitizer build (-DMPMICE_SANITIZE=ON): icoFoam is not instrumented but loads the
# instrumented bridge, so it runs with the sanitizer runtime preloaded (MPMICE_SANITIZER_PRELOAD).
foam() { if [ -n "${MPMICE_SANITIZER_PRELOAD:-}" ]; then LD_PRELOAD="$MPMICE_SANITIZER_PRELOAD" "$@"; else "$@"; fi; }
blockMesh > log.blockMesh 2>&1 || { cat log.blockMesh; exit 1; }

if [ "$mode" = bad ]; then
  if foam icoFoam > log.icoFoam 2>&1; then
    echo "FAIL: icoFoam exited 0 with an unknown patch name"; tail -n 30 log.icoFoam; exit 1
  fi
  if ! grep -q "noSuchPatch" log.icoFoam || ! grep -q "movingWall" log.icoFoam; then
    echo "FAIL: error message does not name the bad patch and the valid ones"; tail -n 30 log.icoFoam; exit 1
  fi
  grep -A2 "unknown patch" log.icoFoam
  echo "PASS: unknown patch rejected"
  exit 0
fi

foam icoFoam > log.icoFoam 2>&1 || { tail -n 40 log.icoFoam; exit 1; }
csv=postProcessing/mpmiceAdapter/forces.csv
[ -f "$csv" ] || { echo "FAIL: $csv missing"; tail -n 40 log.icoFoam; exit 1; }
nsteps=$(grep -c '^Time = ' log.icoFoam)
[ "$nsteps" = "$steps" ] || { echo "FAIL: expected $steps steps, icoFoam ran $nsteps"; exit 1; }
cat "$csv"
awk -F, -v n="$nsteps" '
  NR == 1 { if ($0 != "time,Fx,Fy,Fz") { print "FAIL: bad header: " $0; bad = 1 }; next }
  {
    rows++
    if (NF != 4) { print "FAIL: row " NR " has " NF " fields"; bad = 1 }
    for (i = 1; i <= 4; i++)
      if ($i !~ /^-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/) { print "FAIL: not finite: " $i; bad = 1 }
    if ($1 + 0 <= prev) { print "FAIL: time not increasing at row " NR; bad = 1 }
    prev = $1 + 0
    if ($2 * $2 + $3 * $3 == 0) { print "FAIL: zero force at row " NR; bad = 1 }
  }
  END {
    if (rows != n) { print "FAIL: " rows " rows for " n " steps"; bad = 1 }
    exit bad
  }' "$csv"
echo "PASS: $nsteps steps, $nsteps finite force rows"
