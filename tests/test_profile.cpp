// Knot profiles (bat/profile.hpp, README "Bat files"): diameters at any sorted knots, cut into
// slices by integrating A and I, agree with slice profiles and with closed forms.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "program.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/bat/profile.hpp"
#include "sweetspot/input_error.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

const Material ash{649, 1.814e10, 1.05e9, 1.0};

Bat knot_bat(const Profile& profile, int slices, double length = 0.84) {
  Bat bat;
  bat.name = "knots";
  bat.length = length;
  bat.material = ash;
  cut_into_slices(profile, slices, bat);
  return bat;
}

// A bat file and its profile in a fresh directory.
std::filesystem::path write_bat(const TempDir& dir, const std::string& toml_extra, const std::string& csv,
                                double length = 0.84) {
  dir.write("profile.csv", csv);
  return dir.write("bat.toml", "name = \"knots\"\nlength = " + std::to_string(length) +
                                   "\nprofile = \"profile.csv\"\n" + toml_extra +
                                   "[material]\ndensity = 649\nyoungs_modulus = 1.814e10\nshear_modulus = 1.05e9\n");
}

void require_refused(const std::filesystem::path& toml, const std::vector<std::string>& fragments) {
  try {
    load_bat(toml);
    FAIL("accepted");
  } catch (const InputError& e) {
    for (const std::string& f : fragments) CHECK_THAT(e.what(), Catch::Contains(f));
  }
}

}  // namespace

TEST_CASE("A uniform rod given as 2 knots is the rod given as 336 equal slices", "[profile]") {
  Bat slices;
  slices.name = "rod";
  slices.length = 0.84;
  slices.material = ash;
  slices.set_slices(std::vector<double>(336, 0.06));
  const Bat knots = knot_bat(Profile{Interpolation::linear, {0.0, 0.84}, {0.06, 0.06}, {}}, 336);
  const auto f = compute_modes(slices, BeamTheory::timoshenko).vibrational_frequencies_hz();
  const auto g = compute_modes(knots, BeamTheory::timoshenko).vibrational_frequencies_hz();
  REQUIRE(f.size() == g.size());
  for (std::size_t n = 0; n < f.size(); ++n) CHECK(g[n] == Approx(f[n]).epsilon(1e-10));
}

TEST_CASE("Knots at the slice centres of R161, stepped, are R161", "[profile]") {
  const Bat r161 = load_bat(source_path("studies/bats/r161.toml"));
  Profile p{Interpolation::stepped, {}, r161.outer_diameter, {}};
  for (int i = 0; i < r161.slices(); ++i) p.z.push_back(r161.slice_center(i));
  const Bat knots = knot_bat(p, r161.slices());
  for (int i = 0; i < r161.slices(); ++i) {
    CHECK(knots.area(i) == Approx(r161.area(i)).epsilon(1e-12));
    CHECK(knots.second_moment(i) == Approx(r161.second_moment(i)).epsilon(1e-12));
  }
  const auto f = compute_modes(r161, BeamTheory::timoshenko).vibrational_frequencies_hz();
  const auto g = compute_modes(knots, BeamTheory::timoshenko).vibrational_frequencies_hz();
  for (std::size_t n = 0; n < 10; ++n) CHECK(g[n] == Approx(f[n]).epsilon(1e-10));
}

