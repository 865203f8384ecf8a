#pragma once
// One design evaluated: its objective (a z scan of batted-ball speeds at equal effort, or their
// mean over a spread of impact points) and its constraints (the rig's measure over the barrel,
// the designed shape's numbers). Physics only: the impacts of an evaluation are handed to a
// PointMap, which may spread them over threads and ranks, and each is computed alone so that the
// result is bitwise the same however they are spread.
#include <cstddef>
#include <limits>
#include <functional>
#include <string>
#include <vector>

#include "sweetspot/optimize/problem.hpp"

namespace sweetspot {

// What one point of an evaluation gives: its number (a batted-ball speed, a carry, the rig's
// measure) and its impact's estimated relative errors from the dropped modes and the time step
// (error_estimates.hpp; NaN where not estimated: without a stated accuracy). NaN value: failed.
struct PointValue {
  double value = std::numeric_limits<double>::quiet_NaN();
  double modes_error = std::numeric_limits<double>::quiet_NaN();
  double step_error = std::numeric_limits<double>::quiet_NaN();
};

// Computes value(0), ..., value(count - 1) and returns them in that order. Called alike on every
// worker that shares an evaluation (every MPI rank); value is safe to call from several threads.
using PointMap =
    std::function<std::vector<PointValue>(std::size_t count, const std::function<PointValue(std::size_t)>& value)>;
// One after the other, on the calling thread.
std::vector<PointValue> serial_map(std::size_t count, const std::function<PointValue(std::size_t)>& value);

enum class EvaluationStatus {
  ok,
  failed  // an impact did not end ok, or the objective cannot be told from the scan (a peak at
          // an end of it, a sweet spot running off it): the design counts as infeasible
};
const char* to_string(EvaluationStatus status);

struct DesignEvaluation {
  std::vector<double> x;            // the free parameters, in the problem's order
  double objective = 0;             // m/s (peak_bbs, mean_bbs) or m (sweet_spot_width); NaN if failed
  std::vector<double> constraints;  // each constraint's quantity, in its units; NaN if unknown
  EvaluationStatus status = EvaluationStatus::ok;
  std::string message;              // why it failed
  // At a stated accuracy: the slices the design was scored at, and the estimated relative errors
  // there: the slicing's (Richardson, the larger of the objective's and the measure's), the
  // dropped modes' and the step's (the largest of the impacts the objective and the measure were
  // made from), and their sum.
  int slices_used = 0;
  double slicing_error = std::numeric_limits<double>::quiet_NaN();
  double modes_error = std::numeric_limits<double>::quiet_NaN();
  double step_error = std::numeric_limits<double>::quiet_NaN();
  double total_error = std::numeric_limits<double>::quiet_NaN();
};

// Evaluates the design at x. Never throws for a design the bounds allow (load_optimization
// checked the box): a failure is a status.
DesignEvaluation evaluate_design(const OptimizationProblem& problem, const std::vector<double>& x, const PointMap& map);

// What the optimiser sees of constraint i: (value - limit) / |limit| for an upper bound, (limit -
// value) / |limit| for a lower one; met when <= the problem's constraint_tolerance. A failed
// evaluation violates every constraint by 1 (a whole limit).
double constraint_violation(const OptimizationProblem& problem, const DesignEvaluation& e, std::size_t i);
// Evaluated ok and every constraint met within its tolerance.
bool feasible(const OptimizationProblem& problem, const DesignEvaluation& e);

}  // namespace sweetspot
