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
  - densification strain: where the energy efficiency  eta(e) = int_0^e s de / s(e)  is largest (past 20 %;
    the filled study: with s averaged over a strain window of 0.05, kFilledSmoothing, as the filled runs ring);
  - absorbed energy per unit volume up to the densification strain;
  - the Gibson-Ashby open-cell estimate 0.3 (rho*/rho_s)^1.5 sigma_y beside it.
Writes <out>/lattice_stress_strain.csv (curves), <out>/lattice_summary.csv and, with gnuplot,
<out>/lattice_stress_strain.png.

    scripts/python benchmarks/lattice/lattice_compression.py --build build --out output/lattice

--study filled: the open-cell variants, empty and filled with a viscous liquid (docs/slides.md,
"Filled lattices"). Each shipped scene gets a window in its outer half wall (the 3D cell's side
pore opening onto the specimen's free face, height pi d^2 / (4 a) so the open fraction of the face
is the 3D cell's), a coarser mesh and a faster plate (--mesh, --rate: cost), quadratic B-splines
(--shape) and 9 mm of room beside the specimen (--room); empty runs go through
mpm_solver, filled ones through mpmice with the silicone filler (FILLER below) in the pores and
the buffer gas beside the specimen (--filler pores; --filler surround: the liquid beside it too,
below the plate, whose squeeze film between plate and floor sets the filled stress by the room's
width), at each --viscosities value, for each --per-edge number of cells per edge (default 2, the
shipped scenes; n > 2: the size study's quarter of n/2 x n/2 cells with a window in every wall
across x, one per row; stress and strain over the quarter's width n/2 x a). Writes
lattice_filled_stress_strain.csv, lattice_filled_summary.csv and lattice_filled_stress_strain.png.

    scripts/python benchmarks/lattice/lattice_compression.py --study filled --build build --out output/lattice_filled

--study size: the specimen's size, n cells per edge (--per-edge, default 2,4,8; 2 is the shipped
scenes), still a quarter by the two mirror planes (n/2 x n/2 cells, the central walls halved on
the planes), the plate at the shipped 1000 1/s over the specimen's height n/2 x a, n/2 mm wider than it, n/2 x
1.5 mm of room beside the specimen (n = 2: the shipped scene); stress = plate force / (n/2 a), strain = travel / (n/2 a).
Writes lattice_size_stress_strain.csv, lattice_size_summary.csv and lattice_size_stress_strain.png.

    scripts/python benchmarks/lattice/lattice_compression.py --study size --build build --out output/lattice_size

--study 3d: the slides' cell itself (configs/lattice/lattice3d_a45.yaml: a cube of edge a with three
orthogonal pores of diameter d, an eighth of a 2 x 2 x 2 specimen by three mirror planes), for each
--cells value of a (4.5, 4.0, 3.5 mm: the a = 4.0 and 3.5 mm scenes are the a = 4.5 mm one with the
cube, the pores' centres, the mesh and the plate moved), at --mesh3d and the shipped 1000 1/s, to
--end-strain (cost). stress = plate force / a^2, strain = plate travel / a. Writes
lattice3d_stress_strain.csv and lattice3d_summary.csv (plateau and first yield beside the 2D curve
of --compare2d, default docs/lattice_summary.csv, and Gibson-Ashby).

    scripts/python benchmarks/lattice/lattice_compression.py --study 3d --build build --out output/lattice3d
"""
import argparse
import glob
import math
import os
import re
import subprocess
import sys
import time

import h5py
import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
SCENES = [  # (config, a [m], rho*/rho_s of the slides' 3D cell)
    ("configs/lattice/lattice_a45.yaml", 4.5e-3, 0.37),
    ("configs/lattice/lattice_a40.yaml", 4.0e-3, 0.27),
    ("configs/lattice/lattice_a35.yaml", 3.5e-3, 0.16),
]
SIGMA_Y = 50e6            # the polymer's static yield stress (the configs)
RATE_C, RATE_P = 1.0e5, 2.0
PORE_D = 3.0e-3           # the slides' pore diameter
# The filler: a silicone oil (polydimethylsiloxane), rho 970 kg/m^3 and c 1000 m/s (Dow Corning 200
# fluid data: 0.97 g/cm^3, sound speed about 990 m/s at 25 C, nearly independent of viscosity
# from 1e3 cSt up), cv 1500 J/(kg K); a stiffened gas with p_inf such that c = 1000 m/s at the ambient
# pressure P_AMBIENT and gamma 1.62: the stiffened gas's Grueneisen parameter is gamma - 1 (dp/de at
# fixed rho = (gamma - 1) rho), and the oil's is beta c^2 / c_p = 9.6e-4 1/K x (990 m/s)^2 / 1500 J/(kg K)
# = 0.62 (volume expansion beta of PDMS fluids 9.2-9.6e-4 1/K). Until 5 Dec 2026 gamma was water's 4.4
# (Grueneisen 3.4): the heat the liquid takes in the pores (the drag's, the Lagrangian correction's)
# raised its pressure 5.5 times as much as the oil's would, and a drained pore's liquid, heated, fell
# below 0 K as its cold energy p_inf v grew (docs/slides.md "The filler's Grueneisen parameter").
FILLER_RHO, FILLER_C, FILLER_GAMMA, FILLER_CV = 970.0, 1000.0, 1.62, 1500.0
# The liquid, the solids' stress-free state and the open faces sit at 50 MPa: a gauge offset (only
# pressure differences act on the specimen). At 1 atm and at 10 MPa the runs stop within 5 us: the
# plate starts at full speed, the rarefactions it launches put the liquid beside its corner in
# tension and the solids' EOS has no state there (the liquid has no cavitation model).
P_AMBIENT = 5.0e7
# With --filler pores the mesh beside the specimen below the plate holds the buffer gas at this
# density (c = sqrt(1.4 P_AMBIENT / rho) = 837 m/s): the liquid squeezed out of the windows meets a
# gas that leaves through the open side face, not a liquid film the plate squeezes over the room.
BESIDE_RHO = 100.0


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
            m = h["particles/mass"][:]
            rho = m / h["particles/volume"][:]
            # The plate: the material of the densest particle (its index depends on how many
            # fluids the scene lists first); without material indices, by its density.
            if "particles/material" in h:
                mat = h["particles/material"][:]
                plate = mat == mat[np.argmax(rho)]
            else:
                plate = rho > 1e6
            v = h["particles/velocity"][:, 1]
            pos = h["particles/position"][:, 1]
            t.append(float(h.attrs["time"]))
            p.append(float(np.sum(m[plate] * v[plate])))
            y.append(float(np.mean(pos[plate])))
            if vol0 is None:
                vol0 = float(np.sum(h["particles/volume"][:][~plate]))
    t, p, y = map(np.array, (t, p, y))
    force = np.diff(p) / np.diff(t)                    # on the plate, upwards: the lattice's push
    travel = 0.5 * ((y[0] - y[1:]) + (y[0] - y[:-1]))  # at the interval's middle
    return travel, force, vol0


def mid_plane_stress(directory, name, a, h):
    """The nominal stress across the specimen's mid-plane (the y = 0 mirror plane) per output:
    -sigma_yy of the lattice's particles in the layer next to it (centres below h/2, 2 per cell),
    each over its width V_p / (h/2), summed and divided by a (the quarter's width: n/2 x the cell
    edge for n cells per edge). The bottom half wall spans the whole
    cell there, so this is all the load the specimen carries, the pores' liquid pressure
    included, and none of what the liquid outside it or the buffer above the plate exert on the
    plate. On the empty lattices it matches the plate force within 8 % (4-12 %) and 3 % (20-40 %)."""
    out = []
    for f in sorted(glob.glob(os.path.join(directory, f"{name}_[0-9][0-9][0-9][0-9][0-9][0-9].h5"))):
        with h5py.File(f, "r") as hf:
            m, vol = hf["particles/mass"][:], hf["particles/volume"][:]
            y = hf["particles/position"][:, 1]
            syy = hf["particles/stress"][:, 1]                    # (xx, yy, zz, xy, yz, xz)
        layer = (m / vol < 1e6) & (y < 0.5 * h)                      # the lattice, not the plate
        out.append(float(np.sum(-syy[layer] * vol[layer] / (0.5 * h))) / a)
    return np.array(out)

def pores_and_outer_wall(directory, name, scene, side):
    """Per output of an open-cell scene (open_scene; the filled study): the nominal strain (plate
    travel / side), the pores' liquid pressure above the gas or liquid beside the specimen [Pa] (NaN
    when empty) and the outer wall's outward displacement below its first window [m].
    Pores: the cells inside the specimen's footprint short of its outer wall (x < side - t/2) below
    the plate that are at least 90 % liquid; beside: the cells more than 1 mm beyond the specimen's
    side, below the plate, without solid. The outer wall's segment: the polymer particles that start
    in the outer half wall (thickness t/2) between the bottom half wall and the first row's window,
    tracked by id; its median x displacement. Beside it, outer_wall_collapse(): the pressure at which
    that segment, a cantilever from the specimen's corner, collapses plastically."""
    wall, window_lo = outer_wall(scene, side)
    names = [m["name"] for m in scene["materials"]]
    polymer, plate = names.index("polymer"), names.index("plate")
    files = sorted(glob.glob(os.path.join(directory, f"{name}_[0-9][0-9][0-9][0-9][0-9][0-9].h5")))
    strain, excess, out = [], [], []
    x0 = None
    for f in files:
        with h5py.File(f, "r") as h:
            ids, pos, mat = h["particles/id"][:], h["particles/position"][:], h["particles/material"][:]
            plate_y = float(np.min(pos[mat == plate, 1]))
            if x0 is None:
                y00 = plate_y
                seg = (mat == polymer) & (pos[:, 0] > side - wall) & (pos[:, 1] > wall) & (pos[:, 1] < window_lo)
                x0 = dict(zip(ids[seg], pos[seg, 0]))
            strain.append((y00 - plate_y) / side)
            moved = [pos[i, 0] - x0[k] for i, k in enumerate(ids) if k in x0]
            out.append(float(np.median(moved)) if moved else float("nan"))
            e = float("nan")
            if "grid/cell/silicone_volume_fraction" in h:
                p = h["grid/cell/pressure"][0]
                liquid = h["grid/cell/silicone_volume_fraction"][0]
                solid = h["grid/cell/polymer_volume_fraction"][0] + h["grid/cell/plate_volume_fraction"][0]
                dx = scene["mesh"]["spacing"]
                x = (np.arange(p.shape[1]) + 0.5) * dx[0]
                y = (np.arange(p.shape[0]) + 0.5) * dx[1]
                X, Y = np.meshgrid(x, y)
                pores = (liquid > 0.9) & (X < side - wall) & (Y < plate_y)
                beside = (solid == 0) & (X > side + 1.0e-3) & (Y < plate_y)
                if pores.any() and beside.any():
                    e = float(np.mean(p[pores]) - np.mean(p[beside]))
            excess.append(e)
    return np.array(strain), np.array(excess), np.array(out)


