#include "sweetspot/impact/error_estimates.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The Richardson term's denominator: 2^p - 1 for one doubling of the slices.
double richardson_gain() { return std::pow(static_cast<double>(slicing_refinement), slicing_order) - 1; }

}  // namespace

double error_scale(double vf, double ball_speed) { return std::max(std::abs(vf), 0.05 * std::abs(ball_speed)); }

bool can_refine(int slices, BeamTheory theory, int times) {
  long finer = slices;
  for (int k = 0; k < times; ++k) finer *= slicing_refinement;
  return finer <= max_slices && (theory != BeamTheory::euler_bernoulli || finer <= max_euler_bernoulli_slices);
}

int ladder_start(int slices, BeamTheory theory, double accuracy) {
  return accuracy < 1e-3 && can_refine(slices, theory, 3) ? slicing_refinement * slices : slices;
}

Bat bat_with_slices(BatDesign design, int slices) {
  design.slices = slices;
  return build_bat(design);
}

double slicing_error(const std::vector<double>& vf, std::size_t level) {
  const std::size_t m = vf.size();
  if (m < 2 || level >= m) return nan;
  const double last = std::abs(vf[m - 1] - vf[m - 2]);
  const double finest = m == 2 ? last : std::max(last / richardson_gain(), std::abs(vf[m - 2] - vf[m - 3]) /
                                                                               ((richardson_gain() + 1) * richardson_gain()));
  return slicing_safety * (std::abs(vf[level] - vf[m - 1]) + finest);
}

void add_slicing_error(ImpactResult& r, const std::vector<double>& vf, std::size_t level, bool finer_ok,
                       double ball_speed) {
  if (r.status != CollisionStatus::ok || !finer_ok) {
    r.slicing_error = r.total_error = nan;
    return;
  }
  r.slicing_error = slicing_error(vf, level) / error_scale(r.vf, ball_speed);
  r.total_error = r.slicing_error + r.modes_error + r.step_error;
}

AccuracyBudget accuracy_budget(double accuracy) { return {accuracy / 2, accuracy / 4, accuracy / 4}; }

double slicing_allowance(double accuracy, double modes_error, double step_error) {
  const AccuracyBudget budget = accuracy_budget(accuracy);
  const auto taken = [](double estimate, double share) { return std::isnan(estimate) ? share : estimate; };
  return accuracy - taken(modes_error, budget.modes) - taken(step_error, budget.step);
}

double auto_mode_tolerance(const ImpactScene& scene) {
  return scene.accuracy > 0 ? accuracy_budget(scene.accuracy).modes / (mode_share_overrun * scene.mode_share_divisor)
                            : scene.mode_tolerance;
}

std::optional<ImpactScene> widened_scene(const ImpactScene& scene, const ImpactResult& r) {
  if (!(scene.accuracy > 0) || scene.vibrational_modes != auto_modes || r.status != CollisionStatus::ok) return {};
  const double share = accuracy_budget(scene.accuracy).modes;
  if (!(r.modes_error > share) || scene.mode_share_divisor >= max_mode_share_divisor) return {};
  ImpactScene wider = scene;
  // At least a half-octave further (auto_mode_request's steps): a smaller step may ask the same
  // basis again.
  const double half_octave = 2 * std::sqrt(2.0);
  wider.mode_share_divisor =
      std::min(scene.mode_share_divisor * std::max(r.modes_error / share, half_octave), max_mode_share_divisor);
  if (scene.integrator.method == Method::exact) wider.checked_step = r.step_used;
  return wider;
}

ImpactScene scene_for_accuracy(ImpactScene scene) {
  if (!(scene.accuracy > 0)) return scene;
  if (scene.vibrational_modes >= 0)
    throw InputError("accuracy: a fixed number of modes (" + std::to_string(scene.vibrational_modes) +
                     ") cannot be held to an accuracy; expected modes = \"auto\" (the default) or \"all\"");
  if (scene.step_accuracy > 0)
    throw InputError("accuracy excludes step_accuracy (the accuracy chooses the step): give one of them");
  scene.mode_tolerance = auto_mode_tolerance(scene);
  scene.step_accuracy = accuracy_budget(scene.accuracy).step;
  return scene;
}

SlicingLadder::SlicingLadder(int slices, BeamTheory theory, const ImpactScene& scene)
    : theory_(theory),
      accuracy_(scene.accuracy),
      ball_speed_(scene.ball_speed),
      exact_(scene.integrator.method == Method::exact),
      next_slices_(slices) {}

double SlicingLadder::slicing_allowance() const {
  return sweetspot::slicing_allowance(accuracy_, result_.modes_error, result_.step_error);
}

