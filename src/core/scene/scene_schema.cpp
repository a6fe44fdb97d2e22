// The scene schema: every section and key of a scene file, read, checked and completed here.
// docs/scene-reference.md documents the same keys; keep the two in step. Each reader lists the
// keys its mapping may hold (YamlMap::allow), so an unknown key is an error with a suggestion.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/scene/did_you_mean.h"
#include "core/scene/model_catalog.h"
#include "core/scene/resource_estimate.h"
#include "core/scene/scene.h"
#include "core/scene/shape.h"
#include "core/scene/yaml_reader.h"

namespace mpmice::core {

namespace {

using namespace scene_detail;

const std::vector<std::string> kFaces{"x-", "x+", "y-", "y+", "z-", "z+"};
const std::vector<std::string> kBoundaryTypes{"symmetry", "slip_wall", "noslip_wall", "inflow",
                                              "outflow",  "periodic",  "free"};
const char* const kAxes = "xyz";
constexpr long kIntMax = std::numeric_limits<int>::max();

std::string str(double v) { return formatNumber(v); }

/// A computed value (a sum) shown to 12 digits, so round-off does not clutter the message.
std::string rounded(double v) {
  std::ostringstream os;
  os << std::setprecision(12) << v;
  return os.str();
}

std::string describeFaces(int dim) {
  std::string s;
  for (int f = 0; f < 2 * dim; ++f) s += (f ? ", " : "") + kFaces[static_cast<std::size_t>(f)];
  return s;
}

/// A key that applies only to the other kind of object: a clearer message than "unknown key".
void allowFor(const YamlMap& map, const std::vector<std::string>& keys, const std::vector<std::string>& otherKeys,
              const std::string& why) {
  if (const auto bad = map.firstKeyOutside(keys)) {
    const std::string key = bad->node().Scalar();
    if (std::find(otherKeys.begin(), otherKeys.end(), key) != otherKeys.end())
      bad->fail("key '" + key + "' does not apply here: " + why);
  }
  map.allow(keys);
}

class SchemaReader {
 public:
  SchemaReader(const std::string& text, const std::string& file) : root_(parseYamlText(text, file)) {
    s_.file = file;
  }

  Scene read() {
    if (root_.isNull()) root_.fail("the scene is empty; expected a mapping with mesh, time, materials, geometry, ...");
    const YamlMap top = root_.map();
    top.allow({"scene", "description", "mesh", "time", "gravity", "materials", "geometry", "boundary", "loads",
               "sources", "mpm", "ice", "coupling", "output"});
    // scene: the scene's name (default: the file name without extension).
    const std::string stem = std::filesystem::path(s_.file).stem().string();
    s_.name = top.string("scene", stem.empty() ? std::string("scene") : stem);
    // description: free text.
    if (const auto d = top.get("description")) {
      if (!d->isScalar() && !d->isNull()) d->fail("expected a string, got " + d->shown());
      s_.description = d->isNull() ? std::string() : d->node().Scalar();
    }
    readMesh(top.required("mesh"));
    readTime(top.required("time"));
    s_.gravity = top.vector("gravity", dim_, {0, 0, 0});
    readMaterials(top.required("materials"));
    readBoundary(top.get("boundary"));  // before geometry: solids may cross symmetry faces
    readGeometry(top.required("geometry"));
    if (const auto v = top.get("loads"))
      for (const auto& item : v->list()) s_.loads.push_back(readLoad(item));
    if (const auto v = top.get("sources"))
      for (const auto& item : v->list()) s_.sources.push_back(readSource(item));
    if (const auto v = top.get("mpm")) readMpm(*v);
    if (const auto v = top.get("ice")) readIce(*v);
    if (const auto v = top.get("coupling")) readCoupling(*v);
    if (const auto v = top.get("output")) readOutput(*v);
    checkMemory(top.required("mesh"));
    return s_;
  }

