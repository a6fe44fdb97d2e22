#!/usr/bin/env python3
"""Compression of the open-cell lattices between rigid plates (issue 16, docs/slides.md).

Runs mpm_solver on configs/lattice/lattice_a{45,40,35}.yaml (unless --skip-run: then reads the
outputs already there), and from the particle outputs derives per scene:
  - the plate force per unit depth, -d/dt of the plate's momentum between outputs (the exact time
    average of the contact force over each output interval), and stress = force / a (the quarter
    model's width), strain = plate travel / a;
  - plateau stress: mean stress between 20 % and 40 % strain (ISO 13314); the walls' first
    yield: mean stress between 4 % and 12 % strain (what tests/verification/mpm/test_mpm_lattice.cpp
    asserts on a coarser mesh);
  - densification strain: where the energy efficiency  eta(e) = int_0^e s de / s(e)  is largest;
  - absorbed energy per unit volume up to the densification strain;
  - the Gibson-Ashby open-cell estimate 0.3 (rho*/rho_s)^1.5 sigma_y beside it.
Writes <out>/lattice_stress_strain.csv (curves), <out>/lattice_summary.csv and, with gnuplot,
<out>/lattice_stress_strain.png.

    scripts/python benchmarks/lattice/lattice_compression.py --build build --out output/lattice
"""
import argparse
import glob
import math
import os
import re
import subprocess
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
SCENES = [  # (config, a [m], rho*/rho_s of the slides' 3D cell)
    ("configs/lattice/lattice_a45.yaml", 4.5e-3, 0.37),
    ("configs/lattice/lattice_a40.yaml", 4.0e-3, 0.27),
    ("configs/lattice/lattice_a35.yaml", 3.5e-3, 0.16),
]
SIGMA_Y = 50e6            # the polymer's static yield stress (the configs)
RATE_C, RATE_P = 1.0e5, 2.0
PLATE, POLYMER = 1, 0     # material indices (order of the configs' materials)


def scene_outputs(config):
    text = open(os.path.join(ROOT, config)).read()
    directory = re.search(r"^\s*directory:\s*(\S+)", text, re.M).group(1)
    name = re.search(r"^scene:\s*(\S+)", text, re.M).group(1)
    return directory, name


def run_scene(build, config, cwd):
    exe = os.path.join(build, "mpm_solver", "mpm_solver")
    out = subprocess.run([exe, os.path.join(ROOT, config)], cwd=cwd, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"{config}: mpm_solver failed ({out.returncode}):\n{out.stdout[-2000:]}{out.stderr[-2000:]}")
    return out.stdout


def curve(directory, name):
    files = sorted(glob.glob(os.path.join(directory, f"{name}_[0-9][0-9][0-9][0-9][0-9][0-9].h5")))
    if len(files) < 3:
        sys.exit(f"{directory}: fewer than 3 output steps of {name}")
    t, p, y, vol0 = [], [], [], None
    for f in files:
        with h5py.File(f, "r") as h:
            mat = h["particles/material"][:]
            m = h["particles/mass"][:]
            v = h["particles/velocity"][:, 1]
            pos = h["particles/position"][:, 1]
            plate = mat == PLATE
            t.append(float(h.attrs["time"]))
            p.append(float(np.sum(m[plate] * v[plate])))
            y.append(float(np.mean(pos[plate])))
            if vol0 is None:
                vol0 = float(np.sum(h["particles/volume"][:][mat == POLYMER]))
    t, p, y = map(np.array, (t, p, y))
    force = np.diff(p) / np.diff(t)                    # on the plate, upwards: the lattice's push
    travel = 0.5 * ((y[0] - y[1:]) + (y[0] - y[:-1]))  # at the interval's middle
    return travel, force, vol0


def band_mean(strain, stress, lo, hi):
    sel = (strain >= lo) & (strain <= hi)
    return float(np.mean(stress[sel])) if np.any(sel) else float("nan")


def summarize(strain, stress):
    plateau = band_mean(strain, stress, 0.2, 0.4)
    e = np.concatenate(([0.0], strain))
    s = np.concatenate(([0.0], stress))
    work = np.concatenate(([0.0], np.cumsum(0.5 * (s[1:] + s[:-1]) * np.diff(e))))
    eta = np.where(s > 0, work / np.maximum(s, 1e-30), 0.0)
    valid = e >= 0.2
    k = int(np.argmax(np.where(valid, eta, -1)))
    return plateau, float(e[k]), float(work[k])


