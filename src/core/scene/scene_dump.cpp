// dumpScene: the scene as understood, every default filled in, as YAML in the scene format.
// The text parses back to an equal Scene (numbers are written in their shortest exact form).
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "core/scene/model_catalog.h"
#include "core/scene/scene.h"
#include "core/scene/yaml_reader.h"

namespace mpmice::core {

namespace {

using scene_detail::formatNumber;

std::string num(double v) { return formatNumber(v); }
std::string flag(bool b) { return b ? "true" : "false"; }

bool isPlain(const std::string& s) {
  if (s.empty()) return false;
  static const char* reserved[] = {"true", "false", "yes", "no", "on", "off", "null", "y", "n"};
  std::string low;
  for (char c : s) low += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  for (const char* r : reserved)
    if (low == r) return false;
  const char c0 = s.front();
  if (!((c0 >= 'a' && c0 <= 'z') || (c0 >= 'A' && c0 <= 'Z') || c0 == '_')) return false;
  for (char c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
          c == '.' || c == '/'))
      return false;
  return true;
}

std::string quote(const std::string& s) {
  if (isPlain(s)) return s;
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

std::string vec(const RealVect& v, int dim) {
  std::string s = "[";
  for (int d = 0; d < dim; ++d) s += (d ? ", " : "") + num(v[d]);
  return s + "]";
}

std::string ivec(const IntVect& v, int dim) {
  std::string s = "[";
  for (int d = 0; d < dim; ++d) s += (d ? ", " : "") + std::to_string(v[d]);
  return s + "]";
}

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(v[i]);
  return s + "]";
}

std::string shape(const ShapeSpec& sh, int dim) {
  std::string s = "{type: ";
  if (sh.type == "box") return s + "box, lo: " + vec(sh.lo, dim) + ", hi: " + vec(sh.hi, dim) + "}";
  if (sh.type == "sphere")
    return s + (dim == 2 ? "circle" : "sphere") + ", center: " + vec(sh.center, dim) + ", radius: " + num(sh.radius) + "}";
  if (sh.type == "cylinder" || sh.type == "annulus") {
    s += sh.type + ", center: " + vec(sh.center, dim);
    if (sh.type == "cylinder") s += ", radius: " + num(sh.radius);
    else s += ", inner_radius: " + num(sh.inner_radius) + ", outer_radius: " + num(sh.outer_radius);
    if (dim == 3) s += ", axis: " + vec(sh.axis, 3) + ", length: " + num(sh.length);
    return s + "}";
  }
  s += sh.type + ", shapes: [";
  for (std::size_t i = 0; i < sh.children.size(); ++i) s += (i ? ", " : "") + shape(sh.children[i], dim);
  return s + "]}";
}

/// A model in the catalog's parameter order; for elastic constants, the pair that reproduces the
/// other one exactly when read back (bulk/shear when possible).
std::string model(const ModelSpec& m, const scene_detail::ModelFamily& family) {
  const auto* info = family.find(m.type);
  std::string s = "{type: " + m.type;
  if (!info) return s + "}";
  bool bulkShear = false;
  if (m.has("bulk_modulus") && m.has("shear_modulus") && m.has("youngs_modulus")) {
    double e = 0, nu = 0;
    scene_detail::elasticFromBulkShear(m.get("bulk_modulus"), m.get("shear_modulus"), e, nu);
    bulkShear = e == m.get("youngs_modulus") && nu == m.get("poissons_ratio");
  }
  for (const auto& p : info->params) {
    if (!m.has(p.name)) continue;
    if (p.need == scene_detail::ParamInfo::Need::Elastic) {
      const bool isBulkShear = p.name == "bulk_modulus" || p.name == "shear_modulus";
      if (isBulkShear != bulkShear) continue;
    }
    s += ", " + p.name + ": " + num(m.get(p.name));
  }
  for (const auto& t : info->tables) {
    if (!m.tables.count(t.columns.front())) continue;
    s += ", " + t.key + ": {";
    for (std::size_t i = 0; i < t.columns.size(); ++i)
      s += (i ? ", " : "") + t.columns[i] + ": " + list(m.tables.at(t.columns[i]));
    s += "}";
  }
  return s + "}";
}

/// The upper corner as the scene would give it: a value U near origin + n dx for which
/// (U - origin) / n reproduces the spacing bit for bit (the scene reader computes it that way).
std::optional<double> exactUpper(const Mesh& m, int d) {
  const double lo = m.origin()[d], n = m.cells()[d];
  double up = m.upper(d), down = up;
  for (int k = 0; k < 16; ++k) {
    if ((up - lo) / n == m.dx(d)) return up;
    if ((down - lo) / n == m.dx(d)) return down;
    up = std::nextafter(up, std::numeric_limits<double>::infinity());
    down = std::nextafter(down, -std::numeric_limits<double>::infinity());
  }
  return std::nullopt;
}

void mesh(std::ostream& o, const Mesh& m) {
  const int dim = m.dim();
  RealVect upper{0, 0, 0};
  bool exact = true;
  for (int d = 0; d < dim; ++d) {
    const auto u = exactUpper(m, d);
    exact = exact && u.has_value();
    upper[d] = u ? *u : m.upper(d);
  }
  o << "mesh:\n  dim: " << dim << "\n  lower: " << vec(m.origin(), dim) << "\n  upper: " << vec(upper, dim) << "\n";
  if (exact) {
    std::ostringstream h;  // a readable (rounded) spacing for the comment
    for (int d = 0; d < dim; ++d) h << (d ? ", " : "") << m.dx(d);
    o << "  cells: " << ivec(m.cells(), dim) << "   # spacing [" << h.str() << "]\n";
  }
  else o << "  spacing: " << vec(m.spacing(), dim) << "   # cells: " << ivec(m.cells(), dim) << "\n";
}

void materials(std::ostream& o, const Scene& s) {
  o << "materials:\n";
  for (const auto& m : s.materials) {
    o << "  - name: " << quote(m.name) << "\n";
    if (m.kind == MaterialKind::Fluid) {
      o << "    kind: fluid\n";
      o << "    eos: " << model(m.eos, scene_detail::fluidEquationsOfState()) << "\n";
      if (m.density > 0) o << "    density: " << num(m.density) << "\n";
      o << "    viscosity: " << num(m.viscosity) << "\n";
      if (!m.cavitation.type.empty())
        o << "    cavitation: {model: " << m.cavitation.type << ", pressure: " << num(m.cavitation.get("pressure")) << "}\n";
    } else {
      o << "    kind: solid\n";
      o << "    density: " << num(m.density) << "\n";
      o << "    model: " << model(m.constitutive, scene_detail::constitutiveModels()) << "\n";
      o << "    eos: " << model(m.eos, scene_detail::solidEquationsOfState()) << "\n";
      o << "    thermal_expansivity: " << num(m.thermal_expansivity) << "\n";
    }
    o << "    specific_heat: " << num(m.specific_heat) << "\n";
    o << "    thermal_conductivity: " << num(m.thermal_conductivity) << "\n";
  }
}

void geometry(std::ostream& o, const Scene& s) {
  const int dim = s.mesh.dim();
  o << "geometry:\n";
  for (const auto& r : s.geometry) {
    o << "  - ";
    if (!r.name.empty()) o << "name: " << quote(r.name) << "\n    ";
    o << "shape: " << shape(r.shape, dim) << "\n";
    if (r.fill.size() == 1 && r.fill.front().volume_fraction == 1.0) {
      o << "    material: " << quote(r.fill.front().material) << "\n";
    } else {
      o << "    mixture:\n";
      for (const auto& f : r.fill)
        o << "      - {material: " << quote(f.material) << ", volume_fraction: " << num(f.volume_fraction) << "}\n";
    }
    o << "    velocity: " << vec(r.velocity, dim) << "\n";
    if (r.velocity_gradient != std::array<RealVect, 3>{}) {
      o << "    velocity_origin: " << vec(r.velocity_origin, dim) << "\n";
      o << "    velocity_gradient: [";
      for (int i = 0; i < dim; ++i) o << (i ? ", " : "") << vec(r.velocity_gradient[static_cast<std::size_t>(i)], dim);
      o << "]\n";
    }
    const MaterialSpec* first = r.fill.empty() ? nullptr : s.material(r.fill.front().material);
    // A fluid region with a density takes its state from pressure and density (a temperature
    // beside them is an error).
    if (!r.density || (first && first->kind == MaterialKind::Solid))
      o << "    temperature: " << num(r.temperature) << "\n";
    if (first && first->kind == MaterialKind::Solid) {
      o << "    particles_per_cell: " << ivec(r.particles_per_cell, dim) << "\n";
    } else {
      if (r.pressure) o << "    pressure: " << num(*r.pressure) << "\n";
      if (r.density) o << "    density: " << num(*r.density) << "\n";
    }
  }
}

void boundary(std::ostream& o, const Scene& s) {
  const int dim = s.mesh.dim();
  o << "boundary:\n";
  for (int f = 0; f < 2 * dim; ++f) {
    const BoundarySpec& b = s.boundary[static_cast<std::size_t>(f)];
    o << "  " << boundaryFaceName(f) << ": ";
    if (b.type == BoundaryType::Inflow) {
      o << "{type: inflow, velocity: " << vec(b.velocity, dim);
      if (b.pressure) o << ", pressure: " << num(*b.pressure);
      if (b.density) o << ", density: " << num(*b.density);
      else o << ", temperature: " << num(b.temperature);
      o << ", material: " << quote(b.material) << "}\n";
    } else if (b.type == BoundaryType::Outflow && b.pressure) {
      o << "{type: outflow, pressure: " << num(*b.pressure) << "}\n";
    } else {
      o << toString(b.type) << "\n";
    }
  }
}

void loadsAndSources(std::ostream& o, const Scene& s) {
  const int dim = s.mesh.dim();
  if (!s.loads.empty()) {
    o << "loads:\n";
    for (const auto& l : s.loads) {
      if (l.type == LoadType::File) {
        o << "  - {type: file, material: " << quote(l.material) << ", file: " << quote(l.file)
          << ", mapping: " << name(l.mapping) << ", rbf_support: " << num(l.rbf_support) << ", depth: " << num(l.depth)
          << ", moment_center: " << vec(l.moment_center, dim) << "}\n";
        continue;
      }
      o << "  - {type: " << name(l.type) << ", material: " << quote(l.material) << ", shape: " << shape(l.shape, dim);
      if (l.type == LoadType::Pressure) o << ", pressure: " << num(l.pressure) << ", center: " << vec(l.center, dim);
      else o << ", traction: " << vec(l.traction, dim);
      o << ", start: " << num(l.start) << ", ramp: " << num(l.ramp) << "}\n";
    }
  }
  if (!s.sources.empty()) {
    o << "sources:\n";
    for (const auto& src : s.sources)
      o << "  - {material: " << quote(src.material) << ", shape: " << shape(src.shape, dim)
        << ", power_density: " << num(src.power_density) << ", start: " << num(src.start)
        << ", end: " << num(src.end) << "}\n";
  }
}

void options(std::ostream& o, const Scene& s) {
  const MpmOptions& m = s.mpm;
  o << "mpm:\n  shape_function: " << m.shape_function << "\n  update: " << m.update << "\n  flip: " << num(m.flip)
    << "\n  damping: " << num(m.damping) << "\n  sort_particles: " << flag(m.sort_particles)
    << "\n  stress_work: " << m.stress_work << "\n  outflow_particles: " << m.outflow_particles << "\n";
  const IceOptions& i = s.ice;
  o << "ice:\n  advection: " << i.advection << "\n  limiter: " << i.limiter << "\n  pressure_solver: "
    << i.pressure_solver << "\n  linear_solver: " << i.linear_solver << "\n  solver_tolerance: "
    << num(i.solver_tolerance) << "\n  solver_max_iterations: " << i.solver_max_iterations
    << "\n  preconditioner_reuse: " << i.preconditioner_reuse
    << "\n  pressure_iterations: " << i.max_pressure_iterations << "\n  pressure_tolerance: "
    << num(i.pressure_tolerance) << "\n  shock_viscosity: {linear: " << num(i.shock_viscosity_linear)
    << ", quadratic: " << num(i.shock_viscosity_quadratic) << "}\n  face_pressure: " << i.face_pressure
    << "\n  trace_mass_fraction: " << num(i.trace_mass_fraction) << "\n  equilibrium: " << i.equilibrium
    << "\n  semi_implicit_sound_fraction: " << num(i.semi_implicit_sound_fraction)
    << "\n  semi_implicit_theta: " << num(i.semi_implicit_theta)
    << "\n  exchange:\n    momentum: " << num(i.exchange_momentum)
    << "\n    heat: " << num(i.exchange_heat) << "\n";
  if (!i.exchange_pairs.empty()) {
    o << "    pairs:\n";
    for (const auto& p : i.exchange_pairs)
      o << "      - {materials: [" << quote(p.a) << ", " << quote(p.b) << "], momentum: " << num(p.momentum)
        << ", heat: " << num(p.heat) << "}\n";
  }
  const CouplingSpec& c = s.coupling;
  o << "coupling:\n  schedule: " << name(c.schedule) << "\n  fluid: " << name(c.fluid) << "\n  min_iterations: "
    << c.min_iterations << "\n  max_iterations: " << c.max_iterations << "\n  accept_unconverged: "
    << flag(c.accept_unconverged) << "\n  timeout: " << num(c.timeout) << "\n  ranks: {mpm: " << c.mpm_ranks
    << ", ice: " << c.ice_ranks << "}\n  solid_transport: " << c.solid_transport
    << "\n  surface_pressure: " << c.surface_pressure << "\n";
  if (!c.convergence.empty()) {
    o << "  convergence:\n";
    for (const auto& cv : c.convergence)
      o << "    - {field: " << quote(cv.field) << ", type: " << name(cv.type) << ", limit: " << num(cv.limit)
        << ", strict: " << flag(cv.strict) << "}\n";
  }
  if (c.fluid == FluidSolver::OpenFoam) {
    const InterfaceSpec& f = c.interface;
    o << "  interface:\n    solid: " << quote(f.solid) << "\n    patch: " << quote(f.patch) << "\n    case: "
      << quote(f.openfoam_case) << "\n    solver: " << f.openfoam_solver << "\n    mapping: " << name(f.mapping)
      << "\n    rbf_support: " << num(f.rbf_support) << "\n    mode: " << name(f.mode) << "\n    fluid_density: "
      << num(f.fluid_density) << "\n";
  }
  const AccelerationSpec& a = c.acceleration;
  o << "  acceleration: {type: " << name(a.type);
  if (a.type != AccelerationType::None) o << ", relaxation: " << num(a.relaxation);
  if (a.type == AccelerationType::IqnIls)
    o << ", reuse: " << a.reuse << ", filter: " << num(a.filter)
      << ", preconditioner: " << (a.preconditioner ? "residual_sum" : "none");
  o << "}\n";
  const OutputSpec& out = s.output;
  o << "output:\n  directory: " << quote(out.directory) << "\n  interval: " << num(out.interval)
    << "\n  checkpoint_interval: " << num(out.checkpoint_interval) << "\n  fields: [";
  for (std::size_t k = 0; k < out.fields.size(); ++k) o << (k ? ", " : "") << quote(out.fields[k]);
  o << "]\n  particles: " << flag(out.particles) << "\n  enabled: " << flag(out.enabled) << "\n";
  if (!out.probes.empty()) {
    o << "  probes:\n";
    for (const auto& p : out.probes)
      o << "    - {name: " << quote(p.name) << ", point: " << vec(p.point, s.mesh.dim()) << "}\n";
  }
}

}  // namespace

std::string dumpScene(const Scene& s) {
  std::ostringstream o;
  const int dim = s.mesh.dim();
  o << "scene: " << quote(s.name) << "\n";
  if (!s.description.empty()) o << "description: " << quote(s.description) << "\n";
  mesh(o, s.mesh);
  const TimeSpec& t = s.time;
  o << "time:\n  end: " << num(t.end) << "\n  cfl: " << num(t.cfl) << "\n  dt_max: " << num(t.dt_max)
    << "\n  dt_min: " << num(t.dt_min) << "\n  dt_initial: " << num(t.dt_initial)
    << "\n  dt_collapse_fraction: " << num(t.dt_collapse_fraction) << "\n  max_steps: " << t.max_steps
    << "\n";
  o << "gravity: " << vec(s.gravity, dim) << "\n";
  materials(o, s);
  geometry(o, s);
  boundary(o, s);
  loadsAndSources(o, s);
  options(o, s);
  return o.str();
}

}  // namespace mpmice::core
