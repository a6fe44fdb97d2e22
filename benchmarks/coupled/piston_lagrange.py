#!/usr/bin/python3
"""The adiabatic piston against a Lagrangian solution of its gas (docs/stability.md, "The density-ratio-10
point"). Runs configs/piston.yaml at N cells, a CFL and a solid density (moduli given, so the wave speed
can stay the shipped one) with the mpmice given, outputs every ms to OUTROOT/TAG, and compares the
trapped gas's mean pure-cell pressure (cells ahead of the piston, gas fraction > 0.999, as the study's
`piston` reference measures) with
  (a) the quasi-static answer without the gas's inertia (RK4 of M v' = -(p - p_L));
  (b) a Lagrangian solution of both gas columns (isentropic: the flow is smooth, p = p0 (rho/rho0)^gamma;
      2000 zones ahead, 1000 behind, leapfrog, the piston a rigid node of mass M; converged to 1e-6 in
      p at 20 ms), its pressure averaged over the same cell centres.
  /usr/bin/python3 benchmarks/coupled/piston_lagrange.py TAG N CFL RHO BULK SHEAR MPMICE [v]
  e.g. ... r10 25 0.4 11.7683 1.85119e8 6.34694e7 build/coupler/mpmice v   (v: every millisecond)
OUTROOT: the environment's PISTON_OUT, default /tmp/piston_lagrange."""
import sys, os, glob, subprocess, re, numpy as np, h5py
P0, G, RHO0 = 101325.0, 1.4, 101325.0/(0.4*717.5*300)
XLO, XHI = 0.2, 0.6

def quasi(M, t, n=20000):
    pR = lambda s: P0*(0.4/(0.4-s))**G; pL = lambda s: P0*(0.2/(0.2+s))**G
    acc = lambda s: -(pR(s)-pL(s))/M
    s, v = 0.0, 10.0; h = t/n
    for _ in range(n):
        k1s, k1v = v, acc(s); k2s, k2v = v+.5*h*k1v, acc(s+.5*h*k1s)
        k3s, k3v = v+.5*h*k2v, acc(s+.5*h*k2s); k4s, k4v = v+h*k3v, acc(s+h*k3s)
        s += h/6*(k1s+2*k2s+2*k3s+k4s); v += h/6*(k1v+2*k2v+2*k3v+k4v)
    return s, v, pR(s)

def lagrange(M, times, nz=2000):
    """Barotropic (isentropic) Lagrangian gas on [0,XLO] and [XHI,1], rigid piston node of mass M/area."""
    nl, nr = nz//2, nz
    xl = np.linspace(0, XLO, nl+1); xr = np.linspace(XHI, 1, nr+1)
    ul = 10*xl/XLO; ur = 10*(1-xr)/0.4
    ml = RHO0*np.diff(xl); mr = RHO0*np.diff(xr)
    dx = min(np.diff(xl).min(), np.diff(xr).min()); dt = 0.1*dx/347.0
    # nodal masses
    def pres(x, m): return P0*((m/np.diff(x))/RHO0)**G
    out = {}; t = 0.0; ti = 0
    # leapfrog: velocities at half steps; start with half kick
    def accel(xl, xr):
        pl, pr = pres(xl, ml), pres(xr, mr)
        al = np.zeros_like(xl); ar = np.zeros_like(xr)
        mnl = np.zeros_like(xl); mnl[:-1] += ml/2; mnl[1:] += ml/2
        mnr = np.zeros_like(xr); mnr[:-1] += mr/2; mnr[1:] += mr/2
        al[1:-1] = -(pl[1:]-pl[:-1])/mnl[1:-1]; ar[1:-1] = -(pr[1:]-pr[:-1])/mnr[1:-1]
        mp = M + mnl[-1] + mnr[0]
        a = (pl[-1]-pr[0])/mp
        al[-1] = a; ar[0] = a
        return al, ar, pl, pr
    al, ar, pl, pr = accel(xl, xr)
    ul = ul + 0.5*dt*al; ur = ur + 0.5*dt*ar
    times = sorted(times)
    while ti < len(times):
        xl = xl + dt*ul; xr = xr + dt*ur; t += dt
        al, ar, pl, pr = accel(xl, xr)
        while ti < len(times) and t >= times[ti]-1e-15:
            out[times[ti]] = (xr.copy(), pr.copy(), xr[0]-XHI); ti += 1
        ul = ul + dt*al; ur = ur + dt*ar
    return out

