#pragma once
// The search: NLopt (S. G. Johnson, "The NLopt nonlinear-optimization package",
// https://github.com/stevengj/nlopt) proposes designs inside the bounds, an Evaluator scores them.
// Its algorithms are deterministic given the same scores (and, for MLSL, the same seed), which is
// what lets a killed run resume: answered from its journal, the same calls come in the same order.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sweetspot/optimize/evaluation.hpp"

namespace sweetspot {

// Scores the design at x (the free parameters in the problem's order).
using Evaluator = std::function<DesignEvaluation(const std::vector<double>& x)>;

struct OptimizationHistory {
  std::vector<DesignEvaluation> evaluations;  // every design scored, in the order asked
  std::ptrdiff_t best = -1;                   // the best feasible one, -1 if none is
  std::string stop_reason;                    // why NLopt stopped
};

// Runs the problem's algorithm from its start to at most max_evaluations designs. The optimiser
// works on each parameter scaled to [0, 1] by its bounds, so that xtol_rel and initial_step mean
// the same for a density and a diameter; a failed design scores 0 and violates every constraint.
// An exception from `evaluate` stops the search and is thrown again here.
OptimizationHistory optimize_design(const OptimizationProblem& problem, const Evaluator& evaluate);

// The feasible evaluation with the largest objective (the first of equals), or -1.
std::ptrdiff_t best_evaluation(const OptimizationProblem& problem, const std::vector<DesignEvaluation>& evaluations);

}  // namespace sweetspot
