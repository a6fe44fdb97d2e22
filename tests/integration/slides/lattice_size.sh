#!/usr/bin/env bash
# The lattice specimen's size (issue 16: 2 to 8 cells per edge; benchmarks/lattice/lattice_compression.py
# --study size, docs/slides.md "Specimen size"):
#   1. the size study's scene with 2 cells per edge is the shipped one (mesh and geometry);
#   2. a = 4.5 mm with 2 and 4 cells per edge (a quarter of 2 x 2 cells) on a 0.15 mm mesh to 42 %
#      strain with mpm_solver: the first yield (mean plate stress over 4-12 %) is the walls' yield
#      (t/a) sigma_y' within 25 % for both (the shipped scenes' test asserts it for 2 per edge), and
#      the plateau rises less with 4 per edge (stress at 38-42 % over 8-12 %: measured at 0.1 mm,
#      2.39 with 2 per edge, 1.66 with 4): the mirror planes no longer hold every wall straight, so
#      inner walls can buckle (docs/slides.md "Specimen size");
#   3. the filled study's open-cell scene with 2 and 4 cells per edge has a window in every wall
#      across x, one per row of cells, the liquid in the quarter's pores (geometry only).
#   lattice_size.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$src/scripts/python" - "$src" "$build" <<'PY'
import math, os, subprocess, sys
import yaml
src, build = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(src, "benchmarks", "lattice"))
import lattice_compression as L

config, a, rho = L.SCENES[0]
shipped = yaml.safe_load(open(os.path.join(src, config)))
two = L.size_scene(config, a, 2)
if two["mesh"] != shipped["mesh"] or two["geometry"] != shipped["geometry"]:
    sys.exit("FAIL: the size study's 2-per-edge scene is not the shipped scene")

# The filled study's open-cell scene with n cells per edge (open_scene(..., n)): a window in every
# wall across x (x = i a), one per row of cells, the interior walls cut through their whole
# thickness, the liquid in the quarter's pores [0, n/2 a]^2, the plate at rate x n/2 a; with n = 2
# the study's scene of one window in the outer half wall.
def inside(shape, x, y):
    if shape["type"] == "box":
        return all(lo <= v <= hi for lo, v, hi in zip(shape["lo"], (x, y), shape["hi"]))
    first, *rest = shape["shapes"]
    return inside(first, x, y) and not any(inside(r, x, y) for r in rest)


hm, rate = 1.5e-4, 2000.0
window = math.pi * L.PORE_D ** 2 / (4 * a)
for n in (2, 4):
    k = n // 2
    s = L.open_scene(config, a, hm, rate, 100.0, room=9e-3, filler="pores", n=n)
    lattice = next(g for g in s["geometry"] if g["name"] == "lattice")["shape"]
    filler = next(g for g in s["geometry"] if g["name"] == "filler")["shape"]
    plate = next(g for g in s["geometry"] if g["name"] == "plate")
    half = lattice["shapes"][1]["lo"][0]
    if len(lattice["shapes"]) != 1 + k * k + k * k:
        sys.exit(f"FAIL: {n} per edge: {len(lattice['shapes'])} shapes, expected the block, {k * k} pores, {k * k} windows")
    for i in range(1, k + 1):
        for j in range(k):
            yc = (j + 0.5) * a
            for dx in (-0.9 * half, 0.0, 0.9 * half if i < k else 0.0):
                if inside(lattice, i * a + dx, yc):
                    sys.exit(f"FAIL: {n} per edge: the wall at x = {i * a} has no window in row {j}")
                if not inside(lattice, i * a + dx, yc + 0.5 * window + 2 * hm):
                    sys.exit(f"FAIL: {n} per edge: the wall at x = {i * a} is cut beyond its window in row {j}")
    if abs(filler["hi"][0] - k * a) > 1e-12 or abs(plate["velocity"][1] + rate * k * a) > 1e-9:
        sys.exit(f"FAIL: {n} per edge: the liquid's extent or the plate's speed is not the quarter's")
print("open-cell scenes with 2 and 4 cells per edge: a window in every wall across x, one per row")

h = 1.5e-4
first, rise = {}, {}
for n in (2, 4):
    s = L.size_scene(config, a, n)
    s["mesh"]["spacing"] = [h, h]
    s["mesh"]["upper"] = [h * math.ceil(u / h - 1e-9) for u in s["mesh"]["upper"]]
    s["time"]["end"] = 4.2e-4
    path = s["scene"] + ".yaml"
    yaml.dump(s, open(path, "w"), Dumper=L.SceneDumper, sort_keys=False)
    out = subprocess.run([os.path.join(build, "mpm_solver", "mpm_solver"), path], capture_output=True, text=True)
    if out.returncode != 0:
        print(out.stdout[-3000:] + out.stderr[-3000:])
        sys.exit(f"FAIL: mpm_solver {path} exit {out.returncode}")
    side = n // 2 * a
    travel, force, _ = L.curve(s["output"]["directory"], s["scene"])
    strain, stress = travel / side, force / side
    first[n] = L.band_mean(strain, stress, 0.04, 0.12)
    rise[n] = L.band_mean(strain, stress, 0.38, 0.42) / L.band_mean(strain, stress, 0.08, 0.12)
t = a * (1 - math.sqrt(1 - rho))
walls = t / a * L.SIGMA_Y * (1 + (1000.0 / L.RATE_C) ** (1 / L.RATE_P))
print(f"first yield (4-12 %): 2 per edge {first[2] / 1e6:.3f} MPa, 4 per edge {first[4] / 1e6:.3f} MPa, "
      f"walls' (t/a) sigma_y' {walls / 1e6:.3f} MPa; plateau rise 40 % / 10 %: {rise[2]:.3f}, {rise[4]:.3f}")
for n in (2, 4):
    if not abs(first[n] / walls - 1) <= 0.25:
        sys.exit(f"FAIL: {n} per edge: the first yield is not the walls' yield within 25 %")
if not rise[4] < 0.85 * rise[2]:
    sys.exit("FAIL: the plateau of 4 cells per edge does not rise less than that of 2")
PY
echo "PASS: lattice size"
