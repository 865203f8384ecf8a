#include "sweetspot/study/parallel.hpp"

#include <mpi.h>
#include <omp.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <ranges>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/study/output_paths.hpp"
#include "sweetspot/study/affinity.hpp"
#include "sweetspot/study/dataset.hpp"
#include "sweetspot/study/journal.hpp"
#include "sweetspot/study/output_lock.hpp"
#include "sweetspot/study/study_point.hpp"
#include "sweetspot/study/study_provenance.hpp"
#include "sweetspot/study/study_results.hpp"

namespace sweetspot {

namespace {

enum Tag { tag_work = 1, tag_result = 2, tag_stop = 3, tag_design_modes = 4 };
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// What a rank's impacts add up to: their wall time, to tell the engine's overhead from them, and
// the points whose ball compressed past its radius, where the force law is not meant to hold.
struct RankTally {
  double impact_seconds = 0;
  std::size_t past_radius = 0;
  // Points by status. Every one but ok and no_contact (ball and bat never approach: an outcome,
  // not a failure) is logged with its reason, up to failures_logged.
  std::array<std::size_t, static_cast<std::size_t>(last_collision_status) + 1> by_status{};
  std::size_t failed() const {
    std::size_t n = 0;
    for (std::size_t k = 0; k < by_status.size(); ++k)
      if (is_failure(static_cast<CollisionStatus>(k))) n += by_status[k];
    return n;
  }
  static bool is_failure(CollisionStatus s) { return s != CollisionStatus::ok && s != CollisionStatus::no_contact; }
};

// Failed points logged one by one per rank; the rest are only counted, so that a study whose
// every point fails cannot flood the log.
constexpr std::size_t failures_logged = 20;

void log_rank_summary(int rank, int solves, double solve_seconds, const RankTally& tally, Clock::time_point start) {
  const double total = seconds_since(start);
  spdlog::info("rank {}: {} eigen-solves in {:.3f} s; {:.3f} s of {:.3f} s in impacts ({:.1f} % elsewhere)", rank,
               solves, solve_seconds, tally.impact_seconds, total, 100 * (1 - tally.impact_seconds / total));
  if (tally.past_radius > 0)
    spdlog::warn("rank {}: {} points compressed the ball past its radius (u_max > radius): the force law is not "
                 "meant for that",
                 rank, tally.past_radius);
  if (const std::size_t failed = tally.failed(); failed > 0) {
    std::string statuses;
    for (std::size_t k = 0; k < tally.by_status.size(); ++k)
      if (RankTally::is_failure(static_cast<CollisionStatus>(k)) && tally.by_status[k] > 0)
        statuses += fmt::format("{}{} {}", statuses.empty() ? "" : ", ", tally.by_status[k],
                                to_string(static_cast<CollisionStatus>(k)));
    spdlog::warn("rank {}: {} points failed ({}; {} of them with their reason above)", rank, failed, statuses,
                 std::min(failed, failures_logged));
  }
  if (const std::size_t none = tally.by_status[static_cast<std::size_t>(CollisionStatus::no_contact)]; none > 0)
    spdlog::info("rank {}: {} points without contact (ball and bat never approach there)", rank, none);
}

// "point 17 (z = 0.84, ball_speed = 30)": a grid point by its index and its axis values.
std::string describe_point(const Study& study, std::uint64_t index, const GridPoint& p) {
  std::string text = "point " + std::to_string(index);
  for (std::size_t k = 0; k < study.axes.size(); ++k) {
    const Axis& axis = study.axes[k];
    const std::size_t at = p.coords[k];
    const std::string value = axis.name == "bat"      ? study.bat_names[static_cast<std::size_t>(axis.values[at])]
                              : axis.labels.empty() ? fmt::format("{}", axis.values[at])
                                                    : axis.labels[at];
    text += (k ? ", " : " (") + axis.name + " = " + value + (k + 1 == study.axes.size() ? ")" : "");
  }
  return text;
}

// Marks a point failed for `why`; keeps the status alone when there is no memory for the reason.
void fail_point(ImpactResult& r, const char* why) noexcept {
  r.status = CollisionStatus::failed;
  try {
    r.message = why;
  } catch (...) {
  }
}

// A point never takes its worker down: whatever it throws makes it a failed point with the
// reason, and the sweep goes on. `basis_error` is why its modes could not be had, if they could not.
ImpactResult guarded_point(const GridPoint& point, const ModalBasis* basis, const std::string& basis_error) {
  ImpactResult r;
  try {
    if (!basis_error.empty()) throw std::runtime_error(basis_error);
    return simulate_point(point, basis);
  } catch (const std::exception& e) {
    fail_point(r, e.what());
  } catch (...) {
    fail_point(r, "an unknown error (not a std::exception)");
  }
  return r;
}

// Where the rank's threads may run, and a warning when they must share cores: under Slurm >= 22.05
// an srun without --cpus-per-task binds a rank to one core whatever sbatch asked for. The cores
// are those of the whole team (team_cores), not the calling thread's alone, which OMP_PROC_BIND
// has pinned to one core even in a right binding.
void log_rank_cores(int rank) {
  const std::vector<int> cores = team_cores();
  const int threads = omp_get_max_threads();
  spdlog::info("rank {}: {} OpenMP thread(s) on core(s) {} ({} allowed)", rank, threads,
               cores.empty() ? "unknown" : core_list(cores), cores.size());
  if (!cores.empty() && static_cast<int>(cores.size()) < threads)
    spdlog::warn("rank {}: {} OpenMP threads but only {} core(s) allowed ({}): the threads take turns; bind each rank "
                 "to as many cores as it has threads (srun --cpus-per-task, mpirun --map-by slot:PE=N; "
                 "docs/clusters.md)",
                 rank, threads, cores.size(), core_list(cores));
}

// The modal bases this rank has computed, one per (design, slices, theory, modes solved). A point
// gets what it needs solved (ModeRequest): the rigid modes alone when it keeps no vibrational
// mode (no eigen-solve), the study's largest fixed count, every mode for "all", and for "auto"
// the modes below its pulse's reach (auto_mode_request, from the rigid basis). A basis depends on
// the point alone, never on which points came first: any ranks give the same results.
class ModalCache {
  using Key = std::tuple<std::size_t, int, BeamTheory, int, double>;  // (design, slices, theory, request)
  using Model = std::tuple<std::size_t, int, BeamTheory>;