ImpactScene SlicingLadder::next_scene(ImpactScene scene) const {
  scene.checked_step = checked_step_;
  scene.mode_share_divisor = mode_share_divisor_;
  return scene;
}

bool SlicingLadder::add(ImpactResult r, const ImpactScene& ran) {
  mode_share_divisor_ = ran.mode_share_divisor;
  r.slices_used = next_slices_;
  vf_.push_back(r.vf);
  result_ = std::move(r);
  if (result_.status != CollisionStatus::ok) return true;
  if (exact_ && vf_.size() == 1) checked_step_ = result_.step_used;
  const bool can_double = can_refine(next_slices_, theory_);
  next_slices_ *= slicing_refinement;
  if (vf_.size() < 3 && can_double) return false;  // three slicings at least
  add_slicing_error(result_, vf_, vf_.size() - 1, true, ball_speed_);
  if (result_.slicing_error <= slicing_allowance()) return true;
  const bool nothing_left = !(slicing_allowance() > 0);
  if (can_double && !nothing_left) return false;
  char why[320];
  if (nothing_left)
    std::snprintf(why, sizeof why, "accuracy %.3g: the modes' and the step's estimated errors (%.3g and %.3g%s) leave "
                  "nothing of it for the slicing", accuracy_, result_.modes_error,
                  std::isnan(result_.step_error) ? accuracy_budget(accuracy_).step : result_.step_error,
                  std::isnan(result_.step_error) ? ", its share: not estimated here" : "");
  else if (std::isnan(result_.slicing_error))  // the bat's own slicing could not be cut even once
    std::snprintf(why, sizeof why,
                  "accuracy %.3g: the bat's %d slices cannot be cut finer (max_slices %d, or %d for Euler-Bernoulli), "
                  "so its slicing error cannot be estimated; expected a bat of fewer slices",
                  accuracy_, result_.slices_used, max_slices, max_euler_bernoulli_slices);
  else
    std::snprintf(why, sizeof why,
                  "accuracy %.3g needs the bat cut finer than %d slices (max_slices %d, or %d for Euler-Bernoulli); "
                  "the slicing's estimated error there is %.3g, where the modes and the step leave it %.3g",
                  accuracy_, result_.slices_used, max_slices, max_euler_bernoulli_slices, result_.slicing_error,
                  slicing_allowance());
  result_.status = CollisionStatus::inaccurate;
  result_.message = why;
  return true;
}

void SlicingLadder::stop(const std::string& why) {
  result_.slicing_error = result_.total_error = nan;
  if (vf_.size() >= 2) add_slicing_error(result_, vf_, vf_.size() - 1, true, ball_speed_);
  char text[200];
  std::snprintf(text, sizeof text, "accuracy %.3g: the bat cannot be cut finer than %d slices here: ", accuracy_,
                result_.slices_used);
  result_.status = CollisionStatus::inaccurate;
  result_.message = text + why;
}

ImpactResult simulate_within_accuracy(const BasisAtSlices& basis_at, int slices, BeamTheory theory,
                                      const ImpactScene& scene) {
  SlicingLadder ladder(slices, theory, scene);
  for (bool first = true;; first = false) {
    ImpactScene rung = ladder.next_scene(scene);
    const ModalBasis* basis = nullptr;
    try {
      basis = &basis_at(ladder.next_slices(), rung);
    } catch (const InputError& impractical) {  // the bat's own slicing's refusal is the user's
      if (first) throw;
      ladder.stop(impractical.what());
      return ladder.take_result();
    }
    ImpactResult r = simulate_impact(*basis, rung);
    // Dropped modes past their share: again on a wider basis, while one can be solved (else the
    // result stands, and the ladder says what it leaves for the slicing).
    for (std::optional<ImpactScene> wider; (wider = widened_scene(rung, r));) {
      try {
        r = simulate_impact(basis_at(ladder.next_slices(), *wider), *wider);
        rung = *wider;
      } catch (const InputError&) {
        break;
      }
    }
    if (ladder.add(std::move(r), rung)) return ladder.take_result();
  }
}

ImpactResult simulate_impact_with_errors(const ModalBasis& basis, const std::vector<const ModalBasis*>& finer,
                                         ImpactScene scene) {
  scene.error_estimates = true;
  ImpactResult r = simulate_impact(basis, scene);
  scene.error_estimates = false;  // the finer impacts' exit speeds alone are used
  std::vector<double> vf{r.vf};
  bool finer_ok = !finer.empty();
  for (const ModalBasis* b : finer) {
    const ImpactResult f = simulate_impact(*b, scene);
    finer_ok = finer_ok && f.status == CollisionStatus::ok;
    vf.push_back(f.vf);
  }
  add_slicing_error(r, vf, 0, finer_ok, scene.ball_speed);
  return r;
}

}  // namespace sweetspot
