// The Newtonian viscous stress of ICE, mu (grad u + grad u^T) - (2/3) mu (div u) I (Stokes'
// hypothesis): sound in a viscous gas. A standing wave u = U e sin(k . x) in a periodic box of air
// decays at the classical rate: its acoustic energy as exp(-(4/3) nu |k|^2 t) (amplitude
// exp(-(2/3) nu |k|^2 t); mu lap(u) alone gave nu |k|^2 / 2, a quarter less). Along the grid that
// checks the normal stress's 4/3; across it (k at 45 degrees) the cross derivatives too (without them
// the rate is 7/8 of this one). The inviscid run of the same box is the reference (the scheme's own
// damping of the wave, divided out), and the decay is compared with the discrete operator's exact
// rate for that mode. Energy: the kinetic and acoustic energy lost is heat, the total conserved.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;

namespace {
constexpr double kRho = 1.2, kP = 1e5, kGamma = 1.4;

// Air in a periodic box of n x n cells on the unit square (n x 1 for a wave along x), viscosity mu.
core::Scene viscousAirBox(int nx, int ny, double mu, double end) {
  core::Scene s;
  s.name = "viscous_sound";
  const double h = 1.0 / nx;
  s.mesh = core::Mesh(2, {0, 0, 0}, {h, h, 1}, {nx, ny, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.time.end = end;
  s.materials = {test::idealGas("air", kGamma, 717.5)};
  s.materials[0].viscosity = mu;
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, kP, kRho)};
  // The central face pressure: the Riemann one's dissipation (-Z du at faces in compression, on
  // the same velocities) switches with the wave's phase and does not separate from the viscous
  // rate (with it the rates below measure 0.699 and 0.745 of nu |k|^2 for 0.665 and 0.664).
  s.ice.face_pressure = "average";
  return s;
}

// Acoustic energy [J] of the box: sum V (rho0 |u|^2 / 2 + (p - p0)^2 / (2 rho0 c^2)).
double acousticEnergy(const ice::IceSolver& sol) {
  const double c2 = kGamma * kP / kRho, V = sol.mesh().cellVolume();
  const auto& m = sol.state().mat[0];
  double e = 0;
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
    const double u0 = m.vel(i, j, k, 0), u1 = m.vel(i, j, k, 1), dp = sol.state().press(i, j, k) - kP;
    e += V * (0.5 * kRho * (u0 * u0 + u1 * u1) + dp * dp / (2 * kRho * c2));
  });
  return test::comm().sum(e);
}

struct Decay {
  double acoustic;  // acoustic energy at the end over the start
  double totalChange, heat, lost;  // total energy change, internal energy gained, kinetic + acoustic lost [J]
};

// Standing wave u = U e sin(kx x + ky y), e = k / |k|, on n cells per unit length, to time t.
Decay standingWave(int n, int kx, int ky, double mu, double t) {
  const core::Scene s = viscousAirBox(n, ky == 0 ? 1 : n, mu, t);
  ice::IceSolver sol(s, test::comm());
  const double U = 1.0, kn = std::hypot(kx, ky);
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    const double x = sol.mesh().cellCenter(0, i), y = sol.mesh().cellCenter(1, j);
    const double a = U * std::sin(2 * M_PI * (kx * x + ky * y));
    sol.state().mat[0].vel(i, j, kk, 0) = a * kx / kn;
    sol.state().mat[0].vel(i, j, kk, 1) = a * ky / kn;
  });
  sol.computeEquilibriumPressure();
  const double e0 = acousticEnergy(sol);
  const ice::Totals a = sol.totals();
  test::runToEnd(sol, t);
  const ice::Totals b = sol.totals();
  const double e1 = acousticEnergy(sol);
  return {e1 / e0, b.energy - a.energy, (b.energy - b.kinetic) - (a.energy - a.kinetic), e0 - e1};
}

// The discrete stress's decay rate / nu of the longitudinal mode k = 2 pi (kx, ky) on spacing h
// (ice_solver.cpp, stableTimeStep): L + e^T M e / 3, L = 4 sum_d sin^2(k_d h / 2) / h^2,
// M = s s^T + diag(4 sin^4(k_d h / 2) / h^2), s_d = sin(k_d h) / h.
double discreteRate(int kx, int ky, double h) {
  const double k[2] = {2 * M_PI * kx, 2 * M_PI * ky}, kn = std::hypot(k[0], k[1]);
  double L = 0, es = 0, ed = 0;
  for (int d = 0; d < 2; ++d) {
    const double x = std::pow(std::sin(k[d] * h / 2), 2), e = k[d] / kn;
    L += 4 * x / (h * h);
    es += e * std::sin(k[d] * h) / h;
    ed += e * e * 4 * x * x / (h * h);
  }
  return L + (es * es + ed) / 3;
}


