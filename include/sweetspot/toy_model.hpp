#pragma once
// The toy model of N2000 Appendix A (Figs. 17-18): a ball of mass m = 1 on a massless linear
// spring k = 1 strikes mass Ma = 2, joined to Mb = 4 by a spring k1; no losses. omega =
// sqrt(k1 / mu_ab) and tau = pi sqrt(m / k) (half the ball-spring period) set the regime:
// v_f / v_i -> 5/7 for omega tau >> 1 (one rigid mass 6), 1/3 for omega tau << 1 (Ma alone).
#include "sweetspot/collision.hpp"

namespace sweetspot {

struct ToyResult {
  CollisionStatus status = CollisionStatus::ok;
  double omega_tau = 0;
  double exit_ratio = 0;       // v_f / v_i
  double ball_energy = 0;      // fractions of the initial energy
  double bat_cm_energy = 0;
  double vibration_energy = 0;
  double van_zandt_ratio = 0;  // v_f / v_i by Van Zandt's prescription, for comparison
};

ToyResult toy_model(double omega_tau);

}  // namespace sweetspot
