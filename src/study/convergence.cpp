#include "sweetspot/study/convergence.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>

#include "sweetspot/impact/impact.hpp"
#include "sweetspot/version.hpp"

namespace sweetspot {

namespace {

constexpr double rk4_max_step = 20e-6;   // s: beyond this the force pulse, not stability, limits RK4
constexpr double rk4_stable_share = 0.99;  // of the stability limit: right at it, round-off may tip over
constexpr int rk4_settings = 6;
constexpr double exact_coarsest_step = 80e-6;  // s, halved down to 1.25 us
constexpr int exact_settings = 7;
constexpr double dopri_loosest = 1e-4, dopri_tightest = 1e-12;
constexpr int quick_settings = 3;
// Repeats until both hold; the least time counts, as the one least disturbed by the machine.
constexpr int min_repeats = 3;
constexpr double min_timing = 0.1;  // s

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double relative_error(double value, double reference) { return std::abs(value / reference - 1); }

double largest_stable_rk4_step(const ModalBasis& basis, const ImpactScene& scene) {
  const Eigen::VectorXd& omega = scene_geometry(scene, basis).contact.omega;
  const double omega_max = omega.size() ? omega.maxCoeff() : 0.0;
  if (omega_max == 0) return rk4_max_step;  // rigid modes only: nothing to destabilise
  return std::min(rk4_max_step, rk4_stable_share * rk4_stability_limit / omega_max);
}

// Every setting of one integrator, coarsest first; `quick` keeps the finest few.
std::vector<ConvergenceRun> settings(Method method, double rk4_step, bool quick) {
  std::vector<ConvergenceRun> runs;
  auto add_steps = [&](double coarsest, int count) {
    for (int i = 0; i < count; ++i) runs.push_back({.step = std::ldexp(coarsest, -i)});
  };
  switch (method) {
    case Method::rk4: add_steps(rk4_step, rk4_settings); break;
    case Method::exact: add_steps(exact_coarsest_step, exact_settings); break;
    case Method::dopri:
      for (double tolerance = dopri_loosest; tolerance >= 0.5 * dopri_tightest; tolerance /= 10)
        runs.push_back({.tolerance = tolerance});
      break;
  }
  if (quick && runs.size() > quick_settings) runs.erase(runs.begin(), runs.end() - quick_settings);
  return runs;
}

// The scene under one integrator; its window and contact limit stay as the scene has them.
ImpactScene with_integrator(ImpactScene scene, Method method, double dt, double tolerance) {
  scene.integrator.method = method;
  scene.integrator.dt = dt;
  if (method == Method::dopri) scene.integrator.tolerance = tolerance;
  scene.integrator.record_force = false;  // costs time a study does not spend
  return scene;
}

ImpactScene with_setting(const ImpactScene& scene, Method method, const ConvergenceRun& setting) {
  if (method == Method::dopri) return with_integrator(scene, method, default_step(method), setting.tolerance);
  return with_integrator(scene, method, setting.step, 0);
}

// Runs the scene once, or (not quick) until it has been timed at least min_repeats times and
// for min_timing seconds in all; fills what needs no reference.
void measure(const ModalBasis& basis, const ImpactScene& scene, bool quick, ConvergenceRun& run) {
  const Clock::time_point begin = Clock::now();
  ImpactResult result;
  double best = std::numeric_limits<double>::infinity();
  for (int repeats = 1;; ++repeats) {
    const Clock::time_point start = Clock::now();
    result = simulate_impact(basis, scene);
    best = std::min(best, seconds_since(start));
    if (quick || (repeats >= min_repeats && seconds_since(begin) >= min_timing)) break;
  }
  run.status = result.status;
  run.time_per_impact = best;
  if (result.status != CollisionStatus::ok) return;
  run.vf = result.vf;
  run.contact_time = result.contact_time;
  run.energy_error = std::abs(result.energy.residual) / result.energy.initial;
}

ConvergenceReference reference_run(const ModalBasis& basis, const ImpactScene& scene) {
  ConvergenceReference ref;
  const ImpactResult r = simulate_impact(basis, with_integrator(scene, Method::dopri, ref.first_step, ref.tolerance));
  ref.vf = r.status == CollisionStatus::ok ? r.vf : ConvergenceRun::none;
  ref.contact_time = r.status == CollisionStatus::ok ? r.contact_time : ConvergenceRun::none;
  return ref;
}

// Richardson extrapolation of the two finest exact runs: an estimate of the limit independent of
// the adaptive reference, so that the two agreeing vouches for both.
void cross_check(const IntegratorConvergence& exact, ConvergenceReference& ref) {
  const std::size_t n = exact.runs.size();
  if (n < 2) {
    ref.richardson_vf = ref.disagreement = ConvergenceRun::none;
    return;
  }
  const ConvergenceRun &coarse = exact.runs[n - 2], &fine = exact.runs[n - 1];
  const double gain = std::pow(coarse.step / fine.step, ref.richardson_order);
  ref.richardson_vf = fine.vf + (fine.vf - coarse.vf) / (gain - 1);
  ref.disagreement = relative_error(ref.richardson_vf, ref.vf);
}

void fill_errors(const ConvergenceReference& ref, IntegratorConvergence& integrator) {
  for (ConvergenceRun& run : integrator.runs) {
    run.vf_error = relative_error(run.vf, ref.vf);
    run.contact_time_error = relative_error(run.contact_time, ref.contact_time);
  }
}

}  // namespace

ConvergenceTable run_convergence(const ModalBasis& basis, const ImpactScene& scene, bool quick) {
  validate(scene, basis);  // before scene_geometry, which assumes a valid scene
  ConvergenceTable table;
  table.kept_modes = scene_geometry(scene, basis).contact.count();
  table.rk4_largest_step = largest_stable_rk4_step(basis, scene);
  table.reference = reference_run(basis, scene);
  table.reference.richardson_order = std::min(6.0, scene.ball.a + 1);
  for (Method method : {Method::rk4, Method::exact, Method::dopri}) {
    IntegratorConvergence integrator{method, settings(method, table.rk4_largest_step, quick)};
    for (ConvergenceRun& run : integrator.runs) measure(basis, with_setting(scene, method, run), quick, run);
    fill_errors(table.reference, integrator);
    if (method == Method::exact) cross_check(integrator, table.reference);
    table.integrators.push_back(std::move(integrator));
  }
  return table;
}

const ConvergenceRun* cheapest_within(const IntegratorConvergence& integrator, double vf_error) {
  const auto it =
      std::ranges::find_if(integrator.runs, [&](const ConvergenceRun& run) { return run.vf_error <= vf_error; });
  return it == integrator.runs.end() ? nullptr : &*it;
}

namespace {

struct Column {
  const char* name;
  const char* units;
  const char* long_name;
  double ConvergenceRun::*member;
};

constexpr Column columns[] = {
    {"step", "s", "integration step (rk4, exact); NaN for dopri, whose step adapts", &ConvergenceRun::step},
    {"tolerance", "1", "relative local error per step (dopri only)", &ConvergenceRun::tolerance},
    {"vf", "m/s", "exit speed of the ball, positive away from the bat", &ConvergenceRun::vf},
    {"vf_error", "1", "relative error of the exit speed against the reference", &ConvergenceRun::vf_error},
    {"contact_time_error", "1", "relative error of the contact time against the reference",
     &ConvergenceRun::contact_time_error},
    {"energy_error", "1", "energy balance residual relative to the initial energy", &ConvergenceRun::energy_error},
    {"time_per_impact", "s", "wall time of one impact, least over repeats", &ConvergenceRun::time_per_impact},
};

std::size_t most_settings(const ConvergenceTable& table) {
  std::size_t k = 0;
  for (const IntegratorConvergence& integrator : table.integrators) k = std::max(k, integrator.runs.size());
  return k;
}

Variable column_variable(const ConvergenceTable& table, const Column& column, std::size_t settings) {
  std::vector<double> values(table.integrators.size() * settings, ConvergenceRun::none);
  for (std::size_t i = 0; i < table.integrators.size(); ++i)
    for (std::size_t k = 0; k < table.integrators[i].runs.size(); ++k)
      values[i * settings + k] = table.integrators[i].runs[k].*column.member;
  return {column.name, column.units, column.long_name, {"integrator", "setting"}, std::move(values), {}, {}};
}

std::string describe_reference(const ConvergenceReference& ref) {
  char text[256];
  std::snprintf(text, sizeof text,
                "dopri at tolerance %g, first step %g s; cross-checked by Richardson extrapolation (order %g) "
                "of the two finest exact runs",
                ref.tolerance, ref.first_step, ref.richardson_order);
  return text;
}

}  // namespace

Dataset convergence_dataset(const ConvergenceTable& table, const Study& study) {
  Dataset d;
  Coordinate integrator{"integrator", "", "integrator of the contact phase", {}, {}};  // strings: no units
  for (const IntegratorConvergence& i : table.integrators) integrator.labels.push_back(to_string(i.method));
  Coordinate setting{"setting", "1", "setting of the integrator, coarsest first", {}, {}};
  const std::size_t settings = most_settings(table);
  for (std::size_t k = 0; k < settings; ++k) setting.values.push_back(static_cast<double>(k));
  d.coordinates = {integrator, setting};
  for (const Column& column : columns) d.variables.push_back(column_variable(table, column, settings));

  const ConvergenceReference& ref = table.reference;
  d.text_attributes = {{"Conventions", "CF-1.8"},
                       {"title", "Convergence: " + study.title},
                       {"study_file", study.file.string()},
                       {"kind", to_string(study.kind)},
                       {"study", study.text},
                       {"reference", describe_reference(ref)},
                       {"program", "sweetspot"},
                       {"program_version", version},
                       {"git_commit", git_commit},
                       {"references", "A. M. Nathan, Am. J. Phys. 68, 979 (2000)"}};
  d.number_attributes = {{"reference_vf", ref.vf},
                         {"reference_contact_time", ref.contact_time},
                         {"richardson_vf", ref.richardson_vf},
                         {"reference_disagreement", ref.disagreement},
                         {"reference_tolerance", ref.tolerance},
                         {"reference_first_step", ref.first_step},
                         {"richardson_order", static_cast<double>(ref.richardson_order)},
                         {"kept_modes", static_cast<double>(table.kept_modes)},
                         {"rk4_largest_step", table.rk4_largest_step}};
  return d;
}

}  // namespace sweetspot