 public:
  explicit ModalCache(const Study& study) : study_(study) {
    for (const Axis& axis : study.axes)
      if (axis.name == "modes")
        for (const double m : axis.values) largest_count_ = std::max(largest_count_, static_cast<int>(m));
  }
  // The point's basis, or nullptr with `error` saying why it could not be had (the bat file
  // changed since the study was checked, say); a failure is kept too, not retried per point.
  const ModalBasis* get(const GridPoint& p, std::string& error) {
    const std::optional<ModeRequest> request = request_for(p, error);
    return request ? basis(p, *request, error) : nullptr;
  }
  // Solves, over the OpenMP threads, the bases that `points` need and the cache lacks: a chunk of
  // many bats (a design study) would otherwise solve them on one thread while the others wait.
  // Each basis is the same whichever thread solves it, so results stay bitwise the same.
  void prefetch(const std::vector<GridPoint>& points) {
    std::map<Key, std::pair<const GridPoint*, ModeRequest>> missing;
    for (const GridPoint& p : points) {
      std::string ignored;  // get() reports it, point by point
      const std::optional<ModeRequest> request = needs_modal_basis(p.kind) ? request_for(p, ignored) : std::nullopt;
      if (request && !known(p, *request)) missing.try_emplace(key_of(p, *request), &p, *request);
    }
    if (missing.size() < 2) return;  // one solve gains nothing from the threads
    const std::vector<std::pair<const GridPoint*, ModeRequest>> jobs(std::views::values(missing).begin(),
                                                                    std::views::values(missing).end());
    std::vector<std::optional<ModalBasis>> solved(jobs.size());
    std::vector<std::string> errors(jobs.size());
    const auto start = Clock::now();
#pragma omp parallel for schedule(dynamic)
    for (long j = 0; j < static_cast<long>(jobs.size()); ++j) {
      try {
        solved[j] = solve(*jobs[j].first, jobs[j].second);
      } catch (const std::exception& e) {
        errors[j] = e.what();
      }
    }
    solve_seconds_ += seconds_since(start);
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      if (solved[j]) store(*jobs[j].first, jobs[j].second, std::move(*solved[j]));
      else fail(*jobs[j].first, jobs[j].second, errors[j]);
    }
  }
  int solves() const { return solves_; }
  double solve_seconds() const { return solve_seconds_; }
  // Before a chunk: forgets every basis once they come from more than cached_models models (a bat
  // at a slicing holds its rigid basis and a few partial ones, one per half-octave of `auto`'s
  // reach; counting those apart made a study at a stated accuracy, whose ladder holds each bat at
  // three slicings or more, solve its bases anew at every chunk).
  void make_room() {
    std::set<Model> models;
    for (const Key& key : std::views::keys(cache_)) models.insert(model_of_key(key));
    for (const Key& key : std::views::keys(errors_)) models.insert(model_of_key(key));
    if (models.size() <= cached_models) return;
    cache_.clear();
    errors_.clear();
    complete_from_.clear();
  }

