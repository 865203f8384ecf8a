// Bat files: the shipped bats load with the mass properties physics.md §2 quotes, and every kind
// of bad file fails with one InputError line naming the file, the key or line, and the value.
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <catch2/catch.hpp>

#include "program.hpp"
#include "temp_dir.hpp"
#include "text_edit.hpp"
#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/input_error.hpp"

namespace fs = std::filesystem;
using sweetspot::InputError;
using sweetspot::load_bat;

namespace {

const fs::path bats_dir = fs::path(SWEETSPOT_SOURCE_DIR) / "studies" / "bats";

// A small valid bat: 3 slices of 0.1 m. Bad files are this with one line changed.
constexpr std::string_view good_toml =
    "name = \"test\"\n"
    "length = 0.3\n"
    "profile = \"profile.csv\"\n"
    "[material]\n"
    "density = 649\n"
    "youngs_modulus = 1.8e10\n"
    "shear_modulus = 1.0e9\n";

constexpr std::string_view good_csv =
    "# a comment, then a blank line\n"
    "\n"
    "slice,z_center_m,outer_diameter_m\n"
    "1,0.05,0.030\n"
    "2,0.15,0.050\n"
    "3,0.25,0.060\n";

// A fresh directory holding bat.toml and profile.csv, removed afterwards.
struct BatDir : TempDir {
  fs::path toml, csv;

  explicit BatDir(std::string_view toml_text = good_toml, std::string_view csv_text = good_csv)
      : toml(write("bat.toml", toml_text)), csv(write("profile.csv", csv_text)) {}
};

// The program must refuse the bat with exit status 2 and the same one-line message.
void require_program_error(const fs::path& toml, const std::vector<std::string_view>& fragments) {
  const ProgramRun run = run_program("modes '" + toml.string() + "'");
  INFO("program output: " << run.output);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::StartsWith("sweetspot: error: "));
  for (const std::string_view fragment : fragments) CHECK_THAT(run.output, Catch::Contains(std::string(fragment)));
}

// load_bat must throw an InputError whose single-line message contains every fragment, and the
// program must exit with status 2 printing it.
void require_input_error(const fs::path& toml, const std::vector<std::string_view>& fragments) {
  require_program_error(toml, fragments);
  try {
    load_bat(toml);
  } catch (const InputError& e) {
    const std::string message = e.what();
    INFO("message: " << message);
    CHECK(message.find('\n') == std::string::npos);
    for (const std::string_view fragment : fragments)
      CHECK_THAT(message, Catch::Contains(std::string(fragment)));
    return;
  }
  FAIL("load_bat(" << toml << ") did not throw InputError");
}

void require_toml_error(std::string_view from, std::string_view to,
                        std::initializer_list<std::string_view> fragments) {
  const BatDir bat(with(good_toml, from, to));
  require_input_error(bat.toml, fragments);
}

void require_csv_error(std::string_view from, std::string_view to,
                       std::initializer_list<std::string_view> fragments) {
  const BatDir bat(good_toml, with(good_csv, from, to));
  require_input_error(bat.toml, fragments);
}

}  // namespace

// ---- Good files -------------------------------------------------------------------------------

TEST_CASE("the shipped R161 bat loads with the material of physics.md §2", "[bat_file]") {
  const sweetspot::Bat bat = load_bat(bats_dir / "r161.toml");
  CHECK(bat.name == "R161");
  CHECK(bat.length == 0.84);
  CHECK(bat.slices() == 84);
  CHECK_FALSE(bat.hollow());
  CHECK(bat.material.density == 649);
  CHECK(bat.material.youngs_modulus == 1.814e10);
  CHECK(bat.material.shear_modulus == 1.05e9);
  CHECK(bat.material.shear_coefficient == 1);
  CHECK(bat.outer_diameter.front() == 0.0505);
  CHECK(bat.outer_diameter.back() == 0.0643);
}

TEST_CASE("the R161 profile gives the mass properties physics.md §2 quotes", "[bat_file]") {
  const auto p = sweetspot::mass_properties(load_bat(bats_dir / "r161.toml"));
  CHECK(p.mass == Approx(0.869).epsilon(0.005));
  CHECK(p.z_cm == Approx(0.561).epsilon(0.005));
  CHECK(p.radius_of_gyration() == Approx(0.229).epsilon(0.005));
}

