#!/usr/bin/env python3
"""The slides' three foam models under the underwater shock (issue 16, docs/slides.md).

configs/underwater_foam_2d.yaml stops past 51 us (issue 12's water-air extremes at the free
surface) while its shock is ~12 cm below the charge, before it reaches the foam 21 cm down. So the
scene is cut as the test slides_underwater_shock cuts it, and the foam brought closer: the mesh
from y = FOAM_BOTTOM up (the container's bottom, a rigid mirror plane, moves up with it), the same
3 cm foam layer on it, its top 6 cm below the charge (the shock, ~2700 m/s there, reaches it at
about 20 us, leaving ~25 us of crush before the end). The three foam models of the slides:

  water : Lagrangian foam filled with water, undrained: in the 20-40 us of loading the water cannot
          leave the pores (it would have to flow centimetres through 0.1-1 mm pores), so foam and
          water deform as one solid: the pores' water (90 %) adds 900 kg/m^3 to the foam's 270
          and its bulk modulus 2.2 GPa, the skeleton its deviatoric strength (J2, yield = the foam's
          1.5 MPa plateau, nu 0.49: plastic flow keeps the volume, so it cannot crush by collapsing
          pores, only by compressing the water);
  air   : Lagrangian foam filled with air: the homogenized crushable foam as configs/underwater_foam_2d.yaml
          (the air in its pores, 1.2 kg/m^3 at 1e5 Pa, is left out: it adds 0.4 % to the mass and a
          pressure of ~2.5 MPa only at 90 % volumetric crush);
  none  : a foam with no strength of its own (the slides' Eulerian foam): the homogenized foam
          with its plateau and hardening stresses cut 1000 times (elastic moduli kept).
  (Giving the foam's particles only the skeleton's 10 % of a cell's volume and water the rest was
  tried: the initial fluid fill uses the particles' volume, not the solid EOS's reference density,
  so the cells start 10-90 % empty and the pressure equilibrium has no root at t = 0.)

Per model: the foam's thickness on the axis against time (a probe on the top particle at x = 0,
every step), the stress the foam passes to the bottom (mean -sigma_yy of the bottom particle row
within FOOT of the axis, per output), and the water pressure at fixed points (PROBES, from the
cell pressure per output: output.probes follow solid particles only). Writes
underwater_foam_models.csv, underwater_foam_summary.csv and, with gnuplot,
underwater_foam_models.png into --out.

With --full --tube the scene is configs/underwater_tube_2d.yaml at the shipped depth: the same scene
with the slides' PVC tube around the charge (and `mpm.stress_work: material` for its fragments),
the tube kept (--full alone strips it); the scenes are named underwater_foam_full_tube_<model> and
the CSV and PNG files get a _tube suffix (underwater_foam_summary_tube.csv, ...), so the runs with
and without the tube can share --out.

    scripts/python benchmarks/underwater/foam_models.py --build build --out output/underwater_foam
    scripts/python benchmarks/underwater/foam_models.py --build build --full --tube --end 1.5e-4 --out output/underwater_tube
"""
import argparse
import copy
import csv
import glob
import os
import subprocess
import sys

import h5py
import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
SCENE = os.path.join(ROOT, "configs", "underwater_foam_2d.yaml")
SCENE_3D = os.path.join(ROOT, "configs", "underwater_foam_3d.yaml")
SCENE_TUBE = os.path.join(ROOT, "configs", "underwater_tube_2d.yaml")
CHARGE_BOTTOM = 0.238           # [m], the scene's charge box
FOAM_THICKNESS = 0.03
FOAM_BOTTOM = 0.148             # the cut's bottom: foam top 6 cm below the charge
FOOT = 0.02                     # [m] the bottom stress is averaged over x < FOOT
def probes(bottom):
    """The water pressure points: 4 cm below the charge on the axis, 6 mm above the foam on the axis,
    4 cm below the charge 5 cm to the side."""
    return [("axis_4cm", 0.002, CHARGE_BOTTOM - 0.04), ("axis_above_foam", 0.002, bottom + FOAM_THICKNESS + 0.006),
            ("side_4cm", 0.05, CHARGE_BOTTOM - 0.04)]


