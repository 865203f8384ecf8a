#pragma once
// The tangential half of an oblique ball-bat contact (docs/oblique.md): friction across the line
// of centres, driven by the normal force N(t) the head-on collision computes (collision.hpp).
//
// Both bodies are rigid across the line of centres: the ball (mass m, radius R, moment of inertia
// I about its centre) translates and spins; the bat's struck point recoils with the rigid bat's
// mobility and the bat rolls about its own long axis. The force between them is Coulomb friction
// with the ball's tangential compliance (Cross, Am. J. Phys. 73, 914 (2005); Cross & Nathan, Am.
// J. Phys. 74, 896 (2006); Kensrud, Nathan & Smith, Am. J. Phys. 85, 503 (2017)): the contact
// grips and the ball's surface stretches like a spring of stiffness k_t (with a damper, as lossy
// as the ball is normally) while |F| < mu N, and slides at |F| = mu N otherwise, until the
// sliding stops (the stretch moving as fast as the slip). k_t follows the normal contact stiffness
// at the same force, k_t = grip_stiffness * dN/du of the loading law N = k1 u^a (Mindlin's ratio
// 2 (1 - nu) / (2 - nu) of tangential to normal stiffness is 2/3 for an incompressible ball,
// nu = 1/2). An infinite grip_stiffness is the rigid-body model of the textbooks: slide until the
// contact point comes to rest, then roll.
//
// Signs: t is the tangent of the contact in the plane of the swing; the slip s is the velocity of
// the ball's contact point relative to the bat's along t, s = v - R w - (V + R_b W) with v the
// ball's velocity and w its spin (positive spin turns the contact point against +t), V the bat's
// struck point and W its roll (positive moves the bat's surface at the contact along +t). A force
// F on the ball along t changes v by F/m, w by -R F / I; -F on the bat changes V by -F * mobility
// and W by -R_b F / I_axis. The ball's angular momentum about the contact point, I w + m R v, is
// unchanged by any F: the identity the tests check.
#include <vector>

#include "sweetspot/contact/collision.hpp"

namespace sweetspot {

struct TangentialBodies {
  double ball_mass = 0.145;     // kg
  double ball_radius = 0.0366;  // m
  double ball_inertia = 0;      // kg m^2 about the ball's centre
  double bat_mobility = 0;      // 1/kg: the struck point's velocity per unit impulse from the bat's rigid recoil
  double bat_radius = 0;        // m: the struck section's outer radius
  double bat_axial_inertia = 0; // kg m^2 about the bat's long axis (infinite: the bat does not roll)

  // 1 / mu_t: the slip's change per unit impulse on the ball.
  double inverse_mass() const;
};

struct TangentialMotion {
  double ball_velocity = 0;  // m/s along t
  double ball_spin = 0;      // rad/s
  double bat_velocity = 0;   // m/s along t, the struck point's rigid motion
  double bat_roll = 0;       // rad/s about the bat's long axis

  double slip(const TangentialBodies& b) const;
  // The kinetic energy of these components (J): both bodies, the bat's from its point mobility.
  double energy_change_from(const TangentialMotion& initial, const TangentialBodies& b) const;
};

struct GripLaw {
  double friction = 0;              // coefficient of sliding friction, >= 0
  double grip_stiffness = 2.0 / 3;  // k_t over the normal loading stiffness; infinity: rigid grip (rolling)
  // The stretch's viscous damping ratio, in [0, 1): loss_ratio_for(e0) loses per half cycle the
  // share of energy the ball's normal law loses (1 - e0^2); 0 returns the stretch whole.
  double damping_ratio = 0;
  double k1 = 6.53e7;               // the ball's loading law N = k1 u^a, whose stiffness k_t follows
  double a = 1.84;

  // k_t (N/m) when the normal force is n (N).
  double stiffness(double n) const;
};

struct TangentialResult {
  TangentialMotion final;
  double impulse = 0;        // N s on the ball along t
  double friction_loss = 0;  // J the tangential force took from the two bodies' kinetic energy
  bool slid = false;         // the contact slid at some instant (|F| = mu N)
};

// The tangential motion through a contact whose normal force is `normal_force` (samples of F(t)
// as the collision records them, cubic Hermite between; any number of contacts). The friction
// loss is the work -int F s dt, summed step by step from each step's impulse and its end slips;
// the bodies' kinetic energy falls by exactly that (the energy balance closes to rounding).
TangentialResult tangential_contact(const std::vector<ForceSample>& normal_force, const TangentialBodies& bodies,
                                    const TangentialMotion& initial, const GripLaw& grip);

// The damping ratio zeta whose half cycle returns a velocity ratio e, exp(-pi zeta / sqrt(1 - zeta^2)) = e.
double damping_ratio_for(double e);

// The textbook rolling limit: the impulse that brings the slip to rest, -s0 / (1 / mu_t), and
// the motion it leaves (what a rigid grip gives when friction suffices).
TangentialMotion rolling_exit(const TangentialBodies& bodies, const TangentialMotion& initial);

// The motion after an impulse j on the ball along t.
TangentialMotion after_impulse(const TangentialBodies& bodies, const TangentialMotion& initial, double j);

}  // namespace sweetspot
