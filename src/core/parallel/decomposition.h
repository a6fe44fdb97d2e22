#pragma once
/// @brief Splits the mesh's cells into one box per rank of a communicator.
///
/// The ranks form a process grid (px x py x pz, chosen to keep boxes near-cubic and every box
/// non-empty); each rank owns the cells of its box exactly once. Node ownership follows cells:
/// a rank owns the nodes at the low corner of its cells, and the rank at the upper domain face
/// also owns the closing layer of nodes (unless that direction is periodic, where node n is node 0).
#include <vector>

#include "core/mesh/mesh.h"

namespace mpmice::core {

enum class Centering { Cell, Node };

class Decomposition {
 public:
  Decomposition() = default;
  /// periodic[d]: direction d wraps around (only d < mesh.dim() count).
  Decomposition(const Mesh& mesh, int nranks, std::array<bool, 3> periodic = {false, false, false});

  [[nodiscard]] const Mesh& mesh() const { return mesh_; }
  [[nodiscard]] int numRanks() const { return static_cast<int>(cellBoxes_.size()); }
  [[nodiscard]] const IntVect& processGrid() const { return pgrid_; }
  [[nodiscard]] const std::array<bool, 3>& periodic() const { return periodic_; }
  /// Cells owned by rank r.
  [[nodiscard]] const Box& cellBox(int r) const { return cellBoxes_[r]; }
  /// Indices owned by rank r for the given centering.
  [[nodiscard]] Box ownedBox(int r, Centering c) const;
  /// Index range rank r stores for a field with ng ghost layers (owned region grown; for nodes
  /// the surrounding nodes of its cells, grown).
  [[nodiscard]] Box storedBox(int r, Centering c, int ng) const;
  /// Global index range of the centering (all nodes or all cells).
  [[nodiscard]] Box domainBox(Centering c) const;
  /// Number of distinct indices of that centering (node n is node 0 in periodic directions).
  [[nodiscard]] IntVect period(Centering c) const;
  /// Rank that owns cell (i,j,k); -1 outside the mesh.
  [[nodiscard]] int ownerOfCell(int i, int j, int k) const;

 private:
  Mesh mesh_;
  IntVect pgrid_{1, 1, 1};
  std::array<bool, 3> periodic_{false, false, false};
  std::vector<Box> cellBoxes_;
  std::array<std::vector<int>, 3> cuts_;  // cuts_[d][p] = first cell index of slab p; size p+1
};

/// Chooses a process grid for nranks over cells (all factors, the one with the least surface).
IntVect chooseProcessGrid(const IntVect& cells, int dim, int nranks);

}  // namespace mpmice::core
