// Bats as design spaces (bat/bat_design.hpp, bat/dimensions.hpp, README "Bat files"): named
// dimensions make the shapes they name, to closed forms of cylinders and frustums; a parametric
// bat is the same bat as its knot CSV; every impossible bat is refused naming parameter, value and
// rule; parameters set by name; wood presets are the Wood Handbook's numbers.
#include <algorithm>
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "program.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/parameter_bounds.hpp"
#include "sweetspot/input_error.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double inch = 0.0254, ounce = 0.028349523125;  // m, kg
constexpr double rho = 700;

// Knob 0.05 x 0.02 m, handle 0.025 m to 0.3 m, frustum to a 0.064 m barrel at 0.6 m, 0.84 m long.
Dimensions bat_dimensions() { return {0.05, 0.02, 0.025, 0.3, 0.6, 0.064}; }

BatDesign parametric(const Dimensions& d, double length = 0.84) {
  BatDesign design;
  design.name = "parametric";
  design.length = length;
  design.material = {rho, 1.4e10, 1.5e9, 1};
  design.dimensions = d;
  return design;
}

// A cylinder is a bat whose knob, handle and barrel are one diameter.
Dimensions cylinder(double diameter) { return {diameter, 0.02, diameter, 0.3, 0.6, diameter}; }

// A solid of revolution's part: mass, CM and MOI about its own CM (discs' rotary inertia included).
struct Part {
  double mass, z_cm, moment;
};

// The frustum from radius a at z0 to b at z1, by exact integration of r(s) = a + c s:
// int r^2 s^k ds = a^2 h^(k+1)/(k+1) + 2 a c h^(k+2)/(k+2) + c^2 h^(k+3)/(k+3), int r^4 = (b^5 - a^5)/5c.
Part frustum(double z0, double z1, double a, double b, double density = rho) {
  const double h = z1 - z0, c = (b - a) / h;
  const auto r2 = [&](int k) {
    return a * a * std::pow(h, k + 1) / (k + 1) + 2 * a * c * std::pow(h, k + 2) / (k + 2) +
           c * c * std::pow(h, k + 3) / (k + 3);
  };
  const double r4 = c == 0 ? std::pow(a, 4) * h : (std::pow(b, 5) - std::pow(a, 5)) / (5 * c);
  const double mass = density * pi * r2(0), s_cm = r2(1) / r2(0);
  return {mass, z0 + s_cm, density * pi * (r2(2) - s_cm * s_cm * r2(0)) + density * pi / 4 * r4};
}

Part cylinder_part(double z0, double z1, double diameter) { return frustum(z0, z1, diameter / 2, diameter / 2); }

Part removed(Part p) { return {-p.mass, p.z_cm, -p.moment}; }

// Parts put together by the parallel-axis theorem; a removed part (a bore) counts negative.
MassProperties compose(const std::vector<Part>& parts) {
  MassProperties p;
  double first = 0;
  for (const Part& part : parts) p.mass += part.mass, first += part.mass * part.z_cm;
  p.z_cm = first / p.mass;
  for (const Part& part : parts)
    p.moment_of_inertia_cm += part.moment + part.mass * (part.z_cm - p.z_cm) * (part.z_cm - p.z_cm);
  return p;
}

void require_same(const MassProperties& p, const MassProperties& q, double tolerance = 1e-9) {
  CHECK(p.mass == Approx(q.mass).epsilon(tolerance));
  CHECK(p.z_cm == Approx(q.z_cm).epsilon(tolerance));
  CHECK(p.moment_of_inertia_cm == Approx(q.moment_of_inertia_cm).epsilon(tolerance));
}

// The design is refused, by broken_rule and build_bat alike, with one line holding every fragment.
void require_broken(const BatDesign& design, const std::vector<std::string>& fragments) {
  const auto rule = broken_rule(design);
  REQUIRE(rule);
  INFO("rule: " << *rule);
  CHECK(rule->find('\n') == std::string::npos);
  for (const std::string& f : fragments) CHECK_THAT(*rule, Catch::Contains(f));
  CHECK_THROWS_AS(build_bat(design), InputError);
  CHECK_THROWS_WITH(build_bat(design), *rule);
}

BatDesign with(BatDesign design, std::string_view name, double value) {
  set_design_parameter(design, name, value);
  return design;
}

BatDesign load(const std::string& file) {
  BatSource source;
  return load_bat_design(source_path("studies/bats/" + file), source);
}

}  // namespace

// ---- Closed forms -----------------------------------------------------------------------------

