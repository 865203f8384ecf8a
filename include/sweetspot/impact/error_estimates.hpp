#pragma once
// Estimates of each error source of one impact, relative to the exit speed, against the
// continuous model the bat file describes (a slice profile is its own continuum at any multiple
// of its slices; a profile of knots or named dimensions is its shape):
//   modes   ImpactResult::modes_error, an upper estimate of what the dropped modes change
//           (mode_selection.hpp); 0 when every mode is kept.
//   step    step doubling (Hairer, Norsett & Wanner, "Solving ODEs I", II.4; Richardson's
//           principle applied to the step): |v(h) - v(2h)| / (2^p - 1), p = min(a + 1, 4) for
//           exact stepping and RK4 (the order the ball's t^a onset leaves them at fine steps, as
//           step_selection.hpp's check), or |v(2h) - v(4h)| / (2^p (2^p - 1)) where larger (two
//           runs can agree by chance where the error changes sign); Dormand-Prince at 32x and
//           1024x its tolerance, p = 1 per factor 32 (its global error about proportional to the
//           tolerance). Costs collisions at 2h and 4h: about three quarters of an impact. Where
//           a step accuracy chose the step (a total accuracy's share, too), that accuracy
//           (step_selection.hpp's bound, an envelope over the bat and loose at most points), at
//           no cost: doubling a step chosen that coarse (60-70 us on a 0.7-ms pulse) leaves the
//           estimate's asymptotic range, and it read 3x the share at 1e-3.
//   slicing Richardson extrapolation in the slice count over three slicings N, 2N, 4N
//           (L. F. Richardson, Phil. Trans. R. Soc. A 210, 307 (1911); J. H. Ferziger &
//           M. Peric, "Computational Methods for Fluid Dynamics", 3.9): the frequencies converge
//           at second order in L/N (the uniform rod, test_error_estimates.cpp), so the finest
//           result errs by about |v(2N) - v(4N)| / 3, or by |v(N) - v(2N)| / 12 where that is
//           larger (two slicings can agree by chance where the error changes sign); a coarser
//           result by its distance from the finest plus the finest's error; each times a safety
//           factor 2, as Roache's grid convergence index does (P. J. Roache, J. Fluids Eng. 116,
//           405 (1994): 1.25 with three grids and the order observed, 3 with the order not shown):
//           the convergence is not yet monotone at a bat's own slices (below), and 1.5 fell short
//           on maple_271 in the rig (0.99x the actual error). Two slicings would not do: where the ball strikes between slice
//           centres the error's constant depends on where z falls in its slice, so at a bat's own
//           84 slices the convergence is not yet monotone (R161 at 35.5 cm: 84 -> 168 moves v_f by
//           2e-3 m/s, 168 -> 336 by 1.8e-2, 336 -> 672 by 4.7e-3), and a two-slicing estimate fell
//           to 0.04-0.16x the actual error. Costs the bat's modes at 2N and 4N slices (once per
//           bat, cached as its modes are) and an impact on each.
//   total   slicing + modes + step: each an upper estimate, their sum bounds the total by the
//           triangle inequality.
// Errors are relative to max(|vf|, 5 % of the ball's speed), the scale the step check uses
// (step_selection.hpp), so that a ball nearly stopped does not divide by nothing.
//
// A stated total accuracy A (ImpactScene::accuracy) shares itself among the sources
// (accuracy_budget) and is met by cutting the bat's design at N, 2N, 4N ... slices until the
// finest result's slicing estimate is within its share (SlicingLadder).
#include <functional>
#include <optional>
#include <vector>

#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

// Each slicing of the estimate has this many times the slices of the one before, and the
// frequencies converge at this order in the slice length.
inline constexpr int slicing_refinement = 2;
inline constexpr double slicing_order = 2;
inline constexpr double slicing_safety = 2;

// Whether a bat of `slices` slices can be cut `times` times finer (max_slices, and the dense
// Euler-Bernoulli solve's max_euler_bernoulli_slices).
bool can_refine(int slices, BeamTheory theory, int times = 1);

