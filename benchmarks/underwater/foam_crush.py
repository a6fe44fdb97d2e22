#!/usr/bin/env python3
"""How far the foam layer of configs/underwater_foam_2d.yaml is crushed (issue 16, docs/slides.md).

Reads a run's output steps (particle positions) and prints, per output time (every --every-th and
the last), the downward displacement of the foam's top: the particles that start in the top half
cell of the solid layer (the top row at 2 x 2 particles per cell), their mean over the whole width
and their largest on the charge's axis (x < one cell). The mean is the measure to compare between
meshes: the axis value moves by whole particle spacings as single particles give way. Where the
output has the particles' material and id (mpmice writes them since 4 Dec 2026), the foam is the
material of the lowest particle and particles are followed by id, so a scene with the PVC tube
(whose fragments may leave the domain) is measured too.

    scripts/python benchmarks/underwater/foam_crush.py output/underwater_foam_2d [--every 10]
"""
import argparse
import glob
import os
import sys

import h5py
import numpy as np


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("directory")
    ap.add_argument("--every", type=int, default=10, help="print every N-th output (and the last)")
    args = ap.parse_args()
    files = sorted(glob.glob(os.path.join(args.directory, "*_[0-9][0-9][0-9][0-9][0-9][0-9].h5")))
    if len(files) < 2:
        sys.exit(f"{args.directory}: fewer than 2 output steps (*_NNNNNN.h5)")
    with h5py.File(files[0], "r") as h:
        if "particles/position" not in h:
            sys.exit(f"{files[0]}: no particles/position (output.particles must be on)")
        p0 = h["particles/position"][:]
        hx, hy = float(h.attrs["spacing"][0]), float(h.attrs["spacing"][1])
        tagged = "particles/material" in h and "particles/id" in h
        if tagged:
            mat, ids0 = h["particles/material"][:], h["particles/id"][:]
            foam = mat == mat[np.argmin(p0[:, 1])]
            p0, ids0 = p0[foam], ids0[foam]
    top = p0[:, 1] > p0[:, 1].max() - 0.5 * hy   # the top half cell of the layer
    axis = top & (p0[:, 0] < hx)
    print(f"{args.directory}: cell {hx * 1e3:g} x {hy * 1e3:g} mm, foam top at y = {p0[:, 1].max():.4f} m, "
          f"{int(top.sum())} top particles ({int(axis.sum())} on the axis)")
    print("t [us], mean crush of the top [mm], largest on the axis [mm]")
    picks = files[::args.every] + ([files[-1]] if (len(files) - 1) % args.every else [])
    for f in picks:
        with h5py.File(f, "r") as h:
            t = float(h.attrs["time"])
            p = h["particles/position"][:]
            if tagged:
                ids = h["particles/id"][:]
                where = dict(zip(ids.tolist(), range(len(ids))))
                if any(i not in where for i in ids0.tolist()):
                    sys.exit(f"{f}: foam particles removed")
                p = p[[where[i] for i in ids0.tolist()]]
        if p.shape[0] != p0.shape[0]:
            sys.exit(f"{f}: {p.shape[0]} particles against {p0.shape[0]} at the start (particles removed)")
        d = p0[:, 1] - p[:, 1]
        print(f"{t * 1e6:7.1f}  {d[top].mean() * 1e3:7.2f}  {d[axis].max() * 1e3:7.2f}")


if __name__ == "__main__":
    main()