TEST_CASE("halving the R161 slices keeps its mass and centre of mass", "[bat_file]") {
  const sweetspot::Bat bat = load_bat(bats_dir / "r161.toml");
  const sweetspot::Bat fine = sweetspot::resample(bat, 2 * bat.slices());
  REQUIRE(fine.slices() == 168);
  const auto p = sweetspot::mass_properties(bat);
  const auto q = sweetspot::mass_properties(fine);
  CHECK(q.mass == Approx(p.mass).epsilon(1e-12));
  CHECK(q.z_cm == Approx(p.z_cm).epsilon(1e-12));
}

TEST_CASE("resampling to any slice count keeps the mass exactly (A and I averaged, not diameters)", "[bat_file]") {
  // Averaging the diameters instead made R161 at 100 slices 0.869092 kg instead of 0.869359.
  for (const char* file : {"r161.toml", "torpedo.toml", "aluminium.toml"}) {
    const sweetspot::Bat bat = load_bat(bats_dir / file);
    const double mass = sweetspot::mass_properties(bat).mass;
    for (int n : {5, 37, 100, 123, 1000}) {
      const sweetspot::Bat cut = sweetspot::resample(bat, n);
      REQUIRE(cut.slices() == n);
      INFO(file << " at " << n << " slices");
      CHECK(sweetspot::mass_properties(cut).mass == Approx(mass).epsilon(1e-12));
      // I too is the mean over each new slice: its integral along the bat is kept.
      double inertia = 0, cut_inertia = 0;
      for (int i = 0; i < bat.slices(); ++i) inertia += bat.second_moment(i) * bat.slice_thickness();
      for (int i = 0; i < n; ++i) cut_inertia += cut.second_moment(i) * cut.slice_thickness();
      CHECK(cut_inertia == Approx(inertia).epsilon(1e-12));
    }
  }
}

TEST_CASE("the shipped torpedo bat loads", "[bat_file]") {
  const sweetspot::Bat bat = load_bat(bats_dir / "torpedo.toml");
  CHECK(bat.name == "torpedo");
  CHECK(bat.length == 0.85);
  CHECK(bat.slices() == 85);
  CHECK(bat.material.density == 690);
  CHECK(bat.material.youngs_modulus == 1.65e10);
  CHECK(bat.material.shear_modulus == 9.0e8);
}

TEST_CASE("a minimal bat file: integer length, no slice column, BOM, CRLF, default kappa",
          "[bat_file]") {
  const BatDir dir(with(good_toml, "length = 0.3", "length = 1"),
                   "\xEF\xBB\xBFz_center_m,outer_diameter_m\r\n0.125,0.03\r\n0.375,0.05\r\n0.625,0.05\r\n"
                   "0.875,0.04\r\n");
  const sweetspot::Bat bat = load_bat(dir.toml);
  CHECK(bat.length == 1.0);
  CHECK(bat.outer_diameter == std::vector{0.03, 0.05, 0.05, 0.04});
  CHECK(bat.material.shear_coefficient == 1);
}

TEST_CASE("a hollow bat with a shear coefficient", "[bat_file]") {
  const BatDir dir(with(good_toml, "length = 0.3", "length = 0.4") + "shear_coefficient = 0.9\n",
                   "slice, z_center_m, outer_diameter_m, inner_diameter_m\n"
                   "1, 0.05, 0.03, 0\n2, 0.15, 0.05, 0.04\n3, 0.25, 0.06, 0.05\n4, 0.35, 0.06, 0.05\n");
  const sweetspot::Bat bat = load_bat(dir.toml);
  REQUIRE(bat.hollow());
  CHECK(bat.inner_diameter == std::vector{0.0, 0.04, 0.05, 0.05});
  CHECK(bat.material.shear_coefficient == 0.9);
}

// ---- Bad files: files that cannot be read ------------------------------------------------------

TEST_CASE("bat file: missing TOML file", "[bat_file]") {
  const BatDir dir;
  require_input_error(dir.path / "nope.toml", {"nope.toml", "not found"});
}

TEST_CASE("bat file: TOML path is a directory", "[bat_file]") {
  const BatDir dir;
  require_input_error(dir.path, {dir.path.string(), "not a regular file"});
}

TEST_CASE("bat file: missing profile CSV", "[bat_file]") {
  require_toml_error("profile.csv", "missing.csv",
                     {"missing.csv", "not found", "key 'profile'", "bat.toml"});
}

TEST_CASE("bat file: TOML syntax error", "[bat_file]") {
  require_toml_error("length = 0.3", "length = = 0.3", {"bat.toml:2:", "TOML syntax error"});
}

// ---- Bad files: keys --------------------------------------------------------------------------

