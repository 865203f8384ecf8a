#include "sweetspot/optimize/optimization_run.hpp"

#include <mpi.h>
#include <omp.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/bat_design_text.hpp"
#include "sweetspot/optimize/optimization_dataset.hpp"
#include "sweetspot/optimize/optimizer.hpp"
#include "sweetspot/optimize/parallel_map.hpp"
#include "sweetspot/study/journal.hpp"
#include "sweetspot/study/output_lock.hpp"
#include "sweetspot/study/output_paths.hpp"
#include "sweetspot/version.hpp"

namespace sweetspot {

namespace {

namespace fs = std::filesystem;

// ---- A journal row: the design's bits, its objective, its constraints, its status, and what a
// stated accuracy chose and estimated (slices_used, the slicing's, modes', step's and total errors)

constexpr std::size_t accuracy_fields = 5;

std::size_t row_width(const OptimizationProblem& p) {
  return p.free.size() + 1 + p.constraints.size() + 1 + accuracy_fields;
}

std::vector<double> to_row(const DesignEvaluation& e) {
  std::vector<double> row = e.x;
  row.push_back(e.objective);
  row.insert(row.end(), e.constraints.begin(), e.constraints.end());
  row.push_back(static_cast<double>(e.status));
  row.insert(row.end(), {static_cast<double>(e.slices_used), e.slicing_error, e.modes_error, e.step_error,
                         e.total_error});
  return row;
}

DesignEvaluation from_row(const OptimizationProblem& p, const double* row) {
  DesignEvaluation e;
  const std::size_t n = p.free.size(), m = p.constraints.size();
  e.x.assign(row, row + n);
  e.objective = row[n];
  e.constraints.assign(row + n + 1, row + n + 1 + m);
  e.status = static_cast<EvaluationStatus>(static_cast<int>(row[n + 1 + m]));
  const double* chosen = row + n + 2 + m;
  e.slices_used = static_cast<int>(chosen[0]);
  e.slicing_error = chosen[1], e.modes_error = chosen[2], e.step_error = chosen[3], e.total_error = chosen[4];
  return e;
}

// Why a row's slices_used and estimates (`chosen`) cannot be an evaluation's, or "". Without a
// stated accuracy there are none (0 and NaN); with one, an ok evaluation was scored on its
// design's own slices doubled at least twice (the design's own are min_slices or more), with
// finite estimates summing to a total within the accuracy; a failed one may hold the last rung's.
std::string accuracy_row_problem(const OptimizationProblem& p, bool ok, const double* chosen) {
  const double slices = chosen[0], accuracy = p.model.accuracy;
  const double *estimates = chosen + 1, total = chosen[4];
  if (accuracy == 0)
    return slices == 0 && std::all_of(estimates, estimates + 4, [](double e) { return std::isnan(e); })
               ? ""
               : "estimates of an accuracy the problem does not state";
  if (!(slices >= 0 && slices <= max_slices && slices == std::floor(slices))) return "a slice count out of range";
  if (std::any_of(estimates, estimates + 4, [](double e) { return e < 0 || std::isinf(e); }))
    return "a negative or infinite error estimate";
  if (!ok) return "";
  if (slices < 4 * min_slices) return "an ok evaluation on fewer slices than three slicings give";
  if (std::any_of(estimates, estimates + 4, [](double e) { return std::isnan(e); }))
    return "an ok evaluation without its error estimates";
  if (total != chosen[1] + chosen[2] + chosen[3]) return "a total error that is not its estimates' sum";
  if (!(total <= accuracy)) return "an ok evaluation whose total error passes the accuracy";
  return "";
}

// Why a journaled row cannot be one of this problem's evaluations, or "".
std::string row_problem(const OptimizationProblem& p, const double* row) {
  const std::size_t n = p.free.size(), m = p.constraints.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!(row[i] >= p.free[i].lower && row[i] <= p.free[i].upper)) return "a design outside the bounds";
  const double status = row[n + 1 + m];
  if (status != 0 && status != 1) return "an unknown status";
  if (status == 0 && !std::isfinite(row[n])) return "an ok evaluation without an objective";
  for (std::size_t j = 0; j < m; ++j)
    if (status == 0 && std::isnan(row[n + 1 + j])) return "an ok evaluation with a NaN constraint";
  return accuracy_row_problem(p, status == 0, row + n + 2 + m);
}

// ---- The output claimed by rank 0 ----------------------------------------------------------

std::vector<fs::path> inputs(const OptimizationProblem& p) {
  std::vector<fs::path> files{p.file, p.base_source.toml_file};
  if (!p.reference_source.toml_file.empty()) files.push_back(p.reference_source.toml_file);
  return files;
}

fs::path temporary(const fs::path& path) { return path.string() + ".tmp"; }

// The first words of the comment a best bat file starts with (write_best_bat): the run replaces, or
// removes when it finds no feasible design, only a file so marked, not one of the user's that has
// the name (it did either without looking).
constexpr std::string_view best_comment_start = "The best design of the optimisation ";

void check_best_replaceable(const fs::path& best) {
  std::ifstream in(best, std::ios::binary);
  std::string first;
  if (!in || !std::getline(in, first)) return;  // none there, or empty
  if (!first.starts_with("# " + std::string(best_comment_start)))
    throw InputError(best.string() + ": exists and is not a best design an earlier run wrote (its first line is not "
                     "\"# " + std::string(best_comment_start) + "...\"); expected it moved away, or another output "
                     "name (the run writes its best design to OUTPUT_best.toml)");
}

struct OutputClaim {
  OutputLock lock;
  // The best bat file is named after the output's stem, which outputs of other names share
  // (r.h5, r.nc): it has a lock of its own, or two runs would write one file.
  OutputLock best_lock;
  Journal journal;
  OutputClaim(const OptimizationProblem& p, const OptimizeOptions& o)
      : lock(o.output),
        best_lock(best_bat_path(o.output)),
        journal(Journal::path_for(o.output),
                journal_key(p.text, {p.base_source, p.reference_source},
                            static_cast<std::uint64_t>(p.optimizer.max_evaluations), row_width(p)),
                o.resume, [&p](const double* row) { return row_problem(p, row); }) {
    if (!journal.dropped().empty()) spdlog::warn("{}: {}", Journal::path_for(o.output).string(), journal.dropped());
  }
  static void check(const OptimizationProblem& p, const OptimizeOptions& o) {
    const fs::path journal = Journal::path_for(o.output), best = best_bat_path(o.output);
    check_output_paths(o.output,
                       {dataset_temporary_path(o.output), journal, Journal::rewrite_path(journal),
                        OutputLock::path_for(o.output), best, temporary(best), OutputLock::path_for(best)},
                       inputs(p));
    check_best_replaceable(best);
  }
};

// Rank 0 claims the output; all ranks learn whether it did and stop together if not.
std::unique_ptr<OutputClaim> claim_output(const OptimizationProblem& p, const OptimizeOptions& o, int rank) {
  std::unique_ptr<OutputClaim> claim;
  std::string refusal;
  if (rank == 0) try {
      OutputClaim::check(p, o);
      claim = std::make_unique<OutputClaim>(p, o);
    } catch (const InputError& e) {
      refusal = e.what();
    }
  share_refusal(refusal);
  return claim;
}

// ---- Rank 0 drives, the others serve -------------------------------------------------------

enum Command : int { stop = 0, evaluate = 1 };

DesignEvaluation evaluate_everywhere(const OptimizationProblem& p, std::vector<double> x) {
  int command = Command::evaluate;
  MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Bcast(x.data(), static_cast<int>(x.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return evaluate_design(p, x, mpi_map);
}

void serve(const OptimizationProblem& p) {
  for (;;) {
    int command = Command::stop;
    MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (command == Command::stop) return;
    std::vector<double> x(p.free.size());
    MPI_Bcast(x.data(), static_cast<int>(x.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
    evaluate_design(p, x, mpi_map);
  }
}

// Rank 0's scorer: the journal's answer for an evaluation it holds (the same design, bit for
// bit, since the optimiser repeats its path), else a new evaluation shared by every rank,
// journaled before the optimiser sees it.
class JournaledEvaluator {
 public:
  // A failed evaluation's reason is text, which the journal's rows of numbers do not hold: such
  // rows are dropped from the journal and evaluated again when asked (a design's evaluation is
  // deterministic, and failures are rare), so that the resumed run's `failure` says what an
  // uninterrupted run's does.
  JournaledEvaluator(const OptimizationProblem& p, Journal& journal, Verbosity verbosity)
      : problem_(p), journal_(journal), verbosity_(verbosity), recovered_(static_cast<std::size_t>(p.optimizer.max_evaluations)) {
    const std::size_t width = row_width(p);
    std::vector<std::uint64_t> ok_points;
    std::vector<double> ok_rows;
    for (std::size_t k = 0; k < journal.recovered_points().size(); ++k) {
      const double* row = journal.recovered_values().data() + k * width;
      DesignEvaluation e = from_row(p, row);
      if (e.status != EvaluationStatus::ok) continue;
      ok_points.push_back(journal.recovered_points()[k]);
      ok_rows.insert(ok_rows.end(), row, row + width);
      recovered_[ok_points.back()] = std::move(e);
    }
    if (ok_points.size() < journal.recovered_points().size()) journal.rewrite(ok_points, ok_rows);
  }

  DesignEvaluation operator()(const std::vector<double>& x) {
    const std::size_t index = asked_++;
    const std::optional<DesignEvaluation>& old = recovered_.at(index);
    if (old && std::memcmp(old->x.data(), x.data(), x.size() * sizeof(double)) == 0) {
      ++resumed_;
      keep(index, *old);
      return *old;
    }
    if (old) forget_from(index);
    DesignEvaluation e = evaluate_everywhere(problem_, x);
    journal_.append({index}, to_row(e));
    keep(index, e);
    log(index, e);
    return e;
  }
  int resumed() const { return resumed_; }

 private:
  void log(std::size_t index, const DesignEvaluation& e) const {
    if (verbosity_ == Verbosity::quiet) return;
    std::string design;
    for (std::size_t i = 0; i < e.x.size(); ++i) design += fmt::format(" {}={:.6g}", problem_.free[i].name, e.x[i]);
    const std::string what = fmt::format("evaluation {}:{} -> {} {:.6g} ({})", index, design, to_string(problem_.objective.kind),
                                         e.objective, e.status != EvaluationStatus::ok ? e.message
                                                                       : feasible(problem_, e) ? "feasible" : "infeasible");
    // Every evaluation when verbose; otherwise every 25th, so that a long search shows progress.
    if (verbosity_ == Verbosity::verbose || index % 25 == 0) spdlog::info("{}", what);
  }

  void keep(std::size_t index, const DesignEvaluation& e) {
    kept_points_.push_back(index);
    const std::vector<double> row = to_row(e);
    kept_rows_.insert(kept_rows_.end(), row.begin(), row.end());
  }

  // The optimiser asked another design than the journal's at `index` (a forged or damaged record,
  // or a library that changed between the kill and the resume): that record and every later one
  // belong to another path. They are dropped, from memory and from the journal, and computed anew.
  void forget_from(std::size_t index) {
    std::size_t dropped = 0;
    for (std::size_t k = index; k < recovered_.size(); ++k) dropped += recovered_[k].has_value();
    std::fill(recovered_.begin() + static_cast<std::ptrdiff_t>(index), recovered_.end(), std::nullopt);
    journal_.rewrite(kept_points_, kept_rows_);
    spdlog::warn("the journal's evaluation {} is of another design than this run asks (the optimiser did not "
                 "repeat its path): it and the later journaled evaluations, {} in all, are dropped and computed again",
                 index, dropped);
  }

  const OptimizationProblem& problem_;
  Journal& journal_;
  Verbosity verbosity_;
  std::vector<std::uint64_t> kept_points_;  // what the journal must hold: every evaluation served so far
  std::vector<double> kept_rows_;
  std::vector<std::optional<DesignEvaluation>> recovered_;
  std::size_t asked_ = 0;
  int resumed_ = 0;
};

// The best design as a bat file beside the dataset, written whole or not at all.
void write_best_bat(const OptimizationProblem& p, const OptimizationHistory& h, const fs::path& path) {
  const DesignEvaluation& best = h.evaluations[static_cast<std::size_t>(h.best)];
  BatDesign design = design_at(p, best.x);
  design.name = p.base.name + " (optimised)";
  const std::string comment = fmt::format(
      "{}{} ({}): {} = {:.17g}, evaluation {} of {}.\n"
      "Written by sweetspot {} ({}); the base bat is {}.",
      best_comment_start, p.file.string(), p.title, to_string(p.objective.kind), best.objective, h.best, h.evaluations.size(), version,
      git_commit, p.base_source.toml_file.string());
  {
    std::ofstream out(temporary(path), std::ios::binary);
    out << bat_design_text(design, comment);
    if (!out) throw std::runtime_error(temporary(path).string() + ": cannot write the best design's bat file");
  }
  fs::rename(temporary(path), path);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

fs::path best_bat_path(const fs::path& output) {
  return output.parent_path() / (output.stem().string() + "_best.toml");
}

void run_optimization(const OptimizationProblem& problem, const OptimizeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::unique_ptr<OutputClaim> claim = claim_output(problem, options, rank);
  if (rank != 0) return serve(problem);

  spdlog::info("optimising {} ({} free parameters, {}, at most {} evaluations) on {} rank{} x {} thread{}",
               problem.file.string(), problem.free.size(), to_string(problem.optimizer.algorithm),
               problem.optimizer.max_evaluations, ranks, ranks == 1 ? "" : "s", omp_get_max_threads(),
               omp_get_max_threads() == 1 ? "" : "s");
  JournaledEvaluator evaluator(problem, claim->journal, options.verbosity);
  OptimizationHistory history;
  try {
    history = optimize_design(problem, std::ref(evaluator));
  } catch (...) {
    int command = Command::stop;  // release the serving ranks before the error goes up
    MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
    throw;
  }
  int command = Command::stop;
  MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);

  OptimizationRunInfo info{ranks, omp_get_max_threads(), seconds_since(start), evaluator.resumed(), {}};
  if (history.best >= 0) {
    info.best_bat_file = best_bat_path(options.output);
    write_best_bat(problem, history, info.best_bat_file);
  }
  write_dataset(options.output, optimization_dataset(problem, history, info));
  if (history.best < 0) {
    // A best bat file beside the dataset must be this dataset's: one left by an earlier run into
    // the same output (whose dataset this one has just replaced) is removed, and the log says so.
    const fs::path stale = best_bat_path(options.output);
    std::error_code error;
    const bool removed = fs::remove(stale, error);
    spdlog::warn("no feasible design among {} evaluations: no best bat file written{}", history.evaluations.size(),
                 removed  ? fmt::format(" (removed {}, an earlier run's best design)", stale.string())
                 : error ? fmt::format(" ({}, an earlier run's, could not be removed: {})", stale.string(), error.message())
                         : "");
  }
  claim->journal.remove();
  if (evaluator.resumed() > 0) spdlog::info("resumed: {} evaluations from the journal", evaluator.resumed());
  if (history.best >= 0) {
    const DesignEvaluation& best = history.evaluations[static_cast<std::size_t>(history.best)];
    std::string design;
    for (std::size_t i = 0; i < best.x.size(); ++i) design += fmt::format(" {}={:.9g}", problem.free[i].name, best.x[i]);
    spdlog::info("best: evaluation {}:{} -> {} {:.9g}", history.best, design, to_string(problem.objective.kind), best.objective);
  }
  spdlog::info("{} evaluations in {:.2f} s on {} rank{} x {} thread{} ({}); wrote {}",
               history.evaluations.size(), info.wall_time, ranks, ranks == 1 ? "" : "s", omp_get_max_threads(),
               omp_get_max_threads() == 1 ? "" : "s", history.stop_reason, options.output.string());
}

}  // namespace sweetspot
