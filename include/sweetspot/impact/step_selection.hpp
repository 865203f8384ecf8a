#pragma once
// The integration settings that meet a stated accuracy (relative exit-speed error), from the
// pulse the scene makes: each method's error was measured against its step relative to the
// pulse duration T (sweetspot convergence, README "Numerics") and is modelled as
//   exact: a baseball-like ball (modelled_step: e0 >= 0.5, a in [1.5, 2.2]) within 10 (dt/T)^3.8
//          (e0 >= 0.8: 12 (dt/T)^3.8, and 0.17 (dt/T)^(a+1) at fine steps; a softball-like
//          one, 0.4 <= e0 < 0.5, 75 (dt/T)^3.8)
//          on a single contact whose force rises to one maximum and falls, wherever on the bat
//          at closing speeds up to 130 m/s (where the ringing bat shakes the force into more
//          maxima, up to 7x more); other balls 7 (dt/T)^3.8
//          on the high-impact scene, up to 4x that at 150 m/s;
//   rk4: 555 (dt/T)^4;   dopri: up to about 20x its tolerance;
// For a modelled ball up to 130 m/s the step is taken as the model says, and one run is made
// where its force has one maximum: its cost is within 2x the cheapest fixed step that meets the
// accuracy (tests/benchmarks/bench_accuracy).
// Elsewhere the settings keep within half the accuracy asked for, for margin, and the
// fixed-step methods also keep omega_c h (the contact's own ringing) below a bound that
// tightens with the accuracy: a nearly dead ball's force falls within a few 1/omega_c, far
// inside T. Those models are calibrated on single contacts; where the ball is caught again
// (handle, 150 m/s, e0 <= 0.35) a step they choose can err several times more, or even miss a
// contact. So collide_within() checks each such result against a run at twice the step.
#include "sweetspot/contact/ball.hpp"
#include "sweetspot/contact/collision.hpp"

namespace sweetspot {

// Whether the method's step for an accuracy comes from its error model alone (no check run).
bool modelled_step(Method method, const Ball& ball);

// Sets dt and contact_phase_limit (exact, rk4: dt never above RK4's stability limit for
// omega_max) or the tolerance (dopri). omega_wall is the frequency of a hollow barrel's wall mode
// in the contact (0 for none): the exact stepper's step then resolves its ringing (below).
CollisionOptions options_for_accuracy(CollisionOptions options, double accuracy, const Ball& ball,
                                      double approach_speed, double recoil, double omega_max, double omega_wall = 0);

// The collision at options.dt; for a modelled step (above) that is all, unless the ball is
// caught again, its force has more than one maximum (Collision::force_peaks) or it closes faster
// than 130 m/s. Otherwise (exact, rk4) with its exit speed's error checked: a run at twice
// the step costs half as much, and their difference over 2^p - 1 (p = a + 1 at most 4, the order
// the ball's t^a onset leaves at fine steps) bounds the finer run's error. While that exceeds
// `accuracy` (relative to |v_f|, or to 5 % of the ball's speed when v_f is near 0), the step
// halves, 8 times at most. Dormand-Prince, which controls its own error, runs once.
// A caller that runs the impact again wherever the ball is caught again (auto modes, which then
// keep every solved mode) asks for the first run that shows it, unchecked: checking a result that
// is thrown away cost two runs more, or three. `stop` ends that run where the ball touches again
// (CollisionOptions::stop_when_caught_again): the caller needs nothing more of it.
enum class CaughtAgain { check, return_unchecked, stop };
Collision collide_within(const ModalContact& body, const Ball& ball, double ball_speed, CollisionOptions options,
                         double accuracy, CaughtAgain caught_again = CaughtAgain::check);

}  // namespace sweetspot