def outer_wall_collapse(scene, side):
    """The pores' overpressure [Pa] at which the outer half wall's segment below the first window
    (thickness t/2, length L from the bottom half wall to the window) collapses as a cantilever
    clamped at the specimen's corner: 2 M_p / L^2 with M_p = sigma_y (t/2)^2 / 4 (static yield, per
    unit depth; the rate's Cowper-Symonds factor at 2000 1/s adds 14 %)."""
    wall, window_lo = outer_wall(scene, side)
    return 2.0 * SIGMA_Y * wall ** 2 / 4.0 / (window_lo - wall) ** 2


def outer_wall(scene, side):
    """The outer half wall's thickness t/2 and the bottom of its first window (open_scene's lattice:
    the specimen's box, the pores, then the windows; the outer wall's reach beyond x = side)."""
    shapes = next(g for g in scene["geometry"] if g["name"] == "lattice")["shape"]["shapes"]
    windows = [b for b in shapes[1:] if b["hi"][0] > side]
    return shapes[1]["lo"][0], min(b["lo"][1] for b in windows)


def at_strain(strain, values, e):
    """values at nominal strain e (linear between outputs; NaN beyond the run)."""
    ok = np.isfinite(values)
    if not ok.any() or e > strain[ok][-1]:
        return float("nan")
    return float(np.interp(e, strain[ok], values[ok]))


