#!/usr/bin/env python3
"""Writes the stability map's two study files (configs/studies/stability_{piston,slab}.yaml):
one-factor-at-a-time around each scene's shipped settings plus two slices, every point giving
every swept key (so the CSV's columns are complete). docs/stability.md explains the design.
Run: python3 benchmarks/coupled/stability_points.py  (rewrites the two files)."""
import os

AIR = 101325.0 / (0.4 * 717.5 * 300.0)  # the scenes' quiet air: p / (R T), R = (gamma - 1) cv
RATIOS = [1, 10, 100, 1e3, 1e4, 1e5]
KS = [0, 1e3, 1e6, 1e9, 1e12, 1e15]
SCHEDULES = [("explicit_serial", "none"), ("explicit_parallel", "none")] + [
    (s, a) for s in ("implicit_serial", "implicit_parallel") for a in ("none", "constant", "aitken", "iqn_ils")]

SCENES = {
    "piston": dict(scene="../piston.yaml", reference="piston", solid="copper", rho=8900.0, K=140.0e9, G=48.0e9,
                   title="the adiabatic piston (configs/piston.yaml, 25 cells)", set={}),
    "slab": dict(scene="../shock_slab.yaml", reference="shock_slab", solid="steel", rho=7850.0, K=160.0e9, G=79.0e9,
                 title="the shock on a steel slab (configs/shock_slab.yaml at dx = 0.008, 125 cells)",
                 set={"mesh.spacing": 0.008}),
}


def g(x):
    return f"{x:.6g}"


def write(name, c):
    base = dict(ratio=None, K=1e15, cfl=0.4, advection="second_order", limiter="van_leer", pressure="explicit",
                schedule="monolithic", acc="none")
    pts = []

    def add(group, **kw):
        p = dict(base, **kw)
        if all(p != q for _, q in pts):  # a slice point the factors already ran is not run twice
            pts.append((group, p))

    add("base")
    for r in RATIOS:
        add("density", ratio=r)
    for k in KS[:-1]:
        add("exchange", K=k)
    for f in (0.1, 0.2, 0.7, 1.0):
        add("cfl", cfl=f)
    add("ice", advection="first_order")
    add("ice", limiter="minmod")
    add("ice", limiter="superbee")
    add("ice", pressure="semi_implicit")
    for s, a in SCHEDULES:
        add("schedule", schedule=s, acc=a)
    for r in RATIOS:
        for s, a in (("explicit_serial", "none"), ("implicit_serial", "iqn_ils")):
            add("density x schedule", ratio=r, schedule=s, acc=a)
    for k in KS:
        for f in (0.1, 0.7, 1.0):
            add("exchange x cfl", K=k, cfl=f)
    solid = c["solid"]
    lines = [
        f"# The stability map on {c['title']} (docs/stability.md). Written by",
        "# benchmarks/coupled/stability_points.py: one factor at a time around the shipped settings, then the",
        "# slices density ratio x schedule and exchange K x CFL. The density ratio is the solid's density over",
        f"# the quiet air's ({AIR:.4f} kg/m^3); the solid's moduli scale with its density, so its wave speed and the",
        "# time step stay those of the shipped scene. time.dt_min stops a collapsing step instead of a spin.",
        f"#   build/study/study configs/studies/stability_{name}.yaml --out studies/stability_{name}",
        "# (or scripts/stability_map.sh: both studies, the maps and the CSVs in docs/).",
        f"study: stability_{name}",
        f"scene: {c['scene']}",
        "program: mpmice",
        f"reference: {c['reference']}",
        "time_limit: 300",
        "repeats: 1",
        "set:",
        "  output.interval: 0",
        "  time.dt_min: 1.0e-9",
    ]
    for k, v in c["set"].items():
        lines.append(f"  {k}: {v}")
    lines.append("points:")
    last = None
    for group, p in pts:
        if group != last:
            lines.append(f"  # {group}")
            last = group
        rho = c["rho"] if p["ratio"] is None else AIR * p["ratio"]
        f = rho / c["rho"]
        kv = [(f"materials[{solid}].density", g(rho)), (f"materials[{solid}].model.bulk_modulus", g(c["K"] * f)),
              (f"materials[{solid}].model.shear_modulus", g(c["G"] * f)), ("ice.exchange.momentum", g(p["K"])),
              ("time.cfl", g(p["cfl"])), ("ice.advection", p["advection"]), ("ice.limiter", p["limiter"]),
              ("ice.pressure_solver", p["pressure"]), ("coupling.schedule", p["schedule"]),
              ("coupling.acceleration.type", p["acc"])]
        lines += [f"  {'-' if i == 0 else ' '} {k}: {v}" for i, (k, v) in enumerate(kv)]
    out = os.path.join(os.path.dirname(__file__), "..", "..", "configs", "studies", f"stability_{name}.yaml")
    with open(out, "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print(f"{out}: {len(pts)} points")


for n, c in SCENES.items():
    write(n, c)
