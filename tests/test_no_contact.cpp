// A ball and a bat that never approach have no collision: status no_contact and NaN results,
// through the library, `sweetspot impact` and a study's dataset. A ball at rest struck by the bat
// (a tee) collides as any other. No NaN output ever comes with status ok.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "program.hpp"
#include "temp_dir.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/formulas.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/wall.hpp"

using namespace sweetspot;

namespace {

const ModalBasis& r161() {
  static const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko);
  return basis;
}

// Every output the library can compute, asked for.
ImpactScene asking_everything(ImpactScene s) {
  s.rigid_comparison = s.van_zandt_comparison = s.histories = s.force_response = s.mode_response = true;
  s.history.probes = {0.13};
  return s;
}

// The bat translating at cm_speed toward the ball, no rotation.
ImpactScene translating(double z, double ball_speed, double cm_speed) {
  ImpactScene s;
  s.z = z;
  s.ball_speed = ball_speed;
  s.swing = {0, false, cm_speed, 0};
  return asking_everything(s);
}

// The high-impact swing, 51 rad/s about 9 cm from the knob: the knob moves away from the ball.
ImpactScene swung(double z, double ball_speed, bool pivoted = false) {
  ImpactScene s;
  s.z = z;
  s.ball_speed = ball_speed;
  s.swing = {51, true, 0, 0.09};
  s.pivoted = pivoted;
  return asking_everything(s);
}

void require_no_contact(const ImpactResult& r) {
  INFO(to_string(r.status) << ": " << r.message);
  REQUIRE(r.status == CollisionStatus::no_contact);
  CHECK_THAT(r.message, Catch::Contains("never approach"));
  for (double x : {r.vf, r.e_eff, r.contact_time, r.collision_time, r.u_max, r.peak_force, r.impulse, r.vf_rigid,
                   r.vf_van_zandt, r.energy.ball, r.energy.vibration, r.energy.residual})
    CHECK(std::isnan(x));
  CHECK(r.contacts == 0);
  CHECK(r.mode_energy.empty());
  CHECK(r.force_response.empty());
  CHECK(r.mode_response.empty());
  CHECK(r.histories.time.empty());
}

}  // namespace

TEST_CASE("A ball moving away from a slower bat has no contact, whatever the integrator", "[no_contact]") {
  for (Method method : {Method::exact, Method::rk4, Method::dopri})
    for (int modes : {0, 18, auto_modes}) {
      ImpactScene s = translating(0.705, -40, 10);
      s.integrator.method = method;
      s.integrator.dt = default_step(method);
      s.vibrational_modes = modes;
      INFO(to_string(method) << ", modes " << modes);
      require_no_contact(simulate_impact(r161(), s));
    }
  // Moving together at the same speed, they never meet either.
  require_no_contact(simulate_impact(r161(), translating(0.705, -10, 10)));
  // The bat catching up with a receding ball does meet it: closing speed 5 m/s.
  const ImpactResult caught = simulate_impact(r161(), translating(0.705, -5, 10));
  CHECK(caught.status == CollisionStatus::ok);
  CHECK(caught.vf > 10);  // the ball leaves faster than the bat came
}

TEST_CASE("At the knob of a bat rotating away, a slow ball has no contact, free or pivoted", "[no_contact]") {
  // v_bat(0) = 51 (0 - 0.09) = -4.6 m/s: the knob recedes faster than the ball arrives.
  for (double ball_speed : {0.0, 0.5, 1.0})
    for (bool pivoted : {false, true}) {
      INFO("ball " << ball_speed << " m/s, pivoted " << pivoted);
      require_no_contact(simulate_impact(r161(), swung(0.0, ball_speed, pivoted)));
    }
  // A ball fast enough to catch it collides.
  CHECK(simulate_impact(r161(), swung(0.0, 10)).status == CollisionStatus::ok);
}

TEST_CASE("A ball at rest struck by the bat (a tee) collides: the rigid bat's exit speed", "[no_contact]") {
  // Rigid bat, ball at rest: v_f = (1 + e0) / (1 + R0) v_bat (physics.md §5).
  ImpactScene s = translating(0.605, 0, 30);
  s.vibrational_modes = 0;
  const ImpactResult r = simulate_impact(r161(), s);
  REQUIRE(r.status == CollisionStatus::ok);
  const SceneGeometry g = scene_geometry(s, r161());
  CHECK(r.vf == Approx((1 + s.ball.e0) / (1 + g.recoil) * 30).epsilon(1e-6));
  CHECK(r.e_eff == Approx(s.ball.e0).epsilon(1e-6));
  // With the flexible bat, every output asked is finite.
  s.vibrational_modes = auto_modes;
  const ImpactResult flexible = simulate_impact(r161(), s);
  REQUIRE(flexible.status == CollisionStatus::ok);
  CHECK(flexible.vf > 0);
  CHECK(std::isfinite(flexible.vf_van_zandt));
  CHECK(std::isfinite(flexible.force_response.back()));
}