def band_mean(strain, stress, lo, hi):
    sel = (strain >= lo) & (strain <= hi)
    return float(np.mean(stress[sel])) if np.any(sel) else float("nan")


# The filled study's densification strain: the energy efficiency of the stress averaged over this
# strain window (summarize).
kFilledSmoothing = 0.05


def summarize(strain, stress, smooth=0.0):
    """Plateau (mean over 20-40 %), densification strain (largest energy efficiency past 20 %) and
    the energy to it. smooth > 0: the efficiency's stress is the mean over a strain window of that
    width centred on each point (the filled runs ring at +-5 MPa: a dip made the largest
    efficiency of a noisy curve, at 26 % strain for a = 3.5 mm, 1 Pa s); the work is the curve's own.
    With smooth > 0 a largest efficiency at 20 % or at the curve's end gives NaN (no densification
    strain in the range)."""
    plateau = band_mean(strain, stress, 0.2, 0.4)
    e = np.concatenate(([0.0], strain))
    s = np.concatenate(([0.0], stress))
    work = np.concatenate(([0.0], np.cumsum(0.5 * (s[1:] + s[:-1]) * np.diff(e))))
    if smooth > 0:
        s = np.array([s[np.abs(e - x) <= 0.5 * smooth].mean() for x in e])
    eta = np.where(s > 0, work / np.maximum(s, 1e-30), 0.0)
    valid = e >= 0.2
    k = int(np.argmax(np.where(valid, eta, -1)))
    if smooth > 0 and (k == int(np.argmax(valid)) or k == len(e) - 1):
        # The largest efficiency at 20 % (it only falls: no plateau ends in the range) or at the
        # run's end (densification not reached): not a densification strain.
        return plateau, float("nan"), float("nan")
    return plateau, float(e[k]), float(work[k])


def parse_log(text):
    """(steps, wall [s], particle-steps/s, particles) from a run's log; a run that stopped: its
    last progress line."""
    n = re.search(r"particles: (\d+)", text) or re.search(r", (\d+) particles\)", text)
    steps = re.findall(r"^(?:done: |step )(\d+)[ ,].*?wall ([0-9.]+) s", text, re.M)
    if not (n and steps):
        return 0, 0, 0, 0
    k, wall = int(steps[-1][0]), float(steps[-1][1])
    return k, wall, k * int(n.group(1)) / wall, int(n.group(1))


def gnuplot(script, png):
    """Runs a gnuplot script; without gnuplot the CSV files stand alone."""
    try:
        subprocess.run(["gnuplot", "-e", script], check=True)
        print(f"wrote {png}")
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"gnuplot: {e} (the CSV files are written)")


class SceneDumper(yaml.SafeDumper):
    """Writes shared lists in full (no YAML anchors)."""
    def ignore_aliases(self, data):
        return True


