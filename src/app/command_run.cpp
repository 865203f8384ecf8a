// sweetspot run: a study swept over MPI ranks and OpenMP threads into one HDF5 dataset.
#include <memory>

#include "commands.hpp"
#include "mpi_command.hpp"
#include "sweetspot/study/parallel.hpp"

namespace sweetspot::app {

void add_run_command(CLI::App& app) {
  auto study = std::make_shared<Study>();
  add_mpi_command(app,
                  {"run", "Run a study (alone or under mpirun) into one HDF5 dataset", "study", "study file (TOML)",
                   "dataset to write (default: the study's name .h5)",
                   "keep the points a killed run finished, compute the rest", "report progress after every chunk"},
                  [study](const std::string& file) { *study = load_study(file); },
                  [study](const RunOptions& options) { run_study(*study, options); });
}

}  // namespace sweetspot::app
