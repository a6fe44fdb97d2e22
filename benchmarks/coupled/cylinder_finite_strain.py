#!/usr/bin/env python3
"""Eq. 13 of a finished pressurized-cylinder run against the small-strain Lame sum and against the
exact finite-strain annulus the code solves (docs/coupling.md, "The angular pattern traced").

The MPM linear_elastic model is hypoelastic with the Jaumann rate; for the radial expansion of an
annulus (no spin) that is linear elasticity in logarithmic strain, with equilibrium on the current
radii: d sigma_r / dr + (sigma_r - sigma_theta) / r = 0, plane strain, sigma_r = -(P - p_ref) on the
current inner radius and -(p_amb - p_ref) on the outer one. Solved by shooting on r(r_i).

Usage: cylinder_finite_strain.py RUN.h5 P DX [K G] [RI RO PREF PAMB]
  RUN.h5: the last output step (mpmice); P: the cavity pressure cylinder_lame prints.
Prints Eq. 13 and the bands (0-1, 1-2, 2-4, 4-8, >= 8 dx from the nearer surface) for both references,
and the loads the wall carries: the Lame form sigma_r = A - B / r^2, sigma_theta = A + B / r^2 fitted
(least squares) to the particles >= 2 dx from both surfaces, read as the inner and outer gauge loads
(against the stress-free state) that make it, beside the exact ones (P - p_ref, p_amb - p_ref) and
beside the same fit of the finite-strain reference (what finite strain alone moves them by).
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
    return r, sr, st  # the radial and hoop stresses at current radius r


def lame_loads(r, sr, st, ri, ro):
    """The inner and outer gauge loads (Pi, Po) of the Lame form fitted to sigma_r, sigma_theta at r."""
    M = np.vstack([np.concatenate([np.ones_like(r)] * 2), np.concatenate([-1 / r**2, 1 / r**2])]).T
    (A, B), *_ = np.linalg.lstsq(M, np.concatenate([sr, st]), rcond=None)
    k = ro**2 - ri**2
    d = B * k / (ri**2 * ro**2)  # Pi - Po
    Pi = (A * k - ro**2 * d) / (ri**2 - ro**2)
    return Pi, Pi - d


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
    rr, rsr, rst = finite_strain_annulus(P, K, G, ri, ro, pref, pamb)
    ssum = rsr + rst
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
    c, sn = x[:, 0] / r, x[:, 1] / r
    sig_r = s[:, 0] * c * c + s[:, 1] * sn * sn + 2 * s[:, 3] * c * sn  # datasets: xx, yy, zz, xy, yz, xz
    sig_t = s[:, 0] * sn * sn + s[:, 1] * c * c - 2 * s[:, 3] * c * sn
    inner = d >= 2
    Pi, Po = lame_loads(r[inner], sig_r[inner], sig_t[inner], ri, ro)
    keep = (rr >= ri + 2 * dx) & (rr <= ro - 2 * dx)
    Fi, Fo = lame_loads(rr[keep], rsr[keep], rst[keep], ri, ro)
    print("loads the wall carries (Lame fit, >= 2 dx from both surfaces): inner %.6e Pa (P - p_ref %.6e: %+.1f Pa), "
          "outer %.6e Pa (p_amb - p_ref %.6e: %+.1f Pa); the finite-strain reference's fit: %+.1f / %+.1f Pa"
          % (Pi, P - pref, Pi - (P - pref), Po, pamb - pref, Po - (pamb - pref), Fi - (P - pref), Fo - (pamb - pref)))


if __name__ == "__main__":
    main()