def open_scene(config, a, h, rate, viscosity=None, filled_cfl=None, shape=None, room=3.0e-3, filler="surround",
               beside_rho=BESIDE_RHO, n=2, solid_transport=None):
    """The shipped scene as the open-cell variant: a window in the outer half wall, mesh h, plate at
    rate x a, to 70 % strain, `room` [m] of mesh beside the specimen, MPM's shape function `shape`
    (None: the shipped scene's); filled with the silicone at `viscosity` [Pa s] unless None, in the
    pores and beside the specimen below the plate (filler "surround") or in the pores only, the
    buffer gas beside the specimen (filler "pores", at density beside_rho). n > 2 cells per edge:
    the specimen of size_scene (a quarter of n/2 x n/2 cells, the plate at rate x n/2 a) with a
    window in every wall across x (the interior walls' full thickness, the outer half wall), one per
    row of cells, so that each row's pores open onto the next and the last onto the free face."""
    if filler not in ("surround", "pores"):
        raise ValueError(f"open_scene: filler '{filler}' (expected 'surround' or 'pores')")
    if n < 2 or n % 2:
        raise ValueError(f"open_scene: {n} cells per edge (expected an even number of at least 2)")
    k = n // 2
    side = k * a                                              # the quarter's width and height
    s = yaml.safe_load(open(os.path.join(ROOT, config))) if n == 2 else size_scene(config, a, n)
    if shape is not None:
        s["mpm"]["shape_function"] = shape
    name = s["scene"] + ("_empty" if viscosity is None else f"_filled_mu{viscosity:g}")   # size_scene's has _n<n>
    s["scene"] = name
    s["description"] = f"Open-cell lattice a = {a * 1e3:.1f} mm" + ("" if n == 2 else f", {n} cells per edge") + ", " + \
        ("empty" if viscosity is None else f"filled with silicone of {viscosity:g} Pa s") + f", {rate:g} 1/s"
    s["mesh"]["spacing"] = [h, h]
    # room beside the specimen (it spreads sideways as it collapses: 1.5 mm was left at 61 % strain,
    # and the filled ones' strut on the mirror plane reached 3 mm out at 47-67 %); whole cells
    s["mesh"]["upper"] = [h * math.ceil(u / h - 1e-9) for u in (side + room, s["mesh"]["upper"][1])]
    s["time"]["end"] = 0.7 / rate
    s["output"]["interval"] = 0.005 / rate
    s["output"]["directory"] = name
    lattice = next(g for g in s["geometry"] if g["name"] == "lattice")
    plate = next(g for g in s["geometry"] if g["name"] == "plate")
    plate["velocity"] = [0.0, -rate * side]
    plate["shape"]["hi"][0] = s["mesh"]["upper"][0]               # the plate spans the mesh's width
    pore_lo = lattice["shape"]["shapes"][1]["lo"][0]          # t/2: the half wall's thickness
    window = math.pi * PORE_D ** 2 / (4 * a)                  # the 3D face's open fraction x a
    for i in range(1, k + 1):                                 # the walls at x = i a; the last the outer half wall
        x_hi = i * a + (0.5 * h if i == k else pore_lo + 0.5 * h)
        for j in range(k):
            lattice["shape"]["shapes"].append({"type": "box", "lo": [i * a - pore_lo - 0.5 * h, (j + 0.5) * a - 0.5 * window],
                                               "hi": [x_hi, (j + 0.5) * a + 0.5 * window]})
    if viscosity is None:
        return s
    s["materials"].insert(0, {"name": "silicone", "kind": "fluid", "specific_heat": FILLER_CV, "viscosity": viscosity,
                              "eos": {"type": "stiffened_gas", "gamma": FILLER_GAMMA,
                                      "p_inf": FILLER_RHO * FILLER_C ** 2 / FILLER_GAMMA - P_AMBIENT}})
    for m in s["materials"][1:]:
        m["eos"] = {"type": "solid_bulk", "threshold_pressure": P_AMBIENT}
    lo, hi = s["mesh"]["lower"], s["mesh"]["upper"]
    # The liquid stays below the plate; above it a compliant buffer
    # (an ideal gas of the liquid's density at P_AMBIENT, c = 269 m/s) moving with the plate from
    # the start: where the plate leaves a cell the cell's solid volume (from node masses) lags, and
    # with the stiff liquid there that mismatch became tension beyond -P_AMBIENT (run stopped at
    # 5 us); the buffer turns it into a pressure change of ~1 MPa instead.
    bottom = plate["shape"]["lo"][1]
    s["materials"].insert(1, {"name": "buffer", "kind": "fluid", "eos": {"type": "ideal_gas", "gamma": 1.4},
                              "specific_heat": P_AMBIENT / (0.4 * FILLER_RHO * 300.0)})
    edge = hi[0] if filler == "surround" else side   # the liquid's extent in x below the plate
    beside = [] if filler == "surround" else [
        {"name": "beside", "shape": {"type": "box", "lo": [side, lo[1]], "hi": [hi[0], bottom]}, "material": "buffer",
         "density": beside_rho, "pressure": P_AMBIENT}]
    s["geometry"][0:0] = [
        {"name": "filler", "shape": {"type": "box", "lo": lo, "hi": [edge, bottom]}, "material": "silicone",
         "density": FILLER_RHO, "pressure": P_AMBIENT}] + beside + [
        {"name": "buffer", "shape": {"type": "box", "lo": [lo[0], bottom], "hi": hi}, "material": "buffer",
         "velocity": list(plate["velocity"]), "density": FILLER_RHO, "pressure": P_AMBIENT}]
    s["boundary"]["x+"] = {"type": "outflow", "pressure": P_AMBIENT}   # the specimen's open side
    s["boundary"]["y+"] = {"type": "outflow", "pressure": P_AMBIENT}   # refills above the plate
    s["ice"] = {"advection": "first_order", "exchange": {"momentum": 1.0e15, "heat": 0}}
    s["coupling"] = {"schedule": "monolithic"}
    if solid_transport:  # coupling.solid_transport (None: the scene's default, ice; the study passes mpm)
        s["coupling"]["solid_transport"] = solid_transport
    # The coupled step needs a smaller CFL number than the empty lattice's: at the shipped 0.3 the
    # polymer particle at the window's upper corner, past which the liquid is squeezed out, rings
    # (|v| 20-40 m/s against the plate's 7, 200 MPa) until its stored stress work is negative and
    # the health check stops the run (a = 3.5 mm, 1 Pa s: 11 us; 0.2: 35 us; 0.1 completes).
    if filled_cfl is not None:
        s["time"]["cfl"] = filled_cfl
    return s


COLOURS = {4.5: "#1f77b4", 4.0: "#d62728", 3.5: "#2ca02c"}  # the plots' colour per cell edge a [mm]


def write_summary(path, summary):
    """One row per run: the dicts' keys as the header, floats to 6 digits."""
    keys = list(summary[0].keys())
    with open(path, "w") as f:
        f.write(",".join(keys) + "\n")
        for r in summary:
            f.write(",".join(f"{r[k]:.6g}" if isinstance(r[k], float) else str(r[k]) for k in keys) + "\n")


def plot_curves(stem, summary, dash, label, ylabel, title):
    """<stem>.png from <stem>.csv (columns 4 and 5: strain, stress): a line per summary row, coloured
    by the cell edge, dashed by dash(row), titled 'a = .. mm, ' + label(row)."""
    png, csv = stem + ".png", stem + ".csv"
    plots = ", ".join(
        f"'< grep ^{r['scene']}, {csv}' using 4:5 with lines lw 2 dt {dash(r)} "
        f"lc rgb '{COLOURS.get(round(r['a_mm'], 1), 'black')}' title 'a = {r['a_mm']:.1f} mm, {label(r)}'"
        for r in summary)
    gp = (f"set terminal pngcairo size 1000,650; set output '{png}'; set datafile separator ',';"
          f"set xlabel 'nominal strain'; set ylabel '{ylabel}'; set grid;"
          f"set title '{title}'; set key top left; plot {plots}")
    gnuplot(gp, png)


