#!/usr/bin/env python3
"""The largest stable CFL number of MPM's explicit USL step in 1D (docs/mpm.md "The time step's limit").

A linear model of the step (src/mpm/solver/mpm_solver.cpp: P2G with the lumped node mass, internal
force, v_L = v_n + dt f / m, FLIP / PIC G2P, stress update from grad v_L) on a free bar of 6 cells
of particles, at rest, unit density, P-modulus and spacing (c = 1, dt = CFL), placed at an offset
`shift` (in cells) to the grid. A perturbation is stepped 1500 times; the CFL number where it grows
a thousandfold is found by bisection, per offset. Pure Python (no numpy needed).

    python3 benchmarks/mpm/step_stability.py SHAPE PPC [FLIP]   # SHAPE linear | gimp | bspline2

prints the limit at each offset and the smallest (e.g. gimp 2: min 0.599 at offset 0.01).
No small-mass cut-off (MpmSolver::kSmallMassFraction), so linear hats read low where a particle
barely reaches a node (offsets near 0.35 at 2 per cell); GIMP and B-splines need none.
"""
import math
import random
import sys


def linear(r, lp):
    return (1 - abs(r), -(1 if r > 0 else -1)) if abs(r) < 1 else (0.0, 0.0)


def gimp(r, lp):
    a = abs(r)
    s = 1 if r > 0 else -1
    if a < lp:
        return 1 - (r * r + lp * lp) / (2 * lp), -r / lp
    if a < 1 - lp:
        return 1 - a, -s
    if a < 1 + lp:
        return (1 + lp - a) ** 2 / (4 * lp), -s * (1 + lp - a) / (2 * lp)
    return 0.0, 0.0


def bspline2(r, lp):
    a = abs(r)
    s = 1 if r > 0 else -1
    if a < 0.5:
        return 0.75 - a * a, -2 * r
    if a < 1.5:
        return 0.5 * (1.5 - a) ** 2, -s * (1.5 - a)
    return 0.0, 0.0


SHAPES = {"linear": linear, "gimp": gimp, "bspline2": bspline2}


def weights(kind, ppc, shift, cells, nodes):
    lp = 0.5 / ppc  # GIMP half-width: the particle's share of the cell
    rows = []
    for k in range(cells * ppc):
        x = 2 + (k + 0.5) / ppc + shift
        row = {}
        for i in range(nodes):
            w, g = SHAPES[kind](x - i, lp)
            if w or g:
                row[i] = (w, g)
        rows.append(row)
    return rows


def grows(kind, ppc, shift, cfl, flip, cells=6, steps=1500):
    nodes = cells + 5
    rows = weights(kind, ppc, shift, cells, nodes)
    n = len(rows)
    m = vol = 1.0 / ppc
    mass = [0.0] * nodes
    for row in rows:
        for i, (w, _) in row.items():
            mass[i] += m * w
    random.seed(1)
    v = [random.uniform(-1, 1) for _ in range(n)]
    s = [random.uniform(-1, 1) for _ in range(n)]
    n0 = math.sqrt(sum(a * a for a in v) + sum(a * a for a in s))
    for _ in range(steps):
        mom = [0.0] * nodes
        f = [0.0] * nodes
        for p, row in enumerate(rows):
            for i, (w, g) in row.items():
                mom[i] += m * w * v[p]
                f[i] -= vol * s[p] * g
        vn = [mom[i] / mass[i] if mass[i] > 0 else 0.0 for i in range(nodes)]
        vl = [vn[i] + cfl * f[i] / mass[i] if mass[i] > 0 else 0.0 for i in range(nodes)]
        for p, row in enumerate(rows):
            dv = grad = pic = 0.0
            for i, (w, g) in row.items():
                dv += w * (vl[i] - vn[i])
                grad += g * vl[i]
                pic += w * vl[i]
            v[p] = flip * (v[p] + dv) + (1 - flip) * pic
            s[p] += cfl * grad
        if math.sqrt(sum(a * a for a in v) + sum(a * a for a in s)) > 1e3 * n0:
            return True
    return False


def limit(kind, ppc, shift, flip):
    lo, hi = 0.1, 1.5
    for _ in range(12):
        mid = 0.5 * (lo + hi)
        if grows(kind, ppc, shift, mid, flip):
            hi = mid
        else:
            lo = mid
    return lo


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in SHAPES:
        sys.exit("usage: step_stability.py linear|gimp|bspline2 PPC [FLIP]")
    kind, ppc = sys.argv[1], int(sys.argv[2])
    flip = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
    shifts = [0, 0.01, 0.03, 0.06, 0.1, 0.15, 0.2, 0.25, 0.35, 0.5, 0.75]
    limits = [limit(kind, ppc, sh, flip) for sh in shifts]
    print(f"{kind} ppc {ppc} flip {flip}: min {min(limits):.3f};",
          " ".join(f"{sh:g}:{c:.3f}" for sh, c in zip(shifts, limits)))


if __name__ == "__main__":
    main()
