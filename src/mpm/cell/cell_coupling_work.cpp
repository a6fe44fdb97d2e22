// The energy of the coupling's node forces and momentum increments, booked to the cells they came
// from: NodeCellOperators::cellCouplingWork, and the nodes' share of the kinetic deficit
// (applyCellMomentumIncrement).
//
// ICE's Lagrangian phase closes each cell's energy with the coupling work: the flux-form p dV work
// of the cell less what its fluids take less this work is a mismatch it hands to the cell's
// materials as heat (src/ice/sources/lagrangian_phase.cpp); the kinetic deficit (what ICE's
// exchange charged a cell for the solid's kinetic energy less what its nodes gained) goes to the
// solid's particles as heat. The grid realises both node by node. Booking a node's share back to
// cells by the node-to-cell average put the energy of a vector made in one cell partly into its
// neighbours: at a crushing foam's top the water cell's pressure force (most of the load) did work
// booked to the foam's cell below, whose mismatch stayed at -3.5 J a step and cooled the foam's
// top particles; the light slab of docs/stability.md (density ratio 1) cooled below 0 K the same
// way. Here each vector is followed from its cell: a particle's share m_p / M_c of its cell's
// vector acts on its stencil nodes with its weights (spreadCellVectors), so its power is
//   P_c = sum_{p in c} (m_p / M_c) vec_c . v~_p,   v~_p = sum_i w_ip vbar_i,
// vbar the mean node velocity of the update (v + v_L) / 2 (0 where the update does not move the
// node; mirror images beyond symmetry planes, whose folded vectors act on the nodes inside); a cell
// without particles of its own gave its vector to its corner nodes: P_c = sum_corners (share
// m_i / M_c) vec_c . vbar_i. The mean-stress force of a particle (addCellPressureStress,
// -V_p S_p grad w_ip) does -V_p S_p : L~_p, L~_p = sum_i vbar_i (x) grad w_ip. Summed over cells
// these are the nodes' own sums (the same products regrouped): dt f_i . vbar_i for the work, and
// m_i dv_i . vbar_i = the kinetic energy change of node i for a momentum increment.
#include "mpm/cell/node_cell_operators.h"
#include <utility>

#include "mpm/solver/kernels.h"

