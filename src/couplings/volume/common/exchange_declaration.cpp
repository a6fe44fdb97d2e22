#include "couplings/volume/common/exchange_declaration.h"

#include <sstream>

#include "coupler/launch/handshake.h"

namespace mpmice::coupler {

namespace {

struct PointFields {
  std::vector<const char*> names;
  std::vector<int> components;  // of the exchange field (SolidExchangeFields)
};

// The fields of each point in wire order, as SolidExchangeFields::at lists them.
const PointFields& fieldsOf(ExchangePoint p) {
  static const std::array<PointFields, 4> table{
      PointFields{{"mass", "velocity", "temperature", "specific_volume", "face_density", "face_flux"}, {1, 3, 1, 1, 3, 3}},
      PointFields{{"pressure_force", "pressure"}, {3, 1}},
      PointFields{{"lagrangian_momentum", "coupling_work", "volume_change"}, {3, 1, 1}},
      PointFields{{"exchange_momentum", "exchange_energy"}, {3, 1}}};
  return table[static_cast<std::size_t>(p)];
}

std::size_t index(ExchangePoint p) { return static_cast<std::size_t>(p); }

/// Uses with nothing read or written, sized for `solids` slots.
FieldUses none(std::size_t solids) {
  FieldUses u;
  for (ExchangePoint p : kExchangePoints)
    u.at[index(p)].assign(solids, std::vector<int>(fieldsOf(p).components.size(), 0));
  return u;
}

/// The exchange coefficient of the pair (a, b) in ice.exchange (a pair entry overrides the default).
double coefficient(const core::Scene& s, const std::string& a, const std::string& b, bool heat) {
  for (const auto& pr : s.ice.exchange_pairs)
    if ((pr.a == a && pr.b == b) || (pr.a == b && pr.b == a)) return heat ? pr.heat : pr.momentum;
  return heat ? s.ice.exchange_heat : s.ice.exchange_momentum;
}

/// True when material m exchanges (momentum or heat) with another material; m < 0: any pair.
bool exchanges(const core::Scene& s, int m, bool heat) {
  const auto& mats = s.materials;
  for (std::size_t a = 0; a < mats.size(); ++a)
    for (std::size_t b = a + 1; b < mats.size(); ++b)
      if ((m < 0 || static_cast<int>(a) == m || static_cast<int>(b) == m) &&
          coefficient(s, mats[a].name, mats[b].name, heat) != 0.0)
        return true;
  return false;
}

/// The solid state's components: the face transport (dim components each) only with
/// coupling.solid_transport mpm.
std::vector<int> solidStateComponents(const core::Scene& s) {
  const int dim = s.mesh.dim(), faces = s.coupling.solid_transport == "mpm" ? dim : 0;
  return {1, dim, 1, 1, faces, faces};
}

void setAll(FieldUses& u, ExchangePoint p, const std::vector<int>& components) {
  for (auto& slot : u.at[index(p)]) slot = components;
}

}  // namespace

long FieldUses::valuesPerCell() const {
  long n = 0;
  for (const auto& point : at)
    for (const auto& slot : point)
      for (int c : slot) n += c;
  return n;
}

FieldUses FieldUses::everything(std::size_t solids) {
  FieldUses u = none(solids);
  for (ExchangePoint p : kExchangePoints) setAll(u, p, fieldsOf(p).components);
  setAll(u, ExchangePoint::SolidState, {1, 3, 1, 1, 0, 0});  // the face transport came with the declarations
  return u;
}

ExchangeDeclaration solidDeclaration(const core::Scene& scene) {
  const std::vector<int> solids = scene.solids();
  const int dim = scene.mesh.dim();
  ExchangeDeclaration d{none(solids.size()), none(solids.size())};
  setAll(d.writes, ExchangePoint::SolidState, solidStateComponents(scene));
  setAll(d.writes, ExchangePoint::LagrangianMomentum, {dim, 1, 1});
  // The exchange energy is read whatever the coefficients: besides the drag and heat exchange it
  // carries the solids' heat-capacity share of the Lagrangian energy correction and of the viscous
  // heat's second-order part in the cells they share with fluids (ICE's sources phase). Declared
  // only with K or H nonzero before 6 Dec 2026, a scene with K = H = 0 dropped that share: the
  // closed box's energy grew by 1.6e-2 of its scale in 1000 steps (MpmIceEnergyBudget).
  for (std::size_t s = 0; s < solids.size(); ++s) {
    d.reads.at[index(ExchangePoint::PressureForce)][s] = {dim, s == 0 ? 1 : 0};
    d.reads.at[index(ExchangePoint::ExchangeIncrements)][s] = {exchanges(scene, solids[s], false) ? dim : 0, 1};
  }
  return d;
}

ExchangeDeclaration fluidDeclaration(const core::Scene& scene) {
  const std::size_t solids = scene.solids().size();
  const int dim = scene.mesh.dim();
  ExchangeDeclaration d{none(solids), none(solids)};
  setAll(d.reads, ExchangePoint::SolidState, solidStateComponents(scene));
  setAll(d.reads, ExchangePoint::LagrangianMomentum, {dim, 1, 1});
  setAll(d.writes, ExchangePoint::PressureForce, {dim, 1});
  setAll(d.writes, ExchangePoint::ExchangeIncrements, {dim, 1});
  return d;
}

std::string describeUses(const std::vector<int>& components, ExchangePoint p, const std::string& solid) {
  const PointFields& f = fieldsOf(p);
  std::string out = solid + ":";
  bool any = false;
  for (std::size_t i = 0; i < components.size(); ++i) {
    if (components[i] == 0) continue;
    out += std::string(" ") + f.names[i];
    if (f.components[i] > 1) {  // appended piece by piece (GCC 12's -Wrestrict misfires on "(" + s)
      out += '(';
      out += std::to_string(components[i]);
      out += ')';
    }
    any = true;
  }
  return any ? out : out + " nothing";
}

FieldUses agree(const core::Scene& scene, const ExchangeDeclaration& solid, const ExchangeDeclaration& fluid) {
  std::vector<std::string> solids;
  for (int m : scene.solids()) solids.push_back(scene.materials[m].name);
  FieldUses travel = none(solids.size());
  for (ExchangePoint p : kExchangePoints) {
    const bool bySolid = producedBySolid(p);
    const FieldUses& writes = bySolid ? solid.writes : fluid.writes;
    const FieldUses& reads = bySolid ? fluid.reads : solid.reads;
    for (std::size_t s = 0; s < solids.size(); ++s) {
      const auto& w = writes.of(p, s);
      const auto& r = reads.of(p, s);
      bool ok = w.size() == r.size() && writes.at[index(p)].size() == solids.size() &&
                reads.at[index(p)].size() == solids.size();
      for (std::size_t i = 0; ok && i < r.size(); ++i) ok = r[i] <= w[i];
      if (!ok)
        throw HandshakeMismatch(std::string("coupler: the two programs do not agree on the ") + describe(p) +
                                " exchange point: the " + (bySolid ? "fluid" : "solid") + " reads " +
                                describeUses(r, p, solids[s]) + ", but the " + (bySolid ? "solid" : "fluid") +
                                " writes " + describeUses(w, p, solids[s]) +
                                " (both programs must be built from the same source and read the same scene)");
      travel.at[index(p)][s] = r;
    }
  }
  return travel;
}

std::string encodeDeclaration(const ExchangeDeclaration& d) {
  std::ostringstream os;
  for (const FieldUses* u : {&d.reads, &d.writes})
    for (const auto& point : u->at) {
      os << point.size();
      for (const auto& slot : point) {
        os << " " << slot.size();
        for (int c : slot) os << " " << c;
      }
      os << "\n";
    }
  return os.str();
}

ExchangeDeclaration decodeDeclaration(const std::string& text) {
  std::istringstream is(text);
  ExchangeDeclaration d;
  for (FieldUses* u : {&d.reads, &d.writes})
    for (auto& point : u->at) {
      std::size_t slots = 0;
      is >> slots;
      point.assign(slots, {});
      for (auto& slot : point) {
        std::size_t n = 0;
        is >> n;
        slot.assign(n, 0);
        for (int& c : slot) is >> c;
      }
    }
  if (!is) throw HandshakeMismatch("coupler: the peer's exchange declaration is malformed: '" + text + "'");
  return d;
}

}  // namespace mpmice::coupler
