#!/usr/bin/env python3
"""A textbook scheme beside ICE on a shock tube (docs/ice.md "The neighbours"): MUSCL-Hancock
(primitive variables; van Leer's limiter, or --limiter minmod / superbee) or first-order Godunov, both with the HLLC flux, one ideal
gas, zero-gradient ends. Prints the largest density and pressure in the window behind the shock
against the exact star state, in % of the shock's jump, as ice_shock_sweep measures ICE.

  scripts/python benchmarks/ice/muscl_hllc_reference.py --left 12,0,1e6 --right 0.166,0,1e5 \\
      --gamma 1.4 --x0 0.4 --t 2.97e-4 --cells 100,200,400 --star 0.244949,173582 --window 0.63,0.755

--star: the exact density behind the right-going shock and the star pressure (ice_shock_sweep's
exact solver prints them with ICE_SHOCK_DUMP); --window: from halfway between contact and shock to
the shock (5 cells ahead are added)."""
import argparse

import numpy as np


def hllc(g, rl, ul, pl, rr, ur, pr):
    cl, cr = np.sqrt(g * pl / rl), np.sqrt(g * pr / rr)
    sl, sr = np.minimum(ul - cl, ur - cr), np.maximum(ul + cl, ur + cr)
    ss = (pr - pl + rl * ul * (sl - ul) - rr * ur * (sr - ur)) / (rl * (sl - ul) - rr * (sr - ur))
    el, er = pl / (g - 1) + 0.5 * rl * ul * ul, pr / (g - 1) + 0.5 * rr * ur * ur
    fl = np.array([rl * ul, rl * ul * ul + pl, (el + pl) * ul])
    fr = np.array([rr * ur, rr * ur * ur + pr, (er + pr) * ur])
    ql, qr = np.array([rl, rl * ul, el]), np.array([rr, rr * ur, er])

    def star(r, u, p, e, s):
        f = r * (s - u) / (s - ss)
        return f * np.array([np.ones_like(r), ss, e / r + (ss - u) * (ss + p / (r * (s - u)))])

    qsl, qsr = star(rl, ul, pl, el, sl), star(rr, ur, pr, er, sr)
    return np.where(sl >= 0, fl, np.where(ss >= 0, fl + sl * (qsl - ql), np.where(sr > 0, fr + sr * (qsr - qr), fr)))


def limited(a, b, limiter):
    if limiter == "minmod":
        return np.where(a * b > 0, np.sign(a) * np.minimum(np.abs(a), np.abs(b)), 0.0)
    if limiter == "superbee":
        s = np.sign(a)
        return np.where(a * b > 0, s * np.maximum(np.minimum(2 * np.abs(a), np.abs(b)), np.minimum(np.abs(a), 2 * np.abs(b))), 0.0)
    return np.where(a * b > 0, 2 * a * b / np.where(a + b == 0, 1, a + b), 0.0)  # van Leer


def run(g, n, left, right, x0, t_end, second_order, cfl=0.4, limiter="van_leer"):
    dx = 1.0 / n
    x = (np.arange(n) + 0.5) * dx
    w = np.array([np.where(x < x0, left[k], right[k]) for k in range(3)])
    q = np.array([w[0], w[0] * w[1], w[2] / (g - 1) + 0.5 * w[0] * w[1] ** 2])
    t = 0.0
    while t < t_end * (1 - 1e-12):
        r = q[0]
        u = q[1] / r
        p = (g - 1) * (q[2] - 0.5 * r * u * u)
        dt = min(cfl * dx / np.max(np.abs(u) + np.sqrt(g * p / r)), t_end - t)
        wp = np.array([r, u, p])
        wg = np.concatenate([wp[:, :1], wp[:, :1], wp, wp[:, -1:], wp[:, -1:]], axis=1)
        if second_order:
            a, b = wg[:, 1:-1] - wg[:, :-2], wg[:, 2:] - wg[:, 1:-1]
            d = limited(a, b, limiter)
            wc = wg[:, 1:-1]
            rc, uc, pc = wc
            half = 0.5 * dt / dx * np.array([uc * d[0] + rc * d[1], uc * d[1] + d[2] / rc, g * pc * d[1] + uc * d[2]])
            wl, wr = wc - 0.5 * d - half, wc + 0.5 * d - half
            fl, fr = wr[:, :-1], wl[:, 1:]
        else:
            fl, fr = wg[:, 1:-2], wg[:, 2:-1]
        f = hllc(g, fl[0], fl[1], fl[2], fr[0], fr[1], fr[2])
        q = q - dt / dx * (f[:, 1:] - f[:, :-1])
        t += dt
    r = q[0]
    u = q[1] / r
    return x, r, u, (g - 1) * (q[2] - 0.5 * r * u * u)


def main():
    ap = argparse.ArgumentParser()
    v3 = lambda s: [float(z) for z in s.split(",")]
    ap.add_argument("--left", type=v3, required=True)
    ap.add_argument("--right", type=v3, required=True)
    ap.add_argument("--gamma", type=float, default=1.4)
    ap.add_argument("--x0", type=float, required=True)
    ap.add_argument("--t", type=float, required=True)
    ap.add_argument("--cells", default="100,200,400")
    ap.add_argument("--star", type=v3, required=True)
    ap.add_argument("--window", type=v3, required=True)
    ap.add_argument("--limiter", default="van_leer", choices=["van_leer", "minmod", "superbee"])
    ap.add_argument("--cfl", type=float, default=0.4)
    a = ap.parse_args()
    rho_s, p_s = a.star
    for n in [int(c) for c in a.cells.split(",")]:
        for second in (False, True):
            x, r, u, p = run(a.gamma, n, a.left, a.right, a.x0, a.t, second, a.cfl, a.limiter)
            m = (x > a.window[0]) & (x < a.window[1] + 5.0 / n)
            print("%-13s %5d cells: overshoot rho %+.2f %% p %+.2f %%" % (
                "muscl-hancock" if second else "godunov", n, 100 * (r[m].max() - rho_s) / (rho_s - a.right[0]),
                100 * (p[m].max() - p_s) / (p_s - a.right[2])))


if __name__ == "__main__":
    main()