TEST_CASE("A parametric cylinder has a solid cylinder's mass, CM and MOI", "[bat_design]") {
  const double d = 0.06, L = 0.84;
  const MassProperties p = design_mass_properties(parametric(cylinder(d), L));
  const double mass = rho * pi * d * d / 4 * L;
  require_same(p, {mass, L / 2, mass * (L * L / 12 + d * d / 16)});
}

TEST_CASE("A parametric tube has a hollow cylinder's mass, CM and MOI", "[bat_design]") {
  const double d = 0.06, t = 0.003, di = d - 2 * t, L = 0.84;
  Dimensions tube = cylinder(d);
  tube.wall_thickness = t;
  const MassProperties p = design_mass_properties(parametric(tube, L));
  const double mass = rho * pi * (d * d - di * di) / 4 * L;
  require_same(p, {mass, L / 2, mass * (L * L / 12 + (d * d + di * di) / 16)});
}

TEST_CASE("Slicing a cylinder loses exactly each slice's own m dz^2/12 of its MOI", "[bat_design]") {
  const BatDesign design = parametric(cylinder(0.06));
  const Bat bat = build_bat(design);
  const MassProperties exact = design_mass_properties(design), sliced = mass_properties(bat);
  const double dz = bat.slice_thickness();
  CHECK(sliced.mass == Approx(exact.mass).epsilon(1e-12));
  CHECK(exact.moment_of_inertia_cm - sliced.moment_of_inertia_cm ==
        Approx(exact.mass * dz * dz / 12).epsilon(1e-9));
}

TEST_CASE("A frustum of two knots has the textbook volume and centroid", "[bat_design]") {
  const double a = 0.0125, b = 0.032, L = 0.84;
  BatDesign design = parametric(cylinder(0.06), L);
  design.dimensions.reset();
  design.profile = {Interpolation::linear, {0, L}, {2 * a, 2 * b}, {}};
  const MassProperties p = design_mass_properties(design);
  CHECK(p.mass == Approx(rho * pi * L / 3 * (a * a + a * b + b * b)).epsilon(1e-12));
  CHECK(p.z_cm == Approx(L * (a * a + 2 * a * b + 3 * b * b) / (4 * (a * a + a * b + b * b))).epsilon(1e-12));
  require_same(p, compose({frustum(0, L, a, b)}));
}

TEST_CASE("A parametric bat is its knob, handle, frustum taper and barrel put together", "[bat_design]") {
  const Dimensions d = bat_dimensions();
  const double L = 0.84;
  const std::vector<Part> solid = {cylinder_part(0, d.knob_length, d.knob_diameter),
                                   cylinder_part(d.knob_length, d.taper_start, d.handle_diameter),
                                   frustum(d.taper_start, d.taper_end, d.handle_diameter / 2, d.barrel_diameter / 2),
                                   cylinder_part(d.taper_end, L, d.barrel_diameter)};
  SECTION("flat end") { require_same(design_mass_properties(parametric(d, L)), compose(solid)); }
  SECTION("cupped end: a bore half the barrel wide") {
    Dimensions cupped = d;
    cupped.end = EndShape::cupped;
    cupped.end_depth = 0.025;
    std::vector<Part> parts = solid;
    parts.push_back(removed(cylinder_part(L - 0.025, L, d.barrel_diameter / 2)));
    require_same(design_mass_properties(parametric(cupped, L)), compose(parts));
  }
  SECTION("hollow: the same bat less its bore, the handle's along the knob, wall_thickness in beyond") {
    Dimensions hollow = d;
    hollow.wall_thickness = 0.002;
    const double bore = d.handle_diameter - 0.004;
    std::vector<Part> parts = solid;
    parts.push_back(removed(cylinder_part(0, d.taper_start, bore)));
    parts.push_back(removed(frustum(d.taper_start, d.taper_end, bore / 2, (d.barrel_diameter - 0.004) / 2)));
    parts.push_back(removed(cylinder_part(d.taper_end, L, d.barrel_diameter - 0.004)));
    require_same(design_mass_properties(parametric(hollow, L)), compose(parts));
  }
}

TEST_CASE("A rounded end holds within 0.3 % of a half-ellipsoid's mass, never more", "[bat_design]") {
  Dimensions rounded = bat_dimensions();
  rounded.end = EndShape::rounded;
  rounded.end_depth = 0.015;
  const double L = 0.84;
  // The bat up to the end's start is the flat bat of that length.
  const double body = design_mass_properties(parametric(bat_dimensions(), L - rounded.end_depth)).mass;
  const double cap = design_mass_properties(parametric(rounded, L)).mass - body;
  const double ellipsoid = rho * 2.0 / 3 * pi * std::pow(rounded.barrel_diameter / 2, 2) * rounded.end_depth;
  CHECK(cap <= ellipsoid);
  CHECK(cap >= 0.997 * ellipsoid);
}

