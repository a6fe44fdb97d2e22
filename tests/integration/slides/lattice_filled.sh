#!/usr/bin/env bash
# The filled open-cell lattice, small (issue 16; benchmarks/lattice/lattice_compression.py --study
# filled, docs/slides.md): configs/lattice/lattice_a45.yaml as the study's open-cell variant on a
# 0.25 mm mesh at 2000 1/s, 5 % strain.
#   1. empty (mpm_solver) against filled with the 100 Pa s silicone (mpmice): the mean stress
#      across the specimen's mid-plane over 2-5 % strain of the filled lattice is above the
#      empty one's (the liquid is pushed out
#      through the side windows: pressure in the pores, viscous drag);
#   2. with the liquid in the pores only and the gas beside the specimen (--filler pores), the same
#      stress with 3 and 6 mm of mesh beside the specimen (within 5 %; measured 12.95 / 13.27 MPa with the
#      filler's gamma 1.62, 13.09 / 13.40 with 4.4, where the liquid beside the specimen gave 15.57 / 22.76
#      MPa), above the empty one's (7.83 MPa; filled with the liquid beside it 15.32);
#      there the pores' liquid sits above the gas beside the specimen (5.65 MPa over 2-5 %) and
#      pushes the outer wall's segment below the window out further than the empty lattice's
#      (0.142 against 0.017 mm at 5 %; docs/slides.md "Why the walls go");
#   3. the filled scene in a closed box (the open faces made slip walls), 1 % strain: the fluids'
#      mass (filler + the buffer above the plate) is kept to round-off (1e-12 relative), so no
#      liquid is made or lost at the walls, the plate or the lattice.
#   lattice_filled.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$src/scripts/python" - "$src" "$build" <<'PY'
import csv, os, subprocess, sys
import yaml
src, build = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(src, "benchmarks", "lattice"))
import lattice_compression as L

config, a, _ = L.SCENES[0]
rate, h = 2000.0, 2.5e-4


def run(scene, exe):
    path = scene["scene"] + ".yaml"
    yaml.dump(scene, open(path, "w"), Dumper=L.SceneDumper, sort_keys=False)
    out = subprocess.run([exe, path], capture_output=True, text=True)
    if out.returncode != 0:
        print(out.stdout[-3000:] + out.stderr[-3000:])
        sys.exit(f"FAIL: {exe} {path} exit {out.returncode}")
    return scene["output"]["directory"]


outer = {}


def mean_stress(scene, exe):
    """Runs scene to 5 % strain; the mean stress across the mid-plane over 2-5 % [Pa]. Keeps the
    pores' mean excess pressure over 2-5 % and the outer wall's outward displacement at the end
    (L.pores_and_outer_wall) in outer[scene name]."""
    scene["time"]["end"] = 0.05 / rate
    d = run(scene, exe)
    travel, _, _ = L.curve(d, scene["scene"])
    mid = L.mid_plane_stress(d, scene["scene"], a, h)
    e, excess, out = L.pores_and_outer_wall(d, scene["scene"], scene, a)
    outer[scene["scene"]] = (L.band_mean(e, excess, 0.02, 0.05), out[-1])
    return L.band_mean(travel / a, 0.5 * (mid[1:] + mid[:-1]), 0.02, 0.05)


mpmice = os.path.join(build, "coupler", "mpmice")
stress = {}
for mu in (None, 100.0):
    exe = os.path.join(build, "mpm_solver", "mpm_solver") if mu is None else mpmice
    stress[mu] = mean_stress(L.open_scene(config, a, h, rate, mu), exe)
print(f"mean stress across the mid-plane 2-5 %: empty {stress[None] / 1e6:.3f} MPa, filled (100 Pa s) {stress[100.0] / 1e6:.3f} MPa")
if not stress[100.0] > stress[None]:
    sys.exit("FAIL: the filled lattice is not stiffer than the empty one")

# The liquid in the pores only, the gas beside the specimen (the study's default, --filler pores): the
# filled stress does not depend on the mesh's width beside the specimen (with the liquid beside it,
# the film the plate squeezes did: docs/slides.md "The liquid beside the specimen").
pores = {}
for room in (3.0e-3, 6.0e-3):
    s = L.open_scene(config, a, h, rate, 100.0, room=room, filler="pores")
    s["scene"] += f"_pores_room{room * 1e3:g}"
    s["output"]["directory"] = s["scene"]
    pores[room] = mean_stress(s, mpmice)
p3, p6 = pores[3.0e-3], pores[6.0e-3]
print(f"pores only, mean stress across the mid-plane 2-5 %: room 3 mm {p3 / 1e6:.4f} MPa, 6 mm {p6 / 1e6:.4f} MPa")
if not p3 > stress[None]:
    sys.exit("FAIL: the lattice with its pores filled is not stiffer than the empty one")
if not abs(p6 - p3) <= 0.05 * p3:
    sys.exit("FAIL: with the liquid in the pores only, the stress depends on the room beside the specimen")

# The pores' liquid pressure pushes the outer wall open (docs/slides.md "Why the walls go"): the
# pores sit above the gas beside the specimen and the outer wall's segment below the window moves
# out further than the empty lattice's.
empty_name = L.open_scene(config, a, h, rate, None)["scene"]
pores_name = L.open_scene(config, a, h, rate, 100.0, room=3.0e-3, filler="pores")["scene"] + "_pores_room3"
(excess, out_filled), (_, out_empty) = outer[pores_name], outer[empty_name]
print(f"pores only, 2-5 %: pore excess {excess / 1e6:.3f} MPa (collapse of the outer wall's segment "
      f"{L.outer_wall_collapse(L.open_scene(config, a, h, rate, 100.0), a) / 1e6:.2f} MPa); that segment out at 5 %: "
      f"filled {out_filled * 1e3:.4f} mm, empty {out_empty * 1e3:.4f} mm")
if not excess > 0:
    sys.exit("FAIL: the filled pores are not above the gas beside the specimen")
if not out_filled > out_empty:
    sys.exit("FAIL: the filled lattice's outer wall is not pushed out further than the empty one's")

s = L.open_scene(config, a, h, rate, 100.0)
s["scene"] += "_closed"
s["output"]["directory"] = s["scene"]
s["time"]["end"] = 0.01 / rate
s["boundary"]["x+"] = "slip_wall"
s["boundary"]["y+"] = "slip_wall"
d = run(s, mpmice)
rows = list(csv.DictReader(open(os.path.join(d, s["scene"] + "_conservation.csv"))))
m0, m1 = float(rows[0]["fluid_mass"]), float(rows[-1]["fluid_mass"])
print(f"closed box: fluid mass {m0:.12e} -> {m1:.12e} kg (relative {(m1 - m0) / m0:.2e}) over {rows[-1]['step']} steps")
if not abs(m1 - m0) <= 1e-12 * m0:
    sys.exit("FAIL: the fluid mass changed in the closed box")
PY
echo "PASS: filled lattice"
