// A stated accuracy chooses the step: given with a step (--dt, dt), the step would be silently
// ignored, so the two are refused together, by `impact` and by a study alike. An accuracy of 0,
// below 0 or NaN states no error: refused everywhere, as a study's key always was, not read as
// "not set". Each refusal one line, exit status 2, before any work, an earlier output untouched.
// (Python's impact and impacts: tests/check_python.py.)
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include "program.hpp"
#include "refusal.hpp"
#include "temp_dir.hpp"

namespace {

const std::string r161 = source_path("studies/bats/r161.toml");
const std::string impact = "impact --bat " + r161 + " --z 0.7 --ball-speed 40 --center 0.09 --omega 51";

std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A study over the R161 with `lines` added to its [scene], run into out.h5 that holds an earlier
// result.
ProgramRun run_study(const TempDir& dir, const std::string& lines, const std::string& axes = "") {
  dir.write("out.h5", "an earlier result");
  const auto study = dir.write("study.toml", "[scene]\nbat = \"" + r161 + "\"\ncenter = 0.09\nomega = 51\nmodes = 0\n" +
                                                 lines + "[axes]\nz = [0.7]\nball_speed = [40.0]\n" + axes);
  return run_program("run " + study.string() + " -o " + dir / "out.h5");
}

}  // namespace

TEST_CASE("impact refuses --dt with --accuracy, naming both", "[cli][accuracy]") {
  require_refused(run_program(impact + " --dt 1e-5 --accuracy 1e-4"), {"impact: --dt excludes --accuracy"});
  require_refused(run_program(impact + " --accuracy 1e-4 --dt 1e-5 --integrator dopri"), {"--dt", "--accuracy"});
  // Either alone runs.
  for (const std::string alone : {" --dt 1e-5", " --accuracy 1e-4"}) {
    const ProgramRun run = run_program(impact + alone + " --json");
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK(run.output.find("\"status\": \"ok\"") != std::string::npos);
  }
}

TEST_CASE("impact refuses an --accuracy of 0, below 0 or NaN, as a study refuses its key", "[cli][accuracy]") {
  const std::pair<std::string, std::string> values[] = {{"0", "0"}, {"-1e-4", "-0.0001"}, {"nan", "nan"}};
  for (const auto& [value, shown] : values) {
    INFO(value);
    require_refused(run_program(impact + " --accuracy " + value),
                    {"impact: --accuracy " + shown + ": expected a finite number > 0 (relative vf error the integration may add)"});
  }
  TempDir dir;
  require_refused(run_study(dir, "accuracy = 0\n"),
                  {"key 'scene.accuracy' = 0: expected a finite number > 0 (relative vf error the integration may add)"});
  CHECK(text_of(dir / "out.h5") == "an earlier result");
}

TEST_CASE("A study refuses dt with accuracy, in [scene] or as an axis, naming both keys", "[study][accuracy]") {
  TempDir dir;
  require_refused(run_study(dir, "dt = 1e-5\naccuracy = 1e-4\n"),
                  {"key 'scene.dt' = 1e-05: expected dt or accuracy, not both: key 'scene.accuracy' is also given"});
  CHECK(text_of(dir / "out.h5") == "an earlier result");
  CHECK_FALSE(std::filesystem::exists(dir / "out.h5.journal"));
  require_refused(run_study(dir, "accuracy = 1e-4\n", "dt = [1e-5, 2e-5]\n"),
                  {"key 'axes.dt' = [...]: expected dt or accuracy, not both: key 'scene.accuracy'"});
  require_refused(run_study(dir, "dt = 1e-5\n", "accuracy = [1e-4, 1e-5]\n"), {"'scene.dt'", "'axes.accuracy'"});
  CHECK(text_of(dir / "out.h5") == "an earlier result");
  // Either alone runs.
  for (const std::string alone : {"dt = 1e-5\n", "accuracy = 1e-4\n"}) {
    const ProgramRun run = run_study(dir, alone);
    INFO(run.output);
    CHECK(run.exit_code == 0);
  }
}

// Issue 24: under dopri a stated accuracy chooses the tolerance (step_selection.cpp), so a
// tolerance given beside it was silently overridden; refused with it as dt is, whatever the
// integrator (the fixed-step methods take no tolerance at all).
TEST_CASE("A tolerance beside a stated accuracy is refused, by impact and by a study", "[cli][study][accuracy]") {
  require_refused(run_program(impact + " --integrator dopri --accuracy 1e-5 --tolerance 1e-12"),
                  {"impact: --tolerance excludes --accuracy"});
  require_refused(run_program(impact + " --tolerance 1e-12 --accuracy 1e-5"), {"--tolerance", "--accuracy"});
  CHECK(run_program(impact + " --integrator dopri --tolerance 1e-10").exit_code == 0);
  TempDir dir;
  require_refused(run_study(dir, "integrator = \"dopri\"\ntolerance = 1e-12\naccuracy = 1e-5\n"),
                  {"key 'scene.tolerance' = 1e-12: expected tolerance or accuracy, not both: key 'scene.accuracy'"});
  require_refused(run_study(dir, "accuracy = 1e-5\n", "tolerance = [1e-10, 1e-12]\n"),
                  {"key 'axes.tolerance' = [...]", "'scene.accuracy'"});
  CHECK(text_of(dir / "out.h5") == "an earlier result");
  CHECK_FALSE(std::filesystem::exists(dir / "out.h5.journal"));
}
