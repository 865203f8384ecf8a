#pragma once
// An optimisation's dataset (README "Design optimisation"): every evaluated design over
// `evaluation` with its objective, constraints, feasibility and status, the bounds and the best
// design over `parameter`, and what made it (the optimisation file's text, the bats', the
// program, the cost).
#include <filesystem>

#include "sweetspot/optimize/optimizer.hpp"
#include "sweetspot/study/dataset.hpp"

namespace sweetspot {

struct OptimizationRunInfo {
  int ranks = 1, threads = 1;
  double wall_time = 0;         // s
  int resumed_evaluations = 0;  // answered from a killed run's journal
  std::filesystem::path best_bat_file;  // empty when no design was feasible
};

Dataset optimization_dataset(const OptimizationProblem& problem, const OptimizationHistory& history,
                             const OptimizationRunInfo& info);

}  // namespace sweetspot
