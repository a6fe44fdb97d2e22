#pragma once
/// @brief The MPM-ICE node-cell transfer operators of libmpm, in one place.
///
/// ICE lives on cell centres, MPM on nodes and particles. Everything that moves a quantity between
/// the two sits here, written once on two helpers:
///   cellOfParticle()   the (clamped) mesh cell of a particle
///   forCellNodes()     the node-to-cell average: the corner nodes of a cell with each node's share
///                      (1 / number of mesh cells around it, so mass is conserved on mesh faces)
/// and the operators built on them, in the order of the MPM-ICE step:
///   cellState(m)                    cell mass, velocity, temperature, volume, specific volume of
///                                   solid m (absent-solid state where it does not reach)
///   addCellPressureStress(p)        the mean-stress force: sigma + (p - p_ref) I, p interpolated to
///                                   the particle (its own cell's inside the solid); the excess over
///                                   the solid side's pressure along the surface normal only
///   addCellForce(m, F)              a cell force to the particles of m in the cell (mass shares),
///                                   each to its nodes with its own shape function
///   cellLagrangianMomentum(m, out)  the node-to-cell average of m v_L
///   cellCouplingWork(m, out, dt)    the work the coupling forces did on the nodes, booked to the
///                                   cell each force came from (cell_coupling_work.cpp)
///   applyCellMomentumIncrement(m)   the exchange momentum / cell mass, spread to the nodes; the
///                                   kinetic energy the nodes did not take (kineticDeficit(m)),
///                                   booked to the cell each increment came from
///   addCellEnergy(m, E)             heat to the particles, by the transpose of the node-to-cell
///                                   average (every joule reaches a particle, none gets more)
///
/// Per-step data: cellState(m) and the node masses behind it carry the step generation they were
/// computed in (newStep() starts a generation: MpmSolver::beginStep calls it). Every operator that
/// uses them throws std::logic_error, naming itself, when they come from another step.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "core/field/field.h"
#include "core/mesh/box.h"
#include "core/mesh/mesh.h"
#include "core/scene/scene.h"
#include "mpm/cell/cell_state.h"
#include "mpm/grid/boundary_conditions.h"
#include "mpm/grid/grid.h"
#include "mpm/particles/particle_set.h"
#include "mpm/shape/shape_function.h"