 private:
  // What the point needs solved; for "auto", read from its bat's rigid basis (no eigen-solve).
  std::optional<ModeRequest> request_for(const GridPoint& p, std::string& error) {
    const int modes = p.scene.vibrational_modes;
    if (modes == 0) return ModeRequest::rigid_only();
    if (modes == all_modes) return ModeRequest::all();
    if (modes != auto_modes) return ModeRequest::lowest(std::max(modes, largest_count_));
    const ModalBasis* rigid = basis(p, ModeRequest::rigid_only(), error);
    return rigid ? std::optional(auto_mode_request(p.scene, *rigid)) : std::nullopt;
  }

  static Model model_of(const GridPoint& p) { return std::make_tuple(p.design, p.slices, p.theory); }
  static Model model_of_key(const Key& k) { return std::make_tuple(std::get<0>(k), std::get<1>(k), std::get<2>(k)); }
  static Key key_of(const GridPoint& p, ModeRequest request) {
    return std::make_tuple(p.design, p.slices, p.theory, request.vibrational, request.below_omega);
  }

  // A basis the cache holds for the request, or one that took every mode at a lower frequency
  // (the same dense solve, so reusing it changes nothing).
  const ModalBasis* cached(const GridPoint& p, ModeRequest request) const {
    if (const auto it = complete_from_.find(model_of(p));
        it != complete_from_.end() && request.below_omega >= it->second.first)
      return it->second.second;
    const auto it = cache_.find(key_of(p, request));
    return it == cache_.end() ? nullptr : &it->second;
  }
  bool known(const GridPoint& p, ModeRequest request) const {
    return cached(p, request) || errors_.contains(key_of(p, request));
  }

  ModalBasis solve(const GridPoint& p, ModeRequest request) const {
    // A point at other slices (with_design_slices): the design cut anew, so that knots and
    // dimensions are sampled from their shape.
    if (p.slices < 0) return compute_modes(bat_with_slices(study_.design_specs[p.design], -p.slices), p.theory, request);
    Bat bat = study_.designs[p.design];
    if (p.slices > 0) bat = resample(bat, p.slices);
    return compute_modes(bat, p.theory, request);
  }
  const ModalBasis* store(const GridPoint& p, ModeRequest request, ModalBasis solved) {
    if (!request.is_rigid_only()) ++solves_;
    const ModalBasis* kept = &cache_.emplace(key_of(p, request), std::move(solved)).first->second;
    if (request.below_omega > 0 && kept->complete()) {
      auto& lowest = complete_from_.try_emplace(model_of(p), request.below_omega, kept).first->second;
      if (request.below_omega < lowest.first) lowest = {request.below_omega, kept};
    }
    return kept;
  }
  std::string fail(const GridPoint& p, ModeRequest request, const std::string& why) {
    const std::string error = "the modes of " + study_.bats[p.bat].string() + ": " + why;
    errors_.emplace(key_of(p, request), error);
    return error;
  }

  const ModalBasis* basis(const GridPoint& p, ModeRequest request, std::string& error) {
    if (const ModalBasis* kept = cached(p, request)) return kept;
    if (const auto it = errors_.find(key_of(p, request)); it != errors_.end()) return error = it->second, nullptr;
    try {
      const auto start = Clock::now();
      ModalBasis solved = solve(p, request);
      if (!request.is_rigid_only()) solve_seconds_ += seconds_since(start);
      return store(p, request, std::move(solved));
    } catch (const std::exception& e) {
      error = fail(p, request, e.what());
      return nullptr;
    }
  }

