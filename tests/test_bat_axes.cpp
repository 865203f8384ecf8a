// Bats as design spaces in studies: bat parameters as axes make one bat per combination, each
// built and checked before any work; what a designer reads of each bat follows the physics
// (mass in proportion to the density, frequencies as sqrt(E / rho)); impossible bats are refused
// naming the axis, the value and the rule; runs stay bitwise the same on any ranks and threads
// and resume to the uninterrupted dataset.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <string>

#include "program.hpp"
#include "study_dir.hpp"
#include "temp_dir.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/bat_properties.hpp"
#include "sweetspot/study/study.hpp"

using namespace sweetspot;

namespace {

// The high-impact swing on one bat file (copied beside the study), with `axes` as its [axes].
std::string design_study(const std::string& bat, const std::string& axes, const std::string& output = "") {
  return "[scene]\nbat = \"bats/" + bat + "\"\ncenter = 0.09\nomega = 51\nball_speed = 40\nmodes = 4\n[axes]\n" + axes +
         (output.empty() ? "" : "[output]\n" + output);
}

struct DesignDir : StudyDir {
  explicit DesignDir(const std::string& text) : StudyDir() {
    for (const char* file : {"maple_271.toml", "alloy_bbcor.toml"})
      std::filesystem::copy_file(source_path(std::string("studies/bats/") + file), dir.path / "bats" / file);
    study = dir.write("design.toml", text);
  }
};

std::string refusal(const std::string& text) { return study_refusal(DesignDir(text).study); }

}  // namespace

TEST_CASE("A bat-parameter axis makes one bat per value, in row-major order after the bat files", "[bat_axes]") {
  const DesignDir d(design_study("r161.toml",
                                 "\"bat.density\" = [500, 649, 800]\nbat = [\"bats/r161.toml\", \"bats/torpedo.toml\"]\n"
                                 "z = [0.6, 0.7]\n"));
  const Study study = load_study(d.study);
  REQUIRE(study.designs.size() == 6);
  REQUIRE(design_axes(study) == std::vector<std::size_t>{1, 0});  // the bat axis first, wherever written
  // The points of one (bat, density) share a design, and the grid's design is the one built.
  for (std::size_t i = 0; i < study.points(); ++i) {
    const GridPoint p = grid_point(study, i);
    CHECK(p.design == p.bat * 3 + p.coords[0]);
    CHECK(study.designs[p.design].material.density == study.axes[0].values[p.coords[0]]);
    CHECK(study.designs[p.design].name == study.bat_names[p.bat]);
  }
  // Tasks run model-major over bat and density: each design's points in one contiguous run.
  CHECK(models(study) == 6);
  const std::vector<std::size_t> order = task_order(study);
  std::set<std::size_t> finished;
  for (std::size_t t = 0; t < order.size(); ++t) {
    const std::size_t design = grid_point(study, order[t]).design;
    if (t > 0 && grid_point(study, order[t - 1]).design != design) finished.insert(grid_point(study, order[t - 1]).design);
    CHECK(finished.count(design) == 0);
  }
  CHECK(finished.size() == 5);
}

TEST_CASE("A bat's mass goes as its density and its frequencies as sqrt(E / rho)", "[bat_axes]") {
  // Geometry fixed, K scales with the moduli and M with the density: omega^2 = (E / rho) x const.
  const DesignDir d(design_study("r161.toml",
                                 "\"bat.density\" = [500, 649, 800]\n\"bat.youngs_modulus\" = [1.2e10, 1.814e10]\n"
                                 "z = [0.6, 0.7]\n"));
  Study study = load_study(d.study);
  REQUIRE(study.designs.size() == 6);
  const DesignModes modes = design_modes(study, 4);
  const double mass_per_density = study.design_mass[0].mass / 500;
  for (std::size_t b = 0; b < 6; ++b) {
    const Material& m = study.designs[b].material;
    CHECK(study.design_mass[b].mass / m.density == Approx(mass_per_density).epsilon(1e-14));
    CHECK(study.design_mass[b].z_cm == Approx(study.design_mass[0].z_cm).epsilon(1e-14));
  }
  // Young's modulus alone moves bending, not shear: compare designs of one modulus across densities.
  for (std::size_t b = 0; b < 6; ++b)
    for (int n = 0; n < 4; ++n) {
      const std::size_t same_modulus = b % 2;  // density-major: designs 0, 2, 4 share E, and 1, 3, 5
      const double ratio = std::sqrt(study.designs[same_modulus].material.density / study.designs[b].material.density);
      CHECK(modes.frequencies_hz[b][n] == Approx(modes.frequencies_hz[same_modulus][n] * ratio).epsilon(1e-10));
    }
  // A bat's mass properties are R161's of physics.md §2 at its own density.
  CHECK(study.design_mass[2].mass == Approx(0.869).epsilon(1e-3));
  CHECK(study.design_mass[2].z_cm == Approx(0.561).epsilon(1e-3));
}