namespace mpmice::mpm {

/// The mesh cell coordinate of position x in direction d (floor; not clamped).
inline int cellCoordinate(const core::Mesh& mesh, int d, double x) {
  return static_cast<int>(std::floor((x - mesh.origin()[d]) / mesh.dx(d)));
}

/// The mesh cell of particle i, clamped into `within` in the mesh's directions (0 beyond them).
inline std::array<int, 3> cellOfParticle(const core::Mesh& mesh, const ParticleSet& p, std::size_t i,
                                         const core::Box& within) {
  std::array<int, 3> c{0, 0, 0};
  for (int d = 0; d < mesh.dim(); ++d)
    c[d] = std::clamp(cellCoordinate(mesh, d, p.x[d][i]), within.lo[d], within.hi[d]);
  return c;
}

/// The open faces of the mesh, per direction.
struct OpenFaces {
  std::array<bool, 3> low{false, false, false}, high{false, false, false};
  bool any = false;
  OpenFaces() = default;
  OpenFaces(const std::array<core::BoundarySpec, 6>& faces, int dim) {
    for (int d = 0; d < dim; ++d) {
      low[d] = core::isOpenBoundary(faces[2 * d].type);
      high[d] = core::isOpenBoundary(faces[2 * d + 1].type);
      any = any || low[d] || high[d];
    }
  }
  /// True when node index idx in direction d lies on an open face.
  [[nodiscard]] bool onFace(const core::Mesh& mesh, int d, int idx) const {
    return (low[d] && idx == 0) || (high[d] && idx == mesh.cells()[d]);
  }
};

/// The node-to-cell share of node (i, j, k) with the images: 1/2 per direction at an interior node
/// and at a node on an open face, 1 at a node on another mesh face (nodeShare otherwise).
inline double imageShare(const core::Mesh& mesh, const OpenFaces& of, int i, int j, int k) {
  const int idx[3] = {i, j, k};
  double w = 1.0;
  for (int d = 0; d < mesh.dim(); ++d)
    if ((idx[d] > 0 && idx[d] < mesh.cells()[d]) || of.onFace(mesh, d, idx[d])) w *= 0.5;
  return w;
}


/// Share of a node's value that goes to each mesh cell around it (1 / number of such cells).
inline double nodeShare(const core::Mesh& mesh, int i, int j, int k) {
  const int idx[3] = {i, j, k};
  double w = 1.0;
  for (int d = 0; d < mesh.dim(); ++d)
    if (idx[d] > 0 && idx[d] < mesh.cells()[d]) w *= 0.5;
  return w;
}

/// The node-to-cell average: calls f(ni, nj, nk, share) for each corner node of cell (i, j, k).
template <class F>
void forCellNodes(const core::Mesh& mesh, int i, int j, int k, F&& f) {
  const int dim = mesh.dim(), nc = 1 << dim;
  for (int c = 0; c < nc; ++c) {
    const int ni = i + (c & 1), nj = j + (dim > 1 ? (c >> 1) & 1 : 0), nk = k + (dim > 2 ? (c >> 2) & 1 : 0);
    f(ni, nj, nk, nodeShare(mesh, ni, nj, nk));
  }
}

/// forCellNodes by flat offsets into node fields stored on one box (the grid's node fields): the
/// same corners in the same order with the same shares, the shares kept per node and the corners
/// as offsets from the cell's first corner, so a cell loop reads the fields' data directly.
class CellCorners {
 public:
  CellCorners() = default;
  /// With `open` (the images' average, open_face_images.h): imageShare instead of nodeShare.
  CellCorners(const core::Mesh& mesh, const core::Box& nodes, const OpenFaces* open = nullptr);
  [[nodiscard]] const core::Box& nodes() const { return nodes_; }
  /// f(n, share) for each corner node of cell (i, j, k), n the flat index in a field on nodes().
  template <class F>
  void forCorners(int i, int j, int k, F&& f) const {
    const std::int64_t n0 = origin_ + i + sy_ * j + sz_ * k;
    for (int c = 0; c < nc_; ++c) {
      const std::int64_t n = n0 + off_[c];
      f(n, share_[static_cast<std::size_t>(n)]);
    }
  }

 private:
  core::Box nodes_;
  int nc_ = 0;
  std::int64_t off_[8] = {}, sy_ = 0, sz_ = 0, origin_ = 0;
  std::vector<double> share_;
};

class NodeCellOperators {
 public:
  /// References into the solver that owns this (they must outlive it). `ownedCells`: this rank's
  /// cells; `massFloor`: below it a node or cell has no velocity (kMassFloorFraction x the
  /// smallest particle mass).
  NodeCellOperators(const core::Scene& scene, const core::Box& ownedCells, Grid& grid, const BoundaryConditions& bcs,
                    ParticleSet& particles, ShapeKind shape, double massFloor);

  /// Starts a new step generation: per-step data of the previous one is refused from now on.
  void newStep() { ++generation_; }
  [[nodiscard]] std::uint64_t generation() const { return generation_; }
  /// p_ref of the mean-stress correction: the first solid's EOS threshold_pressure (the pressure
  /// at which the solids are stress-free), kReferencePressure when it gives none.
  [[nodiscard]] double referencePressure() const { return pRef_; }