TEST_CASE("A linear taper's slices hold the frustums' exact mass and second moment", "[profile]") {
  // A cone frustum of diameters d1, d2 over length h: volume pi h (d1^2 + d1 d2 + d2^2) / 12, and
  // the integral of I = pi d^4 / 64 along it pi h (d1^4 + d1^3 d2 + ... + d2^4) / 320.
  const double d1 = 0.025, d2 = 0.066, h = 0.5;
  const Profile p{Interpolation::linear, {0.2, 0.7}, {d1, d2}, {}};
  for (int n : {7, 84, 100}) {
    const Bat bat = knot_bat(p, n);
    double volume = 0, inertia_integral = 0;
    for (int i = 0; i < n; ++i) {
      volume += bat.area(i) * bat.slice_thickness();
      inertia_integral += bat.second_moment(i) * bat.slice_thickness();
    }
    const double ends = std::numbers::pi / 4 * (0.2 * d1 * d1 + 0.14 * d2 * d2);  // cylinders beyond the knots
    const double ends_i = std::numbers::pi / 64 * (0.2 * std::pow(d1, 4) + 0.14 * std::pow(d2, 4));
    INFO(n << " slices");
    CHECK(volume == Approx(std::numbers::pi * h * (d1 * d1 + d1 * d2 + d2 * d2) / 12 + ends).epsilon(1e-13));
    const double sum4 = std::pow(d1, 4) + std::pow(d1, 3) * d2 + d1 * d1 * d2 * d2 + d1 * std::pow(d2, 3) + std::pow(d2, 4);
    CHECK(inertia_integral == Approx(std::numbers::pi * h * sum4 / 320 + ends_i).epsilon(1e-13));
  }
}

TEST_CASE("The shape-preserving cubic stays between its knots and keeps lines straight", "[profile]") {
  // A handle-to-barrel step: a natural cubic spline would bulge past both diameters.
  const Profile step{Interpolation::pchip, {0.0, 0.3, 0.4, 0.5, 0.84}, {0.025, 0.025, 0.045, 0.066, 0.066}, {}};
  double previous = 0;
  for (int k = 0; k <= 840; ++k) {
    const double d = step.diameter(k * 0.001);
    CHECK(d >= previous - 1e-15);  // monotone data, monotone curve
    CHECK(d >= 0.025 - 1e-15);
    CHECK(d <= 0.066 + 1e-15);
    previous = d;
  }
  const Profile line{Interpolation::pchip, {0.0, 0.2, 0.5, 0.84}, {0.02, 0.03, 0.045, 0.062}, {}};
  for (double z : {0.1, 0.33, 0.7}) CHECK(line.diameter(z) == Approx(0.02 + 0.05 * z).epsilon(1e-14));
}

TEST_CASE("Bat files: knots, a designer's few, and slices written to 4 decimals", "[profile][bat_file]") {
  TempDir dir;
  SECTION("ten knots with pchip, 0.5 cm slices") {
    const auto toml = write_bat(dir, "interpolation = \"pchip\"\nslices = 168\n",
                                "z_m,outer_diameter_m\n0,0.060\n0.012,0.030\n0.05,0.024\n0.2,0.025\n0.38,0.030\n"
                                "0.46,0.045\n0.53,0.060\n0.6,0.0655\n0.8,0.0660\n0.84,0.064\n");
    const Bat bat = load_bat(toml);
    CHECK(bat.slices() == 168);
    CHECK(compute_modes(bat, BeamTheory::timoshenko).vibrational_frequencies_hz()[0] > 100);
    const ProgramRun run = run_program("impact --bat " + toml.string() + " --z 0.7 --ball-speed 40 --center 0.09 --omega 51");
    INFO(run.output);
    CHECK(run.exit_code == 0);
  }
  SECTION("a knot profile is cut into about 1-cm slices unless told") {
    const auto toml = write_bat(dir, "", "z_m,outer_diameter_m\n0,0.03\n0.84,0.06\n");
    CHECK(load_bat(toml).slices() == 84);
  }
  SECTION("a 33-in bat's slice centres written to 4 decimals") {
    const double length = 33 * 0.0254;
    std::string csv = "z_center_m,outer_diameter_m\n";
    char row[64];
    for (int i = 0; i < 84; ++i) {
      std::snprintf(row, sizeof row, "%.4f,%.4f\n", (i + 0.5) * length / 84, 0.03 + 0.0003 * i);
      csv += row;
    }
    CHECK(load_bat(write_bat(dir, "", csv, length)).slices() == 84);
  }
}