  const Study& study_;
  int largest_count_ = 0;
  std::map<Key, ModalBasis> cache_;
  std::map<Key, std::string> errors_;
  std::map<Model, std::pair<double, const ModalBasis*>> complete_from_;  // lowest "below" that took all
  int solves_ = 0;
  double solve_seconds_ = 0;
};

GridPoint without_estimates_point(GridPoint p) {
  p.scene.error_estimates = false;
  return p;
}

// The point on its design cut into `slices` slices, which ModalCache::solve cuts from the design
// itself (slices negative): knots and dimensions sampled from their shape, a slice profile exact
// at any multiple of its rows.
GridPoint with_design_slices(GridPoint p, int slices) {
  p.slices = -slices;
  return p;
}

int point_slices(const Study& study, const GridPoint& p) {
  if (p.slices < 0) return -p.slices;
  return p.slices > 0 ? p.slices : study.designs[p.design].slices();
}

// A point at a stated accuracy first runs at the slicing its ladder starts at (ladder_start) where
// its bat serves this many points or more; else at the bat's own. A solve at eight times the
// slices costs about a hundred impacts (8 ms against 75 us, the wood study at 1e-4), and starting
// finer saves an impact at about half the points: the wood study's 31 points per bat ran 869
// points/s from twice the slices against 1 075 from their own.
constexpr std::size_t points_per_bat_for_finer_start = 1000;

GridPoint at_ladder_start(const Study& study, const GridPoint& p) {
  if (p.kind != StudyKind::impact || !(p.scene.accuracy > 0) ||
      study.points() < points_per_bat_for_finer_start * study.designs.size())
    return p;
  return with_design_slices(p, ladder_start(point_slices(study, p), p.theory, p.scene.accuracy));
}

// The point at twice and four times its slices (as far as it can be cut), for the slicing error of
// a point that asks for its estimates without a stated accuracy (error_estimates.hpp); their own
// estimates are not asked. None for a point that asks no estimate or states an accuracy.
std::vector<GridPoint> finer_points(const Study& study, const GridPoint& p) {
  if (p.kind != StudyKind::impact || !p.scene.error_estimates || p.scene.accuracy > 0) return {};
  std::vector<GridPoint> finer;
  for (int times = 1, slices = point_slices(study, p); times <= 2 && can_refine(point_slices(study, p), p.theory, times);
       ++times)
    finer.push_back(with_design_slices(without_estimates_point(p), slices *= slicing_refinement));
  return finer;
}

// The points at a stated accuracy whose dropped modes took more than their share, run again with
// that share divided (widened_scene), on bases solved as far as it asks (solved first, as a
// chunk's are); `points` then say so. A point whose wider basis cannot be had keeps its result.
void widen_mode_shares(ModalCache& cache, std::vector<GridPoint>& points, std::vector<ImpactResult>& results) {
  std::vector<std::size_t> again(points.size());
  std::iota(again.begin(), again.end(), std::size_t{0});
  while (!again.empty()) {
    std::vector<std::size_t> rerun;
    std::vector<GridPoint> wider;
    for (const std::size_t i : again)
      if (std::optional<ImpactScene> scene = widened_scene(points[i].scene, results[i])) {
        rerun.push_back(i);
        wider.push_back(points[i]);
        wider.back().scene = std::move(*scene);
      }
    cache.prefetch(wider);
    std::vector<const ModalBasis*> bases(wider.size());
    std::vector<std::string> reasons(wider.size());
    for (std::size_t k = 0; k < wider.size(); ++k) bases[k] = cache.get(wider[k], reasons[k]);
#pragma omp parallel for schedule(dynamic)
    for (std::size_t k = 0; k < wider.size(); ++k)
      if (bases[k]) {
        results[rerun[k]] = guarded_point(wider[k], bases[k], {});
        points[rerun[k]] = wider[k];
      }
    again.clear();
    for (std::size_t k = 0; k < wider.size(); ++k)
      if (bases[k]) again.push_back(rerun[k]);
  }
}

// The chunk's points at a stated accuracy (`results` holds their first rung, at_ladder_start):
// each climbs its SlicingLadder, a rung for every point at once, each rung's bases solved before
// its impacts, as a chunk's are, so that any ranks and threads give the same results.
void refine_to_accuracy(const Study& study, ModalCache& cache, const std::vector<GridPoint>& grid,
                        std::vector<ImpactResult>& results) {
  std::vector<std::size_t> pending;
  std::vector<GridPoint> rung;
  std::vector<ImpactResult> rung_results;
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (grid[i].kind == StudyKind::impact && grid[i].scene.accuracy > 0) {
      pending.push_back(i);
      rung.push_back(grid[i]);
      rung_results.push_back(std::move(results[i]));
    }
  std::vector<SlicingLadder> ladders;
  for (const std::size_t i : pending) ladders.emplace_back(point_slices(study, grid[i]), grid[i].theory, grid[i].scene);
  std::vector<char> done(pending.size(), 0);
  for (;;) {
    widen_mode_shares(cache, rung, rung_results);
    for (std::size_t k = 0; k < pending.size(); ++k)
      if (!done[k] && (done[k] = ladders[k].add(std::move(rung_results[k]), rung[k].scene)))
        results[pending[k]] = ladders[k].take_result();
    std::size_t kept = 0;
    for (std::size_t k = 0; k < pending.size(); ++k)
      if (!done[k]) {
        if (kept != k) pending[kept] = pending[k], ladders[kept] = std::move(ladders[k]);
        ++kept;
      }
    pending.resize(kept);
    ladders.erase(ladders.begin() + static_cast<std::ptrdiff_t>(kept), ladders.end());
    if (pending.empty()) return;
    rung.resize(kept);
    rung_results.assign(kept, ImpactResult{});
    done.assign(kept, 0);
    for (std::size_t k = 0; k < kept; ++k) {
      rung[k] = with_design_slices(grid[pending[k]], ladders[k].next_slices());
      rung[k].scene = ladders[k].next_scene(rung[k].scene);
    }
    cache.prefetch(rung);
    std::vector<const ModalBasis*> bases(kept);
    std::vector<std::string> reasons(kept);
    for (std::size_t k = 0; k < kept; ++k) bases[k] = cache.get(rung[k], reasons[k]);
#pragma omp parallel for schedule(dynamic)
    for (std::size_t k = 0; k < kept; ++k)
      if (bases[k]) rung_results[k] = guarded_point(rung[k], bases[k], reasons[k]);
    for (std::size_t k = 0; k < kept; ++k)
      if (!bases[k]) {  // the finer rung cannot be solved: the finest so far, inaccurate, and why
        ladders[k].stop(reasons[k]);
        results[pending[k]] = ladders[k].take_result();
        done[k] = 1;
      }
  }
}

// Computes a chunk of points with the OpenMP threads; rows in the order of `points`. Adds the
// chunk to the rank's tally.
std::vector<double> compute_chunk(const Study& study, const OutputLayout& layout, ModalCache& cache,
                                  const std::vector<std::uint64_t>& points, RankTally& tally) {
  std::vector<GridPoint> grid(points.size());
  std::vector<const ModalBasis*> bases(points.size(), nullptr);  // none for the wall and the toy
  std::vector<std::string> reasons(points.size());  // why a point failed: first its modes', then its own
  cache.make_room();
  for (std::size_t i = 0; i < points.size(); ++i) grid[i] = at_ladder_start(study, grid_point(study, points[i]));
  // The finer points of those asking for their slicing error, and their bases.
  std::vector<std::vector<GridPoint>> finer(points.size());
  std::vector<std::vector<const ModalBasis*>> finer_bases(points.size());
  std::vector<GridPoint> to_solve = grid;
  for (std::size_t i = 0; i < points.size(); ++i) {
    finer[i] = finer_points(study, grid[i]);
    to_solve.insert(to_solve.end(), finer[i].begin(), finer[i].end());
  }
  cache.prefetch(to_solve);  // the chunk's bats solved over the threads
  for (std::size_t i = 0; i < points.size(); ++i) {  // then looked up serially: the cache is not shared
    if (needs_modal_basis(grid[i].kind)) bases[i] = cache.get(grid[i], reasons[i]);
    std::string ignored;  // a finer basis that failed: the slicing error stays NaN
    for (const GridPoint& f : finer[i]) finer_bases[i].push_back(cache.get(f, ignored));
  }
  std::vector<ImpactResult> results(points.size());
  std::vector<char> lost(points.size(), 0);  // char, not bool: each thread writes its own
  const auto start = Clock::now();
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < points.size(); ++i) {
    try {
      results[i] = guarded_point(grid[i], bases[i], reasons[i]);
      if (finer[i].empty()) continue;
      std::vector<double> vf{results[i].vf};
      bool finer_ok = true;
      for (std::size_t k = 0; k < finer[i].size() && finer_ok; ++k) {
        finer_ok = finer_bases[i][k] != nullptr;
        if (!finer_ok) break;
        const ImpactResult f = guarded_point(finer[i][k], finer_bases[i][k], {});
        finer_ok = f.status == CollisionStatus::ok;
        vf.push_back(f.vf);
      }
      add_slicing_error(results[i], vf, 0, finer_ok, grid[i].scene.ball_speed);
    } catch (...) {  // no memory left even to record the point: all NaN (status -1 in the dataset)
      lost[i] = 1;
      results[i].status = CollisionStatus::failed;  // and no further slicings
    }
  }
  refine_to_accuracy(study, cache, grid, results);
  std::vector<double> rows(points.size() * layout.width);
  std::size_t past_radius = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (lost[i]) {
      std::fill_n(rows.data() + i * layout.width, layout.width, std::nan(""));
      continue;
    }
    const ImpactResult& r = results[i];
    // The toy model's ball is dimensionless: no radius to pass.
    if (grid[i].kind != StudyKind::toy && grid[i].kind != StudyKind::certification &&
        r.u_max > grid[i].scene.ball.radius)
      ++past_radius;
    layout.extract(r, rows.data() + i * layout.width);
    if (RankTally::is_failure(r.status)) reasons[i] = r.message;
  }
  tally.impact_seconds += seconds_since(start);
  tally.past_radius += past_radius;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CollisionStatus status = lost[i] ? CollisionStatus::failed : results[i].status;
    if (RankTally::is_failure(status) && tally.failed() < failures_logged)
      spdlog::warn("{} {}: {}", describe_point(study, points[i], grid[i]), to_string(status), reasons[i]);
    ++tally.by_status[static_cast<std::size_t>(status)];
  }
  return rows;
}