  /// Cell-centred state of solid material m (an extra particle-to-grid pass of that material),
  /// with the absent-solid state in cells it does not reach. Needs the node mass of this step's
  /// particle-to-grid pass (the grid's). Throws std::invalid_argument if m is not a solid.
  const SolidCellState& cellState(int material);
  /// Per-cell Lagrangian momentum of material m: the node-to-cell average of m_node v_L (after the
  /// grid update; needs cellState(m) this step).
  void cellLagrangianMomentum(int material, core::Field& out);
  /// Per-cell work [J] of the coupling forces (the grid's externalForce) on the nodes in this
  /// step's grid update (Grid::externalWork), node-to-cell averaged and shared among the solids in
  /// proportion to their node mass: sums over the cells to the nodes' total (after updateGrid).
  /// The work [J] the coupling forces of this step (addCellForce, addCellPressureStress) did on
  /// material m, per owned cell, booked to the cell the force came from (cell_coupling_work.cpp):
  /// each particle's share of its cell's pressure force and its mean-stress force, times the
  /// mean node velocity (v + v_L) / 2 at its stencil nodes, dt times; a cell without particles
  /// of m, its force on the corner nodes. Summed over cells and materials it is the nodes' work
  /// sum_i dt f_i . (v_i + v_L,i) / 2 that the grid update realised. After updateGrid.
  /// `volumeChange` (optional, owned cells): the solid's own volume change over the step in each
  /// cell, dt sum_p V_p tr(L~_p) over m's particles in it, L~_p the gradient of the same mean node
  /// velocity (the volume the mean-stress work above acts on; ICE's Lagrangian phase lets the
  /// cell's fluids take the rest of the cell's volume change, docs/coupling.md).
  void cellCouplingWork(int material, core::Field& out, double dt, core::Field* volumeChange = nullptr);
  /// The node mass below which the grid update does not accelerate a node (and the coupling
  /// forces do no work there): MpmSolver's floor.
  void setWorkMassFloor(double floor) { workFloor_ = floor; }
  /// Adds per-cell velocity increments of material m (owned cells) to the Lagrangian node velocity:
  /// the momentum m_cell dv spread as addCellForce spreads a force. Collective.
  void applyCellVelocityIncrement(int material, const core::Field& dv);
  /// The same for per-cell momentum increments [kg m/s] (ICE's exchange momentum): divided by the
  /// cell mass of m (0 where it is absent), then applyCellVelocityIncrement. Collective.
  void applyCellMomentumIncrement(int material, const core::Field& dp);
  /// Per cell [J], after applyCellMomentumIncrement(m): the kinetic energy a cell of m gains from
  /// its increment dp at its Lagrangian velocity u_L (dp . u_L + |dp|^2 / (2 m): what ICE's
  /// exchange counts) less what the nodes gained (node-to-cell average of the node kinetic
  /// energy change). The nodes take a smoothed increment (each node the mass-weighted mean of its
  /// cells'), and walls stop constrained components, so they take less: the solid gets the
  /// difference as heat (addCellEnergy), and the step stays conservative.
  /// With bookForceWorkAtStepEnd(dt) this step, what the nodes gained is counted at the node
  /// velocity less dt f / (2 m) (f the grid's internal, body and load force, m the node mass; nodes
  /// above the work floor, unconstrained components): the increments' share of the forces' work,
  /// dt f . dv / 2 at each node, goes to the stress work instead of to the heat.
  [[nodiscard]] const core::Field& kineticDeficit(int material) const { return deficit_.at(material); }
  /// The grid forces' work of this step is counted at the node velocity the step ends with, after
  /// the exchange's increments (the particles deform with them; MPM's grid count of the stress
  /// work takes that velocity, and the models' own count follows the deformation):
  /// MpmSolver::updateGrid calls this with the step's dt, and applyCellMomentumIncrement then
  /// books the increments' share of the forces' work (kineticDeficit) to the stress work rather
  /// than to the heat, whichever count mpm.stress_work reports. For this step only.
  void bookForceWorkAtStepEnd(double dt) {
    forceWorkDt_ = dt;
    forceWorkStamp_ = generation_;
  }
  /// applyCellMomentumIncrement booked a share of the forces' work this step (MpmSolver's ledger
  /// follows the forces' work to the end velocity then).
  [[nodiscard]] bool forceWorkShifted() const { return forceWorkShifted_ == generation_; }
  /// Adds per-cell forces on material m (owned cells, 3 components) to the external node force:
  /// each cell's force shared among the particles of m in it in proportion to their mass, each
  /// share given to the particle's nodes with its own shape function (the same weights as its
  /// particle-to-grid transfer, so the load reaches the particles where they are; a cell's force
  /// used to go to its corner nodes by node mass, which at a surface put a fifth of the seed
  /// cylinder's load a cell deep into the wall). A cell the solid reaches only through its nodes
  /// (no particle inside) keeps the corner-node-mass transpose. The total force is kept. After
  /// cellState(m). Collective.
  void addCellForce(int material, const core::Field& force);
  /// The mean-stress correction: the internal force of every particle uses sigma + (p_p - pRef) I,
  /// p_p the cell pressure interpolated to the particle (cellToParticles: cells -> nodes -> the
  /// particle's shape function, as Uintah's MPMICE does; a particle in a surface cell then sees
  /// the pressure gradient across the surface instead of one cell's value: Eq. 13 error of the
  /// seed cylinder 0.0845 -> 0.0733 at dx 0.025, docs/coupling.md), except inside the solid (the
  /// surface weight a below kInteriorSurfaceWeight), where it is the pressure of the particle's own
  /// cell (the cell whose pressure force it receives, addCellForce): the interpolated one made the
  /// piston's copper ring up at small steps (docs/verification-coupled.md, "The piston stopped at
  /// small steps"). Adds -sum_p V_p S_p grad w_ip to the external node force, S_p = (q - a e) I +
  /// a e n n with q = p_p - pRef, e = q - q_in the excess over the node value at the heaviest node
  /// of the particle's stencil (the solid's side),
  /// n the normal of the node mass and a in [0, 1] how much of a surface the particle is
  /// (kSurfaceLayerCells). The gas pressure the interpolation carries into the surface particles
  /// then pushes along the normal only: as an isotropic stress that layer carried hoop load and
  /// left the wall 1.3 % (dx 0.025) to 2.8 % (dx 0.05) short of the load (docs/coupling.md). A
  /// uniform pressure stays isotropic. Collective.
  void addCellPressureStress(const core::Field& cellPressure, double pRef);
  void addCellPressureStress(const core::Field& cellPressure) { addCellPressureStress(cellPressure, pRef_); }
  /// A cell-centred scalar (owned cells) minus `offset`, interpolated to every particle: each node
  /// takes the average of the mesh cells around it, each particle the node values weighted by
  /// its shape function (renormalised over the nodes inside the mesh; mirror images beyond
  /// symmetry planes). Reproduces a linear field at particles whose stencil nodes are interior
  /// mesh nodes. Collective.
  void cellToParticles(const core::Field& cellValue, double offset, std::vector<double>& out);
  /// Adds per-cell internal energy [J] of material m (owned cells; e.g. ICE's exchange heat) to its
  /// particles by the transpose of the node-to-cell average that made ICE's cell mass: to its
  /// corner nodes in proportion to their particle mass of m, from a node to its particles in
  /// proportion to m_p w_ip. No energy is lost (a cell without particles of its own still hands
  /// it on) and a particle's temperature change is a weighted mean of its cells' dE / (m_c cv),
  /// never more (the cell mass ICE sees is smeared over the surface cells). A cooling cell goes by
  /// thermal energy instead (below). Collective.
  void addCellEnergy(int material, const core::Field& energy);
  /// The same for several fields at once: their per-cell sum (one pass over the particles for the
  /// node weights, one for the deposit). A cell whose sum is negative (cooling) gives it by the
  /// particles' thermal energy m_p cv T_p instead of their mass, and down to the floor of
  /// kMinCellTemperatureShare of the material's mean temperature; the rest to the whole material.
  void addCellEnergy(int material, std::initializer_list<const core::Field*> energies);
  /// The communicator of addCellEnergy's sums over the ranks (the solver's; it must outlive this).
  void setComm(const core::Comm& comm) { comm_ = &comm; }
  /// The cooling addCellEnergy gave to whole materials because a cell's was beyond
  /// kMinCellTemperatureShare of the material's mean temperature (run totals; the same on every rank).
  struct SpreadCooling {
    double energy = 0;  // [J], <= 0
    long cells = 0, steps = 0;
  };
  [[nodiscard]] const SpreadCooling& spreadCooling() const { return spreadCooling_; }
  /// The face transport of the node-to-cell average of material m's mass (solid_face_transport.cpp):
  /// per cell face normal to d, at the low face of each owned cell (component d, 3 components),
  /// the face density D_f = sum_p m_p H'_f(x_p,d) g_f(x_p) / A_f [kg/m^3] and the face mass flux
  /// F_f = sum_p m_p v_p,d H'_f(x_p,d) g_f(x_p) / A_f [kg/(m^2 s)]. H_f(x) is the share of a
  /// particle at x that the node-to-cell average gives to the cells above face f in d, g_f its
  /// share in the face's row of cells in the other directions, A_f the face area. So the rate of
  /// change of a cell's mass as the particles move at v_p is exactly the flux F into it through
  /// its faces less the flux out (uniform interior; the mirror images at walls are left out), and
  /// D_f times the solid's specific volume is the fraction of the face the smeared solid covers
  /// (1 inside a uniform solid). Collective.
  void solidFaceTransport(int material, core::Field& density, core::Field& flux);

