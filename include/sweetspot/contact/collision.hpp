#pragma once
// The collision of a ball with a modal system (physics.md §4): the ball's nonlinear spring drives
// modes a_n'' + 2 zeta_n omega_n a_n' + omega_n^2 a_n = -F psi_n (zeta_n = 0 but for a hollow
// barrel's wall, README "Hollow barrels"). The same integrator serves the bat (its kept modes at
// the impact point), the rigid immovable wall (no modes at all) and the toy model of N2000 App. A.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "sweetspot/contact/ball.hpp"

namespace sweetspot {

// What the ball sees of the struck body. Modal coordinates are mass-orthonormal, so the energy is
// sum 1/2 (a_n'^2 + omega_n^2 a_n^2); modes with omega = 0 are rigid motions.
struct ModalContact {
  Eigen::VectorXd omega;      // rad/s
  Eigen::VectorXd psi;        // mode shapes at the contact point
  Eigen::VectorXd velocity0;  // a_n'(0) at first touch (a_n(0) = 0)
  // Static (residual) flexibility of the modes left out, sum psi_n^2 / omega_n^2 over them: they
  // are too fast for the pulse to excite and follow the force quasi-statically, yielding c F.
  double residual_compliance = 0;
  // Viscous damping ratio zeta_n of each mode, in [0, 1): empty when every mode is undamped (a
  // solid bat's beam modes). Only a hollow barrel's wall mode is damped, by zeta = eta / 2 of its
  // loss factor. Undamped modes follow the undamped code paths bit for bit; a damped mode needs
  // omega_n > 0.
  Eigen::VectorXd damping_ratio;