TEST_CASE("The drop is the length in inches less the weight in ounces", "[bat_axes]") {
  CHECK(bat_drop(33 * 0.0254, 30 * 0.028349523125) == Approx(3).epsilon(1e-12));
  CHECK(std::abs(bat_drop(34 * 0.0254, 34 * 0.028349523125)) < 1e-12);  // a 34-in, 34-oz bat: drop 0
  CHECK(bat_drop(32 * 0.0254, 31 * 0.028349523125) == Approx(1).epsilon(1e-12));  // a "-1" bat
}

TEST_CASE("An impossible bat is refused before any work, naming the axis, the value and the rule", "[bat_axes]") {
  SECTION("barrel thinner than the handle") {
    const std::string e = refusal(design_study("maple_271.toml", "\"bat.barrel_diameter\" = [0.066, 0.02]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("key 'axes.bat.barrel_diameter' = 0.02") && Catch::Contains("handle_diameter") &&
                      Catch::Contains("impossible bat"));
  }
  SECTION("taper outside the length") {
    const std::string e = refusal(design_study("maple_271.toml", "\"bat.taper_end\" = [0.5, 0.9]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("key 'axes.bat.taper_end' = 0.9") && Catch::Contains("taper_end"));
  }
  SECTION("a length that puts the taper beyond the bat's end") {
    const std::string e = refusal(design_study("maple_271.toml", "\"bat.length\" = [0.84, 0.3]\nz = [0.25]\n"));
    CHECK_THAT(e, Catch::Contains("axes.bat.") && Catch::Contains("0.3") && Catch::Contains("impossible bat"));
  }
  SECTION("a wall as thick as the radius") {
    const std::string e =
        refusal(design_study("alloy_bbcor.toml", "\"bat.wall_thickness\" = [0.003, 0.0125]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("key 'axes.bat.wall_thickness' = 0.0125") && Catch::Contains("radius"));
  }
  SECTION("a wall of 0 (a solid bat has none)") {
    const std::string e = refusal(design_study("alloy_bbcor.toml", "\"bat.wall_thickness\" = [0.003, 0]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("axes.bat.wall_thickness") && Catch::Contains("expected a positive, finite value"));
  }
  SECTION("a dimension of a bat given by its profile") {
    const std::string e = refusal(design_study("r161.toml", "\"bat.barrel_diameter\" = [0.06]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("key 'axes.bat.barrel_diameter' = 0.06") && Catch::Contains("R161"));
  }
  SECTION("the length of a bat given by one diameter per slice") {
    const std::string e = refusal(design_study("r161.toml", "\"bat.length\" = [0.84, 0.86]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("key 'axes.bat.length'") && Catch::Contains("slice"));
  }
  SECTION("a negative density") {
    const std::string e = refusal(design_study("r161.toml", "\"bat.density\" = [649, -1]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("key 'axes.bat.density' = -1"));
  }
  SECTION("an unknown wood") {
    const std::string e = refusal(design_study("maple_271.toml", "\"bat.material\" = [\"maple\", \"oak\"]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("key 'axes.bat.material[1]' = \"oak\"") && Catch::Contains("\"maple\""));
  }
  SECTION("an unquoted bat parameter, which TOML reads as a table") {
    const std::string e = refusal(design_study("maple_271.toml", "bat.density = [600, 700]\nz = [0.6]\n"));
    CHECK_THAT(e, Catch::Contains("quoted key"));
  }
  SECTION("z beyond the shortest bat of a length axis") {
    const std::string e = refusal(design_study("maple_271.toml", "\"bat.length\" = [0.84, 0.80]\nz = [0.82]\n"));
    CHECK_THAT(e, Catch::Contains("key 'axes.z") && Catch::Contains("0.82") && Catch::Contains("bat.length = 0.8"));
  }
}

TEST_CASE("Through the program an impossible bat is one line, exit 2, and no output is written", "[bat_axes]") {
  const DesignDir d(design_study("maple_271.toml", "\"bat.barrel_diameter\" = [0.066, 0.02]\nz = [0.6]\n"));
  const auto before = d.snapshot();
  const ProgramRun run = run_program("run " + d.study.string() + " -o " + d / "out.h5");
  require_refused(run, "axes.bat.barrel_diameter");
  CHECK(d.snapshot() == before);
}

namespace {

void require_identical(const std::string& a, const std::string& b) {
  const ProgramRun compare =
      run_command(std::string(python) + " " + source_path("tests/compare_datasets.py") + " " + a + " " + b);
  INFO(compare.output);
  REQUIRE(compare.exit_code == 0);
}

// 3 woods x 3 barrels of the maple 271 (9 bats) and the R161 at 3 densities (3 bats).
constexpr const char* design_axes_text =
    "\"bat.material\" = [\"maple\", \"ash\", \"birch\"]\n\"bat.barrel_diameter\" = [0.0610, 0.0635, 0.0660]\n";

}  // namespace

TEST_CASE("A design study gives the same dataset bit for bit on any ranks and threads", "[bat_axes][mpi]") {
  const DesignDir d(design_study("maple_271.toml", std::string(design_axes_text) +
                                                       "z = { start = 0.55, stop = 0.80, count = 6 }\n",
                                 "variables = [\"vf\", \"sweet_spot_z\", \"sweet_spot_width\", \"status\"]\n"));
  const ProgramRun serial = run_program("run " + d.study.string() + " -o " + d / "serial.h5 --quiet");
  INFO(serial.output);
  REQUIRE(serial.exit_code == 0);
  for (const auto& [ranks, threads] : {std::pair{1, 2}, {2, 1}, {3, 1}}) {
    const std::string out = d / std::to_string(10 * ranks + threads).append(".h5");
    const ProgramRun run = run_program_mpi(ranks, threads, "run " + d.study.string() + " -o " + out);
    INFO(ranks << " ranks x " << threads << " threads\n" << run.output);
    REQUIRE(run.exit_code == 0);
    require_identical(d / "serial.h5", out);
  }
}

TEST_CASE("A design study killed with SIGKILL resumes to the dataset of an uninterrupted run", "[bat_axes]") {
  const DesignDir d(design_study("maple_271.toml", std::string(design_axes_text) +
                                                       "z = { start = 0.55, stop = 0.80, count = 200 }\n"
                                                       "ball_speed = [30, 35, 40, 45]\n",
                                 "variables = [\"vf\", \"sweet_spot_z\", \"status\"]\n"));
  REQUIRE(run_program("run " + d.study.string() + " -o " + d / "whole.h5 --quiet").exit_code == 0);
  const std::string out = d / "killed.h5";
  const ProgramRun killed =
      run_and_kill(std::string(SWEETSPOT_PROGRAM), "run " + d.study.string() + " -o " + out + " --quiet", out);
  INFO(killed.output);
  REQUIRE_THAT(killed.output, Catch::Contains("killed 137"));
  const ProgramRun resumed = run_program("run " + d.study.string() + " -o " + out + " --resume");
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  CHECK_THAT(resumed.output, Catch::Contains("resuming:"));
  require_identical(d / "whole.h5", out);
}

TEST_CASE("A design dataset holds each bat's mass, drop, balance, swing weight and modes over its dimensions",
          "[bat_axes]") {
  const DesignDir d(design_study("maple_271.toml", std::string(design_axes_text) +
                                                       "z = { start = 0.55, stop = 0.80, count = 6 }\n",
                                 "variables = [\"sweet_spot_z\", \"sweet_spot_vf\", \"sweet_spot_width\"]\n"));
  const std::string out = d / "out.h5";
  const ProgramRun run = run_program("run " + d.study.string() + " -o " + out + " --quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun check =
      run_command(std::string(python) + " " + source_path("tests/check_design_dataset.py") + " " + out);
  INFO(check.output);
  CHECK(check.exit_code == 0);
  CHECK_THAT(check.output, Catch::Contains("design dataset ok"));
}

TEST_CASE("The sweet spot does not depend on the order a study writes z in", "[bat_axes]") {
  const std::string z = "[0.60, 0.62, 0.64, 0.66, 0.68, 0.70, 0.72, 0.74, 0.76, 0.78]";
  const DesignDir up(design_study("r161.toml", "\"bat.density\" = [600, 700]\nz = " + z + "\n",
                                  "variables = [\"sweet_spot_z\", \"sweet_spot_width\"]\n"));
  const auto down = up.dir.write("down.toml", design_study("r161.toml",
                                                           "\"bat.density\" = [600, 700]\nz = [0.78, 0.76, 0.74, 0.72, "
                                                           "0.70, 0.68, 0.66, 0.64, 0.62, 0.60]\n",
                                                           "variables = [\"sweet_spot_z\", \"sweet_spot_width\"]\n"));
  REQUIRE(run_program("run " + up.study.string() + " -o " + up / "up.h5 --quiet").exit_code == 0);
  REQUIRE(run_program("run " + down.string() + " -o " + up / "down.h5 --quiet").exit_code == 0);
  const ProgramRun check = run_command(
      std::string(python) + " -c \"import xarray as xr, numpy as np; a = xr.open_dataset('" + up / "up.h5" +
      "', engine='h5netcdf'); b = xr.open_dataset('" + up / "down.h5" +
      "', engine='h5netcdf'); assert np.isfinite(a.sweet_spot_width).all(); "
      "assert (a.sweet_spot_z.values == b.sweet_spot_z.values).all() and "
      "(a.sweet_spot_width.values == b.sweet_spot_width.values).all(); print('same')\"");
  INFO(check.output);
  CHECK(check.output == "same\n");
}

TEST_CASE("Bat-parameter axes are CF names with their own long names and units, and bat.length is bat_length",
          "[bat_axes]") {
  // Two bat files, so a bat dimension, beside a length, a loss factor and a modulus.
  const DesignDir d(design_study("maple_271.toml",
                                 "bat = [\"bats/maple_271.toml\", \"bats/alloy_bbcor.toml\"]\n"
                                 "\"bat.length\" = [0.83, 0.84]\n\"bat.loss_factor\" = [0.001, 0.002]\n"
                                 "\"bat.youngs_modulus\" = [1.2e10, 1.4e10]\nz = [0.6, 0.65]\n"));
  const std::string out = d / "out.h5";
  const ProgramRun run = run_program("run " + d.study.string() + " -o " + out + " --quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun check = run_command(
      std::string(python) + " -c \"import xarray as xr; ds = xr.open_dataset('" + out + "', engine='h5netcdf'); "
      "assert ds.vf.dims == ('bat', 'bat_length', 'bat_loss_factor', 'bat_youngs_modulus', 'z'), ds.vf.dims; "
      "assert ds.bat_length.attrs == {'units': 'm', 'long_name': 'bat length'}, ds.bat_length.attrs; "
      "assert ds.bat_loss_factor.attrs == {'units': '1', 'long_name': 'bat loss factor'}, ds.bat_loss_factor.attrs; "
      "assert ds.bat_youngs_modulus.attrs['units'] == 'Pa', ds.bat_youngs_modulus.attrs; "
      "assert 'bat_length' in ds.coords and ds.bat_mass.dims == ('bat', 'bat_length', 'bat_loss_factor', "
      "'bat_youngs_modulus'), ds.bat_mass.dims; "
      "assert ds.bat_toml.dims == ('bat',) and 'bat.length' in ds.attrs['study'], ds.attrs['study']; "
      "assert ds.vf.sel(bat_length=0.84, bat='maple 271').dims == ('bat_loss_factor', 'bat_youngs_modulus', 'z'); "
      "print('ok')\"");
  INFO(check.output);
  CHECK(check.output == "ok\n");
}
