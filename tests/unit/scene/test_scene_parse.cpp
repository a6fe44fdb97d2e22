// Good scenes: defaults filled in, elastic constants converted, the dump parses back to an equal
// scene, the hash follows the mesh, materials and boundary, and the shipped configs load.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "core/scene/model_catalog.h"
#include "core/scene/scene.h"

namespace mpmice::core {
namespace {

const std::string kMinimal = R"(
mesh: {dim: 1, lower: [0], upper: [2], cells: [20]}
time: {end: 0.5}
materials:
  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}
geometry:
  - {shape: {type: box, lo: [0], hi: [2]}, material: air, pressure: 1e5}
)";

const std::string kSolid2D = R"(
mesh: {dim: 2, lower: [0, 0], upper: [1.2, 1.2], spacing: 0.025}
time: {end: 4e-3}
materials:
  - name: steel
    kind: solid
    density: 8900
    model: {type: linear_elastic, bulk_modulus: 117e9, shear_modulus: 43.8e9}
geometry:
  - {shape: {type: annulus, center: [0, 0], inner_radius: 0.5, outer_radius: 1.0}, material: steel}
)";

const std::string kEverything = R"(
scene: everything
description: "every section: the \"features\" in one scene"
mesh: {dim: 2, lower: [-0.1, 0], upper: [1.1, 0.6], spacing: [0.1, 0.05]}
time: {end: 1e-3, cfl: 0.3, dt_max: 1e-5, dt_min: 1e-12, dt_initial: 1e-7, max_steps: 1000}
gravity: [0, -9.81]
materials:
  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}, viscosity: 1.8e-5, thermal_conductivity: 0.025}
  - {name: water, kind: fluid, eos: {type: stiffened_gas, gamma: 4.4, p_inf: 6e8}, density: 1000, specific_heat: 4186}
  - {name: gas, kind: fluid, eos: {type: mie_gruneisen, reference_density: 1000, sound_speed: 1500, slope: 2, gruneisen: 0.5}}
  - {name: products, kind: fluid, eos: {type: jwl, A: 3.7e11, B: 3.2e9, R1: 4.15, R2: 0.95, omega: 0.3, reference_density: 1630}}
  - name: steel
    kind: solid
    density: 7800
    model: {type: j2_plasticity, youngs_modulus: 200e9, poissons_ratio: 0.29, yield_stress: 3e8,
            hardening: {plastic_strain: [0, 0.1, 0.5], stress: [3e8, 4e8, 5e8]}, failure_strain: 0.8}
    eos: {type: solid_bulk, threshold_pressure: 2e5}
    thermal_expansivity: 1.2e-5
  - {name: rubber, kind: solid, density: 1100, model: {type: neo_hookean, youngs_modulus: 1e7, poissons_ratio: 0.45}}
  - {name: "7 alloy", kind: solid, density: 2700, model: {type: j2_plasticity, bulk_modulus: 70e9, shear_modulus: 26e9, yield_stress: 2e8, hardening_modulus: 1e9}}
geometry:
  - name: background
    shape: {type: box, lo: [-0.1, 0], hi: [1.1, 0.6]}
    mixture: [{material: air, volume_fraction: 0.75}, {material: water, volume_fraction: 0.25}]
    pressure: 101325
    temperature: 290
  - shape: {type: union, shapes: [{type: circle, center: [0.2, 0.2], radius: 0.1}, {type: cylinder, center: [0.5, 0.2], radius: 0.05}]}
    material: steel
    velocity: [1, 0]
    particles_per_cell: [3, 2]
  - {shape: {type: difference, shapes: [{type: box, lo: [0.7, 0.1], hi: [0.9, 0.3]}, {type: annulus, center: [0.8, 0.2], inner_radius: 0, outer_radius: 0.05}]}, material: rubber, particles_per_cell: 4}
  - {shape: {type: box, lo: [0, 0.4], hi: [0.2, 0.5]}, material: "7 alloy"}
  - {shape: {type: circle, center: [1, 0.5], radius: 0.05}, material: gas, pressure: 1e5, density: 1000, velocity: [0, 1]}