TEST_CASE("bat file: missing key", "[bat_file]") {
  SECTION("name") {
    require_toml_error("name = \"test\"\n", "", {"bat.toml", "key 'name'", "missing"});
  }
  SECTION("length") {
    require_toml_error("length = 0.3\n", "", {"bat.toml", "key 'length'", "missing"});
  }
  SECTION("profile") {
    require_toml_error("profile = \"profile.csv\"\n", "", {"bat.toml", "key 'profile'", "missing"});
  }
  SECTION("material") {
    const std::string material(good_toml.substr(good_toml.find("[material]")));
    require_toml_error(material, "", {"bat.toml", "key 'material'", "missing"});
  }
  SECTION("material.density") {
    require_toml_error("density = 649\n", "", {"bat.toml", "key 'material.density'", "missing"});
  }
  SECTION("material.youngs_modulus") {
    require_toml_error("youngs_modulus = 1.8e10\n", "",
                       {"bat.toml", "key 'material.youngs_modulus'", "missing"});
  }
  SECTION("material.shear_modulus") {
    require_toml_error("shear_modulus = 1.0e9\n", "",
                       {"bat.toml", "key 'material.shear_modulus'", "missing"});
  }
}

TEST_CASE("bat file: unknown key", "[bat_file]") {
  SECTION("top level") {
    require_toml_error("length = 0.3", "lenght = 0.3",
                       {"bat.toml", "key 'lenght'", "unknown", "0.3"});
  }
  SECTION("in [material]") {
    require_toml_error("density = 649", "density = 649\npoisson_ratio = 0.3",
                       {"bat.toml", "key 'material.poisson_ratio'", "unknown", "0.3"});
  }
}

TEST_CASE("bat file: wrong type", "[bat_file]") {
  SECTION("string for length") {
    require_toml_error("length = 0.3", "length = \"long\"",
                       {"bat.toml", "key 'length'", "long", "string"});
  }
  SECTION("boolean for density") {
    require_toml_error("density = 649", "density = true",
                       {"key 'material.density'", "true", "boolean"});
  }
  SECTION("number for name") {
    require_toml_error("name = \"test\"", "name = 3", {"key 'name'", "3", "non-empty string"});
  }
  SECTION("empty name") {
    require_toml_error("name = \"test\"", "name = \"\"", {"key 'name'", "non-empty string"});
  }
  SECTION("a NUL character in the name") {  // a dataset could not store it (h5py refused it late)
    require_toml_error("name = \"test\"", "name = \"a\\u0000b\"", {"key 'name'", "without NUL characters"});
  }
  SECTION("number for profile") {
    require_toml_error("profile = \"profile.csv\"", "profile = 3",
                       {"key 'profile'", "3", "string"});
  }
  SECTION("number for material") {
    const std::string material(good_toml.substr(good_toml.find("[material]")));
    require_toml_error(material, "material = 3", {"key 'material'", "3", "must be a table"});
  }
}

TEST_CASE("bat file: non-positive length or material constant", "[bat_file]") {
  SECTION("length") {
    require_toml_error("length = 0.3", "length = 0",
                       {"bat.toml", "key 'length'", "value 0 ", "positive"});
  }
  SECTION("density") {
    require_toml_error(
        "density = 649", "density = -3",
        {"bat.toml:5: key 'material.density': value -3 must be a positive number (kg/m^3)"});
  }
  SECTION("youngs_modulus") {
    require_toml_error("youngs_modulus = 1.8e10", "youngs_modulus = -1.8e10",
                       {"key 'material.youngs_modulus'", "-1.8", "positive"});
  }
  SECTION("shear_modulus") {
    require_toml_error("shear_modulus = 1.0e9", "shear_modulus = 0.0",
                       {"key 'material.shear_modulus'", "value 0 ", "positive"});
  }
  SECTION("shear_coefficient") {
    require_toml_error("density = 649", "density = 649\nshear_coefficient = -0.5",
                       {"key 'material.shear_coefficient'", "-0.5", "positive"});
  }
}

TEST_CASE("bat file: NaN or infinity in the TOML file", "[bat_file]") {
  SECTION("length = nan") {
    require_toml_error("length = 0.3", "length = nan", {"key 'length'", "nan", "finite"});
  }
  SECTION("density = inf") {
    require_toml_error("density = 649", "density = inf",
                       {"key 'material.density'", "inf", "finite"});
  }
  SECTION("shear_modulus = -inf") {
    require_toml_error("shear_modulus = 1.0e9", "shear_modulus = -inf",
                       {"key 'material.shear_modulus'", "-inf", "finite"});
  }
}

// ---- Bad files: the profile CSV ---------------------------------------------------------------

