// The promise of one line `sweetspot: error: ...` for a refusal holds for sweetspot's own output,
// whatever the MPI library writes to the same stderr: Open MPI warns at start-up on some machines
// (no sysfs topology, a missing network interface), and the tests must still recognise the
// refusal (own_lines.hpp). Here the noise is made on purpose: btl_tcp_if_include naming an
// interface that does not exist makes Open MPI 4.1 write a warning (or, started alone, an
// ORTE_ERROR_LOG line from failing to) in MPI_Init, before any refusal.
#include <catch2/catch.hpp>

#include <string>

#include "own_lines.hpp"
#include "program.hpp"
#include "refusal.hpp"
#include "temp_dir.hpp"

namespace {

const std::string noisy_mpi = "OMPI_MCA_btl_tcp_if_include=nonexistent0 ";

}  // namespace

TEST_CASE("sweetspot's own lines are told from the MPI library's by their prefix", "[program]") {
  CHECK(is_own_line("sweetspot: error: x.toml: study file not found"));
  CHECK(is_own_line("sweetspot: warning: the ball compressed 30 mm"));
  CHECK(is_own_line("[23:01:16] rank 0: 1 OpenMP thread(s) on core(s) 0 (1 allowed)"));
  CHECK(is_own_line("[23:01:16 rank 12] rank 12: 1 eigen-solves in 0.001 s"));
  CHECK_FALSE(is_own_line("[vm:16178] [[21452,0],0] ORTE_ERROR_LOG: Out of resource in file show_help.c"));
  CHECK_FALSE(is_own_line("[10-0-0-7:16317] 1 more process has sent help message help-mpi-btl-tcp.txt"));
  CHECK_FALSE(is_own_line("--------------------------------------------------------------------------"));
  CHECK_FALSE(is_own_line("WARNING: An invalid value was given for btl_tcp_if_include.  This"));
  CHECK_FALSE(is_own_line("  Exit code:    2"));
  CHECK_FALSE(is_own_line(""));
  // Two lines of sweetspot's own are two, with or without the library's between them.
  CHECK(own_lines("sweetspot: error: a\n-----\nWARNING: b\n[12:00:00] c\n").size() == 2);
  CHECK(foreign_lines("sweetspot: error: a\n-----\nWARNING: b\n[12:00:00] c\n").size() == 2);
}

TEST_CASE("run and optimize refusals are one line of sweetspot's own among Open MPI's warnings", "[program]") {
  TempDir dir;
  const std::string missing = dir / "missing.toml";
  for (const std::string command : {"run", "optimize"}) {
    const ProgramRun run = run_command(noisy_mpi + SWEETSPOT_PROGRAM + " " + command + " " + missing + " -o " +
                                       dir / "out.h5");
    INFO(run.output);
    CHECK_FALSE(foreign_lines(run.output).empty());  // the noise came: else this test proves nothing
    require_refused(run, {missing, "not found"});
  }
  // Under mpirun too, where mpirun's notes on the exit status follow.
  const ProgramRun mpi = run_command(noisy_mpi + "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                                     "OMP_NUM_THREADS=1 mpirun -np 2 --oversubscribe --bind-to none " +
                                     SWEETSPOT_PROGRAM + " run " + missing + " -o " + dir / "out.h5");
  INFO(mpi.output);
  // The provoked noise: Open MPI's warning, or, where its help system fails to print it (seen on a
  // loaded machine), the ORTE_ERROR_LOG lines of that failure.
  CHECK_THAT(mpi.output, Catch::Contains("btl_tcp_if_include") || Catch::Contains("ORTE_ERROR_LOG"));
  require_refused(mpi, {missing, "not found"});
}