class Progress {
 public:
  Progress(std::size_t total, std::size_t already, Verbosity v) : total_(total), done_(already), start_done_(already), verbosity_(v) {}
  void add(std::size_t n) {
    done_ += n;
    const auto now = Clock::now();
    const double since_report = std::chrono::duration<double>(now - last_).count();
    if (verbosity_ == Verbosity::quiet || (verbosity_ == Verbosity::normal && since_report < 2 && done_ < total_)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = (done_ - start_done_) / std::max(elapsed, 1e-9);
    spdlog::info("{}/{} points ({:.1f} %), {:.0f} points/s, ETA {:.0f} s", done_, total_, 100.0 * done_ / total_, rate,
                 (total_ - done_) / std::max(rate, 1e-9));
  }

 private:
  std::size_t total_, done_, start_done_;
  Verbosity verbosity_;
  Clock::time_point start_ = Clock::now(), last_ = Clock::now();
};

// Where the output `name` sits in a point's row, or -1 when the study does not ask it.
int column_of(const OutputLayout& layout, std::string_view name) {
  const auto it = std::ranges::find(layout.names, name);
  return it == layout.names.end() ? -1 : layout.offsets[it - layout.names.begin()];
}

// Why a journal's row cannot be a finished point of this study, or "" when it can: a status
// outside the enumeration, a failed point with values, an ok point without its exit speed (an
// inaccurate point keeps what it got, which may be NaN where a finer slicing could not be solved).

std::string recovered_row_problem(const OutputLayout& layout, const double* row) {
  const int status_at = column_of(layout, "status"), vf_at = column_of(layout, "vf");
  if (status_at < 0) return "";  // without a status there is nothing the values must agree with
  const double status = row[status_at];
  const bool named = status >= 0 && status <= 255 && status == std::floor(status) &&
                     std::string_view(to_string(static_cast<CollisionStatus>(static_cast<int>(status)))) != "unknown";
  if (!named) return fmt::format("status {} is none of the statuses", status);
  if (status == static_cast<double>(CollisionStatus::ok))
    return vf_at >= 0 && !std::isfinite(row[vf_at]) ? fmt::format("status ok with vf = {}", row[vf_at]) : "";
  if (stores_values(static_cast<CollisionStatus>(static_cast<int>(status)))) return "";
  for (int i = 0; i < layout.width; ++i)
    if (i != status_at && !std::isnan(row[i])) return fmt::format("a failed point with a value {}", row[i]);
  return "";
}

// Rank 0's hold on the output for the whole run, taken before any rank works: the paths checked,
// the lock taken, the journal read (and the points it recovered).
struct OutputClaim {
  OutputLock lock;
  Journal journal;

