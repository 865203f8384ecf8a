// The bat parameters' ranges (parameter_bounds.hpp), the same in bat files, studies, optimisations
// and the library: just inside a range the model computes finite results, just outside the value is
// refused with one line naming where it was given, the value as written and the range expected.
// Also the messages of issue 24: integers shown as written, names shown as names, points off the
// bat with the digits that tell them from its end, certify's own refusals.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "program.hpp"
#include "refusal.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/bat/parameter_bounds.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/optimize/problem.hpp"
#include "sweetspot/study/study.hpp"
#include "sweetspot/study/study_point.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

const std::string maple = source_path("studies/bats/maple_271.toml");
const std::string r161 = source_path("studies/bats/r161.toml");

BatDesign maple_design() {
  BatSource source;
  return load_bat_design(maple, source);
}

// The bat's modes all finite (the rigid two 0, the rest positive), and its mass finite.
void require_finite_model(const BatDesign& design) {
  const Bat bat = build_bat(design);
  const ModalBasis basis = compute_modes(bat, BeamTheory::timoshenko);
  INFO(design.name << ": omega " << basis.omega.transpose());
  CHECK(std::isfinite(basis.mass));
  CHECK(basis.mass > 0);
  CHECK(basis.omega.allFinite());
  CHECK(basis.omega(2) > 0);
}

