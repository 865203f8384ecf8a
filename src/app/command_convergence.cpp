// sweetspot convergence: error against run time for every integrator on a study's base scene,
// and the total error (each source estimated, and the actual one against the continuum) at every
// stated accuracy, logged as tables and written as one dataset (a work-precision diagram's data).
#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "commands.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/study/accuracy_sweep.hpp"
#include "sweetspot/study/convergence.hpp"
#include "sweetspot/study/dataset.hpp"
#include "sweetspot/study/input_kind.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/output_lock.hpp"
#include "sweetspot/study/output_paths.hpp"

namespace sweetspot::app {

namespace {

// The error the recommendation asks of each integrator: well below any physical uncertainty.
constexpr double recommended_vf_error = 1e-6;

struct ConvergenceCommandOptions {
  std::string study;
  std::string output;
  bool output_given = false;  // `-o ""` is a mistake to refuse, not a wish for the default
  bool quick = false;
};

// "z = 0.605, bat = R161": where grid point 0 sits on the study's axes.
std::string describe_point(const Study& study, const GridPoint& point) {
  std::string text;
  for (std::size_t a = 0; a < study.axes.size(); ++a) {
    const Axis& axis = study.axes[a];
    const std::size_t i = point.coords[a];
    const std::string value = axis.name == "bat" ? study.bat_names[point.bat]
                              : axis.labels.empty() ? fmt::format("{:g}", axis.values[i])
                                                    : axis.labels[i];
    text += (text.empty() ? "" : ", ") + axis.name + " = " + value;
  }
  return text;
}

std::string describe_setting(Method method, const ConvergenceRun& run) {
  if (method == Method::dopri) return fmt::format("tol {:.0e}", run.tolerance);
  return fmt::format("dt {:.4g} us", 1e6 * run.step);
}

void log_table(const ConvergenceTable& table) {
  const ConvergenceReference& ref = table.reference;
  spdlog::info("reference vf = {:.12f} m/s (dopri, tolerance {:g}), Richardson (exact, order {}) {:.12f} m/s: "
               "relative difference {:.2e}",
               ref.vf, ref.tolerance, ref.richardson_order, ref.richardson_vf, ref.disagreement);
  spdlog::info("{:<6} {:<16} {:>10} {:>14} {:>13} {:>12}", "method", "setting", "vf error", "contact error",
               "energy error", "time/impact");
  for (const IntegratorConvergence& integrator : table.integrators)
    for (const ConvergenceRun& run : integrator.runs)
      spdlog::info("{:<6} {:<16} {:>10.2e} {:>14.2e} {:>13.2e} {:>9.1f} us{}", to_string(integrator.method),
                   describe_setting(integrator.method, run), run.vf_error, run.contact_time_error, run.energy_error,
                   1e6 * run.time_per_impact,
                   run.status == CollisionStatus::ok ? "" : std::string("  ") + to_string(run.status));
  for (const IntegratorConvergence& integrator : table.integrators) {
    const ConvergenceRun* best = cheapest_within(integrator, recommended_vf_error);
    if (best)
      spdlog::info("cheapest {} reaching vf error {:g}: {} ({:.2e}), {:.1f} us per impact",
                   to_string(integrator.method), recommended_vf_error, describe_setting(integrator.method, *best),
                   best->vf_error, 1e6 * best->time_per_impact);
    else
      spdlog::info("no {} setting reaches vf error {:g}", to_string(integrator.method), recommended_vf_error);
  }
}

std::string describe_choice(const AccuracyRun& run) {
  const std::string step = run.step > 0 ? fmt::format("{:.3g} us", 1e6 * run.step) : "adaptive";
  return fmt::format("{:g} slices, {:g} modes, {}", run.slices, run.modes, step);
}

void log_sweep(const AccuracySweep& sweep) {
  spdlog::info("continuum vf = {:.10f} m/s (Richardson in the slices up to {}, modes auto at 1e-9, exact at 2.5 us; its "
               "last two slicings differ by {:.1e})",
               sweep.reference_vf, sweep.reference_slices, sweep.reference_difference);
  spdlog::info("{:<9} {:<34} {:>9} {:>9} {:>9} {:>9} {:>9} {:>7} {:>12}", "accuracy", "chosen", "slicing", "modes",
               "step", "total", "actual", "ratio", "time/impact");
  for (const AccuracyRun& run : sweep.runs)
    spdlog::info("{:<9} {:<34} {:>9.2e} {:>9.2e} {:>9.2e} {:>9.2e} {:>9.2e} {:>7.2f} {:>9.1f} us{}",
                 std::isnan(run.accuracy) ? std::string("default") : fmt::format("{:g}", run.accuracy),
                 describe_choice(run), run.slicing_error, run.modes_error, run.step_error, run.total_error,
                 run.actual_error, run.total_error / run.actual_error, 1e6 * run.time_per_impact,
                 run.status == CollisionStatus::ok ? "" : std::string("  ") + to_string(run.status));
}

void run(const ConvergenceCommandOptions& o) {
  spdlog::set_pattern("[%H:%M:%S] %v");
  require_input_kind(o.study, {InputKind::study}, "convergence", "study file");
  const Study study = load_study(o.study);
  if (study.kind != StudyKind::impact)
    throw InputError(o.study + ": kind = \"" + to_string(study.kind) +
                     "\": convergence needs a study of kind \"impact\" (a ball on a bat)");
  const GridPoint point = grid_point(study, 0);
  // The table sets every integrator's step and tolerance itself, and the sweep each accuracy: a
  // study's own choice of step would stand in for theirs at every row.
  const std::pair<const char*, double> chosen[] = {{"accuracy", point.scene.accuracy},
                                                   {"step_accuracy", point.scene.step_accuracy}};
  for (const auto& [key, value] : chosen)
    if (value > 0)
      throw InputError(fmt::format("{}: key '{}' = {:g}: convergence runs every integrator at its own steps and "
                                   "each accuracy of its sweep itself; expected no {} in the study",
                                   o.study, key, value, key));
  const std::filesystem::path out =
      o.output_given ? o.output : std::filesystem::path(o.study).stem().string() + "_convergence.h5";
  // Before any work, and held to the end: a run or another convergence writing the same output
  // would share its temporary file.
  check_output_paths(out, {dataset_temporary_path(out), OutputLock::path_for(out)}, study_inputs(study));
  const OutputLock lock(out);
  if (!study.axes.empty())
    spdlog::info("{} has {} grid points: using grid point 0 ({})", o.study, study.points(),
                 describe_point(study, point));
  Bat bat = study.designs[point.design];  // as the study read and checked it
  if (point.slices > 0) bat = resample(bat, point.slices);
  // Every mode while the full solve is practical; past that, what an impact of the scene asks.
  const ModalBasis basis =
      compute_modes(bat, point.theory,
                    bat.slices() <= max_full_solve_slices
                        ? ModeRequest::all()
                        : impact_mode_request(point.scene, compute_modes(bat, point.theory, ModeRequest::rigid_only())));

  // A point where the ball never meets the bat has nothing to converge: every row would be NaN.
  if (const ImpactResult probe = simulate_impact(basis, point.scene); probe.status == CollisionStatus::no_contact)
    throw InputError(o.study + ": " + (study.axes.empty() ? "the scene" : "grid point 0 (" +
                     describe_point(study, point) + ")") + ": " + probe.message +
                     ": expected a point where the ball meets the bat");
  const ConvergenceTable table = run_convergence(basis, point.scene, o.quick);
  spdlog::info("{}: z = {:g} m, {} modes kept (rigid included), largest stable RK4 step {:.4g} us{}", bat.name,
               point.scene.z, table.kept_modes, 1e6 * table.rk4_largest_step, o.quick ? " (quick)" : "");
  log_table(table);
  // Every source at once: the slicing too, against the continuum the bat file describes.
  const AccuracySweep sweep = run_accuracy_sweep(study.design_specs[point.design], bat.slices(), point.theory,
                                                 point.scene, o.quick);
  log_sweep(sweep);
  Dataset dataset = convergence_dataset(table, study);
  add_accuracy_sweep(dataset, sweep);
  write_dataset(out, dataset);
  spdlog::info("wrote {}", out.string());
}

}  // namespace

void add_convergence_command(CLI::App& app) {
  auto o = std::make_shared<ConvergenceCommandOptions>();
  CLI::App* cmd =
      app.add_subcommand("convergence", "Error against run time of every integrator on a study's base scene");
  cmd->add_option("study", o->study, "study file (TOML) of kind \"impact\"; with axes, grid point 0")->required();
  CLI::Option* output =
      cmd->add_option("-o,--output", o->output, "dataset to write (default: the study's name + _convergence.h5)");
  cmd->add_flag("--quick", o->quick, "the 3 finest settings of each integrator, each timed once (for tests)");
  cmd->callback([o, output] {
    o->output_given = output->count() > 0;
    run(*o);
  });
}

}  // namespace sweetspot::app
