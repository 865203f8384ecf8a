// sweetspot optimize: a bat design searched by NLopt under the rules' constraints, each design's
// impacts spread over MPI ranks and OpenMP threads, into one HDF5 dataset and a bat file.
#include <mpi.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "commands.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/optimize/optimization_run.hpp"

namespace sweetspot::app {

namespace {

struct OptimizeCommandOptions {
  std::string file;
  std::string output;
  bool output_given = false;  // `-o ""` is a mistake to refuse, not a wish for the default
  bool resume = false, quiet = false, verbose = false;
};

// Rank 0 says why, and the others wait until it has (as `run` does).
[[noreturn]] void refuse(const std::string& message, int rank) {
  if (rank == 0) std::fprintf(stderr, "sweetspot: error: %s\n", message.c_str());
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  std::exit(2);
}

void optimize(const OptimizeCommandOptions& o) {
  int provided = 0, rank = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  spdlog::set_pattern(rank == 0 ? "[%H:%M:%S] %v" : "[%H:%M:%S rank " + std::to_string(rank) + "] %v");
  if (o.quiet) spdlog::set_level(spdlog::level::warn);
  OptimizationProblem problem;
  try {
    problem = load_optimization(o.file);  // every rank validates; a bad file stops before any work
  } catch (const InputError& e) {
    refuse(e.what(), rank);
  }
  OptimizeOptions options;
  options.output = o.output_given ? o.output : std::filesystem::path(o.file).stem().string() + ".h5";
  options.resume = o.resume;
  options.verbosity = o.quiet ? Verbosity::quiet : o.verbose ? Verbosity::verbose : Verbosity::normal;
  try {
    run_optimization(problem, options);
  } catch (const RunRefused& e) {  // thrown on every rank, before any work
    refuse(e.what(), rank);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweetspot: error on rank %d: %s\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
}

}  // namespace

void add_optimize_command(CLI::App& app) {
  auto o = std::make_shared<OptimizeCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "optimize", "Search a bat design (alone or under mpirun) into one HDF5 dataset and a bat file OUT_best.toml");
  cmd->add_option("optimization", o->file, "optimisation file (TOML)")->required();
  CLI::Option* output = cmd->add_option("-o,--output", o->output, "dataset to write (default: the file's name .h5)");
  cmd->add_flag("--resume", o->resume, "answer the evaluations a killed run journaled, compute the rest");
  auto* quiet = cmd->add_flag("--quiet", o->quiet, "only warnings and errors");
  auto* verbose = cmd->add_flag("--verbose", o->verbose, "log every evaluation");
  quiet->excludes(verbose);
  cmd->callback([o, output] {
    o->output_given = output->count() > 0;
    optimize(*o);
  });
}

}  // namespace sweetspot::app
