#pragma once
// Runs commands (the sweetspot program, mpirun, Debian's python3) from a test and captures what
// they print and how they exit.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

struct ProgramRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline ProgramRun run_command(const std::string& command) {
  ProgramRun run;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) run.output += buffer.data();
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

inline ProgramRun run_program(const std::string& arguments) {
  return run_command(std::string(SWEETSPOT_PROGRAM) + " " + arguments);
}

// The program under mpirun with `ranks` ranks of `threads` OpenMP threads, oversubscribing the
// machine's cores when asked for more (Open MPI refuses root without the two variables).
inline ProgramRun run_program_mpi(int ranks, int threads, const std::string& arguments) {
  return run_command("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=" +
                     std::to_string(threads) + " mpirun -np " + std::to_string(ranks) +
                     " --oversubscribe --bind-to none " + SWEETSPOT_PROGRAM + " " + arguments);
}

// Starts `program arguments` (a study run on one thread writing `out`) and kills it with SIGKILL
// as soon as its journal holds some finished points, well before the end. Prints "killed 137"
// when it was killed; a run that ended first is not waited for forever ("killed 0").
inline ProgramRun run_and_kill(const std::string& program, const std::string& arguments, const std::string& out) {
  return run_command("OMP_NUM_THREADS=1 " + program + " " + arguments + " & pid=$!; while kill -0 $pid 2>/dev/null && [ $(stat -c %s " +
                     out + ".journal 2>/dev/null || echo 0) -lt 20000 ]; do sleep 0.005; done; kill -9 $pid 2>/dev/null; "
                     "wait $pid; echo killed $?");
}

inline std::string source_path(const std::string& relative) {
  return std::string(SWEETSPOT_SOURCE_DIR) + "/" + relative;
}

// Debian's interpreter, which has h5py, xarray and h5netcdf; the first python3 on PATH may not.
inline const char* python = "/usr/bin/python3";
