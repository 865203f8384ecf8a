#pragma once
// The integration settings that meet a stated accuracy (relative exit-speed error), from the
// pulse the scene makes: each method's error was measured against its step relative to the
// pulse duration T (sweetspot convergence, README "Numerics") and is modelled as
//   exact: 7 (dt/T)^3.8 on the high-impact scene, up to 4x that at 150 m/s;
//   rk4: 555 (dt/T)^4;   dopri: up to about 20x its tolerance;
// and the settings chosen keep within half the accuracy asked for, for margin. The fixed-step
// methods also keep omega_c h (the contact's own ringing) below a bound that tightens with the
// accuracy: a nearly dead ball's force falls within a few 1/omega_c, far inside T.
// Calibrated on single contacts; where the ball is caught again (handle, 150 m/s, e0 <= 0.35)
// errors can exceed the model several times.
#include "sweetspot/ball.hpp"
#include "sweetspot/collision.hpp"

namespace sweetspot {

// Sets dt and contact_phase_limit (exact, rk4: dt never above RK4's stability limit for
// omega_max) or the tolerance (dopri).
CollisionOptions options_for_accuracy(CollisionOptions options, double accuracy, const Ball& ball,
                                      double approach_speed, double recoil, double omega_max);

}  // namespace sweetspot
