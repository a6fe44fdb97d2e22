#include "ice/linear/hypre_struct_pcg.h"

#include <HYPRE_struct_ls.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpmice::ice::linear {

namespace {

void check(HYPRE_Int err, const char* what) {
  if (err != 0) {
    HYPRE_ClearAllErrors();
    throw std::runtime_error(std::string("ice: hypre ") + what + " failed (error " + std::to_string(err) + ")");
  }
}

}  // namespace

struct HypreStructPcg::Objects {
  core::Box owned, domain;
  int dim = 0, hdim = 0;  // the mesh's dimension, hypre's (at least 2: PFMG and SMG have no 1D)
  std::array<bool, 3> periodic{};
  HYPRE_StructGrid grid = nullptr;
  HYPRE_StructStencil stencil = nullptr;
  HYPRE_StructMatrix A = nullptr;
  HYPRE_StructVector b = nullptr, x = nullptr;
  std::vector<double> values, rhs, sol;
  HYPRE_Int lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};
  // The PCG and its multigrid hierarchy, kept between solves (hypre_struct_pcg.h, the lagged
  // hierarchy), with the matrix they were set up from and the counters of the reuse rule.
  HYPRE_StructSolver pcg = nullptr, mg = nullptr;
  StructPreconditioner mgKind = StructPreconditioner::Pfmg;
  std::vector<double> setupValues;
  int since = 0, firstIts = 0;
  bool rebuild = false;

  Objects(MPI_Comm comm, const core::Box& ownedBox, const StencilBoundary& bc, int dimension)
      : owned(ownedBox), domain(bc.domain), dim(dimension), hdim(std::max(dimension, 2)), periodic(bc.periodic) {
    HYPRE_Init();  // idempotent; the CPU build needs nothing more
    HYPRE_Int period[3] = {0, 0, 0};
    for (int d = 0; d < hdim; ++d) {  // a 1D mesh is one row of cells (y index 0)
      lower[d] = owned.lo[d];
      upper[d] = owned.hi[d];
      if (periodic[d]) period[d] = domain.length(d);
    }
    check(HYPRE_StructGridCreate(comm, hdim, &grid), "StructGridCreate");
    if (owned.ok()) check(HYPRE_StructGridSetExtents(grid, lower, upper), "StructGridSetExtents");
    check(HYPRE_StructGridSetPeriodic(grid, period), "StructGridSetPeriodic");
    check(HYPRE_StructGridAssemble(grid), "StructGridAssemble");
    // Entry 0 the centre, 1 + 2 d + s the neighbour at -1 (s = 0) or +1 (s = 1) along d.
    check(HYPRE_StructStencilCreate(hdim, 2 * hdim + 1, &stencil), "StructStencilCreate");
    HYPRE_Int offset[3] = {0, 0, 0};
    check(HYPRE_StructStencilSetElement(stencil, 0, offset), "StructStencilSetElement");
    for (int d = 0; d < hdim; ++d)
      for (int s = 0; s < 2; ++s) {
        HYPRE_Int o[3] = {0, 0, 0};
        o[d] = s ? 1 : -1;
        check(HYPRE_StructStencilSetElement(stencil, 1 + 2 * d + s, o), "StructStencilSetElement");
      }
    check(HYPRE_StructMatrixCreate(comm, grid, stencil, &A), "StructMatrixCreate");
    check(HYPRE_StructMatrixInitialize(A), "StructMatrixInitialize");
    check(HYPRE_StructVectorCreate(comm, grid, &b), "StructVectorCreate");
    check(HYPRE_StructVectorInitialize(b), "StructVectorInitialize");
    check(HYPRE_StructVectorCreate(comm, grid, &x), "StructVectorCreate");
    check(HYPRE_StructVectorInitialize(x), "StructVectorInitialize");
    const auto n = static_cast<std::size_t>(owned.numPts());
    values.resize(n * static_cast<std::size_t>(2 * hdim + 1));
    rhs.resize(n);
    sol.resize(n);
  }
  ~Objects() {
    destroySolver();
    if (x) HYPRE_StructVectorDestroy(x);
    if (b) HYPRE_StructVectorDestroy(b);
    if (A) HYPRE_StructMatrixDestroy(A);
    if (stencil) HYPRE_StructStencilDestroy(stencil);
    if (grid) HYPRE_StructGridDestroy(grid);
  }
  Objects(const Objects&) = delete;
  Objects& operator=(const Objects&) = delete;

  int entries() const { return 2 * hdim + 1; }
  /// Writes a matrix (values in hypre's order) into A and assembles it.
  void setMatrix(const double* v) {
    HYPRE_Int e[7] = {0, 1, 2, 3, 4, 5, 6};
    if (owned.ok())
      check(HYPRE_StructMatrixSetBoxValues(A, lower, upper, entries(), e, const_cast<double*>(v)),
            "StructMatrixSetBoxValues");
    check(HYPRE_StructMatrixAssemble(A), "StructMatrixAssemble");
  }
  void destroySolver() {
    if (pcg) HYPRE_StructPCGDestroy(pcg);
    if (mg) {
      if (mgKind == StructPreconditioner::Pfmg) HYPRE_StructPFMGDestroy(mg);
      else HYPRE_StructSMGDestroy(mg);
    }
    pcg = mg = nullptr;
  }
  /// A fresh PCG and multigrid hierarchy from A as it stands (collective); the counters restart.
  void build(MPI_Comm comm, StructPreconditioner kind, const double* v) {
    destroySolver();
    mgKind = kind;
    check(HYPRE_StructPCGCreate(comm, &pcg), "StructPCGCreate");
    HYPRE_StructPCGSetTwoNorm(pcg, 1);
    HYPRE_StructPCGSetRelChange(pcg, 0);
    HYPRE_StructPCGSetLogging(pcg, 0);
    HYPRE_StructPCGSetPrintLevel(pcg, 0);
    if (kind == StructPreconditioner::Pfmg) {
      check(HYPRE_StructPFMGCreate(comm, &mg), "StructPFMGCreate");
      HYPRE_StructPFMGSetMaxIter(mg, 1);
      HYPRE_StructPFMGSetTol(mg, 0.0);
      HYPRE_StructPFMGSetZeroGuess(mg);
      HYPRE_StructPFMGSetRAPType(mg, 0);    // Galerkin coarse operators (the jumps)
      HYPRE_StructPFMGSetRelaxType(mg, 2);  // red-black Gauss-Seidel, symmetric
      HYPRE_StructPFMGSetNumPreRelax(mg, 1);
      HYPRE_StructPFMGSetNumPostRelax(mg, 1);
      HYPRE_StructPCGSetPrecond(pcg, HYPRE_StructPFMGSolve, HYPRE_StructPFMGSetup, mg);
    } else {
      check(HYPRE_StructSMGCreate(comm, &mg), "StructSMGCreate");
      HYPRE_StructSMGSetMemoryUse(mg, 0);
      HYPRE_StructSMGSetMaxIter(mg, 1);
      HYPRE_StructSMGSetTol(mg, 0.0);
      HYPRE_StructSMGSetZeroGuess(mg);
      HYPRE_StructSMGSetNumPreRelax(mg, 1);
      HYPRE_StructSMGSetNumPostRelax(mg, 1);
      HYPRE_StructPCGSetPrecond(pcg, HYPRE_StructSMGSolve, HYPRE_StructSMGSetup, mg);
    }
    check(HYPRE_StructPCGSetup(pcg, A, b, x), "StructPCGSetup");
    setupValues.assign(v, v + values.size());
    since = 0;
    firstIts = 0;
    rebuild = false;
  }
  /// One PCG solve of the system as set (x its initial guess): iterations, final relative residual.
  std::pair<int, double> run(double tol, int maxIterations) {
    HYPRE_StructPCGSetMaxIter(pcg, maxIterations);
    HYPRE_StructPCGSetTol(pcg, tol);
    HYPRE_StructPCGSolve(pcg, A, b, x);  // not converging is an error code, read by the caller
    HYPRE_ClearAllErrors();
    HYPRE_Int its = 0;
    double rel = 0;
    HYPRE_StructPCGGetNumIterations(pcg, &its);
    HYPRE_StructPCGGetFinalRelativeResidualNorm(pcg, &rel);
    if (since++ == 0) firstIts = static_cast<int>(its);
    return {static_cast<int>(its), rel};
  }
};