// The slicing a stated accuracy's ladder starts at where many impacts share each bat's solves (a
// study's), for a bat cut into `slices`: at accuracies tighter than 1e-3, twice them where the
// bat can be cut three times finer still; else its own. A bat's own slicing is often short of the
// slicing's second-order regime (R161, 40 m/s, 50.5-78.5 cm: the first doubling moves v_f up to
// 50x what the second does, not 4x), and the estimate's guard against such a chance agreement
// (slicing_error) then needs a fourth slicing, from which the first serves nothing: at 1e-4, 55 %
// of the design study's points did. At 1e-3 and looser the three from the bat's own slices mostly
// suffice. A single impact starts at the bat's own slices: there a solve at eight times them
// costs more than the impact it may save.
int ladder_start(int slices, BeamTheory theory, double accuracy);

// The scale errors are relative to (above).
double error_scale(double vf, double ball_speed);

// The bat `design` describes, cut into `slices` slices: a slice profile resampled (exact at any
// multiple of its rows), knots or dimensions sampled from the shape.
Bat bat_with_slices(BatDesign design, int slices);

// The absolute slicing error (m/s) of the result at slicing `level` of `vf`, the exit speeds of
// one scene at N, 2N, 4N ... slices (above). NaN with fewer than two slicings; with two, the
// finest's 2 |v(N) - v(2N)|: the safety factor on the whole difference, not on its Richardson
// third, the order not being shown (Roache's factor of three on the Richardson term would give
// |v(N) - v(2N)|).
double slicing_error(const std::vector<double>& vf, std::size_t level);

// Sets r.slicing_error (relative) and r.total_error from the exit speeds at r's slicing and the
// finer ones (`vf`, r's first), or NaN where one is not ok (`finer_ok` false).
void add_slicing_error(ImpactResult& r, const std::vector<double>& vf, std::size_t level, bool finer_ok,
                       double ball_speed);

// What a stated total accuracy A (ImpactScene::accuracy) allows each source: the slicing half,
// the dropped modes and the time step a quarter each. The slicing takes the largest share
// because it is the dearest to reduce (each halving of its error costs the bat's modes at 1.4x
// the slices and another impact), the other two being cheap per impact.
struct AccuracyBudget {
  double slicing = 0, modes = 0, step = 0;
};
AccuracyBudget accuracy_budget(double accuracy);

// What the dropped modes and the step leave of a stated accuracy for the slicing: more than its
// half where they take less than their quarters (the step takes its quarter; `auto` often drops
// far less than its quarter allows), less where the modes take more (a ball caught again counts
// the dropped modes once per contact), so that the total is held to the accuracy either way. An
// estimate not made (NaN: the step's, where the impact reports no estimates, as in a study that
// does not write them) counts as its quarter.
double slicing_allowance(double accuracy, double modes_error, double step_error);

// At a stated accuracy auto keeps the dropped modes within their share over this factor. It holds
// them against the rigid bat's exit speed, the one scale known before the impact; the impact
// states the estimate against its own (impact.cpp), larger where the flexible bat returns the ball
// slower: 1-1.5x over R161's barrel, about 2x toward its handle, up to 7x on maple_271 at 30 cm.
// With the whole share as the tolerance, 33 118 of the design-space study's 38 808 points would
// pass it at 1e-4 (all but those near the sweet spot) and run again on a wider basis
// (widened_scene): 3 700 points/s instead of about 4 300 at 2 (3 508 run again).
inline constexpr double mode_share_overrun = 2;

// The tolerance `auto` keeps the dropped modes within for the scene: its mode_tolerance, or at a
// stated accuracy the modes' share (scene_for_accuracy) over mode_share_overrun and its
// mode_share_divisor.
double auto_mode_tolerance(const ImpactScene& scene);