 private:
  // ------------------------------------------------------------------------------------ mesh
  void readMesh(const YamlValue& v) {
    const YamlMap m = v.map();
    m.allow({"dim", "lower", "upper", "cells", "spacing"});
    dim_ = static_cast<int>(m.required("dim").integer(1, 3));           // dim: 1, 2 or 3
    const RealVect lower = m.required("lower").vector(dim_);            // lower: corner [m]
    const YamlValue upperValue = m.required("upper");                   // upper: corner [m]
    const RealVect upper = upperValue.vector(dim_);
    for (int d = 0; d < dim_; ++d)
      if (!(upper[d] > lower[d]))
        upperValue.fail(std::string("upper must exceed lower in every direction; in ") + kAxes[d] + ": lower " +
                        str(lower[d]) + ", upper " + str(upper[d]));
    const auto cells = m.get("cells"), spacing = m.get("spacing");
    if (cells && spacing) spacing->fail("give either cells or spacing, not both");
    if (!cells && !spacing) m.fail("missing required key 'cells' (or 'spacing'): the mesh resolution");
    IntVect n{1, 1, 1};
    RealVect dx{1, 1, 1};
    if (cells) {  // cells: cells per direction, a list of dim integers >= 1
      if (!cells->isList() || static_cast<int>(cells->list().size()) != dim_)
        cells->fail("expected a list of " + std::to_string(dim_) + (dim_ == 1 ? " integer" : " integers") +
                    " >= 1 (cells per direction), got " +
                    (cells->isList() ? std::to_string(cells->list().size()) : cells->shown()));
      const auto items = cells->list();
      for (int d = 0; d < dim_; ++d) n[d] = static_cast<int>(items[static_cast<std::size_t>(d)].integer(1, kIntMax));
    } else {  // spacing: one number or one per direction; must divide upper - lower
      RealVect h{0, 0, 0};
      if (spacing->isList()) {
        h = spacing->vector(dim_, Range::positive());
      } else {
        const double one = spacing->number(Range::positive());
        for (int d = 0; d < dim_; ++d) h[d] = one;
      }
      for (int d = 0; d < dim_; ++d) {
        const double extent = upper[d] - lower[d];
        const double ratio = extent / h[d];
        const double rounded = std::round(ratio);
        if (rounded < 1 || std::abs(rounded * h[d] - extent) > 1e-9 * extent)
          spacing->fail("spacing " + str(h[d]) + " does not divide the mesh extent " + str(extent) + " in " +
                        kAxes[d] + " (" + str(extent) + " / " + str(h[d]) + " = " + str(ratio) +
                        "); choose a spacing that fits a whole number of cells, or give cells");
        if (rounded > double(kIntMax))
          spacing->fail("spacing " + str(h[d]) + " gives " + str(rounded) + " cells in " + kAxes[d] +
                        ", more than the " + std::to_string(kIntMax) + " one direction can hold; choose a coarser spacing");
        n[d] = static_cast<int>(rounded);
      }
    }
    // The cell count in checked 64-bit arithmetic (each direction fits an int, the product may not).
    std::int64_t total = 1;
    for (int d = 0; d < dim_; ++d)
      if (__builtin_mul_overflow(total, std::int64_t(n[d]), &total))
        (cells ? *cells : *spacing)
            .fail("the mesh would have more than " + std::to_string(std::numeric_limits<std::int64_t>::max()) +
                  " cells (" + std::to_string(n[0]) + (dim_ > 1 ? " x " + std::to_string(n[1]) : "") +
                  (dim_ > 2 ? " x " + std::to_string(n[2]) : "") + "); choose fewer cells");
    // The mesh spans exactly [lower, upper]: the spacing is the extent over the cell count.
    for (int d = 0; d < dim_; ++d) dx[d] = (upper[d] - lower[d]) / n[d];
    s_.mesh = Mesh(dim_, lower, dx, n);
  }

  /// A scene whose lower-bound memory estimate exceeds what this machine has available now
  /// cannot run: refuse it with the estimate (resource_estimate.h).
  void checkMemory(const YamlValue& mesh) const {
    const ResourceEstimate e = estimateResources(s_);
    const double available = availableMemory();
    if (available > 0 && e.bytes > available)
      mesh.fail("the scene needs " + e.describe() + " (a lower bound), more than the " +
                str(available / 1073741824.0) + " GiB this machine has available; coarsen the mesh " +
                "(mesh.spacing or mesh.cells) or the solids' particles_per_cell");
  }

  // ------------------------------------------------------------------------------------ time
  void readTime(const YamlValue& v) {
    const YamlMap m = v.map();
    m.allow({"end", "cfl", "dt_max", "dt_min", "dt_initial", "dt_collapse_fraction", "max_steps"});
    TimeSpec& t = s_.time;
    t.end = m.number("end", Range::positive());                                  // end time [s]
    t.cfl = m.number("cfl", t.cfl, Range::openClosed(0, 1));                     // CFL number
    t.dt_max = m.number("dt_max", t.dt_max, Range::positive());                  // largest step [s]
    t.dt_min = m.number("dt_min", t.dt_min, Range::nonNegative());               // smallest step [s]
    t.dt_initial = m.number("dt_initial", t.dt_initial, Range::nonNegative());   // 0 = from CFL
    // A stable step below this fraction of the first one stops the run (0 = off).
    t.dt_collapse_fraction = m.number("dt_collapse_fraction", t.dt_collapse_fraction, Range{0.0, 1.0, false, true});
    t.max_steps = m.integer("max_steps", t.max_steps, 0);                        // 0 = no limit
    if (t.dt_min > t.dt_max)
      m.required("dt_min").fail("dt_min " + str(t.dt_min) + " exceeds dt_max " + str(t.dt_max));
  }

  // ------------------------------------------------------------------------------- materials
  void readMaterials(const YamlValue& v) {
    const auto items = v.list();
    if (items.empty()) v.fail("expected at least one material");
    for (const auto& item : items) s_.materials.push_back(readMaterial(item));
  }

  MaterialSpec readMaterial(const YamlValue& v) {
    const YamlMap m = v.map();
    MaterialSpec mat;
    mat.where = v.loc();
    const YamlValue nameValue = m.required("name");  // name: unique, referenced elsewhere
    mat.name = nameValue.string();
    for (std::size_t i = 0; i < s_.materials.size(); ++i)
      if (s_.materials[i].name == mat.name)
        nameValue.fail("duplicate material name '" + mat.name + "' (materials[" + std::to_string(i) +
                       "] has it already); material names must be unique");
    const std::string kind = m.required("kind").choice({"fluid", "solid"}, "material kind");
    const std::vector<std::string> fluidKeys{"name", "kind", "eos", "density", "specific_heat", "viscosity",
                                             "thermal_conductivity", "cavitation"};
    const std::vector<std::string> solidKeys{"name", "kind", "density", "model", "eos", "specific_heat",
                                             "thermal_conductivity", "thermal_expansivity"};
    // specific_heat: cv [J/(kg K)]; thermal_conductivity [W/(m K)].
    if (kind == "fluid") {
      mat.kind = MaterialKind::Fluid;
      allowFor(m, fluidKeys, solidKeys, "material '" + mat.name + "' is a fluid");
      mat.eos = readModel(m.required("eos"), fluidEquationsOfState());          // eos: see catalog
      mat.density = m.number("density", 0.0, Range::positive());               // optional reference
      mat.viscosity = m.number("viscosity", mat.viscosity, Range::nonNegative());  // [Pa s]
      // cavitation: {model: pressure_cutoff, pressure: p_c} (docs/ice.md "Cavitation"); absent: none.
      if (const auto cav = m.get("cavitation")) mat.cavitation = readCavitation(*cav, mat);
    } else {
      mat.kind = MaterialKind::Solid;
      allowFor(m, solidKeys, fluidKeys, "material '" + mat.name + "' is a solid");
      mat.density = m.number("density", Range::positive());                    // [kg/m^3], required
      mat.constitutive = readModel(m.required("model"), constitutiveModels());  // model: see catalog
      if (const auto eos = m.get("eos")) {
        mat.eos = readModel(*eos, solidEquationsOfState());
        if (mat.eos.type == "crush_curve" && mat.constitutive.type != "crushable_foam")
          eos->fail("material '" + mat.name + "': the crush_curve equation of state is a crushable foam's; its model "
                    "is '" + mat.constitutive.type + "' (use solid_bulk)");
      }
      completeSolidEos(mat.eos, mat.constitutive, mat.density);
      mat.thermal_expansivity = m.number("thermal_expansivity", 0.0, Range::any());  // beta [1/K]
    }
    mat.specific_heat = m.number("specific_heat", mat.specific_heat, Range::positive());
    mat.thermal_conductivity = m.number("thermal_conductivity", 0.0, Range::nonNegative());
    return mat;
  }