def parse_log(text):
    m = re.search(r"done: (\d+) steps, .*wall ([0-9.]+) s.*?([0-9.e+]+) particle-steps/s", text)
    n = re.search(r"particles: (\d+)", text)
    return (int(m.group(1)), float(m.group(2)), float(m.group(3)), int(n.group(1))) if m and n else (0, 0, 0, 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default="output/lattice")
    ap.add_argument("--skip-run", action="store_true", help="read the existing outputs")
    args = ap.parse_args()
    cwd = os.getcwd()
    os.makedirs(args.out, exist_ok=True)
    rows, summary = [], []
    for config, a, rho in SCENES:
        directory, name = scene_outputs(config)
        log = run_scene(os.path.abspath(args.build), config, cwd) if not args.skip_run else \
            open(os.path.join(directory, "log.mpm_solver")).read()
        steps, wall, rate, particles = parse_log(log)
        travel, force, vol0 = curve(directory, name)
        strain, stress = travel / a, force / a
        plateau, e_d, w_d = summarize(strain, stress)
        rho_p = vol0 / (a * a)
        rate_factor = 1 + (1000.0 / RATE_C) ** (1 / RATE_P)
        ga = 0.3 * rho ** 1.5 * SIGMA_Y
        t_wall = a * (1 - math.sqrt(1 - rho))
        rows += [(name, a, s_, st) for s_, st in zip(strain, stress)]
        summary.append((name, a * 1e3, rho, rho_p, plateau / 1e6, e_d, w_d / 1e6, ga / 1e6, plateau / ga,
                        t_wall / a * SIGMA_Y * rate_factor / 1e6, band_mean(strain, stress, 0.04, 0.12) / 1e6,
                        particles, steps, wall, rate))
    with open(os.path.join(args.out, "lattice_stress_strain.csv"), "w") as f:
        f.write("scene,a_mm,strain,stress_MPa\n")
        for name, a, s_, st in rows:
            f.write(f"{name},{a * 1e3:.1f},{s_:.6f},{st / 1e6:.6f}\n")
    with open(os.path.join(args.out, "lattice_summary.csv"), "w") as f:
        f.write("scene,a_mm,rho_rel_slides,rho_rel_particles,plateau_MPa,densification_strain,"
                "absorbed_MJ_per_m3,gibson_ashby_MPa,plateau_over_gibson_ashby,wall_yield_MPa,first_yield_MPa,"
                "particles,steps,wall_s,particle_steps_per_s\n")
        for r in summary:
            f.write(",".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in r) + "\n")
    for r in summary:
        print(f"{r[0]}: a {r[1]:.1f} mm  rho* {r[2]:.2f} (particles {r[3]:.3f})  plateau {r[4]:.3f} MPa  "
              f"densification {r[5]:.3f}  absorbed {r[6]:.3f} MJ/m^3  Gibson-Ashby {r[7]:.3f} MPa "
              f"(ratio {r[8]:.2f})  first yield (4-12 %) {r[10]:.3f} MPa against the walls' (t/a) sigma_y' "
              f"{r[9]:.3f} MPa  {r[11]} particles, {r[12]} steps, wall {r[13]:.1f} s, {r[14]:.3g} particle-steps/s")
    png = os.path.join(args.out, "lattice_stress_strain.png")
    csv = os.path.join(args.out, "lattice_stress_strain.csv")
    plots = ", ".join(f"'< grep ^{r[0]}, {csv}' using 3:4 with lines lw 2 title 'a = {r[1]:.1f} mm, rho*/rho_s {r[2]:.2f}'"
                      for r in summary)
    gp = (f"set terminal pngcairo size 900,600; set output '{png}'; set datafile separator ',';"
          "set xlabel 'nominal strain'; set ylabel 'nominal stress [MPa] (plate force / a)'; set grid;"
          f"set key top left; plot {plots}")
    try:
        subprocess.run(["gnuplot", "-e", gp], check=True)
        print(f"wrote {png}")
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"gnuplot: {e} (the CSV files are written)")


if __name__ == "__main__":
    main()