// Every dimension of `d` for a design of length `length` with the wood's constants.
BatDesign shaped(double length, const Dimensions& d) {
  BatDesign design = maple_design();
  design.name = "shape";
  design.length = length;
  design.dimensions = d;
  return design;
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("each material constant at both ends of its range makes a bat with finite modes", "[bounds]") {
  for (const char* name : {"density", "youngs_modulus", "shear_modulus", "shear_coefficient", "hoop_modulus"}) {
    const ParameterBound& bound = *parameter_bound(name);
    for (const double value : {bound.low, bound.high}) {
      BatDesign design = maple_design();
      // The shear modulus stays at most 10 times Young's (bat_design.cpp): the other follows.
      if (name == std::string("youngs_modulus")) design.material.shear_modulus = std::min(design.material.shear_modulus, value);
      if (name == std::string("shear_modulus")) design.material.youngs_modulus = std::max(design.material.youngs_modulus, value);
      set_design_parameter(design, name, value);
      INFO(name << " = " << value);
      CHECK_FALSE(broken_rule(design));
      require_finite_model(design);
    }
  }
}

TEST_CASE("each material constant just outside its range is refused, naming it and the range", "[bounds]") {
  for (const char* name : {"density", "youngs_modulus", "shear_modulus", "shear_coefficient", "hoop_modulus"}) {
    const ParameterBound& bound = *parameter_bound(name);
    for (const double value : {bound.low * 0.999, bound.high * 1.001}) {
      BatDesign design = maple_design();
      INFO(name << " = " << value);
      CHECK_THROWS_WITH(set_design_parameter(design, name, value),
                        Catch::Contains(name) && Catch::Contains("expected " + expected_range(bound)));
      // A design made another way (a bat file, Python's knots) meets the same rule.
      design.material.*(name == std::string("density")            ? &Material::density
                        : name == std::string("youngs_modulus")    ? &Material::youngs_modulus
                        : name == std::string("shear_modulus")     ? &Material::shear_modulus
                        : name == std::string("shear_coefficient") ? &Material::shear_coefficient
                                                                   : &Material::hoop_modulus) = value;
      const auto rule = rule_break(design);
      REQUIRE(rule);
      CHECK(rule->parameter == name);
      CHECK_THROWS_AS(build_bat(design), InputError);
    }
  }
}

TEST_CASE("the smallest and the largest bat the ranges allow have finite modes", "[bounds]") {
  // A millimetre everywhere: 1-mm knob and diameters, 4 mm long.
  require_finite_model(shaped(0.004, {0.001, 0.001, 0.001, 0.002, 0.003, 0.001, EndShape::flat, 0, 0}));
  // 2 m long and 1 m thick, solid and with a 0.1-mm wall.
  require_finite_model(shaped(2, {1, 0.2, 1, 0.5, 1.5, 1, EndShape::flat, 0, 0}));
  require_finite_model(shaped(2, {1, 0.2, 1, 0.5, 1.5, 1, EndShape::flat, 0, 1e-4}));
  // The 271 with the thinnest wall, of the lightest and floppiest material allowed.
  BatDesign thin = maple_design();
  thin.dimensions->end = EndShape::flat, thin.dimensions->end_depth = 0, thin.dimensions->wall_thickness = 1e-4;
  set_design_parameter(thin, "density", 10);
  set_design_parameter(thin, "shear_modulus", 1e6);
  set_design_parameter(thin, "youngs_modulus", 1e6);
  require_finite_model(thin);
  // The densest and floppiest wood on a 1-mm handle, its shear modulus 10 times Young's, the most
  // allowed; a million times made this bat's stiffness singular.
  BatDesign needle = maple_design();
  needle.dimensions->knob_diameter = needle.dimensions->handle_diameter = 0.001;
  needle.material.density = 25000, needle.material.youngs_modulus = 1e6, needle.material.shear_modulus = 1e7;
  require_finite_model(needle);
  needle.material.shear_modulus = 1e12;
  const auto rule = rule_break(needle);
  REQUIRE(rule);
  CHECK(rule->parameter == "shear_modulus");
  CHECK_THAT(rule->message, Catch::Contains("expected at most 10 times youngs_modulus"));
}

TEST_CASE("dimensions just outside their ranges are refused by the design's rules", "[bounds]") {
  const auto refused = [](double length, const Dimensions& d, const std::string& name, const std::string& range) {
    const auto rule = rule_break(shaped(length, d));
    REQUIRE(rule);
    CHECK(rule->parameter == name);
    CHECK_THAT(rule->message, Catch::Contains(range));
  };
  refused(0.004, {0.001, 0.001, 0.00099, 0.002, 0.003, 0.001, EndShape::flat, 0, 0}, "handle_diameter", "0.001 to 1 m");
  refused(0.84, {0.05, 0.02, 0.024, 0.3, 0.6, 1e300, EndShape::flat, 0, 0}, "barrel_diameter", "0.001 to 1 m");
  refused(2.001, {0.05, 0.02, 0.024, 0.3, 0.6, 0.06, EndShape::flat, 0, 0}, "length", "0.001 to 2 m");
  refused(0.84, {0.05, 0.02, 0.024, 0.3, 0.6, 0.06, EndShape::flat, 0, 0.99e-4}, "wall_thickness", "0.0001 to 0.5 m");
  refused(0.84, {0.05, 0.02, 0.024, 0.3, 0.6, 0.06, EndShape::flat, 0, 1e-30}, "wall_thickness", "0.0001 to 0.5 m");
}

TEST_CASE("a profile's diameters and wall are held to the same ranges as named dimensions", "[bounds]") {
  BatDesign tube = maple_design();
  tube.dimensions.reset();
  tube.length = 0.84;
  tube.profile.interpolation = Interpolation::linear;
  tube.profile.z = {0, 0.84};
  tube.profile.outer = {0.06, 0.06};
  tube.profile.inner = {0.06 - 2e-4, 0.06 - 2e-4};  // a 0.1-mm wall: the thinnest allowed
  require_finite_model(tube);
  tube.profile.inner = {0.06 - 2e-9, 0.06 - 2e-9};  // 1 nm: auto once estimated an error of 1.1 on it
  CHECK_THROWS_WITH(build_bat(tube), Catch::Contains("wall") && Catch::Contains("0.0001 to 0.5 m"));
  tube.profile.inner.clear();
  tube.profile.outer = {0.06, 1.5};
  CHECK_THROWS_WITH(build_bat(tube), Catch::Contains("outer_diameter 1.5 m") && Catch::Contains("0.001 to 1 m"));
}

TEST_CASE("a bat file names the key and the value as written when it leaves a range", "[bounds]") {
  TempDir dir;
  const std::string body = read(maple);
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = body;
    text.replace(text.find(from), from.size(), to);
    return dir.write("bat.toml", text);
  };
  BatSource source;
  CHECK_THROWS_WITH(load_bat_design(with("barrel_diameter = 0.0635", "barrel_diameter = 1e300"), source),
                    Catch::Contains("bat.toml:21: key 'dimensions.barrel_diameter'") && Catch::Contains("1e+300") &&
                        Catch::Contains("expected 0.001 to 1 m"));
  CHECK_THROWS_WITH(load_bat_design(with("barrel_diameter = 0.0635", "barrel_diameter = \"40 in\""), source),
                    Catch::Contains("key 'dimensions.barrel_diameter'") && Catch::Contains("\"40 in\"") &&
                        Catch::Contains("expected 0.001 to 1 m"));
  CHECK_THROWS_WITH(load_bat_design(with("preset = \"maple\"", "preset = \"maple\"\nyoungs_modulus = 1e300"), source),
                    Catch::Contains("key 'material.youngs_modulus'") && Catch::Contains("1e+300") &&
                        Catch::Contains("1000000 to 1e+12 Pa"));
  CHECK_THROWS_WITH(load_bat_design(with("preset = \"maple\"", "preset = \"maple\"\nshear_coefficient = 1e15"), source),
                    Catch::Contains("key 'material.shear_coefficient'") && Catch::Contains("0.1 to 1"));
  // Units still read, and a value at the bound is taken.
  CHECK(load_bat_design(with("barrel_diameter = 0.0635", "barrel_diameter = \"2.5 in\""), source)
            .dimensions->barrel_diameter == Approx(0.0635));
  CHECK(load_bat_design(with("preset = \"maple\"", "preset = \"maple\"\ndensity = 25000"), source).material.density ==
        25000);
  // slices = 2^63 - 1 is shown as written, not as the double it does not fit.
  CHECK_THROWS_WITH(load_bat_design(with("[material]", "slices = 9223372036854775807\n[material]"), source),
                    Catch::Contains("key 'slices'") && Catch::Contains("9223372036854775807"));
}

