// Bounds on what a user can ask, and the command line's usage errors: each refused before any
// work with one line `sweetspot: error: ...` naming the option or key, the value and the bound,
// exit status 2, and no existing output touched.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "program.hpp"
#include "refusal.hpp"
#include "temp_dir.hpp"

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A bat of length 0.84 m over a profile of `rows` slices of 6 cm diameter.
std::filesystem::path write_bat(const TempDir& dir, const std::string& name, int rows) {
  std::ostringstream csv;
  csv << "z_center_m,outer_diameter_m\n";
  csv.precision(12);
  for (int i = 0; i < rows; ++i) csv << (i + 0.5) * 0.84 / rows << ",0.06\n";
  dir.write(name + ".csv", csv.str());
  return dir.write(name + ".toml", "name = \"" + name + "\"\nlength = 0.84\nprofile = \"" + name +
                                       ".csv\"\n[material]\ndensity = 649\nyoungs_modulus = 1.814e10\n"
                                       "shear_modulus = 1.05e9\n");
}

const std::string r161 = source_path("studies/bats/r161.toml");
const std::string scene = " --ball-speed 40 --center 0.09 --omega 51";

// A study over the R161 with `scene` lines in [scene] and `rest` after it; run into out.h5,
// which holds an earlier result that must survive a refusal.
ProgramRun run_study(const TempDir& dir, const std::string& scene_lines, const std::string& rest) {
  dir.write("out.h5", "\x89HDF\r\n\x1a\nan earlier result");
  const auto study = dir.write("study.toml", "[scene]\nbat = \"" + r161 + "\"\ncenter = 0.09\nomega = 51\n" +
                                                 scene_lines + rest);
  return run_program("run " + study.string() + " -o " + dir / "out.h5");
}

void require_untouched(const TempDir& dir) {
  CHECK(read_file(dir / "out.h5") == "\x89HDF\r\n\x1a\nan earlier result");
  CHECK_FALSE(std::filesystem::exists(dir / "out.h5.journal"));
}

}  // namespace

TEST_CASE("A step that could take more than 1e7 steps per contact, or step over a whole one, is refused",
          "[bounds]") {
  require_refused(run_program("impact --bat " + r161 + " --z 0.7" + scene + " --integrator exact --dt 1e-12"),
                  {"impact: --dt 1e-12: expected a step in [5e-09, 0.001] s"});
  // A mistyped 1e300 overflowed the state: status non_finite, and values that meant nothing.
  require_refused(run_program("impact --bat " + r161 + " --z 0.7" + scene + " --dt 1e300"),
                  {"impact: --dt 1e+300: expected a step in [5e-09, 0.001] s"});
  require_refused(run_program("wall --speed 40 --dt 4.9e-9"), {"wall: --dt 4.9e-09"});
  // The bound itself is a step that works: a 1 ms contact in 2e5 steps.
  const ProgramRun finest = run_program("impact --bat " + r161 + " --z 0.7" + scene + " --integrator exact --dt 5e-9 --modes 0");
  INFO(finest.output);
  CHECK(finest.exit_code == 0);
  CHECK_THAT(finest.output, Catch::Contains("status          ok"));
  TempDir dir;
  require_refused(run_study(dir, "dt = 1e-12\n", "[axes]\nz = [0.7]\nball_speed = [40.0]\n"),
                  {"key 'scene.dt' = 1e-12: expected a number in [5e-9, 1e-3]"});
  require_refused(run_study(dir, "dt = 0.002\n", "[axes]\nz = [0.7]\nball_speed = [40.0]\n"),
                  {"key 'scene.dt' = 0.002: expected a number in [5e-9, 1e-3]"});
  require_untouched(dir);
}

TEST_CASE("An option that is not a number says that a number was expected", "[bounds]") {
  require_refused(run_program("impact --bat " + r161 + " --z 0.7" + scene + " --accuracy abc"),
                  {"impact: --accuracy = abc: expected a number"});
}

