#pragma once
// Closed forms of physics.md §5: the rigid bat, the lossless ball, the effective COR, the
// response g(omega) of a force profile and Van Zandt's prescription.
#include <vector>

#include "sweetspot/contact/collision.hpp"

namespace sweetspot {

// v_f = (e0 - R0)/(1 + R0) v_ball + (e0 + 1)/(1 + R0) v_bat.
double rigid_exit_speed(double e0, double recoil, double ball_speed, double bat_speed);

// The e0 that, put in the rigid formula, gives exit speed vf.
double effective_cor(double vf, double recoil, double ball_speed, double bat_speed);

// e0 = 1: v_f = (1 - sum R_n)/(1 + sum R_n) v_ball + 2/(1 + sum R_n) v_bat.
double lossless_exit_speed(double response_sum, double ball_speed, double bat_speed);

// g(omega) = |integral Fhat(t) e^(i omega t) dt|^2 with Fhat = F / impulse, from force samples
// (cubic Hermite between samples, Gauss-Legendre on each segment).
double force_response(const std::vector<ForceSample>& force, double omega);
// g at each of several omegas, the impulse integrated once.
std::vector<double> force_responses(const std::vector<ForceSample>& force, const std::vector<double>& omegas);

// R_n = m psi_n^2 g(omega_n) for every mode of the body.
std::vector<double> mode_responses(const ModalContact& body, double ball_mass, const std::vector<ForceSample>& force);

// Van Zandt: R0 -> R0 + m a_vib, with a_vib the vibrational velocity of the impact point per unit
// impulse at the end of the assumed force profile `force` (modes with omega > 0 only).
double van_zandt_exit_speed(const ModalContact& body, const Ball& ball, double recoil, double ball_speed,
                            double bat_speed, const std::vector<ForceSample>& force);

}  // namespace sweetspot
