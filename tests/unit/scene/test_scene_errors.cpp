// Bad scenes, one per row: each must fail with a SceneError whose message names the key path,
// the line, the offending value and the valid choices (the substrings listed with the row).
#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace mpmice::core {
namespace {

// A valid 1D fluid scene, one section per line (line numbers below count on this):
//   1 mesh, 2 time, 3 materials:, 4 the air, 5 geometry:, 6 the region.
const std::string kMesh = "mesh: {dim: 1, lower: [0], upper: [1], cells: [10]}\n";
const std::string kTime = "time: {end: 1}\n";
const std::string kAir = "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}\n";
const std::string kRegion = "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 1}\n";
const std::string kBase = kMesh + kTime + kAir + kRegion;

// 2D scene with air and steel (lines 1 mesh, 2 time, 3 materials:, 4 air, 5 steel, 6 geometry:, 7, 8).
const std::string kMesh2 = "mesh: {dim: 2, lower: [0, 0], upper: [1, 1], cells: [10, 10]}\n";
const std::string kSteel =
    "  - {name: steel, kind: solid, density: 8900, model: {type: linear_elastic, bulk_modulus: 117e9, "
    "shear_modulus: 43.8e9}}\n";
const std::string kBase2 = kMesh2 + kTime + kAir + kSteel +
                           "geometry:\n"
                           "  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1}\n"
                           "  - {shape: {type: circle, center: [0.5, 0.5], radius: 0.2}, material: steel}\n";

std::string solidWith(const std::string& model) {
  return kMesh2 + kTime + "materials:\n  - {name: steel, kind: solid, density: 8900, model: " + model + "}\n" +
         "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: steel}\n";
}

struct BadScene {
  const char* what;
  std::string yaml;
  std::vector<std::string> expect;  // substrings of the message
};

std::vector<BadScene> badScenes() {
  return {
      {"unknown top-level key", kBase + "gravty: [0]\n",
       {"test.yaml:7:1: gravty: unknown key 'gravty' at the top level", "did you mean 'gravity'?"}},
      {"spacing far below the mesh (cells per direction overflow an int)",
       "mesh: {dim: 1, lower: [0], upper: [1], spacing: 1.0e-12}\n" + kTime + kAir + kRegion,
       {"test.yaml:1:", "mesh.spacing", "cells in x, more than the 2147483647 one direction can hold"}},
      {"cell count overflows 64 bits",
       "mesh: {dim: 3, lower: [0, 0, 0], upper: [1, 1, 1], cells: [2147483647, 2147483647, 2147483647]}\n" + kTime +
           kAir + kRegion,
       {"test.yaml:1:", "mesh.cells", "the mesh would have more than 9223372036854775807 cells"}},
      {"scene larger than the machine's memory",
       "mesh: {dim: 2, lower: [0, 0], upper: [1, 1], cells: [200000, 200000]}\n" + kTime + kAir +
           "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1}\n",
       {"test.yaml:1:", "the scene needs 4e+10 cells", "GiB this machine has available", "coarsen the mesh"}},
      {"misspelled EOS",
       kMesh + kTime + "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gass, gamma: 1.4}}\n" + kRegion,
       {"test.yaml:4:", "materials[0].eos.type: unknown equation of state 'ideal_gass'",
        "valid: ideal_gas, jwl, mie_gruneisen, stiffened_gas (did you mean 'ideal_gas'?)"}},
      {"unknown constitutive model", solidWith("{type: elastic_linear, bulk_modulus: 1e9, shear_modulus: 1e9}"),
       {"materials[0].model.type", "unknown constitutive model 'elastic_linear'",
        "valid: cowper_symonds, crushable_foam, j2_plasticity, linear_elastic, neo_hookean"}},
      {"negative shock viscosity", kBase + "ice: {shock_viscosity: {linear: -1}}\n",
       {"test.yaml:7:", "ice.shock_viscosity.linear: -1 is out of range"}},
      {"semi-implicit sound fraction zero", kBase + "ice: {semi_implicit_sound_fraction: 0}\n",
       {"test.yaml:7:", "ice.semi_implicit_sound_fraction: 0 is out of range; expected a number in (0, 1]"}},
      {"semi-implicit theta below one half", kBase + "ice: {semi_implicit_theta: 0.4}\n",
       {"test.yaml:7:", "ice.semi_implicit_theta: 0.4 is out of range; expected a number in [0.5, 1]"}},
      {"misspelled face pressure", kBase + "ice: {face_pressure: riemann_lowmach}\n",
       {"test.yaml:7:", "ice.face_pressure: unknown face pressure 'riemann_lowmach'",
        "valid: auto, average, riemann, riemann_low_mach (did you mean 'riemann_low_mach'?)"}},
      {"preconditioner reuse zero", kBase + "ice: {preconditioner_reuse: 0}\n",
       {"test.yaml:7:", "ice.preconditioner_reuse: 0 is out of range; expected an integer >= 1"}},
      {"unknown shock viscosity key", kBase + "ice: {shock_viscosity: {quadratik: 1}}\n",
       {"test.yaml:7:", "unknown key 'quadratik'", "quadratic"}},
      {"CFL above one", kMesh + "time: {end: 1, cfl: 1.5}\n" + kAir + kRegion,
       {"test.yaml:2:", "time.cfl: 1.5 is out of range; expected a number in (0, 1]"}},
      {"collapse fraction of one", kMesh + "time: {end: 1, dt_collapse_fraction: 1}\n" + kAir + kRegion,
       {"test.yaml:2:", "time.dt_collapse_fraction: 1 is out of range; expected a number in [0, 1)"}},
      {"negative collapse fraction", kMesh + "time: {end: 1, dt_collapse_fraction: -1e-6}\n" + kAir + kRegion,
       {"time.dt_collapse_fraction: -1e-6 is out of range; expected a number in [0, 1)"}},
      {"zero density of a solid",
       kMesh2 + kTime +
           "materials:\n  - {name: steel, kind: solid, density: 0, model: {type: linear_elastic, "
           "bulk_modulus: 1e9, shear_modulus: 1e9}}\n"
           "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: steel}\n",
       {"materials[0].density: 0 is out of range; expected a number > 0"}},
      {"negative density of a fluid region",
       kMesh + kTime + kAir + "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 1, "
                              "density: -1}\n",
       {"test.yaml:6:", "geometry[0].density: -1 is out of range; expected a number > 0"}},
      {"negative initial pressure",
       kMesh + kTime + kAir + "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: -5}\n",
       {"geometry[0].pressure: -5 is out of range", "> 0"}},
      {"mixture fractions not summing to one",
       kMesh + kTime + kAir + "  - {name: water, kind: fluid, eos: {type: stiffened_gas, gamma: 4.4, p_inf: 6e8}}\n" +
           "geometry:\n  - name: column\n    shape: {type: box, lo: [0], hi: [1]}\n    pressure: 1\n"
           "    mixture: [{material: water, volume_fraction: 0.6}, {material: air, volume_fraction: 0.3}]\n",
       {"test.yaml:10:", "geometry[0].mixture", "geometry[0] ('column')", "sum to 0.9,", "expected 1"}},
      {"solid geometry outside the mesh",
       kMesh2 + kTime + kAir + kSteel +
           "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1}\n"
           "  - {shape: {type: circle, center: [0.9, 0.5], radius: 0.2}, material: steel}\n"
           "boundary: {x-: slip_wall, x+: slip_wall}\n",
       {"test.yaml:8:", "geometry[1].shape", "outside the mesh", "x in [0.7, 1.1]", "[0, 1]"}},
      {"negative checkpoint interval", kBase + "output: {checkpoint_interval: -0.1}\n",
       {"test.yaml:7:", "output.checkpoint_interval: -0.1 is out of range; expected a number >= 0"}},
      {"checkpoint interval not a number", kBase + "output: {checkpoint_interval: often}\n",
       {"test.yaml:7:", "output.checkpoint_interval: expected a number, got 'often'"}},
      {"string where a number is expected", kMesh + "time: {end: soon}\n" + kAir + kRegion,
       {"test.yaml:2:", "time.end: expected a number, got 'soon'"}},
      {"wrong vector length", kBase + "gravity: [0, -9.81]\n",
       {"test.yaml:7:", "gravity: expected a list of 1 number (one per mesh direction), got 2"}},
      {"missing time.end", kMesh + "time: {cfl: 0.5}\n" + kAir + kRegion,
       {"test.yaml:2:", "time: missing required key 'end'"}},
      {"unknown boundary face", kBase + "boundary:\n  x0: symmetry\n",
       {"test.yaml:8:3", "boundary.x0: unknown key 'x0' in boundary", "valid keys: x+, x-, y+, y-, z+, z-"}},
      {"boundary face beyond dim", kBase + "boundary:\n  y-: symmetry\n",
       {"test.yaml:8:", "boundary.y-: face 'y-' is beyond the mesh dimension 1 (faces: x-, x+)"}},
      {"periodic on one face only", kBase + "boundary:\n  x+: outflow\n  x-: periodic\n",
       {"test.yaml:9:", "boundary.x-: periodic must be set on both faces x- and x+; x+ is outflow"}},
      {"unknown material reference",
       kMesh + kTime + kAir + "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: aire, pressure: 1}\n",
       {"test.yaml:6:", "geometry[0].material: unknown material 'aire'; valid: air (did you mean 'air'?)"}},
      {"YAML syntax error", kMesh + "time: {end: 1\n" + kAir + kRegion, {"test.yaml:3:", "YAML syntax error"}},
      {"unknown schedule", kBase + "coupling:\n  schedule: monolitic\n",
       {"test.yaml:8:13", "coupling.schedule: unknown coupling schedule 'monolitic'",
        "valid: explicit_parallel, explicit_serial, implicit_parallel, implicit_serial, monolithic",
        "did you mean 'monolithic'?"}},
      {"fluid region with density and temperature",
       kMesh + kTime + kAir + "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 1, density: 1, temperature: 300}\n",
       {"test.yaml:6:", "geometry[0].temperature: give density or temperature for a fluid region, not both",
        "density 1 kg/m^3 was given"}},
      {"unknown surface pressure", kBase + "coupling:\n  surface_pressure: cells\n",
       {"test.yaml:8:", "coupling.surface_pressure: unknown surface pressure 'cells'", "cell", "interpolated"}},
      {"unknown acceleration", kBase + "coupling:\n  acceleration: {type: aitkin}\n",
       {"coupling.acceleration.type: unknown acceleration 'aitkin'", "valid: aitken, constant, iqn_ils, none",
        "did you mean 'aitken'?"}},
      {"unknown shape type",
       kMesh + kTime + kAir + "geometry:\n  - {shape: {type: boks, lo: [0], hi: [1]}, material: air, pressure: 1}\n",
       {"geometry[0].shape.type: unknown shape type 'boks'", "did you mean 'box'?"}},
      {"box with lo >= hi",
       kMesh + kTime + kAir + "geometry:\n  - {shape: {type: box, lo: [0.5], hi: [0.5]}, material: air, pressure: 1}\n",
       {"geometry[0].shape.hi: box needs lo < hi in every direction; in x: lo 0.5 >= hi 0.5"}},
      {"annulus inner >= outer",
       kMesh2 + kTime + kAir +
           "geometry:\n  - {shape: {type: annulus, center: [0, 0], inner_radius: 1, outer_radius: 0.5}, "
           "material: air, pressure: 1}\n",
       {"geometry[0].shape.inner_radius: inner_radius 1 must be below outer_radius 0.5"}},
      {"poisson ratio 0.5", solidWith("{type: linear_elastic, youngs_modulus: 1e9, poissons_ratio: 0.5}"),
       {"test.yaml:4:", "materials[0].model.poissons_ratio: 0.5 is out of range; expected a number in (-1, 0.5)"}},
      {"both elastic pairs",
       solidWith("{type: neo_hookean, youngs_modulus: 1e9, poissons_ratio: 0.3, bulk_modulus: 1e9, "
                 "shear_modulus: 1e9}"),
       {"materials[0].model: give exactly one pair of elastic constants",
        "got youngs_modulus, poissons_ratio, bulk_modulus, shear_modulus"}},
      {"duplicate material name",
       kMesh + kTime + kAir + "  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.3}}\n" + kRegion,
       {"test.yaml:5:", "materials[1].name: duplicate material name 'air'"}},
      {"fluid without eos", kMesh + kTime + "materials:\n  - {name: air, kind: fluid}\n" + kRegion,
       {"materials[0]: missing required key 'eos'"}},
      {"missing EOS parameter",
       kMesh + kTime + "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas}}\n" + kRegion,
       {"materials[0].eos: missing required parameter 'gamma'", "> 1"}},
      {"unknown cavitation model",
       kMesh + kTime +
           "materials:\n  - {name: water, kind: fluid, eos: {type: stiffened_gas, gamma: 4.4, p_inf: 6e8}, "
           "cavitation: {model: cut_off, pressure: 0}}\n" +
           "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: water, pressure: 1e5}\n",
       {"test.yaml:4:", "materials[0].cavitation.model: unknown cavitation model 'cut_off'", "pressure_cutoff"}},
      {"cavitation of a gas",
       kMesh + kTime +
           "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}, "
           "cavitation: {model: pressure_cutoff, pressure: 0}}\n" + kRegion,
       {"materials[0].cavitation.model", "cavitation applies to liquids: mie_gruneisen or stiffened_gas"}},
      {"cavitation cut-off above the Mie-Gruneisen reference pressure",
       kMesh + kTime +
           "materials:\n  - {name: water, kind: fluid, eos: {type: mie_gruneisen, reference_density: 1000, "
           "sound_speed: 1480, slope: 1.92, gruneisen: 0.35, reference_pressure: 1e5}, "
           "cavitation: {model: pressure_cutoff, pressure: 2e5}}\n" +
           "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: water, pressure: 1e5}\n",
       {"materials[0].cavitation.pressure", "the cut-off 2e5 Pa must lie below the liquid's reference_pressure 1e5 Pa"}},
      {"cavitation without its pressure",
       kMesh + kTime +
           "materials:\n  - {name: water, kind: fluid, eos: {type: stiffened_gas, gamma: 4.4, p_inf: 6e8}, "
           "cavitation: {model: pressure_cutoff}}\n" +
           "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: water, pressure: 1e5}\n",
       {"materials[0].cavitation", "pressure"}},
      {"misspelled EOS parameter",
       kMesh + kTime + "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas, gama: 1.4}}\n" + kRegion,
       {"materials[0].eos.gama: unknown key 'gama'", "did you mean 'gamma'?"}},
      {"crush curve for a solid that is not a foam",
       kMesh2 + kTime + "materials:\n  - {name: steel, kind: solid, density: 8900, model: {type: neo_hookean, "
                        "youngs_modulus: 1e9, poissons_ratio: 0.3}, eos: {type: crush_curve}}\n"
                        "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: steel}\n",
       {"test.yaml:4:", "materials[0].eos", "crush_curve", "crushable foam", "'neo_hookean'", "solid_bulk"}},
      {"solid without density",
       kMesh2 + kTime + "materials:\n  - {name: steel, kind: solid, model: {type: neo_hookean, youngs_modulus: 1e9, "
                        "poissons_ratio: 0.3}}\n"
                        "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: steel}\n",
       {"materials[0]: missing required key 'density'"}},
      {"unknown material kind", kMesh + kTime + "materials:\n  - {name: air, kind: gas}\n" + kRegion,
       {"materials[0].kind: unknown material kind 'gas'; valid: fluid, solid"}},
      {"load on a fluid",
       kBase2 + "loads:\n  - {type: traction, material: air, shape: {type: box, lo: [0, 0], hi: [1, 1]}, "
                "traction: [1, 0]}\n",
       {"loads[0].material: material 'air' is a fluid; loads act on solid particles"}},
      {"source in a solid",
       kBase2 + "sources:\n  - {material: steel, shape: {type: box, lo: [0, 0], hi: [1, 1]}, power_density: 1}\n",
       {"sources[0].material: material 'steel' is a solid; sources heat fluids"}},
      {"solid in a mixture",
       kMesh2 + kTime + kAir + kSteel +
           "geometry:\n  - shape: {type: box, lo: [0, 0], hi: [1, 1]}\n    pressure: 1\n"
           "    mixture: [{material: steel, volume_fraction: 0.5}, {material: air, volume_fraction: 0.5}]\n",
       {"geometry[0].mixture", "a solid cannot share a geometry object with other materials"}},
      {"spacing that does not divide the extent",
       "mesh: {dim: 1, lower: [0], upper: [1], spacing: 0.3}\n" + kTime + kAir + kRegion,
       {"mesh.spacing: spacing 0.3 does not divide the mesh extent 1 in x"}},
      {"dimension four", "mesh: {dim: 4, lower: [0], upper: [1], cells: [10]}\n" + kTime + kAir + kRegion,
       {"test.yaml:1:", "mesh.dim: 4 is out of range; expected an integer in [1, 3]"}},
      {"pressure on a solid region",
       kMesh2 + kTime + kAir + kSteel +
           "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: steel, pressure: 1}\n",
       {"geometry[0].pressure: key 'pressure' does not apply here", "pressure and density apply to fluid geometry"}},
      {"inflow of a solid",
       kBase2 + "boundary:\n  x-: {type: inflow, velocity: [1, 0], pressure: 1, material: steel}\n",
       {"boundary.x-.material: material 'steel' is a solid; only a fluid can flow in"}},
      {"duplicate YAML key", kBase + "time: {end: 2}\n",
       {"test.yaml:7:1: time: duplicate key 'time' (first given at line 2)"}},
      {"circle in 3D",
       "mesh: {dim: 3, lower: [0, 0, 0], upper: [1, 1, 1], cells: [4, 4, 4]}\n" + kTime + kAir +
           "geometry:\n  - {shape: {type: circle, center: [0, 0, 0], radius: 1}, material: air, pressure: 1}\n",
       {"geometry[0].shape.type: 'circle' is a 2D shape and this mesh is 3D; use 'sphere'"}},
      {"constant relaxation above one", kBase + "coupling:\n  acceleration: {type: constant, relaxation: 1.5}\n",
       {"coupling.acceleration.relaxation: 1.5 is out of range; expected a number in (0, 1]"}},
      {"reuse given to aitken", kBase + "coupling:\n  acceleration: {type: aitken, reuse: 3}\n",
       {"coupling.acceleration.reuse: unknown key 'reuse'"}},
      {"empty scene", "", {"the scene is empty"}},
      {"hardening table not starting at zero",
       solidWith("{type: j2_plasticity, bulk_modulus: 1e9, shear_modulus: 1e9, yield_stress: 1e6, "
                 "hardening: {plastic_strain: [0.1, 0.2], stress: [1e6, 2e6]}}"),
       {"materials[0].model.hardening.plastic_strain: must start at 0"}},
      {"unknown mpm shape function", kBase + "mpm: {shape_function: bspline}\n",
       {"mpm.shape_function: unknown shape function 'bspline'; valid: bspline2, bspline3, gimp, linear"}},
      {"unknown mpm outflow_particles", kBase + "mpm: {outflow_particles: keep}\n",
       {"mpm.outflow_particles: unknown particles leaving through an outflow face 'keep'; valid: error, remove"}},
      {"max_iterations below min", kBase + "coupling: {min_iterations: 5, max_iterations: 2}\n",
       {"coupling.max_iterations: 2 is out of range; expected an integer >= 5"}},
      {"openfoam without an interface", kBase2 + "coupling: {schedule: explicit_serial, fluid: openfoam}\n",
       {"coupling: missing required key 'interface'"}},
      {"openfoam interface on a fluid",
       kBase2 + "coupling:\n  schedule: explicit_serial\n  fluid: openfoam\n  interface: {solid: air, patch: flap, case: c}\n",
       {"test.yaml:12:", "coupling.interface.solid: material 'air' is a fluid"}},
      {"openfoam with the monolithic schedule",
       kBase2 + "coupling:\n  fluid: openfoam\n  interface: {solid: steel, patch: flap, case: c}\n",
       {"valid schedules: explicit_serial, implicit_serial"}},
      {"unknown interface mapping",
       kBase2 + "coupling:\n  schedule: implicit_serial\n  fluid: openfoam\n"
                "  interface: {solid: steel, patch: flap, case: c, mapping: rbff}\n",
       {"coupling.interface.mapping: unknown interface mapping 'rbff'; valid: nearest_neighbor, rbf"}},
      {"interface given to ice", kBase2 + "coupling:\n  interface: {solid: steel, patch: flap, case: c}\n",
       {"coupling.interface", "applies to coupling.fluid 'openfoam' only"}},
      {"probe without a point", kBase2 + "output: {probes: [{name: tip}]}\n",
       {"output.probes[0]: missing required key 'point'"}},
      {"boolean expected", kBase + "output: {particles: maybe}\n",
       {"output.particles: expected true or false, got 'maybe'"}},
      {"velocity gradient with too few rows",
       kMesh2 + kTime + kAir +
           "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1, "
           "velocity_gradient: [[1, 0]]}\n",
       {"test.yaml:6:", "geometry[0].velocity_gradient: expected 2 rows of 2 numbers", "got 1 rows"}},
      {"velocity gradient given as a vector",
       kMesh + kTime + kAir +
           "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 1, "
           "velocity_gradient: [2]}\n",
       {"geometry[0].velocity_gradient[0]: expected 1 rows of 1 numbers", "row 1 is '2'", "[[-25]]"}},
      {"velocity gradient row of the wrong length",
       kMesh2 + kTime + kAir +
           "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1, "
           "velocity_gradient: [[1, 0], [0]]}\n",
       {"geometry[0].velocity_gradient[1]", "2"}},
      {"velocity origin without a gradient",
       kMesh + kTime + kAir +
           "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 1, "
           "velocity_origin: [0.5]}\n",
       {"geometry[0].velocity_origin: velocity_origin needs velocity_gradient"}},
  };
}

void PrintTo(const BadScene& row, std::ostream* os) { *os << row.what; }

class BadSceneTest : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, FailsWithAMessageNamingKeyLineValueAndChoices) {
  const BadScene& row = GetParam();
  try {
    (void)parseScene(row.yaml, "test.yaml");
    FAIL() << "expected a SceneError for: " << row.what << "\n" << row.yaml;
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("test.yaml", 0), 0u) << msg;
    for (const auto& s : row.expect)
      EXPECT_NE(msg.find(s), std::string::npos) << row.what << ":\n  message: " << msg << "\n  lacks:   " << s;
  }
}