TEST_CASE("bat file: NaN or infinity in the profile", "[bat_file]") {
  SECTION("z") {
    require_csv_error("2,0.15,", "2,nan,", {"profile.csv:5", "z_center_m", "nan", "finite"});
  }
  SECTION("diameter") {
    require_csv_error("0.050", "inf", {"profile.csv:5", "outer_diameter_m", "inf", "finite"});
  }
}

TEST_CASE("bat file: profile row with the wrong number of fields", "[bat_file]") {
  SECTION("too few") {
    require_csv_error("2,0.15,0.050", "2,0.15", {"profile.csv:5", "2 fields", "2,0.15"});
  }
  SECTION("too many") {
    require_csv_error("2,0.15,0.050", "2,0.15,0.050,",
                      {"profile.csv:5", "4 fields", "2,0.15,0.050,"});
  }
}

TEST_CASE("bat file: profile field that is not a number", "[bat_file]") {
  require_csv_error("0.050", "0.05o",
                    {"profile.csv:5", "outer_diameter_m", "0.05o", "not a number"});
}

TEST_CASE("bat file: a profile that is not UTF-8 text, which a dataset could not store", "[bat_file]") {
  require_csv_error("# a comment", "# a caf\xE9 comment", {"profile.csv:1", "byte 0xE9", "UTF-8"});
  require_csv_error("1,0.05,0.030", "1,0.05,0.030\xC3", {"profile.csv:4", "byte 0xC3", "UTF-8"});  // cut short
  require_csv_error("# a comment", std::string_view("# a\0comment", 12), {"profile.csv:1", "byte 0x00"});
  const BatDir bat(with(good_toml, "length = 0.3", "length = 0.4"),  // UTF-8 is fine
                   with(good_csv, "# a comment", "# a café comment ω") + "4,0.35,0.060\n");
  CHECK(load_bat(bat.toml).slices() == 4);
}

TEST_CASE("bat file: profile header with a wrong column", "[bat_file]") {
  SECTION("unknown") {
    require_csv_error("outer_diameter_m", "diameter_m",
                      {"profile.csv:3", "unknown column 'diameter_m'"});
  }
  SECTION("duplicate") {
    require_csv_error("slice,z_center_m,outer_diameter_m", "slice,z_center_m,slice",
                      {"profile.csv:3", "'slice'", "twice"});
  }
  SECTION("required column absent") {
    const BatDir dir(good_toml, "slice,z_center_m\n1,0.05\n2,0.15\n3,0.25\n");
    require_input_error(dir.toml, {"profile.csv:1", "outer_diameter_m"});
  }
}

TEST_CASE("bat file: zero or negative diameter", "[bat_file]") {
  SECTION("zero") {
    require_csv_error("0.050", "0", {"profile.csv:5: outer_diameter_m = 0 must be positive"});
  }
  SECTION("negative") {
    require_csv_error("0.050", "-0.05", {"profile.csv:5", "outer_diameter_m = -0.05", "positive"});
  }
}

TEST_CASE("bat file: bad inner diameter", "[bat_file]") {
  const std::string hollow =
      "z_center_m,outer_diameter_m,inner_diameter_m\n0.05,0.03,0\n0.15,0.05,0.04\n0.25,0.06,0.05\n";
  SECTION("inner >= outer") {
    const BatDir dir(good_toml, with(hollow, "0.05,0.04", "0.05,0.05"));
    require_input_error(dir.toml, {"profile.csv:3", "inner_diameter_m = 0.05", "less than",
                                   "outer_diameter_m = 0.05"});
  }
  SECTION("inner < 0") {
    const BatDir dir(good_toml, with(hollow, "0.03,0", "0.03,-0.01"));
    require_input_error(dir.toml, {"profile.csv:2", "inner_diameter_m = -0.01", "negative"});
  }
}

TEST_CASE("bat file: profile not sorted by z", "[bat_file]") {
  require_csv_error("3,0.25", "3,0.10", {"profile.csv:6", "z_center_m = 0.10", "0.15", "sorted"});
}

TEST_CASE("bat file: profile unevenly spaced", "[bat_file]") {
  require_csv_error("2,0.15", "2,0.16", {"profile.csv:5", "z_center_m = 0.16", "even spacing"});
}

TEST_CASE("bat file: profile does not span the length", "[bat_file]") {
  SECTION("bat longer than the profile") {
    require_toml_error("length = 0.3", "length = 0.4",
                       {"profile.csv", "0.05 to 0.25", "0.4 m", "3 slices"});
  }
  SECTION("evenly spaced but shifted") {
    const BatDir dir(good_toml, "z_center_m,outer_diameter_m\n0.04,0.03\n0.14,0.05\n0.24,0.06\n");
    require_input_error(dir.toml, {"profile.csv", "0.04 to 0.24", "0.05 to 0.25"});
  }
}