PROBES = probes(FOAM_BOTTOM)
MODELS = ["water", "air", "none"]
P_AMBIENT = 1.0e5


def scene(model, end, full=False, dim=2, tube=False):
    if tube and (not full or dim == 3):
        raise ValueError("tube: only with full in 2D (configs/underwater_tube_2d.yaml at the shipped depth)")
    if dim == 3:   # the 3D quarter model as shipped: the foam on the bottom, the axis at x = z = 0
        s = yaml.safe_load(open(SCENE_3D))
        s["scene"] = f"underwater_foam_3d_{model}"
        s["description"] = f"Underwater shock on the foam 21 cm below the charge, 3D quarter model, foam model '{model}'"
        s["time"]["end"] = end
        foam_material(s, model)
        s["output"]["directory"] = s["scene"]
        s["output"]["probes"] = [{"name": "foam_top", "point": [0.0, FOAM_THICKNESS, 0.0]}]
        return s
    s = yaml.safe_load(open(SCENE_TUBE if tube else SCENE))
    if full:   # the shipped scene's depth: the foam on the container's bottom, 21 cm below the charge
        s["scene"] = f"underwater_foam_full{'_tube' if tube else ''}_{model}"
        s["description"] = (f"Underwater shock on the foam 21 cm below the charge{', with the PVC tube' if tube else ''}, "
                            f"foam model '{model}'")
        s["time"]["end"] = end
        foam_material(s, model)
        if not tube:
            s["geometry"] = [g for g in s["geometry"] if g["name"] != "tube"]
        s["output"]["directory"] = s["scene"]
        s["output"]["probes"] = [{"name": "foam_top", "point": [0.0, FOAM_THICKNESS]}]
        return s
    s["scene"] = f"underwater_foam_{model}"
    s["description"] = f"Underwater shock on a foam 6 cm below the charge, foam model '{model}'"
    s["mesh"]["lower"] = [0.0, FOAM_BOTTOM]
    s["time"]["end"] = end
    top = FOAM_BOTTOM + FOAM_THICKNESS
    foam = next(g for g in s["geometry"] if g["name"] == "foam")
    foam["shape"] = {"type": "box", "lo": [0.0, FOAM_BOTTOM], "hi": [s["mesh"]["upper"][0], top]}
    water = next(g for g in s["geometry"] if g["name"] == "water")
    water["shape"]["lo"][1] = top
    foam_material(s, model)
    s["geometry"] = [g for g in s["geometry"] if g["name"] != "tube"]
    s["output"]["directory"] = s["scene"]
    s["output"]["probes"] = [{"name": "foam_top", "point": [0.0, top]}]
    return s


FOAM_EOS = None   # --foam-eos: the crushable foams' solid EOS for ICE (None: the scene's, solid_bulk)


def foam_material(s, model):
    mat = next(m for m in s["materials"] if m["name"] == "foam")
    if FOAM_EOS and model != "water":
        mat["eos"] = {"type": FOAM_EOS}
    if model == "water":
        mat["density"] = 270.0 + 0.9 * 1000.0
        k_water, nu = 2.2e9, 0.49
        mat["model"] = {"type": "j2_plasticity", "youngs_modulus": 3 * k_water * (1 - 2 * nu), "poissons_ratio": nu,
                        "yield_stress": float(mat["model"]["plateau_stress"])}
    if model == "none":
        for k in ("plateau_stress", "hardening_gamma", "hardening_alpha2"):
            mat["model"][k] = float(mat["model"][k]) * 1e-3   # (PyYAML reads 1.5e6 as a string)


