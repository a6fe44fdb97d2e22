#!/usr/bin/env python3
"""The coupled verification study of docs/verification-coupled.md: runs mpmice on the three scenes
at three spacings each, writes the profiles as CSV and draws them (gnuplot) into docs/.

Run from the repository:  python3 benchmarks/coupled/coupled_study.py build [scratch-dir]
(the scratch directory, default /tmp/coupled_study, must be new or empty)
Needs h5dump (HDF5 tools) and gnuplot. The asserted figures are those of the ctests
test_coupled_{stokes,shock_slab,piston}; this script draws what they measure.
"""
import math, os, re, subprocess, sys

build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build")
scratch = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "/tmp/coupled_study")
repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
docs = os.path.join(repo, "docs")
mpmice = os.path.join(build, "coupler", "mpmice")
if os.path.exists(scratch) and os.listdir(scratch):
    sys.exit(f"coupled_study.py: {scratch} is not empty; give a new or empty scratch directory")
os.makedirs(scratch, exist_ok=True)


def dump(h5, name):
    out = subprocess.run(["h5dump", "-d", name, "-y", "-w", "0", h5], capture_output=True, text=True, check=True).stdout
    body = out[out.index("DATA {") + 6:out.rindex("}")]
    return [float(x) for x in re.split(r"[,\s]+", body.replace("}", " ")) if x]


def run(scene_text, name):
    d = os.path.join(scratch, name)
    os.makedirs(d, exist_ok=True)
    text = re.sub(r"directory: .*", "directory: " + os.path.join(d, "out"), scene_text)
    path = os.path.join(d, name + ".yaml")
    open(path, "w").write(text)
    r = subprocess.run([mpmice, path], capture_output=True, text=True)
    outdir = os.path.join(d, "out")
    files = sorted(f for f in os.listdir(outdir) if f.endswith(".h5")) if os.path.isdir(outdir) else []
    status = "ok" if r.returncode == 0 else (r.stderr.strip().splitlines() or ["exit %d" % r.returncode])[-1]
    return [os.path.join(outdir, f) for f in files], status


def plot(png, title, xlabel, ylabel, series, extra=""):
    gp = [f"set terminal pngcairo noenhanced size 900,560 font ',11'", f"set output '{png}'", f"set title \"{title}\"",
          f"set xlabel '{xlabel}'", f"set ylabel '{ylabel}'", "set key inside left top box opaque", "set grid", extra]
    parts = []
    for csv, cols, label, style in series:
        parts.append(f"'{csv}' using {cols} with {style} title '{label}'")
    gp.append("plot " + ", ".join(parts))
    subprocess.run(["gnuplot"], input="\n".join(gp), text=True, check=True)


def write(csv, header, rows):
    with open(csv, "w") as f:
        f.write(header + "\n")
        for r in rows:
            f.write(",".join("%.10g" % v for v in r) + "\n")


# ---- Stokes' first problem -------------------------------------------------------------------
base = open(os.path.join(repo, "configs", "stokes_plate.yaml")).read()
mu = float(re.search(r"viscosity: ([0-9.e+-]+)", base).group(1))
t_end = float(re.search(r"end: ([0-9.e+-]+)", base).group(1))
nu = mu / (101325 / (0.4 * 717.5 * 300))
series = []
print("stokes: dx, max |u - exact| / U")
for dx in (0.02, 0.01, 0.005):
    text = base.replace("spacing: 0.005", f"spacing: {dx}").replace("0.005]", f"{dx}]")
    files, status = run(text, f"stokes_{dx}")
    h5 = files[-1]
    uy = dump(h5, "/grid/cell/air_velocity")[1::3]
    rows, err = [], 0
    for i, u in enumerate(uy):
        x = (i + 0.5) * dx
        ex = math.erf((x - 0.1) / (2 * math.sqrt(nu * t_end))) if x > 0.1 else 0.0
        rows.append((x, u, ex))
        if x > 0.1:
            err = max(err, abs(u - ex))
    print(f"  {dx}: {err:.4e} ({status})")
    csv = os.path.join(scratch, f"stokes_{dx}.csv")
    write(csv, "x,u_y,exact", rows)
    series.append((csv, "1:2", f"dx = {dx} (max error {100 * err:.2f} % of U)", "linespoints pt 7 ps 0.5"))
series.append((series[-1][0], "1:3", "exact U erf((x - 0.1) / 2 sqrt(nu t))", "lines lw 2 dt 2 lc rgb 'black'"))
plot(os.path.join(docs, "coupled_stokes.png"), "Stokes' first problem, t = %g ms (nu = %.2f m^2/s, plate surface x = 0.1)" % (1e3 * t_end, nu),
     "x [m]", "u_y / U", series, "set datafile separator ','\nset xrange [0:0.6]")

