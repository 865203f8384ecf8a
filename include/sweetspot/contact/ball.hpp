#pragma once
// The ball: a nonlinear, lossy spring (physics.md §3, N2000 Fig. 2).
//   compression (u increasing): F = k1 u^a
//   expansion   (u decreasing): F = F_m (u / u_m)^b,  b = (1 + a) / e0^2 - 1
// F_m (u/u_m)^b is used rather than k2 u^b because k2 = k1 u_m^(a-b) overflows for small e0.

namespace sweetspot {

struct Ball {
  double mass = 0.145;     // kg
  double radius = 0.0366;  // m
  double k1 = 6.53e7;      // N / m^a
  double a = 1.84;         // compression exponent
  double e0 = 0.5;         // coefficient of restitution on a rigid, immovable wall

  double expansion_exponent() const { return (1 + a) / (e0 * e0) - 1; }
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
  // Takes `force` as the force at u, to be answered without a pow: for a caller that has it from
  // a neighbouring evaluation (to round-off).
  void remember(double u, double force) const { last_u_ = u, last_force_ = force; }
  // Switches to the expansion branch at maximum compression u_m.
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