  int count() const { return static_cast<int>(omega.size()); }
  double damping(int n) const { return damping_ratio.size() ? damping_ratio(n) : 0.0; }
  bool damped() const { return damping_ratio.size() && (damping_ratio.array() != 0).any(); }
};

// How the contact phase is integrated (see README, "Numerics"):
//   rk4    classical RK4 at the fixed step dt, as N2000; refused when omega_max dt > 2.8
//   exact  exact modal stepping: closed-form modes under a cubic Hermite force, step dt set by
//          the force pulse alone (unconditionally stable)
//   dopri  adaptive Dormand-Prince 5(4) to `tolerance`, starting at dt: the reference path
enum class Method { rk4, exact, dopri };
const char* to_string(Method method);
// Throws InputError for anything but "rk4", "exact" or "dopri".
Method parse_method(const std::string& text);
// The step each method takes unless told otherwise: N2000's 5 us for RK4; 10 us for exact
// stepping (vf to about 2e-8 over the high-impact scenes, README "Numerics"); the first trial
// step for Dormand-Prince.
double default_step(Method method);

// The defaults are sweetspot's recommended settings, the same for the library, the program and
// studies: exact modal stepping at its default step. N2000's (RK4 at 5 us) are one call away,
// with_n2000_settings() (n2000_settings.hpp).
struct CollisionOptions {
  Method method = Method::exact;
  double dt = 1e-5;                // s: the step (rk4, exact) or the first step (dopri)
  double tolerance = 1e-9;         // relative local error per step (dopri)
  double window = 5e-3;            // s of free flight followed after each separation
  double max_contact_time = 0.05;  // s; a contact lasting longer is reported as no separation
  bool record_force = false;       // keep the force samples F(t) in the result
  bool find_collision_time = true;  // the 99 % impulse time (NaN when not asked: a study may not)
  // Integrate what the damped modes dissipate (the energy balance's term damping_dissipated); a
  // scene that asks for no energy leaves it out (NaN), which spares a quadrature per step over
  // every damped mode. The motion is the same either way.
  bool damping_loss = true;
  // rk4, exact: steps are halved until omega_c h stays below this at both ends, omega_c the
  // contact's own ringing (the ball's stiffness against the contact's mobility). 2 keeps them
  // stable; a stated accuracy asks less (a nearly dead ball's force falls within a few 1/omega_c).
  double contact_phase_limit = 2;
  // exact: a body that only moves rigidly (no vibrating or damped mode, no residual compliance)
  // collides in closed form, without steps or their error, unless the force profile is recorded;
  // false steps it all the same (to measure the stepper itself).
  bool rigid_closed_form = true;
  // End the collision where the ball first touches again after a separation (contacts = 2): for a
  // caller that runs such an impact again and needs nothing else of this run.
  bool stop_when_caught_again = false;
};

// The collision time is when this fraction of the impulse has been delivered.
inline constexpr double collision_time_fraction = 0.99;

// A contact takes at most this many steps: a mistyped step (1e-12 for 1e-5) or tolerance would
// otherwise fill the memory with force samples. Past it the point fails.
inline constexpr double max_contact_steps = 1e7;
// The finest step (s) a user may give the fixed-step methods: one that could take more than
// max_contact_steps to cover max_contact_time is refused before any work.
inline constexpr double finest_step = CollisionOptions{}.max_contact_time / max_contact_steps;
// The coarsest: a baseball's contact lasts about a millisecond, and a step that long steps over it
// (a mistyped 1e300 overflowed: status non_finite).
inline constexpr double coarsest_step = 1e-3;
inline bool valid_step(double dt) { return dt >= finest_step && dt <= coarsest_step; }

// unbalanced: integrated, but the energy balance is off by more than 1 % (impact.hpp).
// no_contact: ball and struck point never approach (closing speed <= 0 at first touch): there is
// no collision, and every result is NaN. A ball at rest struck by a moving bat (a tee) collides.
// failed: the point could not be computed (an error, or more than max_contact_steps in a
// contact); the message says why. A study records it and goes on.
// Datasets list every status by value (flag_values): `failed` stays the last.
// inaccurate: a stated accuracy could not be met (error_estimates.hpp); the values are the
// closest the program came, its estimates say how close.
enum class CollisionStatus { ok, no_separation, non_finite, refused_step, unbalanced, no_contact, failed, inaccurate };
inline constexpr CollisionStatus last_collision_status = CollisionStatus::inaccurate;  // for loops over all
const char* to_string(CollisionStatus status);

struct ForceSample {
  double t;      // s since first touch
  double force;  // N
  double rate;   // dF/dt, N/s
};

struct Collision {
  CollisionStatus status = CollisionStatus::ok;
  std::string message;         // why, when the status is not ok
  double ball_velocity = 0;    // final, m/s, positive away from the bat
  Eigen::VectorXd a, a_dot;    // final modal state
  double contact_time = 0;     // s in contact, summed over contacts
  double collision_time = 0;   // s from first touch until 99 % of the impulse is delivered (or NaN)
  double u_max = 0;            // largest compression, m
  double peak_force = 0;       // N
  double impulse = 0;          // N s delivered to the ball
  double dissipated = 0;       // J lost in the ball (loop areas of all contacts)
  // J dissipated by the damped modes (the barrel wall), int sum 2 zeta_n omega_n a_n'^2 dt from
  // first touch to the last separation (contacts and the free flights between them), integrated
  // alongside the modes, not inferred from the balance; 0 without damping.
  double damping_dissipated = 0;
  int contacts = 0;
  // The force's maxima over all contacts, at the steps' ends (where the compression's rate turns
  // from rising to falling): one for a smooth pulse, more where the bat's ringing shakes it.
  int force_peaks = 0;
  double step = 0;                 // s, the fixed step taken (0: Dormand-Prince's adaptive steps)
  std::vector<ForceSample> force;  // only with record_force

  // Energy of mode n: 1/2 (a_n'^2 + omega_n^2 a_n^2) (what it holds, damped or not).
  double mode_energy(const ModalContact& body, int n) const;
};

// The largest stable RK4 step is 2.8 / omega_max; a larger one is refused, never integrated.
inline constexpr double rk4_stability_limit = 2.8;

Collision collide(const ModalContact& body, const Ball& ball, double ball_speed, const CollisionOptions& options);

// F and dF/dt at time t in [p.t, q.t], from the cubic Hermite interpolant between two samples.
ForceSample interpolate_force(const ForceSample& p, const ForceSample& q, double t);

// Time at which a fraction of the impulse is delivered, from the force samples (cubic Hermite).
double impulse_time(const std::vector<ForceSample>& force, double fraction);

}  // namespace sweetspot
