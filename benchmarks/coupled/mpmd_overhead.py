#!/usr/bin/env python3
"""Issue 13: the MPMD launch (mpm_solver + ice_solver, 1 + 1 ranks) against the in-process
driver mpmice on the seed cylinder (configs/pressurized_cylinder.yaml at time.end 1e-3, 715
steps), interleaved in one run, medians of N (default 5).

Run from the repository:  python3 benchmarks/coupled/mpmd_overhead.py build [scratch-dir] [N]
(scratch default /tmp/mpmd_overhead, created or reused). With BASELINE=<other build dir> in the
environment, that build's MPMD runs are interleaved too (rows "baseline ..."), for before/after.
Prints one table (markdown):
each run's step loop (compute + exchange seconds of the solid's process, as its closing line
prints them; mpmice: of its one process), the ratio to mpmice (monolithic-style), iterations per
step, the solid's compute/exchange split, the fluid's, the message latency, and the load
average (1 min) over the runs. The targets (issue 13): MPMD monolithic-style <= 1.05x mpmice,
explicit_parallel <= 0.65x, implicit_parallel + IQN-ILS no slower per step than
implicit_serial + IQN-ILS.
"""
import os, re, statistics, subprocess, sys

build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build")
scratch = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "/tmp/mpmd_overhead")
repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 5
repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
mpmice = os.path.join(build, "coupler", "mpmice")
mpm = os.path.join(build, "mpm_solver", "mpm_solver")
ice = os.path.join(build, "ice_solver", "ice_solver")
mpirun = os.path.join(repo, "scripts", "mpirun")
os.makedirs(scratch, exist_ok=True)
base = open(os.path.join(repo, "configs", "pressurized_cylinder.yaml")).read()
base = re.sub(r"\n  end: [0-9.e+-]+", "\n  end: 1.0e-3", base, count=1)
# The baseline (and docs/benchmarks.md's idle table) is the seed cylinder with linear
# shape functions and 2 x 2 particles per cell; the shipped scene now uses bspline2 with 4 x 4, a
# 4x heavier solid, so the benchmark pins the measured settings.
base = re.sub(r"particles_per_cell: [0-9]+", "particles_per_cell: 2", base)
base = re.sub(r"shape_function: [a-z0-9]+", "shape_function: linear", base)
IQN = "  acceleration: {type: iqn_ils, relaxation: 0.1, reuse: 8}\n"


def scene(schedule, accel=""):
    name = schedule + ("_iqn" if accel else "")
    text = base.replace("  schedule: monolithic\n", "  schedule: %s\n%s" % (schedule, accel))
    text = re.sub(r"directory: .*", "directory: " + os.path.join(scratch, name, "out"), text)
    os.makedirs(os.path.join(scratch, name), exist_ok=True)
    path = os.path.join(scratch, name, name + ".yaml")
    open(path, "w").write(text)
    return path


RUNS = [  # label, command builder
    ("mpmice, monolithic-style", lambda: [mpmice, scene("monolithic")]),
    ("MPMD 1+1, monolithic-style", lambda: [mpirun, "-np", "1", mpm, scene("monolithic"), ":", "-np", "1", ice,
                                            scene("monolithic")]),
    ("MPMD 1+1, explicit_parallel", lambda: [mpirun, "-np", "1", mpm, scene("explicit_parallel"), ":", "-np", "1",
                                             ice, scene("explicit_parallel")]),
    ("MPMD 1+1, implicit_serial + IQN-ILS", lambda: [mpirun, "-np", "1", mpm, scene("implicit_serial", IQN), ":",
                                                     "-np", "1", ice, scene("implicit_serial", IQN)]),
    ("MPMD 1+1, implicit_parallel + IQN-ILS", lambda: [mpirun, "-np", "1", mpm, scene("implicit_parallel", IQN), ":",
                                                       "-np", "1", ice, scene("implicit_parallel", IQN)]),
]
baseline = os.environ.get("BASELINE")
if baseline:
    bm, bi = (os.path.join(os.path.abspath(baseline), d, d) for d in ("mpm_solver", "ice_solver"))
    for sched in ("monolithic", "explicit_parallel"):
        RUNS.append(("baseline MPMD 1+1, " + sched, lambda s=sched: [mpirun, "-np", "1", bm, scene(s), ":", "-np", "1",
                                                                    bi, scene(s)]))
SPLIT = re.compile(r"coupling \((mpmice|mpm_solver[^)]*|ice_solver[^)]*)\): computed ([0-9.e+-]+) s, ([0-9.e+-]+) s in exchange")
ITERS = re.compile(r"iterations in (\d+) steps \(([0-9.e+-]+) per step\)")
LATENCY = re.compile(r"message latency ([0-9.e+-]+) us")

results = {label: [] for label, _ in RUNS}
loads = []
for rep in range(repeats):
    for label, command in RUNS:
        loads.append(os.getloadavg()[0])
        r = subprocess.run(command(), capture_output=True, text=True, cwd=scratch)
        out = r.stdout + r.stderr
        if r.returncode != 0:
            sys.exit("mpmd_overhead.py: %s failed (exit %d):\n%s" % (label, r.returncode, out[-3000:]))
        split = {m.group(1).split(",")[0]: (float(m.group(2)), float(m.group(3))) for m in SPLIT.finditer(out)}
        solid = split.get("mpmice") or split["mpm_solver"]
        steps, per = ITERS.search(out).groups()
        lat = LATENCY.search(out)
        results[label].append({"loop": sum(solid), "solid": solid, "fluid": split.get("ice_solver"),
                               "steps": int(steps), "iters": float(per), "latency": float(lat.group(1)) if lat else None})
        print("run %d/%d %-40s %.3f s" % (rep + 1, repeats, label, sum(solid)), file=sys.stderr, flush=True)

med = lambda xs: statistics.median(xs)
ref = med([x["loop"] for x in results[RUNS[0][0]]])
print("| run | step loop [s] (median of %d) | / mpmice | per step [ms] | iterations/step | solid compute / exchange [s] | fluid compute / exchange [s] | latency [us] |" % repeats)
print("|---|---|---|---|---|---|---|---|")
for label, _ in RUNS:
    xs = results[label]
    loop = med([x["loop"] for x in xs])
    sc = med([x["solid"][0] for x in xs]), med([x["solid"][1] for x in xs])
    fl = "%.2f / %.2f" % (med([x["fluid"][0] for x in xs]), med([x["fluid"][1] for x in xs])) if xs[0]["fluid"] else "-"
    lat = "%.1f" % med([x["latency"] for x in xs]) if xs[0]["latency"] is not None else "-"
    print("| %s | %.3f (%s) | %.2fx | %.2f | %.2f | %.2f / %.2f | %s | %s |" % (
        label, loop, ", ".join("%.2f" % x["loop"] for x in xs), loop / ref, 1e3 * loop / xs[0]["steps"],
        xs[0]["iters"], sc[0], sc[1], fl, lat))
print("\nload average (1 min) during the runs: min %.2f, median %.2f, max %.2f (%d cores)" % (
    min(loads), med(loads), max(loads), os.cpu_count()))
