#!/usr/bin/env python3
"""Reads the stability map's two study CSVs (build/study/study on configs/studies/stability_*.yaml),
writes docs/stability_{piston,slab}.csv (the study's rows, plus the density ratio, `stable` and a
short stop reason) and draws the maps with gnuplot: docs/stability_ofat.png (one factor at a time),
docs/stability_density_schedule.png and docs/stability_exchange_cfl.png (the slices).
Usage: stability_map.py STUDY_DIR_PISTON STUDY_DIR_SLAB DOCS_DIR (scripts/stability_map.sh)."""
import csv
import math
import os
import subprocess
import sys

AIR = 101325.0 / (0.4 * 717.5 * 300.0)
SOLID = {"piston": "copper", "slab": "steel"}
SCHED_ORDER = ["monolithic", "explicit_serial", "explicit_parallel",
               "implicit_serial/none", "implicit_serial/constant", "implicit_serial/aitken", "implicit_serial/iqn_ils",
               "implicit_parallel/none", "implicit_parallel/constant", "implicit_parallel/aitken",
               "implicit_parallel/iqn_ils"]


def stop_reason(row):
    """A short name for why a point did not finish (empty when it did)."""
    st, note = row["status"], row["note"]
    if st in ("ok", "no_error"):
        return ""
    if st == "timeout":
        return "time limit"
    n = note.lower()
    for key, name in (("non-physical state", "health check"), ("equilibrium pressure", "equilibrium pressure"),
                      ("dt_min", "time step collapse"), ("dt_collapse_fraction", "time step collapse"),
                      ("coupling.max_iterations", "coupling iterations"),
                      ("converge", "no convergence")):
        if key in n:
            return name
    return "error"


def schedule_of(row):
    s, a = row["coupling.schedule"], row["coupling.acceleration.type"]
    return s if s in ("monolithic", "explicit_serial", "explicit_parallel") else f"{s}/{a}"


def error_line(study_dir, r):
    """The run's own error message: the first line of its log naming an error or a stop (the study's
    `note` is the log's last line, which after an MPI abort is Open MPI's banner)."""
    path = os.path.join(study_dir, r["run"], "run.log")
    if r["status"] in ("ok", "no_error") or not os.path.exists(path):
        return r["note"]
    with open(path, errors="replace") as fh:
        for line in fh:
            if line.startswith("mpmice: "):  # the program's own stop message
                return line.strip()
    return r["note"]


def load(study_dir, name):
    path = os.path.join(study_dir, f"stability_{name}.csv")
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    solid = SOLID[name]
    for r in rows:
        r["note"] = error_line(study_dir, r)
        r["density_ratio"] = f"{float(r[f'materials[{solid}].density']) / AIR:.4g}"
        r["stable"] = "yes" if r["status"] in ("ok", "no_error") else "no"
        r["stop"] = stop_reason(r)
        r["schedule_label"] = schedule_of(r)
    return rows