boundary:
  x-: {type: inflow, velocity: [10, 0], pressure: 2e5, density: 2.3, material: air}
  x+: {type: outflow, pressure: 101325}
  y-: noslip_wall
  y+: slip_wall
loads:
  - {type: pressure, material: steel, shape: {type: circle, center: [0.2, 0.2], radius: 0.1}, pressure: 1e6, center: [0.2, 0.2], start: 1e-4, ramp: 1e-4}
  - {type: traction, material: rubber, shape: {type: box, lo: [0.7, 0.1], hi: [0.9, 0.3]}, traction: [0, -1e3]}
sources:
  - {material: products, shape: {type: circle, center: [1, 0.5], radius: 0.05}, power_density: 1e12, end: 5e-4}
mpm: {shape_function: bspline2, update: musl, flip: 0.95, damping: 10, sort_particles: false}
ice:
  advection: first_order
  limiter: minmod
  pressure_solver: semi_implicit
  linear_solver: bicgstab
  solver_tolerance: 1e-8
  solver_max_iterations: 200
  pressure_iterations: 20
  pressure_tolerance: 1e-9
  shock_viscosity: {linear: 1, quadratic: 2}
  exchange: {momentum: 1e12, heat: 1e3, pairs: [{materials: [steel, air], momentum: 1e15}, {materials: [water, air], heat: 10}]}
coupling:
  schedule: implicit_serial
  fluid: openfoam
  min_iterations: 2
  max_iterations: 30
  accept_unconverged: true
  timeout: 120
  ranks: {mpm: 2, ice: 3}
  convergence: [{field: solid_velocity, type: relative, limit: 1e-5, strict: true}, {field: pressure, type: absolute, limit: 1}]
  acceleration: {type: iqn_ils, relaxation: 0.1, reuse: 4, filter: 1e-6}
  interface: {solid: steel, patch: flap, case: "fluid case", solver: pisoFoam, mapping: nearest_neighbor, rbf_support: 0.5, mode: one_way, fluid_density: 1000}
output: {directory: "out dir/everything", interval: 1e-4, fields: [pressure, velocity], particles: false, enabled: false, probes: [{name: tip, point: [0.5, 1]}, {name: base, point: [0.5, 0]}]}
)";

const std::string k3D = R"(
mesh: {dim: 3, lower: [0, 0, 0], upper: [1, 2, 3], cells: [3, 7, 11]}
time: {end: 1}
gravity: [0, 0, -9.81]
materials:
  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}
  - {name: bar, kind: solid, density: 1, model: {type: linear_elastic, youngs_modulus: 100, poissons_ratio: 0}}
geometry:
  - {shape: {type: box, lo: [0, 0, 0], hi: [1, 2, 3]}, material: air, pressure: 1}
  - {shape: {type: cylinder, center: [0.5, 1, 1.5], radius: 0.2, axis: [0, 1, 0], length: 1}, material: bar, particles_per_cell: [1, 2, 3]}
  - {shape: {type: annulus, center: [0.5, 1, 1.5], inner_radius: 0.1, outer_radius: 0.3, length: 0.2}, material: air, pressure: 2}
  - {shape: {type: sphere, center: [0.5, 0.5, 0.5], radius: 0.25}, material: bar}
boundary: {z-: periodic, z+: periodic, x-: free}
)";

/// The same scene read from different text has different source locations: compare without.
void clearLocations(ShapeSpec& s) {
  s.where = {};
  for (auto& c : s.children) clearLocations(c);
}
Scene withoutLocations(Scene s) {
  for (auto& m : s.materials) m.where = m.constitutive.where = m.eos.where = m.cavitation.where = {};
  for (auto& r : s.geometry) {
    r.where = {};
    clearLocations(r.shape);
  }
  for (auto& b : s.boundary) b.where = {};
  for (auto& l : s.loads) {
    l.where = {};
    clearLocations(l.shape);
  }
  for (auto& src : s.sources) {
    src.where = {};
    clearLocations(src.shape);
  }
  s.coupling.interface.where = {};
  for (auto& p : s.output.probes) p.where = {};
  return s;
}