TEST_CASE("bat file: empty profile", "[bat_file]") {
  SECTION("header only") {
    const BatDir dir(good_toml, "# nothing yet\nslice,z_center_m,outer_diameter_m\n");
    require_input_error(dir.toml, {"profile.csv", "no rows"});
  }
  SECTION("no header either") {
    const BatDir dir(good_toml, "");
    require_input_error(dir.toml, {"profile.csv", "no header"});
  }
}

// ---- Bats of named dimensions and wood presets --------------------------------------------------

namespace {

// A small valid parametric bat; bad files are this with one line changed.
constexpr std::string_view dimensions_toml =
    "name = \"parametric\"\n"
    "length = 0.84\n"
    "[material]\n"
    "preset = \"maple\"\n"
    "[dimensions]\n"
    "knob_diameter = 0.05\n"
    "knob_length = 0.02\n"
    "handle_diameter = 0.025\n"
    "taper_start = 0.3\n"
    "taper_end = 0.6\n"
    "barrel_diameter = 0.064\n";

void require_dimensions_error(std::string_view from, std::string_view to,
                              const std::vector<std::string_view>& fragments) {
  const BatDir bat(with(dimensions_toml, from, to));
  require_input_error(bat.toml, fragments);
}

}  // namespace

TEST_CASE("bat file: named dimensions and a preset make a bat, constants overriding the preset", "[bat_file]") {
  const BatDir dir(with(dimensions_toml, "preset = \"maple\"", "preset = \"maple\"\ndensity = 650"));
  sweetspot::BatSource source;
  const sweetspot::BatDesign design = sweetspot::load_bat_design(dir.toml, source);
  CHECK(design.material_name == "maple");
  CHECK(design.material.density == 650);
  CHECK(design.material.youngs_modulus == Approx(1.1 * 12.6e9));  // maple's, FPL-GTR-190
  CHECK(source.profile_file.empty());
  CHECK(source.profile_text.empty());
  CHECK(load_bat(dir.toml).slices() == 84);
}

TEST_CASE("bat file: bad named dimensions, a shape given twice or not at all", "[bat_file]") {
  const struct {
    const char* what;
    std::string_view from, to;
    std::vector<std::string_view> fragments;
  } cases[] = {
      {"unknown dimension", "barrel_diameter", "barel_diameter",
       {"bat.toml", "key 'dimensions.barel_diameter'", "unknown", "0.064", "barrel_diameter"}},
      {"missing dimension", "taper_end = 0.6\n", "", {"bat.toml", "key 'dimensions.taper_end'", "missing"}},
      {"unknown end shape", "taper_end = 0.6", "taper_end = 0.6\nend = \"conical\"",
       {"bat.toml", "key 'dimensions.end'", "conical", "'flat', 'rounded' or 'cupped'"}},
      {"an impossible bat", "barrel_diameter = 0.064", "barrel_diameter = 0.02",
       {"bat.toml", "key 'dimensions.barrel_diameter'", "barrel_diameter 0.02 m", "less than handle_diameter 0.025 m"}},
      {"a negative wall", "taper_end = 0.6", "taper_end = 0.6\nwall_thickness = -0.002",
       {"bat.toml", "key 'dimensions.wall_thickness'", "-0.002", "positive"}},
      {"an interpolation other than the frustums'", "length = 0.84", "length = 0.84\ninterpolation = \"pchip\"",
       {"bat.toml", "key 'interpolation'", "pchip", "[dimensions]"}},
      {"both profile and [dimensions]", "length = 0.84", "length = 0.84\nprofile = \"profile.csv\"",
       {"bat.toml", "key 'dimensions'", "key 'profile'", "one shape"}},
      {"neither profile nor [dimensions]", dimensions_toml.substr(dimensions_toml.find("[dimensions]")), "",
       {"bat.toml", "key 'profile'", "missing", "[dimensions]"}},
  };
  for (const auto& c : cases) {
    DYNAMIC_SECTION(c.what) { require_dimensions_error(c.from, c.to, c.fragments); }
  }
}

TEST_CASE("bat file: an unknown wood preset", "[bat_file]") {
  require_dimensions_error("preset = \"maple\"", "preset = \"oak\"",
                           {"bat.toml", "key 'material.preset'", "oak", "maple, ash, birch"});
}