# ---- Shock on a steel slab -------------------------------------------------------------------
base = open(os.path.join(repo, "configs", "shock_slab.yaml")).read()
series_p, series_s = [], []
print("shock_slab: dx, final pressure profile; stress at t = 0.6 ms")
for dx in (0.005, 0.0025, 0.00125):
    text = base.replace("spacing: 0.0025", f"spacing: {dx}").replace("interval: 5.0e-5", "interval: 0.0")
    files, status = run(text, f"slab_{dx}")
    p = dump(files[-1], "/grid/cell/pressure")
    csv = os.path.join(scratch, f"slab_p_{dx}.csv")
    write(csv, "x,p", [((i + 0.5) * dx, v) for i, v in enumerate(p)])
    series_p.append((csv, "1:($2/1e6)", f"dx = {dx}", "lines"))
    files, status2 = run(text.replace("end: 9.0e-4", "end: 6.0e-4"), f"slab_early_{dx}")
    xs = dump(files[-1], "/particles/position")[0::3]
    sxx = dump(files[-1], "/particles/stress")[0::6]
    csv = os.path.join(scratch, f"slab_s_{dx}.csv")
    write(csv, "x,sigma_xx", sorted(zip(xs, sxx)))
    series_s.append((csv, "1:($2/1e6)", f"dx = {dx}", "lines"))
    print(f"  {dx}: {status}, {status2}")
g = 1.4
p1, p2, r2, u2 = 101325.0, 455962.5, 3.138211382, 433.9858869
A, B = 2 / ((g + 1) * r2), (g - 1) / (g + 1) * p2
lo, hi = p2, 1e3 * p2
for _ in range(200):
    m = 0.5 * (lo + hi)
    if (m - p2) * math.sqrt(A / (m + B)) < u2:
        lo = m
    else:
        hi = m
p5 = lo
rr = p5 / p2
r5 = r2 * ((g + 1) * rr + (g - 1)) / ((g - 1) * rr + (g + 1))
Wr = r2 * u2 / (r5 - r2)
W = r2 * u2 / (r2 - p1 / (0.4 * 717.5 * 300))
thit = 0.4 / W
xr = 0.7 - Wr * (9e-4 - thit)
csv = os.path.join(scratch, "slab_p_exact.csv")
write(csv, "x,p", [(0, p2), (xr, p2), (xr, p5), (0.7, p5)])
series_p.append((csv, "1:($2/1e6)", "exact (rigid-wall reflection)", "lines lw 2 dt 2 lc rgb 'black'"))
plot(os.path.join(docs, "coupled_shock_slab_pressure.png"), "Mach 2 shock reflected from a steel slab (x = 0.7), t = 0.9 ms",
     "x [m]", "p [MPa]", series_p, "set datafile separator ','\nset xrange [0.3:0.72]")
c = math.sqrt((160e9 + 4 * 79e9 / 3) / 7850)
xf = 0.7 + c * (6e-4 - thit)
csv = os.path.join(scratch, "slab_s_exact.csv")
write(csv, "x,sigma_xx", [(0.7, -(p5 - p1)), (xf, -(p5 - p1)), (xf, 0), (1.0, 0)])
series_s.append((csv, "1:($2/1e6)", "front at sqrt((K + 4G/3) / rho) = %.0f m/s" % c, "lines lw 2 dt 2 lc rgb 'black'"))
plot(os.path.join(docs, "coupled_shock_slab_stress.png"), "Stress wave in the steel slab, t = 0.6 ms (24 us after the hit)",
     "x [m]", "sigma_xx [MPa]", series_s, "set datafile separator ','\nset xrange [0.7:1.0]")
print(f"  exact p5 = {p5:.6g} Pa, c_L = {c:.5g} m/s")

# ---- The adiabatic piston --------------------------------------------------------------------
series = []
print("piston: cells, status, largest |p / p_exact - 1|")
for n in (25, 50, 100):
    text = subprocess.run([sys.executable, os.path.join(repo, "benchmarks", "coupled", "piston_scene.py"), str(n)],
                          capture_output=True, text=True, check=True).stdout
    text = text.replace("interval: 0.001", "interval: 0.0005")
    files, status = run(text, f"piston_{n}")
    rows, worst = [], 0
    dx = 1.0 / n
    for h5 in files[1:]:
        xs = dump(h5, "/particles/position")[0::3]
        s = sum(xs) / len(xs) - 0.4
        p = dump(h5, "/grid/cell/pressure")
        th = dump(h5, "/grid/cell/air_volume_fraction")
        cells = [i for i in range(n) if (i + 0.5) * dx > 0.6 + s and th[i] > 0.999]
        pm = sum(p[i] for i in cells) / len(cells)
        rows.append((s, pm))
    # against the gas height h = h0 - s (measured): the adiabat itself, whatever the piston's speed
    csv = os.path.join(scratch, f"piston_{n}.csv")
    write(csv, "s,p", rows)
    for s, pm in rows:
        worst = max(worst, abs(pm / (101325 * (0.4 / (0.4 - s)) ** g) - 1))
    print(f"  {n}: {status}; largest |p / p0 (h0 / h)^gamma - 1| = {worst:.4f} over {len(rows)} outputs")
    series.append((csv, "(0.4-$1):($2/1e3)", f"{n} cells" + ("" if status == "ok" else " (stopped)"), "linespoints pt 7 ps 0.6"))
csv = os.path.join(scratch, "piston_exact.csv")
write(csv, "s,p", [(0.2 * k / 100, 101325 * (0.4 / (0.4 - 0.2 * k / 100)) ** g) for k in range(101)])
series.append((csv, "(0.4-$1):($2/1e3)", "adiabat p0 (h0 / h)^gamma", "lines lw 2 dt 2 lc rgb 'black'"))
plot(os.path.join(docs, "coupled_piston.png"), "Adiabatic piston: trapped-gas pressure against its height h",
     "h [m]", "p [kPa]", series, "set datafile separator ','\nset xrange [0.2:0.4]\nset key right top")