def run_all(jobs, commands):
    """Runs (argv, cwd, log) jobs at most `jobs` at a time, the next one as soon as any ends; a
    run that stops is reported (its curve is kept up to the stop) and the others go on."""
    pending, running = list(commands), []
    while pending or running:
        while pending and len(running) < jobs:
            argv, cwd, log = pending.pop(0)
            running.append((subprocess.Popen(argv, cwd=cwd, stdout=open(log, "w"), stderr=subprocess.STDOUT), log))
        done = [(p, log) for p, log in running if p.poll() is not None]
        if not done:
            time.sleep(0.5)
            continue
        for proc, log in done:
            running.remove((proc, log))
            if proc.returncode != 0:
                lines = [l for l in open(log).read().splitlines() if l and not l.startswith("step ")]
                print(f"{' '.join(proc.args)} stopped ({proc.returncode}): " + " / ".join(lines[1:3])[:600])


def filled_study(args):
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    build = os.path.abspath(args.build)
    viscosities = [float(v) for v in args.viscosities.split(",")]
    cases, commands = [], []
    for n in per_edge(args.per_edge or "2"):
        for config, a, rho in SCENES:
            for mu in [None] + viscosities:
                s = open_scene(config, a, args.mesh, args.rate, mu, args.filled_cfl, args.shape, args.room, args.filler,
                               args.beside_density, n, args.solid_transport)
                path = os.path.join(out, s["scene"] + ".yaml")
                yaml.dump(s, open(path, "w"), Dumper=SceneDumper, sort_keys=False)
                exe = os.path.join(build, "mpm_solver", "mpm_solver") if mu is None else \
                    os.path.join(build, "coupler", "mpmice")
                log = os.path.join(out, s["scene"] + ".log")
                cases.append((s["scene"], a, rho, mu, n, os.path.join(out, s["output"]["directory"]), log))
                if not args.only or s["scene"] in args.only.split(","):
                    commands.append(([exe, path], out, log))
    if not args.skip_run:
        run_all(args.jobs, commands)
    rows, summary = [], []
    for name, a, rho, mu, n, directory, log in cases:
        if not glob.glob(os.path.join(directory, "*.h5")):
            print(f"{name}: no outputs in {directory}, left out")
            continue
        side = n // 2 * a                                          # the quarter's width and height
        travel, force, vol0 = curve(directory, name)
        mid = mid_plane_stress(directory, name, side, args.mesh)
        strain, stress = travel / side, 0.5 * (mid[1:] + mid[:-1])    # over each output interval
        plate_plateau = band_mean(strain, force / side, 0.2, 0.4)
        plateau, e_d, w_d = summarize(strain, stress, smooth=kFilledSmoothing)
        if strain[-1] < 0.4:  # a run that stopped before the plateau's band ends has no plateau
            plateau = plate_plateau = float("nan")
        steps, wall, rate, particles = parse_log(open(log).read())
        scene = yaml.safe_load(open(os.path.join(out, name + ".yaml")))
        e_pw, excess, wall_out = pores_and_outer_wall(directory, name, scene, side)
        rows += [(name, a, mu, e, st, fp / side) for e, st, fp in zip(strain, stress, force)]
        summary.append({"scene": name, "a_mm": a * 1e3, "cells_per_edge": n, "rho_rel_particles": vol0 / (side * side),
                        "viscosity_Pa_s": 0.0 if mu is None else mu, "filled": int(mu is not None),
                        "first_yield_MPa": band_mean(strain, stress, 0.04, 0.12) / 1e6, "plateau_MPa": plateau / 1e6,
                        "densification_strain": e_d, "absorbed_MJ_per_m3": w_d / 1e6,
                        "absorbed_to_50pct_MJ_per_m3": float(np.trapz(np.concatenate(([0.0], stress[strain <= 0.5])),
                                                                       np.concatenate(([0.0], strain[strain <= 0.5])))) / 1e6,
                        "plate_force_plateau_MPa": plate_plateau / 1e6, "end_strain": float(strain[-1]),
                        "pore_excess_20_40_MPa": (band_mean(e_pw, excess, 0.2, 0.4) if e_pw[-1] >= 0.4 else float("nan")) / 1e6,
                        "outer_wall_collapse_MPa": outer_wall_collapse(scene, side) / 1e6,
                        "outer_wall_out_30_mm": at_strain(e_pw, wall_out, 0.3) * 1e3,
                        "outer_wall_out_50_mm": at_strain(e_pw, wall_out, 0.5) * 1e3,
                        "particles": particles, "steps": steps, "wall_s": wall})
    empty = {(r["a_mm"], r["cells_per_edge"]): r for r in summary if not r["filled"]}
    for r in summary:  # NaN where the empty run of the same cell is not in the output (--only)
        e = empty.get((r["a_mm"], r["cells_per_edge"]))
        r["plateau_over_empty"] = r["plateau_MPa"] / e["plateau_MPa"] if e else float("nan")
        r["absorbed_50_over_empty"] = (r["absorbed_to_50pct_MJ_per_m3"] / e["absorbed_to_50pct_MJ_per_m3"]
                                       if e else float("nan"))
    with open(os.path.join(out, "lattice_filled_stress_strain.csv"), "w") as f:
        f.write("scene,a_mm,viscosity_Pa_s,strain,stress_MPa,plate_stress_MPa\n")
        for name, a, mu, e, st, sp in rows:
            f.write(f"{name},{a * 1e3:.1f},{0 if mu is None else mu:g},{e:.6f},{st / 1e6:.6f},{sp / 1e6:.6f}\n")
    write_summary(os.path.join(out, "lattice_filled_summary.csv"), summary)
    for r in summary:
        print(f"{r['scene']}: rho* {r['rho_rel_particles']:.3f}  first yield {r['first_yield_MPa']:.3f} MPa  plateau "
              f"{r['plateau_MPa']:.3f} MPa (x{r['plateau_over_empty']:.3f} of empty)  densification "
              f"{r['densification_strain']:.3f}  absorbed {r['absorbed_MJ_per_m3']:.3f} MJ/m^3, to 50 % "
              f"{r['absorbed_to_50pct_MJ_per_m3']:.3f} (x{r['absorbed_50_over_empty']:.3f})  {r['particles']} particles, "
              f"{r['steps']} steps, wall {r['wall_s']:.1f} s")
        print(f"  pores' liquid above the side 20-40 %: {r['pore_excess_20_40_MPa']:.2f} MPa (the outer wall's segment "
              f"below the window collapses at {r['outer_wall_collapse_MPa']:.2f} MPa); that segment pushed out "
              f"{r['outer_wall_out_30_mm']:.3f} / {r['outer_wall_out_50_mm']:.3f} mm at 30 / 50 % strain")
    dashes = {0.0: 1, viscosities[0]: 2}
    plot_curves(os.path.join(out, "lattice_filled_stress_strain"), summary,
                lambda r: dashes.get(r["viscosity_Pa_s"], 3),
                lambda r: ("empty" if not r["filled"] else f"filled {r['viscosity_Pa_s']:g} Pa s") +
                ("" if r["cells_per_edge"] == 2 else f", {r['cells_per_edge']} per edge"),
                "nominal stress across the mid-plane [MPa]",
                f"open-cell lattices, {args.rate:g} 1/s, mesh {args.mesh * 1e3:g} mm, {args.shape}")


