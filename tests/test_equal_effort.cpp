// Equal-effort swings and batted-ball speeds: the reference bat keeps the player's swing exactly,
// another bat's swing scales as its knob MOI to the power -n; the struck point's speed is the
// swing's; the rules' linear batted-ball speed is the full model's exactly for a rigid bat, and
// for a flexible one when e_A is taken at the collision's own relative speed (the bat's initial
// motion is rigid, so only the relative speed at the struck point matters).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "study_dir.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/batted_ball.hpp"
#include "sweetspot/impact/equal_effort.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/study.hpp"

using namespace sweetspot;

namespace {

Bat r161() { return load_bat(source_path("studies/bats/r161.toml")); }

double knob_moi(const std::string& file) {
  BatSource source;
  return design_mass_properties(load_bat_design(source_path(file), source)).moment_of_inertia_about(0);
}

std::string refusal(const std::string& scene) { return study_refusal(StudyDir(3, scene).study); }

// N2000's high-impact swing (51 rad/s about 9 cm from the knob), a 38 m/s pitch, asking for the
// linear batted-ball speed with e_A taken at `e_a_speed`.
ImpactScene swung_scene(double z, int modes, double e_a_speed) {
  ImpactScene scene;
  scene.z = z;
  scene.ball_speed = 38;
  scene.swing = {51, true, 0, 0.09};
  scene.vibrational_modes = modes;
  scene.linear_batted_ball = true;
  scene.e_a_speed = e_a_speed;
  return scene;
}

}  // namespace

TEST_CASE("An equal-effort swing scales as the knob MOI to the power -n, and keeps the reference's", "[swing]") {
  const Swing given{51, true, 0, 0.09};
  const Swing same = equal_effort_swing(given, 0.2, 0.2, 0.3);
  CHECK(same.omega == given.omega);
  CHECK(same.center == given.center);
  const Swing heavier = equal_effort_swing(given, 0.2, 0.25, 0.3);
  CHECK(heavier.omega == Approx(51 * std::pow(0.2 / 0.25, 0.3)).epsilon(1e-15));
  CHECK(heavier.center == given.center);
  const Swing translating = equal_effort_swing({51, false, 20, 0}, 0.2, 0.16, 0.25);
  CHECK(translating.cm_speed / translating.omega == Approx(20.0 / 51).epsilon(1e-15));  // the same field, scaled
}

TEST_CASE("In a study the reference bat swings as given and the others with the same effort", "[swing]") {
  const StudyDir d(3, "swing = \"equal_effort\"\nreference_bat = \"bats/r161.toml\"\nswing_exponent = 0.27\n");
  const Study study = load_study(d.study);
  REQUIRE(study.equal_effort);
  const double i_r161 = knob_moi("studies/bats/r161.toml"), i_torpedo = knob_moi("studies/bats/torpedo.toml");
  CHECK(study.reference_moi == i_r161);
  for (std::size_t i = 0; i < study.points(); ++i) {
    const GridPoint p = grid_point(study, i);
    const double expected = p.bat == 0 ? 51 : 51 * std::pow(i_r161 / i_torpedo, 0.27);
    CHECK(p.scene.swing.omega == Approx(expected).epsilon(1e-15));
    CHECK(p.scene.swing.center == 0.09);
  }
}

TEST_CASE("The struck point moves at the swing's speed there", "[swing]") {
  const ModalBasis basis = compute_modes(r161(), BeamTheory::timoshenko, ModeRequest::lowest(4));
  ImpactScene scene;
  scene.z = 0.683;
  scene.swing = {51, true, 0, 0.09};
  scene.vibrational_modes = 4;
  CHECK(simulate_impact(basis, scene).bat_speed == Approx(51 * (0.683 - 0.09)).epsilon(1e-13));
}

TEST_CASE("The linear batted-ball speed is the rigid bat's exactly", "[swing]") {
  const ModalBasis basis = compute_modes(r161(), BeamTheory::timoshenko, ModeRequest::rigid_only());
  for (const double z : {0.5, 0.683, 0.8})
    for (const double e_a_speed : {20.0, lab_e_a_speed}) {
      ImpactScene scene = swung_scene(z, 0, e_a_speed);
      scene.integrator.dt = 2e-6;  // e_A from a collision at another speed: integrated finely, both
      const ImpactResult r = simulate_impact(basis, scene);
      REQUIRE(r.status == CollisionStatus::ok);
      CHECK(r.bbs_linear == Approx(r.vf).epsilon(1e-9));
    }
}

TEST_CASE("With e_A at the collision's relative speed the linear rule is the flexible bat's too", "[swing]") {
  const ModalBasis basis = compute_modes(r161(), BeamTheory::timoshenko, ModeRequest::lowest(18));
  for (const double z : {0.55, 0.683, 0.78}) {
    const ImpactResult r = simulate_impact(basis, swung_scene(z, 18, 38 + 51 * (z - 0.09)));
    REQUIRE(r.status == CollisionStatus::ok);
    CHECK(r.bbs_linear == Approx(r.vf).epsilon(1e-9));
    // Taken at the lab's 136 mph instead, a flexible bat's e_A is not the game's: the rule errs,
    // by far more than the integration but by little.
    const double error = std::abs(simulate_impact(basis, swung_scene(z, 18, lab_e_a_speed)).bbs_linear / r.vf - 1);
    CHECK(error > 1e-6);
    CHECK(error < 0.05);
  }
}

TEST_CASE("Bad equal-effort settings are refused naming the key", "[swing]") {
  CHECK_THAT(refusal("swing = \"equal_effort\"\n"), Catch::Contains("reference_bat") && Catch::Contains("missing"));
  CHECK_THAT(refusal("reference_bat = \"bats/r161.toml\"\n"),
             Catch::Contains("key 'scene.reference_bat'") && Catch::Contains("equal_effort"));
  CHECK_THAT(refusal("swing = \"fast\"\n"), Catch::Contains("key 'scene.swing' = \"fast\""));
  // The range optimisations take too: 0 (every bat swung as the reference) to 2.
  CHECK_THAT(refusal("swing = \"equal_effort\"\nreference_bat = \"bats/r161.toml\"\nswing_exponent = 2.5\n"),
             Catch::Contains("key 'scene.swing_exponent' = 2.5") && Catch::Contains("[0, 2]"));
  CHECK_THAT(refusal("swing = \"equal_effort\"\nreference_bat = \"bats/r161.toml\"\nswing_exponent = -0.1\n"),
             Catch::Contains("key 'scene.swing_exponent' = -0.1"));
  CHECK_THAT(refusal("swing = \"equal_effort\"\nreference_bat = \"bats/none.toml\"\n"),
             Catch::Contains("key 'scene.reference_bat'") && Catch::Contains("none.toml"));
}