  /// `cavitation: {model: pressure_cutoff, pressure: p_c}` of fluid `mat`: a model mapping whose
  /// name key is `model` (checked against cavitationModels()). Only liquids may cavitate.
  static ModelSpec readCavitation(const YamlValue& v, const MaterialSpec& mat) {
    if (!v.isMap()) v.fail("expected a mapping {model: pressure_cutoff, pressure: <Pa>}; got " + v.shown());
    const YamlMap map = v.map();
    const YamlValue model = map.required("model");
    const ModelFamily& family = cavitationModels();
    ModelSpec c;
    c.where = v.loc();
    c.type = model.choice(family.names(), family.noun);
    std::vector<std::string> keys = family.find(c.type)->keys();
    std::replace(keys.begin(), keys.end(), std::string("type"), std::string("model"));
    map.allow(keys);
    for (const auto& p : family.find(c.type)->params) c.params[p.name] = map.number(p.name, p.range);
    if (mat.eos.type != "mie_gruneisen" && mat.eos.type != "stiffened_gas")
      model.fail("material '" + mat.name + "' has the equation of state '" + mat.eos.type +
                 "'; cavitation applies to liquids: mie_gruneisen or stiffened_gas");
    if (mat.eos.type == "stiffened_gas" && !(c.params["pressure"] > -mat.eos.get("p_inf")))
      map.required("pressure").fail("the cut-off " + str(c.params["pressure"]) + " Pa must lie above the stiffened gas's " +
                                    "lowest pressure -p_inf = " + str(-mat.eos.get("p_inf")) + " Pa");
    if (mat.eos.type == "mie_gruneisen" && !(c.params["pressure"] < mat.eos.get("reference_pressure", 0.0)))
      map.required("pressure").fail("the cut-off " + str(c.params["pressure"]) + " Pa must lie below the " +
                                    "liquid's reference_pressure " + str(mat.eos.get("reference_pressure", 0.0)) +
                                    " Pa (a vapour pressure or a tensile limit)");
    return c;
  }

  /// A reference to a material by name; `kind` restricts it (nullptr: any).
  std::string materialRef(const YamlValue& v, const MaterialKind* kind, const std::string& why) const {
    std::vector<std::string> names;
    for (const auto& mat : s_.materials) names.push_back(mat.name);
    const std::string name = v.choice(names, "material");
    if (kind && s_.material(name)->kind != *kind)
      v.fail("material '" + name + "' is a " + (*kind == MaterialKind::Solid ? "fluid" : "solid") + "; " + why);
    return name;
  }

  // ---------------------------------------------------------------------------------- shapes
  ShapeSpec readShape(const YamlValue& v) const {
    const YamlMap m = v.map();
    ShapeSpec sh;
    sh.where = v.loc();
    const YamlValue typeValue = m.required("type");
    sh.type = typeValue.choice(shapeTypes(), "shape type");
    if (sh.type == "circle") {
      if (dim_ != 2) typeValue.fail("'circle' is a 2D shape and this mesh is " + std::to_string(dim_) + "D; use 'sphere'");
      sh.type = "sphere";
    }
    const std::vector<std::string> axisKeys{"axis", "length"};
    auto roundKeys = [&](std::vector<std::string> keys) {
      if (dim_ == 3) keys.insert(keys.end(), axisKeys.begin(), axisKeys.end());
      allowFor(m, keys, axisKeys, "axis and length apply to 3D meshes only");
    };
    auto readAxis = [&] {
      if (dim_ != 3) return;
      const auto a = m.get("axis");  // axis: direction of the axis (3D), default [0, 0, 1]
      if (a) {
        sh.axis = a->vector(3);
        if (sh.axis[0] == 0 && sh.axis[1] == 0 && sh.axis[2] == 0) a->fail("the axis must not be zero");
      }
      sh.length = m.number("length", 0.0, Range::nonNegative());  // 0 = infinite
    };
    if (sh.type == "box") {
      m.allow({"type", "lo", "hi"});
      sh.lo = m.required("lo").vector(dim_);
      const YamlValue hiValue = m.required("hi");
      sh.hi = hiValue.vector(dim_);
      for (int d = 0; d < dim_; ++d)
        if (!(sh.lo[d] < sh.hi[d]))
          hiValue.fail(std::string("box needs lo < hi in every direction; in ") + kAxes[d] + ": lo " +
                       str(sh.lo[d]) + " >= hi " + str(sh.hi[d]));
    } else if (sh.type == "sphere") {
      m.allow({"type", "center", "radius"});
      sh.center = m.required("center").vector(dim_);
      sh.radius = m.number("radius", Range::positive());
    } else if (sh.type == "cylinder") {
      roundKeys({"type", "center", "radius"});
      sh.center = m.required("center").vector(dim_);
      sh.radius = m.number("radius", Range::positive());
      readAxis();
    } else if (sh.type == "annulus") {
      roundKeys({"type", "center", "inner_radius", "outer_radius"});
      sh.center = m.required("center").vector(dim_);
      sh.inner_radius = m.number("inner_radius", Range::nonNegative());
      sh.outer_radius = m.number("outer_radius", Range::positive());
      if (!(sh.inner_radius < sh.outer_radius))
        m.required("inner_radius")
            .fail("inner_radius " + str(sh.inner_radius) + " must be below outer_radius " + str(sh.outer_radius));
      readAxis();
    } else {  // union, difference
      m.allow({"type", "shapes"});
      const YamlValue list = m.required("shapes");
      const auto items = list.list();
      const std::size_t least = sh.type == "union" ? 1 : 2;
      if (items.size() < least)
        list.fail(sh.type + " needs at least " + std::to_string(least) + " shapes, got " + std::to_string(items.size()));
      for (const auto& item : items) sh.children.push_back(readShape(item));
    }
    return sh;
  }

