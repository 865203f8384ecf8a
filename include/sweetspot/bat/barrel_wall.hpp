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
//
// The load is the ball's contact patch, not a point (README "Hollow barrels"; load = "patch", the
// default of the bat file's [barrel] table):
// - The patch: the overlap of the undeformed ball (radius R_b) with the undeformed barrel (outer
//   radius R_c) at the ball's compression delta, an ellipse of half-length sqrt(2 R_b delta) along
//   the bat and half-width sqrt(2 R_t delta) around it, 1/R_t = 1/R_b + 1/R_c (arc half-angle the
//   half-width over R_c, at most pi/2). The pressure over it is Hertz-like, p ~ sqrt(1 - x^2/A^2
//   - y^2/B^2) (Johnson, "Contact Mechanics", 1985, ch. 4): a modelling choice, neither the true
//   contact of a soft ball on a shell nor its true area (Hertz's is half the overlap's).
// - Mode n's generalized load is F phi_n, phi_n the pressure-weighted mean over the patch of
//   cos(n theta) W_n(z) / W_n(0), W_n(z) = exp(-beta_n |z|)(cos beta_n z + sin beta_n |z|)
//   Hetenyi's point-load deflection of the mode's beam (phi = 1 for a point). By reciprocity the
//   ball sees the wall's displacement weighted the same way: the n = 2 mode's shape at the contact
//   is phi_2 / sqrt(m_w) (its frequency unchanged, its static stiffness k_w / phi_2^2).
// - The shell's other harmonics, n >= 3, follow the load quasi-statically: each a beam on an
//   elastic foundation of Vlasov's semi-membrane theory (Calladine ch. 8; Soedel ch. on shells),
//   k_f,n = pi E_t h^3 (n^2 - 1)^2 / (12 a^3), bending stiffness pi E_z h a^3 / n^4,
//   beta_n^4 = k_f,n / (4 EI_n), point compliance c_n = beta_n / (2 k_f,n) (n = 2: the formulas
//   above); the patch's compliance sum_{n>=3} phi_n^2 c_n is a massless spring in series with the
//   ball (the contact's residual compliance). n = 1 is the beam's bending, already in the beam
//   modes; n = 0 (breathing) stretches the hoop, membrane-stiff: neglected.
// The patch depends on the ball's compression: one impact holds phi_2 and the harmonics'
// compliance at a self-consistent effective compression (impact.cpp), so every integrator and its
// energy balance are exactly those of a fixed modal system.
//
// Assumptions: thin wall (h << a), no Poisson coupling (a ring, not a plate strip), a tube long
// against 2 / beta on both sides of the impact (the open barrel end is not modelled), one mode
// (n = 2) vibrating and the rest static, each harmonic projected on its point-load shape (a
// one-term Ritz projection: it slightly overstates the stiffness of a spread load).
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

  // The section, for the patch and the shell's other harmonics.
  double outer_radius = 0;   // m, R_c: the surface the ball meets
  double radius = 0;         // m, a: the mid-surface
  double thickness = 0;      // m, h
  double hoop_modulus = 0;   // Pa, E_t as used (after any calibration)
  double axial_modulus = 0;  // Pa, E_z
  WallLoad load = WallLoad::patch;

  double frequency_hz() const { return omega / (2 * std::numbers::pi); }
};

// The wall mode of a section of these diameters (inner < outer, both > 0) and material (its
// barrel calibration not applied: barrel_wall does that).
WallMode wall_mode(double outer_diameter, double inner_diameter, const Material& material);

// One wall mode per slice, with mass 0 where the slice is solid or its bore (the run of hollow
// slices it lies in) is shorter than the largest spread along it; empty for a solid bat. A
// calibrated barrel (Material::barrel) scales the hoop modulus of every slice, and a measured
// frequency with a measured compression sets the modes' mass (README "Hollow barrels"). Throws
// InputError when a calibration finds no reference section (no tube).
std::vector<WallMode> barrel_wall(const Bat& bat);

// ---- The shell's harmonics, the patch and the barrel compression ----

// Harmonic n >= 2 of the section (Vlasov's semi-membrane beam on an elastic foundation).
struct ShellHarmonic {
  double foundation = 0;  // N/m^2: k_f,n = pi E_t h^3 (n^2 - 1)^2 / (12 a^3)
  double bending = 0;     // N m^2: EI_n = pi E_z h a^3 / n^4
  double beta = 0;        // 1/m: (k_f,n / (4 EI_n))^(1/4)
  double compliance = 0;  // m/N: c_n = beta_n / (2 k_f,n), a point load's
};
ShellHarmonic shell_harmonic(int n, double radius, double thickness, double hoop_modulus, double axial_modulus);
ShellHarmonic shell_harmonic(const WallMode& wall, int n);

// The ball's contact patch on the barrel at compression delta (m): half-length along the bat and
// the arc's half-angle (rad, at most pi/2). Zero size for delta <= 0.
struct ContactPatch {
  double half_length = 0;
  double half_angle = 0;
};
ContactPatch contact_patch(double ball_radius, double barrel_radius, double compression);

// phi_n of the patch for harmonic n of decay rate beta (1/m): the Hertz-pressure-weighted mean of
// cos(n theta) W_n(z) / W_n(0). Exactly 1 for a patch of zero size. The theta integral is closed
// (int sqrt(c^2 - t^2) cos(n t) dt = pi c J1(n c) / n), the z one Gauss-Legendre (8 points) on
// panels of 2 / beta up to z = 40 / beta (W is below e^-40 past it) or the patch's end.
double patch_factor(int n, double beta, const ContactPatch& patch);

// Harmonics n = first, first + step, ... stop at max_harmonic or once three terms running fall
// below harmonic_sum_tolerance of their sum (a term alone may sit near a zero of J1).
inline constexpr int max_harmonic = 200;
inline constexpr double harmonic_sum_tolerance = 1e-6;

// sum_{n>=3} phi_n^2 c_n: the static compliance (m/N) of the shell's other harmonics under the patch.
double harmonics_compliance(const WallMode& wall, const ContactPatch& patch, int last_harmonic = max_harmonic);

// What the ball's patch at compression delta makes of the wall: the n = 2 mode's factor phi_2 and
// the other harmonics' compliance. A point load (WallLoad::point, or delta <= 0 for phi) gives
// phi_2 = 1 and no compliance.
struct PatchLoad {
  double phi = 1;         // phi_2
  double compliance = 0;  // m/N
};
PatchLoad patch_load(const WallMode& wall, double ball_radius, double compression);

// The barrel compression test (ASTM F2844): two diametrically opposite platens of width w along
// the bat (a line load uniform over w, a point around the circumference) approach by
// 4 F sum_{n even >= 2} c_n chi_n^2, chi_n the mean of W_n / W_n(0) over the platen. The force F
// (N) at which they have approached by `approach`. The platen width is an assumption: 1 in (the
// standard's own was not found).
inline constexpr double compression_approach = 0.04 * 0.0254;  // m: 0.04 in, baseball
inline constexpr double softball_compression_approach = 0.07 * 0.0254;  // m: 0.07 in
inline constexpr double default_platen_width = 0.0254;  // m: 1 in
double barrel_compression(const WallMode& wall, double approach = compression_approach,
                          double platen_width = default_platen_width, int last_harmonic = max_harmonic);

// The reference section of a barrel calibration: the slice with a wall mode of largest outer
// diameter (within 1e-9 of it) nearest 6 in from the barrel end; -1 if none has a wall mode.
int barrel_reference_slice(const Bat& bat, const std::vector<WallMode>& wall);

}  // namespace sweetspot