TEST_CASE("a profile row outside the ranges is refused at its line", "[bounds]") {
  TempDir dir;
  const auto bat = dir.write("bat.toml", "name = \"tube\"\nlength = 0.84\nprofile = \"p.csv\"\n[material]\npreset = \"maple\"\n");
  BatSource source;
  dir.write("p.csv", "z_m,outer_diameter_m,inner_diameter_m\n0,0.06,0.0598\n0.84,0.06,0.0598\n");
  CHECK(mass_properties(build_bat(load_bat_design(bat, source))).mass > 0);  // the thinnest wall allowed
  dir.write("p.csv", "z_m,outer_diameter_m,inner_diameter_m\n0,0.06,0.059999998\n0.84,0.06,0.0598\n");
  CHECK_THROWS_WITH(load_bat_design(bat, source), Catch::Contains("p.csv:2") && Catch::Contains("0.059999998") &&
                                                      Catch::Contains("0.0001 to 0.5 m"));
  dir.write("p.csv", "z_m,outer_diameter_m\n0,0.06\n0.84,1.5\n");
  CHECK_THROWS_WITH(load_bat_design(bat, source), Catch::Contains("p.csv:3") && Catch::Contains("outer_diameter_m = 1.5") &&
                                                      Catch::Contains("0.001 to 1 m"));
}

