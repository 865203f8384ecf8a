#include "sweetspot/optimize/optimizer.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <exception>

namespace sweetspot {

namespace {

// What NLopt's callbacks share: the problem, the scorer, the history and the last design scored
// (NLopt asks the objective and then the constraints at the same point: one evaluation serves both).
struct Search {
  const OptimizationProblem& problem;
  const Evaluator& evaluate;
  OptimizationHistory history;
  std::exception_ptr failure;  // an exception of the scorer, kept to be thrown again
  bool budget_spent = false;
  std::size_t asks = 0;  // NLopt's calls: a design asked again at once is scored once, but counted by NLopt

  std::vector<double> design(const double* u) const {
    std::vector<double> x(problem.free.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const FreeParameter& p = problem.free[i];
      x[i] = std::clamp(p.lower + u[i] * (p.upper - p.lower), p.lower, p.upper);
    }
    return x;
  }

  const DesignEvaluation& at(const double* u) {
    ++asks;
    const std::vector<double> x = design(u);
    if (!history.evaluations.empty() &&
        std::memcmp(history.evaluations.back().x.data(), x.data(), x.size() * sizeof(double)) == 0)
      return history.evaluations.back();
    if (history.evaluations.size() >= static_cast<std::size_t>(problem.optimizer.max_evaluations)) {
      budget_spent = true;
      throw nlopt::forced_stop();
    }
    try {
      history.evaluations.push_back(evaluate(x));
    } catch (...) {
      failure = std::current_exception();
      throw nlopt::forced_stop();
    }
    return history.evaluations.back();
  }
};

double objective(unsigned n, const double* u, double* gradient, void* data) {
  (void)n, (void)gradient;  // derivative-free algorithms only
  const DesignEvaluation& e = static_cast<Search*>(data)->at(u);
  return e.status == EvaluationStatus::ok ? e.objective : 0;
}

void constraints(unsigned m, double* result, unsigned n, const double* u, double* gradient, void* data) {
  (void)n, (void)gradient;
  Search& search = *static_cast<Search*>(data);
  const DesignEvaluation& e = search.at(u);
  for (unsigned i = 0; i < m; ++i) result[i] = constraint_violation(search.problem, e, i);
}

// NLopt's own limit on its calls. NLopt counts calls, not designs scored: a local search starting
// where MLSL just sampled, the objective asked again at a point clamped to the bounds, each asks
// the design just scored again, which is answered without a new evaluation. With max_evaluations
// as NLopt's limit a run stopped "max_evaluations reached" with fewer evaluations recorded; the
// budget of evaluations is therefore Search's alone, and NLopt's limit only a backstop against a
// search that would ask the same design for ever.
int call_limit(const OptimizerSettings& s) {
  return static_cast<int>(std::min<long long>(100LL * s.max_evaluations + 1000, std::numeric_limits<int>::max()));
}

// The stopping rule of a local search, on parameters scaled to [0, 1].
void local_stop(nlopt::opt& opt, const OptimizerSettings& s) {
  opt.set_xtol_rel(s.xtol_rel);
  opt.set_lower_bounds(0.0);
  opt.set_upper_bounds(1.0);
}

nlopt::opt algorithm(const OptimizationProblem& problem) {
  const unsigned n = static_cast<unsigned>(problem.free.size());
  const OptimizerSettings& s = problem.optimizer;
  if (s.algorithm == Algorithm::cobyla) return nlopt::opt(nlopt::LN_COBYLA, n);
  // BOBYQA takes bounds only: the augmented Lagrangian carries the constraints.
  nlopt::opt outer(problem.constraints.empty() ? nlopt::LN_BOBYQA : nlopt::AUGLAG, n);
  nlopt::opt bobyqa(nlopt::LN_BOBYQA, n);
  local_stop(bobyqa, s);
  bobyqa.set_initial_step(s.initial_step);
  if (s.algorithm == Algorithm::bobyqa) {
    if (!problem.constraints.empty()) outer.set_local_optimizer(bobyqa);
    return outer;
  }
  // MLSL: local searches from low-discrepancy (Sobol) starts. It never converges by itself: its
  // run takes the whole budget.
  nlopt::opt mlsl(nlopt::GN_MLSL_LDS, n);
  mlsl.set_local_optimizer(bobyqa);
  mlsl.set_maxeval(call_limit(s));
  local_stop(mlsl, s);
  if (problem.constraints.empty()) return mlsl;
  nlopt::opt auglag(nlopt::AUGLAG, n);
  auglag.set_local_optimizer(mlsl);
  return auglag;
}

std::string stop_reason(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS: return "success";
    case nlopt::STOPVAL_REACHED: return "stopval reached";
    case nlopt::FTOL_REACHED: return "ftol_rel reached";
    case nlopt::XTOL_REACHED: return "xtol_rel reached";
    case nlopt::MAXEVAL_REACHED: return "max_evaluations reached";
    case nlopt::MAXTIME_REACHED: return "maxtime reached";
    default: return "nlopt result " + std::to_string(static_cast<int>(r));
  }
}

}  // namespace

std::ptrdiff_t best_evaluation(const OptimizationProblem& problem, const std::vector<DesignEvaluation>& evaluations) {
  std::ptrdiff_t best = -1;
  for (std::size_t i = 0; i < evaluations.size(); ++i)
    if (feasible(problem, evaluations[i]) && (best < 0 || evaluations[i].objective > evaluations[best].objective))
      best = static_cast<std::ptrdiff_t>(i);
  return best;
}

OptimizationHistory optimize_design(const OptimizationProblem& problem, const Evaluator& evaluate) {
  const OptimizerSettings& s = problem.optimizer;
  Search search{problem, evaluate, {}, nullptr};
  nlopt::srand(s.seed);  // MLSL's random numbers, and any other algorithm's: the same every run
  nlopt::opt opt = algorithm(problem);
  local_stop(opt, s);
  opt.set_maxeval(call_limit(s));
  opt.set_initial_step(s.initial_step);
  opt.set_max_objective(objective, &search);
  if (!problem.constraints.empty())
    opt.add_inequality_mconstraint(constraints, &search,
                                   std::vector<double>(problem.constraints.size(), s.constraint_tolerance));
  std::vector<double> u(problem.free.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    const FreeParameter& p = problem.free[i];
    u[i] = (p.start - p.lower) / (p.upper - p.lower);
  }
  double value = 0;
  try {
    const nlopt::result result = opt.optimize(u, value);
    search.history.stop_reason =
        result != nlopt::MAXEVAL_REACHED
            ? stop_reason(result)
            : "NLopt's limit of " + std::to_string(call_limit(s)) + " calls reached (" + std::to_string(search.asks) +
                  " calls for " + std::to_string(search.history.evaluations.size()) + " designs)";
  } catch (const nlopt::forced_stop&) {
    if (search.failure) std::rethrow_exception(search.failure);
    search.history.stop_reason = "max_evaluations reached";
  } catch (const nlopt::roundoff_limited&) {
    search.history.stop_reason = "roundoff limited";
  }
  if (search.failure) std::rethrow_exception(search.failure);
  search.history.best = best_evaluation(problem, search.history.evaluations);
  return std::move(search.history);
}

}  // namespace sweetspot
