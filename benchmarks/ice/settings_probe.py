#!/usr/bin/env python3
"""Runs an ICE scene over a grid of settings and prints which runs complete and which stop.

For each mesh (cells per direction), advection (first order or second order with a limiter),
pressure solver and CFL number the scene is written to a scratch directory with those keys set
and run with ice_solver; the line printed is the setting, the exit status and the program's
last 'done' or error line. A robustness probe, not a test: every run should complete or stop with
a message naming what, where and when.

  python3 benchmarks/ice/settings_probe.py build/ice_solver/ice_solver benchmarks/ice/blast_three_fluids.yaml \\
      --cells 48x40,96x80 --cfl 0.2,0.4,0.7
"""
import argparse
import os
import subprocess
import tempfile

import yaml


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ice_solver")
    ap.add_argument("scene")
    ap.add_argument("--cells", default="", help="meshes, e.g. 48x40,96x80 (default: the scene's)")
    ap.add_argument("--cfl", default="0.2,0.4,0.7")
    ap.add_argument("--advection", default="superbee,minmod,van_leer,first_order",
                    help="limiters of second order, or first_order")
    ap.add_argument("--pressure", default="explicit,semi_implicit")
    a = ap.parse_args()
    with open(a.scene) as f:
        base = yaml.safe_load(f)
    meshes = [[int(n) for n in c.split("x")] for c in a.cells.split(",") if c] or [base["mesh"]["cells"]]
    work = tempfile.mkdtemp(prefix="settings_probe_")
    total = stopped = 0
    for cells in meshes:
        for adv in a.advection.split(","):
            for ps in a.pressure.split(","):
                for cfl in a.cfl.split(","):
                    s = yaml.safe_load(yaml.safe_dump(base))
                    s["mesh"]["cells"] = cells
                    s["time"]["cfl"] = float(cfl)
                    ice = dict(s.get("ice") or {})
                    ice.pop("limiter", None)
                    ice.pop("advection", None)
                    if adv == "first_order":
                        ice["advection"] = "first_order"
                    else:
                        ice["limiter"] = adv
                    ice["pressure_solver"] = ps
                    s["ice"] = ice
                    s["output"] = {"enabled": False}
                    path = os.path.join(work, "s.yaml")
                    with open(path, "w") as f:
                        yaml.safe_dump(s, f, sort_keys=False)
                    r = subprocess.run([a.ice_solver, path], cwd=work, capture_output=True, text=True, timeout=1800)
                    lines = [l for l in (r.stdout + r.stderr).splitlines() if l.startswith("done") or "error" in l]
                    total += 1
                    stopped += r.returncode != 0
                    print(f"{'x'.join(map(str, cells)):>8} {adv:>12} {ps:>13} cfl {cfl}: exit {r.returncode}  "
                          f"{lines[0][:150] if lines else ''}", flush=True)
    print(f"{total - stopped} of {total} completed, {stopped} stopped")


if __name__ == "__main__":
    main()