TEST_CASE("A parametric bat equals the same shape written as a knot CSV", "[bat_design]") {
  // Knob as thick as the handle: a shape a knot CSV (no steps) can write.
  const TempDir dir;
  const std::string material = "[material]\ndensity = 700\nyoungs_modulus = 1.4e10\nshear_modulus = 1.5e9\n";
  dir.write("knots.csv", "z_m,outer_diameter_m\n0,0.025\n0.3,0.025\n0.6,0.064\n0.84,0.064\n");
  const auto knots = dir.write("knots.toml", "name = \"k\"\nlength = 0.84\nprofile = \"knots.csv\"\n" + material);
  const auto dims = dir.write("dims.toml", "name = \"d\"\nlength = 0.84\n" + material +
                                               "[dimensions]\nknob_diameter = 0.025\nknob_length = 0.02\n"
                                               "handle_diameter = 0.025\ntaper_start = 0.3\ntaper_end = 0.6\n"
                                               "barrel_diameter = 0.064\n");
  const Bat a = load_bat(knots), b = load_bat(dims);
  REQUIRE(a.slices() == 84);
  REQUIRE(b.slices() == 84);
  CHECK_FALSE(b.hollow());
  for (int i = 0; i < a.slices(); ++i) {
    INFO("slice " << i);
    CHECK(b.outer_diameter[i] == Approx(a.outer_diameter[i]).epsilon(1e-12));
    CHECK(b.section_area[i] == Approx(a.section_area[i]).epsilon(1e-12));
    CHECK(b.section_second_moment[i] == Approx(a.section_second_moment[i]).epsilon(1e-12));
  }
  BatSource source;
  const MassProperties of_dims = design_mass_properties(load_bat_design(dims, source));
  CHECK(source.profile_file.empty());  // named dimensions read no CSV
  require_same(of_dims, design_mass_properties(load_bat_design(knots, source)), 1e-12);
  CHECK(source.profile_file == dir.path / "knots.csv");
}

TEST_CASE("load_bat is build_bat of load_bat_design, and a profile's mass properties are its slices'", "[bat_design]") {
  for (const char* file : {"r161.toml", "torpedo.toml", "aluminium.toml"}) {
    INFO(file);
    const BatDesign design = load(file);
    REQUIRE(design.slice_profile);
    const Bat built = build_bat(design), loaded = load_bat(source_path(std::string("studies/bats/") + file));
    CHECK(built.section_area == loaded.section_area);
    CHECK(built.section_second_moment == loaded.section_second_moment);
    // Slices of uniform section: the exact shape is the slices, with each one's m dz^2/12.
    const MassProperties exact = design_mass_properties(design), sliced = mass_properties(built);
    CHECK(exact.mass == Approx(sliced.mass).epsilon(1e-12));
    CHECK(exact.z_cm == Approx(sliced.z_cm).epsilon(1e-12));
    const double dz = built.slice_thickness();
    CHECK(exact.moment_of_inertia_cm - sliced.moment_of_inertia_cm == Approx(exact.mass * dz * dz / 12).epsilon(1e-9));
  }
}

// ---- Impossible bats --------------------------------------------------------------------------

