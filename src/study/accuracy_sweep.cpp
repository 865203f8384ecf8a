#include "sweetspot/study/accuracy_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

namespace {

// The design's bases for a scene, solved once per slice count and kept: the sweep times the
// impacts, as a study's points run them on bases solved once per bat.
class BasisCache {
 public:
  BasisCache(const BatDesign& design, BeamTheory theory, ImpactScene scene)
      : design_(design), theory_(theory), scene_(std::move(scene)) {}
  const ModalBasis& at(int slices) { return at(slices, scene_); }
  // For a rung of the scene (its mode_share_divisor maybe raised: SlicingLadder).
  const ModalBasis& at(int slices, const ImpactScene& rung) {
    const std::pair key(slices, rung.mode_share_divisor);
    auto found = bases_.find(key);
    if (found != bases_.end()) return found->second;
    const Bat bat = bat_with_slices(design_, slices);
    const ModeRequest request = impact_mode_request(rung, compute_modes(bat, theory_, ModeRequest::rigid_only()));
    return bases_.emplace(key, compute_modes(bat, theory_, request)).first->second;
  }

 private:
  const BatDesign& design_;
  BeamTheory theory_;
  ImpactScene scene_;
  std::map<std::pair<int, double>, ModalBasis> bases_;  // by slices and mode_share_divisor
};

// The least wall time of `repeats` calls, and the last result.
template <class F>
std::pair<ImpactResult, double> timed(F&& f, int repeats) {
  ImpactResult r;
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < repeats; ++k) {
    const auto start = std::chrono::steady_clock::now();
    r = f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return {std::move(r), best};
}

double reference_vf(const BatDesign& design, int slices, BeamTheory theory, ImpactScene scene,
                    AccuracySweep& sweep) {
  scene.mode_tolerance = 1e-9;
  scene.integrator.method = Method::exact;
  scene.integrator.dt = 2.5e-6;
  const int coarse = 8 * slices, fine = 2 * coarse;  // 32N would ask more modes than is practical
  const auto vf_at = [&](int n) {
    const Bat bat = bat_with_slices(design, n);
    const ModeRequest request = impact_mode_request(scene, compute_modes(bat, theory, ModeRequest::rigid_only()));
    return simulate_impact(compute_modes(bat, theory, request), scene).vf;
  };
  const double v_coarse = vf_at(coarse), v_fine = vf_at(fine);
  sweep.reference_slices = fine;
  sweep.reference_difference = std::abs(v_coarse / v_fine - 1);
  return v_fine + (v_fine - v_coarse) / (std::pow(2.0, slicing_order) - 1);
}

AccuracyRun run_of(const ImpactResult& r, double accuracy, double seconds, double reference) {
  AccuracyRun run;
  run.accuracy = accuracy;
  run.status = r.status;
  run.slices = r.slices_used, run.modes = static_cast<double>(r.modes_kept.size()), run.step = r.step_used;
  run.slicing_error = r.slicing_error, run.modes_error = r.modes_error, run.step_error = r.step_error;
  run.total_error = r.total_error;
  run.actual_error = std::abs(r.vf / reference - 1);
  run.time_per_impact = seconds;
  return run;
}

}  // namespace

AccuracySweep run_accuracy_sweep(const BatDesign& design, int slices, BeamTheory theory, const ImpactScene& given,
                                 bool quick) {
  ImpactScene scene = given;
  scene.vibrational_modes = auto_modes;
  scene.step_accuracy = 0;
  scene.accuracy = 0;
  scene.error_estimates = true;
  AccuracySweep sweep;
  const double reference = reference_vf(design, slices, theory, scene, sweep);
  sweep.reference_vf = reference;
  const int repeats = quick ? 1 : 3;

  BasisCache defaults(design, theory, scene);
  std::vector<const ModalBasis*> finer;
  for (int times = 1, n = slices; times <= 2 && can_refine(slices, theory, times); ++times)
    finer.push_back(&defaults.at(n *= slicing_refinement));
  const ModalBasis& basis = defaults.at(slices);
  const auto [plain, plain_seconds] =
      timed([&] { return simulate_impact_with_errors(basis, finer, scene); }, repeats);
  sweep.runs.push_back(run_of(plain, AccuracyRun::none, plain_seconds, reference));

  const std::vector<double> accuracies =
      quick ? std::vector<double>{1e-3} : std::vector<double>{1e-2, 3e-3, 1e-3, 3e-4, 1e-4};
  for (const double accuracy : accuracies) {
    ImpactScene stated = scene;
    stated.accuracy = accuracy;
    BasisCache cache(design, theory, stated);
    const auto basis_at = [&](int n, const ImpactScene& rung) -> const ModalBasis& { return cache.at(n, rung); };
    simulate_within_accuracy(basis_at, slices, theory, stated);  // solves the bases it needs, untimed
    const auto [r, seconds] =
        timed([&] { return simulate_within_accuracy(basis_at, slices, theory, stated); }, repeats);
    sweep.runs.push_back(run_of(r, accuracy, seconds, reference));
  }
  return sweep;
}

namespace {

struct Column {
  const char* name;
  const char* units;
  const char* long_name;
  double AccuracyRun::*member;
};

constexpr Column columns[] = {
    {"accuracy", "1", "stated total relative vf error (NaN: the default settings)", &AccuracyRun::accuracy},
    {"accuracy_slices", "1", "slices the bat was cut into", &AccuracyRun::slices},
    {"accuracy_modes", "1", "vibrational modes kept", &AccuracyRun::modes},
    {"accuracy_step", "s", "fixed time step taken (0: adaptive)", &AccuracyRun::step},
    {"slicing_error", "1", "estimated relative vf error of the slicing", &AccuracyRun::slicing_error},
    {"modes_error", "1", "estimated relative vf error of the dropped modes", &AccuracyRun::modes_error},
    {"step_error", "1", "estimated relative vf error of the time step", &AccuracyRun::step_error},
    {"total_error", "1", "estimated total relative vf error", &AccuracyRun::total_error},
    {"actual_error", "1", "relative vf error against the continuum reference", &AccuracyRun::actual_error},
    {"accuracy_time_per_impact", "s", "wall time of one impact at that accuracy, least over repeats",
     &AccuracyRun::time_per_impact},
};

}  // namespace

void add_accuracy_sweep(Dataset& d, const AccuracySweep& sweep) {
  Coordinate run{"accuracy_run", "1", "setting of the accuracy sweep: 0 the default settings, then loosest first",
                 {}, {}};
  for (std::size_t k = 0; k < sweep.runs.size(); ++k) run.values.push_back(static_cast<double>(k));
  d.coordinates.push_back(run);
  for (const Column& column : columns) {
    std::vector<double> values;
    for (const AccuracyRun& r : sweep.runs) values.push_back(r.*column.member);
    d.variables.push_back({column.name, column.units, column.long_name, {"accuracy_run"}, std::move(values), {}, {}});
  }
  d.number_attributes.push_back({"continuum_vf", sweep.reference_vf});
  d.number_attributes.push_back({"continuum_slices", static_cast<double>(sweep.reference_slices)});
  d.number_attributes.push_back({"continuum_slicing_difference", sweep.reference_difference});
}

}  // namespace sweetspot
