#include "core/io/time_series.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace mpmice::core {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  for (;;) {
    const auto comma = line.find(',', pos);
    out.push_back(trim(line.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos)));
    if (comma == std::string::npos) return out;
    pos = comma + 1;
  }
}

}  // namespace

TimeSeries readTimeSeries(std::istream& in, const std::string& column, const std::string& what) {
  std::string raw;
  int lineNo = 0;
  std::vector<std::string> head;
  std::string headLine;
  std::size_t ct = 0, cu = 0;
  TimeSeries s;
  while (std::getline(in, raw)) {
    ++lineNo;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> c = cells(line);
    if (head.empty()) {
      head = c;
      headLine = line;
      auto find = [&](const std::string& name) {
        const auto it = std::find(head.begin(), head.end(), name);
        if (it == head.end())
          throw std::invalid_argument(what + ":" + std::to_string(lineNo) + ": no column '" + name +
                                      "' in the header '" + headLine + "'");
        return static_cast<std::size_t>(it - head.begin());
      };
      ct = find("time");
      cu = find(column);
      continue;
    }
    auto num = [&](std::size_t k) {
      const std::string at = what + ":" + std::to_string(lineNo) + ": column " + std::to_string(k + 1) + " ('" + head[k] + "')";
      if (k >= c.size()) throw std::invalid_argument(at + ": missing (the line has " + std::to_string(c.size()) + " columns)");
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(c[k].c_str(), &end);
      if (c[k].empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        throw std::invalid_argument(at + ": expected a finite number, got '" + c[k] + "'");
      return v;
    };
    const double t = num(ct), u = num(cu);
    if (!s.t.empty() && t < s.t.back())
      throw std::invalid_argument(what + ":" + std::to_string(lineNo) + ": time " + c[ct] + " is before the line above's");
    s.t.push_back(t);
    s.u.push_back(u);
  }
  if (head.empty()) throw std::invalid_argument(what + ": no header line (expected the column names, 'time' among them)");
  return s;
}

TimeSeries readTimeSeriesFile(const std::string& path, const std::string& column) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read the file");
  return readTimeSeries(in, column, path);
}

}  // namespace mpmice::core