TEST_CASE("a study refuses bat parameters, ball keys and swing exponents outside their ranges", "[bounds]") {
  TempDir dir;
  const auto study = [&](const std::string& lines) {
    return dir.write("study.toml", "[scene]\nbat = \"" + r161 + "\"\ncenter = 0.09\nomega = 51\nball_speed = 40\n" + lines);
  };
  const auto refused = [&](const std::string& lines, const std::vector<std::string>& fragments) {
    INFO(lines);
    try {
      load_study(study(lines));
      FAIL("accepted");
    } catch (const InputError& e) {
      const std::string what = e.what();
      CHECK(what.find('\n') == std::string::npos);
      for (const std::string& f : fragments) CHECK_THAT(what, Catch::Contains(f));
    }
  };
  refused("z = 0.7\n[axes]\n\"bat.density\" = [649, 1e300]\n", {"bat.density", "1e+300", "10 to 25000 kg/m^3"});
  refused("z = 0.7\n\"bat.shear_coefficient\" = 1e15\n", {"bat.shear_coefficient", "1e+15", "0.1 to 1"});
  refused("z = 0.7\n\"bat.youngs_modulus\" = 1e-20\n", {"bat.youngs_modulus", "1e-20", "1000000 to 1e+12 Pa"});
  refused("z = 0.7\na = 50\n", {"key 'scene.a'", "50", "[0.5, 3]"});
  refused("z = 0.7\nk1 = 1e20\n", {"key 'scene.k1'", "[1000, 1e12]"});
  refused("z = 0.7\nball_mass = 11\n", {"key 'scene.ball_mass'", "[0.001, 10] kg"});
  refused("z = 0.7\nswing = \"equal_effort\"\nreference_bat = \"" + r161 + "\"\nswing_exponent = 1e300\n",
          {"key 'scene.swing_exponent'", "1e+300", "[0, 2]"});
  refused("z = 0.7\nslices = 9223372036854775807\n", {"key 'scene.slices'", "9223372036854775807"});
  refused("z = 0.7\n[axes]\n\"bat.material\" = [\"maple\", \"ash\", \"maple\"]\n", {"\"maple\"", "appears twice"});
  // At the ends of their ranges, the same keys are taken.
  CHECK_NOTHROW(load_study(study("z = 0.7\na = 3\nk1 = 1e12\nball_mass = 10\n\"bat.density\" = 25000\n")));
  CHECK_NOTHROW(load_study(study("z = 0.7\nswing = \"equal_effort\"\nreference_bat = \"" + r161 +
                                 "\"\nswing_exponent = 0\n")));
}

TEST_CASE("a study with a bat outside the ranges is refused by the program before any work", "[bounds][program]") {
  TempDir dir;
  dir.write("out.h5", "\x89HDF\r\n\x1a\nan earlier result");
  const auto study = dir.write("study.toml", "[scene]\nbat = \"" + r161 +
                                                 "\"\ncenter = 0.09\nomega = 51\nball_speed = 40\nz = 0.7\n"
                                                 "[axes]\n\"bat.youngs_modulus\" = [1.8e10, 1e300]\n");
  require_refused(run_program("run " + study.string() + " -o " + dir / "out.h5"),
                  {"study.toml", "bat.youngs_modulus", "1e+300", "1000000 to 1e+12 Pa"});
  CHECK(read(dir / "out.h5") == "\x89HDF\r\n\x1a\nan earlier result");
}

