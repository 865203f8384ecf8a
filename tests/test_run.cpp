// Studies end to end: `sweetspot run` alone and under mpirun gives the same dataset bit for bit,
// a killed run resumes to the same file, bad studies are refused before any work, xarray reads
// the result as it is, and the studies without a bat (wall, toy) run without modes and show the
// physics of N2000 Figs. 3 and 18.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "program.hpp"
#include "temp_dir.hpp"

namespace {

// A small study on both shipped bats: 2 bats x 3 z x 2 speeds, axes not in alphabetical order.
std::string small_study(int z_count = 3, int modes = 18) {
  std::ostringstream s;
  s << "[scene]\nbat = \"" << source_path("studies/bats/r161.toml") << "\"\ncenter = 0.09\nomega = 51\n"
    << "modes = " << modes << "\n[axes]\nbat = [\"" << source_path("studies/bats/r161.toml") << "\", \""
    << source_path("studies/bats/torpedo.toml") << "\"]\nz = { start = 0.605, stop = 0.705, count = " << z_count
    << " }\nball_speed = [30.0, 40.0]\n";
  return s.str();
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void require_identical(const std::string& a, const std::string& b) {
  const ProgramRun compare = run_command(std::string(python) + " " + source_path("tests/compare_datasets.py") + " " + a + " " + b);
  INFO(compare.output);
  REQUIRE(compare.exit_code == 0);
}

}  // namespace

TEST_CASE("A study gives the same dataset bit for bit on any ranks and threads", "[run][mpi]") {
  TempDir dir;
  const auto study = dir.write("study.toml", small_study());
  const ProgramRun serial = run_program("run " + study.string() + " -o " + dir / "serial.h5 --quiet");
  INFO(serial.output);
  REQUIRE(serial.exit_code == 0);
  for (const auto& [ranks, threads] : {std::pair{1, 1}, {1, 2}, {2, 1}, {2, 2}, {3, 1}}) {
    const std::string out = dir / std::to_string(10 * ranks + threads).append(".h5");
    const ProgramRun run = run_program_mpi(ranks, threads, "run " + study.string() + " -o " + out);
    INFO(ranks << " ranks x " << threads << " threads\n" << run.output);
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains("1 eigen-solves") || Catch::Contains("2 eigen-solves"));
    require_identical(dir / "serial.h5", out);
  }
}

TEST_CASE("xarray opens the dataset and its values are those of sweetspot impact", "[run]") {
  TempDir dir;
  const auto study = dir.write("study.toml", small_study());
  REQUIRE(run_program("run " + study.string() + " -o " + dir / "out.h5 --quiet").exit_code == 0);
  const ProgramRun impact = run_program("impact --bat " + source_path("studies/bats/torpedo.toml") +
                                        " --z 0.655 --ball-speed 40 --center 0.09 --omega 51 --modes 18 --json");
  REQUIRE(impact.exit_code == 0);
  const std::string vf = impact.output.substr(impact.output.find("\"vf\": ") + 6);
  const ProgramRun check = run_command(std::string(python) + " " + source_path("tests/check_run.py") + " " +
                                       dir / "out.h5" + " torpedo 0.655 40 " + vf.substr(0, vf.find(',')));
  INFO(check.output);
  CHECK(check.exit_code == 0);
}

TEST_CASE("A run killed with SIGKILL resumes to the file of an uninterrupted run", "[run]") {
  TempDir dir;
  const auto study = dir.write("study.toml", small_study(400));  // 1600 points: about a second
  REQUIRE(run_program("run " + study.string() + " -o " + dir / "whole.h5 --quiet").exit_code == 0);
  // Kill the run as soon as its journal holds some finished points, well before the end.
  const std::string out = dir / "killed.h5";
  const ProgramRun killed = run_and_kill(std::string(SWEETSPOT_PROGRAM), "run " + study.string() + " -o " + out + " --quiet", out);
  INFO(killed.output);
  REQUIRE_THAT(killed.output, Catch::Contains("killed 137"));
  CHECK_FALSE(std::filesystem::exists(out));
  REQUIRE(std::filesystem::exists(out + ".journal"));
  REQUIRE(std::filesystem::exists(out + ".lock"));  // the killed run's: a stale lock blocks nothing
  const ProgramRun resumed = run_program("run " + study.string() + " -o " + out + " --resume");
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  CHECK_THAT(resumed.output, Catch::Contains("resuming:"));
  CHECK_FALSE(std::filesystem::exists(out + ".journal"));
  CHECK_FALSE(std::filesystem::exists(out + ".lock"));
  require_identical(dir / "whole.h5", out);
}

