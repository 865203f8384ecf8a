#pragma once
// `sweetspot optimize`: the search over MPI ranks and OpenMP threads. Rank 0 drives NLopt and
// journals every evaluation (OUT.journal, fsync'd as a study's: a run killed at any moment
// resumes with --resume, the optimiser re-run from its start and every journaled evaluation
// answered from the journal, so it takes the same path to the same best design); for each new
// design it sends the design to every rank, and all share its impacts (parallel_map.hpp). At the
// end rank 0 writes the dataset (every evaluation, the best design) and the best design as a
// bat file.
#include <filesystem>

#include "sweetspot/optimize/problem.hpp"
#include "sweetspot/study/parallel.hpp"

namespace sweetspot {

// The dataset, resume and verbosity: a study run's options (parallel.hpp), the same in meaning.
using OptimizeOptions = RunOptions;

// The best design's bat file: OUT_best.toml beside OUT (its extension replaced).
std::filesystem::path best_bat_path(const std::filesystem::path& output);

// Call between MPI_Init_thread and MPI_Finalize on every rank. Throws RunRefused on every rank,
// before any work, for an output that cannot or must not be written, one another run holds, or a
// journal that cannot be trusted.
void run_optimization(const OptimizationProblem& problem, const OptimizeOptions& options);

}  // namespace sweetspot
