// IceSolver's restart state: every stored field a step reads before it writes it (ghosts
// included, so the next step reads exactly what it would have read), the clock and the counters. What the scene gives again (the EOS, the
// boundary conditions, the sources, the exchange coefficients, the initial pressure) the solver a
// restart builds recomputes as the original run did; scratch is rewritten before it is read.
#include <algorithm>
#include <span>
#include <stdexcept>

#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

namespace {
/// `a` followed by `b` (appended, not operator+: GCC 12 misreads "x" + std::string under -O3).
std::string cat(const std::string& a, const std::string& b) {
  std::string s = a;
  s += b;
  return s;
}

/// Every field of the state, with its checkpoint name.
template <class State, class F>
void forEveryField(State& st, F&& f) {
  for (std::size_t m = 0; m < st.mat.size(); ++m) {
    auto& x = st.mat[m];
    std::string p = "m";
    p += std::to_string(m);
    p += '.';
    f(cat(p, "mass"), x.mass);
    f(cat(p, "vel"), x.vel);
    f(cat(p, "eint"), x.eint);
    f(cat(p, "spvol"), x.spvol);
    f(cat(p, "theta"), x.theta);
    f(cat(p, "kappa"), x.kappa);
    f(cat(p, "velL"), x.velL);
    f(cat(p, "eintL"), x.eintL);
    f(cat(p, "spvolL"), x.spvolL);
    for (int d = 0; d < 3; ++d) f(cat(cat(p, "velFace"), std::to_string(d)), x.velFace[d]);
    f(cat(p, "dMom"), x.dMom);
    f(cat(p, "dEnergy"), x.dEnergy);
  }
  f("press", st.press);
  f("dp", st.dp);
  // Not the face volume fluxes and face pressures: a step computes them before it reads them (and
  // the advection's mass fluxes have their storage at the end of a step).
}

std::size_t sizeOf(const core::Field& f) { return static_cast<std::size_t>(f.npts() * f.ncomp()); }
}  // namespace

void IceSolver::saveCheckpoint(core::CheckpointData& data, const std::string& prefix) const {
  forEveryField(st_, [&](const std::string& name, const core::Field& f) {
    data.put(cat(cat(prefix, "."), name), std::span<const double>(f.data(), sizeOf(f)));
  });
  data.put(prefix + ".iters", std::vector<double>(st_.iters.begin(), st_.iters.end()));  // counts, as doubles
  data.put(prefix + ".clock", std::vector<double>{t_, static_cast<double>(nsteps_), dt_, collapse_.first(),
                                                  static_cast<double>(fallbacks_), static_cast<double>(linIters_),
                                                  static_cast<double>(linItersTotal_), audit_.created, audit_.energy,
                                                  lastBound_});
  // The pressure solver's multigrid set-up (its matrix and reuse counters): a resumed run rebuilds
  // the hierarchy the interrupted one was using, so it continues bit for bit.
  if (semi_.hypre)
    if (std::vector<double> s = semi_.hypre->setupState(); !s.empty()) data.put(prefix + ".pressure_solver_setup", std::move(s));
}

void IceSolver::loadCheckpoint(const core::CheckpointData& data, const std::string& prefix) {
  semi_.mobilityFresh = false;
  forEveryField(st_, [&](const std::string& name, core::Field& f) {
    const std::string key = cat(cat(prefix, "."), name);
    const std::span<double> out(f.data(), sizeOf(f));
    // The velocities hold the mesh's dimension of components; a checkpoint written before
    // (3 Dec 2026) holds 3, the ones beyond an exact zero: its first components are taken.
    const bool velocity = name.ends_with(".vel") || name.ends_with(".velL");
    const std::vector<double>& v = data.get(key);
    if (out.empty()) return;  // a fluid's velL, eintL, spvolL (ice_state.h): written by older programs, read by none
    if (velocity && f.ncomp() < 3 && v.size() == static_cast<std::size_t>(3 * f.npts()))
      std::copy(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(out.size()), out.begin());
    else
      data.copyTo(key, out);
  });
  // The per-cell iteration counts are kept only where the output writes them (ice_state.h), by the
  // run that wrote the checkpoint and by this one each on its own: a diagnostic the next step
  // makes again, taken where both keep them and 0 where only this run does.
  const std::vector<double>& it = data.get(prefix + ".iters");
  if (!it.empty() && !st_.iters.empty() && it.size() != st_.iters.size())
    throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".iters' has " +
                                std::to_string(it.size()) + " values, expected " + std::to_string(st_.iters.size()));
  if (it.size() == st_.iters.size())
    std::transform(it.begin(), it.end(), st_.iters.begin(), [](double x) { return static_cast<int>(x); });
  else
    std::fill(st_.iters.begin(), st_.iters.end(), 0);
  const auto& c = data.get(prefix + ".clock");
  // 7: written before the energy audit (its sums start at 0); 9: before the semi-implicit step's
  // growth bound (the resumed run starts it again from the explicit step).
  if (c.size() != 7 && c.size() != 9 && c.size() != 10)
    throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".clock' has " +
                                std::to_string(c.size()) + " values, expected 10");
  t_ = c[0];
  nsteps_ = static_cast<long>(c[1]);
  dt_ = c[2];
  collapse_.resumeFirst(c[3]);
  fallbacks_ = static_cast<long>(c[4]);
  linIters_ = static_cast<int>(c[5]);
  linItersTotal_ = static_cast<long>(c[6]);
  if (c.size() >= 9) audit_.created = c[7], audit_.energy = c[8];
  lastBound_ = c.size() >= 10 ? c[9] : 0.0;
  const bool structured = linearSolver_ == LinearSolver::PfmgPcg || linearSolver_ == LinearSolver::SmgPcg;
  if (semiImplicit_ && structured && data.has(prefix + ".pressure_solver_setup"))
    structSolver().restoreSetupState(data.get(prefix + ".pressure_solver_setup"));
}

}  // namespace mpmice::ice