  // -------------------------------------------------------------------------------- geometry
  void readGeometry(const YamlValue& v) {
    const auto items = v.list();
    if (items.empty()) v.fail("expected at least one geometry object");
    for (const auto& item : items) s_.geometry.push_back(readRegion(item));
  }

  RegionSpec readRegion(const YamlValue& v) {
    const YamlMap m = v.map();
    RegionSpec r;
    r.where = v.loc();
    r.name = m.string("name", "");
    const std::string label = r.name.empty() ? v.path() : v.path() + " ('" + r.name + "')";
    const auto material = m.get("material"), mixture = m.get("mixture");
    if (material && mixture) mixture->fail("give either material or mixture, not both");
    if (!material && !mixture) m.fail("missing required key 'material' (or 'mixture'): what fills " + label);
    if (material) {  // material: one material, volume fraction 1
      r.fill.push_back({materialRef(*material, nullptr, ""), 1.0});
    } else {  // mixture: [{material, volume_fraction}, ...], fractions sum to 1
      double sum = 0;
      for (const auto& item : mixture->list()) {
        const YamlMap f = item.map();
        f.allow({"material", "volume_fraction"});
        const YamlValue ref = f.required("material");
        FillSpec fill{materialRef(ref, nullptr, ""), f.number("volume_fraction", Range::openClosed(0, 1))};
        for (const auto& other : r.fill)
          if (other.material == fill.material) ref.fail("material '" + fill.material + "' appears twice in the mixture");
        sum += fill.volume_fraction;
        r.fill.push_back(fill);
      }
      if (r.fill.empty()) mixture->fail("expected at least one material in the mixture");
      if (std::abs(sum - 1.0) > 1e-9)
        mixture->fail(label + ": the volume fractions sum to " + rounded(sum) + ", expected 1 (within 1e-9)");
    }
    bool solid = false;
    for (const auto& f : r.fill) solid = solid || s_.material(f.material)->kind == MaterialKind::Solid;
    if (solid && r.fill.size() > 1)
      mixture->fail(label + ": a solid cannot share a geometry object with other materials; give the solid "
                    "its own geometry object (its particles fill the shape)");
    const std::vector<std::string> common{"name",     "shape",           "material",          "mixture",
                                          "velocity", "velocity_origin", "velocity_gradient", "temperature"};
    std::vector<std::string> fluidKeys = common, solidKeys = common;
    fluidKeys.insert(fluidKeys.end(), {"pressure", "density"});
    solidKeys.push_back("particles_per_cell");
    allowFor(m, solid ? solidKeys : fluidKeys, solid ? fluidKeys : solidKeys,
             solid ? "pressure and density apply to fluid geometry; a solid takes its density from its material"
                   : "particles_per_cell applies to solid geometry only");
    const YamlValue shapeValue = m.required("shape");
    r.shape = readShape(shapeValue);
    r.velocity = m.vector("velocity", dim_, {0, 0, 0});                  // initial velocity [m/s]
    readVelocityProfile(m, r);
    r.temperature = m.number("temperature", r.temperature, Range::positive());  // [K]
    if (!solid) {
      r.pressure = m.number("pressure", Range::positive());               // [Pa], required
      if (m.has("density")) r.density = m.number("density", Range::positive());  // [kg/m^3]
      // pressure and one of density or temperature fix a fluid's state: the third was ignored
      // (a filler given 970 kg/m^3, 50 MPa and 300 K started at 663.7 K, silently).
      if (m.has("density") && m.has("temperature"))
        m.required("temperature").fail("give density or temperature for a fluid region, not both: with the pressure "
                                       "either fixes the state (density " + rounded(*r.density) + " kg/m^3 was "
                                       "given, so this temperature was ignored)");
    } else {
      // particles_per_cell: one integer or one per direction (directions beyond dim hold 1)
      IntVect ppc{1, 1, 1};
      for (int d = 0; d < dim_; ++d) ppc[d] = 2;
      if (const auto p = m.get("particles_per_cell")) {
        if (p->isList()) {
          const auto items = p->list();
          if (static_cast<int>(items.size()) != dim_)
            p->fail("expected one integer or a list of " + std::to_string(dim_) + " integers >= 1, got " +
                    std::to_string(items.size()));
          for (int d = 0; d < dim_; ++d) ppc[d] = static_cast<int>(items[static_cast<std::size_t>(d)].integer(1, 1000));
        } else {
          const int one = static_cast<int>(p->integer(1, 1000));
          for (int d = 0; d < dim_; ++d) ppc[d] = one;
        }
      }
      r.particles_per_cell = ppc;
      checkInsideMesh(r.shape, shapeValue, label);
    }
    return r;
  }

