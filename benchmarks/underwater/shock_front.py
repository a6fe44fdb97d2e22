#!/usr/bin/env python3
"""Shock front in the water below the charge of configs/underwater_foam_2d.yaml (issue 16).

Reads a run's output steps (cell pressure and water velocity), follows the shock down the charge's
axis (the first column of cells, x = dx/2) and writes per output time the front position (where the
pressure falls through half its peak on the leading side, interpolated), the peak pressure and the
largest downward water velocity behind it. The shock speed is the least-squares slope of the front
position over the window given (default: front 1-6 cm below the charge's bottom, "near the
charge"). The water's Hugoniot (Us = c0 + s up, p - p0 = rho0 Us up) then gives, from the
simulated speed, the particle velocity and pressure to compare with the simulated ones, and the
slides' 2700 +- 250 m/s its band.

    scripts/python benchmarks/underwater/shock_front.py output/underwater_foam_2d [--out DIR] [--png F]
"""
import argparse
import glob
import os
import subprocess

import h5py
import numpy as np

RHO0, C0, S, P0 = 1000.0, 1480.0, 1.92, 1.0e5   # the water of the scene
CHARGE_BOTTOM = 0.238                          # [m], the scene's charge box


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("directory")
    ap.add_argument("--out", default=None, help="directory for shock_front.csv (default: the run's)")
    ap.add_argument("--window", nargs=2, type=float, default=[0.01, 0.06],
                    help="distances below the charge's bottom [m] over which the speed is fitted")
    ap.add_argument("--png", default=None, help="gnuplot figure: front depth against time, peak pressure against depth")
    ap.add_argument("--expect-speed", nargs=2, type=float, default=None, metavar=("LO", "HI"),
                    help="exit 1 unless the fitted shock speed lies in [LO, HI] m/s")
    ap.add_argument("--hugoniot-tolerance", type=float, default=None,
                    help="exit 1 unless, averaged over the window, |front speed / Hugoniot speed of the "
                         "peak pressure - 1| is below this")
    args = ap.parse_args()
    files = sorted(glob.glob(os.path.join(args.directory, "*_[0-9][0-9][0-9][0-9][0-9][0-9].h5")))
    rows = []
    for f in files:
        with h5py.File(f, "r") as h:
            t = float(h.attrs["time"])
            oy, dy = float(h.attrs["origin"][1]), float(h.attrs["spacing"][1])
            p = h["grid/cell/pressure"][0, :, 0]
            u = h["grid/cell/water_velocity"][0, :, 0, 1]
        y = oy + (np.arange(p.size) + 0.5) * dy
        below = y < CHARGE_BOTTOM
        if t <= 0 or not np.any(p[below] > 10 * P0):
            continue
        yb, pb, ub = y[below], p[below], u[below]
        k = int(np.argmax(pb))
        half = 0.5 * (pb[k] + P0)
        j = k
        while j > 0 and pb[j - 1] > half:
            j -= 1
        if j == 0:
            continue
        # pressure falls through `half` between cells j-1 (below) and j
        w = (pb[j] - half) / (pb[j] - pb[j - 1])
        front = yb[j] - w * dy
        rows.append((t, front, CHARGE_BOTTOM - front, pb[k], -np.min(ub[j:k + 1]) if k >= j else -ub[k]))
    if len(rows) < 3:
        raise SystemExit(f"{args.directory}: fewer than 3 output times with a shock below the charge")
    out = args.out or args.directory
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "shock_front.csv"), "w") as f:
        f.write("time_s,front_y_m,depth_below_charge_m,peak_pressure_Pa,water_velocity_down_m_s\n")
        for r in rows:
            f.write(",".join(f"{v:.6g}" for v in r) + "\n")
    r = np.array(rows)
    sel = (r[:, 2] >= args.window[0]) & (r[:, 2] <= args.window[1])
    if np.count_nonzero(sel) < 3:
        raise SystemExit(f"fewer than 3 output times with the front {args.window} m below the charge")
    us = float(np.polyfit(r[sel, 0], r[sel, 2], 1)[0])
    up_h = (us - C0) / S
    p_h = P0 + RHO0 * us * up_h
    p_sim = float(np.mean(r[sel, 3]))
    u_sim = float(np.mean(r[sel, 4]))
    print(f"shock speed (front {args.window[0]*100:.0f}-{args.window[1]*100:.0f} cm below the charge, "
          f"{np.count_nonzero(sel)} outputs): {us:.0f} m/s  (slides: 2700 +- 250 m/s)")
    print(f"Hugoniot at that speed: particle velocity {up_h:.0f} m/s, pressure {p_h/1e9:.3f} GPa")
    print(f"simulated behind the front (mean over the window): peak pressure {p_sim/1e9:.3f} GPa, "
          f"water velocity {u_sim:.0f} m/s")
    print(f"Hugoniot of the simulated peak pressure: Us {C0 + S * (-C0 + np.sqrt(C0**2 + 4*S*(p_sim-P0)/RHO0)) / (2*S):.0f} m/s")
    # Local check: the front's speed over 5 outputs against the Hugoniot speed of the peak pressure
    # there (the shock decays as it spreads, so the window's mean pressure is only indicative).
    print("local: depth [cm], front speed [m/s] (5 outputs), peak pressure [GPa], its Hugoniot Us [m/s], "
          "water velocity [m/s], its Hugoniot up [m/s]")
    for i in range(2, len(r) - 2, 4):
        us_l = float(np.polyfit(r[i - 2:i + 3, 0], r[i - 2:i + 3, 2], 1)[0])
        up_p = (-C0 + np.sqrt(C0**2 + 4 * S * (r[i, 3] - P0) / RHO0)) / (2 * S)
        print(f"  {r[i, 2]*100:5.1f}  {us_l:6.0f}  {r[i, 3]/1e9:6.3f}  {C0 + S * up_p:6.0f}  {r[i, 4]:6.0f}  {(us_l - C0) / S:6.0f}")
    print(f"wrote {os.path.join(out, 'shock_front.csv')}")
    idx = [i for i in range(2, len(r) - 2) if sel[i]]
    dev = []
    for i in idx:
        us_l = float(np.polyfit(r[i - 2:i + 3, 0], r[i - 2:i + 3, 2], 1)[0])
        up_p = (-C0 + np.sqrt(C0**2 + 4 * S * (r[i, 3] - P0) / RHO0)) / (2 * S)
        dev.append(abs(us_l / (C0 + S * up_p) - 1))
    mean_dev = float(np.mean(dev)) if dev else float("nan")
    print(f"front speed against the Hugoniot speed of the peak pressure over the window: mean |ratio - 1| {mean_dev:.3f}")
    failed = False
    if args.expect_speed and not args.expect_speed[0] <= us <= args.expect_speed[1]:
        print(f"FAIL: shock speed {us:.0f} m/s outside [{args.expect_speed[0]:.0f}, {args.expect_speed[1]:.0f}]")
        failed = True
    if args.hugoniot_tolerance is not None and not mean_dev < args.hugoniot_tolerance:
        print(f"FAIL: front speed off the Hugoniot by {mean_dev:.3f} (tolerance {args.hugoniot_tolerance})")
        failed = True
    if failed:
        raise SystemExit(1)
    if args.png:
        csv = os.path.join(out, "shock_front.csv")
        t0 = float(np.mean(r[sel, 0]))
        d0 = float(np.mean(r[sel, 2]))
        gp = (f"set terminal pngcairo size 1200,500; set output '{args.png}'; set datafile separator ',';"
              "set multiplot layout 1,2; set grid; set key top left;"
              "set xlabel 'time [us]'; set ylabel 'front depth below the charge [cm]';"
              f"plot '{csv}' skip 1 using ($1*1e6):($3*100) with linespoints pt 7 title 'simulated front (axis)', "
              f"{d0*100} + 2700e-4*(x - {t0*1e6}) dt 2 title '2700 m/s (slides)', "
              f"{d0*100} + 2450e-4*(x - {t0*1e6}) dt 3 lc rgb 'gray' title '2450 / 2950 m/s', "
              f"{d0*100} + 2950e-4*(x - {t0*1e6}) dt 3 lc rgb 'gray' notitle;"
              "set xlabel 'front depth below the charge [cm]'; set ylabel 'pressure [GPa]'; set key top right;"
              f"plot '{csv}' skip 1 using ($3*100):($4/1e9) with linespoints pt 7 title 'simulated peak pressure', "
              f"{(P0 + RHO0 * 2700 * (2700 - C0) / S)/1e9} dt 2 title 'Hugoniot pressure at 2700 m/s';"
              "unset multiplot")
        try:
            subprocess.run(["gnuplot", "-e", gp], check=True)
            print(f"wrote {args.png}")
        except (OSError, subprocess.CalledProcessError) as e:
            print(f"gnuplot: {e} (the CSV file is written)")


if __name__ == "__main__":
    main()
