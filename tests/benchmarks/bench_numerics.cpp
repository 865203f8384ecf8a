// Error against run time on N2000's high-impact scene (R161, 40 m/s, 51 rad/s about 9 cm, e0 0.5):
//  1. all 168 modes at a relative vf error of 1e-6: exact modal stepping (the studies' default)
//     against RK4, each at the largest step that reaches that error (for RK4 also stable);
//  2. modes = auto with a total relative vf error of 1e-4: impacts per second per core.
// Errors are measured against the tightest Dormand-Prince run; times are medians of repeats.
#include <cmath>
#include <cstdio>
#include <vector>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"
#include "../n2000_scenes.hpp"
#include "timing.hpp"

using namespace sweetspot;

namespace {

ImpactScene scene(double z, int modes, Method method, double dt) {
  ImpactScene s = n2000_high_impact(z, modes);
  s.integrator.method = method;
  s.integrator.dt = dt;
  return s;
}

double reference_vf(const ModalBasis& basis, double z) {
  ImpactScene s = scene(z, all_modes, Method::dopri, 1e-7);
  s.integrator.tolerance = 1e-13;
  return simulate_impact(basis, s).vf;
}

// Seconds per impact over the given scenes: the median of 7 repeats, each of enough rounds over
// the scenes to last about 0.2 s (shorter ones catch too much of the machine's other work).
double seconds_per_impact(const ModalBasis& basis, const std::vector<ImpactScene>& scenes) {
  const auto round = [&] {
    for (const ImpactScene& s : scenes) simulate_impact(basis, s);
  };
  const int rounds = std::max(1, static_cast<int>(0.2 / median_seconds(3, round)));
  const double t = median_seconds(7, [&] {
    for (int r = 0; r < rounds; ++r) round();
  });
  return t / (rounds * scenes.size());
}

// The largest step of `steps` (descending) whose vf error stays within `target`.
double largest_step(const ModalBasis& basis, double z, Method method, const std::vector<double>& steps, double target,
                    double reference) {
  for (double dt : steps) {
    const ImpactResult r = simulate_impact(basis, scene(z, all_modes, method, dt));
    if (r.status == CollisionStatus::ok && std::abs(r.vf / reference - 1) <= target) return dt;
  }
  return steps.back();
}

}  // namespace

int main(int argc, char** argv) {
  const ModalBasis basis =
      compute_modes(load_bat(argc > 1 ? argv[1] : SWEETSPOT_R161), BeamTheory::timoshenko);
  const double z = 0.605, target = 1e-6;
  const double reference = reference_vf(basis, z);
  const double rk4_stable = 0.999 * rk4_stability_limit / basis.omega.maxCoeff();
  std::vector<double> exact_steps;  // 80 us down by 5 % at a time
  for (double dt = 80e-6; dt > 5e-6; dt *= 0.95) exact_steps.push_back(dt);
  const double exact_dt = largest_step(basis, z, Method::exact, exact_steps, target, reference);
  const double rk4_dt = largest_step(basis, z, Method::rk4, {rk4_stable, rk4_stable / 2, rk4_stable / 4}, target,
                                     reference);
  const double exact_time = seconds_per_impact(basis, {scene(z, all_modes, Method::exact, exact_dt)});
  const double rk4_time = seconds_per_impact(basis, {scene(z, all_modes, Method::rk4, rk4_dt)});
  std::printf("all %d modes, z = %.3f m, vf error <= %.0e:\n", basis.count(), z, target);
  std::printf("  exact at %5.1f us: %8.1f us per impact\n", 1e6 * exact_dt, 1e6 * exact_time);
  std::printf("  rk4   at %5.2f us: %8.1f us per impact (largest stable step %.2f us)\n", 1e6 * rk4_dt, 1e6 * rk4_time,
              1e6 * rk4_stable);
  std::printf("  exact is %.1fx faster than rk4\n", rk4_time / exact_time);

  // modes = auto: the modes' share 5e-5 and the integration's (exact at 60 us) below 5e-5.
  std::vector<ImpactScene> scenes;
  double worst = 0;
  for (double zi = 0.555; zi < 0.83; zi += 0.02) {
    ImpactScene s = scene(zi, auto_modes, Method::exact, 60e-6);
    s.mode_tolerance = 5e-5;
    s.integrator.find_collision_time = false;  // as in a study that asks for vf alone
    scenes.push_back(s);
    worst = std::max(worst, std::abs(simulate_impact(basis, s).vf / reference_vf(basis, zi) - 1));
  }
  const double auto_time = seconds_per_impact(basis, scenes);
  std::printf("modes = auto (tolerance 5e-5), exact at 60 us, z = 0.555..0.815 m: worst vf error %.1e,\n", worst);
  std::printf("  %.0f impacts per second per core\n", 1 / auto_time);
  // The same impacts with the 99 % impulse time found too, as a study asking for collision_time
  // and Python's impacts() (which gives every output) run them: the like-for-like rate for
  // tests/benchmarks/bench_python.py.
  for (ImpactScene& s : scenes) s.integrator.find_collision_time = true;
  std::printf("  %.0f impacts per second per core with the collision time\n", 1 / seconds_per_impact(basis, scenes));
}