 private:
  /// The node-to-cell corners of the node fields (all stored on the grid's node box), made on
  /// first use; throws std::logic_error naming `what` if field f is stored on another box.
  const CellCorners& corners(const core::Field& f, const char* what);
  /// The same corners with the shares of the average of the solid's own node fields, whose open-face
  /// nodes carry the zero-gradient images (open_face_images.h; every node-to-cell average of
  /// nodeMass_ and of the fields deposited with it, and their transposes). Equal to corners()
  /// without open faces.
  const CellCorners& imageCorners(const core::Field& f, const char* what);
  /// The cell state of m, checked to be of this step generation (else std::logic_error naming op).
  const SolidCellState& current(int material, const char* op) const;
  /// nodeValue_ = (the average of the cells around each node of cellValue - offset, the sum of
  /// their shares): the first half of cellToParticles.
  void cellToNodes(const core::Field& cellValue, double offset);
  /// The owned cell of each particle of material m and each owned cell's mass of them, for this
  /// step generation (computed on the first call of the step: the particles move only in the
  /// grid-to-particle pass, which ends the step).
  struct ParticleCells {
    std::uint64_t stamp = 0;
    std::vector<std::int64_t> slot;  // per particle of m (from its range's start): cells_.index
    std::vector<double> mass;        // per owned cell
  };
  const ParticleCells& particleCells(int material);
  /// Spreads per-cell vectors cellVector(i, j, k, d) of material m into the grid's remap field
  /// (not summed across ranks): see addCellForce.
  template <class F>
  void spreadCellVectors(int material, F&& cellVector);
  /// Sums the grid's remap field across ranks and adds its first dim components to externalForce.
  void addRemapToExternalForce();
  /// Per node of the grid's box: bit d set when the node lies at an open mesh face normal to d
  /// (core::isOpenBoundary(): free or outflow, where ICE's ghost cells continue its fields with zero
  /// gradient and MPM leaves the nodes alone): beyond it, on it, or within kImageLayers - 1 node
  /// layers inside it (the nodes whose stencil support crosses the face, B-splines included). The
  /// solid reaching such a face continues beyond it as far as ICE is concerned, so ICE's pressure
  /// force -V theta grad p there uses the cell's own pressure on the boundary face; the mean-stress
  /// correction, which must cancel it inside the solid, then has no boundary term there either: at
  /// these nodes its normal component is the gradient form -sum_p V_p (S_p - q_k I) grad w_ip, q_k
  /// the node's value (beyond the face: at its nearest face node, zero gradient), zero for a
  /// uniform q (also after the solid moved along the normal). The weak form left -q_k times the
  /// nodes' area on them, an unbalanced force A (p_0 - p_1) on a plate whose boundary rows differ
  /// in pressure, which grew from round-off (docs/coupling.md "Open faces").
  /// openSource_: the flat index of the node whose value q_k is.
  const std::vector<unsigned char>& openFaceNodes();
  /// out = (a + b) / 2 at the nodes whose mass is above floor, 0 elsewhere, the mirror images
  /// beyond symmetry planes filled (the velocity a folded node force meets): cell_coupling_work.cpp.
  void meanNodeVelocity(const core::Field& a, const core::Field& b, double floor, core::Field& out) const;
  /// Adds scale x the power of the cell vectors vec (3 per owned cell, as spreadCellVectors spread
  /// them for material m) against the node velocity vbar, booked to the cell each vector came
  /// from: sum_{p in c} (m_p / M_c) vec_c . sum_i w_ip vbar_i, or for a cell without particles of
  /// m its corner nodes' share: cell_coupling_work.cpp.
  void addCellVectorPower(int material, const std::vector<double>& vec, const core::Field& vbar, double scale,
                          core::Field& out);

