#pragma once
/// @brief Ghost exchange between the boxes of a Decomposition, rank to rank.
///
/// fill(): every rank's ghost layers receive the owners' values (periodic images included).
/// sumAndFill(): node (or cell) contributions that ranks accumulated in their ghost layers are
/// added into the owners' values, then the totals are copied back to every ghost layer: what MPM
/// needs after particle-to-grid. Overlaps are computed once at construction.
/// With ownExterior, the ghost layers outside the mesh (beyond non-periodic domain faces) belong
/// to the rank whose box touches that face, so contributions there are summed across ranks too
/// (wide stencils such as B-splines deposit on nodes outside the mesh).
#include <vector>

#include "core/field/field.h"
#include "core/parallel/comm.h"
#include "core/parallel/decomposition.h"

namespace mpmice::core {

class GhostExchange {
 public:
  GhostExchange(const Decomposition& decomp, const Comm& comm, Centering c, int nghost,
                bool ownExterior = false);

  /// Owners' values into ghosts (field must have the stored box of this exchange).
  void fill(Field& f) const;
  /// Ghost contributions added into owners, then owners' totals into ghosts.
  void sumAndFill(Field& f) const;
  /// Same as fill / sumAndFill for several fields at once (one message per peer).
  void fill(const std::vector<Field*>& fs) const;
  void sumAndFill(const std::vector<Field*>& fs) const;

  [[nodiscard]] const Box& storedBox() const { return stored_; }
  [[nodiscard]] const Box& ownedBox() const { return owned_; }

 private:
  /// One overlap: `mine` in this rank's index space, `theirs` the same indices in the peer's.
  struct Overlap {
    int peer;
    Box mine;
    Box theirs;
  };
  void exchange(const std::vector<Field*>& fs, bool reverseAdd) const;

  Comm comm_;
  Box stored_, owned_;
  std::vector<Overlap> recvFrom_;  // my ghosts <- peer's owned
  std::vector<Overlap> sendTo_;    // my owned -> peer's ghosts
};

}  // namespace mpmice::core