TEST_CASE("An empty value is refused naming its option, not read as the default", "[bounds]") {
  // --swing-tilt "" ran at the default tilt; --bat "" said ": file not found".
  require_refused(run_program("impact --bat " + r161 + " --z 0.7" + scene + " --swing-tilt ''"),
                  {"impact: --swing-tilt \"\": expected a value, not an empty string"});
  require_refused(run_program("impact --bat '' --z 0.7" + scene), {"impact: --bat \"\": expected a value"});
  require_refused(run_program("certify ''"), {"certify: an empty argument: expected a value"});
}

TEST_CASE("A mode tolerance outside 1e-15 to 0.1 is refused, on the command line and in a study", "[bounds]") {
  // 1e300 kept no mode on the command line (its error estimate infinite) and failed every point
  // of a study; 1e-300 overflowed the finer slicings' requests (a slicing estimate of 0.23).
  for (const char* tolerance : {"1e300", "1e-300"})
    require_refused(run_program("impact --bat " + r161 + " --z 0.7" + scene + " --mode-tolerance " + tolerance),
                    {"mode_tolerance", "expected a number from 1e-15 to 0.1"});
  TempDir dir;
  require_refused(run_study(dir, "mode_tolerance = 0.2\n", "[axes]\nz = [0.7]\nball_speed = [40.0]\n"),
                  {"key 'scene.mode_tolerance' = 0.2: expected a number from 1e-15 to 0.1"});
  require_untouched(dir);
}

// 1e5 m/s returned the ball at -4 568 m/s and 1e7 rad/s at 6.6e6 m/s, both "ok", from the command
// line, a study and the optimiser alike. Past 1000 m/s (a flight's launch) and 1000 rad/s no scene
// is a ball's or a batter's; up to them each runs.
TEST_CASE("A speed past 1000 m/s or a swing past 1000 rad/s is refused, on the command line and in a study",
          "[bounds]") {
  const std::string impact = "impact --bat " + r161 + " --z 0.7";
  require_refused(run_program(impact + " --ball-speed 1e5 --center 0.09 --omega 51"),
                  {"ball_speed = 100000", "from -1000 to 1000 m/s"});
  require_refused(run_program(impact + " --ball-speed 40 --cm-speed -1001 --omega 5"), {"cm_speed = -1001"});
  require_refused(run_program(impact + " --ball-speed 40 --center 0.09 --omega 1e7"),
                  {"--omega 10000000 rad/s", "at most 1000 rad/s"});
  CHECK(run_program(impact + " --ball-speed 1000 --center 0.09 --omega 1000 --modes 0").exit_code == 0);
  // A friction coefficient past 100 (1e20 sent the ball off at 8 km/s, its energy from a vanishing
  // force's last step times mu).
  require_refused(run_program(impact + " --ball-speed 40 --center 0.09 --omega 51 --undercut 0.02 --friction 1e20"),
                  {"friction", "from 0 to 100"});
  // A centre far off the bat moved the struck point at 1e6 m/s (status ok, v_f 1e6 m/s).
  require_refused(run_program(impact + " --ball-speed 40 --center -1000 --omega 1000"),
                  {"center = -1000", "struck point at 1000700 m/s", "from -1000 to 1000 m/s"});
  TempDir dir;
  require_refused(run_study(dir, "", "[axes]\nz = [0.7]\nball_speed = [40, 1e5]\n"),
                  {"key 'axes.ball_speed[1]' = 100000", "from -1000 to 1000 m/s"});
  require_refused(run_study(dir, "ball_speed = 40\n", "[axes]\nz = [0.7]\nomega = [51, 1e7]\n"),
                  {"key 'axes.omega[1]'", "at most 1000 rad/s"});
  require_untouched(dir);
}

TEST_CASE("A profile has 4 to 4096 rows, as --slices", "[bounds]") {
  TempDir dir;
  require_refused(run_program("modes " + write_bat(dir, "huge", 20000).string()),
                  {"huge.csv:4098: row 4097: a profile has at most 4096 rows"});
  for (const int rows : {1, 3})
    require_refused(run_program("impact --bat " + write_bat(dir, "few", rows).string() + " --z 0.7" + scene +
                                " --pivot --modes 0"),
                    {"few.csv: the profile has " + std::to_string(rows) + " rows", "at least 4"});
  // Both bounds are profiles that work (4096 rows without vibrational modes: no eigen-solve).
  for (const int rows : {4, 4096}) {
    const std::string bat = write_bat(dir, "edge" + std::to_string(rows), rows).string();
    const ProgramRun run = run_program("impact --bat " + bat + " --z 0.84" + scene + " --pivot --modes 0");
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains("status          ok"));
  }
}