  OutputClaim(const Study& study, const OutputLayout& layout, const RunOptions& options)
      : lock(options.output),
        journal(Journal::path_for(options.output), journal_key(study, layout.width), options.resume,
                [&layout](const double* row) { return recovered_row_problem(layout, row); }) {
    if (!journal.dropped().empty()) spdlog::warn("{}: {}", Journal::path_for(options.output).string(), journal.dropped());
    if (options.resume && journal.recovered_points().empty())
      spdlog::info("resuming: no finished point in a journal: computing all {} points", study.points());
  }

  // Before the claim: no lock file is created where the output cannot or must not be.
  static void check(const Study& study, const RunOptions& options) {
    const std::filesystem::path journal = Journal::path_for(options.output);
    check_output_paths(options.output,
                       {dataset_temporary_path(options.output), journal, Journal::rewrite_path(journal),
                        OutputLock::path_for(options.output)},
                       study_inputs(study));
  }
};

// Rank 0 claims the output; every rank learns whether it did, and all throw RunRefused with rank
// 0's reason if not.
std::unique_ptr<OutputClaim> claim_output(const Study& study, const OutputLayout& layout, const RunOptions& options,
                                          int rank) {
  std::unique_ptr<OutputClaim> claim;
  std::string refusal;
  if (rank == 0) try {
      OutputClaim::check(study, options);
      claim = std::make_unique<OutputClaim>(study, layout, options);
    } catch (const InputError& e) {
      refusal = e.what();
    }
  share_refusal(refusal);
  return claim;
}

// Rank 0: hands out chunks, computes chunks itself between requests, journals every result.
class Coordinator {
 public:
  Coordinator(const Study& study, const OutputLayout& layout, const RunOptions& options, int ranks, Journal& journal)
      : study_(study), layout_(layout), ranks_(ranks), cache_(study), journal_(journal),
        rows_(study.points() * layout.width, std::nan("")), done_(study.points(), false),
        resumed_(resume_journaled()), progress_(study.points(), resumed_, options.verbosity) {
    if (resumed_ > 0) spdlog::info("resuming: {} of {} points already done", resumed_, study.points());
    for (std::size_t point : task_order(study))
      if (!done_[point]) todo_.push_back(point);
    const std::size_t threads = static_cast<std::size_t>(omp_get_max_threads());
    chunk_ = std::clamp<std::size_t>(todo_.size() / (ranks * threads * 16), 4 * threads, 4096);
    // Rank 0 answers requests only between its own chunks: small ones keep the workers' wait short.
    own_chunk_ = ranks > 1 ? std::max<std::size_t>(threads, chunk_ / 64) : chunk_;
  }

