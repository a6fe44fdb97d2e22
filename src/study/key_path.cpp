#include "study/key_path.h"

#include <cctype>

namespace mpmice::study {

KeyPathError::KeyPathError(const std::string& path, const std::string& why)
    : std::runtime_error("key path '" + path + "': " + why), path_(path) {}

std::vector<KeyStep> parseKeyPath(const std::string& path) {
  std::vector<KeyStep> steps;
  std::size_t i = 0;
  if (path.empty()) throw KeyPathError(path, "empty");
  for (;;) {
    KeyStep s;
    while (i < path.size() && path[i] != '.' && path[i] != '[') s.key.push_back(path[i++]);
    if (s.key.empty()) throw KeyPathError(path, "an empty key at character " + std::to_string(i + 1));
    if (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos) throw KeyPathError(path, "'[' without its ']'");
      s.select = path.substr(i + 1, close - i - 1);
      if (s.select->empty()) throw KeyPathError(path, "an empty [] (expected [name] or [index])");
      i = close + 1;
    }
    steps.push_back(s);
    if (i == path.size()) break;
    if (path[i] != '.') throw KeyPathError(path, "expected '.' after ']' at character " + std::to_string(i + 1));
    if (++i == path.size()) throw KeyPathError(path, "ends with '.'");
  }
  return steps;
}

namespace {

bool isIndex(const std::string& s) {
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

const char* kindName(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Map: return "a mapping";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Scalar: return "a scalar";
    default: return "nothing";
  }
}

/// The element of list `list` (reached by `where`) that `select` names.
YAML::Node element(YAML::Node list, const std::string& select, const std::string& path, const std::string& where) {
  if (!list.IsSequence())
    throw KeyPathError(path, "'" + where + "' is " + kindName(list) + ", not a list, so [" + select + "] selects nothing");
  if (isIndex(select)) {
    const std::size_t k = std::stoul(select);
    if (k >= list.size())
      throw KeyPathError(path, "'" + where + "' has " + std::to_string(list.size()) + " elements; no index " + select);
    return list[k];
  }
  std::string names;
  for (std::size_t k = 0; k < list.size(); ++k) {
    YAML::Node e = list[k];
    if (e.IsMap() && e["name"] && e["name"].IsScalar()) {
      if (e["name"].Scalar() == select) return e;
      names += (names.empty() ? "" : ", ") + e["name"].Scalar();
    }
  }
  throw KeyPathError(path, "no element of '" + where + "' is named '" + select + "' (" +
                               (names.empty() ? std::string("its elements have no names; use an index")
                                              : "named: " + names) + ")");
}

}  // namespace

void setKeyPath(YAML::Node root, const std::string& path, const YAML::Node& value) {
  const auto steps = parseKeyPath(path);
  YAML::Node at = root;
  std::string where;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const KeyStep& st = steps[s];
    if (!at.IsMap() && !at.IsNull())
      throw KeyPathError(path, "'" + (where.empty() ? std::string("the scene") : where) + "' is " + kindName(at) +
                                   ", not a mapping, so it has no key '" + st.key + "'");
    where += (where.empty() ? "" : ".") + st.key;
    const bool last = s + 1 == steps.size();
    if (last && !st.select) {
      at[st.key] = YAML::Clone(value);
      return;
    }
    YAML::Node next = at[st.key];
    if (st.select) {
      if (!next.IsDefined() || next.IsNull())
        throw KeyPathError(path, "the scene has no list '" + where + "' to select [" + *st.select + "] from");
      next.reset(element(next, *st.select, path, where));
      where += "[" + *st.select + "]";
      if (last) {
        next = YAML::Clone(value);  // replaces the element itself
        return;
      }
    } else if (!next.IsDefined() || next.IsNull()) {
      at[st.key] = YAML::Node(YAML::NodeType::Map);
      next.reset(at[st.key]);
    }
    at.reset(next);
  }
}

}  // namespace mpmice::study
