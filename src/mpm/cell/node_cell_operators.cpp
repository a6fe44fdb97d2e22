#include "mpm/cell/node_cell_operators.h"

#include <stdexcept>
#include <string>

#include "mpm/cell/open_face_images.h"
#include "mpm/mpm_constants.h"
#include "mpm/solver/kernels.h"

namespace mpmice::mpm {

namespace {
/// The mean-stress correction's surface weight a (addCellPressureStress) below which a particle is
/// inside the solid: there it takes its own cell's pressure, not the interpolated one. Inside a
/// solid a is the node masses' noise (uniform node masses give a = 0); a particle whose stencil
/// reaches the surface's mass ramp has a ~ 0.1 .. 1. With a itself as the weight (no cut) the
/// full cells beside the added-mass slab's surface took part of their cell's pressure and its
/// period went from -0.1 % to +2.2 % (docs/coupling.md). Pinned by
/// AdiabaticPiston.CopperStaysQuietAtSmallStepsOnFinerMeshes and the added-mass and cylinder tests.
constexpr double kInteriorSurfaceWeight = 1e-3;
}  // namespace

using core::Centering;
using core::Field;

NodeCellOperators::NodeCellOperators(const core::Scene& scene, const core::Box& ownedCells, Grid& grid,
                                     const BoundaryConditions& bcs, ParticleSet& particles, ShapeKind shape,
                                     double massFloor)
    : scene_(scene),
      mesh_(scene.mesh),
      cells_(ownedCells),
      grid_(grid),
      bcs_(bcs),
      p_(particles),
      shape_(shape),
      massFloor_(massFloor),
      pRef_(kReferencePressure),
      states_(scene.materials.size()),
      nodeMass_(scene.materials.size()),
      deficit_(scene.materials.size()),
      particleCells_(scene.materials.size()),
      open_(scene.boundary, scene.mesh.dim()) {
  const std::vector<int> solids = scene.solids();
  if (!solids.empty()) pRef_ = scene.materials[solids.front()].eos.get("threshold_pressure", kReferencePressure);
}

CellCorners::CellCorners(const core::Mesh& mesh, const core::Box& nodes, const OpenFaces* open) : nodes_(nodes) {
  const int dim = mesh.dim();
  nc_ = 1 << dim;
  sy_ = nodes.length(0);
  sz_ = sy_ * nodes.length(1);
  origin_ = -(nodes.lo[0] + sy_ * nodes.lo[1] + sz_ * nodes.lo[2]);
  for (int c = 0; c < nc_; ++c)
    off_[c] = (c & 1) + (dim > 1 ? sy_ * ((c >> 1) & 1) : 0) + (dim > 2 ? sz_ * ((c >> 2) & 1) : 0);
  share_.resize(static_cast<std::size_t>(nodes.numPts()));
  core::forEach(nodes, [&](int i, int j, int k) {
    share_[static_cast<std::size_t>(nodes.index(i, j, k))] =
        open ? imageShare(mesh, *open, i, j, k) : nodeShare(mesh, i, j, k);
  });
}

const CellCorners& NodeCellOperators::corners(const Field& f, const char* what) {
  if (!corners_.nodes().ok()) corners_ = CellCorners(mesh_, grid_.box());
  if (!(f.box() == corners_.nodes()))
    throw std::logic_error(std::string("NodeCellOperators::") + what + ": node field '" + f.name() + "' is stored on " +
                           f.box().str() + ", not on the grid's node box " + corners_.nodes().str());
  return corners_;
}

const CellCorners& NodeCellOperators::imageCorners(const Field& f, const char* what) {
  if (!open_.any) return corners(f, what);
  if (!imageCorners_.nodes().ok()) imageCorners_ = CellCorners(mesh_, grid_.box(), &open_);
  if (!(f.box() == imageCorners_.nodes()))
    throw std::logic_error(std::string("NodeCellOperators::") + what + ": node field '" + f.name() + "' is stored on " +
                           f.box().str() + ", not on the grid's node box " + imageCorners_.nodes().str());
  return imageCorners_;
}

const SolidCellState& NodeCellOperators::current(int material, const char* op) const {
  const SolidCellState& cs = states_.at(material);
  if (cs.stamp != generation_) {
    const std::string m = std::to_string(material);
    throw std::logic_error(
        std::string("NodeCellOperators::") + op + ": " +
        (cs.stamp == 0 ? "no cell state of material " + m + " yet"
                       : "the cell state of material " + m + " is from step generation " +
                             std::to_string(cs.stamp) + ", this is generation " + std::to_string(generation_)) +
        ": call cellState(" + m + ") first in this step");
  }
  return cs;
}

const SolidCellState& NodeCellOperators::cellState(int material) {
  if (material < 0 || material >= static_cast<int>(scene_.materials.size()) ||
      scene_.materials[material].kind != core::MaterialKind::Solid)
    throw std::invalid_argument("NodeCellOperators::cellState: material " + std::to_string(material) +
                                " is not a solid of the scene");
  Grid& g = grid_;
  SolidCellState& cs = states_[material];
  if (cs.mass.npts() == 0) {
    cs.mass = Field("mass", Centering::Cell, cells_, 1, 0);
    cs.velocity = Field("velocity", Centering::Cell, cells_, 3, 0);
    cs.temperature = Field("temperature", Centering::Cell, cells_, 1, 0);
    cs.volume = Field("volume", Centering::Cell, cells_, 1, 0);
    cs.specificVolume = Field("specific_volume", Centering::Cell, cells_, 1, 0);
    nodeMass_[material] = Field("mass", Centering::Node, g.box(), 1, Grid::kGhost);
  }
  if (momentum_.npts() == 0) {  // scratch shared by all materials, allocated once
    momentum_ = Field("momentum", Centering::Node, g.box(), 3, Grid::kGhost);
    volumeTemperature_ = Field("volume_temperature", Centering::Node, g.box(), 2, Grid::kGhost);
  }
  // Node mass, momentum, volume and m T of this material.
  Field& nm = nodeMass_[material];
  Field& mom = momentum_;
  Field& vt = volumeTemperature_;
  const auto [b, e] = p_.materialRange(material);
  nm.fill(0.0);
  mom.fill(0.0);
  vt.fill(0.0);
  double* mp[3] = {mom.data(0), mom.data(1), mom.data(2)};
  const GridGeom geom = g.geom();
  // One stencil evaluation per particle for mass, momentum, volume and m T (the operations of
  // kernels::particlesToGrid and of the volume pass, in the same particle order: every node sum
  // gets the same terms in the same order as with two passes).
  kernels::dispatch(shape_, mesh_.dim(), [&]<class S, int D>() {
    kernels::Stencil<S, D> st;
    double* mass = nm.data();
    double* vol = vt.data(0);
    double* mt = vt.data(1);
    for (std::size_t i = b; i < e; ++i) {
      st.compute(p_, i, geom);
      const double m = p_.mass[i];
      double mv[3] = {0, 0, 0};
      for (int d = 0; d < D; ++d) mv[d] = m * p_.v[d][i];
      const double V = p_.vol[i], MT = p_.mass[i] * p_.temperature[i];
      auto deposit = [&](std::int64_t k, double w) {
        mass[k] += m * w;
        for (int d = 0; d < D; ++d) mp[d][k] += mv[d] * w;
        vol[k] += V * w;
        mt[k] += MT * w;
      };
      st.forNodes(geom, [&](std::int64_t k, double w, double, double, double) { deposit(k, w); });
      // Its zero-gradient images beyond open faces (open_face_images.h).
      forOpenFaceImages(mesh_, open_, p_, i, geom, st, [&](const kernels::Stencil<S, D>& im, const int(&shift)[3]) {
        forImageNodes(mesh_, geom, im, shift, deposit);
      });
    }
  });
  bcs_.fold(nm, Parity::Scalar);
  bcs_.fold(mom, Parity::Vector);
  bcs_.fold(vt, Parity::Scalar);
  g.sumAndFill({&nm, &mom, &vt});
  // Node-to-cell average; a cell the solid does not reach gets the absent-solid state: an absent
  // material still needs a valid state for ICE's equilibrium pressure (its volume fraction is
  // zero): the reference specific volume and, as its neighbours' temperature is not known here,
  // the reference temperature.
  const double v0 = 1.0 / scene_.materials[material].density;
  const CellCorners& cc = imageCorners(nm, "cellState");
  imageCorners(mom, "cellState");
  imageCorners(vt, "cellState");
  const double* nmd = nm.data();
  const double* momd[3] = {mom.data(0), mom.data(1), mom.data(2)};
  const double* vol = vt.data(0);
  const double* mtd = vt.data(1);
  core::forEach(cells_, [&](int i, int j, int k) {
    double m = 0, p[3] = {0, 0, 0}, V = 0, MT = 0;
    cc.forCorners(i, j, k, [&](std::int64_t n, double w) {
      m += w * nmd[n];
      for (int d = 0; d < 3; ++d) p[d] += w * momd[d][n];
      V += w * vol[n];
      MT += w * mtd[n];
    });
    const bool massive = m > massFloor_;
    const double T = massive ? MT / m : 0.0, v = massive ? V / m : 0.0;
    cs.volume(i, j, k) = V;
    if (m > 0 && v > 0) {
      cs.mass(i, j, k) = m;
      for (int d = 0; d < 3; ++d) cs.velocity(i, j, k, d) = p[d] / m;
      cs.temperature(i, j, k) = T;
      cs.specificVolume(i, j, k) = v;
    } else {  // absent solid
      cs.mass(i, j, k) = 0.0;
      for (int d = 0; d < 3; ++d) cs.velocity(i, j, k, d) = 0.0;
      cs.temperature(i, j, k) = T > 0 ? T : kReferenceTemperature;
      cs.specificVolume(i, j, k) = v0;
    }
  });
  cs.stamp = generation_;
  return cs;
}

void NodeCellOperators::cellLagrangianMomentum(int material, Field& out) {
  current(material, "cellLagrangianMomentum");
  const Field& nm = nodeMass_[material];
  const Field& vL = grid_.velocityL;
  const CellCorners& cc = imageCorners(nm, "cellLagrangianMomentum");
  imageCorners(vL, "cellLagrangianMomentum");
  const double* nmd = nm.data();
  const auto vLd = components(vL);
  const int nv = vL.ncomp();  // the mesh's directions (the others' momentum is 0)
  core::forEach(cells_, [&](int i, int j, int k) {
    double p[3] = {0, 0, 0};
    cc.forCorners(i, j, k, [&](std::int64_t n, double share) {
      const double w = share * nmd[n];
      for (int d = 0; d < nv; ++d) p[d] += w * vLd[d][n];
    });
    for (int d = 0; d < 3; ++d) out(i, j, k, d) = p[d];
  });
}

const NodeCellOperators::ParticleCells& NodeCellOperators::particleCells(int material) {
  ParticleCells& pc = particleCells_.at(material);
  if (pc.stamp == generation_) return pc;
  const auto [b, e] = p_.materialRange(material);
  pc.slot.resize(e - b);
  pc.mass.assign(static_cast<std::size_t>(cells_.numPts()), 0.0);
  for (std::size_t i = b; i < e; ++i) {
    const auto c = cellOfParticle(mesh_, p_, i, cells_);
    const auto s = cells_.index(c[0], c[1], c[2]);
    pc.slot[i - b] = s;
    pc.mass[static_cast<std::size_t>(s)] += p_.mass[i];
  }
  pc.stamp = generation_;
  return pc;
}

template <class F>
void NodeCellOperators::spreadCellVectors(int material, F&& cellVector) {
  const SolidCellState& cs = states_[material];
  const Field& nm = nodeMass_[material];
  Grid& g = grid_;
  const int dim = mesh_.dim();
  const auto [b, e] = p_.materialRange(material);
  const ParticleCells& pc = particleCells(material);
  g.ensureRemap();
  g.remap.fill(0.0);
  // Each cell's vector once (the particles of a cell read it), 0 where the solid is absent (no
  // particle there reads it).
  const double* cm = cs.mass.data();  // owned cells, no ghosts: flat index = cells_.index
  cellVector_.resize(3 * static_cast<std::size_t>(cells_.numPts()));
  core::forEach(cells_, [&](int i, int j, int k) {
    const auto s = static_cast<std::size_t>(cells_.index(i, j, k));
    for (int d = 0; d < 3; ++d) cellVector_[3 * s + d] = d < dim && cm[s] > massFloor_ ? cellVector(i, j, k, d) : 0.0;
  });
  // Cells holding particles of m: each particle takes its mass share of its cell's vector and gives
  // it to its nodes with its own shape function (the weights of its particle-to-grid transfer).
  const auto r = components(g.remap);
  const GridGeom geom = g.geom();
  kernels::dispatch(shape_, dim, [&]<class S, int D>() {
    kernels::Stencil<S, D> st;
    for (std::size_t i = b; i < e; ++i) {
      const auto s = static_cast<std::size_t>(pc.slot[i - b]);
      if (!(cm[s] > massFloor_)) continue;
      const double share = p_.mass[i] / pc.mass[s];
      double v[3] = {0, 0, 0};
      for (int d = 0; d < D; ++d) v[d] = share * cellVector_[3 * s + d];
      st.compute(p_, i, geom);
      st.forNodes(geom, [&](std::int64_t k, double w, double, double, double) {
        for (int d = 0; d < D; ++d) r[d][k] += w * v[d];
      });
    }
  });
  bcs_.fold(g.remap, Parity::Vector);
  // Cells the solid reaches through its nodes only (no particle inside): the corner nodes in
  // proportion to their mass of m (the transpose of the node-to-cell average).
  const CellCorners& cc = imageCorners(nm, "spreadCellVectors");
  imageCorners(g.remap, "spreadCellVectors");
  const double* nmd = nm.data();
  core::forEach(cells_, [&](int i, int j, int k) {
    const auto s = static_cast<std::size_t>(cells_.index(i, j, k));
    const double mc = cm[s];
    if (!(mc > massFloor_) || pc.mass[s] > 0) return;
    cc.forCorners(i, j, k, [&](std::int64_t n, double share) {
      const double w = share * nmd[n] / mc;
      for (int d = 0; d < dim; ++d) r[d][n] += w * cellVector_[3 * s + d];
    });
  });
}

void NodeCellOperators::applyCellVelocityIncrement(int material, const Field& dv) {
  const SolidCellState& cs = current(material, "applyCellVelocityIncrement");
  Grid& g = grid_;
  const int dim = mesh_.dim();
  // Node momentum increments: the cell's m_c dv spread as a cell vector.
  spreadCellVectors(material, [&](int i, int j, int k, int d) { return cs.mass(i, j, k) * dv(i, j, k, d); });
  g.sumAndFill({&g.remap});
  const double* m = g.mass.data();
  for (int d = 0; d < dim; ++d) {
    double* vl = g.velocityL.data(d);
    const double* dp = g.remap.data(d);
    for (std::int64_t k = 0; k < g.numNodes(); ++k)
      if (m[k] > massFloor_) vl[k] += dp[k] / m[k];
  }
  bcs_.apply(g.velocityL);
}

void NodeCellOperators::applyCellMomentumIncrement(int material, const Field& dp) {
  const SolidCellState& cs = current(material, "applyCellMomentumIncrement");
  if (dv_.npts() == 0) dv_ = Field("dv", Centering::Cell, cells_, 3, 0);
  if (nodeScratch_.npts() == 0)
    nodeScratch_ = Field("node_scratch", Centering::Node, grid_.box(), grid_.velocityL.ncomp(), Grid::kGhost);
  Field& def = deficit_.at(material);
  if (def.npts() == 0) def = Field("kinetic_deficit", Centering::Cell, cells_, 1, 0);
  const Field& nm = nodeMass_[material];
  const Field& vL = grid_.velocityL;
  const int dim = mesh_.dim();
  // What the cell gains at its Lagrangian velocity (ICE's exchange counts this).
  const CellCorners& cc = imageCorners(nm, "applyCellMomentumIncrement");
  imageCorners(vL, "applyCellMomentumIncrement");
  const double* nmd = nm.data();
  const auto vLd = components(vL);
  core::forEach(cells_, [&](int i, int j, int k) {
    const double m = cs.mass(i, j, k);
    double p[3] = {0, 0, 0};
    cc.forCorners(i, j, k, [&](std::int64_t n, double share) {
      for (int d = 0; d < dim; ++d) p[d] += share * nmd[n] * vLd[d][n];
    });
    double gain = 0;
    for (int d = 0; d < 3; ++d) {
      dv_(i, j, k, d) = m > 0 ? dp(i, j, k, d) / m : 0.0;
      if (m > 0 && d < dim) gain += dp(i, j, k, d) * (p[d] / m + 0.5 * dv_(i, j, k, d));
    }
    def(i, j, k) = gain;
  });
  nodeScratch_.copyRegion(vL, vL.box(), vL.box());
  applyCellVelocityIncrement(material, dv_);
  // Less what the nodes gained, booked to the cell each increment came from: a node's kinetic
  // energy change is its momentum increments times its mean velocity (v_old + v_new) / 2, each
  // increment followed from its cell (cell_coupling_work.cpp; cellVector_ holds the cells' m dv as
  // spread). Node-to-cell averaging the nodes' changes instead moved the energy of one cell's
  // increment into its neighbours (a crushing foam's top particles cooled 2 K a step by it).
  meanNodeVelocity(nodeScratch_, vL, massFloor_, nodeScratch_);
  if (forceWorkStamp_ == generation_) {
    // The forces' work is booked at the step's end velocity: a node's gain from the increments,
    // m dv . (v_old + v_new) / 2, is the forces' share dt f . dv / 2 (the particles' stress work:
    // they deform with dv) plus the increments' own, m dv . ((v_old + v_new) / 2 - dt f / (2 m)). Walls'
    // constrained components do not move and take neither (bcs_.apply zeroes them).
    const double* gm = grid_.mass.data();
    const double half = 0.5 * forceWorkDt_;
    for (int d = 0; d < dim; ++d) {
      double* o = nodeScratch_.data(d);
      const double* f = grid_.force.data(d);
      for (std::int64_t k = 0; k < grid_.numNodes(); ++k)
        if (gm[k] > workFloor_ && gm[k] > massFloor_) o[k] -= half * f[k] / gm[k];
    }
    bcs_.apply(nodeScratch_);
    forceWorkShifted_ = generation_;
  }
  if (gotScratch_.npts() == 0) gotScratch_ = Field("kinetic_got", Centering::Cell, cells_, 1, 0);
  gotScratch_.fill(0.0);
  addCellVectorPower(material, cellVector_, nodeScratch_, -1.0, gotScratch_);
  core::forEach(cells_, [&](int i, int j, int k) { def(i, j, k) += gotScratch_(i, j, k); });
}

void NodeCellOperators::addCellForce(int material, const Field& force) {
  current(material, "addCellForce");
  spreadCellVectors(material, [&](int i, int j, int k, int d) { return force(i, j, k, d); });
  if (cellForce_.size() <= static_cast<std::size_t>(material)) {
    cellForce_.resize(static_cast<std::size_t>(material) + 1);
    cellForceStamp_.resize(static_cast<std::size_t>(material) + 1, 0);
  }
  cellForce_[static_cast<std::size_t>(material)] = cellVector_;  // for cellCouplingWork
  cellForceStamp_[static_cast<std::size_t>(material)] = generation_;
  addRemapToExternalForce();
}

void NodeCellOperators::cellToParticles(const Field& cellValue, double offset, std::vector<double>& out) {
  Grid& g = grid_;
  cellToNodes(cellValue, offset);
  // Node -> particle with the particle's own shape function, normalised by the weight of the
  // nodes that hold a value.
  const double* nv = nodeValue_.data(0);
  const double* nw = nodeValue_.data(1);
  const GridGeom geom = g.geom();
  out.assign(p_.size(), 0.0);
  kernels::dispatch(shape_, mesh_.dim(), [&]<class S, int D>() {
    kernels::Stencil<S, D> st;
    for (std::size_t i = 0; i < p_.size(); ++i) {
      st.compute(p_, i, geom);
      double v = 0, w = 0;
      st.forNodes(geom, [&](std::int64_t k, double wi, double, double, double) {
        v += wi * nv[k];
        w += wi * nw[k];
      });
      out[i] = w > 0 ? v / w : 0.0;
    }
  });
}

void NodeCellOperators::cellToNodes(const Field& cellValue, double offset) {
  Grid& g = grid_;
  if (nodeValue_.npts() == 0) nodeValue_ = Field("cell_to_node", Centering::Node, g.box(), 2, Grid::kGhost);
  // Cell -> node: each node the average of the mesh cells around it (its shares sum to 1 on every
  // mesh node; component 1 keeps that sum, so nodes outside the mesh, which no cell reaches,
  // carry weight 0 and drop out of the particle interpolation).
  nodeValue_.fill(0.0);
  const CellCorners& cc = corners(nodeValue_, "cellToNodes");
  double* nv = nodeValue_.data(0);
  double* nw = nodeValue_.data(1);
  core::forEach(cells_, [&](int i, int j, int k) {
    const double v = cellValue(i, j, k) - offset;
    cc.forCorners(i, j, k, [&](std::int64_t n, double share) {
      nv[n] += share * v;
      nw[n] += share;
    });
  });
  g.sumAndFill({&nodeValue_});
  bcs_.mirror(nodeValue_, Parity::Scalar);
}

void NodeCellOperators::addCellPressureStress(const Field& pcell, double pRef) {
  cellToNodes(pcell, pRef);  // p - pRef at the nodes; the particle values are formed below
  Grid& g = grid_;
  g.ensureRemap();
  g.remap.fill(0.0);
  const auto f = components(g.remap);
  const GridGeom geom = g.geom();
  const double* nv = nodeValue_.data(0);
  const double* nw = nodeValue_.data(1);
  const double* nm = g.mass.data();
  double h = mesh_.dx(0);
  for (int d = 1; d < mesh_.dim(); ++d) h = std::min(h, mesh_.dx(d));
  // q at the open-face nodes (for cellCouplingWork too); nothing to do without open faces.
  openAny_ = false;
  const unsigned char* openFace = nullptr;
  if (open_.any) {
    const std::vector<unsigned char>& of = openFaceNodes();
    openFace = of.data();
    openQ_.assign(of.size(), 0.0);
    for (std::size_t k = 0; k < of.size(); ++k)
      if (of[k]) {
        const auto src = static_cast<std::size_t>(openSource_[k]);
        if (nw[src] > 0 && nv[src] != 0.0) openQ_[k] = nv[src] / nw[src], openAny_ = true;
      }
  }
  const bool ownCellAtSurface = scene_.coupling.surface_pressure == "cell";
  stressForce_.assign(5 * p_.size(), 0.0);  // for cellCouplingWork
  stressForceStamp_ = generation_;
  kernels::dispatch(shape_, mesh_.dim(), [&]<class S, int D>() {
    kernels::Stencil<S, D> st;
    for (std::size_t i = 0; i < p_.size(); ++i) {
      // p_p - pRef as cellToParticles gives it, from the same stencil evaluation as the force.
      st.compute(p_, i, geom);
      double qv = 0, qw = 0;
      st.forNodes(geom, [&](std::int64_t k, double wi, double, double, double) {
        qv += wi * nv[k];
        qw += wi * nw[k];
      });
      const double qNodes = qw > 0 ? qv / qw : 0.0;
      // The solid's side: the node pressure at the heaviest node of the stencil; the node mass
      // and its gradient at the particle give the surface normal and how much of a surface it is.
      double M = 0, G[3] = {0, 0, 0}, heaviest = -1, qIn = qNodes;
      st.forNodes(geom, [&](std::int64_t k, double w, double gx, double gy, double gz) {
        M += w * nm[k];
        G[0] += gx * nm[k];
        G[1] += gy * nm[k];
        G[2] += gz * nm[k];
        if (nw[k] > 0 && nm[k] > heaviest) {
          heaviest = nm[k];
          qIn = nv[k] / nw[k];
        }
      });
      const double gn = std::sqrt(G[0] * G[0] + G[1] * G[1] + G[2] * G[2]);
      const double a = M > 0 && gn > 0 ? std::min(1.0, kSurfaceLayerCells * h * gn / M) : 0.0;
      // Inside the solid (its stencil sees no surface: a below kInteriorSurfaceWeight) a particle
      // takes its own cell's pressure, the cell whose pressure force it receives (addCellForce:
      // each cell's force to its particles by mass shares); elsewhere the interpolated one, in
      // which the gas pressure falls across the surface (the cylinder's Eq. 13, docs/coupling.md),
      // unless coupling.surface_pressure is "cell": there the interpolation, which averages the
      // fluid's cells into the surface particles' stress, did net work on a soft slab's own modes
      // under water (docs/verification-coupled.md "Added mass over many periods").
      // With the interpolated pressure inside the solid as well, the piston's copper rang up at a
      // rate that does not fall with the step (FLIP: no damping but the pressure increment's,
      // ~dt K), e-fold in ~0.1 ms below CFL 0.4 at 200 cells, until the trace of air in its cells
      // followed the pressure swings to 1e9 K (docs/verification-coupled.md, "The piston stopped
      // at small steps").
      double q = qNodes;
      if (a < kInteriorSurfaceWeight || ownCellAtSurface) {
        const auto own = cellOfParticle(mesh_, p_, i, cells_);
        q = pcell(own[0], own[1], own[2]) - pRef;
      }
      // Stress added: (q - a e) I + a e n n, e = q - qIn: the excess over the solid side's pressure
      // acts along the normal only (a layer of isotropic excess would carry hoop load).
      const double V = p_.vol[i], ex = a * (q - qIn), iso = q - ex;
      double n[3] = {0, 0, 0};
      if (gn > 0)
        for (int d = 0; d < 3; ++d) n[d] = G[d] / gn;
      if (iso == 0.0 && ex == 0.0) {
        if (!openAny_) continue;
      } else {
        double* sf = &stressForce_[5 * i];
        sf[0] = V * iso, sf[1] = V * ex, sf[2] = n[0], sf[3] = n[1], sf[4] = n[2];
      }
      st.forNodes(geom, [&](std::int64_t k, double, double gx, double gy, double gz) {
        const double gg[3] = {gx, gy, gz};
        double ng = 0;
        for (int d = 0; d < D; ++d) ng += n[d] * gg[d];
        for (int d = 0; d < D; ++d) f[d][k] -= V * (iso * gg[d] + ex * n[d] * ng);
        // A node at an open face (on it, beyond it, or within the reach of the stencils inside
        // it): see openFaceNodes(). The normal component takes back the boundary term of the
        // node's value, -V_p q_k grad w_ip.
        if (!openAny_) return;
        if (const unsigned char o = openFace[k])
          for (int d = 0; d < D; ++d)
            if (o & (1u << d)) f[d][k] += V * openQ_[k] * gg[d];
      });
    }
  });
  bcs_.fold(g.remap, Parity::Vector);
  addRemapToExternalForce();
}

const std::vector<unsigned char>& NodeCellOperators::openFaceNodes() {
  const core::Box& nb = grid_.box();
  if (openFace_.size() == static_cast<std::size_t>(nb.numPts())) return openFace_;
  openFace_.assign(static_cast<std::size_t>(nb.numPts()), 0);
  openSource_.assign(static_cast<std::size_t>(nb.numPts()), 0);
  const int dim = mesh_.dim();
  core::forEach(nb, [&](int i, int j, int k) {
    int idx[3] = {i, j, k};
    unsigned char o = 0;
    for (int d = 0; d < dim; ++d) {
      const int n = mesh_.cells()[d];
      if ((open_.low[d] && idx[d] < kImageLayers) || (open_.high[d] && idx[d] > n - kImageLayers)) {
        o |= static_cast<unsigned char>(1u << d);
        idx[d] = std::clamp(idx[d], 0, n);
      }
    }
    const auto at = static_cast<std::size_t>(nb.index(i, j, k));
    openFace_[at] = o;
    openSource_[at] = nb.index(idx[0], idx[1], idx[2]);
  });
  return openFace_;
}

void NodeCellOperators::addRemapToExternalForce() {
  Grid& g = grid_;
  g.sumAndFill({&g.remap});
  for (int d = 0; d < mesh_.dim(); ++d) {
    double* fe = g.externalForce.data(d);
    const double* df = g.remap.data(d);
    for (std::int64_t k = 0; k < g.numNodes(); ++k) fe[k] += df[k];
  }
}

void NodeCellOperators::addCellEnergy(int material, const Field& energy) { addCellEnergy(material, {&energy}); }

void NodeCellOperators::addCellEnergy(int material, std::initializer_list<const Field*> energies) {
  const double cv = scene_.materials.at(material).specific_heat;
  const auto [b, e] = p_.materialRange(material);
  Grid& g = grid_;
  if (nodeScratch_.npts() == 0)
    nodeScratch_ = Field("node_scratch", Centering::Node, g.box(), g.velocityL.ncomp(), Grid::kGhost);
  if (nodeThermal_.npts() == 0) {
    nodeThermal_ = Field("node_thermal", Centering::Node, g.box(), 1, Grid::kGhost);
    nodeCooling_ = Field("node_cooling", Centering::Node, g.box(), 1, Grid::kGhost);
  }
  if (nodeEnergy_.empty()) nodeEnergy_.emplace_back("node_energy", Centering::Node, g.box(), 1, Grid::kGhost);
  // Every cell's energy goes by the transpose of the node-to-cell average that made the cell mass
  // ICE saw: to its corner nodes in proportion to share x (their particle mass of m), and from a
  // node to its particles in proportion to m_p w_ip. So every joule reaches a particle, and a
  // particle's temperature change is a weighted mean of its cells' (E_c / (m_c cv)), never more:
  // dividing a cell's energy by the mass of the particles inside it instead sent a particle that
  // carries a small part of a smeared cell's mass many times its cell's change (the added-mass
  // slab's rubber at -640 K in step 1, the seed cylinder's wall at -0.03 K at K = 0).
  // A cell's negative energy (cooling) goes the same way with the particles' thermal energy
  // m_p cv T_p in place of their mass: each particle then loses the same fraction of its thermal
  // energy, T_p (1 + sum_i w_ip E_i / W_i) with W the nodes' thermal energy, so no particle
  // crosses 0 K; and a cell's solid is cooled down to a floor only (below). With the mass
  // weights every particle lost the same dT, and a particle that stays where the cells cool every
  // step (the tip of a solid driven through a liquid, where the Lagrangian phase's energy
  // correction is negative: docs/slides.md) reached 0 K while its neighbours were at 240 K.
  // 1. The particles' mass and thermal energy at each node, m_p w_ip and m_p cv T_p w_ip summed as
  //    they are (no mirror images): the weights of the deposit below, so that a node hands out
  //    exactly what it received. One pass for all the fields (the particles do not move between them).
  Field& mw = nodeScratch_;
  mw.fill(0.0);
  nodeThermal_.fill(0.0);
  const GridGeom geom = g.geom();
  double thermal = 0, mass = 0;  // the material's thermal energy and mass on this rank
  kernels::dispatch(shape_, mesh_.dim(), [&]<class S, int D>() {
    kernels::Stencil<S, D> st;
    double* w = mw.data(0);
    double* wt = nodeThermal_.data();
    for (std::size_t i = b; i < e; ++i) {
      st.compute(p_, i, geom);
      const double m = p_.mass[i], mt = m * cv * std::max(p_.temperature[i], 0.0);
      thermal += mt;
      mass += m;
      st.forNodes(geom, [&](std::int64_t k, double wk, double, double, double) {
        w[k] += m * wk;
        wt[k] += mt * wk;
      });
    }
  });
  g.sumAndFill({&mw, &nodeThermal_});
  // The floor a cell's cooling keeps its solid above: kMinCellTemperatureShare of the material's
  // mean temperature.
  std::vector<double> totals{thermal, mass};
  if (comm_ != nullptr) comm_->sumInPlace(totals);
  const double floorHeat = totals[1] > 0 ? kMinCellTemperatureShare * totals[0] / totals[1] : 0.0;  // cv T_floor
  // 2. Each cell's energy (the fields summed in their order) to its corner nodes in proportion to
  //    their share of that mass, or of that thermal energy where the sum is negative and its nodes
  //    hold thermal energy.
  const CellCorners& cc = corners(mw, "addCellEnergy");
  const double* mwd = mw.data(0);
  const double* mtd = nodeThermal_.data();
  Field& ne = nodeEnergy_.front();
  ne.fill(0.0);
  nodeCooling_.fill(0.0);
  corners(ne, "addCellEnergy");
  double* ned = ne.data();
  double* cool = nodeCooling_.data();
  // A cell's cooling takes its solid's thermal energy (as its corner nodes share it to the cell)
  // down to the floor at most; the rest, counted, goes to every particle of the material in
  // proportion to its thermal energy (below). A fraction per step would not do: where the cells
  // cool every step it halves, and halves again (the lattice's strut tip reached 1e-13 K).
  double spread = 0;
  long capped = 0;
  core::forEach(cells_, [&](int i, int j, int k) {
    double E = 0;
    for (const Field* energy : energies) E += (*energy)(i, j, k);
    if (E == 0.0) return;
    if (E < 0) {
      double tc = 0;
      cc.forCorners(i, j, k, [&](std::int64_t n, double share) { tc += share * mtd[n]; });
      if (tc > 0) {
        double floor = 0;
        cc.forCorners(i, j, k, [&](std::int64_t n, double share) { floor += share * mwd[n] * floorHeat; });
        const double available = std::max(tc - floor, 0.0);
        if (E < -available) {
          spread += E + available;
          E = -available;
          ++capped;
        }
        if (E < 0) cc.forCorners(i, j, k, [&](std::int64_t n, double share) { cool[n] += E * share * mtd[n] / tc; });
        return;
      }
    }
    double mc = 0;
    cc.forCorners(i, j, k, [&](std::int64_t n, double share) { mc += share * mwd[n]; });
    if (!(mc > 0)) return;  // no particle reaches the cell's nodes (its mass is zero as well)
    cc.forCorners(i, j, k, [&](std::int64_t n, double share) { ned[n] += E * share * mwd[n] / mc; });
  });
  g.sumAndFill({&ne, &nodeCooling_});
  // Whether any of this rank's nodes cool (most steps of most scenes: none; the deposit below then
  // skips the cooling's division per node).
  bool cooling = false;
  for (std::int64_t n = 0, nn = nodeCooling_.npts(); n < nn && !cooling; ++n) cooling = cool[n] != 0.0;
  // The cooling beyond the cells' caps, as a fraction of the material's thermal energy.
  double everywhere = 0;
  {
    std::vector<double> v{spread, static_cast<double>(capped), totals[0]};
    if (comm_ != nullptr) {
      std::vector<double> w{v[0], v[1]};
      comm_->sumInPlace(w);
      v[0] = w[0], v[1] = w[1];
    }
    if (v[0] < 0 && v[2] > 0) {
      everywhere = v[0] / v[2];
      spreadCooling_.energy += v[0];
      spreadCooling_.cells += static_cast<long>(v[1]);
      ++spreadCooling_.steps;
    }
  }
  // 3. Each node's energy to its particles: dE_p = m_p sum_i w_ip E_i / mw_i, and the cooling
  //    dT_p = T_p sum_i w_ip C_i / W_i (T_p before the step's energy, as W was made).
  kernels::dispatch(shape_, mesh_.dim(), [&]<class S, int D>() {
    kernels::Stencil<S, D> st;
    const double* w = mw.data(0);
    for (std::size_t i = b; i < e; ++i) {
      st.compute(p_, i, geom);
      double h = 0;  // energy per unit mass of the particle
      double r = 0;  // the fraction of its thermal energy it gains (negative)
      st.forNodes(geom, [&](std::int64_t k, double wk, double, double, double) {
        if (w[k] > 0) h += wk * ned[k] / w[k];
        if (cooling && mtd[k] > 0) r += wk * cool[k] / mtd[k];
      });
      const double T0 = p_.temperature[i];
      p_.temperature[i] = T0 + h / cv + std::max(T0, 0.0) * (r + everywhere);
    }
  });
}

}  // namespace mpmice::mpm
