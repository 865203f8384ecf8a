#include "sweetspot/impact/step_selection.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "sweetspot/impact/mode_selection.hpp"

namespace sweetspot {

namespace {

// The pulse duration T sets the step where the force varies on the pulse's own scale; a nearly
// dead ball's force falls within a few contact periods 1/omega_c of maximum compression, much
// shorter (e0 = 0.2: b = 70), and needs omega_c h below this. Measured on e0 = 0.2 impacts
// (18 and all modes, 1-150 m/s, 30-80 cm): omega_c h <= 0.25 keeps them within 6e-5 at T/80.
double contact_phase_for(double allowed) { return std::clamp(0.25 * std::pow(allowed / 5e-5, 0.25), 0.05, 2.0); }

// Exact stepping's error on a single contact of a baseball-like ball (e0 >= 0.5, a near 1.84),
// measured against Dormand-Prince at 1e-13 at 30.5, 60.5 and 80.5 cm, 1, 40 and 150 m/s, e0
// 0.5-1 by 0.1, 18 modes, steps T/160 to T/14: |dvf / vf| <= C (dt/T)^3.8 with C = 2.4 over
// the high-impact range (50-80 cm, 34-46 m/s), up to 7-9 elsewhere (150 m/s) but 2.1 at steps
// of T/56 and finer, and for e0 >= 0.8
// up to 11 at T/160, where the order falls to a + 1 (the ball's t^a onset): there the error is
// within 0.17 (dt/T)^(a+1) down to T/400 (e0 = 1, accuracy 1e-8). Taken at these bounds, the
// step errs within the accuracy without a second run to check it: a check doubles the cost.
// A softball-like ball (0.4 <= e0 < 0.5: b from 10 to 17) falls faster on expansion. At 30.5-
// 80.5 cm, 1 and 40 m/s, e0 0.40 and 0.45, 18 and auto modes the constant reaches 43 (T/14) and
// 38 (T/40, auto), irregularly (the events fall differently at each step); taken as 75. At 150
// m/s it reaches 210, which the closing-speed check (below) covers. At e0 = 0.35 it reaches 650
// at 40 m/s: below 0.4 the step is checked instead.
constexpr double softball_e0 = 0.4, baseball_e0 = 0.5;
double modelled_step_fraction(const Ball& ball, double accuracy) {
  if (ball.e0 < baseball_e0) return std::pow(accuracy / 75, 1 / 3.8);
  if (ball.e0 < 0.8) {
    const double coarse = std::pow(accuracy / 10, 1 / 3.8);
    return coarse >= 1.0 / 40 ? coarse : std::min(1.0 / 40, std::pow(accuracy / 3, 1 / 3.8));
  }
  return std::min(std::pow(accuracy / 12, 1 / 3.8), std::pow(accuracy / 0.17, 1 / (ball.a + 1)));
}
constexpr double modelled_coarsest = 1.0 / 14;  // of T: beyond it the error grows faster

// The exact stepper's step, rounded down to an eighth of an octave of 1 us: a step fitted to each
// point's pulse is new at every point of a study, and so would be every mode's response to it
// and its split parts (a sine, a cosine and a series per mode); on this grid the points of a
// study share a few steps, whose responses each thread remembers, for at most 9 % more steps.
double on_step_grid(double dt) { return 1e-6 * std::exp2(std::floor(8 * std::log2(dt / 1e-6)) / 8); }

// The model's constant holds for a smooth pulse, one that rises to a single maximum and falls:
// where the bat's ringing shakes the force (more maxima) or strikes the ball again, a check run is
// made. Measured with exact stepping at the model's step against a 16 times finer one (R161, the
// torpedo and maple_271 from 20 to 99 % of their length, 1-150 m/s, e0 0.4-0.8, auto and all
// modes, accuracies 1e-3 to 1e-6; 21 600 scenes): single-maximum pulses erred within 0.93 of the
// accuracy up to this closing speed (m/s), and up to 1.3 of it past it; pulses with more maxima
// up to 2.1 of it below 70 m/s and 7 of it past it.
constexpr double modelled_closing_speed = 130;

// A hollow barrel's wall is a stiff spring in series with the ball (docs/hollow-barrels.md),
// ringing at the hoop frequency while the ball presses it, and the force follows that ringing. A
// step near or past its period aliases it: the error stops falling with the step and scatters
// (1e-6 to 1.5e-4 of v_f here), beyond what the models above and step doubling see (the steps'
// ends show one force maximum). With the models' steps alone, over aluminium, alloy_bbcor and
// composite_bbcor (20-99 % of their length, 1-150 m/s, e0 0.4-0.8, 1e-6 to 1e-3; 7 560 whole
// impacts against exact stepping at 0.1 us, scripts/hollow_step_accuracy), up to 1.66x the
// accuracy (aluminium at 21.8 cm and 1 m/s at 1e-6, a 35 us step against a 37 us period;
// composite_bbcor at 16.8 cm and 40 m/s at 1e-4, 45 against 42 us). Held to half the wall's
// period, within 0.86x.
double wall_resolving_step(double omega_wall) { return on_step_grid(std::numbers::pi / omega_wall); }

}  // namespace

bool modelled_step(Method method, const Ball& ball) {
  return method == Method::exact && ball.e0 >= softball_e0 && ball.a >= 1.5 && ball.a <= 2.2;
}

CollisionOptions options_for_accuracy(CollisionOptions options, double accuracy, const Ball& ball,
                                      double approach_speed, double recoil, double omega_max, double omega_wall) {
  const double pulse = pulse_duration(ball, approach_speed, recoil);
  const double allowed = accuracy / 2;
  switch (options.method) {
    case Method::exact:
      if (modelled_step(options.method, ball)) {
        options.dt = on_step_grid(std::clamp(pulse * modelled_step_fraction(ball, accuracy), pulse / 5000,
                                             pulse * modelled_coarsest));
        break;
      }
      // Fast impacts (150 m/s) err about 4x more than the model at the same dt/T: budget for it.
      options.dt = on_step_grid(std::clamp(pulse * std::pow(allowed / 28, 1 / 3.8), pulse / 5000, pulse / 10));
      options.contact_phase_limit = contact_phase_for(allowed);
      break;
    case Method::rk4:
      options.dt = std::clamp(pulse * std::pow(allowed / 555, 0.25), pulse / 20000, pulse / 20);
      if (omega_max > 0) options.dt = std::min(options.dt, 0.99 * rk4_stability_limit / omega_max);
      options.contact_phase_limit = contact_phase_for(allowed);
      break;
    case Method::dopri:
      options.tolerance = allowed / 50;
      break;
  }
  if (options.method == Method::exact && omega_wall > 0)
    options.dt = std::min(options.dt, wall_resolving_step(omega_wall));
  return options;
}

Collision collide_within(const ModalContact& body, const Ball& ball, double ball_speed, CollisionOptions options,
                         double accuracy, CaughtAgain caught_again) {
  if (options.method == Method::dopri) return collide(body, ball, ball_speed, options);
  const auto done_unchecked = [caught_again](const Collision& c) {
    return c.status != CollisionStatus::ok || (caught_again != CaughtAgain::check && c.contacts > 1);
  };
  // The model's run, kept as the check's first run at this step where it is not trusted alone.
  std::optional<Collision> modelled;
  if (modelled_step(options.method, ball) && ball_speed + body.psi.dot(body.velocity0) <= modelled_closing_speed) {
    Collision c = collide(body, ball, ball_speed, options);
    if ((c.contacts == 1 && c.force_peaks == 1) || done_unchecked(c)) return c;  // else caught again or rough
    modelled = std::move(c);
  }
  constexpr int max_halvings = 8;
  const double gain = std::pow(2.0, std::min(ball.a + 1, 4.0)) - 1;
  CollisionOptions coarse = options;
  coarse.dt *= 2;
  Collision previous = collide(body, ball, ball_speed, coarse);  // may be refused (RK4): then one more halving
  if (previous.status == CollisionStatus::ok && done_unchecked(previous)) return previous;
  int agreed = 0;
  for (int halving = 0;; ++halving) {
    Collision c = halving == 0 && modelled ? std::move(*modelled) : collide(body, ball, ball_speed, options);
    if (done_unchecked(c)) return c;
    if (previous.status == CollisionStatus::ok) {
      const double scale = std::max(std::abs(c.ball_velocity), 0.05 * std::abs(ball_speed));
      const double estimate = std::abs(c.ball_velocity - previous.ball_velocity) / gain;
      agreed = estimate <= accuracy * scale ? agreed + 1 : 0;
      // A ball caught again may be caught differently at a finer step, after two coarse runs
      // agreed on a wrong second contact: there, two checks in a row must pass.
      if (agreed >= (c.contacts > 1 ? 2 : 1) || halving == max_halvings) return c;
    }
    previous = std::move(c);
    options.dt /= 2;
  }
}

}  // namespace sweetspot
