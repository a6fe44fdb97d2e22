#!/usr/bin/env bash
# The underwater scene's shock in the water, small (issue 16): the scene cut to the water below the
# charge (no foam), run with mpmice for 18 us; benchmarks/underwater/shock_front.py follows the
# front down the axis and asserts its speed 2-5 cm below the charge and the front speed within 15 %
# of the water Hugoniot's speed for the simulated peak pressure behind it.
#   2d (default): configs/underwater_foam_2d.yaml (plane, x <= 8 cm, y >= 14.8 cm), the speed
#       within the slides' 2700 +- 250 m/s (measured 2556 m/s; 2636 m/s before 6 Dec 2026, when the charge
#       held 25 % more products than its box: docs/ice.md "What a fluid region fills").
#   3d: configs/underwater_foam_3d.yaml (quarter model, x, z <= 7.5 cm, y >= 15 cm, 6.25 mm cells),
#       the speed within 5 % of the same cut at 3.125 mm cells (2075 m/s; measured 2023 m/s; before 6 Dec,
#       the charge 25 % heavy, 2162 and 2089 m/s, asserted within 10 %): the
#       cylindrical charge's shock spreads in two directions and is slower there (docs/slides.md).
#   underwater_shock.sh SOURCE_DIR BUILD_DIR [2d|3d]
set -euo pipefail
src=$1 build=$2 dim=${3:-2d}
case "$dim" in
  2d) scene=$src/configs/underwater_foam_2d.yaml lower="[0.0, 0.148]" upper="[0.08, 0.3]" speed="2450 2950" ;;
  3d) scene=$src/configs/underwater_foam_3d.yaml lower="[0.0, 0.15, 0.0]" upper="[0.075, 0.3, 0.075]" speed="1970 2180" ;;
  *) echo "FAIL: underwater_shock.sh: dimension '$dim' is not 2d or 3d"; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$src/scripts/python" - "$scene" "$work/scene.yaml" "$lower" "$upper" <<'PY'
import sys, yaml
s = yaml.safe_load(open(sys.argv[1]))
s["mesh"]["lower"] = yaml.safe_load(sys.argv[3])
s["mesh"]["upper"] = yaml.safe_load(sys.argv[4])
s["time"]["end"] = 1.8e-5
s["geometry"] = [g for g in s["geometry"] if g["name"] != "foam"]
s["boundary"]["y-"] = "outflow"
s["output"]["directory"] = "out"
s["output"]["interval"] = 1.0e-6
s["output"]["particles"] = False   # no particles left: writing an empty particle set fails (HDF5)
yaml.safe_dump(s, open(sys.argv[2], "w"))
PY
cd "$work"
"$build/coupler/mpmice" scene.yaml > run.log 2>&1 || { tail -n 20 run.log; echo "FAIL: mpmice"; exit 1; }
"$src/scripts/python" "$src/benchmarks/underwater/shock_front.py" out --window 0.02 0.05 \
  --expect-speed $speed --hugoniot-tolerance 0.15
echo "PASS: underwater shock ($dim)"
