// A study's dataset explains itself (README, "The dataset"): tests/check_provenance.py reads it
// with xarray and checks the CF attributes, the integer axes, the bats' texts, the resolved
// scene, the commit and the resume attributes; here are the runs that make it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "program.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

// Two bats (the torpedo, and R161 copied beside the study with a denser wood) over integer axes
// with the words all and auto, pivot, and z_count impact points.
std::string provenance_study(int z_count) {
  std::ostringstream s;
  s << "title = \"provenance\"\n[scene]\ncenter = 0.09\nomega = 51\nball_speed = 40\ne0 = 0.45\n"
    << "[axes]\nbat = [\"dense_r161.toml\", \"" << source_path("studies/bats/torpedo.toml") << "\"]\n"
    << "slices = [20, 40]\nmodes = [0, 2, \"all\", \"auto\"]\npivot = [false, true]\n"
    << "z = { start = 0.60, stop = 0.70, count = " << z_count << " }\n";
  return s.str();
}

std::vector<std::string> provenance_bats(const TempDir& dir) {
  return {dir / "dense_r161.toml", source_path("studies/bats/torpedo.toml")};
}

void write_dense_r161(const TempDir& dir, int density = 800) {
  if (!fs::exists(dir.path / "r161_profile.csv"))
    fs::copy_file(source_path("studies/bats/r161_profile.csv"), dir.path / "r161_profile.csv");
  std::ostringstream text;
  text << "# R161 of a denser wood: its text, not only its results, must differ in the dataset\n"
       << "name = \"dense R161\"\nlength = 0.84\nprofile = \"r161_profile.csv\"\n"
       << "[material]\ndensity = " << density << "\nyoungs_modulus = 1.814e10\nshear_modulus = 1.05e9\n";
  dir.write("dense_r161.toml", text.str());
}

// Runs the study and kills it with SIGKILL as soon as its journal holds some finished points,
// well before the end.
void kill_midway(const fs::path& study, const std::string& out) {
  const ProgramRun killed = run_and_kill(std::string(SWEETSPOT_PROGRAM), "run " + study.string() + " -o " + out + " --quiet", out);
  INFO(killed.output);
  REQUIRE_THAT(killed.output, Catch::Contains("killed 137"));
  REQUIRE(fs::exists(out + ".journal"));
}

ProgramRun check_provenance(const std::string& out, const TempDir& dir, int resumed) {
  std::string command = std::string(python) + " " + source_path("tests/check_provenance.py") + " " + out + " " +
                        SWEETSPOT_SOURCE_DIR + " " + std::to_string(resumed);
  for (const std::string& bat : provenance_bats(dir)) command += " " + bat;
  return run_command(command);
}

}  // namespace

TEST_CASE("A dataset reads back in xarray with CF attributes, integer axes, its bats' texts and scene",
          "[run][provenance]") {
  TempDir dir;
  write_dense_r161(dir);
  const auto study = dir.write("study.toml", provenance_study(2));
  const std::string out = dir / "out.h5";
  const ProgramRun run = run_program("run " + study.string() + " -o " + out + " --quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun check = check_provenance(out, dir, 0);
  INFO(check.output);
  CHECK(check.exit_code == 0);
  CHECK_THAT(check.output, Catch::Contains("provenance ok"));
}

TEST_CASE("A run killed with SIGKILL and resumed says so in its dataset, with the points it took over",
          "[run][provenance]") {
  TempDir dir;
  write_dense_r161(dir);
  const auto study = dir.write("study.toml", provenance_study(60));
  const std::string out = dir / "out.h5";
  kill_midway(study, out);
  const ProgramRun resumed = run_program("run " + study.string() + " -o " + out + " --resume --quiet");
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  const ProgramRun check = check_provenance(out, dir, 1);
  INFO(check.output);
  CHECK(check.exit_code == 0);
  CHECK_THAT(check.output, Catch::Contains("provenance ok"));
}

TEST_CASE("A bat edited between the kill and the resume is refused, and a fresh run's dataset says so",
          "[run][provenance]") {
  TempDir dir;
  write_dense_r161(dir);
  const auto study = dir.write("study.toml", provenance_study(60));
  const std::string out = dir / "out.h5";
  kill_midway(study, out);
  write_dense_r161(dir, 900);  // the study's text is the same; its results are not
  const ProgramRun refused = run_program("run " + study.string() + " -o " + out + " --resume");
  INFO(refused.output);
  REQUIRE(refused.exit_code == 2);
  REQUIRE(std::filesystem::exists(out + ".journal"));  // kept: the user decides
  std::filesystem::remove(out + ".journal");
  const ProgramRun rerun = run_program("run " + study.string() + " -o " + out);
  INFO(rerun.output);
  REQUIRE(rerun.exit_code == 0);
  CHECK_THAT(rerun.output, !Catch::Contains("resuming:"));
  const ProgramRun check = check_provenance(out, dir, 0);  // and bat_toml is the edited file's text
  INFO(check.output);
  CHECK(check.exit_code == 0);
  CHECK_THAT(check.output, Catch::Contains("provenance ok"));
}
