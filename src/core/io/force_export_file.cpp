#include "core/io/force_export_file.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mpmice::core {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

[[noreturn]] void fail(const std::string& file, int line, const std::string& what) {
  throw std::invalid_argument(file + ":" + std::to_string(line) + ": " + what);
}

}  // namespace

std::array<double, 3> ForceExport::totalForce() const {
  std::array<double, 3> s{0, 0, 0};
  for (std::size_t i = 0; i < forces.size(); ++i) s[i % 3] += forces[i];
  return s;
}

std::array<double, 3> ForceExport::totalMoment(const std::array<double, 3>& o) const {
  std::array<double, 3> m{0, 0, 0};
  for (std::size_t k = 0; k < size(); ++k) {
    const double r[3] = {points[3 * k] - o[0], points[3 * k + 1] - o[1], points[3 * k + 2] - o[2]};
    const double* f = &forces[3 * k];
    m[0] += r[1] * f[2] - r[2] * f[1];
    m[1] += r[2] * f[0] - r[0] * f[2];
    m[2] += r[0] * f[1] - r[1] * f[0];
  }
  return m;
}

ForceExport parseForceExport(const std::string& text, const std::string& file) {
  ForceExport out;
  out.file = file;
  std::istringstream in(text);
  std::string raw;
  int lineNo = 0;
  std::size_t columns = 0;
  int firstDataLine = 0;
  while (std::getline(in, raw)) {
    ++lineNo;
    const std::string line = trim(raw);
    if (line.empty()) continue;
    if (line[0] == '#') {
      const std::string key = "Depth [m]:";
      const auto k = line.find(key);
      if (k != std::string::npos) {
        const std::string v = trim(line.substr(k + key.size()));
        char* end = nullptr;
        errno = 0;
        const double d = std::strtod(v.c_str(), &end);
        if (v.empty() || *end != '\0' || errno != 0 || !(d > 0) || !std::isfinite(d))
          fail(file, lineNo, "expected a depth > 0 in metres after '# Depth [m]:', got '" + v + "'");
        out.depth = d;
      }
      continue;
    }
    std::vector<double> values;
    std::size_t pos = 0;
    for (int field = 1;; ++field) {
      const auto comma = line.find(',', pos);
      const std::string tok = trim(line.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos));
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(tok.c_str(), &end);
      if (tok.empty() || *end != '\0' || errno == ERANGE)
        fail(file, lineNo, "column " + std::to_string(field) + ": expected a number, got '" + tok + "'");
      if (!std::isfinite(v))
        fail(file, lineNo, "column " + std::to_string(field) + ": expected a finite number, got '" + tok + "'");
      values.push_back(v);
      if (comma == std::string::npos) break;
      pos = comma + 1;
    }
    if (columns == 0) {
      if (values.size() < 6 || values.size() % 3 != 0)
        fail(file, lineNo, "expected x, y, z and one force vector per fluid phase (3 + 3k numbers, k >= 1), got " +
                               std::to_string(values.size()) + " numbers");
      columns = values.size();
      firstDataLine = lineNo;
    } else if (values.size() != columns) {
      fail(file, lineNo, "expected " + std::to_string(columns) + " numbers as on line " +
                             std::to_string(firstDataLine) + ", got " + std::to_string(values.size()));
    }
    out.points.insert(out.points.end(), values.begin(), values.begin() + 3);
    double f[3] = {0, 0, 0};
    for (std::size_t c = 3; c < values.size(); ++c) f[(c - 3) % 3] += values[c];
    out.forces.insert(out.forces.end(), f, f + 3);
  }
  if (columns == 0)
    fail(file, lineNo, "expected data lines (x, y, z, Fx, Fy, Fz[, ...]) after the comments; the file has none");
  out.phases = static_cast<int>((columns - 3) / 3);
  return out;
}

ForceExport readForceExport(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open())
    throw std::invalid_argument(path + ": cannot open the force export file (does it exist and is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  return parseForceExport(text.str(), path);
}

}  // namespace mpmice::core
