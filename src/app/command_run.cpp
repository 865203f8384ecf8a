// sweetspot run: a study swept over MPI ranks and OpenMP threads into one HDF5 dataset.
#include <mpi.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "commands.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/parallel.hpp"

namespace sweetspot::app {

namespace {

struct RunCommandOptions {
  std::string study;
  std::string output;
  bool output_given = false;  // `-o ""` is a mistake to refuse, not a wish for the default
  bool resume = false, quiet = false, verbose = false;
};

// Rank 0 says why, and the others wait until it has: mpirun stops the job at the first non-zero
// exit, which could otherwise cut rank 0 off before its message.
[[noreturn]] void refuse(const std::string& message, int rank) {
  if (rank == 0) std::fprintf(stderr, "sweetspot: error: %s\n", message.c_str());
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  std::exit(2);
}

void run(const RunCommandOptions& o) {
  int provided = 0, rank = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  spdlog::set_pattern(rank == 0 ? "[%H:%M:%S] %v" : "[%H:%M:%S rank " + std::to_string(rank) + "] %v");
  if (o.quiet) spdlog::set_level(spdlog::level::warn);
  Study study;
  try {
    study = load_study(o.study);  // every rank validates; a bad study stops before any work
  } catch (const InputError& e) {
    refuse(e.what(), rank);
  }
  RunOptions options;
  options.output = o.output_given ? o.output : std::filesystem::path(o.study).stem().string() + ".h5";
  options.resume = o.resume;
  options.verbosity = o.quiet ? Verbosity::quiet : o.verbose ? Verbosity::verbose : Verbosity::normal;
  try {
    run_study(study, options);
  } catch (const RunRefused& e) {  // thrown on every rank, before any work
    refuse(e.what(), rank);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweetspot: error on rank %d: %s\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);  // the other ranks would wait for this one forever
  }
  MPI_Finalize();
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunCommandOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Run a study (alone or under mpirun) into one HDF5 dataset");
  cmd->add_option("study", o->study, "study file (TOML)")->required();
  CLI::Option* output = cmd->add_option("-o,--output", o->output, "dataset to write (default: the study's name .h5)");
  cmd->add_flag("--resume", o->resume, "keep the points a killed run finished, compute the rest");
  auto* quiet = cmd->add_flag("--quiet", o->quiet, "only warnings and errors");
  auto* verbose = cmd->add_flag("--verbose", o->verbose, "report progress after every chunk");
  quiet->excludes(verbose);
  cmd->callback([o, output] {
    o->output_given = output->count() > 0;
    run(*o);
  });
}

}  // namespace sweetspot::app
