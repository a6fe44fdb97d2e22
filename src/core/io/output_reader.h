#pragma once
/// @brief Reads back one output step written by OutputWriter: attributes, grid fields, particles.
///
/// Open serially (any process on its own, e.g. a post-processing tool or a test on rank 0) or
/// collectively over a Comm (MPI-IO; every read call is then collective: all ranks call it, each
/// with its own range or box). Whole datasets come back as a global array in C order with their
/// shape ((nz, ny, nx[, ncomp]) for grid fields, (n[, ncomp]) for particles). readFieldInto()
/// restores a Field's owned region for a restart; particle ranges restore a rank's particles
/// (rank_counts gives the counts each writing rank had).
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/field/field.h"
#include "core/mesh/mesh.h"
#include "core/parallel/comm.h"

namespace mpmice::core {

class H5File;

class OutputReader {
 public:
  struct Array {
    std::vector<double> values;
    std::vector<std::int64_t> shape;
  };

  /// Serial open (read-only).
  explicit OutputReader(const std::string& path);
  /// Collective open (read-only) over comm.
  OutputReader(const Comm& comm, const std::string& path);
  ~OutputReader();
  OutputReader(OutputReader&&) noexcept;
  OutputReader& operator=(OutputReader&&) noexcept;

  [[nodiscard]] double time() const;
  [[nodiscard]] int step() const;
  [[nodiscard]] int dim() const;
  /// The mesh the file was written on (dim, origin, spacing, cells).
  [[nodiscard]] Mesh mesh() const;
  /// Periodic directions of the decomposition the file was written with.
  [[nodiscard]] std::array<bool, 3> periodic() const;
  /// Ranks that wrote the file.
  [[nodiscard]] int numRanks() const;

  [[nodiscard]] std::vector<std::string> gridFieldNames(Centering c) const;
  [[nodiscard]] bool hasGridField(Centering c, const std::string& name) const;
  /// The whole global dataset /grid/<cell|node>/<name>.
  [[nodiscard]] Array readGridField(Centering c, const std::string& name) const;
  /// Reads the region `owned` of the dataset named f.name() (f's centering) into f, all components.
  /// f must store `owned` and have the dataset's component count.
  void readFieldInto(Field& f, const Box& owned) const;

  [[nodiscard]] bool hasParticles() const;
  /// Particle arrays (position first, then the others in name order).
  [[nodiscard]] std::vector<std::string> particleArrayNames() const;
  [[nodiscard]] std::vector<std::int64_t> particleCountsPerRank() const;
  [[nodiscard]] Array readParticleArray(const std::string& name) const;
  /// Rows first .. first+count-1 of /particles/<name>.
  [[nodiscard]] Array readParticleArray(const std::string& name, std::int64_t first, std::int64_t count) const;

 private:
  Array readBlock(const std::string& dataset, const std::vector<std::int64_t>& start,
                  const std::vector<std::int64_t>& count) const;
  [[nodiscard]] std::vector<std::int64_t> shapeOf(const std::string& dataset) const;

  std::unique_ptr<H5File> file_;
};

}  // namespace mpmice::core