void expectRoundTrip(const std::string& text) {
  const Scene a = parseScene(text, "scene.yaml");
  const std::string dumped = dumpScene(a);
  Scene b;
  ASSERT_NO_THROW(b = parseScene(dumped, "scene.yaml")) << dumped;
  EXPECT_EQ(dumpScene(b), dumped);
  EXPECT_TRUE(withoutLocations(a) == withoutLocations(b)) << dumped;
  EXPECT_EQ(sceneHash(a), sceneHash(b));
}

TEST(SceneParse, DefaultsAreFilledIn) {
  const Scene s = parseScene(kMinimal, "configs/minimal.yaml");
  EXPECT_EQ(s.name, "minimal");  // from the file name
  EXPECT_EQ(s.mesh.dim(), 1);
  EXPECT_EQ(s.mesh.cells()[0], 20);
  EXPECT_DOUBLE_EQ(s.mesh.dx(0), 0.1);
  EXPECT_DOUBLE_EQ(s.time.cfl, 0.4);
  EXPECT_EQ(s.time.max_steps, 0);
  EXPECT_EQ(s.gravity, (RealVect{0, 0, 0}));
  const MaterialSpec& air = s.materials.at(0);
  EXPECT_EQ(air.kind, MaterialKind::Fluid);
  EXPECT_DOUBLE_EQ(air.eos.get("gamma"), 1.4);
  EXPECT_DOUBLE_EQ(air.specific_heat, 716.0);
  EXPECT_EQ(air.density, 0.0);
  const RegionSpec& r = s.geometry.at(0);
  EXPECT_DOUBLE_EQ(*r.pressure, 1e5);
  EXPECT_FALSE(r.density.has_value());
  EXPECT_DOUBLE_EQ(r.temperature, 300.0);
  EXPECT_EQ(r.fill.size(), 1u);
  EXPECT_DOUBLE_EQ(r.fill[0].volume_fraction, 1.0);
  for (const auto& b : s.boundary) EXPECT_EQ(b.type, BoundaryType::Symmetry);
  EXPECT_EQ(s.mpm.shape_function, "linear");
  EXPECT_EQ(s.mpm.update, "usl");
  EXPECT_EQ(s.ice.advection, "second_order");
  EXPECT_DOUBLE_EQ(s.ice.exchange_momentum, 1e15);
  EXPECT_EQ(s.coupling.schedule, core::Schedule::Monolithic);
  EXPECT_EQ(s.coupling.acceleration.type, core::AccelerationType::None);
  EXPECT_EQ(s.output.directory, "output");
  EXPECT_EQ(s.periodic(), (std::array<bool, 3>{false, false, false}));
  EXPECT_EQ(s.fluids(), std::vector<int>{0});
  EXPECT_TRUE(s.solids().empty());
}

TEST(SceneParse, TheCollapseFractionDefaultsToOneMillionthAndIsRead) {
  EXPECT_DOUBLE_EQ(parseScene(kMinimal, "configs/minimal.yaml").time.dt_collapse_fraction, 1e-3);
  std::string off = kMinimal;
  const std::string t = "time: {end: 0.5}";
  ASSERT_NE(off.find(t), std::string::npos);
  off.replace(off.find(t), t.size(), "time: {end: 0.5, dt_collapse_fraction: 0}");
  EXPECT_EQ(parseScene(off, "configs/minimal.yaml").time.dt_collapse_fraction, 0.0);
}

