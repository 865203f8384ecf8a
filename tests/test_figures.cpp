// The N2000 figures (scripts/figures): each figure's claim of physics.md §6 checked on the numbers of the datasets it is drawn from (tests/check_figures.py),
// and the script end to end.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "program.hpp"
#include "temp_dir.hpp"

namespace {

const std::string bat = source_path("studies/bats/r161.toml");

// Checks a figure's claim on what `dir` holds.
void check_claim(const std::string& figure, const TempDir& dir) {
  const ProgramRun check = run_command(std::string(python) + " " + source_path("tests/check_figures.py") + " " +
                                       figure + " " + dir.path.string());
  INFO(check.output);
  CHECK(check.exit_code == 0);
}

// Runs the studies a figure is drawn from through the program, then checks its claim.
void check_figure(const std::string& figure, std::initializer_list<std::string> studies) {
  TempDir dir;
  for (const std::string& study : studies) {
    const ProgramRun run =
        run_program("run " + source_path("studies/" + study + ".toml") + " -o " + dir / (study + ".h5") + " --quiet");
    INFO(study << "\n" << run.output);
    REQUIRE(run.exit_code == 0);
  }
  check_claim(figure, dir);
}

bool is_png(const std::filesystem::path& file) {
  char signature[8] = {};
  std::ifstream(file, std::ios::binary).read(signature, sizeof signature);
  return std::string(signature, sizeof signature) == "\x89PNG\r\n\x1a\n";
}

}  // namespace

TEST_CASE("Fig. 3: collision times on a rigid wall within 5 % of N2000's", "[figures]") {
  check_figure("wall", {"wall"});
}

TEST_CASE("Fig. 6: mode shapes of unit amplitude whose zeros are the nodes of N2000", "[figures]") {
  TempDir dir;
  const ProgramRun modes = run_program("modes " + bat + " --json --shapes --count 3");
  INFO(modes.output);
  REQUIRE(modes.exit_code == 0);
  dir.write("modes.json", modes.output);
  check_claim("modes", dir);
}

TEST_CASE("Figs. 7-8, low impact: flexible and rigid peaks, only mode 1 vibrates, dissipation vs vibration",
          "[figures]") {
  check_figure("low_impact", {"low_impact"});
}

TEST_CASE("Figs. 10-11, high impact: Van Zandt near rigid at 60 cm, 18 modes 20 % below, modes 1-4 vibrate",
          "[figures]") {
  check_figure("high_impact", {"high_impact", "high_impact_energy"});
}

TEST_CASE("Fig. 12: e_eff over 60-80 cm slightly higher at half speed", "[figures]") {
  check_figure("e_eff", {"e_eff_full", "e_eff_half"});
}

TEST_CASE("Fig. 16: pivoted and free bats agree from 52 cm out (first contact from 48 cm)", "[figures]") {
  check_figure("pivot", {"pivot"});
}

TEST_CASE("Fig. 18: the toy model's limits 1/3 and 5/7, Van Zandt wrong between them", "[figures]") {
  check_figure("toy", {"toy"});
}

TEST_CASE("Fig. 4: one g(omega tau) for 1-70 m/s", "[figures]") { check_figure("force_profile", {"force_profile"}); }

TEST_CASE("Fig. 2: at 58 m/s on a rigid wall (e0 = 0.53) the F(u) loop's area is (1 - e0^2) of the energy",
          "[figures]") {
  check_figure("force_compression", {"force_compression"});
}

TEST_CASE("Fig. 9: at 6 and 16 cm a low impact at 72 cm shows modes 1 and 3, not 2", "[figures]") {
  check_figure("low_impact_histories", {"histories_low"});
}

TEST_CASE("Figs. 13-15: no rigid motion at 13 cm, the handle moves late, least vibration for 71 cm",
          "[figures]") {
  check_figure("handle", {"histories_handle"});
}

TEST_CASE("scripts/figures writes a PNG for every N2000 item it can draw", "[figures]") {
  TempDir dir;
  const ProgramRun run = run_command("SWEETSPOT=" + std::string(SWEETSPOT_PROGRAM) + " " +
                                     source_path("scripts/figures") + " " + dir / "out");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  for (const char* name : {"table2", "fig03_collision_time", "fig06_mode_shapes", "fig07_low_impact_vf",
                           "fig08_low_impact_energy", "fig10_high_impact_vf", "fig11_high_impact_energy",
                           "fig12_e_eff", "fig16_pivot", "fig18_toy", "fig02_force_compression",
                           "fig04_force_profile", "fig09_low_impact_acceleration", "fig13_handle_displacement",
                           "fig14_vibration_13cm", "fig15_handle_velocity"}) {
    const std::filesystem::path png = dir.path / "out" / (std::string(name) + ".png");
    INFO(png);
    REQUIRE(std::filesystem::exists(png));
    CHECK(std::filesystem::file_size(png) > 10000);  // a drawn figure, not an empty canvas
    CHECK(is_png(png));
  }
}

TEST_CASE("scripts/figures without the program says how to build it and fails", "[figures]") {
  TempDir dir;
  const ProgramRun run =
      run_command("SWEETSPOT=" + dir / "missing" + " " + source_path("scripts/figures") + " " + dir / "out");
  INFO(run.output);
  CHECK(run.exit_code != 0);
  CHECK_THAT(run.output, Catch::Contains("not found") && Catch::Contains("scripts/build"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "out"));
}
