// sweetspot optimize: a bat design searched by NLopt under the rules' constraints, each design's
// impacts spread over MPI ranks and OpenMP threads, into one HDF5 dataset and a bat file.
#include <memory>

#include "commands.hpp"
#include "mpi_command.hpp"
#include "sweetspot/optimize/optimization_run.hpp"
#include "sweetspot/study/input_kind.hpp"

namespace sweetspot::app {

void add_optimize_command(CLI::App& app) {
  auto problem = std::make_shared<OptimizationProblem>();
  add_mpi_command(
      app,
      {"optimize", "Search a bat design (alone or under mpirun) into one HDF5 dataset and a bat file OUT_best.toml",
       "optimization", "optimisation file (TOML)", "dataset to write (default: the file's name .h5)",
       "answer the evaluations a killed run journaled, compute the rest", "log every evaluation"},
      [problem](const std::string& file) {
        require_input_kind(file, {InputKind::optimisation}, "optimize", "optimisation file");
        *problem = load_optimization(file);
      },
      [problem](const RunOptions& options) { run_optimization(*problem, options); });
}

}  // namespace sweetspot::app
