#!/usr/bin/env python3
"""Eq. 13 of a finished pressurized-cylinder run against the small-strain Lame sum and against the
exact finite-strain annulus the code solves (docs/coupling.md, "The angular pattern traced").

The MPM linear_elastic model is hypoelastic with the Jaumann rate; for the radial expansion of an
annulus (no spin) that is linear elasticity in logarithmic strain, with equilibrium on the current
radii: d sigma_r / dr + (sigma_r - sigma_theta) / r = 0, plane strain, sigma_r = -(P - p_ref) on the
current inner radius and -(p_amb - p_ref) on the outer one. Solved by shooting on r(r_i).

Usage: cylinder_finite_strain.py RUN.h5 P DX [K G] [RI RO PREF PAMB]
  RUN.h5: the last output step (mpmice); P: the cavity pressure cylinder_lame prints.
Prints Eq. 13 and the bands (0-1, 1-2, 2-4, 4-8, >= 8 dx from the nearer surface) for both references.
"""
import sys

import h5py
import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq


def finite_strain_annulus(P, K, G, ri, ro, pref, pamb):
    lam = K - 2 * G / 3
    M = lam + 2 * G
    Pi, Po = P - pref, pamb - pref

    def rhs(R, y):
        r, sr = y
        et = np.log(r / R)
        er = (sr - lam * et) / M
        lr = np.exp(er)
        st = lam * er + M * et
        return [lr, -(sr - st) / r * lr]

    def shoot(r0):
        return solve_ivp(rhs, [ri, ro], [r0, -Pi], rtol=1e-12, atol=1e-14 * max(abs(Pi), 1), dense_output=True)

    u = brentq(lambda u: shoot(ri + u).y[1, -1] + Po, -1e-2 * ri, 1e-2 * ri, xtol=1e-16)
    sol = shoot(ri + u)
    R = np.linspace(ri, ro, 4001)
    r, sr = sol.sol(R)
    et = np.log(r / R)
    er = (sr - lam * et) / M
    st = lam * er + M * et
    return r, sr + st  # the sum at current radius r


def main():
    a = sys.argv[1:]
    if len(a) < 3:
        sys.exit(__doc__)
    fn, P, dx = a[0], float(a[1]), float(a[2])
    K = float(a[3]) if len(a) > 3 else 117.0e9
    G = float(a[4]) if len(a) > 4 else 43.8e9
    ri, ro, pref, pamb = (float(v) for v in a[5:9]) if len(a) > 8 else (0.5, 1.0, 101325.0, 101325.0)
    with h5py.File(fn, "r") as f:
        x = f["particles/position"][:]
        s = f["particles/stress"][:]
    r = np.hypot(x[:, 0], x[:, 1])
    total = s[:, 0] + s[:, 1]
    S = 2 * ((P - pref) * ri**2 - (pamb - pref) * ro**2) / (ro**2 - ri**2)
    rr, ssum = finite_strain_annulus(P, K, G, ri, ro, pref, pamb)
    refs = [("small-strain", np.full_like(r, S)), ("finite-strain", np.interp(r, rr, ssum))]
    d = np.minimum(r - ri, ro - r) / dx
    bands = [(0, 1), (1, 2), (2, 4), (4, 8), (8, 1e9)]
    for name, ref in refs:
        e = (total - ref) / S
        band = " ".join("%.4f" % (np.abs(e)[(d >= lo) & (d < hi)].sum() / len(e)) for lo, hi in bands)
        signed = " ".join("%+.4f" % (e[(d >= lo) & (d < hi)].mean() if ((d >= lo) & (d < hi)).any() else 0.0)
                          for lo, hi in bands)
        print("%-13s Eq. 13 %.5f | bands %s | signed %s" % (name, np.abs(e).mean(), band, signed))
    for R in (ri, 0.5 * (ri + ro), ro):
        print("finite-strain sum at r = %.3f: %+.4f %% of the small-strain S" % (R, 100 * (np.interp(R, rr, ssum) / S - 1)))


if __name__ == "__main__":
    main()