TEST_CASE("A bad study is refused before any work and leaves the output file alone", "[run]") {
  TempDir dir;
  const std::string out = dir / "out.h5";
  dir.write("out.h5", "\x89HDF\r\n\x1a\nan earlier result");
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {small_study() + "speed = [1]\n", "speed"},
      {small_study() + "[output]\nvariables = [\"vf\", \"spin\"]\n", "spin"},
      {"[scene]\nbat = \"missing.toml\"\nz = 0.7\nball_speed = 40\ncenter = 0.09\nomega = 51\n", "missing.toml"},
  };
  for (const Case& c : cases) {
    const auto study = dir.write("bad.toml", c.text);
    for (int ranks : {1, 2}) {
      const ProgramRun run = ranks == 1 ? run_program("run " + study.string() + " -o " + out)
                                        : run_program_mpi(ranks, 1, "run " + study.string() + " -o " + out);
      INFO(c.expected << ", " << ranks << " ranks\n" << run.output);
      CHECK(run.exit_code != 0);
      CHECK_THAT(run.output, Catch::Contains("bad.toml") && Catch::Contains(c.expected));
      CHECK(read_file(out) == "\x89HDF\r\n\x1a\nan earlier result");
      CHECK_FALSE(std::filesystem::exists(out + ".journal"));
    }
  }
}

TEST_CASE("The wall and toy studies solve for no modes and show N2000 Figs. 3 and 18", "[run]") {
  TempDir dir;
  for (const std::string kind : {"wall", "toy"}) {
    const std::string out = dir / (kind + ".h5");
    // Not --quiet: the log's summary of each rank is what shows that no modes were computed.
    const ProgramRun run = run_program("run " + source_path("studies/" + kind + ".toml") + " -o " + out);
    INFO(kind << "\n" << run.output);
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains("rank 0: 0 eigen-solves"));
    const ProgramRun check =
        run_command(std::string(python) + " " + source_path("tests/check_kinds.py") + " " + kind + " " + out);
    INFO(check.output);
    CHECK(check.exit_code == 0);
  }
}

TEST_CASE("A toy study under mpirun: no rank solves for modes, the dataset is the serial one", "[run][mpi]") {
  TempDir dir;
  const std::string study = source_path("studies/toy.toml");
  REQUIRE(run_program("run " + study + " -o " + dir / "serial.h5 --quiet").exit_code == 0);
  const ProgramRun run = run_program_mpi(2, 2, "run " + study + " -o " + dir / "mpi.h5");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("rank 0: 0 eigen-solves") && Catch::Contains("rank 1: 0 eigen-solves"));
  require_identical(dir / "serial.h5", dir / "mpi.h5");
}

TEST_CASE("A study of rigid bats computes no eigen-decomposition and stores no frequencies", "[run]") {
  TempDir dir;
  const auto study = dir.write("study.toml", small_study(3, 0));
  const ProgramRun run = run_program("run " + study.string() + " -o " + dir / "rigid.h5");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("rank 0: 0 eigen-solves"));
  const ProgramRun check = run_command(std::string(python) + " -c \"import xarray as x; d = x.open_dataset('" +
                                       dir / "rigid.h5" + "', engine='h5netcdf'); assert 'frequency' not in d; " +
                                       "assert 'mode' not in d.dims; assert float(d.vf.min()) > 0; print('ok')\"");
  INFO(check.output);
  CHECK(check.exit_code == 0);
}

TEST_CASE("Points that compress the ball past its radius are reported, by the impact command too", "[run]") {
  // a = 3 at 30-40 m/s compresses the ball 54-62 mm, past its 36.6 mm radius: the model runs, but
  // its force law is not meant for that, and the user is told.
  TempDir dir;
  std::string text = small_study();
  text.replace(text.find("[scene]\n"), 8, "[scene]\na = 3\n");
  const auto study = dir.write("study.toml", text);
  const ProgramRun run = run_program("run " + study.string() + " -o " + dir / "out.h5 --quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("rank 0: 12 points compressed the ball past its radius"));
  const ProgramRun normal = run_program("run " + dir.write("normal.toml", small_study()).string() + " -o " +
                                        dir / "normal.h5 --quiet");
  CHECK_THAT(normal.output, !Catch::Contains("radius"));

  const std::string impact = "impact --bat " + source_path("studies/bats/r161.toml") +
                             " --z 0.605 --ball-speed 40 --center 0.09 --omega 51 --integrator exact";
  const ProgramRun past = run_program(impact + " --a 3");
  CHECK(past.exit_code == 0);
  CHECK_THAT(past.output, Catch::Contains("past its radius 36.6 mm"));
  CHECK_THAT(run_program(impact).output, !Catch::Contains("radius"));
}
