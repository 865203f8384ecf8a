// Each rank logs the cores it may run on (its affinity mask) and warns when it has fewer than its
// OpenMP threads, as a rank bound by srun without --cpus-per-task would (cluster/README.md).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "program.hpp"
#include "temp_dir.hpp"
#include "sweetspot/study/affinity.hpp"

TEST_CASE("Each rank logs the cores it may run on and warns when it has fewer than its threads", "[run]") {
  TempDir dir;
  const auto study = dir.write("study.toml", "kind = \"toy\"\n[axes]\nomega_tau = [0.5, 1, 2]\n");
  // One core this test may itself use, as a rank bound by srun without --cpus-per-task would be.
  const std::vector<int> cores = sweetspot::allowed_cores();
  REQUIRE_FALSE(cores.empty());
  const std::string core = std::to_string(cores.front());
  const auto run_on_one_core = [&](int threads) {
    return run_command("OMP_NUM_THREADS=" + std::to_string(threads) + " taskset -c " + core + " " +
                       SWEETSPOT_PROGRAM + " run " + study.string() + " -o " + dir / "toy.h5");
  };
  const ProgramRun crowded = run_on_one_core(2);
  INFO(crowded.output);
  REQUIRE(crowded.exit_code == 0);
  CHECK_THAT(crowded.output, Catch::Contains("rank 0: 2 OpenMP thread(s) on core(s) " + core + " (1 allowed)"));
  CHECK_THAT(crowded.output, Catch::Contains("rank 0: 2 OpenMP threads but only 1 core(s) allowed (" + core + ")"));
  const ProgramRun alone = run_on_one_core(1);
  INFO(alone.output);
  REQUIRE(alone.exit_code == 0);
  CHECK_THAT(alone.output, Catch::Contains("rank 0: 1 OpenMP thread(s) on core(s) " + core + " (1 allowed)"));
  CHECK_THAT(alone.output, !Catch::Contains("but only"));
}

TEST_CASE("Core lists are written as ranges, as taskset writes them", "[run]") {
  CHECK(sweetspot::core_list({0, 1, 2, 3, 8, 10, 11}) == "0-3,8,10-11");
  CHECK(sweetspot::core_list({5}) == "5");
  CHECK(sweetspot::core_list({}) == "");
}