  void run() {
    int active = ranks_ - 1;
    while (active > 0 || next_ < todo_.size()) {
      serve_requests(active, next_ >= todo_.size());
      if (next_ < todo_.size()) {
        const std::vector<std::uint64_t> chunk = take_chunk(own_chunk_);
        finish(chunk, compute_chunk(study_, layout_, cache_, chunk, tally_));
      }
    }
  }

  void log_summary(Clock::time_point start) const { log_rank_summary(0, cache_.solves(), cache_.solve_seconds(), tally_, start); }

  const std::vector<double>& rows() const { return rows_; }
  std::size_t resumed_points() const { return resumed_; }

 private:
  // The journal's points kept as done, but those of a failing status: the journal holds no text,
  // so they are computed again (deterministic, and rare) for the reason the log gives, and dropped
  // from the journal, which will hold them once more. Returns how many are kept.
  std::size_t resume_journaled() {
    const std::vector<std::uint64_t>& recovered = journal_.recovered_points();
    const int status_at = column_of(layout_, "status");
    std::vector<std::uint64_t> kept;
    std::vector<double> kept_rows;
    for (std::size_t i = 0; i < recovered.size(); ++i) {
      const double* row = journal_.recovered_values().data() + i * layout_.width;
      if (status_at >= 0 && RankTally::is_failure(static_cast<CollisionStatus>(static_cast<int>(row[status_at]))))
        continue;
      store_row(recovered[i], row);
      kept.push_back(recovered[i]);
      kept_rows.insert(kept_rows.end(), row, row + layout_.width);
    }
    if (kept.size() < recovered.size()) journal_.rewrite(kept, kept_rows);
    return kept.size();
  }

  std::vector<std::uint64_t> take_chunk(std::size_t size) {
    const std::size_t end = std::min(next_ + size, todo_.size());
    std::vector<std::uint64_t> chunk(todo_.begin() + next_, todo_.begin() + end);
    next_ = end;
    return chunk;
  }

  // Answers every waiting worker; blocks for one when there is nothing left to compute here.
  void serve_requests(int& active, bool block) {
    while (active > 0) {
      int waiting = 0;
      MPI_Status status;
      if (block) MPI_Probe(MPI_ANY_SOURCE, tag_result, MPI_COMM_WORLD, &status), waiting = 1;
      else MPI_Iprobe(MPI_ANY_SOURCE, tag_result, MPI_COMM_WORLD, &waiting, &status);
      if (!waiting) return;
      receive_result(status);
      const std::vector<std::uint64_t> chunk = next_ < todo_.size() ? take_chunk(chunk_) : std::vector<std::uint64_t>{};
      if (chunk.empty()) {
        MPI_Send(nullptr, 0, MPI_UINT64_T, status.MPI_SOURCE, tag_stop, MPI_COMM_WORLD);
        --active;
      } else {
        MPI_Send(chunk.data(), static_cast<int>(chunk.size()), MPI_UINT64_T, status.MPI_SOURCE, tag_work, MPI_COMM_WORLD);
      }
    }
  }

