// The convergence table (sweetspot convergence): its reference is vouched for by Richardson
// extrapolation, exact stepping shows its order a + 1 at fine steps, every integrator's finest setting reaches
// the reference, and the command writes a dataset xarray reads. Quick mode on 18 modes: cheap.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "program.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/study/convergence.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

// The high-impact scene at 60.5 cm (N2000 Figs. 10-11) with 18 modes.
const ConvergenceTable& table() {
  static const ConvergenceTable t = [] {
    const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko);
    ImpactScene s;
    s.z = 0.605;
    s.ball_speed = 40;
    s.swing = {51, true, 0, 0.09};
    s.vibrational_modes = 18;
    return run_convergence(basis, s, true);
  }();
  return t;
}

const IntegratorConvergence& integrator(Method method) {
  const auto& all = table().integrators;
  const auto it = std::ranges::find_if(all, [&](const IntegratorConvergence& i) { return i.method == method; });
  REQUIRE(it != all.end());
  return *it;
}

}  // namespace

TEST_CASE("convergence: the adaptive reference and Richardson extrapolation agree", "[convergence]") {
  const ConvergenceReference& ref = table().reference;
  INFO("reference " << ref.vf << ", Richardson " << ref.richardson_vf);
  CHECK(ref.vf > 30);
  CHECK(ref.disagreement < 1e-8);
  CHECK(ref.disagreement == Approx(std::abs(ref.richardson_vf / ref.vf - 1)));
}

TEST_CASE("convergence: exact stepping's error falls with the step at order a + 1", "[convergence]") {
  const auto& runs = integrator(Method::exact).runs;
  REQUIRE(runs.size() >= 2);
  for (std::size_t k = 1; k < runs.size(); ++k) {
    CHECK(runs[k].step == Approx(runs[k - 1].step / 2));
    CHECK(runs[k].vf_error < runs[k - 1].vf_error);
  }
  const auto &coarse = runs[runs.size() - 2], &fine = runs.back();
  const double order = std::log2(coarse.vf_error / fine.vf_error);
  INFO("vf errors " << coarse.vf_error << " at " << coarse.step << " s, " << fine.vf_error << " at " << fine.step
                    << " s: order " << order);
  // The ball's t^a onset sets the order at fine steps (tests/test_integrators.cpp).
  CHECK(order == Approx(Ball().a + 1).margin(0.4));
  CHECK(table().reference.richardson_order == Ball().a + 1);
}

TEST_CASE("convergence: every integrator's finest setting reaches the reference", "[convergence]") {
  for (const IntegratorConvergence& i : table().integrators) {
    INFO(to_string(i.method));
    REQUIRE(i.runs.size() == 3);  // quick
    for (const ConvergenceRun& run : i.runs) {
      CHECK(run.status == CollisionStatus::ok);
      CHECK(run.time_per_impact > 0);
      CHECK(std::isnan(i.method == Method::dopri ? run.step : run.tolerance));
    }
    CHECK(i.runs.back().vf_error < 1e-8);
    CHECK(i.runs.back().contact_time_error < 1e-8);
    CHECK(i.runs.back().energy_error < 1e-8);
    CHECK(cheapest_within(i, 1e-8) != nullptr);
  }
  CHECK(cheapest_within(integrator(Method::exact), 0) == nullptr);
}

TEST_CASE("convergence: the command writes one dataset that xarray opens", "[convergence][program]") {
  TempDir dir;
  const auto study = dir.write("scene.toml", "# 18 modes\ntitle = \"high impact\"\n[scene]\nbat = \"" +
                                                 source_path("studies/bats/r161.toml") +
                                                 "\"\nz = 0.605\nball_speed = 40\ncenter = 0.09\nomega = 51\n"
                                                 "e0 = 0.5\nmodes = 18\n");
  const std::string out = dir / "out.h5";
  const ProgramRun run = run_program("convergence " + study.string() + " -o " + out + " --quick");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("Richardson") && Catch::Contains("wrote"));
  const ProgramRun check =
      run_command(std::string(python) + " " + source_path("tests/check_convergence.py") + " " + out + " 3");
  INFO(check.output);
  CHECK(check.exit_code == 0);
  // The figure's script draws both panels from it (the work-precision diagram, the accuracy sweep).
  const std::string png = dir / "out.png";
  const ProgramRun plot =
      run_command(std::string(python) + " " + source_path("scripts/plot_convergence.py") + " " + out + " " + png);
  INFO(plot.output);
  CHECK(plot.exit_code == 0);
  CHECK(std::filesystem::file_size(png) > 10000);
}

// Every row of its table was NaN and the command exited 0, writing the dataset.
TEST_CASE("convergence: a scene where the ball never meets the bat is refused", "[convergence][program]") {
  TempDir dir;
  const auto study = dir.write("away.toml", "[scene]\nbat = \"" + source_path("studies/bats/r161.toml") +
                                                "\"\ncenter = 0.09\nomega = 51\nz = 0.7\nball_speed = -40\n");
  const ProgramRun run = run_program("convergence " + study.string() + " -o " + dir / "away.h5" + " --quick");
  INFO(run.output);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("away.toml: the scene: ball and bat never approach"));
  CHECK_FALSE(std::filesystem::exists(dir / "away.h5"));
}

TEST_CASE("convergence: a study of another kind is refused with exit status 2", "[convergence][program]") {
  const ProgramRun run = run_program("convergence " + source_path("studies/wall.toml") + " -o /nonexistent/x.h5");
  INFO(run.output);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("wall.toml") && Catch::Contains("impact"));
}