HypreStructPcg::HypreStructPcg(const core::Comm& comm, StructPreconditioner preconditioner, int reuse)
    : comm_(comm), pre_(preconditioner), reuse_(std::max(reuse, 1)) {}

HypreStructPcg::~HypreStructPcg() = default;

LinearResult HypreStructPcg::solve(const FaceStencil& A, const StencilBoundary& bc, const core::Field& b,
                                   core::Field& x, double tol, int maxIterations) {
  if (!h_ || h_->owned != A.owned || h_->dim != A.dim || h_->domain != bc.domain || h_->periodic != bc.periodic)
    h_ = std::make_unique<Objects>(comm_.raw(), A.owned, bc, A.dim);
  Objects& H = *h_;
  const int ne = 2 * H.hdim + 1;
  // Values in hypre's order: the stencil entry fastest, then x, y, z (the owned box's order).
  double bb = 0;
  forEachRow(A, bc, [&](int i, int j, int k, double diag, const std::array<double, 6>& off) {
    const std::size_t c = static_cast<std::size_t>(A.owned.index(i, j, k));
    double* v = &H.values[c * static_cast<std::size_t>(ne)];
    v[0] = diag;
    for (int e = 0; e < 2 * H.hdim; ++e) v[1 + e] = -off[static_cast<std::size_t>(e)];  // 0 beyond A.dim
    H.rhs[c] = b(i, j, k);
    H.sol[c] = x(i, j, k);  // the initial guess: what x holds (the previous step's increment)
    bb += H.rhs[c] * H.rhs[c];
  });
  LinearResult res;
  if (!(comm_.sum(bb) > 0)) {
    x.fill(0.0);
    res.converged = true;
    return res;
  }
  if (A.owned.ok()) {
    check(HYPRE_StructVectorSetBoxValues(H.b, H.lower, H.upper, H.rhs.data()), "StructVectorSetBoxValues");
    check(HYPRE_StructVectorSetBoxValues(H.x, H.lower, H.upper, H.sol.data()), "StructVectorSetBoxValues");
  }
  check(HYPRE_StructVectorAssemble(H.b), "StructVectorAssemble");
  check(HYPRE_StructVectorAssemble(H.x), "StructVectorAssemble");
  if (!pending_.empty()) {  // a restart: the hierarchy the interrupted run was using
    const std::size_t want = 3 + H.values.size();
    if (pending_.size() != want)
      throw std::runtime_error("ice: the restart checkpoint's pressure solver set-up holds " +
                               std::to_string(pending_.size()) + " values on this rank, expected " +
                               std::to_string(want) + " (written with another decomposition?)");
    H.setMatrix(pending_.data() + 3);
    H.build(comm_.raw(), pre_, pending_.data() + 3);
    ++setups_;
    H.since = static_cast<int>(pending_[0]);
    H.firstIts = static_cast<int>(pending_[1]);
    H.rebuild = pending_[2] != 0;
    pending_.clear();
  }
  H.setMatrix(H.values.data());
  const bool fresh = !H.pcg || H.since >= reuse_ || H.rebuild;
  if (fresh) {
    H.build(comm_.raw(), pre_, H.values.data());
    ++setups_;
  }
  auto [its, rel] = H.run(tol, maxIterations);
  if (!fresh && !(std::isfinite(rel) && rel <= tol)) {  // the lagged hierarchy failed: once more, fresh
    if (A.owned.ok())
      check(HYPRE_StructVectorSetBoxValues(H.x, H.lower, H.upper, H.sol.data()), "StructVectorSetBoxValues");
    check(HYPRE_StructVectorAssemble(H.x), "StructVectorAssemble");
    H.build(comm_.raw(), pre_, H.values.data());
    ++setups_;
    const auto [its2, rel2] = H.run(tol, maxIterations);
    its += its2;
    rel = rel2;
  } else if (!fresh && its > 2 * H.firstIts + 2) {
    H.rebuild = true;  // the coarse levels no longer fit: a fresh hierarchy next solve
  }

  res.iterations = its;
  res.error = rel;
  res.converged = std::isfinite(rel) && rel <= tol;
  if (A.owned.ok()) check(HYPRE_StructVectorGetBoxValues(H.x, H.lower, H.upper, H.sol.data()), "StructVectorGetBoxValues");
  core::forEach(A.owned, [&](int i, int j, int k) { x(i, j, k) = H.sol[static_cast<std::size_t>(A.owned.index(i, j, k))]; });
  return res;
}

std::vector<double> HypreStructPcg::setupState() const {
  if (!h_ || !h_->pcg) return pending_;
  std::vector<double> s{static_cast<double>(h_->since), static_cast<double>(h_->firstIts), h_->rebuild ? 1.0 : 0.0};
  s.insert(s.end(), h_->setupValues.begin(), h_->setupValues.end());
  return s;
}

void HypreStructPcg::restoreSetupState(std::vector<double> state) { pending_ = std::move(state); }

}  // namespace mpmice::ice::linear
