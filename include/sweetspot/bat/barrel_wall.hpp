#pragma once
// The barrel wall of a hollow bat (the trampoline effect, README "Hollow barrels"): wherever the
// struck slice is hollow, the wall under the ball ovals (the lowest hoop mode of the shell, n = 2)
// in series with the ball. That local motion is one more normal mode of the bat: its ovaling
// cos(2 theta) carries no net momentum of the section, so it is orthogonal to every beam mode and
// adds one decoupled oscillator of mass m_w and stiffness k_w at the contact point.
//
// Ring theory (Rayleigh's inextensional ring; Soedel, "Vibrations of Shells and Plates", 3rd ed.,
// ch. 5; Blevins, "Formulas for Natural Frequency and Mode Shape", table 9-2) for the section of
// mid-surface radius a and wall h, with the hoop modulus E_t and density rho:
//   omega^2 = E_t h^2 n^2 (n^2 - 1)^2 / (12 rho a^4 (n^2 + 1)) = 3 E_t h^2 / (5 rho a^4)  (n = 2)
// The ovaling's amplitude W(z) along the tube follows a beam on an elastic foundation (Vlasov's
// semi-membrane theory of long shells; Calladine, "Theory of Shell Structures", ch. 8): hoop
// bending gives the foundation k_f = 3 pi E_t h^3 / (4 a^3) per unit length, the axial stretching
// that an inextensional, shear-free ovaling needs gives the bending stiffness pi E_z h a^3 / 16.
// A point load on an infinite such beam (Hetenyi) deflects by F beta / (2 k_f), so
//   k_w = 2 k_f / beta,  beta^4 = 3 (E_t / E_z) h^2 / a^6,
// and the mode's mass is what puts it at the ring's frequency, m_w = k_w / omega^2.
// Assumptions: thin wall (h << a), no Poisson coupling (a ring, not a plate strip), a tube long
// against 2 / beta on both sides of the impact (the open barrel end is not modelled), a point
// load (the ball's contact patch is not), one mode (n = 2) standing for the wall's whole yield.
// A bore shorter than the largest spread 2 / beta of its sections (a wooden bat's cupped end: 1 in
// deep, a wall half the radius thick, 2 / beta 4.4 cm) is no tube that can oval: its slices have
// no wall mode, and the beam alone takes the ball there.
#include <numbers>
#include <vector>

#include "sweetspot/bat/bat.hpp"

namespace sweetspot {

// The wall's damping: a material loss factor eta (Material::wall_loss_factor, default
// default_wall_loss_factor = 1e-4, aluminium alloy) makes the mode a viscously damped oscillator
//   a'' + 2 zeta omega a' + omega^2 a = -psi F,   zeta = eta / 2,
// the viscous damping that dissipates the same energy per cycle as the hysteretic loss factor at
// resonance, 2 pi eta of the mode's energy (Cremer, Heckl & Petersson, "Structure-Borne Sound",
// ch. 3; Nashif, Jones & Henderson, "Vibration Damping", ch. 2). Over a ~0.6 ms collision at 1.5
// kHz the alloy's 1e-4 takes under 0.1 % of what the wall holds; a carbon/epoxy wall's 1e-3 to
// 1e-2 (Chandra, Singh & Gupta, Compos. Struct. 46, 41 (1999)) up to about 10 %. A loss factor
// outside [0, 1) is refused.
struct WallMode {
  double omega = 0;        // rad/s, the lowest hoop (n = 2) mode of the section
  double stiffness = 0;    // N/m: static stiffness of the wall under a point load, k_w
  double mass = 0;         // kg: the mode's mass at the contact point, k_w / omega^2
  double loss_factor = 0;  // the wall's material loss factor eta: damping ratio eta / 2

  double spread = 0;        // m: 2 / beta, the length of tube the ovaling takes up

  double frequency_hz() const { return omega / (2 * std::numbers::pi); }
};

// The wall mode of a section of these diameters (inner < outer, both > 0) and material.
WallMode wall_mode(double outer_diameter, double inner_diameter, const Material& material);

// One wall mode per slice, with mass 0 where the slice is solid or its bore (the run of hollow
// slices it lies in) is shorter than the largest spread along it; empty for a solid bat.
std::vector<WallMode> barrel_wall(const Bat& bat);

}  // namespace sweetspot
