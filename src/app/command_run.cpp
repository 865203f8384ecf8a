// sweetspot run: a study swept over MPI ranks and OpenMP threads into one HDF5 dataset.
#include <memory>
#include <optional>

#include "commands.hpp"
#include "mpi_command.hpp"
#include "sweetspot/study/input_kind.hpp"
#include "sweetspot/study/parallel.hpp"
#include "sweetspot/uncertainty/uncertainty_study.hpp"

namespace sweetspot::app {

void add_run_command(CLI::App& app) {
  // A study of any kind; kind = "uncertainty" draws its samples when it is loaded (on every rank,
  // the same bits) and adds its statistics to the dataset.
  auto study = std::make_shared<Study>();
  auto uncertainty = std::make_shared<std::optional<UncertaintyStudy>>();
  add_mpi_command(app,
                  {"run", "Run a study (alone or under mpirun) into one HDF5 dataset", "study", "study file (TOML)",
                   "dataset to write (default: the study's name .h5)",
                   "keep the points a killed run finished, compute the rest", "report progress after every chunk"},
                  [study, uncertainty](const std::string& file) {
                    if (require_input_kind(file, {InputKind::study, InputKind::uncertainty_study}, "run",
                                           "study file") == InputKind::uncertainty_study)
                      *uncertainty = load_uncertainty_study(file);
                    else
                      *study = load_study(file);
                  },
                  [study, uncertainty](const RunOptions& options) {
                    if (*uncertainty)
                      run_uncertainty_study(**uncertainty, options);
                    else
                      run_study(*study, options);
                  });
}

}  // namespace sweetspot::app
