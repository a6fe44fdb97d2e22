#include "core/scene/yaml_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "core/scene/did_you_mean.h"

namespace mpmice::core::scene_detail {

namespace {

SourceLoc locOf(const YAML::Mark& m, const std::string& file) {
  SourceLoc loc;
  loc.file = file;
  if (m.line >= 0) {
    loc.line = m.line + 1;
    loc.column = m.column + 1;
  }
  return loc;
}

/// A value as echoed in a message: at most 80 characters (a 50 MB scalar must not become 50 MB
/// of stderr).
std::string capped(const std::string& v) {
  constexpr std::size_t kMax = 80;
  if (v.size() <= kMax) return v;
  return v.substr(0, kMax - 3) + "... (" + std::to_string(v.size()) + " characters)";
}

std::string childPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::optional<double> toDouble(std::string s) {
  if (!s.empty() && s[0] == '+') s.erase(0, 1);
  if (s.empty()) return std::nullopt;
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

// ---------------------------------------------------------------------------------------- Range

bool Range::contains(double v) const {
  const bool aboveLo = loOpen ? v > lo : v >= lo;
  const bool belowHi = hiOpen ? v < hi : v <= hi;
  return aboveLo && belowHi;
}

std::string Range::describe() const {
  const bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
  if (hasLo && hasHi)
    return std::string("in ") + (loOpen ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) +
           (hiOpen ? ")" : "]");
  if (hasLo) return (loOpen ? "> " : ">= ") + formatNumber(lo);
  if (hasHi) return (hiOpen ? "< " : "<= ") + formatNumber(hi);
  return "finite";
}

std::string formatNumber(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc()) return "nan";
  // "1.17e+11" -> "1.17e11", "2e-04" -> "2e-4": the same digits, easier to read.
  std::string s(buf, end);
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
  std::string sign;
  if (exponent[0] == '+' || exponent[0] == '-') {
    if (exponent[0] == '-') sign = "-";
    exponent.erase(0, 1);
  }
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return mantissa + "e" + sign + exponent;
}

// ------------------------------------------------------------------------------------ YamlValue

YamlValue::YamlValue(YAML::Node node, std::string path, std::string file)
    : node_(std::move(node)), path_(std::move(path)), file_(std::move(file)) {}

SourceLoc YamlValue::loc() const { return locOf(node_.Mark(), file_); }

void YamlValue::fail(const std::string& what) const { throw SceneError(loc(), path_, what); }

std::string YamlValue::shown() const {
  if (isNull()) return "nothing";
  if (isScalar()) return "'" + capped(node_.Scalar()) + "'";
  if (isList()) return "a list";
  return "a mapping";
}

double YamlValue::number(const Range& r) const {
  if (!isScalar()) fail("expected a number " + r.describe() + ", got " + shown());
  const auto v = toDouble(node_.Scalar());
  if (!v) fail("expected a number, got " + shown());
  if (!r.contains(*v)) fail(capped(node_.Scalar()) + " is out of range; expected a number " + r.describe());
  return *v;
}

long YamlValue::integer(long lo, long hi) const {
  const std::string range = hi >= std::numeric_limits<int>::max()
                                ? ">= " + std::to_string(lo)
                                : "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!isScalar()) fail("expected an integer " + range + ", got " + shown());
  std::string s = node_.Scalar();
  if (!s.empty() && s[0] == '+') s.erase(0, 1);
  long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size())
    fail("expected an integer, got " + shown());
  if (v < lo || v > hi) fail(capped(node_.Scalar()) + " is out of range; expected an integer " + range);
  return v;
}

bool YamlValue::boolean() const {
  if (isScalar()) {
    const std::string s = lower(node_.Scalar());
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
  }
  fail("expected true or false, got " + shown());
}

std::string YamlValue::string() const {
  if (!isScalar() || node_.Scalar().empty()) fail("expected a string, got " + shown());
  return node_.Scalar();
}

std::string YamlValue::choice(const std::vector<std::string>& valid, const std::string& noun) const {
  if (!isScalar()) fail("expected the name of a " + noun + " (" + joinNames(valid) + "), got " + shown());
  const std::string s = node_.Scalar();
  if (std::find(valid.begin(), valid.end(), s) != valid.end()) return s;
  fail("unknown " + noun + " '" + capped(s) + "'; valid: " + joinNames(valid) +
       (s.size() <= 80 ? didYouMean(s, valid) : std::string()));
}

std::vector<YamlValue> YamlValue::list() const {
  if (!isList()) fail("expected a list, got " + shown());
  std::vector<YamlValue> out;
  std::size_t i = 0;
  for (const auto& item : node_) out.emplace_back(item, path_ + "[" + std::to_string(i++) + "]", file_);
  return out;
}

std::vector<double> YamlValue::numbers(const Range& r) const {
  std::vector<double> out;
  for (const auto& item : list()) out.push_back(item.number(r));
  return out;
}

RealVect YamlValue::vector(int dim, const Range& r) const {
  const std::string expected =
      "expected a list of " + std::to_string(dim) + (dim == 1 ? " number" : " numbers") +
      " (one per mesh direction)";
  if (!isList()) fail(expected + ", got " + shown());
  const auto items = list();
  if (static_cast<int>(items.size()) != dim)
    fail(expected + ", got " + std::to_string(items.size()));
  RealVect v{0, 0, 0};
  for (int d = 0; d < dim; ++d) v[d] = items[d].number(r);
  return v;
}

YamlMap YamlValue::map() const { return YamlMap(*this); }

// -------------------------------------------------------------------------------------- YamlMap

YamlMap::YamlMap(const YamlValue& v) : self_(v) {
  if (!v.isMap()) v.fail("expected a mapping (key: value pairs), got " + v.shown());
  const YAML::Node& n = v.node();
  for (const auto& kv : n) {
    const YAML::Node k = kv.first;
    YamlValue keyValue(k, v.path(), self_.loc().file);
    if (!k.IsScalar()) keyValue.fail("keys must be plain names, got " + keyValue.shown());
    const std::string key = k.Scalar();
    if (const auto seen = index_.find(key); seen != index_.end())
      throw SceneError(locOf(k.Mark(), self_.loc().file), childPath(v.path(), key),
                       "duplicate key '" + capped(key) + "' (first given at line " +
                           std::to_string(entries_[seen->second].keyNode.Mark().line + 1) + ")");
    index_.emplace(key, entries_.size());
    entries_.push_back({key, k, YamlValue(kv.second, childPath(v.path(), key), self_.loc().file)});
  }
}

void YamlMap::allow(const std::vector<std::string>& keys, const std::string& note) const {
  if (const auto bad = firstKeyOutside(keys)) {
    const std::string key = bad->node().Scalar();
    const std::string where = path().empty() ? "at the top level" : "in " + path();
    std::string msg = "unknown key '" + capped(key) + "' " + where + "; valid keys: " + joinNames(keys) +
                      (key.size() <= 80 ? didYouMean(key, keys) : std::string());
    if (!note.empty()) msg += "; " + note;
    bad->fail(msg);
  }
}

std::optional<YamlValue> YamlMap::firstKeyOutside(const std::vector<std::string>& keys) const {
  for (const auto& e : entries_)
    if (std::find(keys.begin(), keys.end(), e.key) == keys.end())
      return YamlValue(e.keyNode, childPath(path(), e.key), self_.loc().file);
  return std::nullopt;
}

bool YamlMap::has(const std::string& key) const { return get(key).has_value(); }

std::optional<YamlValue> YamlMap::get(const std::string& key) const {
  if (const auto it = index_.find(key); it != index_.end()) return entries_[it->second].value;
  return std::nullopt;
}

YamlValue YamlMap::required(const std::string& key) const {
  if (auto v = get(key)) return *v;
  fail("missing required key '" + key + "'");
}

std::vector<std::string> YamlMap::keys() const {
  std::vector<std::string> out;
  for (const auto& e : entries_) out.push_back(e.key);
  return out;
}

double YamlMap::number(const std::string& key, const Range& r) const {
  if (!has(key)) fail("missing required key '" + key + "' (a number " + r.describe() + ")");
  return required(key).number(r);
}

double YamlMap::number(const std::string& key, double fallback, const Range& r) const {
  const auto v = get(key);
  return v ? v->number(r) : fallback;
}

long YamlMap::integer(const std::string& key, long fallback, long lo, long hi) const {
  const auto v = get(key);
  return v ? v->integer(lo, hi) : fallback;
}

bool YamlMap::boolean(const std::string& key, bool fallback) const {
  const auto v = get(key);
  return v ? v->boolean() : fallback;
}

std::string YamlMap::string(const std::string& key) const { return required(key).string(); }

std::string YamlMap::string(const std::string& key, const std::string& fallback) const {
  const auto v = get(key);
  return v ? v->string() : fallback;
}

std::string YamlMap::choice(const std::string& key, const std::string& fallback,
                            const std::vector<std::string>& valid, const std::string& noun) const {
  const auto v = get(key);
  return v ? v->choice(valid, noun) : fallback;
}

RealVect YamlMap::vector(const std::string& key, int dim, const RealVect& fallback, const Range& r) const {
  const auto v = get(key);
  return v ? v->vector(dim, r) : fallback;
}

// ---------------------------------------------------------------------------------- parseYamlText

YamlValue parseYamlText(const std::string& text, const std::string& file) {
  try {
    return YamlValue(YAML::Load(text), "", file);
  } catch (const YAML::Exception& e) {
    throw SceneError(locOf(e.mark, file), "", "YAML syntax error: " + e.msg);
  }
}

}  // namespace mpmice::core::scene_detail