TEST_CASE("Every impossible parametric bat is refused naming parameter, value and rule", "[bat_design]") {
  const BatDesign bat = parametric(bat_dimensions());
  REQUIRE_FALSE(broken_rule(bat));
  SECTION("barrel thinner than the handle") {
    require_broken(with(bat, "barrel_diameter", 0.02), {"barrel_diameter 0.02 m", "handle_diameter 0.025 m", "less than"});
  }
  SECTION("knob thinner than the handle") {
    require_broken(with(bat, "knob_diameter", 0.02), {"knob_diameter 0.02 m", "handle_diameter 0.025 m", "less than"});
  }
  SECTION("taper starting within the knob") {
    require_broken(with(bat, "taper_start", 0.01), {"taper_start 0.01 m", "knob_length 0.02 m", "knob_length < taper_start"});
  }
  SECTION("taper ending before it starts") {
    require_broken(with(bat, "taper_end", 0.3), {"taper_end 0.3 m", "taper_start 0.3 m", "taper_start < taper_end"});
  }
  SECTION("taper ending beyond the length") {
    require_broken(with(bat, "taper_end", 0.9), {"taper_end 0.9 m", "length 0.84", "taper_end < length - end_depth"});
    require_broken(with(bat, "length", 0.5), {"taper_end 0.6 m", "length 0.5", "taper_end < length - end_depth"});
  }
  SECTION("taper ending in the cup") {
    BatDesign cupped = with(bat, "end_depth", 0.25);
    cupped.dimensions->end = EndShape::cupped;
    require_broken(cupped, {"taper_end 0.6 m", "end_depth 0.25 m", "taper_end < length - end_depth"});
  }
  SECTION("wall as thick as the radius, or thicker") {
    require_broken(with(bat, "wall_thickness", 0.0125), {"wall_thickness 0.0125 m", "radius 0.0125 m", "thinner"});
    require_broken(with(bat, "wall_thickness", 0.02), {"wall_thickness 0.02 m", "radius 0.0125 m"});
  }
  SECTION("a cupped hollow bat") {
    BatDesign cupped = with(with(bat, "end_depth", 0.02), "wall_thickness", 0.002);
    cupped.dimensions->end = EndShape::cupped;
    require_broken(cupped, {"wall_thickness 0.002 m", "cupped", "solid"});
  }
  SECTION("a depth for a flat end, none for a rounded one") {
    require_broken(with(bat, "end_depth", 0.01), {"end_depth 0.01 m", "'flat'"});
    BatDesign rounded = bat;
    rounded.dimensions->end = EndShape::rounded;
    require_broken(rounded, {"end_depth 0 m", "'rounded'", "positive"});
  }
  SECTION("non-positive or non-finite values") {
    require_broken(with(bat, "knob_length", 0), {"knob_length 0 m", "not positive"});
    require_broken(with(bat, "handle_diameter", -0.025), {"handle_diameter -0.025 m", "not positive"});
    require_broken(with(bat, "barrel_diameter", NAN), {"barrel_diameter nan m", "not a finite number"});
    // A wall set is a wall: 0 or less is refused when set, before any rule (a solid bat has none).
    CHECK_THROWS_WITH(with(bat, "wall_thickness", 0), Catch::Contains("'wall_thickness' = 0:") &&
                                                          Catch::Contains("expected a positive, finite value"));
    CHECK_THROWS_WITH(with(bat, "wall_thickness", -0.001), Catch::Contains("'wall_thickness' = -0.001:") &&
                                                               Catch::Contains("expected a positive, finite value"));
    require_broken(with(bat, "length", INFINITY), {"length inf m", "not a positive, finite number"});
    require_broken(with(bat, "density", 0), {"density 0 kg/m^3", "not a positive, finite number"});
    require_broken(with(bat, "shear_coefficient", -1), {"shear_coefficient -1 ", "not a positive, finite number"});
  }
}

TEST_CASE("A knot profile may change its length while its knots stay on the bat", "[bat_design]") {
  BatDesign design = parametric(cylinder(0.06));
  design.dimensions.reset();
  design.profile = {Interpolation::linear, {0, 0.42, 0.84}, {0.03, 0.06, 0.06}, {}};
  require_broken(with(design, "length", 0.8), {"knot at z_m = 0.84 m", "beyond length 0.8 m"});
  // Longer: the last knot's diameter is held to the new end, a cylinder's worth more mass.
  const double before = design_mass_properties(design).mass;
  const double after = design_mass_properties(with(design, "length", 0.9)).mass;
  CHECK(after - before == Approx(rho * pi * 0.06 * 0.06 / 4 * 0.06).epsilon(1e-9));
  CHECK(build_bat(with(design, "length", 0.9)).slices() == 90);  // about 1 cm each
}

// ---- Parameters by name -----------------------------------------------------------------------

TEST_CASE("A design's parameters: length, the material constants and every dimension", "[bat_design]") {
  BatDesign bat = parametric(bat_dimensions());
  const std::vector<std::string> expected = {"length",        "density",         "youngs_modulus",  "shear_modulus",
                                             "shear_coefficient", "hoop_modulus", "wall_loss_factor", "loss_factor",
                                             "knob_diameter", "knob_length", "handle_diameter",
                                             "taper_start",   "taper_end",       "barrel_diameter", "end_depth",
                                             "wall_thickness"};
  CHECK(design_parameters(bat) == expected);
  for (const std::string& name : expected) {
    // A value within the parameter's range (parameter_bounds.hpp): outside it, setting it throws.
    const ParameterBound* bound = parameter_bound(name);
    const double value = bound ? std::clamp(0.125, bound->low, bound->high) : 0.125;
    set_design_parameter(bat, name, value);
    CHECK(design_parameter(bat, name) == value);
  }
  const BatDesign r161 = load("r161.toml");
  CHECK(design_parameters(r161) == std::vector<std::string>(expected.begin(), expected.begin() + 8));
  CHECK(design_parameter(r161, "density") == 649);
}

