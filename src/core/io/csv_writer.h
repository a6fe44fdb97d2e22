#pragma once
/// @brief A small CSV writer for per-step summaries: conservation monitors, iteration logs, probes.
///
/// The header line names the columns; each row() writes one line of numbers (as many as columns,
/// formatted with `%.<precision>g`, default 12 significant digits) and flushes it, so a crashed
/// run keeps every row written before the crash. Only the rank it is told to write on touches the
/// file; on every other rank the writer is inactive and row() only checks the column count. Append
/// mode continues an existing file (a restart) without repeating the header. Writing to a given
/// std::ostream (stdout, a test's string stream) works the same way.
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

#include "core/parallel/comm.h"

namespace mpmice::core {

class CsvWriter {
 public:
  enum class Mode { Truncate, Append };

  /// Writes `path` on rank `writerRank` of comm only.
  CsvWriter(const Comm& comm, const std::string& path, std::vector<std::string> columns, int writerRank = 0,
            Mode mode = Mode::Truncate, int precision = 12);
  /// A restart, before opening `path` in Append mode: cuts the file to its first `length` bytes
  /// (what length() gave at the checkpoint; rows written after it are dropped, so the series has
  /// no duplicated or lost row). On writerRank; throws std::invalid_argument on every rank, naming
  /// the file, when it is missing or shorter than that. Collective.
  static void cutForResume(const Comm& comm, const std::string& path, std::int64_t length, int writerRank = 0);
  /// Writes to `os` (which must outlive the writer) when `active`.
  CsvWriter(std::ostream& os, std::vector<std::string> columns, bool active = true, int precision = 12);

  /// One row; throws std::invalid_argument when the count differs from the number of columns.
  void row(const std::vector<double>& values);
  void row(std::initializer_list<double> values) { row(std::vector<double>(values)); }

  [[nodiscard]] const std::vector<std::string>& columns() const { return columns_; }
  [[nodiscard]] bool active() const { return out_ != nullptr; }
  [[nodiscard]] const std::string& path() const { return path_; }
  /// Bytes written to the file so far (every row flushed); 0 where the writer is inactive.
  [[nodiscard]] std::int64_t length() const;

 private:
  void writeHeader();

  std::vector<std::string> columns_;
  std::string path_;
  std::ofstream file_;
  std::ostream* out_ = nullptr;
  int precision_ = 12;
};

}  // namespace mpmice::core