def size_scene(config, a, n):
    """The shipped scene with n cells per edge: its quarter holds n/2 x n/2 cells."""
    s = yaml.safe_load(open(os.path.join(ROOT, config)))
    k = n // 2
    lattice = next(g for g in s["geometry"] if g["name"] == "lattice")
    plate = next(g for g in s["geometry"] if g["name"] == "plate")
    half = lattice["shape"]["shapes"][1]["lo"][0]               # t/2: the half wall's thickness
    rate = -plate["velocity"][1] / a                             # the shipped nominal strain rate
    side, room = k * a, k * 1.5e-3
    s["scene"] = f"{s['scene']}_n{n}"
    s["description"] = f"Open-cell square lattice a = {a * 1e3:.1f} mm, {n} x {n} cells (a quarter by symmetry), {rate:g} 1/s"
    r = lambda x: round(x, 10)  # noqa: E731 (no float dust in the scene file)
    s["mesh"]["upper"] = [r(side + room), r(side + 1.0e-3)]
    lattice["shape"]["shapes"] = [{"type": "box", "lo": [0.0, 0.0], "hi": [r(side), r(side)]}] + [
        {"type": "box", "lo": [r(i * a + half), r(j * a + half)], "hi": [r((i + 1) * a - half), r((j + 1) * a - half)]}
        for j in range(k) for i in range(k)]
    plate["shape"] = {"type": "box", "lo": [0.0, r(side)], "hi": [r(side + k * 1.0e-3), r(side + 0.5e-3)]}
    plate["velocity"] = [0.0, -rate * side]
    s["output"]["directory"] = s["scene"]
    return s


def per_edge(text):
    """--per-edge's list of cells per edge, each an even number of at least 2."""
    out = []
    for v in text.split(","):
        try:
            n = int(v)
        except ValueError:
            sys.exit(f"--per-edge: '{v}' is not a number of cells (expected even numbers >= 2, comma-separated)")
        if n < 2 or n % 2:
            sys.exit(f"--per-edge: {n} is not an even number of cells of at least 2")
        out.append(n)
    return out


def size_study(args):
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    exe = os.path.join(os.path.abspath(args.build), "mpm_solver", "mpm_solver")
    cases, commands = [], []
    for config, a, rho in SCENES:
        for n in per_edge(args.per_edge or "2,4,8"):
            s = size_scene(config, a, n)
            path = os.path.join(out, s["scene"] + ".yaml")
            yaml.dump(s, open(path, "w"), Dumper=SceneDumper, sort_keys=False)
            log = os.path.join(out, s["scene"] + ".log")
            cases.append((s["scene"], a, rho, n, os.path.join(out, s["output"]["directory"]), log))
            commands.append(([exe, path], out, log))
    if not args.skip_run:
        run_all(args.jobs, commands)
    rows, summary = [], []
    for name, a, rho, n, directory, log in cases:
        if not glob.glob(os.path.join(directory, "*.h5")):
            print(f"{name}: no outputs in {directory}, left out")
            continue
        side = n // 2 * a
        travel, force, vol0 = curve(directory, name)
        strain, stress = travel / side, force / side
        plateau, e_d, w_d = summarize(strain, stress)
        steps, wall, _, particles = parse_log(open(log).read())
        rows += [(name, a, n, e, st) for e, st in zip(strain, stress)]
        summary.append({"scene": name, "a_mm": a * 1e3, "cells_per_edge": n, "rho_rel_particles": vol0 / side ** 2,
                        "first_yield_MPa": band_mean(strain, stress, 0.04, 0.12) / 1e6,
                        "plateau_MPa": plateau / 1e6,
                        "plateau_rise_40_over_10": band_mean(strain, stress, 0.38, 0.42) / band_mean(strain, stress, 0.08, 0.12),
                        "densification_strain": e_d, "absorbed_MJ_per_m3": w_d / 1e6, "end_strain": float(strain[-1]),
                        "particles": particles, "steps": steps, "wall_s": wall})
    with open(os.path.join(out, "lattice_size_stress_strain.csv"), "w") as f:
        f.write("scene,a_mm,cells_per_edge,strain,stress_MPa\n")
        for name, a, n, e, st in rows:
            f.write(f"{name},{a * 1e3:.1f},{n},{e:.6f},{st / 1e6:.6f}\n")
    write_summary(os.path.join(out, "lattice_size_summary.csv"), summary)
    for r in summary:
        print(f"{r['scene']}: a {r['a_mm']:.1f} mm, {r['cells_per_edge']} per edge, rho* {r['rho_rel_particles']:.3f}  "
              f"first yield {r['first_yield_MPa']:.3f} MPa  plateau {r['plateau_MPa']:.3f} MPa (40 % / 10 %: "
              f"{r['plateau_rise_40_over_10']:.2f})  densification {r['densification_strain']:.3f}  absorbed "
              f"{r['absorbed_MJ_per_m3']:.3f} MJ/m^3  end strain {r['end_strain']:.3f}  {r['particles']} particles, "
              f"{r['steps']} steps, wall {r['wall_s']:.1f} s")
    dashes = {2: 1, 4: 2, 8: 3}
    plot_curves(os.path.join(out, "lattice_size_stress_strain"), summary,
                lambda r: dashes.get(r["cells_per_edge"], 4), lambda r: f"{r['cells_per_edge']} per edge",
                "nominal stress [MPa] (plate force / specimen width)",
                "square lattices, n cells per edge (quarter models), 1000 1/s")