  /// velocity_gradient: dim rows of dim numbers (row i: d u_i / d x_j [1/s]); velocity_origin: the
  /// point [m] where the velocity is `velocity` (default: the coordinate origin).
  void readVelocityProfile(const YamlMap& m, RegionSpec& r) const {
    const auto g = m.get("velocity_gradient");
    if (const auto o = m.get("velocity_origin")) {
      if (!g) o->fail("velocity_origin needs velocity_gradient: it is the point where the velocity is `velocity`");
      r.velocity_origin = o->vector(dim_);
    }
    if (!g) return;
    const std::string expected = "expected " + std::to_string(dim_) + " rows of " + std::to_string(dim_) +
                                 " numbers (row i: d u_i / d x_j [1/s]), e.g. " +
                                 (dim_ == 1 ? std::string("[[-25]]") : dim_ == 2 ? std::string("[[0, 1], [0, 0]]")
                                                                                 : std::string("[[0, 1, 0], [0, 0, 0], [0, 0, 0]]"));
    if (!g->isList()) g->fail(expected + ", got " + g->shown());
    const auto rows = g->list();
    if (static_cast<int>(rows.size()) != dim_) g->fail(expected + ", got " + std::to_string(rows.size()) + " rows");
    for (int i = 0; i < dim_; ++i) {
      const YamlValue& row = rows[static_cast<std::size_t>(i)];
      if (!row.isList()) row.fail(expected + "; row " + std::to_string(i + 1) + " is " + row.shown());
      r.velocity_gradient[static_cast<std::size_t>(i)] = row.vector(dim_);
    }
  }

  void checkInsideMesh(const ShapeSpec& sh, const YamlValue& where, const std::string& label) const {
    const auto b = shapeBounds(sh, dim_);
    if (!b) return;
    const Mesh& mesh = s_.mesh;
    // Beyond a symmetry face the shape continues as its mirror image (quarter models), so only
    // the other faces bound the solid.
    for (int d = 0; d < dim_; ++d) {
      const double lo = mesh.origin()[d], hi = mesh.upper(d), tol = 1e-9 * (hi - lo);
      const bool mirrorLo = s_.boundary[static_cast<std::size_t>(2 * d)].type == BoundaryType::Symmetry;
      const bool mirrorHi = s_.boundary[static_cast<std::size_t>(2 * d + 1)].type == BoundaryType::Symmetry;
      if ((!mirrorLo && b->first[d] < lo - tol) || (!mirrorHi && b->second[d] > hi + tol))
        where.fail(label + ": the solid reaches outside the mesh: " + kAxes[d] + " in [" + str(b->first[d]) +
                   ", " + str(b->second[d]) + "] but the mesh spans [" + str(lo) + ", " + str(hi) +
                   "]; particles outside the mesh are an error: move or shrink the shape, or enlarge the mesh "
                   "(only symmetry faces may cut a solid)");
    }
  }

  // -------------------------------------------------------------------------------- boundary
  void readBoundary(const std::optional<YamlValue>& v) {
    if (v) {
      const YamlMap m = v->map();
      m.allow(kFaces);
      for (int f = 0; f < 6; ++f) {
        const auto face = m.get(kFaces[static_cast<std::size_t>(f)]);
        if (!face) continue;
        if (f >= 2 * dim_)
          face->fail("face '" + kFaces[static_cast<std::size_t>(f)] + "' is beyond the mesh dimension " +
                     std::to_string(dim_) + " (faces: " + describeFaces(dim_) + ")");
        s_.boundary[static_cast<std::size_t>(f)] = readFace(*face);
      }
    }
    for (int d = 0; d < dim_; ++d) {
      const auto& a = s_.boundary[static_cast<std::size_t>(2 * d)];
      const auto& b = s_.boundary[static_cast<std::size_t>(2 * d + 1)];
      if ((a.type == BoundaryType::Periodic) == (b.type == BoundaryType::Periodic)) continue;
      const int f = a.type == BoundaryType::Periodic ? 2 * d : 2 * d + 1;
      const int other = f ^ 1;
      const auto& o = s_.boundary[static_cast<std::size_t>(other)];
      const SourceLoc loc = s_.boundary[static_cast<std::size_t>(f)].where;
      throw SceneError(loc, std::string("boundary.") + boundaryFaceName(f),
                       std::string("periodic must be set on both faces ") + boundaryFaceName(2 * d) + " and " +
                           boundaryFaceName(2 * d + 1) + "; " + boundaryFaceName(other) + " is " +
                           toString(o.type) + (o.where.line == 0 ? " (the default)" : ""));
    }
  }

