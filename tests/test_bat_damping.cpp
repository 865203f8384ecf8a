// The bat's own damping (README "Damping", Material::loss_factor): every vibrational mode of the
// beam damped at zeta = eta / 2. Zero changes no bit; the loss is integrated with the modes and
// closes the energy balance with the ball's COR law, the barrel's patch and the wall's damping;
// the three integrators agree; more damping takes more; wood presets carry wood's 0.01; bad
// loss factors are refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "program.hpp"
#include "refusal.hpp"
#include "study_dir.hpp"
#include "sweetspot/ball/ball_presets.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_design_text.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/material_presets.hpp"
#include "sweetspot/impact/impact.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

Bat with_loss(Bat bat, double eta) {
  bat.material.loss_factor = eta;
  return bat;
}

ImpactScene swing_at(double z, bool pivoted) {
  ImpactScene scene;
  scene.z = z, scene.ball_speed = 40, scene.swing.omega = 51;
  scene.swing.about_center = true, scene.swing.center = pivoted ? 0.1524 : 0.09;
  scene.pivoted = pivoted;
  return scene;
}

}  // namespace

TEST_CASE("A loss factor of 0 leaves every result as it was, bit for bit", "[damping]") {
  const Bat bat = load_bat(source_path("studies/bats/r161.toml"));
  REQUIRE(bat.material.loss_factor == 0);  // N2000's bat: given by its constants, undamped
  const ModalBasis basis = compute_modes(bat, BeamTheory::timoshenko);
  ImpactScene scene = swing_at(0.6, false);
  const ImpactResult a = simulate_impact(basis, scene);
  CHECK(a.energy.damped == 0);
  scene.vibrational_modes = all_modes;
  const ImpactResult b = simulate_impact(basis, scene);
  CHECK(b.energy.damped == 0);
  // The same bat with the key given as 0 is the same bat.
  const TempDir dir;
  const auto file = dir.write("r161.toml", "name = \"R161\"\nlength = 0.84\nprofile = \"" +
                                               source_path("studies/bats/r161_profile.csv") +
                                               "\"\n[material]\ndensity = 649\nyoungs_modulus = 1.814e10\n"
                                               "shear_modulus = 1.05e9\nloss_factor = 0\n");
  CHECK(simulate_impact(compute_modes(load_bat(file), BeamTheory::timoshenko), scene).vf == b.vf);
}

TEST_CASE("The energy balance closes with the bat damped, the ball's COR law and the patch-loaded wall",
          "[damping]") {
  const Ball ball = preset_ball(find_ball_preset("ncaa", "test")).ball;
  for (const char* file : {"studies/bats/maple_271.toml", "studies/bats/alloy_bbcor.toml"}) {
    const ModalBasis basis = compute_modes(with_loss(load_bat(source_path(file)), 0.02), BeamTheory::timoshenko);
    for (const bool pivoted : {false, true})
      for (const double z : {0.45, 0.64, 0.72}) {
        ImpactScene scene = swing_at(z, pivoted);
        scene.ball = ball;
        double vf[3];
        int k = 0;
        for (const Method method : {Method::exact, Method::rk4, Method::dopri}) {
          scene.integrator.method = method;
          scene.integrator.dt = method == Method::rk4 ? 1e-6 : method == Method::dopri ? 1e-6 : 1e-5;
          scene.integrator.tolerance = 1e-12;
          const ImpactResult r = simulate_impact(basis, scene);
          INFO(file << " pivoted " << pivoted << " z " << z << " " << to_string(method));
          REQUIRE(r.status == CollisionStatus::ok);
          CHECK(r.energy.damped > 0);
          CHECK(std::abs(r.energy.residual) <= 1e-6 * r.energy.initial);
          vf[k++] = r.vf;
        }
        CHECK(vf[1] == Approx(vf[0]).epsilon(1e-6));
        CHECK(vf[2] == Approx(vf[0]).epsilon(1e-6));
      }
  }
}

TEST_CASE("More damping takes more of the vibration", "[damping]") {
  const Bat bat = load_bat(source_path("studies/bats/r161.toml"));
  double previous_loss = -1, previous_vibration = 1e9;
  for (const double eta : {0.0, 0.005, 0.01, 0.05}) {
    const ModalBasis basis = compute_modes(with_loss(bat, eta), BeamTheory::timoshenko);
    ImpactScene scene = swing_at(0.5, false);
    scene.vibrational_modes = all_modes;
    const ImpactResult r = simulate_impact(basis, scene);
    INFO("eta " << eta);
    CHECK(r.energy.damped > previous_loss);
    CHECK(r.energy.vibration < previous_vibration);
    previous_loss = r.energy.damped, previous_vibration = r.energy.vibration;
  }
}

TEST_CASE("Wood presets carry wood's loss factor, and a bat file's design writes it back", "[damping]") {
  for (const MaterialPreset& p : material_preset_list()) CHECK(p.material.loss_factor == 0.01);
  BatSource source;
  BatDesign d = load_bat_design(source_path("studies/bats/maple_271.toml"), source);
  CHECK(d.material.loss_factor == 0.01);
  set_design_parameter(d, "loss_factor", 0.03);
  const TempDir dir;
  const auto file = dir.write("written.toml", bat_design_text(d, "test"));
  CHECK(load_bat(file).material.loss_factor == 0.03);
}

TEST_CASE("A loss factor below 0 or from 1 up is refused naming the file and key", "[damping]") {
  const TempDir dir;
  for (const char* value : {"1", "-0.1", "\"x\"", "nan"}) {
    const auto file = dir.write("bad.toml", std::string("name = \"b\"\nlength = 0.84\nprofile = \"") +
                                                source_path("studies/bats/r161_profile.csv") +
                                                "\"\n[material]\npreset = \"ash\"\nloss_factor = " + value + "\n");
    require_refused(run_program("modes " + file.string()), {"bad.toml", "loss_factor", "[0, 1)"});
  }
}

TEST_CASE("A scene that asks no energy skips the damping's integral and moves exactly as one that does",
          "[damping]") {
  const ModalBasis basis =
      compute_modes(load_bat(source_path("studies/bats/maple_271.toml")), BeamTheory::timoshenko);
  for (const double z : {0.5, 0.7}) {
    ImpactScene scene = swing_at(z, false);
    const ImpactResult tracked = simulate_impact(basis, scene);
    scene.integrator.damping_loss = false;
    const ImpactResult skipped = simulate_impact(basis, scene);
    CHECK(skipped.status == CollisionStatus::ok);
    CHECK(skipped.vf == tracked.vf);  // the dissipation is a record, not a force
    CHECK(tracked.energy.damped > 0);
    CHECK(std::isnan(skipped.energy.damped));
  }
}
