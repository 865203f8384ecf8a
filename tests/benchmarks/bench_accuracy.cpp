// The defaults' error and cost against N2000's settings and all modes, and what `accuracy = A` costs against the cheapest fixed step that meets A, with exact stepping,
// over the high-impact range of scenes: R161, 51 rad/s about 9 cm from the knob, e0 = 0.5,
// impacts at 50.5-79.5 cm (every 3 cm), ball at 34, 40 and 46 m/s; modes = auto (the default)
// and all. For each A: the largest fixed step (80 us down by 5 % at a time) whose worst relative
// vf error over the range is within A, its time per impact, the worst error and time of
// accuracy = A, and their ratio; also the worst error of a few fixed steps (the README's
// recommended settings). Errors are against Dormand-Prince at 1e-13 with the same modes; times
// are the least of 5 repeats (this machine is shared), in CPU time of this thread.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/n2000_settings.hpp"
#include "../n2000_scenes.hpp"

using namespace sweetspot;

namespace {

double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

std::vector<ImpactScene> high_impact_range(int modes) {
  std::vector<ImpactScene> scenes;
  for (int cm = 0; cm <= 29; cm += 3)
    for (double speed : {34.0, 40.0, 46.0}) {
      ImpactScene s = n2000_high_impact(0.505 + cm / 100.0, modes);
      s.ball_speed = speed;
      s.integrator.method = Method::exact;
      s.integrator.dt = default_step(Method::exact);
      s.integrator.find_collision_time = false;  // as a study that asks for vf alone
      scenes.push_back(s);
    }
  return scenes;
}

struct Measure {
  double worst = 0;    // relative vf error
  double seconds = 0;  // per impact
};

// Worst error and the least time per impact over 5 repeats of enough rounds to last 0.05 s.
Measure measure(const ModalBasis& basis, const std::vector<ImpactScene>& scenes, const std::vector<double>& reference) {
  Measure m;
  for (std::size_t i = 0; i < scenes.size(); ++i)
    m.worst = std::max(m.worst, std::abs(simulate_impact(basis, scenes[i]).vf / reference[i] - 1));
  const auto round = [&] {
    for (const ImpactScene& s : scenes) simulate_impact(basis, s);
  };
  double start = cpu_seconds();
  round();
  const int rounds = std::max(1, static_cast<int>(0.05 / std::max(cpu_seconds() - start, 1e-6)));
  m.seconds = 1e9;
  for (int repeat = 0; repeat < 5; ++repeat) {
    start = cpu_seconds();
    for (int r = 0; r < rounds; ++r) round();
    m.seconds = std::min(m.seconds, (cpu_seconds() - start) / (rounds * scenes.size()));
  }
  return m;
}

std::vector<ImpactScene> with_step(std::vector<ImpactScene> scenes, double dt) {
  for (ImpactScene& s : scenes) s.integrator.dt = dt;
  return scenes;
}

std::vector<ImpactScene> with_accuracy(std::vector<ImpactScene> scenes, double accuracy) {
  for (ImpactScene& s : scenes) s.step_accuracy = accuracy;
  return scenes;
}

// The worst relative vf error over the scenes at a fixed step.
double measure_error(const ModalBasis& basis, const std::vector<ImpactScene>& scenes,
                     const std::vector<double>& reference, double dt) {
  double worst = 0;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    ImpactScene s = scenes[i];
    s.integrator.dt = dt;
    const ImpactResult r = simulate_impact(basis, s);
    worst = std::max(worst, r.status == CollisionStatus::ok ? std::abs(r.vf / reference[i] - 1) : INFINITY);
  }
  return worst;
}

void report(const ModalBasis& basis, int modes, const char* label) {
  const std::vector<ImpactScene> scenes = high_impact_range(modes);
  std::vector<double> reference;
  for (ImpactScene s : scenes) {
    s.integrator.method = Method::dopri;
    s.integrator.dt = 1e-7;
    s.integrator.tolerance = 1e-13;
    reference.push_back(simulate_impact(basis, s).vf);
  }
  std::vector<std::pair<double, double>> errors;  // step, worst error
  for (double dt = 80e-6; dt > 4e-6; dt *= 0.95) errors.push_back({dt, measure_error(basis, scenes, reference, dt)});
  std::printf("modes = %s, %zu scenes (50.5-79.5 cm, 34-46 m/s, e0 0.5):\n", label, scenes.size());
  for (double dt : {10e-6, 20e-6, 25e-6, 40e-6, 60e-6}) {
    const Measure m = measure(basis, with_step(scenes, dt), reference);
    std::printf("  fixed %4.0f us: worst vf error %.1e, %6.1f us per impact\n", 1e6 * dt, m.worst, 1e6 * m.seconds);
  }
  std::printf("  %-9s %-28s %-30s %s\n", "accuracy", "cheapest fixed step", "accuracy = A", "cost ratio");
  for (double accuracy : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
    const auto meets = std::ranges::find_if(errors, [&](const auto& e) { return e.second <= accuracy; });
    if (meets == errors.end()) continue;
    const Measure fixed = measure(basis, with_step(scenes, meets->first), reference);
    const Measure chosen = measure(basis, with_accuracy(scenes, accuracy), reference);
    std::printf("  %-9.0e %5.1f us: %6.1f us/impact     worst %.1e: %6.1f us/impact   %.2f\n", accuracy,
                1e6 * meets->first, 1e6 * fixed.seconds, chosen.worst, 1e6 * chosen.seconds,
                chosen.seconds / fixed.seconds);
  }
}

}  // namespace

// The defaults against N2000's settings and all modes: vf error against all modes (Dormand-
// Prince at 1e-13) and time per impact, over the same range.
void compare_defaults(const ModalBasis& basis) {
  const std::vector<ImpactScene> all = high_impact_range(all_modes);
  std::vector<double> reference;
  for (ImpactScene s : all) {
    s.integrator.method = Method::dopri;
    s.integrator.dt = 1e-7;
    s.integrator.tolerance = 1e-13;
    reference.push_back(simulate_impact(basis, s).vf);
  }
  std::vector<ImpactScene> by_default = all, n2000 = all;
  for (ImpactScene& s : by_default) s.vibrational_modes = ImpactScene{}.vibrational_modes;
  for (ImpactScene& s : n2000) s = with_n2000_settings(s);
  std::printf("against all modes, 30 scenes (50.5-79.5 cm, 34-46 m/s, e0 0.5):\n");
  for (const auto& [label, scenes] : {std::pair<const char*, const std::vector<ImpactScene>&>{"default (exact 10 us, "
                                                                                               "modes auto)", by_default},
                                      {"exact 10 us, all modes", all}, {"N2000 (rk4 5 us, 18 modes)", n2000}}) {
    const Measure m = measure(basis, scenes, reference);
    std::printf("  %-32s worst vf error %.1e, %6.1f us per impact\n", label, m.worst, 1e6 * m.seconds);
  }
}

int main(int argc, char** argv) {
  const ModalBasis basis = compute_modes(load_bat(argc > 1 ? argv[1] : SWEETSPOT_R161), BeamTheory::timoshenko);
  compare_defaults(basis);
  report(basis, auto_modes, "auto");
  report(basis, all_modes, "all");
}
