#pragma once
// One impact of a ball on a bat: the scene in, a plain result out (physics.md §4-5). Never throws
// for a bad physical outcome: the status says what went wrong. The rigid wall (wall.hpp) and the
// toy model (toy_model.hpp) give the same result type, so that a study stores any of them alike.
#include <limits>
#include <string>
#include <vector>

#include "sweetspot/contact/collision.hpp"
#include "sweetspot/impact/histories.hpp"
#include "sweetspot/impact/rig_measures.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/scene.hpp"

namespace sweetspot {

// Energies in J. initial = ball + bat_translation + bat_rotation + vibration + ball_dissipated +
// barrel + damped + residual; the residual measures the integration error.
struct ImpactEnergy {
  double initial = 0;
  double ball = 0;
  double bat_translation = 0;
  double bat_rotation = 0;
  double vibration = 0;
  double ball_dissipated = 0;
  double residual = 0;
  // A hollow barrel's wall (barrel_wall.hpp): the energy its ovaling holds after the collision
  // (0 where the struck slice is solid). It is a normal mode of its own, apart from `vibration`.
  double barrel = 0;
  // What the bat's damping (its loss factor's on the beam's vibrational modes, the wall's on its
  // ovaling) dissipated from first touch to the last separation, the contacts and the free flights
  // between them: int sum 2 zeta omega a'^2 dt, integrated with the collision (not inferred from
  // the balance); 0 for an undamped beam with a solid section or a lossless wall.
  double damped = 0;
  // An oblique impact (oblique_impact.hpp), 0 for a head-on one: the ball's spin energy after the
  // collision, the bat's rigid motion across the line of centres (its recoil and its roll about
  // its own axis), and what friction took from the two (sliding and the grip's elastic energy not
  // given back). The initial energy then holds the ball's spin and the motion across the line.
  double ball_spin = 0;
  double bat_tangential = 0;
  double friction = 0;
};

// The ball as it leaves the bat: what its flight starts from (docs/oblique.md). NaN where there
// was no collision.
struct BallLaunch {
  double speed = std::numeric_limits<double>::quiet_NaN();     // m/s, the exit velocity's magnitude
  double angle = std::numeric_limits<double>::quiet_NaN();     // degrees above the horizontal
  double backspin = std::numeric_limits<double>::quiet_NaN();  // rpm, positive lifts the ball
  double sidespin = std::numeric_limits<double>::quiet_NaN();  // rpm; 0 in the plane of the swing
};

struct ImpactResult {
  CollisionStatus status = CollisionStatus::ok;
  std::string message;
  double z = 0;               // impact location, m from the knob
  double vf = 0;              // exit speed, m/s, positive away from the bat (oblique: the velocity's magnitude)
  double e_eff = 0;           // effective COR
  double contact_time = 0;    // s
  double collision_time = 0;  // s, 99 % of the impulse
  double u_max = 0;           // m
  double peak_force = 0;      // N
  double impulse = 0;         // N s
  double bat_speed = 0;       // m/s: the struck point's speed toward the ball at first touch
  // The struck slice's lowest hoop frequency (barrel_wall.hpp), Hz; NaN where it is solid.
  double hoop_frequency = std::numeric_limits<double>::quiet_NaN();
  // The same section's barrel compression (barrel_wall.hpp, ASTM F2844): N at 0.04 in; NaN where solid.
  double barrel_compression = std::numeric_limits<double>::quiet_NaN();
  // A patch-loaded wall (barrel_wall.hpp): the n = 2 mode's patch factor phi_2 and the other
  // harmonics' compliance (m/N) the collision used, at the effective compression (m) they were
  // evaluated at. NaN where no wall takes the ball; phi 1 and compliance 0 for a point load.
  double barrel_phi = std::numeric_limits<double>::quiet_NaN();
  double barrel_compliance = std::numeric_limits<double>::quiet_NaN();
  double barrel_compression_eff = std::numeric_limits<double>::quiet_NaN();
  // The rules' linear estimate of vf (batted_ball.hpp), NaN unless the scene asks for it.
  double bbs_linear = std::numeric_limits<double>::quiet_NaN();
  // Exit speeds to compare with vf (physics.md §5), NaN unless the scene asks for them: the rigid
  // bat's at the same point (free or pivoted), and Van Zandt's prescription for the same
  // collision (the toy model always gives it).
  double vf_rigid = std::numeric_limits<double>::quiet_NaN();
  double vf_van_zandt = std::numeric_limits<double>::quiet_NaN();
  // The measures of the bat-test rig (rig_measures.hpp): e_a for every scene that collides; bbcor,
  // besr and bpf only for a pivoted one, whose recoil factor is the rig's r = m d^2 / I_pivot
  // (NaN for a free bat, which no rig holds).
  RigMeasures rig;
  int certified = -1;  // a certification study's point: 1 when the bat passes every rule, else 0
  ImpactEnergy energy;
  BallLaunch launch;  // speed, angle and spins the ball leaves with (every collision of a bat)
  // Its flight from that launch (flight.hpp), where a study asks it: m, m, s, degrees below the
  // horizontal. NaN otherwise.
  double distance = std::numeric_limits<double>::quiet_NaN();
  double apex = std::numeric_limits<double>::quiet_NaN();
  double hang_time = std::numeric_limits<double>::quiet_NaN();
  double landing_angle = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> mode_energy;  // J per kept vibrational mode (of the held bat when pivoted)
  std::vector<int> modes_kept;      // vibrational mode numbers kept (1 = the first)
  double modes_error = 0;           // modes = auto: estimated relative vf error of the dropped ones
  // Estimated relative vf errors of the other sources (error_estimates.hpp), NaN unless asked
  // (ImpactScene::error_estimates; the slicing error needs the bat at twice its slices, so only
  // the callers that hold the bat's design fill it): the time stepping's (step doubling), the
  // slicing's against the continuum the bat file describes (Richardson in N), and the total,
  // slicing + modes + step.
  double step_error = std::numeric_limits<double>::quiet_NaN();
  double slicing_error = std::numeric_limits<double>::quiet_NaN();
  double total_error = std::numeric_limits<double>::quiet_NaN();
  int contacts = 0;
  // The slicing, and the step, the impact was computed at: the bat's own slices unless a stated
  // accuracy chose finer ones (error_estimates.hpp); the fixed step (s; 0 for Dormand-Prince,
  // whose steps adapt).
  int slices_used = 0;
  double step_used = 0;
  std::vector<ForceSample> force;   // only when the scene records the force
  // Only when the scene asks for them (ImpactScene::histories, force_response, mode_response)
  // and the collision ends ok.
  Histories histories;
  std::vector<double> force_response;  // g(omega tau) at each force_response_grid() value
  std::vector<double> mode_response;   // R_n per kept vibrational mode
};

// Sets the residual from the other terms, once they are all filled. An ok result whose residual
// exceeds balance_limit of the initial energy is marked unbalanced: its step was far too coarse
// for the pulse, and its numbers are not to be reported as if they were right.
constexpr double balance_limit = 1e-2;
// A patch-loaded wall's effective compression over the largest (impact.cpp): the force-weighted
// mean compression int F u dt / int F dt of a ball on a rigid wall, both branches of its power-law
// force, (f(a) + e0 f(b)) / (1 + e0) with f(p) = B(1 + 1/(p+1), 1/2) / 2 (0.874 for N2000's ball).
double mean_compression_fraction(const Ball& ball);

void close_balance(ImpactResult& result);

// Whether a collision of this status has values to report: not one that never touched, nor one
// that failed (no separation, a state no longer finite, too many steps), whose values would be
// those of the state it stopped in (the ball's approach speed, or an overflow).
bool has_values(CollisionStatus status);

// The values a result gives only when asked, NaN otherwise (a study may not ask).
struct AskedValues {
  bool collision_time = true;
  bool vf_rigid = false;
  bool vf_van_zandt = false;
  bool bbs_linear = false;
  bool e_a = false;  // a bat was struck: the collision efficiency exists (the wall and toy have none)
  bool energy = true;  // the energy balance (not asked of a damped bat whose loss is not integrated)
};

// No NaN or infinite output comes with status ok: an ok result with one (a degenerate pulse, an
// overflow) becomes non_finite, its message naming the value. Values not asked are skipped.
void require_finite(ImpactResult& result, const AskedValues& asked);

// The omega tau at which a study gives g(omega tau): 0, 0.1, ..., 20 (tau = collision_time),
// far enough for g to fall to nothing (N2000 Fig. 4).
std::vector<double> force_response_grid();

// What every collision gives whatever was struck: status, message, vf, the times, u_max,
// peak_force, impulse, contacts and energy.ball_dissipated. The caller adds what depends on the
// struck body: e_eff and the rest of the energy balance. A refused step gives status and message
// only, since nothing was integrated; no contact (nothing to integrate) gives NaN for all of them.
ImpactResult collision_result(const Collision& c);

// A ball the bat's vibration catches again (a handle impact) is run again with every mode kept
// that auto solves at this tolerance, or at the scene's where tighter: on the basis solved that
// far (ModalBasis::widened) where the scene's looser tolerance solved less. The one-pulse estimate
// counted once per contact bounds such an impact on that basis (its error under 1e-7 over the
// design-space study at 1e-5 to 1e-4: scripts/mode_tolerance_honesty), but not on a narrower one:
// solved as for 1e-4 it erred up to 2.6x it (9e-4) and moved collision times up to 3.2x.
inline constexpr double caught_again_mode_tolerance = 1e-5;

// Validates the scene (InputError for bad input), then runs the collision.
ImpactResult simulate_impact(const ModalBasis& basis, const ImpactScene& scene);

}  // namespace sweetspot