TEST_CASE("Setting a parameter the design lacks names it, the value and the choices", "[bat_design]") {
  BatDesign r161 = load("r161.toml");
  CHECK_THROWS_WITH(set_design_parameter(r161, "barrel_diameter", 0.06),
                    Catch::Contains("'barrel_diameter' = 0.06") && Catch::Contains("profile CSV") &&
                        Catch::Contains("expected one of length, density"));
  CHECK_THROWS_WITH(set_design_parameter(r161, "poisson_ratio", 0.3),
                    Catch::Contains("'poisson_ratio' = 0.3") && Catch::Contains("no such parameter"));
  CHECK_THROWS_AS(design_parameter(r161, "taper_end"), InputError);
  // One diameter per slice fixes the length; setting it to what it is changes nothing.
  CHECK_THROWS_WITH(set_design_parameter(r161, "length", 0.9),
                    Catch::Contains("'length' = 0.9") && Catch::Contains("one diameter per slice") &&
                        Catch::Contains("0.84"));
  set_design_parameter(r161, "length", 0.84);
  CHECK(build_bat(r161).slices() == 84);
}

// ---- Wood presets -----------------------------------------------------------------------------

TEST_CASE("Wood presets are the Wood Handbook's numbers at 12 % moisture", "[bat_design]") {
  CHECK(material_presets() == std::vector<std::string>{"maple", "ash", "birch"});
  // Specific gravity, static-bending MOE and G_LR/E_L (FPL-GTR-190 Tables 5-3a and 5-1).
  const struct {
    const char* name;
    double gravity, bending_modulus, shear_ratio;
  } handbook[] = {{"maple", 0.63, 12.6e9, 0.111}, {"ash", 0.60, 12.0e9, 0.109}, {"birch", 0.62, 13.9e9, 0.074}};
  for (const auto& wood : handbook) {
    INFO(wood.name);
    BatDesign design = parametric(bat_dimensions());
    design.material.shear_coefficient = 0.9;
    set_material_preset(design, wood.name);
    CHECK(design.material_name == wood.name);
    CHECK(design.material.density == Approx(1000 * wood.gravity * 1.12));
    CHECK(design.material.youngs_modulus == Approx(1.1 * wood.bending_modulus));
    CHECK(design.material.shear_modulus == Approx(wood.shear_ratio * 1.1 * wood.bending_modulus));
    CHECK(design.material.shear_coefficient == 0.9);  // the beam's, not the wood's
  }
  BatDesign design = parametric(bat_dimensions());
  CHECK_THROWS_WITH(set_material_preset(design, "oak"), Catch::Contains("'oak'") && Catch::Contains("maple, ash, birch"));
}

TEST_CASE("The shipped parametric bats are legal bats of their kind", "[bat_design]") {
  SECTION("maple 271: 33 in, 2 1/2 in barrel, a pro wood bat's weight") {
    const BatDesign maple = load("maple_271.toml");
    CHECK(maple.material_name == "maple");
    REQUIRE(maple.dimensions);
    CHECK(maple.dimensions->end == EndShape::cupped);
    CHECK(maple.dimensions->barrel_diameter <= 2.625 * inch);
    const double ounces = design_mass_properties(maple).mass / ounce;
    CHECK(ounces >= 30);  // drop -3 or heavier,
    CHECK(ounces <= 33);  // and no heavier than its length
    CHECK(mass_properties(build_bat(maple)).mass == Approx(design_mass_properties(maple).mass).epsilon(1e-12));
  }
  SECTION("alloy BBCOR: hollow, barrel at most 2 5/8 in, drop no lighter than -3") {
    const BatDesign alloy = load("alloy_bbcor.toml");
    REQUIRE(alloy.dimensions);
    CHECK(alloy.dimensions->wall_thickness > 0);
    CHECK(build_bat(alloy).hollow());
    CHECK(alloy.dimensions->barrel_diameter <= 2.625 * inch);
    CHECK(alloy.length / inch - design_mass_properties(alloy).mass / ounce >= -3);
  }
}