namespace mpmice::mpm {

using core::Centering;
using core::Field;

void NodeCellOperators::meanNodeVelocity(const Field& a, const Field& b, double floor, Field& out) const {
  const Grid& g = grid_;
  const int dim = mesh_.dim();
  const double* gm = g.mass.data();
  for (int d = 0; d < out.ncomp(); ++d) {  // the node vectors' components: the mesh's directions
    double* o = out.data(d);
    const double* va = a.data(d);
    const double* vb = b.data(d);
    for (std::int64_t k = 0; k < g.numNodes(); ++k) o[k] = d < dim && gm[k] > floor ? 0.5 * (va[k] + vb[k]) : 0.0;
  }
  bcs_.mirror(out, Parity::Vector);
}

void NodeCellOperators::addCellVectorPower(int material, const std::vector<double>& vec, const Field& vbar,
                                           double scale, Field& out) {
  const SolidCellState& cs = states_.at(static_cast<std::size_t>(material));
  const double* cm = cs.mass.data();  // owned cells: flat index = cells_.index
  const ParticleCells& pc = particleCells(material);
  const auto vb = components(vbar);
  double* P = out.data();
  const auto [b, e] = p_.materialRange(material);
  const GridGeom geom = grid_.geom();
  kernels::dispatch(shape_, mesh_.dim(), [&]<class S, int D>() {
    kernels::Stencil<S, D> st;
    for (std::size_t i = b; i < e; ++i) {
      const auto s = static_cast<std::size_t>(pc.slot[i - b]);
      if (!(cm[s] > massFloor_)) continue;
      double vt[3] = {0, 0, 0};
      st.compute(p_, i, geom);
      st.forNodes(geom, [&](std::int64_t k, double w, double, double, double) {
        for (int a = 0; a < D; ++a) vt[a] += w * vb[a][k];
      });
      double power = 0;
      for (int a = 0; a < D; ++a) power += vec[3 * s + static_cast<std::size_t>(a)] * vt[a];
      P[s] += scale * p_.mass[i] / pc.mass[s] * power;
    }
  });
  const Field& nm = nodeMass_[static_cast<std::size_t>(material)];
  const int dim = mesh_.dim();
  const CellCorners& cc = imageCorners(nm, "addCellVectorPower");
  imageCorners(vbar, "addCellVectorPower");
  const double* nmd = nm.data();
  core::forEach(cells_, [&](int i, int j, int k) {
    const auto s = static_cast<std::size_t>(cells_.index(i, j, k));
    const double mc = cm[s];
    if (!(mc > massFloor_) || pc.mass[s] > 0) return;
    double power = 0;
    cc.forCorners(i, j, k, [&](std::int64_t n, double share) {
      const double w = share * nmd[n] / mc;
      for (int d = 0; d < dim; ++d) power += w * vec[3 * s + static_cast<std::size_t>(d)] * vb[d][n];
    });
    P[s] += scale * power;
  });
}

void NodeCellOperators::cellCouplingWork(int material, Field& out, double dt, Field* volumeChange) {
  current(material, "cellCouplingWork");
  out.fill(0.0);
  if (volumeChange) volumeChange->fill(0.0);
  const auto mi = static_cast<std::size_t>(material);
  const bool force = mi < cellForce_.size() && cellForceStamp_[mi] == generation_;
  const bool stress = stressForceStamp_ == generation_ && stressForce_.size() == 5 * p_.size();
  if (!force && !stress && !volumeChange) return;
  Grid& g = grid_;
  if (nodeScratch_.npts() == 0)
    nodeScratch_ = Field("node_scratch", Centering::Node, g.box(), g.velocityL.ncomp(), Grid::kGhost);
  Field& vb = nodeScratch_;
  meanNodeVelocity(g.velocity, g.velocityL, workFloor_, vb);
  if (force) addCellVectorPower(material, cellForce_[mi], vb, dt, out);
  if (!stress && !volumeChange) return;
  // The mean-stress forces: -V_p S_p : L~_p, S = iso I + ex n n (V folded into iso and ex); the
  // volume change dt V_p tr(L~_p).
  const ParticleCells& pc = particleCells(material);
  const auto vbd = components(std::as_const(vb));
  double* W = out.data();
  double* dV = volumeChange ? volumeChange->data() : nullptr;
  const auto [b, e] = p_.materialRange(material);
  const GridGeom geom = g.geom();
  const std::vector<unsigned char>& openFace = openFaceNodes();
  const bool anyOpen = stress && openAny_ && openQ_.size() == openFace.size();
  kernels::dispatch(shape_, mesh_.dim(), [&]<class S, int D>() {
    kernels::Stencil<S, D> st;
    for (std::size_t i = b; i < e; ++i) {
      static constexpr double kNoStress[5] = {0, 0, 0, 0, 0};
      const double* sf = stress ? &stressForce_[5 * i] : kNoStress;
      if (sf[0] == 0.0 && sf[1] == 0.0 && !anyOpen && !dV) continue;
      double L[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      double open = 0;  // the open-face nodes' term (addCellPressureStress): V_p q_k grad w_ip . vbar_k
      st.compute(p_, i, geom);
      st.forNodes(geom, [&](std::int64_t k, double, double gx, double gy, double gz) {
        const double gg[3] = {gx, gy, gz};
        for (int a = 0; a < D; ++a)
          for (int c = 0; c < D; ++c) L[a][c] += vbd[a][k] * gg[c];
        if (anyOpen)
          if (const unsigned char o = openFace[k])
            for (int a = 0; a < D; ++a)
              if (o & (1u << a)) open += openQ_[k] * gg[a] * vbd[a][k];
      });
      double trace = 0, nLn = 0;
      for (int a = 0; a < D; ++a) {
        trace += L[a][a];
        for (int c = 0; c < D; ++c) nLn += sf[2 + a] * L[a][c] * sf[2 + c];
      }
      W[pc.slot[i - b]] -= dt * (sf[0] * trace + sf[1] * nLn - p_.vol[i] * open);
      if (dV) dV[pc.slot[i - b]] += dt * p_.vol[i] * trace;
    }
  });
}

}  // namespace mpmice::mpm