TEST_CASE("Bad knot profiles are refused naming the file, the line or key, the value and the rule", "[profile][bat_file]") {
  TempDir dir;
  require_refused(write_bat(dir, "", "z_m,outer_diameter_m\n0,0.03\n0.85,0.06\n"),
                  {"profile.csv:3", "z_m = 0.85", "outside the bat", "0.84"});
  require_refused(write_bat(dir, "", "z_m,outer_diameter_m\n0.4,0.03\n"), {"profile.csv", "at least 2 knots"});
  require_refused(write_bat(dir, "", "z_m,outer_diameter_m\n0.4,0.03\n0.3,0.05\n"),
                  {"profile.csv:3", "z_m = 0.3", "sorted"});
  require_refused(write_bat(dir, "interpolation = \"spline\"\n", "z_m,outer_diameter_m\n0,0.03\n0.84,0.06\n"),
                  {"bat.toml", "interpolation", "spline", "'stepped', 'linear' or 'pchip'"});
  require_refused(write_bat(dir, "slices = 2\n", "z_m,outer_diameter_m\n0,0.03\n0.84,0.06\n"),
                  {"bat.toml", "slices", "2", "4 to 4096"});
  require_refused(write_bat(dir, "interpolation = \"linear\"\n",
                            "z_center_m,outer_diameter_m\n0.105,0.03\n0.315,0.04\n0.525,0.05\n0.735,0.06\n"),
                  {"bat.toml", "interpolation", "one diameter per slice", "z_m"});
  require_refused(write_bat(dir, "", "z_center_m,z_m,outer_diameter_m\n0.4,0.4,0.03\n"), {"both"});
}

TEST_CASE("A pchip profile whose bore crosses the outside between knots is refused, naming the knots", "[profile][bat_file]") {
  // Inside every knot the wall is 0.1 mm, but the two curves bend apart: pchip's outer curve rises
  // later than its inner one between the second and third knots.
  TempDir dir;
  const std::string csv = "z_m,outer_diameter_m,inner_diameter_m\n0,0.03,0\n0.4,0.03,0.0298\n0.5,0.06,0.0598\n0.84,0.06,0.0598\n";
  const Profile crossing{Interpolation::pchip, {0, 0.4, 0.5, 0.84}, {0.03, 0.03, 0.06, 0.06}, {0, 0.0298, 0.0598, 0.0598}};
  const ThinnestWall thinnest = thinnest_wall(crossing);
  REQUIRE(thinnest.wall < 0);
  // The minimum found is the curve's: no sample of a fine scan of the interval lies below it.
  for (int k = 0; k <= 10000; ++k) {
    const double z = 0.4 + 0.1 * k / 10000;
    CHECK(crossing.diameter(z) - crossing.diameter(z, true) >= thinnest.wall - 1e-15);
  }
  CHECK(thinnest.z > 0.4);
  CHECK(thinnest.z < 0.5);
  require_refused(write_bat(dir, "interpolation = \"pchip\"\n", csv),
                  {"profile.csv: lines 3-4", "pchip", "inner diameter reaches the outer", "expected a wall everywhere"});
  // Linear between the same knots keeps the wall the knots give.
  CHECK(load_bat(write_bat(dir, "interpolation = \"linear\"\n", csv)).slices() == 84);
  Profile kept = crossing;
  kept.interpolation = Interpolation::linear;
  CHECK(thinnest_wall(kept).wall == Approx(0.0002));
}

TEST_CASE("A comment after a profile row's values is a comment", "[profile][bat_file]") {
  TempDir plain, commented;
  const Bat a = load_bat(write_bat(plain, "", "z_m,outer_diameter_m\n0,0.05\n0.2,0.025\n0.84,0.065\n"));
  const Bat b = load_bat(write_bat(commented, "", "z_m,outer_diameter_m  # knots\n0,0.05 # knob\n0.2,0.025\t# handle\n0.84,0.065#end\n"));
  CHECK(a.outer_diameter == b.outer_diameter);
  CHECK(a.section_area == b.section_area);
}
