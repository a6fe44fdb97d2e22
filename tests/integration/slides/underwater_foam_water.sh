#!/usr/bin/env bash
# The water-filled foam under the underwater shock runs past its former stop (issue 16,
# docs/slides.md "The three foam models"): benchmarks/underwater/foam_models.py's water-filled
# model at the shipped scene's depth (--full: the foam on the container's bottom, 21 cm below the
# charge), cut to x <= 4 cm (10 x 75 cells; the x+ slip wall keeps the charge's half width), run with
# mpmice to 120 us.
# Before the Lagrangian energy fix and the advection fallback guarded the thermal energy e - e_cold
# (src/ice/sources/lagrangian_phase.cpp, src/ice/advection/advection_phase.cpp), they guarded e
# itself: the Mie-Gruneisen water with reference_temperature 300 has e = 0 at 300 K, so in the
# cells it shares with the foam's top every energy share that took it from ~+4e4 J/kg (310 K) to
# below 10 % of that was refused as a drain of its internal energy and the refused share audited;
# this cut stopped on the energy audit at 94.7 us (step 1166, cell (3,7)), the full width at 103.2 us.
# Asserts: mpmice completes (exit 0, the last probe row at the end time) and the shock has reached
# and crushed the foam (its top on the axis lower by more than 1 mm).
#   underwater_foam_water.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$src/scripts/python" - "$src" "$build" <<'PY'
import csv, os, subprocess, sys
import yaml
src, build = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(src, "benchmarks", "underwater"))
import foam_models as F

end, width = 1.2e-4, 0.04
s = F.scene("water", end, full=True)
s["mesh"]["upper"][0] = width
for g in s["geometry"]:
    g["shape"]["hi"][0] = min(g["shape"]["hi"][0], width)
s["output"]["interval"] = 1.0e-5
yaml.safe_dump(s, open("scene.yaml", "w"), sort_keys=False)
with open("run.log", "w") as log:
    rc = subprocess.call([os.path.join(build, "coupler", "mpmice"), "scene.yaml"], stdout=log, stderr=subprocess.STDOUT)
if rc != 0:
    print(open("run.log").read()[-2000:])
    sys.exit(f"FAIL: mpmice exit {rc} on the water-filled foam (the former stop: the energy audit at 94.7 us)")
rows = list(csv.DictReader(open(os.path.join(s["output"]["directory"], s["scene"] + "_probes.csv"))))
t, crush = float(rows[-1]["time"]), -float(rows[-1]["foam_top_uy"])
print(f"water-filled foam, x <= {width} m: t = {t:.6g} s, {rows[-1]['step']} steps, crush on the axis {crush * 1e3:.3f} mm")
if abs(t - end) > 1e-9 * end:
    sys.exit(f"FAIL: the run ended at t = {t} s, expected time.end = {end} s")
if not crush > 1.0e-3:
    sys.exit(f"FAIL: the foam's top moved {crush * 1e3:.3f} mm, expected a crush above 1 mm (the shock reaches it at ~90 us)")
PY
echo "PASS: water-filled foam"