TEST_CASE("A study that cannot fit in the machine's memory is refused, naming its axes", "[bounds]") {
  TempDir dir;
  require_refused(run_study(dir, "modes = 18\n",
                            "[axes]\nz = { start = 0.0, stop = 0.84, count = 1000 }\n"
                            "ball_speed = { start = 1, stop = 100, count = 1000 }\ne0 = { start = 0.05, stop = 1, count = 1000 }\n"
                            "[output]\nvariables = [\"vf\", \"status\", \"mode_energy\"]\n"),
                  {"study.toml: the study needs about ", "GB of memory, more than the ",
                   "1000000000 points = z (1000) x ball_speed (1000) x e0 (1000), 20 values each"});
  require_untouched(dir);
}

TEST_CASE("A history of exactly 1e5 steps is accepted, one more is refused", "[bounds]") {
  TempDir dir;
  const std::string axes = "[axes]\nz = [0.7]\nball_speed = [40.0]\n[output]\nvariables = [\"status\", \"force\"]\n";
  require_refused(run_study(dir, "modes = 0\nhistory_step = 2.9e-8\n", axes),
                  {"key 'scene.history_step' = 2.9e-08: history_window / history_step = 103448 samples; at most 1e5"});
  require_untouched(dir);
  // 3e-3 / 3e-8 is 100000.00000000001 in floating point: 1e5 steps all the same.
  const ProgramRun run = run_study(dir, "modes = 0\nhistory_step = 3e-8\n", axes);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun check = run_command(std::string(python) + " -c \"import xarray as x; d = x.open_dataset('" +
                                       dir / "out.h5" + "', engine='h5netcdf'); assert d.sizes['time'] == 100001, " +
                                       "d.sizes; assert int(d.status.max()) == 0; print('ok')\"");
  INFO(check.output);
  CHECK(check.exit_code == 0);
}

TEST_CASE("RK4 with modes it cannot integrate stably is refused by the study, as by impact", "[bounds]") {
  require_refused(run_program("impact --bat " + r161 + " --z 0.7" + scene + " --integrator rk4 --modes all"),
                  {"--dt: RK4 step dt = 5e-06 s is unstable"});
  TempDir dir;
  require_refused(run_study(dir, "integrator = \"rk4\"\nmodes = \"all\"\n", "[axes]\nz = [0.7]\nball_speed = [40.0]\n"),
                  {"key 'scene.modes' = \"all\": with integrator = \"rk4\" and dt = 5e-06 s, R161 (", " in 84 slices",
                   "omega dt = ", "> 2.8 is unstable"});
  require_untouched(dir);
  // An axis names the combination: the modes value, the bat and its slices, and the step.
  require_refused(run_study(dir, "integrator = \"rk4\"\n",
                            "[axes]\nz = [0.7]\nball_speed = [40.0]\nslices = [84, 168]\nmodes = [18, \"all\"]\n"
                            "dt = [1e-6, 2.7e-6]\n"),
                  {"key 'axes.modes' = \"all\": with integrator = \"rk4\" and dt = 2.7e-06 s", "in 84 slices"});
  // Held at a pivot, the fastest kept mode is the held bat's.
  require_refused(run_study(dir, "integrator = \"rk4\"\npivot = true\nmodes = \"all\"\n",
                            "[axes]\nz = [0.7]\nball_speed = [40.0]\n"),
                  {"pivoted at center = 0.09 m"});
  // What RK4 can integrate runs (18 modes at 5 us; all modes at a stated accuracy).
  for (const std::string ok : {"integrator = \"rk4\"\nmodes = 18\n", "integrator = \"rk4\"\nmodes = \"all\"\naccuracy = 1e-4\n"}) {
    const ProgramRun run = run_study(dir, ok, "[axes]\nz = [0.7]\nball_speed = [40.0]\n");
    INFO(run.output);
    CHECK(run.exit_code == 0);
  }
}

