#pragma once
/// @brief A communicator handed to a library: rank, size and the few collectives the solvers use.
///
/// Libraries receive a Comm from their program's launch layer and never reach for
/// MPI_COMM_WORLD. A Comm does not own the MPI_Comm it wraps.
#include <mpi.h>

#include <string>
#include <vector>

namespace mpmice::core {

class Comm {
 public:
  Comm() = default;
  explicit Comm(MPI_Comm c);

  [[nodiscard]] MPI_Comm raw() const { return comm_; }
  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }
  [[nodiscard]] bool root() const { return rank_ == 0; }

  [[nodiscard]] double sum(double v) const;
  [[nodiscard]] double max(double v) const;
  [[nodiscard]] double min(double v) const;
  [[nodiscard]] long long sum(long long v) const;
  [[nodiscard]] int max(int v) const;
  /// Elementwise sum of a vector over all ranks (in place).
  void sumInPlace(std::vector<double>& v) const;
  void barrier() const;
  /// The message of the lowest rank whose `mine` is not empty, on every rank ("" when every
  /// rank's is empty: then one integer reduction and nothing else). Collective.
  [[nodiscard]] std::string firstMessage(const std::string& mine) const;

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace mpmice::core