  BoundarySpec readFace(const YamlValue& v) const {
    BoundarySpec b;
    b.where = v.loc();
    std::optional<YamlMap> m;
    std::string type;
    if (v.isScalar()) {  // shorthand: just the type name
      type = v.choice(kBoundaryTypes, "boundary condition");
    } else {
      m.emplace(v.map());
      type = m->required("type").choice(kBoundaryTypes, "boundary condition");
    }
    const auto index = std::find(kBoundaryTypes.begin(), kBoundaryTypes.end(), type) - kBoundaryTypes.begin();
    b.type = static_cast<BoundaryType>(index);
    if (b.type == BoundaryType::Inflow) {
      if (!m) v.fail("inflow needs velocity and pressure: write {type: inflow, velocity: [...], pressure: ...}");
      m->allow({"type", "velocity", "pressure", "density", "temperature", "material"});
      b.velocity = m->required("velocity").vector(dim_);   // [m/s]
      b.pressure = m->number("pressure", Range::positive());  // [Pa]
      if (m->has("density") && m->has("temperature"))
        m->required("temperature").fail("give density or temperature for an inflow, not both");
      if (m->has("density")) b.density = m->number("density", Range::positive());
      b.temperature = m->number("temperature", b.temperature, Range::positive());
      const MaterialKind fluid = MaterialKind::Fluid;
      if (const auto mat = m->get("material")) {
        b.material = materialRef(*mat, &fluid, "only a fluid can flow in");
      } else {
        const auto fluids = s_.fluids();
        if (fluids.empty()) v.fail("an inflow needs a fluid material, and the scene has none");
        b.material = s_.materials[static_cast<std::size_t>(fluids.front())].name;
      }
    } else if (b.type == BoundaryType::Outflow) {
      if (m) {
        m->allow({"type", "pressure"});
        if (m->has("pressure")) b.pressure = m->number("pressure", Range::positive());  // fixed [Pa]
      }
    } else if (m) {
      m->allow({"type"}, std::string(toString(b.type)) + " takes no parameters");
    }
    return b;
  }

  // ------------------------------------------------------------------------- loads, sources
  LoadSpec readLoad(const YamlValue& v) const {
    const YamlMap m = v.map();
    LoadSpec l;
    l.where = v.loc();
    l.type = m.required("type").option(kLoadNames, "load type");
    if (l.type == LoadType::File) return readFileLoad(m, l);
    const std::vector<std::string> pressureKeys{"type", "material", "shape", "pressure", "center", "start", "ramp"};
    const std::vector<std::string> tractionKeys{"type", "material", "shape", "traction", "start", "ramp"};
    const bool pressure = l.type == LoadType::Pressure;
    allowFor(m, pressure ? pressureKeys : tractionKeys, pressure ? tractionKeys : pressureKeys,
             "a " + std::string(name(l.type)) + " load takes " + joinNames(pressure ? pressureKeys : tractionKeys));
    const MaterialKind solid = MaterialKind::Solid;
    l.material = materialRef(m.required("material"), &solid, "loads act on solid particles");
    l.shape = readShape(m.required("shape"));
    if (pressure) {
      l.pressure = m.number("pressure", Range::any());  // [Pa], pushes away from center
      l.center = m.vector("center", dim_, {0, 0, 0});
    } else {
      l.traction = m.required("traction").vector(dim_);  // [Pa] per unit area
    }
    l.start = m.number("start", 0.0, Range::nonNegative());  // [s]
    l.ramp = m.number("ramp", 0.0, Range::nonNegative());    // [s], 0 = at once
    return l;
  }

  // Point forces from a fluid code's export file, held on the solid's surface particles.
  LoadSpec readFileLoad(const YamlMap& m, LoadSpec l) const {
    m.allow({"type", "material", "file", "mapping", "rbf_support", "depth", "moment_center"},
            "a file load takes type, material, file, mapping, rbf_support, depth, moment_center "
            "(it acts on the whole surface of the material from t = 0)");
    const MaterialKind solid = MaterialKind::Solid;
    l.material = materialRef(m.required("material"), &solid, "loads act on solid particles");
    l.file = m.required("file").string();
    if (l.file.empty()) m.required("file").fail("expected the path of a force export file");
    l.mapping = m.option("mapping", l.mapping, kInterfaceMappingNames, "interface mapping");
    l.rbf_support = m.number("rbf_support", l.rbf_support, Range::nonNegative());  // [m], 0 = thin-plate spline
    l.depth = m.number("depth", 0.0, Range::nonNegative());                          // [m], 0 = the file's
    l.moment_center = m.vector("moment_center", dim_, {0, 0, 0});
    return l;
  }

  SourceSpec readSource(const YamlValue& v) const {
    const YamlMap m = v.map();
    m.allow({"material", "shape", "power_density", "start", "end"});
    SourceSpec src;
    src.where = v.loc();
    const MaterialKind fluid = MaterialKind::Fluid;
    src.material = materialRef(m.required("material"), &fluid, "sources heat fluids");
    src.shape = readShape(m.required("shape"));
    src.power_density = m.number("power_density", Range::any());  // [W/m^3]
    src.start = m.number("start", 0.0, Range::nonNegative());      // [s]
    src.end = m.number("end", s_.time.end, Range::nonNegative());  // [s], default: time.end
    if (!(src.end > src.start))
      (m.has("end") ? m.required("end") : v).fail("end " + str(src.end) + " must be after start " + str(src.start));
    return src;
  }

  // ----------------------------------------------------------------------- solver options
  void readMpm(const YamlValue& v) {
    const YamlMap m = v.map();
    m.allow({"shape_function", "update", "flip", "damping", "sort_particles", "stress_work", "outflow_particles"});
    MpmOptions& o = s_.mpm;
    o.shape_function = m.choice("shape_function", o.shape_function, {"linear", "gimp", "bspline2", "bspline3"},
                                "shape function");
    o.update = m.choice("update", o.update, {"usf", "usl", "musl"}, "MPM update scheme");
    o.flip = m.number("flip", o.flip, Range::closed(0, 1));                 // 1 = FLIP, 0 = PIC
    o.damping = m.number("damping", o.damping, Range::nonNegative());       // [1/s]
    o.sort_particles = m.boolean("sort_particles", o.sort_particles);
    o.stress_work = m.choice("stress_work", o.stress_work, {"auto", "material", "grid"}, "stress work");
    o.outflow_particles =
        m.choice("outflow_particles", o.outflow_particles, {"remove", "error"}, "particles leaving through an outflow face");
  }