TEST_CASE("an optimisation's bounds, weights and swing exponent meet the same ranges", "[bounds]") {
  TempDir dir;
  const auto problem = [&](const std::string& free, const std::string& exponent, const std::string& weights) {
    return dir.write("opt.toml", "bat = \"" + maple + "\"\n[free]\n" + free +
                                     "\n[player]\ncenter = 0.09\nomega = 51\nball_speed = 40\nswing_exponent = " +
                                     exponent + "\n[model]\nmodes = 0\n[objective]\nmaximize = \"mean_bbs\"\n"
                                     "points = [0.7, 0.75]\nweights = " + weights + "\n");
  };
  CHECK_NOTHROW(load_optimization(problem("density = { min = 10, max = 25000, start = 700 }", "2", "[1, 1]")));
  CHECK_NOTHROW(load_optimization(problem("density = { min = 100, max = 3000 }", "0", "[1e307, 1e307]")));
  CHECK_THROWS_WITH(load_optimization(problem("density = { min = 100, max = 25001 }", "0.3", "[1, 1]")),
                    Catch::Contains("free.density.max") && Catch::Contains("25001") &&
                        Catch::Contains("10 to 25000 kg/m^3"));
  CHECK_THROWS_WITH(load_optimization(problem("barrel_diameter = { min = 0.06, max = 1e300 }", "0.3", "[1, 1]")),
                    Catch::Contains("free.barrel_diameter.max") && Catch::Contains("0.001 to 1 m"));
  CHECK_THROWS_WITH(load_optimization(problem("density = { min = 100, max = 3000 }", "2.01", "[1, 1]")),
                    Catch::Contains("player.swing_exponent") && Catch::Contains("[0, 2]"));
  CHECK_THROWS_WITH(load_optimization(problem("density = { min = 100, max = 3000 }", "0.3", "[1e308, 1e308]")),
                    Catch::Contains("objective.weights") && Catch::Contains("finite sum"));
}

TEST_CASE("a point off the bat is shown with the digits that tell it from the bat's end", "[bounds][program]") {
  const ProgramRun run =
      run_program("impact --bat " + r161 + " --z 0.840000002 --ball-speed 40 --center 0.09 --omega 51");
  require_refused(run, {"z = 0.840000002", "0 to 0.84 m"});
  TempDir dir;
  const auto study = dir.write("study.toml", "[scene]\nbat = \"" + r161 +
                                                 "\"\ncenter = 0.09\nomega = 51\nball_speed = 40\nz = 0.840000002\n");
  CHECK_THROWS_WITH(load_study(study), Catch::Contains("= 0.840000002") && Catch::Contains("0 to 0.84 m"));
}

TEST_CASE("certify refuses too many modes and a bat too short for the rig in its own name", "[bounds][program]") {
  require_refused(run_program("certify " + r161 + " --modes 1000"), {"certify: modes 1000", "'auto'"});
  TempDir dir;
  std::string text = read(maple);
  const std::string from = "taper_end = 0.6604";
  text.replace(text.find(from), from.size(), "taper_end = 0.25");
  text.replace(text.find("taper_start = 0.3048"), 20, "taper_start = 0.2");
  text.replace(text.find("length = 0.8382"), 15, "length = 0.3");
  const auto bat = dir.write("short.toml", text);
  require_refused(run_program("certify " + bat.string()),
                  {"certify", "expected a bat longer than", "must lie before the scanned barrel"});
}

TEST_CASE("an auto estimate orders of magnitude past the tolerance fails the point, with a reason", "[bounds]") {
  ImpactScene scene;
  scene.vibrational_modes = auto_modes;
  scene.mode_tolerance = 1e-5;
  ImpactResult r;
  r.modes_error = 1.1;
  flag_untrusted_modes_error(scene, r);
  CHECK(r.status == CollisionStatus::failed);
  CHECK_THAT(r.message, Catch::Contains("1.1") && Catch::Contains("mode_tolerance"));
  ImpactResult near;
  near.modes_error = 12 * scene.mode_tolerance;  // repeated contacts: within what impact.cpp allows
  flag_untrusted_modes_error(scene, near);
  CHECK(near.status == CollisionStatus::ok);
  // A stated accuracy gives the modes its share (a quarter), not mode_tolerance: a ball caught
  // four times near the handle counts that share about four times over, and must stay ok.
  scene.accuracy = 1e-3;
  ImpactResult stated;
  stated.modes_error = 4.1 * accuracy_budget(scene.accuracy).modes;
  flag_untrusted_modes_error(scene, stated);
  CHECK(stated.status == CollisionStatus::ok);
  stated.modes_error = 0.03;  // past 100 times the share
  flag_untrusted_modes_error(scene, stated);
  CHECK(stated.status == CollisionStatus::failed);
  CHECK_THAT(stated.message, Catch::Contains("the accuracy's share"));
}
