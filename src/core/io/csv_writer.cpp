#include "core/io/csv_writer.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace mpmice::core {

namespace {
std::string quoteIfNeeded(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}
}  // namespace

CsvWriter::CsvWriter(const Comm& comm, const std::string& path, std::vector<std::string> columns, int writerRank,
                     Mode mode, int precision)
    : columns_(std::move(columns)), path_(path), precision_(precision) {
  if (columns_.empty()) throw std::invalid_argument("CsvWriter: '" + path + "' needs at least one column");
  if (comm.rank() != writerRank) return;
  const bool continuing = mode == Mode::Append && std::filesystem::exists(path) &&
                          std::filesystem::file_size(path) > 0;
  file_.open(path, continuing ? std::ios::app : std::ios::trunc);
  if (!file_) throw std::runtime_error("CsvWriter: cannot open '" + path + "' for writing");
  out_ = &file_;
  if (!continuing) writeHeader();
}

void CsvWriter::cutForResume(const Comm& comm, const std::string& path, std::int64_t length, int writerRank) {
  std::string err;
  if (comm.rank() == writerRank) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || static_cast<std::int64_t>(size) < length || length <= 0)
      err = "--restart: the CSV file '" + path + "' " +
            (ec ? std::string("is missing") : "has " + std::to_string(size) + " bytes") + ", the checkpoint needs its first " +
            std::to_string(length);
    else
      std::filesystem::resize_file(path, static_cast<std::uintmax_t>(length));
  }
  err = comm.firstMessage(err);
  if (!err.empty()) throw std::invalid_argument(err);
}

std::int64_t CsvWriter::length() const {
  if (!out_ || path_.empty()) return 0;
  return static_cast<std::int64_t>(std::filesystem::file_size(path_));
}

CsvWriter::CsvWriter(std::ostream& os, std::vector<std::string> columns, bool active, int precision)
    : columns_(std::move(columns)), precision_(precision) {
  if (columns_.empty()) throw std::invalid_argument("CsvWriter: needs at least one column");
  if (!active) return;
  out_ = &os;
  writeHeader();
}

void CsvWriter::writeHeader() {
  for (std::size_t i = 0; i < columns_.size(); ++i) *out_ << (i ? "," : "") << quoteIfNeeded(columns_[i]);
  *out_ << '\n' << std::flush;
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument("CsvWriter" + (path_.empty() ? std::string() : " '" + path_ + "'") + ": row has " +
                                std::to_string(values.size()) + " values, the header has " +
                                std::to_string(columns_.size()) + " columns");
  if (!out_) return;
  std::string line;
  char buf[64];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.*g", precision_, values[i]);
    if (i) line += ',';
    line += buf;
  }
  *out_ << line << '\n' << std::flush;
  if (!*out_) throw std::runtime_error("CsvWriter: writing '" + path_ + "' failed");
}

}  // namespace mpmice::core
