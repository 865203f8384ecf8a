#pragma once
// Internal: the collision of the ball with a body that only moves rigidly (no vibrational mode, no
// residual compliance, no damping), in closed form. The compression u then obeys one equation,
// u'' = -mu F(u), mu = 1/m + sum psi_n^2 the contact's mobility, and each branch of the force law
// conserves energy: u' = w0 sqrt(1 - (u/u_m)^(a+1)) closing, e w0 sqrt(1 - (u/u_m)^(b+1)) parting.
// So u_m, the exit speeds and the impulse are algebraic, and the times along a branch are
// incomplete Beta integrals (the complete ones are Gamma functions): no time step, no step error.
#include <optional>

#include "sweetspot/contact/collision.hpp"

namespace sweetspot::detail {

// int_0^1 dx / sqrt(1 - x^q) = B(1/q, 1/2) / q: the time a mass on a spring F ~ u^(q-1) takes
// to stop from speed c, in units of u_m / c.
double whole_branch_time(double q);

// The time u' = c sqrt(1 - (u/u_m)^q) takes from u = 0 to the u where (u/u_m)^q = level, in
// units of u_m / c: int_0^x dx / sqrt(1 - x^q), x = level^(1/q), for q > 1 and level in [0, 1].
double branch_time(double level, double q);

// The collision in closed form, or nothing where it does not apply (a vibrating, damped or
// compliant body, a recorded force profile, no approach, a contact past max_contact_time): the
// stepper takes those.
std::optional<Collision> rigid_collision(const ModalContact& body, const Ball& ball, double ball_speed,
                                         const CollisionOptions& options);

}  // namespace sweetspot::detail