// The wave k = 2 pi (kx, ky) on n cells per unit length with viscosity mu, to t = 0.02 s (7.5
// periods along x): its amplitude's decay rate over nu |k|^2 against the discrete operator's, within
// 2 %, and the total energy conserved.
void expectNewtonianRate(int kx, int ky, double mu) {
  const int n = 32;
  const double nu = mu / kRho, t = 0.02;
  const Decay visc = standingWave(n, kx, ky, mu, t), inv = standingWave(n, kx, ky, 0.0, t);
  const double measured = -std::log(visc.acoustic / inv.acoustic) / (2 * nu * t);  // amplitude rate / nu
  const double k2 = 4 * M_PI * M_PI * (kx * kx + ky * ky), exact = discreteRate(kx, ky, 1.0 / n) / 2;
  std::printf("  acoustic energy: viscous %.6f, inviscid %.6f; rate / (nu |k|^2) %.4f (discrete Newtonian %.4f, "
              "continuous 2/3; mu lap u alone 1/2)\n",
              visc.acoustic, inv.acoustic, measured / k2, exact / k2);
  std::printf("  energy: lost %.6e J, heat %.6e J, total change %.3e J\n", visc.lost, visc.heat, visc.totalChange);
  EXPECT_NEAR(visc.totalChange, 0.0, 1e-6 * visc.lost) << "total energy conserved";
  EXPECT_NEAR(measured / k2, exact / k2, 0.02 * exact / k2);
}
// 3D: air in a periodic unit cube of n^3 cells; a wave u = U e sin(k . x), k = 2 pi m (m integer),
// polarization e (unit). Longitudinal (e along k: sound) or transverse (e normal to k: a shear
// wave, steady without viscosity). Returns the energy ratio as above.
Decay standingWave3(int n, const int m[3], const double e[3], double mu, double t) {
  core::Scene s;
  s.name = "viscous_wave_3d";
  const double h = 1.0 / n;
  s.mesh = core::Mesh(3, {0, 0, 0}, {h, h, h}, {n, n, n});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.time.end = t;
  s.materials = {test::idealGas("air", kGamma, 717.5)};
  s.materials[0].viscosity = mu;
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, kP, kRho)};
  s.ice.face_pressure = "average";  // as viscousAirBox
  ice::IceSolver sol(s, test::comm());
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    const double x[3] = {sol.mesh().cellCenter(0, i), sol.mesh().cellCenter(1, j), sol.mesh().cellCenter(2, kk)};
    const double a = std::sin(2 * M_PI * (m[0] * x[0] + m[1] * x[1] + m[2] * x[2]));
    for (int d = 0; d < 3; ++d) sol.state().mat[0].vel(i, j, kk, d) = a * e[d];
  });
  sol.computeEquilibriumPressure();
  auto energy = [&]() {  // acoustic + kinetic, three components
    const double c2 = kGamma * kP / kRho, V = sol.mesh().cellVolume();
    const auto& M = sol.state().mat[0];
    double E = 0;
    core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
      double u2 = 0;
      for (int d = 0; d < 3; ++d) u2 += M.vel(i, j, kk, d) * M.vel(i, j, kk, d);
      const double dp = sol.state().press(i, j, kk) - kP;
      E += V * (0.5 * kRho * u2 + dp * dp / (2 * kRho * c2));
    });
    return test::comm().sum(E);
  };
  const double e0 = energy();
  const ice::Totals a = sol.totals();
  test::runToEnd(sol, t);
  const ice::Totals b = sol.totals();
  const double e1 = energy();
  return {e1 / e0, b.energy - a.energy, (b.energy - b.kinetic) - (a.energy - a.kinetic), e0 - e1};
}

// The discrete stress's rate / nu for the mode k = 2 pi m on spacing h and polarization e, an
// eigenvector of its symbol L I + M / 3 (the faces' normal differences and the tangential
// derivatives, the mean of the two cells' central differences): L = 4 sum_d sin^2(k_d h / 2) / h^2,
// M_qq = 4 sin^2(k_q h / 2) / h^2, M_qp = sin(k_q h) sin(k_p h) / h^2 (p != q).
double discreteRate3(const int m[3], const double e[3], double h) {
  double k[3], L = 0;
  for (int d = 0; d < 3; ++d) k[d] = 2 * M_PI * m[d], L += 4 * std::pow(std::sin(k[d] * h / 2), 2) / (h * h);
  double eMe = 0;
  for (int q = 0; q < 3; ++q)
    for (int p = 0; p < 3; ++p)
      eMe += e[q] * e[p] *
             (p == q ? 4 * std::pow(std::sin(k[q] * h / 2), 2) / (h * h) : std::sin(k[q] * h) * std::sin(k[p] * h) / (h * h));
  return L + eMe / 3;
}