TEST_CASE("A ball moving away from the wall has no contact", "[no_contact]") {
  const ImpactResult r = hit_wall(Ball{}, -3, CollisionOptions{});
  CHECK(r.status == CollisionStatus::no_contact);
  CHECK(std::isnan(r.vf));
  CHECK(std::isnan(r.e_eff));
}

TEST_CASE("An ok result with a NaN or infinite output becomes non_finite, naming it", "[no_contact]") {
  const ImpactResult good = simulate_impact(r161(), swung(0.705, 40));
  REQUIRE(good.status == CollisionStatus::ok);
  ImpactResult r = good;
  require_finite(r, {true, true, true});
  CHECK(r.status == CollisionStatus::ok);  // vf_rigid and vf_van_zandt computed: all finite
  r.force_response.back() = std::numeric_limits<double>::quiet_NaN();
  require_finite(r, {});
  CHECK(r.status == CollisionStatus::non_finite);
  CHECK(r.message == "force_response is not finite");
  r = good;
  r.mode_response.front() = std::numeric_limits<double>::infinity();
  require_finite(r, {});
  CHECK(r.message == "mode_response is not finite");
  // A value not asked for is NaN by design, and is not held against the result.
  r = good;
  r.collision_time = std::numeric_limits<double>::quiet_NaN();
  require_finite(r, {false});
  CHECK(r.status == CollisionStatus::ok);
  require_finite(r, {true});
  CHECK(r.message == "collision_time is not finite");
}

TEST_CASE("sweetspot impact reports no_contact with null results", "[no_contact][program]") {
  const std::string bat = "impact --bat " + source_path("studies/bats/r161.toml");
  for (const std::string scene : {" --z 0.7 --ball-speed -40 --cm-speed 10 --omega 0",
                                  " --z 0 --ball-speed 1 --center 0.09 --omega 51"}) {
    const ProgramRun run = run_program(bat + scene + " --json");
    INFO(scene << "\n" << run.output);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains("\"status\": \"no_contact\""));
    CHECK_THAT(run.output, Catch::Contains("\"vf\": null, \"e_eff\": null, \"contact_time\": null"));
    CHECK_THAT(run.output, Catch::Contains("\"contacts\": 0"));
  }
  const ProgramRun tee = run_program(bat + " --z 0.7 --ball-speed 0 --center 0.09 --omega 51 --json");
  CHECK_THAT(tee.output, Catch::Contains("\"status\": \"ok\""));
}

TEST_CASE("A study stores no_contact in its status flags and NaN in its values", "[no_contact][program]") {
  TempDir dir;
  const auto study = dir.write("study.toml", "[scene]\nbat = \"" + source_path("studies/bats/r161.toml") +
                                                 "\"\nz = 0.705\ncm_speed = 10\nomega = 0\n[axes]\n"
                                                 "ball_speed = [-40, 0, 40]\n[output]\nvariables = [\"vf\", "
                                                 "\"vf_van_zandt\", \"force_response\", \"status\"]\n");
  const ProgramRun run = run_program("run " + study.string() + " -o " + dir / "out.h5 --quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun read = run_command(
      std::string(python) +
      " -c \"import xarray as xr, numpy as np; ds = xr.open_dataset('" + dir / "out.h5" +
      "', engine='h5netcdf'); s = ds.status; meaning = dict(zip(s.flag_values.tolist(), s.flag_meanings.split())); "
      "print([meaning[int(x)] for x in s.values], np.isnan(ds.vf.values).tolist(), "
      "bool(np.isnan(ds.force_response.values[0]).all()), bool(np.isfinite(ds.force_response.values[1:]).all()))\"");
  INFO(read.output);
  CHECK(read.exit_code == 0);
  CHECK_THAT(read.output,
             Catch::Contains("['no_contact', 'ok', 'ok'] [True, False, False] True True"));
}
