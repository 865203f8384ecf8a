#pragma once
// Total error against run time at a stated accuracy (error_estimates.hpp) on one scene: for each
// accuracy, what it chose (slices, modes, step), what each source's estimate says, the actual
// error against a converged reference, and the time per impact. The default settings (no stated
// accuracy, the bat's own slices) are the first row; the accuracies run from 1e-2 to 1e-4 (1e-3
// alone when quick), whose slicings stay below the reference's. The reference is Richardson
// extrapolation in the slices (order 2) of the scene with modes auto at 1e-9 and exact stepping
// at 2.5 us, on the design cut into 8N and 16N slices, N the bat's own.
// Free of I/O: `sweetspot convergence` prints the table and writes it into its dataset.
#include <limits>
#include <vector>

#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/impact/scene.hpp"
#include "sweetspot/study/dataset.hpp"

namespace sweetspot {

struct AccuracyRun {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double accuracy = none;  // stated total accuracy; NaN for the default settings
  CollisionStatus status = CollisionStatus::ok;
  double slices = none, modes = none, step = none;  // what was chosen (step in s; 0: adaptive)
  double slicing_error = none, modes_error = none, step_error = none, total_error = none;  // estimates
  double actual_error = none;     // |vf / vf_reference - 1|
  double time_per_impact = none;  // s, wall time of the whole impact at that accuracy (its eigen-solves
                                  // excluded: a study solves each once per bat), least over repeats
};

struct AccuracySweep {
  double reference_vf = 0;        // m/s
  int reference_slices = 0;       // the finer of the two extrapolated from
  double reference_difference = 0;  // |v(4N) - v(8N)| / v: how far the reference's own slicing was
  std::vector<AccuracyRun> runs;  // the default settings, then the accuracies loosest first
};

// Throws InputError for a scene validate() refuses.
AccuracySweep run_accuracy_sweep(const BatDesign& design, int slices, BeamTheory theory, const ImpactScene& scene,
                                 bool quick);

// The sweep's variables over a dimension "accuracy", to join the convergence dataset.
void add_accuracy_sweep(Dataset& d, const AccuracySweep& sweep);

}  // namespace sweetspot