TEST(SceneParse, SolidDefaultsAndBulkShearConversion) {
  const Scene s = parseScene(kSolid2D, "cyl.yaml");
  EXPECT_EQ(s.mesh.cells()[0], 48);
  EXPECT_EQ(s.mesh.cells()[1], 48);
  EXPECT_NEAR(s.mesh.upper(0), 1.2, 1e-12);
  const MaterialSpec& steel = s.materials.at(0);
  EXPECT_EQ(steel.kind, MaterialKind::Solid);
  const ModelSpec& m = steel.constitutive;
  EXPECT_EQ(m.type, "linear_elastic");
  // Hand values: E = 9KG / (3K + G) = 116.82 GPa, nu = (3K - 2G) / (2 (3K + G)) = 0.3336.
  EXPECT_NEAR(m.get("youngs_modulus") / 1e9, 116.82, 0.005);
  EXPECT_NEAR(m.get("poissons_ratio"), 0.3336, 5e-5);
  EXPECT_DOUBLE_EQ(m.get("bulk_modulus"), 117e9);
  EXPECT_DOUBLE_EQ(m.get("shear_modulus"), 43.8e9);
  // The solid EOS is filled in from the model and the density.
  EXPECT_EQ(steel.eos.type, "solid_bulk");
  EXPECT_DOUBLE_EQ(steel.eos.get("bulk_modulus"), 117e9);
  EXPECT_DOUBLE_EQ(steel.eos.get("threshold_pressure"), 101325.0);
  EXPECT_DOUBLE_EQ(steel.eos.get("reference_density"), 8900.0);
  EXPECT_EQ(s.geometry.at(0).particles_per_cell, (IntVect{2, 2, 1}));
  EXPECT_EQ(s.solids(), std::vector<int>{0});
}

TEST(SceneParse, YoungPoissonConversion) {
  const Scene s = parseScene(k3D, "bar.yaml");
  const ModelSpec& m = s.material("bar")->constitutive;
  // E = 100, nu = 0: K = E / 3, G = E / 2.
  EXPECT_DOUBLE_EQ(m.get("bulk_modulus"), 100.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.get("shear_modulus"), 50.0);
  double E = 0, nu = 0;
  scene_detail::elasticFromBulkShear(117e9, 43.8e9, E, nu);
  double K = 0, G = 0;
  scene_detail::bulkShearFromElastic(E, nu, K, G);
  EXPECT_NEAR(K / 117e9, 1.0, 1e-12);
  EXPECT_NEAR(G / 43.8e9, 1.0, 1e-12);
}

TEST(SceneParse, EverythingIsRead) {
  const Scene s = parseScene(kEverything, "x.yaml");
  EXPECT_EQ(s.name, "everything");
  EXPECT_EQ(s.description, "every section: the \"features\" in one scene");
  EXPECT_EQ(s.mesh.cells(), (IntVect{12, 12, 1}));
  EXPECT_EQ(s.gravity, (RealVect{0, -9.81, 0}));
  const ModelSpec& j2 = s.material("steel")->constitutive;
  EXPECT_EQ(j2.tables.at("plastic_strain"), (std::vector<double>{0, 0.1, 0.5}));
  EXPECT_EQ(j2.tables.at("stress"), (std::vector<double>{3e8, 4e8, 5e8}));
  EXPECT_FALSE(j2.has("hardening_modulus"));
  EXPECT_DOUBLE_EQ(j2.get("failure_strain"), 0.8);
  EXPECT_DOUBLE_EQ(s.material("steel")->eos.get("threshold_pressure"), 2e5);
  EXPECT_DOUBLE_EQ(s.material("steel")->eos.get("bulk_modulus"), s.material("steel")->constitutive.get("bulk_modulus"));
  EXPECT_DOUBLE_EQ(s.material("7 alloy")->constitutive.get("hardening_modulus"), 1e9);
  EXPECT_DOUBLE_EQ(s.material("gas")->eos.get("reference_pressure"), 0.0);
  EXPECT_EQ(s.geometry[0].fill.size(), 2u);
  EXPECT_EQ(s.geometry[1].shape.children.at(0).type, "sphere");  // circle is read as sphere
  EXPECT_EQ(s.geometry[1].particles_per_cell, (IntVect{3, 2, 1}));
  EXPECT_EQ(s.geometry[2].particles_per_cell, (IntVect{4, 4, 1}));
  EXPECT_EQ(s.boundary[0].type, BoundaryType::Inflow);
  EXPECT_EQ(s.boundary[0].material, "air");
  EXPECT_DOUBLE_EQ(*s.boundary[0].density, 2.3);
  EXPECT_EQ(s.boundary[2].type, BoundaryType::NoSlipWall);
  EXPECT_EQ(s.loads.at(1).traction, (RealVect{0, -1e3, 0}));
  EXPECT_DOUBLE_EQ(s.sources.at(0).end, 5e-4);
  ASSERT_EQ(s.ice.exchange_pairs.size(), 2u);
  EXPECT_DOUBLE_EQ(s.ice.exchange_pairs[0].heat, 1e3);       // the section default
  EXPECT_DOUBLE_EQ(s.ice.exchange_pairs[1].momentum, 1e12);  // the section default
  EXPECT_DOUBLE_EQ(s.ice.shock_viscosity_linear, 1.0);
  EXPECT_DOUBLE_EQ(s.ice.shock_viscosity_quadratic, 2.0);
  EXPECT_EQ(s.coupling.mpm_ranks, 2);
  EXPECT_EQ(s.coupling.ice_ranks, 3);
  EXPECT_EQ(s.coupling.convergence.at(1).type, core::MeasureType::Absolute);
  EXPECT_EQ(s.coupling.acceleration.reuse, 4);
  EXPECT_EQ(s.output.fields, (std::vector<std::string>{"pressure", "velocity"}));
  EXPECT_FALSE(s.output.enabled);
}

