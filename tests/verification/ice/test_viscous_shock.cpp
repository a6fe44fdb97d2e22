// The structure of a viscous, heat-conducting shock: Becker's exact solution of the 1D Navier-Stokes
// equations (ideal gas, constant mu, Stokes' hypothesis, Prandtl number 3/4). With k = (4/3) mu cp
// the total enthalpy h + u^2 / 2 is the same through the shock, and the momentum balance
// m u + p - (4/3) mu du/dx = const (m = rho u) becomes
//   (4/3) mu u du/dx = m (gamma + 1) / (2 gamma) (u - u1) (u - u2),
// whose solution is x - x0 = l / (u1 - u2) [u1 ln(u1 - u) - u2 ln(u - u2)], l = 8 gamma mu / (3 (gamma + 1) m).
// It checks the normal viscous stress (4/3) mu du/dx, the conduction and the viscous heat together:
// the shock's thickness is set by the first two and its states by the third (the heat is the
// kinetic energy the stress takes). A Mach 2 shock in air held still between a supersonic inflow
// and an outflow at the downstream pressure, started from the exact profile, run until it settles;
// the profile, placed by its mid-velocity point, against the exact one at three meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;

namespace {
constexpr double kGamma = 1.4, kCv = 717.5, kCp = kGamma * kCv, kR = kCp - kCv;
constexpr double kRho1 = 1.2, kP1 = 1e5, kMach = 2.0, kLength = 0.16, kX0 = 0.08;

struct Becker {
  double u1, u2, m, H, l, mu;
  explicit Becker(double mu_) : mu(mu_) {
    const double c1 = std::sqrt(kGamma * kP1 / kRho1);
    u1 = kMach * c1;
    u2 = u1 * ((kGamma - 1) * kMach * kMach + 2) / ((kGamma + 1) * kMach * kMach);
    m = kRho1 * u1;
    H = kCp * kP1 / (kRho1 * kR) + 0.5 * u1 * u1;
    l = 8 * kGamma * mu / (3 * (kGamma + 1) * m);
  }
  // x(u) - x0 (x0: where u = (u1 + u2) / 2).
  [[nodiscard]] double x(double u) const {
    auto f = [&](double v) { return l / (u1 - u2) * (u1 * std::log(u1 - v) - u2 * std::log(v - u2)); };
    return f(u) - f(0.5 * (u1 + u2));
  }
  // u at x - x0 (bisection: x(u) falls from +inf at u2 to -inf at u1).
  [[nodiscard]] double u(double xi) const {
    double lo = u2, hi = u1;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      (x(mid) > xi ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
  [[nodiscard]] double p2() const { return kP1 * (1 + 2 * kGamma / (kGamma + 1) * (kMach * kMach - 1)); }
};

struct ShockRun {
  double l1;     // sum |u - u_exact| dx / ((u1 - u2) l), the exact profile placed at the run's mid point
  double l1T;    // the same for the temperature, over (T2 - T1) l
  double width;  // (u1 - u2) / max |du/dx| over the exact one's
  double drift;  // the mid point's move from x0 [m]
  long steps;
};

ShockRun runShock(int n, double mu, double tEnd, const char* facePressure) {
  const Becker b(mu);
  core::Scene s;
  s.name = "becker_shock";
  const double dx = kLength / n;
  s.mesh = core::Mesh(2, {0, 0, 0}, {dx, 0.1, 1}, {n, 1, 1});  // one row, dy >> dx: the 1D step bounds
  for (auto& bc : s.boundary) bc.type = core::BoundaryType::Periodic;
  s.boundary[0].type = core::BoundaryType::Inflow;
  s.boundary[0].velocity = {b.u1, 0, 0};
  s.boundary[0].density = kRho1;
  s.boundary[0].pressure = kP1;
  s.boundary[1].type = core::BoundaryType::Outflow;
  s.boundary[1].pressure = b.p2();
  s.time.end = tEnd;
  s.materials = {test::idealGas("air", kGamma, kCv)};
  s.materials[0].viscosity = mu;
  s.materials[0].thermal_conductivity = 4.0 / 3.0 * mu * kCp;  // Prandtl 3/4
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, kP1, kRho1)};
  s.ice.face_pressure = facePressure;
  ice::IceSolver sol(s, test::comm());
  const double V = sol.mesh().cellVolume();
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {  // the exact profile
    auto& a = sol.state().mat[0];
    const double u = b.u(sol.mesh().cellCenter(0, i) - kX0), rho = b.m / u, h = b.H - 0.5 * u * u;
    a.vel(i, j, k, 0) = u;
    a.mass(i, j, k) = rho * V;
    a.spvol(i, j, k) = 1 / rho;
    a.eint(i, j, k) = h / kGamma;  // e = cv T = h / gamma
  });
  sol.computeEquilibriumPressure();
  test::runToEnd(sol, tEnd);
  // The run's profile on every rank, in x order.
  std::vector<double> u(static_cast<std::size_t>(n), 0.0), T(static_cast<std::size_t>(n), 0.0);
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
    const auto& a = sol.state().mat[0];
    u[static_cast<std::size_t>(i)] = a.vel(i, j, k, 0);
    T[static_cast<std::size_t>(i)] = a.eos->temperature(1 / a.spvol(i, j, k), a.eint(i, j, k));
  });
  for (double& v : u) v = test::comm().sum(v);
  for (double& v : T) v = test::comm().sum(v);
  const double half = 0.5 * (b.u1 + b.u2);
  double xm = kX0, slope = 0;
  for (int i = 0; i + 1 < n; ++i) {
    const double a = u[static_cast<std::size_t>(i)], c = u[static_cast<std::size_t>(i + 1)];
    if (a >= half && c < half) xm = sol.mesh().cellCenter(0, i) + dx * (a - half) / (a - c);
    slope = std::max(slope, (a - c) / dx);
  }
  double l1 = 0, l1T = 0;
  for (int i = 0; i < n; ++i) {
    const double ue = b.u(sol.mesh().cellCenter(0, i) - xm);
    l1 += std::abs(u[static_cast<std::size_t>(i)] - ue) * dx;
    l1T += std::abs(T[static_cast<std::size_t>(i)] - (b.H - 0.5 * ue * ue) / kCp) * dx;
  }
  const double dT = 0.5 * (b.u1 * b.u1 - b.u2 * b.u2) / kCp;  // T2 - T1
  // The exact profile's steepest slope: at u* = sqrt(u1 u2) (d/du of (u - u1)(u - u2) / u = 0).
  const double us = std::sqrt(b.u1 * b.u2);
  const double exactSlope = 3 * (kGamma + 1) * b.m / (8 * kGamma * mu) * (b.u1 - us) * (us - b.u2) / us;
  return {l1 / ((b.u1 - b.u2) * b.l), l1T / (dT * b.l), exactSlope / slope, xm - kX0, sol.steps()};
}

