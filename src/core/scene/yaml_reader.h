#pragma once
/// @brief Reading YAML scene values with errors that name the file, line, key path and value.
///
/// YamlValue wraps one yaml-cpp node together with its key path ("materials[1].eos.type") and
/// converts it to numbers, integers, booleans, strings, choices and mesh-length vectors, throwing
/// SceneError with the 1-based line and column when the value is of the wrong type or out of range.
/// YamlMap reads a mapping: allow() declares the keys it may hold (any other key is an error with a
/// "did you mean" suggestion), duplicate keys are errors, and required() names the missing key.
#include <yaml-cpp/yaml.h>

#include <limits>
#include <optional>
#include <unordered_map>
#include <string>
#include <utility>
#include <vector>

#include "core/scene/options.h"
#include "core/scene/scene.h"

namespace mpmice::core::scene_detail {

/// The interval a number must lie in; describe() gives "> 0", ">= 0", "in (0, 1]", ...
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false, hiOpen = false;

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range nonNegative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range above(double v) { return {v, std::numeric_limits<double>::infinity(), true, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }
  static Range openClosed(double a, double b) { return {a, b, true, false}; }
  [[nodiscard]] bool contains(double v) const;
  [[nodiscard]] std::string describe() const;
};

class YamlMap;

class YamlValue {
 public:
  YamlValue(YAML::Node node, std::string path, std::string file);

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const YAML::Node& node() const { return node_; }
  [[nodiscard]] SourceLoc loc() const;
  [[noreturn]] void fail(const std::string& what) const;

  [[nodiscard]] bool isNull() const { return !node_.IsDefined() || node_.IsNull(); }
  [[nodiscard]] bool isScalar() const { return node_.IsScalar(); }
  [[nodiscard]] bool isList() const { return node_.IsSequence(); }
  [[nodiscard]] bool isMap() const { return node_.IsMap(); }
  /// The value as written (scalars), or "a list" / "a mapping" / "nothing".
  [[nodiscard]] std::string shown() const;

  [[nodiscard]] double number(const Range& r = Range::any()) const;
  [[nodiscard]] long integer(long lo, long hi = std::numeric_limits<long>::max()) const;
  [[nodiscard]] bool boolean() const;
  [[nodiscard]] std::string string() const;
  /// One of `valid`; else "unknown <noun> 'x'; valid: ... (did you mean 'y'?)".
  [[nodiscard]] std::string choice(const std::vector<std::string>& valid, const std::string& noun) const;
  /// One of the names of `table` (options.h), as its enum value; else the error of choice().
  template <class E, std::size_t N>
  [[nodiscard]] E option(const std::array<std::pair<E, std::string_view>, N>& table, const std::string& noun) const {
    std::vector<std::string> names;
    for (const auto& [v, n] : table) names.emplace_back(n);
    const std::string chosen = choice(names, noun);
    for (const auto& [v, n] : table)
      if (n == chosen) return v;
    return table[0].first;  // not reached: choice() throws for a name not in the table
  }
  [[nodiscard]] std::vector<YamlValue> list() const;
  /// A list of exactly `dim` numbers in r, zero-filled to three components.
  [[nodiscard]] RealVect vector(int dim, const Range& r = Range::any()) const;
  [[nodiscard]] std::vector<double> numbers(const Range& r = Range::any()) const;
  [[nodiscard]] YamlMap map() const;

 private:
  YAML::Node node_;
  std::string path_;
  std::string file_;
};

class YamlMap {
 public:
  explicit YamlMap(const YamlValue& v);

  [[nodiscard]] const YamlValue& self() const { return self_; }
  [[nodiscard]] const std::string& path() const { return self_.path(); }
  [[noreturn]] void fail(const std::string& what) const { self_.fail(what); }
  /// Every key must be one of `keys`; else an error at the key ("unknown key 'x' in <path>").
  /// `note` is appended to that message (e.g. why a key does not apply here).
  void allow(const std::vector<std::string>& keys, const std::string& note = "") const;
  /// A key present here but not in `keys`, if any (to explain keys that do not apply).
  [[nodiscard]] std::optional<YamlValue> firstKeyOutside(const std::vector<std::string>& keys) const;

  [[nodiscard]] bool has(const std::string& key) const;
  [[nodiscard]] std::optional<YamlValue> get(const std::string& key) const;
  [[nodiscard]] YamlValue required(const std::string& key) const;
  [[nodiscard]] std::vector<std::string> keys() const;

  // Shorthands: required (no fallback) and optional (with fallback) values.
  [[nodiscard]] double number(const std::string& key, const Range& r) const;
  [[nodiscard]] double number(const std::string& key, double fallback, const Range& r) const;
  [[nodiscard]] long integer(const std::string& key, long fallback, long lo,
                             long hi = std::numeric_limits<long>::max()) const;
  [[nodiscard]] bool boolean(const std::string& key, bool fallback) const;
  [[nodiscard]] std::string string(const std::string& key) const;
  [[nodiscard]] std::string string(const std::string& key, const std::string& fallback) const;
  [[nodiscard]] std::string choice(const std::string& key, const std::string& fallback,
                                   const std::vector<std::string>& valid, const std::string& noun) const;
  /// One of the names of `table` (coupling_options.h), as its enum value; else the error of choice().
  template <class E, std::size_t N>
  [[nodiscard]] E option(const std::string& key, E fallback, const std::array<std::pair<E, std::string_view>, N>& table,
                         const std::string& noun) const {
    const auto v = get(key);
    return v ? v->option(table, noun) : fallback;
  }
  [[nodiscard]] RealVect vector(const std::string& key, int dim, const RealVect& fallback,
                                const Range& r = Range::any()) const;

 private:
  struct Entry {
    std::string key;
    YAML::Node keyNode;
    YamlValue value;
  };
  YamlValue self_;
  std::vector<Entry> entries_;
  std::unordered_map<std::string, std::size_t> index_;  // key -> entry (duplicate keys in O(n))
  std::string file_;
};

/// Parses YAML text into its root value (path ""); a syntax error is a SceneError with the line.
YamlValue parseYamlText(const std::string& text, const std::string& file);

/// Shortest text that reads back as exactly the same double ("0.1", "1e+15", "117000000000").
std::string formatNumber(double v);

}  // namespace mpmice::core::scene_detail