// Where auto's dropped modes took more than their share of a stated accuracy in `scene`, the scene
// to run the impact again in, so that the slicing is left its part: the share divided
// (ImpactScene::mode_share_divisor) by the scene's divisor times the estimate over the share (or
// 2^1.5, the cube of a half-octave of reach, where that is more), at most
// max_mode_share_divisor; with exact stepping at the step `r` took, as the ladder's finer rungs
// take it (the wider basis moves the pulse by the dropped modes' error). Nothing where `r` needs
// no such run (no stated accuracy, modes not auto, within the share, or the divisor already at
// its most). On a complete basis auto keeps within the share; on a partial one
// the unsolved modes are dropped whatever their cost, and a ball the bat's vibration catches
// again meets them at every contact, counted once per contact (impact.cpp): up to 3x the share
// near R161's handle. The run again asks a basis solved further, whose unsolved tail's estimate
// falls about as the cube of the reach (auto_solve_factor), and keeps every solved mode.
inline constexpr double max_mode_share_divisor = 64;  // the reach 4x the first's, its solve 4-16x the cost
std::optional<ImpactScene> widened_scene(const ImpactScene& scene, const ImpactResult& r);

// The least and largest total accuracy that may be asked: below 1e-7 the round-off that a second
// contact magnifies (docs/numerics.md) is as large as the error asked; above 0.1 a result says
// nothing.
inline constexpr double min_accuracy = 1e-7, max_accuracy = 0.1;

// The scene a stated accuracy makes (ImpactScene::accuracy > 0): auto modes within the modes'
// share, the step chosen for the step's share. Unchanged without one. Throws InputError when the scene fixes a mode count or a step accuracy.
ImpactScene scene_for_accuracy(ImpactScene scene);

// One scene at a stated accuracy on its bat cut at N, 2N, 4N ... slices: at least three
// slicings, then one more while the finest one's slicing estimate exceeds its share. The finest
// result is the answer, with `slices_used`. Where the slices cannot double again (max_slices, the
// Euler-Bernoulli limit, or a finer solve that is impractical) before the share is met, its
// status is `inaccurate`, and why.
// A study computes each rung for many points at once (study/parallel.cpp), `simulate_within_accuracy`
// one point.
class SlicingLadder {
 public:
  SlicingLadder(int slices, BeamTheory theory, const ImpactScene& scene);
  int next_slices() const { return next_slices_; }
  // The scene of the next rung: after the first, with exact stepping, at the step the first
  // chose and checked (ImpactScene::checked_step). The step's error hardly depends on the
  // slicing (the pulse moves by the slicing's error, 1e-4 or less), and checking it again at
  // every rung made the design study at 1e-4 2.2x slower. With the modes' share divided as the
  // last rung's was (widened_scene): the finer rungs drop the same modes.
  ImpactScene next_scene(ImpactScene scene) const;
  // The result at next_slices() of the scene `ran` (next_scene's, its mode_share_divisor maybe
  // raised); true when the ladder is done and result() is the answer.
  bool add(ImpactResult r, const ImpactScene& ran);
  // The ladder ended before its slicing met its share because the next rung cannot be solved
  // (`why`: its solve is impractical): the finest result so far, its slicing estimate from the
  // slicings there are (NaN with one), status `inaccurate` and why.
  void stop(const std::string& why);
  ImpactResult take_result() { return std::move(result_); }

 private:
  double slicing_allowance() const;

  BeamTheory theory_;
  double accuracy_, ball_speed_;
  bool exact_;
  double checked_step_ = 0;
  double mode_share_divisor_ = 1;
  int next_slices_;
  std::vector<double> vf_;
  ImpactResult result_;
};

// The bat's basis at a slice count for a scene (impact_mode_request; the caller's cache: solved
// once per count and request). Throws InputError where that solve is impractical.
using BasisAtSlices = std::function<const ModalBasis&(int slices, const ImpactScene& scene)>;

// One impact at a stated accuracy (scene.accuracy > 0), by a SlicingLadder; a rung caught again
// past the modes' share runs again on a wider basis (widened_scene).
ImpactResult simulate_within_accuracy(const BasisAtSlices& basis_at, int slices, BeamTheory theory,
                                      const ImpactScene& scene);

// One impact with every estimate, as the program's `impact` and Python's `impact` run it without
// a stated accuracy: at the bat's slices (`basis`), the slicing error from the same scene on the
// design at twice and four times them (`finer`, one or two bases: fewer where it cannot be cut so
// finely).
ImpactResult simulate_impact_with_errors(const ModalBasis& basis, const std::vector<const ModalBasis*>& finer,
                                         ImpactScene scene);

}  // namespace sweetspot