def histories(directory, name, dy, bottom):
    """Per output: time, the water pressure at PROBES, the bottom stress. In 3D the probes lie in the
    z = 0 symmetry plane (the first layer of cells, which holds the axis) and the bottom stress is
    averaged within FOOT of the axis in x and z (a quarter disc)."""
    rows = []
    for f in sorted(glob.glob(os.path.join(directory, f"{name}_[0-9][0-9][0-9][0-9][0-9][0-9].h5"))):
        with h5py.File(f, "r") as h:
            t = float(h.attrs["time"])
            o, d = h.attrs["origin"], h.attrs["spacing"]
            cells = h["grid/cell/pressure"][:]              # (z, y, x); 2D: z has one layer
            p = cells[0]
            probe = [float(p[int((y - o[1]) / d[1]), int((x - o[0]) / d[0])]) for _, x, y in probes(bottom)]
            pos = h["particles/position"][:]
            st = h["particles/stress"][:]
            syy = st[:, 1]                                   # (xx, yy, zz, xy, yz, xz)
            three = cells.shape[0] > 1
            radius = np.hypot(pos[:, 0], pos[:, 2]) if three else pos[:, 0]
            foot = (pos[:, 1] < bottom + 0.5 * dy) & (radius < FOOT)
            # the normal stress on the bottom: the cells' pressure (above the ambient) on the mixture
            # plus the foam's own stress, over the bottom row within FOOT of the axis
            nfoot = max(1, int(round(FOOT / d[0])))
            if three:
                xc = (np.arange(nfoot) + 0.5) * d[0]
                near = np.hypot(xc[:, None], xc[None, :]) < FOOT   # (z, x) cells of the bottom row
                p_bottom = float(np.mean(cells[:nfoot, 0, :nfoot][near])) - P_AMBIENT
            else:
                p_bottom = float(np.mean(p[0, :nfoot])) - P_AMBIENT
            rows.append([t] + probe + [p_bottom - float(np.mean(syy[foot])) if np.any(foot) else float("nan")])
    return np.array(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default="output/underwater_foam")
    ap.add_argument("--end", type=float, default=3.8e-5,
                    help="[s]; the no-strength foam's run stops at 39 us (water above its crushed top)")
    ap.add_argument("--models", default=",".join(MODELS))
    ap.add_argument("--skip-run", action="store_true")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time")
    ap.add_argument("--full", action="store_true",
                    help="the shipped scene's depth (foam on the bottom, 21 cm below the charge; needs the water's "
                         "cavitation model to run past 49.5 us); use --end 1.5e-4")
    ap.add_argument("--dim", type=int, choices=[2, 3], default=2,
                    help="3: the 3D quarter model (configs/underwater_foam_3d.yaml) at its depth; use --end 1.5e-4")
    ap.add_argument("--tube", action="store_true",
                    help="with --full: the scene with the slides' PVC tube (configs/underwater_tube_2d.yaml), the tube "
                         "kept; scenes and output files get a _tube suffix")
    ap.add_argument("--foam-eos", choices=["solid_bulk", "crush_curve"], default=None,
                    help="the air-filled and strengthless foams' solid EOS for ICE (default: the scene's, solid_bulk); "
                         "crush_curve: the foam's own crush curve (docs/slides.md \"ICE's view of the foam\")")
    args = ap.parse_args()
    global FOAM_EOS
    FOAM_EOS = args.foam_eos
    if args.tube and (not args.full or args.dim == 3):
        ap.error("--tube needs --full (the tube's scene, configs/underwater_tube_2d.yaml, is 2D at the shipped depth)")
    tube = "_tube" if args.tube else ""
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    exe = os.path.join(os.path.abspath(args.build), "coupler", "mpmice")
    models = args.models.split(",")
    procs = []
    for m in models:
        s = scene(m, args.end, args.full, args.dim, args.tube)
        path = os.path.join(out, s["scene"] + ".yaml")
        yaml.safe_dump(s, open(path, "w"), sort_keys=False)
        if not args.skip_run:
            procs.append((m, subprocess.Popen([exe, path], cwd=out, stdout=open(path[:-5] + ".log", "w"),
                                              stderr=subprocess.STDOUT)))
        if len(procs) == args.jobs or (m == models[-1] and procs):
            for name, pr in procs:
                if pr.wait() != 0:
                    print(f"{name}: mpmice exit {pr.returncode} (see the .log beside its scene in {out}); its outputs up to the stop are used")
            procs = []
    summary, curves = [], []
    for m in models:
        name = f"underwater_foam_3d_{m}" if args.dim == 3 else f"underwater_foam_full{tube}_{m}" if args.full \
            else f"underwater_foam_{m}"
        bottom = 0.0 if args.full or args.dim == 3 else FOAM_BOTTOM
        d = os.path.join(out, name)
        spacing = yaml.safe_load(open(os.path.join(out, name + ".yaml")))["mesh"]["spacing"]
        dy = float(spacing[1] if isinstance(spacing, list) else spacing)
        pr = list(csv.DictReader(open(os.path.join(d, name + "_probes.csv"))))
        tp = np.array([float(r["time"]) for r in pr])
        thick = FOAM_THICKNESS + np.array([float(r["foam_top_uy"]) for r in pr])
        hist = histories(d, name, dy, bottom)
        for t, th in zip(tp[::10], thick[::10]):
            curves.append((m, "thickness", t, th))
        for row in hist:
            for k, (pn, _, _) in enumerate(PROBES):
                curves.append((m, "p_" + pn, row[0], row[1 + k]))
            curves.append((m, "bottom_stress", row[0], row[-1]))
        arrive = next((t for t, th in zip(tp, thick) if th < FOAM_THICKNESS - 1e-4), float("nan"))
        summary.append({"model": m, "t_end_us": tp[-1] * 1e6, "steps": int(pr[-1]["step"]),
                        "shock_at_foam_us": arrive * 1e6, "crush_mm": (FOAM_THICKNESS - thick[-1]) * 1e3,
                        "crush_strain": (FOAM_THICKNESS - thick[-1]) / FOAM_THICKNESS,
                        "peak_bottom_stress_MPa": float(np.nanmax(hist[:, -1])) / 1e6,
                        "peak_p_above_foam_MPa": float(np.max(hist[:, 2])) / 1e6})
    with open(os.path.join(out, f"underwater_foam_models{tube}.csv"), "w") as f:
        f.write("model,quantity,time_s,value\n")
        for c in curves:
            f.write(f"{c[0]},{c[1]},{c[2]:.9g},{c[3]:.9g}\n")
    with open(os.path.join(out, f"underwater_foam_summary{tube}.csv"), "w") as f:
        keys = list(summary[0].keys())
        f.write(",".join(keys) + "\n")
        for r in summary:
            f.write(",".join(f"{r[k]:.6g}" if isinstance(r[k], float) else str(r[k]) for k in keys) + "\n")
    for r in summary:
        print(", ".join(f"{k} {v:.4g}" if isinstance(v, float) else f"{k} {v}" for k, v in r.items()))
    png = os.path.join(out, f"underwater_foam_models{tube}.png")
    c = os.path.join(out, f"underwater_foam_models{tube}.csv")
    sel = lambda m, q: f"'< grep ^{m},{q}, {c}'"
    gp = (f"set terminal pngcairo size 1000,800; set output '{png}'; set datafile separator ','; set multiplot layout 2,1;"
          "set grid; set xlabel 'time [us]'; set ylabel 'foam thickness on the axis [mm]'; set key bottom left;"
          "plot " + ", ".join(f"{sel(m, 'thickness')} using ($3*1e6):($4*1e3) with lines lw 2 title '{m}'" for m in models) + ";"
          "set ylabel 'stress to the bottom [MPa]'; set key top left;"
          "plot " + ", ".join(f"{sel(m, 'bottom_stress')} using ($3*1e6):($4/1e6) with linespoints lw 2 title '{m}'"
                              for m in models) + "; unset multiplot")
    try:
        subprocess.run(["gnuplot", "-e", gp], check=True)
        print(f"wrote {png}")
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"gnuplot: {e} (the CSV files are written)")


if __name__ == "__main__":
    main()