// Each setting at 40, 80, 160 and 320 cells over the 0.16 m (0.9 to 7.6 cells per l), to 1 ms
// (steady: at 4 ms the errors are the same to 4 digits). Returns the four runs.
std::vector<ShockRun> study(const char* facePressure) {
  const double mu = 2.0;  // l = 3.8 mm; the exact shock is 4.6 l thick by its steepest slope (17.5 mm)
  std::vector<ShockRun> runs;
  for (const int n : {40, 80, 160, 320}) {
    runs.push_back(runShock(n, mu, 1e-3, facePressure));
    const ShockRun& r = runs.back();
    std::printf("  %s, %d cells (%.1f per l): L1(u) / ((u1 - u2) l) %.4e, L1(T) / ((T2 - T1) l) %.4e, width / exact "
                "%.4f, mid point moved %.3e m, %ld steps\n",
                facePressure, n, Becker(mu).l / (kLength / n), r.l1, r.l1T, r.width, r.drift, r.steps);
  }
  for (std::size_t q = 1; q < runs.size(); ++q)
    std::printf("  order %.2f (u), %.2f (T)\n", std::log2(runs[q - 1].l1 / runs[q].l1), std::log2(runs[q - 1].l1T / runs[q].l1T));
  return runs;
}

// The last two meshes' orders in u and T above `order`, the finest's L1(u) below `l1` and its width
// within `width` of the exact one.
void expectConverges(const std::vector<ShockRun>& r, double order, double l1, double width) {
  EXPECT_GT(std::log2(r[2].l1 / r[3].l1), order);
  EXPECT_GT(std::log2(r[2].l1T / r[3].l1T), order);
  EXPECT_LT(r[3].l1, l1);
  EXPECT_NEAR(r[3].width, 1.0, width);
}
}  // namespace

// The central face pressure: the scheme adds no dissipation of its own to the profile and it
// converges at second order (measured 2.02 in u from 80 cells on; width within 0.8 % at 320 cells).
TEST(IceViscousShock, BeckerProfileAtSecondOrderWithTheCentralFacePressure) {
  expectConverges(study("average"), 1.8, 0.01, 0.02);
}

// The default (Riemann) face pressure adds its first-order dissipation: the profile converges at
// first order, 12 % too wide at 7.6 cells per l.
TEST(IceViscousShock, BeckerProfileAtFirstOrderWithTheRiemannFacePressure) {
  expectConverges(study("riemann"), 0.9, 0.2, 0.15);
}
