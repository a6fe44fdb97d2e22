#!/usr/bin/env bash
# The underwater scene with the slides' PVC tube around the charge (issue 16): configs/underwater_foam_2d.yaml
# with the tube's geometry object (4 mm PVC wall, x 12-16 mm, dipping 20 mm into the water), run with
# mpmice for 12 us. It used to stop at 7.0 us on a PVC particle at the tube's lower outer corner below
# 0 K: the embedded-fluid temperature rule (src/ice/exchange/trace_temperature.cpp) moved the
# expanding water of the tube's cells to the soft PVC's temperature change and took that heat from
# the PVC; it now moves both to their heat-capacity-weighted mean. Asserts the run completes (the
# health checks stop it with a non-zero status on any non-physical state) with the tube's
# particles in the output. Then the same scene at 2.5 mm cells to 6 us: it stopped at 4.13 us with
# the water in the tube's end cell at -2.6 K, cooled by the cell's energy correction, which charged
# the cell's heat capacities for the PVC's compression (the solid's own volume change, booked as
# work the fluids did, now comes from MPM: docs/coupling.md "The solid's own volume change").
#   underwater_tube.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$src/scripts/python" - "$src/configs/underwater_foam_2d.yaml" "$work/scene.yaml" <<'PY'
import sys, yaml
s = yaml.safe_load(open(sys.argv[1]))
tube = {"name": "tube", "shape": {"type": "box", "lo": [0.012, 0.23], "hi": [0.016, 0.262]},
        "material": "pvc", "particles_per_cell": 2}
names = [g["name"] for g in s["geometry"]]
s["geometry"].insert(names.index("charge"), tube)
s["time"]["end"] = 1.2e-5
s["output"]["directory"] = "out"
s["output"]["interval"] = 1.0e-5
yaml.safe_dump(s, open(sys.argv[2], "w"))
s["mesh"]["spacing"] = [0.0025, 0.0025]
s["time"]["end"] = 6.0e-6
s["output"]["directory"] = "out_fine"
s["output"]["interval"] = 0
yaml.safe_dump(s, open(sys.argv[2].replace(".yaml", "_fine.yaml"), "w"))
PY
cd "$work"
"$build/coupler/mpmice" scene_fine.yaml > run_fine.log 2>&1 || { tail -n 3 run_fine.log; echo "FAIL: mpmice with the tube at 2.5 mm"; exit 1; }
grep -q "^done" run_fine.log || { tail -n 3 run_fine.log; echo "FAIL: no closing line at 2.5 mm"; exit 1; }
echo "tube at 2.5 mm: $(grep '^done' run_fine.log)"
"$build/coupler/mpmice" scene.yaml > run.log 2>&1 || { tail -n 5 run.log; echo "FAIL: mpmice with the tube"; exit 1; }
grep -q "^done" run.log || { tail -n 5 run.log; echo "FAIL: no closing line"; exit 1; }
"$src/scripts/python" - out <<'PY'
import glob, sys, h5py, numpy as np
f = sorted(glob.glob(sys.argv[1] + "/*_[0-9][0-9][0-9][0-9][0-9][0-9].h5"))[-1]
with h5py.File(f) as h:
    x = h["particles/position"][:]
    T = h["particles/temperature"][:]
    t = float(h.attrs["time"])
    # mpmice writes each particle's material (its index in the scene's materials) and global id.
    if "particles/material" not in h or "particles/id" not in h:
        print("FAIL: no particles/material or particles/id in " + f)
        sys.exit(1)
    mat, ids = h["particles/material"][:], h["particles/id"][:]
tube = (x[:, 0] > 0.008) & (x[:, 1] > 0.2)   # the tube's particles (the foam lies below 3 cm)
print(f"t = {t:.3g} s: {tube.sum()} tube particles, temperature {T[tube].min():.2f} .. {T[tube].max():.2f} K")
if t < 1.2e-5 * (1 - 1e-9) or tube.sum() == 0 or not (T[tube].min() > 0):
    print("FAIL: tube state")
    sys.exit(1)
# The scene lists water, air, products, pvc, foam: the tube is material 3, the foam 4; ids unique.
if set(mat[tube].tolist()) != {3.0} or set(mat[~tube].tolist()) != {4.0} or len(set(ids.tolist())) != len(ids):
    print(f"FAIL: material indices {sorted(set(mat.tolist()))} or ids not as expected")
    sys.exit(1)
PY
echo "PASS: underwater tube"