def scene_3d(a, h, rate, end_strain):
    """configs/lattice/lattice3d_a45.yaml with the cell edge a, mesh h, plate at rate x a."""
    s = yaml.safe_load(open(os.path.join(ROOT, "configs", "lattice", "lattice3d_a45.yaml")))
    tag = f"{a * 1e4:.0f}"
    s["scene"] = f"lattice3d_a{tag}"
    s["description"] = f"Open-cell cubic lattice (pores d = 3 mm) a = {a * 1e3:.1f} mm, eighth model, 3D"
    room, plate_t = 1.5e-3, 0.5e-3                    # the shipped scene's room beside and the plate's thickness
    up = lambda v: h * math.ceil(v / h - 1e-9)
    s["mesh"]["spacing"] = [h, h, h]
    s["mesh"]["upper"] = [up(a + room), up(a + plate_t + 0.5e-3), up(a + room)]
    lattice = next(g for g in s["geometry"] if g["name"] == "lattice")
    box, *pores = lattice["shape"]["shapes"]
    box["hi"] = [a, a, a]
    for c in pores:
        c["center"] = [0.5 * a] * 3
    plate = next(g for g in s["geometry"] if g["name"] == "plate")
    plate["shape"] = {"type": "box", "lo": [0.0, a, 0.0], "hi": [s["mesh"]["upper"][0], a + plate_t, s["mesh"]["upper"][2]]}
    plate["velocity"] = [0.0, -rate * a, 0.0]
    s["time"]["end"] = end_strain / rate
    s["output"]["interval"] = 0.01 / rate
    s["output"]["directory"] = s["scene"]
    return s