  void readIce(const YamlValue& v) {
    const YamlMap m = v.map();
    m.allow({"advection", "limiter", "pressure_solver", "linear_solver", "solver_tolerance",
             "solver_max_iterations", "preconditioner_reuse", "exchange", "pressure_iterations", "pressure_tolerance", "shock_viscosity",
             "face_pressure", "trace_mass_fraction", "equilibrium", "semi_implicit_sound_fraction",
             "semi_implicit_theta"});
    IceOptions& o = s_.ice;
    o.advection = m.choice("advection", o.advection, {"first_order", "second_order"}, "advection scheme");
    o.limiter = m.choice("limiter", o.limiter, {"minmod", "van_leer", "superbee"}, "limiter");
    o.pressure_solver = m.choice("pressure_solver", o.pressure_solver, {"explicit", "semi_implicit"}, "pressure solver");
    o.linear_solver = m.choice("linear_solver", o.linear_solver, {"cg", "bicgstab", "pfmg_pcg", "smg_pcg"}, "linear solver");
    o.solver_tolerance = m.number("solver_tolerance", o.solver_tolerance, Range::positive());
    o.solver_max_iterations = static_cast<int>(m.integer("solver_max_iterations", o.solver_max_iterations, 1, kIntMax));
    o.preconditioner_reuse = static_cast<int>(m.integer("preconditioner_reuse", o.preconditioner_reuse, 1, kIntMax));
    o.max_pressure_iterations = static_cast<int>(m.integer("pressure_iterations", o.max_pressure_iterations, 1, kIntMax));
    o.pressure_tolerance = m.number("pressure_tolerance", o.pressure_tolerance, Range::positive());
    o.face_pressure =
        m.choice("face_pressure", o.face_pressure, {"auto", "riemann", "riemann_low_mach", "average"}, "face pressure");
    o.trace_mass_fraction = m.number("trace_mass_fraction", o.trace_mass_fraction, Range::closed(0, 0.01));
    o.equilibrium = m.choice("equilibrium", o.equilibrium, {"fixed_energy", "with_work"}, "equilibrium pressure energies");
    o.semi_implicit_sound_fraction =
        m.number("semi_implicit_sound_fraction", o.semi_implicit_sound_fraction, Range::openClosed(0, 1));
    o.semi_implicit_theta = m.number("semi_implicit_theta", o.semi_implicit_theta, Range::closed(0.5, 1));
    if (const auto sv = m.get("shock_viscosity")) {
      const YamlMap q = sv->map();
      q.allow({"linear", "quadratic"});
      o.shock_viscosity_linear = q.number("linear", o.shock_viscosity_linear, Range::nonNegative());
      o.shock_viscosity_quadratic = q.number("quadratic", o.shock_viscosity_quadratic, Range::nonNegative());
    }
    if (const auto ex = m.get("exchange")) {
      const YamlMap e = ex->map();
      e.allow({"momentum", "heat", "pairs"});
      o.exchange_momentum = e.number("momentum", o.exchange_momentum, Range::nonNegative());  // K
      o.exchange_heat = e.number("heat", o.exchange_heat, Range::nonNegative());              // H
      if (const auto pairs = e.get("pairs"))
        for (const auto& item : pairs->list()) {
          const YamlMap p = item.map();
          p.allow({"materials", "momentum", "heat"});
          const YamlValue mats = p.required("materials");
          const auto names = mats.list();
          if (names.size() != 2) mats.fail("expected a list of two material names, got " + std::to_string(names.size()));
          ExchangePair pair;
          pair.a = materialRef(names[0], nullptr, "");
          pair.b = materialRef(names[1], nullptr, "");
          if (pair.a == pair.b) mats.fail("an exchange pair needs two different materials, got '" + pair.a + "' twice");
          for (const auto& q : o.exchange_pairs)
            if ((q.a == pair.a && q.b == pair.b) || (q.a == pair.b && q.b == pair.a))
              mats.fail("the pair (" + pair.a + ", " + pair.b + ") is given twice");
          pair.momentum = p.number("momentum", o.exchange_momentum, Range::nonNegative());
          pair.heat = p.number("heat", o.exchange_heat, Range::nonNegative());
          o.exchange_pairs.push_back(pair);
        }
    }
  }