def run(tag, N, cfl, rho, K, Gm, binary, extra=None):
    d = os.path.join(os.environ.get('PISTON_OUT', '/tmp/piston_lagrange'), tag); os.makedirs(d, exist_ok=True)
    src = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), '../../configs/piston.yaml')).read()
    src = src.replace('spacing: 0.02', f'spacing: {1.0/N}').replace('cfl: 0.4', f'cfl: {cfl}')
    src = src.replace('density: 8900', f'density: {rho}').replace('bulk_modulus: 140.0e9', f'bulk_modulus: {K}').replace('shear_modulus: 48.0e9', f'shear_modulus: {Gm}')
    src = src.replace('directory: output/piston', f'directory: {d}/out')
    for k, v in (extra or {}).items(): src = src.replace(k, v)
    open(f'{d}/s.yaml', 'w').write(src)
    for f in glob.glob(f'{d}/out/*.h5'): os.remove(f)
    r = subprocess.run([binary, f'{d}/s.yaml'], capture_output=True, text=True)
    res = []
    for f in sorted(glob.glob(f'{d}/out/piston_*.h5')):
        h = h5py.File(f); t = float(h.attrs['time'][0])
        n = int(h.attrs['cells'][0]); dx = float(h.attrs['spacing'][0])
        p = h['grid/cell/pressure'][0, 0, :]; th = h['grid/cell/air_volume_fraction'][0, 0, :]
        xp = h['particles/position'][:, 0]; mp = h['particles/mass'][:]
        res.append((t, p, th, (xp*mp).sum()/mp.sum(), dx))
    s0 = res[0][3]
    rows = []
    for t, p, th, mx, dx in res[1:]:
        s = mx - s0; xc = (np.arange(len(p))+0.5)*dx
        sel = (xc > XHI + s) & (th > 0.999)
        rows.append((t, p[sel].mean(), s, xc[sel]))
    return rows, r.returncode, r.stdout[-300:] + r.stderr[-500:]

if __name__ == '__main__':
    tag, N, cfl, rho, K, Gm, binary = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5], sys.argv[6], sys.argv[7]
    M = rho*0.4
    rows, rc, tail = run(tag, N, cfl, rho, K, Gm, binary)
    if rc != 0: print('RC', rc, tail)
    lag = lagrange(M, [r[0] for r in rows])
    eq, el, es = [], [], []
    for t, pm, s, xc in rows:
        sq, vq, pq = quasi(M, t, 2000)
        xr, pr, sl = lag[t]
        zc = 0.5*(xr[1:]+xr[:-1]); pl = np.interp(xc, zc, pr).mean()
        eq.append(pm/pq-1); el.append(pm/pl-1); es.append((pq/pl-1))
    print(f'{tag}: N={N} cfl={cfl} rho={rho}: t_end={rows[-1][0]:.4f} quasi-static ref: max {100*max(map(abs,eq)):.3f} % final {100*abs(eq[-1]):.3f} % | Lagrangian ref: max {100*max(map(abs,el)):.3f} % final {100*abs(el[-1]):.3f} % | quasi vs Lagrange: max {100*max(map(abs,es)):.3f} % final {100*abs(es[-1]):.3f} %')
    if len(sys.argv) > 8:
        for (t, pm, s, xc), a, b in zip(rows, eq, el): print(f'  t={t:.4f} p={pm:.1f} s={s:.5f} errQ={100*a:+.3f}% errL={100*b:+.3f}%')
