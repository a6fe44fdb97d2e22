#!/usr/bin/env python3
"""Linear stability of ICE's explicit step for sound waves (the bound kMaxAcousticCourant).

The step, linearised about a uniform state at rest (density rho, sound speed c), without the
Riemann terms (they act only at faces in compression; a rarefaction has none), in units where the
pressure is p / (rho c) and the velocity is in units of c, nu_d = c dt / dx_d:

  face velocity   U_f = (u_L + u_R) / 2 - nu (p_R - p_L)            (phase 3, per direction)
  pressure        p*  = p - sum_d nu_d (U_f,hi - U_f,lo)            (phase 5, explicit increment)
  cell momentum   u'  = u - nu_d (p*_f,hi - p*_f,lo), p*_f the mean of the two cells' p*  (phases 6-9)
  next pressure   p'  = p*                                          (the next step's equilibrium)

For each Fourier mode the step is a matrix on (u_1 .. u_dim, p); the script prints the largest
modulus of its eigenvalues over the modes (> 1: the mode grows). 1D: stable up to nu = 1 / sqrt(2);
2D: up to sum_d nu_d^2 = 1 / 2, so sum_d nu_d <= 0.7 is stable in every dimension (ICE's bound).

  python3 benchmarks/ice/acoustic_stability.py          (about 5 s)
"""
import math

import numpy as np


def amplification(nus, thetas):
    """Largest |eigenvalue| of the step's matrix for the mode with phase angles thetas per direction."""
    dim = len(nus)
    n = dim + 1  # u_1 .. u_dim, p
    E = [np.exp(1j * t) for t in thetas]
    # p* = p - sum_d nu_d div_d(U): rows of the map (u, p) -> p*
    ps = np.zeros(n, dtype=complex)
    ps[dim] = 1.0
    for d in range(dim):
        mean_div = (E[d] - 1 / E[d]) / 2            # (U_hi - U_lo) from the cell velocities' means
        lap = E[d] - 2 + 1 / E[d]                    # (U_hi - U_lo) from -nu (p_R - p_L): -nu * lap
        ps[d] += -nus[d] * mean_div
        ps[dim] += -nus[d] * (-nus[d] * lap)
    M = np.zeros((n, n), dtype=complex)
    for d in range(dim):
        M[d, d] = 1.0
        M[d, :] += -nus[d] * (E[d] - 1 / E[d]) / 2 * ps  # mean face pressures' difference of p*
    M[dim, :] = ps
    return max(abs(np.linalg.eigvals(M)))


def worst(nus, samples):
    grid = np.linspace(0, math.pi, samples)
    if len(nus) == 1:
        return max(amplification(nus, (t,)) for t in grid)
    return max(amplification(nus, (a, b)) for a in grid for b in grid)


def main():
    print("1D: nu = c dt / dx, largest |g| over the modes")
    for nu in (0.5, 0.6, 0.7, 1 / math.sqrt(2), 0.72, 0.75, 0.8, 0.9, 1.0):
        print(f"  nu {nu:.4f}: |g| {worst((nu,), 721):.5f}")
    print("2D: nu_x = nu_y, largest |g| over the modes")
    for s in (0.6, 0.7, 1 / math.sqrt(2), 0.72, 0.75):
        each = s / math.sqrt(2)
        print(f"  nu_x = nu_y = {each:.4f} (sum nu_d^2 = {2 * each * each:.4f}, sum nu_d = {2 * each:.4f}): "
              f"|g| {worst((each, each), 91):.5f}")
        half = s / 2
        print(f"  nu_x = nu_y = {half:.4f} (sum nu_d = {s:.4f}): |g| {worst((half, half), 91):.5f}")


if __name__ == "__main__":
    main()
