#include "mpmice/fluid/fluid_side.h"

// DBG-BEGIN
#include <cstdio>
#include <cstdlib>
#include <cmath>
namespace mpmice::coupler {
namespace {
int dbgStep = 0;
bool dbgOn() { static const bool on = std::getenv("MPMICE_DBG") != nullptr; return on; }
void dbgDump(ice::IceSolver& ice, const char* tag) {
  if (!dbgOn()) return;
  const auto& st = ice.state();
  const core::Box& b = ice.ownedBox();
  const double V = ice.mesh().cellVolume();
  struct Mx { double v = 0; int i = -1, j = -1; void up(double x, int a, int c) { if (std::abs(x) > std::abs(v)) { v = x; i = a; j = c; } } };
  Mx pmax, pmin, dp, thA, uA, uS, dvS, mS, velS, sumth;
  pmin.v = 1e300;
  core::forEach(b, [&](int i, int j, int k) {
    const auto& A = st.mat[0];
    const auto& S = st.mat[1];
    pmax.up(st.press(i, j, k), i, j);
    if (st.press(i, j, k) < pmin.v) { pmin.v = st.press(i, j, k); pmin.i = i; pmin.j = j; }
    dp.up(st.dp(i, j, k), i, j);
    if (S.mass(i, j, k) > 0) thA.up(A.theta(i, j, k), i, j);
    sumth.up(A.theta(i, j, k) + S.theta(i, j, k) - 1.0, i, j);
    for (int d = 0; d < 2; ++d) {
      uA.up(A.velFace[d](i, j, k), i, j);
      uS.up(S.velFace[d](i, j, k), i, j);
      velS.up(S.vel(i, j, k, d), i, j);
      const double m = S.mass(i, j, k);
      if (m > 0) dvS.up(S.dMom(i, j, k, d) / m, i, j);
    }
    (void)V;
  });
  {
    Mx e0, eL; int n = 0;
    core::forEach(b, [&](int i, int j, int k) {
      const auto& A = st.mat[0];
      const auto& S = st.mat[1];
      if (S.theta(i, j, k) < 0.99) return;
      ++n;
      e0.up(A.eint(i, j, k), i, j);
      eL.up(A.eintL(i, j, k), i, j);
    });
    std::printf("DBGE %d %s solidcells %d air e %.4g(%d,%d) eL %.4g(%d,%d)\n", dbgStep, tag, n, e0.v, e0.i, e0.j, eL.v, eL.i, eL.j);
  }
  std::printf("DBG %d %s pmax %.4g(%d,%d) pmin %.4g(%d,%d) dp %.3g(%d,%d) thAirInSolid %.3g(%d,%d) uAf %.3g(%d,%d) uSf %.3g(%d,%d) velS %.3g(%d,%d) dvS %.3g(%d,%d) sumth-1 %.3g\n",
              dbgStep, tag, pmax.v, pmax.i, pmax.j, pmin.v, pmin.i, pmin.j, dp.v, dp.i, dp.j, thA.v, thA.i, thA.j,
              uA.v, uA.i, uA.j, uS.v, uS.i, uS.j, velS.v, velS.i, velS.j, dvS.v, dvS.i, dvS.j, sumth.v);
  const char* cs = std::getenv("MPMICE_DBG_CELL");
  int ci = -1, cj = -1, s0 = 0;
  if (cs && std::sscanf(cs, "%d,%d,%d", &ci, &cj, &s0) == 3 && dbgStep >= s0) {
    for (int j = cj - 1; j <= cj + 1; ++j)
      for (int i = ci - 1; i <= ci + 1; ++i) {
        const auto& A = st.mat[0];
        const auto& S = st.mat[1];
        std::printf("   c(%d,%d) p %.5g peq %.5g dp %.3g | air m %.3g th %.3g v %.3g u (%.3g,%.3g) uf (%.3g,%.3g) kap %.3g | st m %.4g th %.8f v %.6g u (%.3g,%.3g) uf (%.3g,%.3g) kap %.3g dM (%.3g,%.3g) divU %.3g\n",
                    i, j, st.press(i, j, 0), st.pressEq(i, j, 0), st.dp(i, j, 0), A.mass(i, j, 0), A.theta(i, j, 0),
                    A.spvol(i, j, 0), A.vel(i, j, 0, 0), A.vel(i, j, 0, 1), A.velFace[0](i, j, 0), A.velFace[1](i, j, 0),
                    A.kappa(i, j, 0), S.mass(i, j, 0), S.theta(i, j, 0), S.spvol(i, j, 0), S.vel(i, j, 0, 0),
                    S.vel(i, j, 0, 1), S.velFace[0](i, j, 0), S.velFace[1](i, j, 0), S.kappa(i, j, 0),
                    S.dMom(i, j, 0, 0), S.dMom(i, j, 0, 1), st.divU(i, j, 0));
      }
  }
}
}  // namespace
}  // namespace mpmice::coupler
// DBG-END

namespace mpmice::coupler {

FluidSide::FluidSide(ice::IceSolver& ice, const core::Scene& scene) : ice_(ice) {
  for (int m : scene.solids()) fields_.emplace_back(m, scene.materials[m].name, ice.ownedBox());
}

void FluidSide::consumeAProduceB(double dt) {
  if (!started_) start();
  for (auto& f : fields_)
    ice_.setExternalMaterialState(f.material, all(f.mass), all(f.velocity), all(f.temperature),
                                  all(f.specificVolume));
  ice_.computeEquilibriumPressure();
  ice_.beginStep(dt);
  ice_.computeFaceVelocities();
  ice_.computePressureIncrement();
  ice_.computeFacePressure();
  dbgDump(ice_, "B"); // DBG
  for (auto& f : fields_) {
    const core::Field p = ice_.pressureForce(f.material);
    f.pressureForce.copyRegion(p, f.pressureForce.box(), f.pressureForce.box());
    f.pressure.copyRegion(ice_.pressure(), f.pressure.box(), f.pressure.box());
  }
}

void FluidSide::consumeCProduceD() {
  ice_.computeSourcesAndLagrangian();
  dbgDump(ice_, "L"); // DBG
  for (auto& f : fields_) ice_.setExternalLagrangianMomentum(f.material, all(f.lagrangianMomentum));
  ice_.exchange();
  dbgDump(ice_, "D"); ++dbgStep; // DBG
  for (auto& f : fields_) {
    const core::Field& d = ice_.exchangeMomentum(f.material);
    f.exchangeMomentum.copyRegion(d, f.exchangeMomentum.box(), f.exchangeMomentum.box());
  }
}

void FluidSide::finishStep() { ice_.advectFluids(); }

void FluidSide::start() {
  for (auto& f : fields_)
    ice_.setExternalMaterialState(f.material, all(f.mass), all(f.velocity), all(f.temperature),
                                  all(f.specificVolume));
  ice_.fitFluidsToExternalVolume();
  started_ = true;
}

void FluidSide::primeOutput() {
  for (auto& f : fields_) {
    f.pressure.copyRegion(ice_.pressure(), f.pressure.box(), f.pressure.box());
    f.pressureForce.fill(0.0);
    f.exchangeMomentum.fill(0.0);
  }
}

void FluidSide::fullStep(double dt) {
  consumeAProduceB(dt);
  consumeCProduceD();
  finishStep();
}

SideTotals FluidSide::totals() const {
  const ice::Totals t = ice_.totals();
  SideTotals s;
  s.mass = t.mass;
  s.momentum = t.momentum;
  s.energy = t.energy;
  return s;
}

}  // namespace mpmice::coupler