// A 3D mode against the discrete rate, within 2 %; the total energy conserved.
void expectNewtonianRate3(const int m[3], const double e[3], double mu, const char* what) {
  const int n = 16;
  const double nu = mu / kRho, t = 0.01;
  const Decay visc = standingWave3(n, m, e, mu, t), inv = standingWave3(n, m, e, 0.0, t);
  const double measured = -std::log(visc.acoustic / inv.acoustic) / (2 * nu * t);
  const double k2 = 4 * M_PI * M_PI * (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  double ek = 0;  // e . k / |k|: 1 longitudinal, 0 transverse
  for (int d = 0; d < 3; ++d) ek += e[d] * 2 * M_PI * m[d] / std::sqrt(k2);
  // The amplitude's rate: the operator's on a shear wave (all its energy kinetic), half of it on
  // sound (half the time in the pressure, which the stress does not damp).
  const double half = std::abs(ek) > 0.5 ? 0.5 : 1.0;
  const double exact = half * discreteRate3(m, e, 1.0 / n);
  const double continuous = half * (1.0 + ek * ek / 3);  // nu |k|^2 (4/3 / 2 sound, 1 shear)
  std::printf("  %s: energy viscous %.6f, inviscid %.6f; rate / (nu |k|^2) %.4f (discrete %.4f, continuous %.4f)\n", what,
              visc.acoustic, inv.acoustic, measured / k2, exact / k2, continuous);
  std::printf("  energy: lost %.6e J, heat %.6e J, total change %.3e J\n", visc.lost, visc.heat, visc.totalChange);
  EXPECT_NEAR(visc.totalChange, 0.0, 1e-6 * visc.lost) << what << ": total energy conserved";
  EXPECT_NEAR(measured / k2, exact / k2, 0.02 * exact / k2) << what;
}
}  // namespace

// Along x: the normal stress is (4/3) mu du/dx.
TEST(IceViscousStress, SoundAlongTheGridDecaysAtTheNewtonianRate) { expectNewtonianRate(1, 0, 0.5); }

// At 45 degrees: the cross derivatives (mu / 3) d_x d_y carry a third of the longitudinal rate's
// excess over mu lap u.
TEST(IceViscousStress, SoundAcrossTheGridDecaysAtTheNewtonianRate) { expectNewtonianRate(1, 1, 0.25); }

// Walls: a compressing and shearing flow in a closed box (no-slip walls at x = 0 and 1, slip walls at
// y = 0 and 1): the stress at a wall at rest does no work (the face's mean velocity is 0 normal to a
// slip wall, and 0 at a no-slip one), so the kinetic energy the viscosity takes is heat and the total
// energy is conserved.
TEST(IceViscousStress, WallsAtRestDoNoWork) {
  const int n = 16;
  core::Scene s = viscousAirBox(n, n, 0.5, 0.01);
  s.boundary[0].type = s.boundary[1].type = core::BoundaryType::NoSlipWall;
  s.boundary[2].type = s.boundary[3].type = core::BoundaryType::SlipWall;
  ice::IceSolver sol(s, test::comm());
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    const double x = sol.mesh().cellCenter(0, i), y = sol.mesh().cellCenter(1, j);
    sol.state().mat[0].vel(i, j, kk, 0) = 5.0 * std::sin(M_PI * x) * std::cos(M_PI * y);
    sol.state().mat[0].vel(i, j, kk, 1) = 3.0 * std::sin(2 * M_PI * x) * std::sin(M_PI * y);
  });
  sol.computeEquilibriumPressure();
  const ice::Totals a = sol.totals();
  test::runToEnd(sol, s.time.end);
  const ice::Totals b = sol.totals();
  const double lost = a.kinetic - b.kinetic;
  std::printf("  kinetic lost %.9e J, internal +%.9e J, total change %.3e J, viscous heat %.9e J\n", lost,
              (b.energy - b.kinetic) - (a.energy - a.kinetic), b.energy - a.energy, sol.viscousHeat());
  ASSERT_GT(lost, 0.1 * a.kinetic);
  EXPECT_NEAR(b.energy, a.energy, 1e-6 * lost) << "total energy conserved";
  EXPECT_GT(sol.viscousHeat(), 0.0);
}

// 3D, k along the cube's diagonal (1, 1, 1): sound (e along k: every cross derivative d_q u_d of
// the three pairs) and a shear wave (e = (1, -1, 0) / sqrt 2, normal to k: the stress's
// tangential part alone, rate nu |k|^2).
TEST(IceViscousStress, ThreeDSoundAndShearAlongTheDiagonalDecayAtTheNewtonianRates) {
  const int m[3] = {1, 1, 1};
  const double r3 = 1 / std::sqrt(3.0), r2 = 1 / std::sqrt(2.0);
  const double along[3] = {r3, r3, r3}, across[3] = {r2, -r2, 0};
  expectNewtonianRate3(m, along, 0.25, "sound along (1, 1, 1)");
  expectNewtonianRate3(m, across, 0.25, "shear wave along (1, 1, 1), e = (1, -1, 0) / sqrt 2");
}
