#pragma once
// The ball: a nonlinear, lossy spring (physics.md §3, N2000 Fig. 2).
//   compression (u increasing): F = k1 u^a
//   expansion   (u decreasing): F = F_m (u / u_m)^b,  b = (1 + a) / e0^2 - 1
// F_m (u/u_m)^b is used rather than k2 u^b because k2 = k1 u_m^(a-b) overflows for small e0.
//
// A real ball's COR falls as it is struck harder (README "Balls"): e(v) = e0 + cor_slope (v -
// cor_speed) on a flat rigid wall at speed v. In a collision the ball takes the e of the energy
// it stores at maximum compression, W = k1 u_m^(a+1) / (a+1): the wall speed sqrt(2 W / m) that
// stores as much. On a rigid flat wall that returns exactly e(v); on a bat, whose recoil leaves
// the ball less to store, the ball is as lively as at that lower wall speed. cor_slope = 0 is
// N2000's ball: one e0 at every speed, bit for bit the law it always was.
#include <algorithm>
#include <cmath>

namespace sweetspot {

// The wall speeds over which a ball's COR law must stay physical, 0 < e <= 1 (m/s: 224 mph,
// past any bat or cannon); the law is held at its value at the end of this range beyond it.
inline constexpr double max_cor_law_speed = 100;

struct Ball {
  double mass = 0.145;     // kg
  double radius = 0.0366;  // m
  double k1 = 6.53e7;      // N / m^a, on a flat surface
  double a = 1.84;         // compression exponent
  double e0 = 0.5;         // coefficient of restitution on a rigid, immovable flat wall at cor_speed
  double cor_slope = 0;    // dCOR/dv on a flat wall, per m/s (0: e0 at every speed)
  double cor_speed = 0;    // m/s: the wall speed at which the COR is e0
  // k1 is the flat wall's: on a barrel the contact is a sphere on a cylinder, and the ball is
  // softer there (curvature_factor). Off for N2000's ball, whose k1 was fitted as it is.
  bool curved_contact = false;

  double expansion_exponent() const { return (1 + a) / (e0 * e0) - 1; }
  bool speed_dependent() const { return cor_slope != 0; }
  // The COR on a rigid flat wall at speed v (m/s).
  double cor_at(double wall_speed) const {
    const double v = std::clamp(wall_speed, 0.0, max_cor_law_speed);
    return speed_dependent() ? e0 + cor_slope * (v - cor_speed) : e0;
  }
  // The wall speed that stores `energy` (J) in the ball at maximum compression.
  double wall_speed_storing(double energy) const { return std::sqrt(2 * energy / mass); }
  // The same law with e0 taken where a collision of this closing speed and recoil R0 = m / M_eff
  // stores the ball's energy (on a rigid bat: the reduced mass m / (1 + R0) at the closing speed,
  // as a wall speed v / sqrt(1 + R0)): e0 is then the COR the closed forms of that collision take.
  Ball anchored_at(double closing_speed, double recoil) const {
    if (!speed_dependent()) return *this;
    Ball anchored = *this;
    anchored.cor_speed = std::clamp(std::abs(closing_speed) / std::sqrt(1 + recoil), 0.0, max_cor_law_speed);
    anchored.e0 = cor_at(anchored.cor_speed);
    return anchored;
  }
  // How much softer the ball is on a convex cylinder of radius `section_radius` than on a flat
  // wall: Hertz's elliptical contact (Johnson, "Contact Mechanics" (1985), sec. 4.2) loads as the
  // square root of the equivalent radius sqrt(R' R''), 1/R' = 1/R, 1/R'' = 1/R + 1/R_c, so k1
  // scales by (R_c / (R + R_c))^(1/4) (0.83 for a baseball on a 2 5/8-in barrel). 1 when
  // curved_contact is off or the section is flat (R_c infinite) or absent.
  double curvature_factor(double section_radius) const {
    if (!curved_contact || !(section_radius > 0) || !std::isfinite(section_radius)) return 1;
    return std::pow(section_radius / (radius + section_radius), 0.25);
  }
  // The ball as it meets a section of that radius: k1 scaled by curvature_factor.
  Ball on_section(double section_radius) const {
    Ball struck = *this;
    struck.k1 *= curvature_factor(section_radius);
    struck.curved_contact = false;  // applied
    return struck;
  }
};

// The force law of one contact, with its memory of the maximum compression.
class ContactForce {
 public:
  explicit ContactForce(const Ball& ball) : ball_(ball), b_(ball.expansion_exponent()) {}

  // Force for compression u (zero when the ball does not touch, u <= 0).
  double operator()(double u) const;
  // dF/du at u, for the time derivative of the force profile. At first touch (u = 0) its limit
  // from above: k1 for a linear ball (a = 1), whose force rises at once; 0 for a > 1.
  double stiffness(double u) const;
  // The compression at which the branch in force gives `force` (> 0): its inverse.
  double compression_at(double force) const;
  // Takes `force` as the force at u, to be answered without a pow: for a caller that has it from
  // a neighbouring evaluation (to round-off).
  void remember(double u, double force) const { last_u_ = u, last_force_ = force; }
  // Switches to the expansion branch at maximum compression u_m. A speed-dependent ball takes the
  // COR of the energy stored there (Ball): the expansion exponent is set anew.
  void start_expansion(double u_max);
  // The ball, expanding, is pressed again past u_m (the bat's vibration can do that): it is back
  // on the compression branch, which meets the expansion one at (u_m, F_m). Below u_m the
  // expansion branch is elastic both ways, so the next maximum compression starts a loop whose
  // area is all the contact dissipates.
  void resume_compression();
  bool expanding() const { return expanding_; }
  // The exponent of the branch in force: F is proportional to u^exponent.
  double exponent() const { return expanding_ ? b_ : ball_.a; }
  double u_max() const { return u_max_; }
  double f_max() const { return f_max_; }
  // Energy lost in the ball over a full loop: F_m u_m (1/(a+1) - 1/(b+1)), a fraction 1 - e0^2
  // of the energy stored at maximum compression.
  double loop_energy() const;

 private:
  Ball ball_;
  double b_;
  bool expanding_ = false;
  double u_max_ = 0;
  double f_max_ = 0;
  // The integrators ask for the force at the same compression several times a step (the step's
  // end is the next one's start, samples, step limits); the last answer saves a pow.
  mutable double last_u_ = -1, last_force_ = 0;
};

}  // namespace sweetspot
