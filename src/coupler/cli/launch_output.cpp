#include "coupler/cli/launch_output.h"

#include <cstdio>
#include <regex>

namespace mpmice::coupler {

namespace {

constexpr std::size_t kTextKept = 1u << 20;
constexpr std::size_t kFluidTail = 20;

enum class Tag { No, Yes, Incomplete };

/// "[<digits>,<digits>]<word>:" at s[pos]: its world rank, stream and length.
Tag matchTag(const std::string& s, std::size_t pos, int& rank, int& stream, std::size_t& len) {
  std::size_t i = pos;
  auto end = [&] { return i >= s.size(); };
  if (s[i] != '[') return Tag::No;
  ++i;
  auto digits = [&](long& v) -> Tag {
    const std::size_t start = i;
    v = 0;
    while (!end() && s[i] >= '0' && s[i] <= '9') v = v * 10 + (s[i++] - '0');
    if (end()) return Tag::Incomplete;
    return i > start && i - start < 10 ? Tag::Yes : Tag::No;
  };
  long job = 0, r = 0;
  if (const Tag t = digits(job); t != Tag::Yes) return t;
  if (s[i++] != ',') return Tag::No;
  if (end()) return Tag::Incomplete;
  if (const Tag t = digits(r); t != Tag::Yes) return t;
  for (const char c : std::string("]<")) {
    if (end()) return Tag::Incomplete;
    if (s[i++] != c) return Tag::No;
  }
  std::string word;
  while (!end() && s[i] != '>' && word.size() < 8) word.push_back(s[i++]);
  if (end()) return Tag::Incomplete;
  if (s[i++] != '>' || (word != "stdout" && word != "stderr" && word != "stddiag")) return Tag::No;
  if (end()) return Tag::Incomplete;
  if (s[i++] != ':') return Tag::No;
  rank = static_cast<int>(r);
  stream = word == "stdout" ? 1 : 2;
  len = i - pos;
  return Tag::Yes;
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

}  // namespace

LaunchOutput::LaunchOutput(const LaunchPlan& plan, std::ostream& terminal, std::unique_ptr<core::LogFile> fluidLog,
                           int fluidProgram, bool inPlace)
    : plan_(plan), terminal_(terminal), fluidLog_(std::move(fluidLog)), fluidProgram_(fluidProgram), inPlace_(inPlace) {}

int LaunchOutput::programOf(int worldRank) const {
  if (worldRank < 0) return -1;
  int first = 0;
  for (std::size_t p = 0; p < plan_.ranks.size(); ++p) {
    if (worldRank < first + plan_.ranks[p]) return static_cast<int>(p);
    first += plan_.ranks[p];
  }
  return -1;
}

void LaunchOutput::feed(std::string_view chunk) {
  pending_.append(chunk);
  std::size_t pos = 0;
  while (pos < pending_.size()) {
    const char c = pending_[pos];
    if (c == '[') {
      int rank = -1, stream = 0;
      std::size_t len = 0;
      const Tag t = matchTag(pending_, pos, rank, stream, len);
      if (t == Tag::Incomplete) break;  // wait for the rest of the tag
      if (t == Tag::Yes) {
        currentKey_ = {rank, stream};
        pos += len;
        continue;
      }
    }
    ++pos;
    if (c == '\n') {
      auto it = partial_.find(currentKey_);
      std::string text = it == partial_.end() ? std::string() : std::move(it->second);
      if (it != partial_.end()) partial_.erase(it);
      line(programOf(currentKey_.first), text);
      currentKey_ = {-1, 0};  // the next piece carries its own tag, or is mpirun's own
    } else {
      partial_[currentKey_].push_back(c);
    }
  }
  pending_.erase(0, pos);
}

bool LaunchOutput::readClosingLine(const std::string& text, SideSummary& s) {
  static const std::regex done(R"(^done: (\d+) steps?, t = ([-+0-9.eE]+) s, wall ([-+0-9.eE]+) s)");
  static const std::regex split(R"(^coupling \(.*\): computed ([-+0-9.eE]+) s, ([-+0-9.eE]+) s in exchange)");
  static const std::regex iters(R"(^coupling: schedule \S+, (\d+) iterations in (\d+) steps)");
  // The transport's details (message latency, each exchange point, bytes per step): the log keeps them.
  static const std::regex detail(R"(^coupling \(.*\): (message latency|per exchange point|[0-9]+ bytes exchanged))");
  std::smatch m;
  if (std::regex_search(text, m, done)) {
    s.steps = std::stol(m[1]);
    s.time = std::stod(m[2]);
    s.wall = std::stod(m[3]);
  } else if (std::regex_search(text, m, split)) {
    s.compute = std::stod(m[1]);
    s.wait = std::stod(m[2]);
  } else if (std::regex_search(text, m, iters)) {
    s.iterations = std::stol(m[1]);
  } else if (!std::regex_search(text, m, detail)) {
    return false;
  }
  s.held.push_back(text);
  return true;
}

std::optional<std::string> LaunchOutput::coupledProgressLine(const std::string& text) {
  static const std::regex progress(
      R"(^step (\d+)  t = (\S+) / (\S+) s \(([^)]*)\)  dt = \S+  wall \S+ s  ETA (\S+)(?: s)?((?:  \w+=\S+)*)$)");
  static const std::regex extra(R"((\w+)=(\S+))");
  std::smatch m;
  if (!std::regex_match(text, m, progress)) return std::nullopt;
  std::string out = "coupler: step " + m[1].str() + "  t = " + m[2].str() + " / " + m[3].str() + " s (" + m[4].str() +
                    ")  ETA " + (m[5].str() == "--" ? std::string("--") : m[5].str() + " s");
  std::optional<double> iters, total;
  std::string dtBy;
  const std::string extras = m[6].str();
  for (auto it = std::sregex_iterator(extras.begin(), extras.end(), extra); it != std::sregex_iterator(); ++it) {
    if ((*it)[1] == "iters") iters = std::stod((*it)[2]);
    if ((*it)[1] == "iters_total") total = std::stod((*it)[2]);
    if ((*it)[1] == "dt_by") dtBy = (*it)[2];
  }
  if (iters) {
    out += "  coupling iterations " + fmt(*iters);
    const long steps = std::stol(m[1]);
    if (total && steps > 0) out += " (" + fmt(*total / double(steps)) + " per step)";
  }
  if (!dtBy.empty()) out += "  dt set by " + (dtBy.starts_with("time.") ? dtBy : "the " + dtBy + " side");
  return out;
}

std::string LaunchOutput::summaryLine(const std::string& program, int ranks, const SideSummary& s,
                                      std::optional<long> iterations) {
  if (!s.steps || !s.time || !s.compute || !s.wait) return {};
  std::string line = "coupler: " + program + " (" + std::to_string(ranks) + (ranks == 1 ? " rank" : " ranks") +
                     "): " + std::to_string(*s.steps) + (*s.steps == 1 ? " step" : " steps") + " to t = " +
                     fmt(*s.time) + " s, compute " + fmt(*s.compute) + " s, wait " + fmt(*s.wait) + " s";
  if (iterations)
    line += ", " + std::to_string(*iterations) + " coupling iterations (" +
            fmt(double(*iterations) / double(std::max(1L, *s.steps))) + " per step)";
  if (s.wall) line += ", wall " + fmt(*s.wall) + " s";
  return line;
}

void LaunchOutput::line(int program, const std::string& text) {
  text_ += text;
  text_ += '\n';
  if (text_.size() > kTextKept) text_.erase(0, text_.size() - kTextKept / 2);
  if (program >= 0 && program == fluidProgram_ && fluidLog_) {
    fluidLog_->write(text + "\n");
    fluidTail_.push_back(text);
    if (fluidTail_.size() > kFluidTail) fluidTail_.erase(fluidTail_.begin());
    return;
  }
  if (program >= 0 && readClosingLine(text, sides_[program])) return;
  if (program >= 0)
    if (const auto progress = coupledProgressLine(text)) return show(*progress, true);
  show(text);
}

void LaunchOutput::show(const std::string& text, bool progress) {
  if (progress && inPlace_) {
    terminal_ << "\r" << text << "\033[K" << std::flush;
    progressShown_ = true;
    return;
  }
  if (progressShown_) terminal_ << "\n";
  progressShown_ = false;
  terminal_ << text << "\n" << std::flush;
}

void LaunchOutput::finish(bool succeeded) {
  feed("");
  if (!pending_.empty()) {  // an unfinished tag at the very end: text
    partial_[currentKey_] += pending_;
    pending_.clear();
  }
  for (auto& [key, text] : partial_)
    if (!text.empty()) line(programOf(key.first), text);
  partial_.clear();
  if (progressShown_) terminal_ << "\n";
  progressShown_ = false;
  // The coupling iterations: the solid side counts them (the verdict is the solid's).
  std::optional<long> iterations;
  for (const auto& [p, s] : sides_)
    if (s.iterations) iterations = s.iterations;
  for (const auto& [p, s] : sides_) {
    const std::string& program = plan_.programs[static_cast<std::size_t>(p)];
    const std::string summary =
        succeeded ? summaryLine(program, plan_.ranks[static_cast<std::size_t>(p)], s, iterations) : std::string();
    if (!summary.empty())
      terminal_ << summary << "\n";
    else
      for (const auto& h : s.held) terminal_ << program << ": " << h << "\n";
  }
  if (!succeeded && fluidLog_ && !fluidTail_.empty()) {
    terminal_ << "coupler: the last lines of " << fluidLog_->path() << ":\n";
    for (const auto& l : fluidTail_) terminal_ << "  " << l << "\n";
  }
  terminal_ << std::flush;
}

}  // namespace mpmice::coupler
