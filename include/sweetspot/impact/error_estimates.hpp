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
//           `accuracy` chose the step, the accuracy itself (step_selection.hpp's bound).
//   slicing Richardson extrapolation in the slice count (L. F. Richardson, Phil. Trans. R. Soc. A
//           210, 307 (1911); J. H. Ferziger & M. Peric, "Computational Methods for Fluid
//           Dynamics", 3.9): the frequencies converge at second order in L/N, so
//           v(N) - v_inf ~ (v(N) - v(2N)) 2^2 / (2^2 - 1), times a safety factor 1.5 as Roache's
//           grid convergence index does (P. J. Roache, J. Fluids Eng. 116, 405 (1994): 1.25 with
//           the order observed, 3 with two grids and the order not shown): the order is shown
//           (the uniform rod, test_error_estimates.cpp), but at a bat's own 84 slices the
//           convergence is not yet asymptotic (R161 and maple_271: 0.73-2.0x the error unsafed). Costs the bat's modes at 2N slices
//           (one more eigen-solve per bat, cached per bat as the modes are: 2-3x the solve at N
//           for auto's partial solve, about 7x for the dense one) and a second impact on them.
//   total   slicing + modes + step: each an upper estimate, their sum bounds the total by the
//           triangle inequality.
// Errors are relative to max(|vf|, 5 % of the ball's speed), the scale the step check uses
// (step_selection.hpp), so that a ball nearly stopped does not divide by nothing.
#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

// The slicing error is estimated against the bat at this many times its slices, at this order.
inline constexpr int slicing_refinement = 2;
inline constexpr double slicing_order = 2;
inline constexpr double slicing_safety = 1.5;

// Whether a bat of `slices` slices can be refined for the estimate (max_slices, and the dense
// Euler-Bernoulli solve's max_euler_bernoulli_slices); where not, the slicing error stays NaN.
bool can_refine(int slices, BeamTheory theory);

// The scale errors are relative to (above).
double error_scale(double vf, double ball_speed);

// The bat `design` describes, cut into `slices` slices: a slice profile resampled (exact at any
// multiple of its rows), knots or dimensions sampled from the shape.
Bat bat_with_slices(BatDesign design, int slices);

// Sets r.slicing_error from the same scene's result on the bat at slicing_refinement times the
// slices (`finer`), and r.total_error. NaN when either result is not ok.
void add_slicing_error(ImpactResult& r, const ImpactResult& finer, double ball_speed);

// One impact with every estimate, as the program's `impact` and Python's `impact` run it: the
// bat's basis by impact_mode_request at its slices (`basis`, solved by the caller) and the
// design's at twice them (`finer_basis`).
ImpactResult simulate_impact_with_errors(const ModalBasis& basis, const ModalBasis& finer_basis, ImpactScene scene);

}  // namespace sweetspot
