#!/usr/bin/env python3
"""Bytes per particle and per cell of mpm_solver and ice_solver: peak RSS against the count.

Each program runs a few steps of a 2D scene at two sizes (output off); the peak resident set of
the child (getrusage RUSAGE_CHILDREN, ru_maxrss) is read after each run. The slope between the
two sizes is the memory per item; the fixed cost (libraries, MPI) cancels.

  mpm_solver, per particle: a 2D elastic block, 512^2 cells, 2x2 then 4x4 particles per cell
              (same mesh: the slope is per particle).
  mpm_solver, per cell:     the same 16^2-cell block (1,024 particles) in a 512^2 then 1024^2 mesh.
  ice_solver, per cell:     a 2D box with 1 then 2 fluids in every cell, 256^2 then 512^2 cells;
              per material = the 2-fluid slope minus the 1-fluid slope.

  benchmarks/memory/footprint.py build        (the build directory holding mpm_solver/, ice_solver/)
"""
import os
import resource
import subprocess
import sys
import tempfile


def peak_rss_kib(cmd, cwd):
    """Runs cmd (in a fresh child process so ru_maxrss is its own) and returns its peak RSS [KiB]."""
    probe = ("import resource, subprocess, sys\n"
             "r = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)\n"
             "if r.returncode: sys.exit('run failed: ' + ' '.join(sys.argv[1:]) + '\\n' + r.stderr[-2000:])\n"
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n")
    out = subprocess.run([sys.executable, "-c", probe] + cmd, cwd=cwd, check=True, capture_output=True, text=True)
    return int(out.stdout.split()[-1])


def mpm_scene(cells, block, ppc, steps):
    h = 1.0 / cells
    lo, hi = 0.5 - block * h / 2, 0.5 + block * h / 2
    return f"""scene: footprint_mpm
mesh: {{dim: 2, lower: [0.0, 0.0], upper: [1.0, 1.0], cells: [{cells}, {cells}]}}
time: {{end: 1.0, cfl: 0.4, dt_max: 1.0e-9, max_steps: {steps}}}
materials:
  - {{name: block, kind: solid, density: 1000, model: {{type: linear_elastic, youngs_modulus: 1.0e6, poissons_ratio: 0.3}}}}
geometry:
  - {{name: block, shape: {{type: box, lo: [{lo}, {lo}], hi: [{hi}, {hi}]}}, material: block, particles_per_cell: {ppc}}}
boundary: {{x-: noslip_wall, x+: noslip_wall, y-: noslip_wall, y+: noslip_wall}}
mpm: {{shape_function: bspline2, update: usl}}
output: {{enabled: false}}
"""


def ice_scene(cells, fluids, steps):
    mats = ["  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}, specific_heat: 717.5}"]
    geo = ["  - {name: air, shape: {type: box, lo: [0.0, 0.0], hi: [1.0, 1.0]}, material: air, pressure: 1.0e5}"]
    if fluids == 2:
        mats.append("  - {name: helium, kind: fluid, eos: {type: ideal_gas, gamma: 1.66}, specific_heat: 3116}")
        geo = ["  - {name: mix, shape: {type: box, lo: [0.0, 0.0], hi: [1.0, 1.0]}, pressure: 1.0e5, "
               "mixture: [{material: air, volume_fraction: 0.5}, {material: helium, volume_fraction: 0.5}]}"]
    return f"""scene: footprint_ice
mesh: {{dim: 2, lower: [0.0, 0.0], upper: [1.0, 1.0], cells: [{cells}, {cells}]}}
time: {{end: 1.0, cfl: 0.4, max_steps: {steps}}}
materials:
{chr(10).join(mats)}
geometry:
{chr(10).join(geo)}
boundary: {{x-: noslip_wall, x+: noslip_wall, y-: noslip_wall, y+: noslip_wall}}
output: {{enabled: false}}
"""


def run(exe, yaml_text, work, name):
    path = os.path.join(work, name + ".yaml")
    with open(path, "w") as f:
        f.write(yaml_text)
    return peak_rss_kib([exe, path], work)


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    mpm = os.path.abspath(os.path.join(build, "mpm_solver", "mpm_solver"))
    ice = os.path.abspath(os.path.join(build, "ice_solver", "ice_solver"))
    work = tempfile.mkdtemp(prefix="footprint_")
    steps = 3
    # MPM per particle: same mesh, 4x the particles.
    n, blk = 512, 256
    a = run(mpm, mpm_scene(n, blk, 2, steps), work, "mpm_p2")
    b = run(mpm, mpm_scene(n, blk, 4, steps), work, "mpm_p4")
    np2, np4 = (2 * blk) ** 2, (4 * blk) ** 2
    per_particle = (b - a) * 1024.0 / (np4 - np2)
    print(f"mpm_solver per particle: {per_particle:.0f} B  (peak RSS {a} KiB with {np2} particles, "
          f"{b} KiB with {np4}; 2D, {n}^2 cells, bspline2)")
    # MPM per cell: same particles, 4x the cells.
    c = run(mpm, mpm_scene(512, 16, 2, steps), work, "mpm_c512")
    d = run(mpm, mpm_scene(1024, 32, 1, steps), work, "mpm_c1024")
    per_cell = (d - c) * 1024.0 / (1024 ** 2 - 512 ** 2)
    print(f"mpm_solver per cell:     {per_cell:.0f} B  (peak RSS {c} KiB with 512^2 cells, {d} KiB with 1024^2;"
          f" 1,024 particles in both)")
    # ICE per cell, 1 and 2 fluids in every cell.
    res = {}
    for fl in (1, 2):
        e = run(ice, ice_scene(256, fl, steps), work, f"ice{fl}_256")
        f = run(ice, ice_scene(512, fl, steps), work, f"ice{fl}_512")
        res[fl] = (f - e) * 1024.0 / (512 ** 2 - 256 ** 2)
        print(f"ice_solver per cell, {fl} fluid(s): {res[fl]:.0f} B  (peak RSS {e} KiB at 256^2 cells, {f} KiB at 512^2)")
    print(f"ice_solver per cell per fluid: {res[2] - res[1]:.0f} B (the second fluid), fixed part per cell "
          f"{2 * res[1] - res[2]:.0f} B")


if __name__ == "__main__":
    main()
