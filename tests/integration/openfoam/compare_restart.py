"""Compares an uninterrupted MPM + OpenFOAM run with a resumed one (run_flap_restart.sh).

    compare_restart.py FULL_OUT RESUMED_OUT LAST_TIME TOL

Every array of every MPM HDF5 file (output steps and checkpoints; a checkpoint's CSV byte lengths
run.*_csv aside: the CSVs are compared themselves), every numeric column of the CSVs (the
wall-time columns compute_s, exchange_s aside), the XDMF index (byte for byte: the clock is
exact), and every file of the fluid's time directory LAST_TIME in the case copy `case` (token by
token). Numbers: max |a - b| <= TOL * max |a| over each array, column (a vector's components
<name>_x/_y/_z together) or file, where a is the uninterrupted run's; everything else exactly. Prints the largest relative difference found in
each kind and exits 1 naming the first item outside TOL.
"""
import os
import re
import sys

import h5py
import numpy as np

full, resumed, last, tol = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
failures, worst = [], {}
NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def judge(kind, what, a, b, scale=None):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        failures.append(f"{what}: shapes {a.shape} and {b.shape}")
        return
    if a.size == 0:
        return
    scale = np.abs(a).max() if scale is None else scale
    d = np.abs(a - b).max() / (scale if scale > 0 else 1.0)
    worst[kind] = max(worst.get(kind, (0.0, ""))[0], d), what if d >= worst.get(kind, (0.0, ""))[0] else worst[kind][1]
    if not d <= tol:
        failures.append(f"{what}: max |difference| / max |value| = {d:.3e} > {tol:g}")


def datasets(group, prefix=""):
    for name, item in group.items():
        if isinstance(item, h5py.Group):
            yield from datasets(item, f"{prefix}/{name}")
        else:
            yield f"{prefix}/{name}"


names = sorted(n for n in os.listdir(full) if not n.startswith("log.") and not n.endswith("_run.yaml") and n != "case")
if names != sorted(n for n in os.listdir(resumed) if not n.startswith("log.") and not n.endswith("_run.yaml") and n != "case"):
    failures.append(f"the output directories hold different files: {names} and {sorted(os.listdir(resumed))}")
for name in names:
    a, b = os.path.join(full, name), os.path.join(resumed, name)
    if not os.path.exists(b):
        continue
    if name.endswith(".h5"):
        with h5py.File(a) as fa, h5py.File(b) as fb:
            sa, sb = sorted(datasets(fa)), sorted(datasets(fb))
            if sa != sb:
                failures.append(f"{name}: different datasets")
            for d in sa:
                if re.match(r"^/(data|counts)/run\.\w+_csv$", d):
                    continue
                judge("MPM HDF5", f"{name}:{d}", fa[d][()], fb[d][()])
    elif name.endswith(".csv"):
        ra = [line.split(",") for line in open(a).read().splitlines()]
        rb = [line.split(",") for line in open(b).read().splitlines()]
        if len(ra) != len(rb) or ra[0] != rb[0]:
            failures.append(f"{name}: {len(ra)} and {len(rb)} lines, or different headers")
            continue
        cols = {col: np.array([float(r[c]) for r in ra[1:]]) for c, col in enumerate(ra[0])}
        for c, col in enumerate(ra[0]):
            if col in ("compute_s", "exchange_s"):
                continue
            # A vector's components share its scale (force_z of a 2D run is round-off around 0).
            group = [v for k, v in cols.items() if re.sub(r"_[xyz]$", "", k) == re.sub(r"_[xyz]$", "", col)]
            judge("CSV", f"{name}:{col}", cols[col], [float(r[c]) for r in rb[1:]], max(np.abs(v).max() for v in group))
    elif open(a, "rb").read() != open(b, "rb").read():
        failures.append(f"{name} differs")
fa, fb = os.path.join(full, "case", last), os.path.join(resumed, "case", last)
count = 0
for root, _, files in os.walk(fa):
    for f in sorted(files):
        a = os.path.join(root, f)
        rel = os.path.relpath(a, fa)
        b = os.path.join(fb, rel)
        if not os.path.exists(b):
            failures.append(f"the resumed run did not write case/{last}/{rel}")
            continue
        if rel == "uniform/cumulativeContErr":  # a diagnostic sum over the run, not state
            continue
        ta, tb = re.split(r"[\s();]+", open(a).read()), re.split(r"[\s();]+", open(b).read())
        if len(ta) != len(tb) or any((x != y) and not (NUMBER.match(x) and NUMBER.match(y)) for x, y in zip(ta, tb)):
            failures.append(f"case/{last}/{rel}: different structure")
            continue
        num = [(float(x), float(y)) for x, y in zip(ta, tb) if NUMBER.match(x)]
        if num:
            judge("OpenFOAM", f"case/{last}/{rel}", [x for x, _ in num], [y for _, y in num])
        count += 1
for kind, (d, what) in sorted(worst.items()):
    print(f"{kind}: largest relative difference {d:.2e} ({what})")
print(f"{len(names)} output files, {count} files of the fluid's time directory {last} compared (tolerance {tol:g})")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
