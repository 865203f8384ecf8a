#include "sweetspot/impact/error_estimates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sweetspot {

double error_scale(double vf, double ball_speed) { return std::max(std::abs(vf), 0.05 * std::abs(ball_speed)); }

bool can_refine(int slices, BeamTheory theory) {
  const int finer = slicing_refinement * slices;
  return finer <= max_slices && (theory != BeamTheory::euler_bernoulli || finer <= max_euler_bernoulli_slices);
}

Bat bat_with_slices(BatDesign design, int slices) {
  design.slices = slices;
  return build_bat(design);
}

void add_slicing_error(ImpactResult& r, const ImpactResult& finer, double ball_speed) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (r.status != CollisionStatus::ok || finer.status != CollisionStatus::ok) {
    r.slicing_error = r.total_error = nan;
    return;
  }
  const double ratio = std::pow(static_cast<double>(slicing_refinement), slicing_order);
  r.slicing_error =
      slicing_safety * std::abs(r.vf - finer.vf) * ratio / (ratio - 1) / error_scale(r.vf, ball_speed);
  r.total_error = r.slicing_error + r.modes_error + r.step_error;
}

ImpactResult simulate_impact_with_errors(const ModalBasis& basis, const ModalBasis& finer_basis, ImpactScene scene) {
  scene.error_estimates = true;
  ImpactResult r = simulate_impact(basis, scene);
  scene.error_estimates = false;  // the finer impact's own step error is not needed
  add_slicing_error(r, simulate_impact(finer_basis, scene), scene.ball_speed);
  return r;
}

}  // namespace sweetspot
