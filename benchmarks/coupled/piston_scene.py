#!/usr/bin/env python3
"""Writes the adiabatic piston scene (configs/piston.yaml) at N cells: python3 piston_scene.py N [t_end].

The gas starts in the quasi-static state of a piston moving at v: uniform pressure, velocity
linear from 0 at each wall to v at the piston (one gas region on each side with a linear velocity
profile, `velocity_gradient`: every mesh samples the same field at its cell centres), so the run
starts without an acoustic transient (homogeneous compression is an exact solution of Euler's
equations for a piston at constant speed). The scene is the same for every N but `mesh.cells`:
a study may vary `mesh.cells` or `mesh.spacing` on configs/piston.yaml directly.
"""
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 50
t_end = float(sys.argv[2]) if len(sys.argv) > 2 else 0.02
L, xl, xr, v = 1.0, 0.2, 0.6, 10.0
dx = L / n
if abs(xl / dx - round(xl / dx)) > 1e-9 or abs(xr / dx - round(xr / dx)) > 1e-9:
    sys.exit(f"piston_scene.py: N = {n} does not put the piston's faces (x = {xl}, {xr}) on cell faces")

print(f"""# The adiabatic piston (Uintah's pistonVal problem), MPM-ICE in 1D.
#
# A copper piston (rho = 8900 kg/m^3, K = 140 GPa, G = 48 GPa; MPM particles) on 0.2 <= x <= 0.6
# moves at v = 10 m/s into air (gamma 1.4, 101325 Pa, 300 K) trapped between it and the slip
# wall at x = 1 (h0 = 0.4 m), and away from the air on 0 <= x <= 0.2 (h_L0 = 0.2 m) behind it.
# The gas starts in the quasi-static state: uniform pressure, velocity linear from 0 at each wall
# to v at the piston (a linear velocity profile in each gas region, sampled at the cell centres of
# any mesh; this file is written by `python3 benchmarks/coupled/piston_scene.py {n}`), so no
# acoustic transient is launched.
# The piston is free (no prescribed motion in MPM): it decelerates under the pressure difference,
# so the exact answer is the quasi-static one with the piston's own dynamics,
#   h' = -v,  M v' = -(p(h) - p_L(h)),  p = p0 (h0 / h)^gamma,  p_L = p0 (h_L0 / (h_L0 + h0 - h))^gamma,
# M = 8900 x 0.4 kg/m^2 (for a constant v, p = p0 (h0 / (h0 - v t))^gamma). At t = 20 ms:
# displacement 0.19639 m, v = 9.443 m/s, p = 260.78 kPa, p_L = 38.89 kPa.
# Measured (docs/verification-coupled.md, tests/verification/coupled/test_piston.cpp), with
# MPM's face transport of the piston's volume (coupling.solid_transport: mpm), to 20 ms: the
# trapped gas's pressure within 0.15 % of p(t) at 50 cells (the shipped scene), 0.53 % at 25,
# 0.04 % at 100, 0.01 % at 200 (order 2.06), the same at any time.cfl from 0.05 to 0.7 (issue 12:
# the face velocity beside the gas the copper holds, src/ice/face/face_phase.cpp; at 100 and 200
# cells below CFL 0.4 since the copper's own-cell mean-stress correction, src/mpm/cell/
# node_cell_operators.cpp: those runs stopped before); the displacement within 0.1 %. With ICE's face fluxes (solid_transport: ice) 4.0-4.3, 4.9 and 7.4 %
# at 25, 50, 100 cells (measured before that fix).
#
# Check it:  coupler check configs/piston.yaml
# Run it:    mpmice configs/piston.yaml
scene: piston
description: "Adiabatic piston: copper at 10 m/s into trapped air (h0 = 0.4 m), free piston"

mesh:
  dim: 1
  lower: [0.0]
  upper: [1.0]
  spacing: {dx:.10g}   # {n} cells

time:
  end: {t_end}
  cfl: 0.4

materials:
  - name: air
    kind: fluid
    eos: {{type: ideal_gas, gamma: 1.4}}
    specific_heat: 717.5
  - name: copper
    kind: solid
    density: 8900
    model: {{type: linear_elastic, bulk_modulus: 140.0e9, shear_modulus: 48.0e9}}

geometry:
  # the gas at rest at each wall, moving with the piston at its faces: u = v x / h_L0 behind it,
  # u = v (1 - x) / h0 ahead of it
  - name: gas_behind
    shape: {{type: box, lo: [0.0], hi: [{xl}]}}
    material: air
    velocity: [0.0]
    velocity_gradient: [[{v / xl:.10g}]]
    pressure: 101325
    temperature: 300
  - name: gas_ahead
    shape: {{type: box, lo: [{xr}], hi: [{L}]}}
    material: air
    velocity: [{v}]
    velocity_origin: [{xr}]
    velocity_gradient: [[{-v / (L - xr):.10g}]]
    pressure: 101325
    temperature: 300""")
print(f"""  - name: piston
    shape: {{type: box, lo: [{xl}], hi: [{xr}]}}
    material: copper
    velocity: [{v}]
    temperature: 300
    particles_per_cell: 2

boundary:
  x-: slip_wall
  x+: slip_wall

mpm:
  shape_function: gimp    # linear + USL is unstable where a particle enters a cell (docs/verification-coupled.md)
  update: usl

ice:
  advection: second_order
  exchange: {{momentum: 1.0e15, heat: 0}}

coupling:
  schedule: monolithic
  solid_transport: mpm   # MPM's face transport of the piston's volume (docs/verification-coupled.md)

output:
  directory: output/piston
  interval: 0.001""")
