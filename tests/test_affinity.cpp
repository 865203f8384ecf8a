// Each rank logs the cores its OpenMP threads may run on and warns when it has fewer than its
// threads, as a rank bound by srun without --cpus-per-task would (docs/clusters.md). The cores are
// the union of the team's masks: OMP_PROC_BIND pins each thread to one core, the first before
// main, and a right binding must not read as a wrong one.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "program.hpp"
#include "temp_dir.hpp"
#include "sweetspot/study/affinity.hpp"

namespace {

// The program run on `cores` (taskset) with `threads` OpenMP threads and `binding` (environment
// assignments such as OMP_PROC_BIND=close, or nothing).
ProgramRun run_on(const std::string& cores, int threads, const std::string& binding) {
  static TempDir dir;
  const auto study = dir.write("study.toml", "kind = \"toy\"\n[axes]\nomega_tau = [0.5, 1, 2]\n");
  return run_command("OMP_NUM_THREADS=" + std::to_string(threads) + " " + binding + " taskset -c " + cores + " " +
                     SWEETSPOT_PROGRAM + " run " + study.string() + " -o " + dir / "toy.h5");
}

const std::vector<std::string> bindings = {"", "OMP_PROC_BIND=close OMP_PLACES=cores",
                                           "OMP_PROC_BIND=spread OMP_PLACES=threads"};

}  // namespace

TEST_CASE("A rank confined to one core warns that its threads take turns, bound or not", "[run]") {
  // One core this test may itself use, as a rank bound by srun without --cpus-per-task would be.
  const std::vector<int> cores = sweetspot::allowed_cores();
  REQUIRE_FALSE(cores.empty());
  const std::string core = std::to_string(cores.front());
  for (const std::string& binding : bindings) {
    INFO("binding: " << binding);
    const ProgramRun crowded = run_on(core, 2, binding);
    INFO(crowded.output);
    REQUIRE(crowded.exit_code == 0);
    CHECK_THAT(crowded.output, Catch::Contains("rank 0: 2 OpenMP thread(s) on core(s) " + core + " (1 allowed)"));
    CHECK_THAT(crowded.output, Catch::Contains("rank 0: 2 OpenMP threads but only 1 core(s) allowed (" + core + ")"));
    const ProgramRun alone = run_on(core, 1, binding);
    INFO(alone.output);
    REQUIRE(alone.exit_code == 0);
    CHECK_THAT(alone.output, Catch::Contains("rank 0: 1 OpenMP thread(s) on core(s) " + core + " (1 allowed)"));
    CHECK_THAT(alone.output, !Catch::Contains("but only"));
  }
}

TEST_CASE("A rank with a core per thread logs them all and no warning, however OpenMP pins its threads", "[run]") {
  const std::vector<int> cores = sweetspot::allowed_cores();
  if (cores.size() < 2) {
    WARN("this test needs 2 cores and has " << cores.size() << ": not checked");
    return;
  }
  const std::vector<int> two = {cores[0], cores[1]};
  const std::string list = sweetspot::core_list(two);
  for (const std::string& binding : bindings) {
    INFO("binding: " << binding);
    const ProgramRun run = run_on(std::to_string(two[0]) + "," + std::to_string(two[1]), 2, binding);
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains("rank 0: 2 OpenMP thread(s) on core(s) " + list + " (2 allowed)"));
    CHECK_THAT(run.output, !Catch::Contains("but only"));
  }
}

TEST_CASE("The team's cores are the union of its threads' masks", "[run]") {
  // In this process nothing pins the threads (unless the test was started with OMP_PROC_BIND):
  // each may use the whole mask, and so may the team.
  if (std::getenv("OMP_PROC_BIND")) return;
  CHECK(sweetspot::team_cores() == sweetspot::allowed_cores());
}

TEST_CASE("Core lists are written as ranges, as taskset writes them", "[run]") {
  CHECK(sweetspot::core_list({0, 1, 2, 3, 8, 10, 11}) == "0-3,8,10-11");
  CHECK(sweetspot::core_list({5}) == "5");
  CHECK(sweetspot::core_list({}) == "");
}