std::string rowName(const ::testing::TestParamInfo<BadScene>& info) {
  std::string n;
  for (const char* c = info.param.what; *c; ++c) n += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Scene, BadSceneTest, ::testing::ValuesIn(badScenes()), rowName);

TEST(SceneErrors, TheBaseScenesAreValid) {
  EXPECT_NO_THROW((void)parseScene(kBase, "test.yaml"));
  EXPECT_NO_THROW((void)parseScene(kBase2, "test.yaml"));
}

TEST(SceneErrors, MissingFileNamesThePath) {
  try {
    (void)loadScene("/nonexistent/dir/scene.yaml");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.yaml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
}

TEST(SceneErrors, ErrorCarriesLocationAndKey) {
  try {
    (void)parseScene(kMesh + "time: {end: 1, cfl: 2}\n" + kAir + kRegion, "a/b.yaml");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.where().file, "a/b.yaml");
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().column, 21);
    EXPECT_EQ(e.key(), "time.cfl");
  }
}

}  // namespace
}  // namespace mpmice::core

namespace mpmice::core {
namespace {

// A hostile scene: 200,000 keys in one mapping, the duplicate among them named (the look-up is a
// hash map now, not a comparison of every pair: docs/scene-reference.md gives the timing), and a
// 1 MB value echoed capped, not whole.
TEST(HostileScene, ManyKeysReadFastAndTheDuplicateIsNamed) {
  std::string yaml = kBase + "output:\n";
  for (int i = 0; i < 200000; ++i) yaml += "  k" + std::to_string(i) + ": 1\n";
  yaml += "  k7: 2\n";
  try {
    (void)parseScene(yaml, "test.yaml");
    FAIL() << "a duplicate key was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("duplicate key 'k7'"), std::string::npos) << e.what();
  }
}

TEST(HostileScene, AHugeValueIsEchoedCapped) {
  const std::string huge(1 << 20, 'x');
  try {
    (void)parseScene(kMesh + "time: {end: " + huge + "}\n" + kAir + kRegion, "test.yaml");
    FAIL() << "a non-number end time was accepted";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_LT(m.size(), 400u) << m.substr(0, 400);
    EXPECT_NE(m.find("(1048576 characters)"), std::string::npos) << m.substr(0, 400);
  }
}

}  // namespace
}  // namespace mpmice::core