  // A result message: the chunk's point indices (as doubles, exact below 2^53) then its rows.
  void receive_result(const MPI_Status& status) {
    int count = 0;
    MPI_Get_count(&status, MPI_DOUBLE, &count);
    std::vector<double> message(count);
    MPI_Recv(message.data(), count, MPI_DOUBLE, status.MPI_SOURCE, tag_result, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const std::size_t n = count / (1 + layout_.width);
    std::vector<std::uint64_t> chunk(message.begin(), message.begin() + n);
    finish(chunk, std::vector<double>(message.begin() + n, message.end()));
  }

  void finish(const std::vector<std::uint64_t>& chunk, const std::vector<double>& rows) {
    if (chunk.empty()) return;
    journal_.append(chunk, rows);
    for (std::size_t i = 0; i < chunk.size(); ++i) store_row(chunk[i], rows.data() + i * layout_.width);
    progress_.add(chunk.size());
  }

  void store_row(std::uint64_t point, const double* row) {
    std::copy_n(row, layout_.width, rows_.begin() + point * layout_.width);
    done_[point] = true;
  }

  const Study& study_;
  const OutputLayout& layout_;
  int ranks_;
  ModalCache cache_;
  Journal& journal_;
  std::vector<double> rows_;
  std::vector<bool> done_;
  std::size_t resumed_;
  Progress progress_;
  std::vector<std::uint64_t> todo_;
  std::size_t next_ = 0, chunk_ = 1, own_chunk_ = 1;
  RankTally tally_;
};

void work(const Study& study, const OutputLayout& layout, int rank) {
  const auto start = Clock::now();
  RankTally tally;
  ModalCache cache(study);
  std::vector<double> message;  // first request: no result
  while (true) {
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_DOUBLE, 0, tag_result, MPI_COMM_WORLD);
    MPI_Status status;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_UINT64_T, &count);
    std::vector<std::uint64_t> chunk(count);
    MPI_Recv(chunk.data(), count, MPI_UINT64_T, 0, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (status.MPI_TAG == tag_stop) break;
    const std::vector<double> rows = compute_chunk(study, layout, cache, chunk, tally);
    message.assign(chunk.begin(), chunk.end());
    message.insert(message.end(), rows.begin(), rows.end());
  }
  log_rank_summary(rank, cache.solves(), cache.solve_seconds(), tally, start);
}

// Each bat's lowest modes, for the dataset (none for a study that keeps no vibrational mode): one
// eigen-solve per bat, shared among the ranks once the sweep is done, rank 0 gathering them. Left
// to rank 0 alone they were a serial tail that grows with the bats, not the ranks (0.7 s of the
// wood study's 3.4 s on 2 ranks). Each design is solved as rank 0 would: the same dataset.
void send_design_modes(const Study& study, int rank, int ranks) {
  if (!keeps_vibrations(study)) return;
  const std::vector<double> packed =
      pack_design_modes(design_modes(study, dataset_mode_count(study), rank, ranks), rank, ranks);
  MPI_Send(packed.data(), static_cast<int>(packed.size()), MPI_DOUBLE, 0, tag_design_modes, MPI_COMM_WORLD);
}

DesignModes gather_design_modes(const Study& study, int ranks) {
  if (!keeps_vibrations(study)) return {};
  DesignModes modes = design_modes(study, dataset_mode_count(study), 0, ranks);
  for (int rank = 1; rank < ranks; ++rank) {
    MPI_Status status;
    MPI_Probe(rank, tag_design_modes, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_DOUBLE, &count);
    std::vector<double> packed(count);
    MPI_Recv(packed.data(), count, MPI_DOUBLE, rank, tag_design_modes, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    unpack_design_modes(packed, rank, ranks, modes);
  }
  return modes;
}

}  // namespace

void share_refusal(std::string refusal) {
  int length = static_cast<int>(refusal.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  refusal.resize(static_cast<std::size_t>(length));
  MPI_Bcast(refusal.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  if (!refusal.empty()) throw RunRefused(refusal);
}

void run_study(const Study& study, const RunOptions& options) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const OutputLayout layout(study);
  const std::unique_ptr<OutputClaim> claim = claim_output(study, layout, options, rank);
  log_rank_cores(rank);  // after the output is checked: a refused run prints its one line alone
  if (rank != 0) {
    work(study, layout, rank);
    send_design_modes(study, rank, ranks);
    return;
  }
  const auto start = Clock::now();
  spdlog::info("study {} ({}): {} points on {} rank(s) x {} thread(s)", study.file.string(), to_string(study.kind),
               study.points(), ranks, omp_get_max_threads());
  Coordinator coordinator(study, layout, options, ranks, claim->journal);
  coordinator.run();
  const RunInfo info{ranks, omp_get_max_threads(), seconds_since(start), coordinator.resumed_points(),
                     Journal::path_for(options.output)};
  const auto output_start = Clock::now();
  const DesignModes modes = gather_design_modes(study, ranks);
  const double modes_seconds = seconds_since(output_start);
  Dataset dataset = make_dataset(study, layout, coordinator.rows(), modes, info);
  if (options.finish) options.finish(dataset);
  write_dataset(options.output, dataset);
  spdlog::info("rank 0: the bats' modes for the dataset in {:.3f} s, the dataset in {:.3f} s", modes_seconds,
               seconds_since(output_start) - modes_seconds);
  claim->journal.remove();  // the lock goes with the claim, after the journal
  coordinator.log_summary(start);
  // The rate is the sweep's (the points' own cost); the run's whole time adds the bats' modes and
  // the dataset (logged above), which grow with the bats and the outputs, not the points.
  spdlog::info("wrote {}: {} points swept in {:.3f} s ({:.3f} s in all), {:.0f} points/s", options.output.string(),
               study.points(), info.wall_time, seconds_since(start), study.points() / info.wall_time);
}

}  // namespace sweetspot