TEST(SceneParse, SourceEndDefaultsToTheEndTime) {
  const Scene s = parseScene(kMinimal + "sources:\n  - {material: air, shape: {type: box, lo: [0], hi: [1]}, "
                                        "power_density: 5}\n",
                             "s.yaml");
  EXPECT_DOUBLE_EQ(s.sources.at(0).end, 0.5);
}

TEST(SceneParse, ThreeDimensionalScene) {
  const Scene s = parseScene(k3D, "bar.yaml");
  EXPECT_EQ(s.periodic(), (std::array<bool, 3>{false, false, true}));
  EXPECT_EQ(s.boundary[0].type, BoundaryType::Free);
  EXPECT_EQ(s.geometry[1].shape.axis, (RealVect{0, 1, 0}));
  EXPECT_DOUBLE_EQ(s.geometry[1].shape.length, 1.0);
  EXPECT_EQ(s.geometry[2].shape.axis, (RealVect{0, 0, 1}));  // default axis
  EXPECT_EQ(s.geometry[1].particles_per_cell, (IntVect{1, 2, 3}));
}

// A linear initial velocity (issue 14: the piston's quasi-static gas on any mesh): u(x) = velocity +
// velocity_gradient (x - velocity_origin), row i holding d u_i / d x_j; read, sampled and dumped.
TEST(SceneParse, ALinearVelocityProfileIsReadSampledAndDumped) {
  const std::string text = R"(
mesh: {dim: 2, lower: [0, 0], upper: [1, 1], cells: [10, 10]}
time: {end: 1}
materials:
  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}
geometry:
  - name: shear
    shape: {type: box, lo: [0, 0], hi: [1, 1]}
    material: air
    pressure: 1e5
    velocity: [10, -1]
    velocity_origin: [0.6, 0.5]
    velocity_gradient: [[-25, 2], [0, 4]]
  - {name: plain, shape: {type: box, lo: [0, 0], hi: [0.1, 0.1]}, material: air, pressure: 1e5, velocity: [3, 4]}
)";
  const Scene s = parseScene(text, "v.yaml");
  const RegionSpec& r = s.geometry.at(0);
  EXPECT_EQ(r.velocity_origin, (RealVect{0.6, 0.5, 0}));
  EXPECT_EQ(r.velocity_gradient[0], (RealVect{-25, 2, 0}));
  EXPECT_EQ(r.velocity_gradient[1], (RealVect{0, 4, 0}));
  EXPECT_EQ(r.velocity_gradient[2], (RealVect{0, 0, 0}));
  const RealVect at = r.velocityAt({1.0, 0.75, 0.3});  // dx = (0.4, 0.25)
  EXPECT_DOUBLE_EQ(at[0], 10 - 25 * 0.4 + 2 * 0.25);
  EXPECT_DOUBLE_EQ(at[1], -1 + 4 * 0.25);
  EXPECT_EQ(at[2], 0.0);
  EXPECT_EQ(r.velocityAt(r.velocity_origin), r.velocity);
  // Without a gradient the velocity is the same everywhere, to the bit.
  const RegionSpec& plain = s.geometry.at(1);
  EXPECT_EQ(plain.velocityAt({0.05, 0.07, 0}), (RealVect{3, 4, 0}));
  EXPECT_EQ(plain.velocityAt({123.0, -4.0, 9.0}), (RealVect{3, 4, 0}));
  expectRoundTrip(text);
}

