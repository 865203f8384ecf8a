#pragma once
// The toy model of N2000 Appendix A (Figs. 17-18): a ball of mass m = 1 on a massless linear
// spring k = 1 strikes mass Ma = 2, joined to Mb = 4 by a spring k1; no losses. omega =
// sqrt(k1 / mu_ab) and tau = pi sqrt(m / k) (half the ball-spring period) set the regime:
// v_f / v_i -> 5/7 for omega tau >> 1 (one rigid mass 6), 1/3 for omega tau << 1 (Ma alone).
#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

// The collision at v_i = 1, in the model's units (m = k = v_i = 1), so vf is v_f / v_i and the
// initial energy is 1/2. The bat's energy splits into its CM's translation (bat_translation) and
// the spring's vibration (vibration); the ball dissipates nothing, so ball + bat_translation +
// vibration + residual = initial. vf_van_zandt is Van Zandt's prescription for the same
// collision (N2000 Fig. 18), driven by the force profile computed here. z stays 0.
ImpactResult toy_model(double omega_tau);

}  // namespace sweetspot