TEST_CASE("Usage errors: one line in the program's style, exit status 2", "[bounds][cli]") {
  const std::string impact = "impact --bat " + r161 + " --z 0.7 --ball-speed 40";
  struct Case {
    std::string arguments, expected;
  };
  const Case cases[] = {
      {"impact --bat " + r161, "impact: --z is required"},
      {impact + " --center 0.1 --spin", "impact: The following argument was not expected: --spin"},
      {"impact --bat " + r161 + " --z abc --ball-speed 40 --center 0.1", "impact: --z: \"abc\": expected a length"},
      {"modes " + r161 + " --slices 3", "modes: --slices: '3': expected a whole number from 4 to 4096"},
      {"modes " + r161 + " --slices abc", "modes: --slices: 'abc': expected a whole number from 4 to 4096"},
      {"run study.toml --quiet --verbose", "run: --quiet excludes --verbose"},
      {impact + " --center 0.1 --cm-speed 3", "impact: --cm-speed excludes --center"},
      {impact + " --center 0.1 --integrator euler", "impact: --integrator: 'euler': expected rk4, exact or dopri"},
      {"modes " + r161 + " --count 0", "modes: --count: '0': expected a whole number from 1 to 8192"},
      {"modes " + r161 + " --shapes", "modes: --shapes requires --json"},
      {"", "expected a command: modes, impact, wall, toy, ball, run, convergence, certify, optimize or flight"},
      {"swing", "expected a command: modes, impact, wall, toy, ball, run, convergence, certify, optimize or flight, not 'swing'"},
      {impact, "impact: give the swing as --cm-speed or as --center"},
  };
  for (const Case& c : cases) {
    const ProgramRun run = run_program(c.arguments);
    require_refused(run, {c.expected});
    CHECK(run.output.size() < 200);  // no 300-digit bound
  }
  CHECK(run_program("--version").exit_code == 0);
  const ProgramRun help = run_program("impact --help");
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.output, Catch::Contains("--ball-speed"));
}

// Issue 24: a negative omega was taken by impact and studies, refused by the optimiser's [player].
// v_bat(z) = V_cm + omega (z - z_cm), +y toward the ball (physics.md §1): a swing turns the barrel
// toward the ball at omega >= 0; a negative one swings it backwards. Refused the same everywhere;
// 0 (a bat at rest, a push) stays.
TEST_CASE("A negative omega is refused wherever a swing is given, 0 taken", "[bounds]") {
  require_refused(run_program("impact --bat " + r161 + " --z 0.7 --ball-speed 40 --cm-speed 10 --omega -40"),
                  {"impact: --omega -40", ">= 0", "backwards"});
  require_refused(run_program("impact --bat " + r161 + " --z 0.7 --ball-speed 40 --center 0.15 --pivot --omega "
                              "-480rpm"),
                  {"--omega -50.26", ">= 0"});
  CHECK(run_program("impact --bat " + r161 + " --z 0.7 --ball-speed 40 --cm-speed 10 --omega 0").exit_code == 0);
  TempDir dir;
  require_refused(run_study(dir, "ball_speed = 40\n", "[axes]\nz = [0.6, 0.7]\nomega = [51, \"-480 rpm\"]\n"),
                  {"key 'axes.omega[1]' = \"-480 rpm\"", ">= 0"});
  require_untouched(dir);
}

// A point given as NaN reached the ball's section (its curvature, a speed-dependent COR) before
// the scene was checked, and an index made from it crashed the program and Python (exit 139).
TEST_CASE("An impact point that is not a number is refused, whatever the ball", "[bounds]") {
  for (const std::string ball : {"n2000", "ncaa", "mlb"})
    for (const std::string extra : {"", " --undercut 0.01", " --integrator dopri"}) {
      INFO(ball << extra);
      require_refused(run_program("impact --bat " + r161 + " --z nan --ball-speed 40 --cm-speed 10 --ball " + ball +
                                  extra),
                      {"impact: z = nan: must lie on the bat"});
    }
  require_refused(run_program("impact --bat " + source_path("studies/bats/alloy_bbcor.toml") +
                              " --z nan --ball-speed 40 --cm-speed 10 --ball ncaa"),
                  {"z = nan"});
}
