#pragma once
// Error against run time for every integrator of the contact phase (collision.hpp) on one scene:
// the work-precision table behind the choice of integrator and step. Each integrator runs over a
// range of settings, coarsest first:
//   rk4    from the largest stable step (0.99 * 2.8 / omega_max of the kept modes, at most 20 us)
//          down by factors of 2, 6 settings
//   exact  steps 80, 40, 20, 10, 5, 2.5, 1.25 us
//   dopri  tolerances 1e-4 ... 1e-12 (every 10x), first step default_step(dopri) = 1e-6 s
// `quick` keeps the 3 finest settings of each and times each once (for tests).
//
// Errors are relative to a reference: the tightest adaptive run (dopri, tolerance 1e-13, first
// step 1e-7 s), cross-checked by Richardson extrapolation (order a + 1) of the two finest exact runs.
// Free of I/O: the caller prints the table and writes the dataset.
#include <limits>
#include <vector>

#include "sweetspot/contact/collision.hpp"
#include "sweetspot/study/dataset.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/scene.hpp"
#include "sweetspot/study/study.hpp"

namespace sweetspot {

// One integrator at one setting. NaN marks what does not apply or what a failed run lacks.
struct ConvergenceRun {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  CollisionStatus status = CollisionStatus::ok;
  double step = none;                // s (rk4, exact); NaN for dopri, whose step adapts
  double tolerance = none;           // dopri only
  double vf = none;                  // m/s
  double contact_time = none;        // s
  double vf_error = none;            // |vf / vf_ref - 1|
  double contact_time_error = none;  // |contact_time / contact_time_ref - 1|
  double energy_error = none;        // |energy residual| / initial energy: needs no reference
  double time_per_impact = none;     // s, wall time of simulate_impact, the least over repeats
};

struct IntegratorConvergence {
  Method method = Method::rk4;
  std::vector<ConvergenceRun> runs;  // coarsest first
};

struct ConvergenceReference {
  double vf = 0;               // m/s, the tightest dopri run
  double contact_time = 0;     // s, the same run
  double richardson_vf = 0;    // m/s, extrapolated from the two finest exact runs
  double disagreement = 0;     // |richardson_vf / vf - 1|
  double tolerance = 1e-13;    // of the reference run
  double first_step = 1e-7;    // s, of the reference run
  // p in v + (v - v_coarse) / (r^p - 1), r the ratio of the steps: a + 1, the order the ball's
  // t^a onset leaves exact stepping at fine steps (its sixth order holds where the force is smooth).
  double richardson_order = 0;
};

struct ConvergenceTable {
  ConvergenceReference reference;
  std::vector<IntegratorConvergence> integrators;  // rk4, exact, dopri
  double rk4_largest_step = 0;                     // s, the coarsest rk4 setting
  int kept_modes = 0;                              // modes the collision integrates (rigid included)
};

// Runs `scene` (its integrator options are replaced; window and contact limit kept) with every
// integrator at every setting. Throws InputError for a scene validate() refuses.
ConvergenceTable run_convergence(const ModalBasis& basis, const ImpactScene& scene, bool quick);

// The cheapest run of an integrator whose vf error is at most `vf_error`, or nullptr when none
// is: the coarsest such setting, since refining never makes a run cheaper. (Measured times can
// say otherwise by noise alone: dopri on a stiff scene takes the same stability-bound steps at
// every loose tolerance.)
const ConvergenceRun* cheapest_within(const IntegratorConvergence& integrator, double vf_error);

// The table as one dataset over (integrator, setting), NaN-padded where an integrator has fewer
// settings, with the study's text, the reference values and the program's version as global
// attributes.
Dataset convergence_dataset(const ConvergenceTable& table, const Study& study);

}  // namespace sweetspot