def study_3d(args):
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    exe = os.path.join(os.path.abspath(args.build), "mpm_solver", "mpm_solver")
    cells = [float(v) * 1e-3 for v in args.cells.split(",")]
    rho_slides = {4.5: 0.37, 4.0: 0.27, 3.5: 0.16}
    two_d = {}
    if os.path.exists(args.compare2d):
        with open(args.compare2d) as f:
            keys = f.readline().strip().split(",")
            for line in f:
                r = dict(zip(keys, line.strip().split(",")))
                two_d[round(float(r["a_mm"]), 1)] = r
    cases, commands = [], []
    for a in cells:
        s = scene_3d(a, args.mesh3d, 1000.0, args.end_strain)
        path = os.path.join(out, s["scene"] + ".yaml")
        yaml.dump(s, open(path, "w"), Dumper=SceneDumper, sort_keys=False)
        log = os.path.join(out, s["scene"] + ".log")
        cases.append((s["scene"], a, os.path.join(out, s["output"]["directory"]), log))
        commands.append(([exe, path], out, log))
    if not args.skip_run:
        run_all(args.jobs, commands)
    rows, summary = [], []
    for name, a, directory, log in cases:
        if len(glob.glob(os.path.join(directory, "*.h5"))) < 3:
            print(f"{name}: fewer than 3 outputs in {directory}, left out")
            continue
        travel, force, vol0 = curve(directory, name)
        strain, stress = travel / a, force / (a * a)
        steps, wall, rate, particles = parse_log(open(log).read())
        rho = rho_slides.get(round(a * 1e3, 1), float("nan"))
        r2 = two_d.get(round(a * 1e3, 1), {})
        plateau = band_mean(strain, stress, 0.2, 0.4) if strain[-1] >= 0.4 else float("nan")
        # densification (largest energy efficiency past 20 %) and the energy to it, as the 2D study
        _, e_d, w_d = summarize(strain, stress) if strain[-1] >= 0.4 else (0, float("nan"), float("nan"))
        rows += [(name, a, e, st) for e, st in zip(strain, stress)]
        summary.append({"scene": name, "a_mm": a * 1e3, "rho_rel_slides": rho, "rho_rel_particles": vol0 / a ** 3,
                        "first_yield_MPa": band_mean(strain, stress, 0.04, 0.12) / 1e6, "plateau_MPa": plateau / 1e6,
                        "plateau_2d_MPa": float(r2.get("plateau_MPa", "nan")),
                        "first_yield_2d_MPa": float(r2.get("first_yield_MPa", "nan")),
                        "gibson_ashby_MPa": 0.3 * rho ** 1.5 * SIGMA_Y / 1e6,
                        "densification_strain": e_d, "absorbed_to_densification_MJ_per_m3": w_d / 1e6,
                        "plateau_2d_densification": float(r2.get("densification_strain", "nan")),
                        "peak_to_12pct_MPa": float(np.max(stress[strain <= 0.12])) / 1e6,
                        "end_strain": float(strain[-1]), "particles": particles, "steps": steps, "wall_s": wall})
    with open(os.path.join(out, "lattice3d_stress_strain.csv"), "w") as f:
        f.write("scene,a_mm,strain,stress_MPa\n")
        for name, a, e, st in rows:
            f.write(f"{name},{a * 1e3:.1f},{e:.6f},{st / 1e6:.6f}\n")
    if not summary:
        return
    keys = list(summary[0].keys())
    with open(os.path.join(out, "lattice3d_summary.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in summary:
            f.write(",".join(f"{r[k]:.6g}" if isinstance(r[k], float) else str(r[k]) for k in keys) + "\n")
    for r in summary:
        print(", ".join(f"{k} {r[k]:.4g}" if isinstance(r[k], float) else f"{k} {r[k]}" for k in keys))
    # The 3D curves (solid) beside the 2D square grids' (dashed, from the 2D summary's directory).
    png = os.path.join(out, "lattice3d_stress_strain.png")
    csv3 = os.path.join(out, "lattice3d_stress_strain.csv")
    csv2 = os.path.join(os.path.dirname(args.compare2d), "lattice_stress_strain.csv")
    colours = COLOURS
    plots = []
    for r in summary:
        a, c = round(r["a_mm"], 1), colours.get(round(r["a_mm"], 1), "black")
        plots.append(f"'< grep ^{r['scene']}, {csv3}' using 3:4 with lines lw 2 lc rgb '{c}' "
                     f"title '3D, a = {a:.1f} mm'")
        if os.path.exists(csv2):
            tag = f"lattice_a{int(round(a * 10))},"
            plots.append(f"'< grep ^{tag} {csv2}' using 3:4 with lines lw 1 dt 2 lc rgb '{c}' title '2D, a = {a:.1f} mm'")
    gp = (f"set terminal pngcairo size 1000,650; set output '{png}'; set datafile separator ',';"
          f"set xlabel 'nominal strain'; set ylabel 'nominal stress (plate force / a^2) [MPa]'; set grid;"
          f"set title '3D cells (eighth model, mesh {args.mesh3d * 1e3:g} mm, 1000 1/s) and the 2D square grids';"
          f"set key top left; plot {', '.join(plots)}")
    gnuplot(gp, png)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default="output/lattice")
    ap.add_argument("--skip-run", action="store_true", help="read the existing outputs")
    ap.add_argument("--study", choices=["closed", "filled", "3d", "size"], default="closed",
                    help="closed: the shipped scenes; filled: open-cell variants, empty and filled")
    ap.add_argument("--mesh", type=float, default=1.5e-4, help="filled study: mesh spacing [m]")
    ap.add_argument("--rate", type=float, default=2000.0, help="filled study: nominal strain rate [1/s]")
    ap.add_argument("--viscosities", default="1,100", help="filled study: the filler's viscosities [Pa s]")
    ap.add_argument("--jobs", type=int, default=2, help="filled study: runs at a time")
    ap.add_argument("--filled-cfl", type=float, default=0.1,
                    help="filled study: time.cfl of the filled (coupled) runs; the empty ones keep the scene's")
    # GIMP (the shipped scenes') lets the filled lattices' thin strut on the mirror plane ring in a
    # volumetric mode of its particles until a polymer particle there falls below 0 K (33 % strain at
    # a = 4.0 mm, 1 Pa s); quadratic B-splines keep it quiet (docs/slides.md, "Filled lattices").
    ap.add_argument("--shape", default="bspline2", help="filled study: MPM shape function of every run, empty and filled")
    ap.add_argument("--room", type=float, default=9.0e-3, help="filled study: mesh beside the specimen [m]")
    ap.add_argument("--solid-transport", choices=["ice", "mpm"], default="mpm",
                    help="filled study: coupling.solid_transport of the filled runs (mpm since 7 Dec 2026: with ice "
                         "the polymer's heat drains into the silicone, docs/slides.md \"The layered column\")")
    ap.add_argument("--beside-density", type=float, default=BESIDE_RHO,
                    help="filled study, --filler pores: the buffer gas's density beside the specimen [kg/m^3]")
    ap.add_argument("--filler", choices=["surround", "pores"], default="pores",
                    help="filled study: the liquid in the pores and beside the specimen below the plate "
                         "(surround), or in the pores only with the buffer gas beside it (pores)")
    ap.add_argument("--only", default="", help="filled study: run only these scenes (comma-separated names); "
                    "the others' outputs are read where present")
    ap.add_argument("--mesh3d", type=float, default=2.5e-4, help="3d study: mesh spacing [m]")
    ap.add_argument("--cells", default="4.5", help="3d study: cell edges a [mm], comma-separated")
    ap.add_argument("--end-strain", type=float, default=0.7, help="3d study: nominal strain at the end")
    ap.add_argument("--compare2d", default=os.path.join(ROOT, "docs", "lattice_summary.csv"),
                    help="3d study: the 2D summary to compare with")
    ap.add_argument("--per-edge", default=None,
                    help="size and filled studies: cells per edge of the specimen (even; size: default 2,4,8, filled: 2)")
    args = ap.parse_args()
    if args.study == "size":
        return size_study(args)
    if args.study == "filled":
        return filled_study(args)
    if args.study == "3d":
        return study_3d(args)
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
    gnuplot(gp, png)


if __name__ == "__main__":
    main()