TEST(SceneParse, DumpParsesBackToAnEqualScene) {
  expectRoundTrip(kMinimal);
  expectRoundTrip(kSolid2D);
  expectRoundTrip(kEverything);
  expectRoundTrip(k3D);
}

// The slides' models and the file load (issue 16) survive the dump.
TEST(SceneParse, SlidesModelsAndFileLoadRoundTrip) {
  const std::string text = R"(
mesh: {dim: 2, lower: [0, 0], upper: [1, 1], spacing: 0.05}
time: {end: 1e-3}
materials:
  - {name: foam, kind: solid, density: 270, model: {type: crushable_foam, youngs_modulus: 1e8, poissons_ratio: 0.05,
     plateau_stress: 1.5e6, densification_strain: 2.3, hardening_alpha2: 4e6, densified_bulk_modulus: 76e9}}
  - {name: polymer, kind: solid, density: 1200, model: {type: cowper_symonds, youngs_modulus: 2e9, poissons_ratio: 0.35,
     yield_stress: 40e6, rate_c: 100, rate_p: 4}}
geometry:
  - {shape: {type: box, lo: [0.1, 0.1], hi: [0.4, 0.4]}, material: foam}
  - {shape: {type: box, lo: [0.6, 0.6], hi: [0.9, 0.9]}, material: polymer}
loads:
  - {type: file, material: foam, file: forces.csv, mapping: nearest_neighbor, depth: 0.1, moment_center: [0.25, 0.1]}
)";
  expectRoundTrip(text);
  const Scene s = parseScene(text, "scene.yaml");
  EXPECT_DOUBLE_EQ(s.materials[0].constitutive.get("plastic_poissons_ratio"), 0.0);  // defaults filled in
  EXPECT_DOUBLE_EQ(s.materials[0].constitutive.get("hardening_beta"), 1.0);
  EXPECT_EQ(s.loads[0].moment_center, (RealVect{0.25, 0.1, 0}));
}

TEST(SceneParse, HashFollowsMeshMaterialsAndBoundary) {
  const std::string h = sceneHash(parseScene(kEverything, "a.yaml"));
  EXPECT_EQ(h.size(), 16u);
  EXPECT_EQ(h, sceneHash(parseScene(kEverything, "b.yaml")));
  auto changed = [&](const std::string& from, const std::string& to) {
    std::string text = kEverything;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    return sceneHash(parseScene(text, "a.yaml"));
  };
  EXPECT_NE(h, changed("gamma: 4.4", "gamma: 4.5"));              // a material parameter
  EXPECT_NE(h, changed("yield_stress: 3e8", "yield_stress: 3.1e8"));
  EXPECT_NE(h, changed("y+: slip_wall", "y+: symmetry"));         // a boundary condition
  EXPECT_NE(h, changed("spacing: [0.1, 0.05]", "spacing: [0.1, 0.1]"));  // the mesh
  EXPECT_EQ(h, changed("interval: 1e-4", "interval: 2e-4"));      // output is not hashed
  EXPECT_EQ(h, changed("end: 1e-3", "end: 2e-3"));                // nor the end time
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SceneConfigs, SodLoads) {
  const Scene s = loadScene(MPMICE_SOURCE_DIR "/configs/sod.yaml");
  EXPECT_EQ(s.name, "sod");
  EXPECT_EQ(s.mesh.cells()[0], 100);
  EXPECT_DOUBLE_EQ(s.time.end, 0.2);
  ASSERT_EQ(s.geometry.size(), 2u);
  EXPECT_DOUBLE_EQ(*s.geometry[1].density, 0.125);
  EXPECT_DOUBLE_EQ(*s.geometry[1].pressure, 0.1);
  EXPECT_DOUBLE_EQ(s.geometry[1].shape.lo[0], 0.5);
  expectRoundTrip(readFile(MPMICE_SOURCE_DIR "/configs/sod.yaml"));
}