def write_csv(rows, out):
    keys = list(rows[0].keys())
    with open(out, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


def err_value(r):
    """log10 of the error; points that stopped get no error."""
    try:
        e = float(r["error"])
        return math.log10(max(e, 1e-6)) if math.isfinite(e) else None
    except ValueError:
        return None


def ofat_label(r, base):
    diff = []
    if r["density_ratio"] != base["density_ratio"]:
        diff.append(f"ratio {r['density_ratio']}")
    for k, short in (("ice.exchange.momentum", "K"), ("time.cfl", "CFL"), ("ice.advection", ""), ("ice.limiter", ""),
                     ("ice.pressure_solver", "")):
        if r[k] != base[k]:
            diff.append(f"{short} {r[k]}".strip())
    if r["schedule_label"] != base["schedule_label"]:
        diff.append(r["schedule_label"])
    return ", ".join(diff) if diff else "base"


def one_factor(rows):
    base = rows[0]
    out, seen = [], set()
    for r in rows:
        changed = sum([r["density_ratio"] != base["density_ratio"], r["ice.exchange.momentum"] != base["ice.exchange.momentum"],
                       r["time.cfl"] != base["time.cfl"],
                       (r["ice.advection"], r["ice.limiter"], r["ice.pressure_solver"]) !=
                       (base["ice.advection"], base["ice.limiter"], base["ice.pressure_solver"]),
                       r["schedule_label"] != base["schedule_label"]])
        lab = ofat_label(r, base)
        if changed <= 1 and lab not in seen:
            seen.add(lab)
            out.append((lab, r))
    return out


def main():
    pist_dir, slab_dir, docs = sys.argv[1:4]
    data = {"piston": load(pist_dir, "piston"), "slab": load(slab_dir, "slab")}
    tmp = os.path.join(os.path.dirname(os.path.abspath(pist_dir)), "stability_plot")  # beside the studies
    os.makedirs(tmp, exist_ok=True)
    for name, rows in data.items():
        write_csv(rows, os.path.join(docs, f"stability_{name}.csv"))
    gp = ['set terminal pngcairo noenhanced size 1400,900 font "sans,10"', 'set key below']
    # 1. one factor at a time: log10 error per point, stopped points as red crosses at the top.
    gp += ['set output "%s"' % os.path.join(docs, "stability_ofat.png"), "set multiplot layout 2,1",
           "set ylabel 'log10 |error|'", "set yrange [-4.5:1.5]", "set xtics rotate by 60 right font ',8'",
           "set grid ytics"]
    for name, rows in data.items():
        pts = one_factor(rows)
        dat = os.path.join(tmp, f"ofat_{name}.dat")
        with open(dat, "w") as fh:
            for i, (lab, r) in enumerate(pts):
                e = err_value(r)
                fh.write(f'{i} "{lab}" {e if e is not None else "NaN"} {1.0 if r["stable"] == "no" else "NaN"}\n')
        title = "adiabatic piston (error: final pressure)" if name == "piston" else "shock on a slab (error: reflected pressure)"
        gp += [f"set title 'One factor at a time around the shipped settings: {title}'",
               f"plot '{dat}' using 1:3:xtic(2) with points pt 7 ps 1.5 lc rgb '#1060c0' title 'ran to the end: log10 error', "
               f"'' using 1:4 with points pt 2 ps 2.5 lw 2 lc rgb '#d02020' title 'stopped (health check / no convergence / time limit)'"]
    gp += ["unset multiplot", "set xtics norotate font ',10'"]

    # 2./3. slices as maps: colour = log10 error, red cross = stopped.
    def slice_plot(fname, xkey, ylabels, pick, xlabel, title, ylabel=""):
        out = ['set output "%s"' % os.path.join(docs, fname), "set multiplot layout 1,2", f"set ylabel '{ylabel}'",
               "set palette defined (-4 '#1a9850', -2 '#fee08b', 0 '#d73027')", "set cbrange [-4:0]",
               "set cblabel 'log10 |error|'", f"set xlabel '{xlabel}'", "unset grid"]
        for name, rows in data.items():
            sel = [r for r in rows if pick(r)]
            xs = sorted({float(xkey(r)) for r in sel})
            dat = os.path.join(tmp, f"{fname}_{name}.dat")
            with open(dat, "w") as fh:
                for r in sel:
                    xi = xs.index(float(xkey(r)))
                    yi = ylabels.index(r["_y"])
                    e = err_value(r)
                    fh.write(f'{xi} {yi} {e if e is not None else "NaN"} {1 if r["stable"] == "no" else "NaN"}\n')
            xt = ", ".join(f'"{x:g}" {i}' for i, x in enumerate(xs))
            yt = ", ".join(f'"{y}" {i}' for i, y in enumerate(ylabels))
            out += [f"set title '{title}: {name}'", f"set xtics ({xt})", f"set ytics ({yt})",
                    f"set xrange [-0.5:{len(xs) - 0.5}]", f"set yrange [-0.5:{len(ylabels) - 0.5}]",
                    f"plot '{dat}' using 1:2:3 with points pt 5 ps 5 lc palette notitle, "
                    f"'' using 1:($4*$2) with points pt 2 ps 4 lw 3 lc rgb '#000000' title 'stopped'"]
        out += ["unset multiplot"]
        return out

    for rows in data.values():
        for r in rows:
            r["_y"] = r["schedule_label"]
    sched_y = ["monolithic", "explicit_serial", "implicit_serial/iqn_ils"]
    others = ("ice.exchange.momentum", "time.cfl", "ice.advection", "ice.limiter", "ice.pressure_solver")
    base_of = {id(r): rows[0] for rows in data.values() for r in rows}

    def dens_pick(r):  # the shipped K, CFL and ICE settings, any density ratio, three schedules
        b = base_of[id(r)]
        return all(r[k] == b[k] for k in others) and r["_y"] in sched_y

    gp_slices = slice_plot("stability_density_schedule.png", lambda r: r["density_ratio"], sched_y, dens_pick,
                           "solid / gas density ratio", "density ratio x schedule, shipped ICE settings")
    for rows in data.values():
        for r in rows:
            r["_y"] = r["time.cfl"]
    cfl_y = ["0.1", "0.4", "0.7", "1"]

    def kc_pick(r):  # the shipped density, ICE settings and schedule, any K and CFL
        b = base_of[id(r)]
        return (all(r[k] == b[k] for k in ("density_ratio", "ice.advection", "ice.limiter", "ice.pressure_solver",
                                            "schedule_label")) and r["_y"] in cfl_y)

    gp_slices += slice_plot("stability_exchange_cfl.png", lambda r: r["ice.exchange.momentum"], cfl_y, kc_pick,
                            "momentum exchange K", "exchange K x CFL, monolithic-style", "CFL")
    gp_slices = [l.replace("set ylabel 'log10 |error|'", "") for l in gp_slices]
    with open(os.path.join(tmp, "stability.gp"), "w") as fh:
        fh.write("\n".join(gp + ["unset ylabel", "unset yrange"] + gp_slices) + "\n")
    subprocess.run(["gnuplot", os.path.join(tmp, "stability.gp")], check=True)
    for name, rows in data.items():
        bad = [r for r in rows if r["stable"] == "no"]
        print(f"{name}: {len(rows)} points, {len(rows) - len(bad)} ran to the end, {len(bad)} stopped")


if __name__ == "__main__":
    main()