  void readCoupling(const YamlValue& v) {
    const YamlMap m = v.map();
    m.allow({"schedule", "fluid", "min_iterations", "max_iterations", "accept_unconverged", "timeout", "ranks",
             "convergence", "acceleration", "interface", "solid_transport", "surface_pressure"});
    CouplingSpec& c = s_.coupling;
    c.schedule = m.option("schedule", c.schedule, kScheduleNames, "coupling schedule");
    c.fluid = m.option("fluid", c.fluid, kFluidSolverNames, "fluid solver");
    if (c.fluid == FluidSolver::OpenFoam) {
      c.interface = readInterface(m.required("interface"));
      if (c.schedule == Schedule::Monolithic || isParallel(c.schedule)) {
        const std::string why = "schedule '" + std::string(name(c.schedule)) +
                                "' does not apply to coupling.fluid 'openfoam', which "
                                "couples through the interface one side after the other; valid schedules: "
                                "explicit_serial, implicit_serial";
        if (const auto sv = m.get("schedule")) sv->fail(why);
        m.fail(why);
      }
    } else if (const auto i = m.get("interface")) {
      i->fail("coupling.interface applies to coupling.fluid 'openfoam' only (ICE shares the volume, not a surface)");
    }
    c.min_iterations = static_cast<int>(m.integer("min_iterations", c.min_iterations, 1, kIntMax));
    c.max_iterations = static_cast<int>(m.integer("max_iterations", c.max_iterations, c.min_iterations, kIntMax));
    c.accept_unconverged = m.boolean("accept_unconverged", c.accept_unconverged);
    c.timeout = m.number("timeout", c.timeout, Range::positive());  // [s]
    // ice: ICE's face fluxes of the solid's cell fraction (the default); mpm: MPM sends, per cell
    // face, the face transport of its node-to-cell average (docs/flap.md "Mixed cells").
    c.solid_transport = m.choice("solid_transport", c.solid_transport, {"ice", "mpm"}, "solid transport");
    // interpolated: the surface particles' mean-stress correction takes the node-interpolated
    // pressure (the default); cell: every particle its own cell's (docs/verification-coupled.md).
    c.surface_pressure =
        m.choice("surface_pressure", c.surface_pressure, {"interpolated", "cell"}, "surface pressure");
    if (const auto r = m.get("ranks")) {
      const YamlMap ranks = r->map();
      ranks.allow({"mpm", "ice"});
      c.mpm_ranks = static_cast<int>(ranks.integer("mpm", c.mpm_ranks, 1, kIntMax));
      c.ice_ranks = static_cast<int>(ranks.integer("ice", c.ice_ranks, 1, kIntMax));
    }
    if (const auto conv = m.get("convergence"))
      for (const auto& item : conv->list()) {
        const YamlMap cm = item.map();
        cm.allow({"field", "type", "limit", "strict"});
        ConvergenceSpec cs;
        cs.field = cm.required("field").choice(
            {"exchange_momentum", "lagrangian_momentum", "pressure", "pressure_force", "solid_velocity",
             "interface_force", "interface_displacement"},
            "exchanged field");
        cs.type = cm.option("type", cs.type, kMeasureNames, "convergence measure");
        cs.limit = cm.number("limit", cs.limit, Range::positive());
        cs.strict = cm.boolean("strict", cs.strict);
        c.convergence.push_back(cs);
      }
    if (const auto acc = m.get("acceleration")) {
      const YamlMap am = acc->map();
      AccelerationSpec& a = c.acceleration;
      a.type = am.required("type").option(kAccelerationNames, "acceleration");
      if (a.type == AccelerationType::None) am.allow({"type"}, "acceleration 'none' takes no parameters");
      if (a.type == AccelerationType::Constant || a.type == AccelerationType::Aitken) am.allow({"type", "relaxation"});
      if (a.type == AccelerationType::IqnIls) am.allow({"type", "relaxation", "reuse", "filter", "preconditioner"});
      a.relaxation = am.number("relaxation", a.relaxation, Range::openClosed(0, 1));
      a.reuse = static_cast<int>(am.integer("reuse", a.reuse, 0, 1000));
      a.filter = am.number("filter", a.filter, Range::nonNegative());
      a.preconditioner = am.choice("preconditioner", a.preconditioner ? "residual_sum" : "none",
                                   {"residual_sum", "none"}, "preconditioner") == "residual_sum";
    }
  }

  InterfaceSpec readInterface(const YamlValue& v) const {
    const YamlMap m = v.map();
    m.allow({"solid", "patch", "case", "solver", "mapping", "rbf_support", "mode", "fluid_density"});
    InterfaceSpec i;
    i.where = v.loc();
    const MaterialKind solid = MaterialKind::Solid;
    i.solid = materialRef(m.required("solid"), &solid, "the coupled surface is a solid's");
    i.patch = m.required("patch").string();
    if (i.patch.empty()) m.required("patch").fail("expected the name of the fluid mesh's coupled boundary patch");
    i.openfoam_case = m.required("case").string();
    i.openfoam_solver = m.choice("solver", i.openfoam_solver, {"pimpleFoam", "pisoFoam", "icoFoam"},
                                 "OpenFOAM solver (incompressible, kinematic pressure)");
    i.mapping = m.option("mapping", i.mapping, kInterfaceMappingNames, "interface mapping");
    i.rbf_support = m.number("rbf_support", i.rbf_support, Range::nonNegative());  // [m], 0 = thin-plate spline
    i.mode = m.option("mode", i.mode, kCouplingModeNames, "interface coupling mode");
    i.fluid_density = m.number("fluid_density", i.fluid_density, Range::positive());  // [kg/m^3]
    return i;
  }

  void readOutput(const YamlValue& v) {
    const YamlMap m = v.map();
    m.allow({"directory", "interval", "checkpoint_interval", "fields", "particles", "enabled", "probes"});
    OutputSpec& o = s_.output;
    o.directory = m.string("directory", o.directory);
    o.interval = m.number("interval", o.interval, Range::nonNegative());  // [s], 0 = last step only
    o.checkpoint_interval = m.number("checkpoint_interval", o.checkpoint_interval, Range::nonNegative());  // [s], 0 = none
    if (const auto f = m.get("fields"))
      for (const auto& item : f->list()) o.fields.push_back(item.string());
    o.particles = m.boolean("particles", o.particles);
    o.enabled = m.boolean("enabled", o.enabled);
    if (const auto pv = m.get("probes"))
      for (const auto& item : pv->list()) {
        const YamlMap pm = item.map();
        pm.allow({"name", "point"});
        ProbeSpec p;
        p.where = item.loc();
        p.name = pm.required("name").string();
        for (const auto& q : o.probes)
          if (q.name == p.name) pm.required("name").fail("probe name '" + p.name + "' is given twice");
        p.point = pm.required("point").vector(dim_);
        o.probes.push_back(p);
      }
  }

  YamlValue root_;
  Scene s_;
  int dim_ = 1;
};

}  // namespace

Scene parseScene(const std::string& yamlText, const std::string& file) {
  return SchemaReader(yamlText, file).read();
}

}  // namespace mpmice::core
