// The program's commands end to end: what they print and how they exit.
#include <catch2/catch.hpp>

#include <algorithm>

#include "program.hpp"
#include "refusal.hpp"

TEST_CASE("modes --json prints the mass properties and Table II of the R161 bat", "[program]") {
  const ProgramRun run = run_program("modes " + source_path("studies/bats/r161.toml") + " --json --count 3");
  REQUIRE(run.exit_code == 0);
  for (const char* key : {"\"mass_kg\": 0.869", "\"z_cm_m\": 0.56", "\"r_g_m\": 0.229", "\"frequencies_hz\": [17",
                          "\"nodes_m\": [[0.16"})
    CHECK_THAT(run.output, Catch::Contains(key));
}

TEST_CASE("modes rejects bad options with a non-zero exit", "[program]") {
  const std::string bat = source_path("studies/bats/r161.toml");
  CHECK(run_program("modes " + bat + " --theory beam").exit_code != 0);
  CHECK(run_program("modes " + bat + " --slices 0").exit_code != 0);
  CHECK(run_program("modes " + bat + " --unknown").exit_code != 0);
  const ProgramRun too_many = run_program("modes " + bat + " --count 500");
  CHECK(too_many.exit_code == 2);
  CHECK_THAT(too_many.output, Catch::Contains("--count 500"));
}

TEST_CASE("wall and toy commands print JSON with their results", "[program]") {
  const ProgramRun wall = run_program("wall --speed 67 --e0 0.5 --n2000 --json");
  REQUIRE(wall.exit_code == 0);
  CHECK_THAT(wall.output, Catch::Contains("\"restitution\": 0.49999"));
  const ProgramRun toy = run_program("toy --omega-tau 20 --json");
  REQUIRE(toy.exit_code == 0);
  CHECK_THAT(toy.output, Catch::Contains("\"exit_ratio\": 0.71"));
  CHECK(run_program("wall --speed -3").exit_code == 2);
  CHECK(run_program("toy --omega-tau 0").exit_code == 2);
  // Past the toy's fixed step nothing is computed: refused, where it printed v_f/v_i = 0 and NaN
  // energies with exit status 0.
  for (const char* json : {"", " --json"})
    require_refused(run_program(std::string("toy --omega-tau 1e300") + json),
                    {"toy: --omega-tau 1e+300", "beyond the toy model's fixed step"});
}

TEST_CASE("a shipped bat is found by name, and an unknown name is refused with the shipped names", "[program]") {
  const std::string scene = " --z 0.7 --ball-speed 40 --cm-speed 10 --omega 40 --json";
  const ProgramRun by_file = run_program("impact --bat " + source_path("studies/bats/r161.toml") + scene);
  const ProgramRun by_name = run_program("impact --bat r161" + scene);
  REQUIRE(by_file.exit_code == 0);
  CHECK(by_name.exit_code == 0);
  CHECK(by_name.output == by_file.output);
  CHECK(run_program("modes torpedo --count 1").exit_code == 0);
  CHECK(run_program("certify alloy_bbcor --json").exit_code == 3);  // found, checked, and it fails BBCOR

  const ProgramRun unknown = run_program("impact --bat r16" + scene);
  CHECK(unknown.exit_code == 2);
  CHECK_THAT(unknown.output, Catch::StartsWith("sweetspot: error: --bat: no bat file or shipped bat 'r16' (shipped: "));
  CHECK_THAT(unknown.output, Catch::Contains(" r161 torpedo)\n"));
  CHECK(std::count(unknown.output.begin(), unknown.output.end(), '\n') == 1);
  // A path is a path: no lookup, load_bat's own message.
  const ProgramRun missing = run_program("impact --bat no_such_bat.toml" + scene);
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.output, !Catch::Contains("shipped"));
}