  const core::Scene& scene_;
  const core::Mesh& mesh_;
  core::Box cells_;
  Grid& grid_;
  const BoundaryConditions& bcs_;
  ParticleSet& p_;
  ShapeKind shape_;
  double massFloor_;
  double pRef_;
  std::uint64_t generation_ = 1;  // 0: the stamp of a state never computed
  std::vector<SolidCellState> states_;    // per scene material (allocated on first use)
  std::vector<core::Field> nodeMass_;     // node mass of each material (behind its cell state)
  core::Field momentum_, volumeTemperature_;  // cellState() scratch (node momentum; V, m T)
  core::Field dv_, gotScratch_;                // applyCellMomentumIncrement() scratch
  core::Field nodeValue_;                      // cellToParticles() node value and weight
  core::Field nodeScratch_;                    // applyCellMomentumIncrement(), addCellEnergy() scratch
  std::vector<core::Field> nodeEnergy_;        // addCellEnergy() scratch (one field)
  core::Field nodeThermal_, nodeCooling_;      // addCellEnergy(): the nodes' thermal energy, their cooling
  const core::Comm* comm_ = nullptr;           // setComm(): addCellEnergy's sums over the ranks
  SpreadCooling spreadCooling_;
  std::vector<core::Field> deficit_;           // per material: kineticDeficit()
  std::vector<ParticleCells> particleCells_;   // per material: spreadCellVectors()
  std::vector<double> cellVector_;             // spreadCellVectors() scratch (3 per owned cell)
  core::Field faceTransport_;                  // solidFaceTransport() node-indexed faces (D, F per d)
  CellCorners corners_;                        // corners(): the node-to-cell average by flat offsets
  CellCorners imageCorners_;                   // imageCorners(): with the images at open faces
  OpenFaces open_;                             // the mesh's open faces
  // cellCouplingWork(): the forces of this step as they were spread (stamp: the generation).
  std::vector<std::vector<double>> cellForce_;   // per material: addCellForce()'s cell vectors (3 per owned cell)
  std::vector<std::uint64_t> cellForceStamp_;
  std::vector<double> stressForce_;              // per particle: V iso, V ex, n (addCellPressureStress)
  std::uint64_t stressForceStamp_ = 0;
  double workFloor_ = 0;
  double forceWorkDt_ = 0;            // bookForceWorkAtStepEnd(): the step's dt
  std::uint64_t forceWorkStamp_ = 0;  // and its generation
  std::uint64_t forceWorkShifted_ = 0;  // the generation applyCellMomentumIncrement booked it in
  std::vector<unsigned char> openFace_;        // openFaceNodes()
  std::vector<std::int64_t> openSource_;       // openFaceNodes(): the node q_k is read at
  std::vector<double> openQ_;                  // addCellPressureStress: q at the open-face nodes (else 0)
  bool openAny_ = false;                       // some open-face node has q != 0 this step
};

}  // namespace mpmice::mpm
