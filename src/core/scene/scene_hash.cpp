// sceneHash: FNV-1a (64 bit) over a canonical text of what both sides of a coupled run must agree
// on: the mesh, the materials (with every model parameter) and the boundary conditions. Numbers
// enter as exact hexadecimal floating point, so any change of any bit changes the text.
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/scene/scene.h"

namespace mpmice::core {

namespace {

class Canonical {
 public:
  Canonical& operator<<(const std::string& s) {
    text_ += s;
    text_ += ';';
    return *this;
  }
  Canonical& operator<<(const char* s) { return *this << std::string(s); }
  Canonical& operator<<(double v) {
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::hex);
    return *this << (ec == std::errc() ? std::string(buf, end) : std::string("?"));
  }
  Canonical& operator<<(int v) { return *this << std::to_string(v); }
  Canonical& operator<<(const RealVect& v) { return *this << v[0] << v[1] << v[2]; }
  Canonical& operator<<(const ModelSpec& m) {
    *this << m.type << static_cast<int>(m.params.size());
    for (const auto& [k, v] : m.params) *this << k << v;
    *this << static_cast<int>(m.tables.size());
    for (const auto& [k, col] : m.tables) {
      *this << k << static_cast<int>(col.size());
      for (double x : col) *this << x;
    }
    return *this;
  }
  [[nodiscard]] const std::string& text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace

std::string sceneHash(const Scene& s) {
  Canonical c;
  const Mesh& m = s.mesh;
  c << "mesh" << m.dim() << m.origin() << m.spacing() << m.cells()[0] << m.cells()[1] << m.cells()[2];
  c << "materials" << static_cast<int>(s.materials.size());
  for (const auto& mat : s.materials) {
    c << mat.name << (mat.kind == MaterialKind::Solid ? "solid" : "fluid") << mat.density << mat.constitutive
      << mat.eos << mat.specific_heat << mat.viscosity << mat.thermal_conductivity << mat.thermal_expansivity;
    if (!mat.cavitation.type.empty()) c << "cavitation" << mat.cavitation;  // absent: the hash as before
  }
  c << "boundary";
  for (const auto& b : s.boundary) {
    c << toString(b.type) << b.velocity << (b.pressure ? *b.pressure : -1.0) << (b.density ? *b.density : -1.0)
      << b.temperature << b.material;
  }
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a offset basis
  for (unsigned char ch : c.text()) {
    h ^= ch;
    h *= 1099511628211ULL;  // FNV prime
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

}  // namespace mpmice::core
