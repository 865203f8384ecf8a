#pragma once
// An impact in the plane of the swing (docs/oblique.md): the ball's centre off the bat's axis by
// the undercut D, the swing tilted, the pitch spinning, friction between ball and bat.
//
// Geometry. In the plane across the bat's axis at the struck point, the bat's point moves along
// the swing's line at swing_tilt above the horizontal and the pitch comes along the same line
// against it (Sawicki, Hubbard & Stronge, Am. J. Phys. 71, 1152 (2003), take the pitch's and the
// bat's paths in one plane too). The line of centres, from the bat's axis to the ball's centre,
// leans theta = asin(D / (R + R_bat)) above the swing's line; it is held fixed through the
// contact (the ball rolls a few millimetres on a 3-cm barrel in a millisecond).
//
// Normal. Along the line of centres the collision is sweetspot's head-on one, unchanged: the
// ball's speed and the bat's swing (translation and rotation in the swing's plane) each scaled by
// cos theta, the flexible beam and its modes, the ball law (collision.hpp, impact.hpp). A
// round bat's bending modes are the same in every plane through its axis, so the normal
// component drives the same beam. D = 0 leaves every number of the head-on impact as it was.
//
// Tangential. Across the line of centres (tangential_contact.hpp): friction with the ball's grip,
// driven by the normal force the head-on collision records. The bat is rigid across the line: it
// recoils with the rigid bat's effective mass at the struck point (free or pivoted, as in the
// normal direction) and rolls about its own axis with its axial moment of inertia; its bending in
// that plane is left out (the tangential impulse is a fraction of the normal one; Cross & Nathan
// 2006 and Kensrud, Nathan & Smith 2017 also take the bat rigid across the line).
#include <string>

#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

// The launch of a head-on impact: vf along the swing's line (tilt 0), no spin.
BallLaunch head_on_launch(double vf);

// R + R_bat(z): how far the ball's centre may lie off the bat's axis and still touch it.
double contact_reach(const ModalBasis& basis, const ImpactScene& scene);

// Why the ball misses the bat (|undercut| >= contact_reach), or "" when it touches it.
std::string miss_reason(const ModalBasis& basis, const ImpactScene& scene);

// The oblique impact: status no_contact with miss_reason when the ball misses; otherwise the
// head-on collision along the line of centres and the friction across it. ImpactResult::vf and
// launch.speed are the exit velocity's magnitude; e_eff, e_a and the rig's measures are the
// normal collision's; the energy balance holds both halves (ImpactEnergy: ball_spin,
// bat_tangential, friction). simulate_impact calls this for every scene that is not head-on.
ImpactResult simulate_oblique_impact(const ModalBasis& basis, const ImpactScene& scene);

}  // namespace sweetspot