TEST(SceneConfigs, PressurizedCylinderLoads) {
  const Scene s = loadScene(MPMICE_SOURCE_DIR "/configs/pressurized_cylinder.yaml");
  EXPECT_EQ(s.mesh.cells(), (IntVect{48, 48, 1}));
  EXPECT_NEAR(s.mesh.dx(0), 0.025, 1e-15);
  const MaterialSpec* steel = s.material("steel");
  ASSERT_NE(steel, nullptr);
  EXPECT_NEAR(steel->constitutive.get("poissons_ratio"), 0.3336, 5e-5);
  EXPECT_EQ(s.boundary[0].type, BoundaryType::Symmetry);
  EXPECT_EQ(s.boundary[1].type, BoundaryType::Outflow);
  // Air fills the domain minus the wall; the wall's particles live in the annulus.
  const RegionSpec& air = s.geometry.at(0);
  EXPECT_TRUE(air.shape.contains({0.2, 0.2, 0}, 2));
  EXPECT_FALSE(air.shape.contains({0.7, 0.0, 0}, 2));
  EXPECT_TRUE(air.shape.contains({1.1, 1.1, 0}, 2));
  ASSERT_EQ(s.sources.size(), 1u);
  EXPECT_DOUBLE_EQ(s.sources[0].end, 2.5e-3);
  EXPECT_DOUBLE_EQ(s.time.end, 4e-3);
  expectRoundTrip(readFile(MPMICE_SOURCE_DIR "/configs/pressurized_cylinder.yaml"));
}

// A fluid's cavitation model (docs/ice.md "Cavitation") is read, dumped and read back.
TEST(SceneParse, CavitationModelRoundTrips) {
  const std::string text =
      "mesh: {dim: 1, lower: [0], upper: [1], cells: [10]}\ntime: {end: 1}\n"
      "materials:\n  - {name: water, kind: fluid, eos: {type: mie_gruneisen, reference_density: 1000, "
      "sound_speed: 1480, slope: 1.92, gruneisen: 0.35, reference_pressure: 1e5}, "
      "cavitation: {model: pressure_cutoff, pressure: -1e5}}\n"
      "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: water, pressure: 1e5}\n";
  const Scene s = parseScene(text, "cav.yaml");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].cavitation.type, "pressure_cutoff");
  EXPECT_DOUBLE_EQ(s.materials[0].cavitation.get("pressure"), -1e5);
  expectRoundTrip(text);
}

// docs/scene-reference.md must mention every model and parameter of the catalog.
TEST(SceneReference, DocumentsEveryModelAndParameter) {
  const std::string doc = readFile(MPMICE_SOURCE_DIR "/docs/scene-reference.md");
  ASSERT_FALSE(doc.empty());
  for (const auto* family : {&scene_detail::constitutiveModels(), &scene_detail::fluidEquationsOfState(),
                             &scene_detail::solidEquationsOfState(), &scene_detail::cavitationModels()})
    for (const auto& m : family->models) {
      EXPECT_NE(doc.find("`" + m.name + "`"), std::string::npos) << m.name;
      for (const auto& p : m.params) EXPECT_NE(doc.find("`" + p.name + "`"), std::string::npos) << m.name << "." << p.name;
      for (const auto& t : m.tables) EXPECT_NE(doc.find("`" + t.key + "`"), std::string::npos) << t.key;
    }
}

}  // namespace
}  // namespace mpmice::core
