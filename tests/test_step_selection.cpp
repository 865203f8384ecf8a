// A stated accuracy chooses the step: the exit speed then errs by no more than that, whatever the
// scene's pulse (fast or slow, few or all modes) and the method.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "n2000_scenes.hpp"
#include "program.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/step_selection.hpp"

using namespace sweetspot;

namespace {

const ModalBasis& r161() {
  static const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko);
  return basis;
}

struct Scene {
  const char* name;
  ImpactScene scene;
};

ImpactScene high_impact(double z, int modes, double speed = 40) {
  ImpactScene s = n2000_high_impact(z, modes);
  s.ball_speed = speed;
  return s;
}

ImpactScene low_impact(double z) { return n2000_low_impact(z); }

double vf(ImpactScene s) {
  const ImpactResult r = simulate_impact(r161(), s);
  REQUIRE(r.status == CollisionStatus::ok);
  return r.vf;
}

double reference(ImpactScene s) {
  s.step_accuracy = 0;
  s.integrator.method = Method::dopri;
  s.integrator.dt = 1e-7;
  s.integrator.tolerance = 1e-13;
  return vf(s);
}

}  // namespace

TEST_CASE("A stated accuracy bounds the exit speed's error for every method", "[step_selection]") {
  const Scene scenes[] = {{"high impact 60.5 cm, all modes", high_impact(0.605, all_modes)},
                          {"high impact 70.5 cm, 18 modes", high_impact(0.705, 18)},
                          {"high impact 80.5 cm, 150 m/s", high_impact(0.805, 18, 150)},
                          {"low impact 60.5 cm", low_impact(0.605)}};
  for (const Scene& c : scenes) {
    const double exact = reference(c.scene);
    for (Method method : {Method::exact, Method::rk4, Method::dopri})
      for (double accuracy : {1e-4, 1e-6}) {
        if (method == Method::dopri && c.scene.vibrational_modes == all_modes) continue;  // explicit: slow
        ImpactScene s = c.scene;
        s.integrator.method = method;
        s.step_accuracy = accuracy;
        const double error = std::abs(vf(s) / exact - 1);
        INFO(c.name << ", " << to_string(method) << ", accuracy " << accuracy << ": error " << error);
        CHECK(error <= accuracy);
      }
  }
}

TEST_CASE("Looser accuracy takes longer steps", "[step_selection]") {
  // Fewer force samples (one per step) at 1e-4 than at 1e-8.
  ImpactScene s = high_impact(0.705, 18);
  s.integrator.method = Method::exact;
  s.integrator.record_force = true;
  s.step_accuracy = 1e-4;
  const auto loose = simulate_impact(r161(), s).force.size();
  s.step_accuracy = 1e-8;
  const auto tight = simulate_impact(r161(), s).force.size();
  CHECK(loose * 4 < tight);
}

TEST_CASE("A stated accuracy holds for a nearly dead ball: its fast expansion shortens the step",
          "[step_selection]") {
  // e0 = 0.2: on expansion F ~ u^70, which falls within a few contact periods 1/omega_c. A step
  // fit for the pulse duration alone (omega_c h up to 2) errs by up to 1.6e-3 at accuracy 1e-4.
  double worst_without = 0;
  for (int modes : {18, all_modes})
    for (double z : {0.605, 0.705}) {
      ImpactScene scene = high_impact(z, modes);
      scene.ball.e0 = 0.2;
      scene.integrator.method = Method::exact;
      const double exact = reference(scene);
      for (double accuracy : {1e-4, 1e-6}) {
        ImpactScene s = scene;
        s.step_accuracy = accuracy;
        const double error = std::abs(vf(s) / exact - 1);
        INFO("z " << z << ", modes " << modes << ", accuracy " << accuracy << ": error " << error);
        CHECK(error <= accuracy);
        // The same pulse-set step with only the stability bound on omega_c h.
        const SceneGeometry g = scene_geometry(s, r161());
        s.integrator = options_for_accuracy(s.integrator, accuracy, s.ball, s.ball_speed + g.bat_speed, g.recoil, 0);
        s.integrator.contact_phase_limit = 2;
        s.step_accuracy = 0;
        worst_without = std::max(worst_without, std::abs(vf(s) / exact - 1) / accuracy);
      }
    }
  CHECK(worst_without > 1);
}

TEST_CASE("A stated accuracy is checked against a run at twice the step, twice where the ball is caught again",
          "[step_selection]") {
  // Near the handle a nearly dead ball (e0 = 0.2) at 150 m/s is caught a second time; at the step
  // the model picks for 1e-4 alone its exit speed errs by 3.2e-4, 3 times the accuracy asked.
  ImpactScene s = high_impact(0.305, 18, 150);
  s.ball.e0 = 0.2;
  s.integrator.method = Method::exact;
  const double exact = reference(s);
  s.step_accuracy = 1e-4;
  const ImpactResult checked = simulate_impact(r161(), s);
  REQUIRE(checked.status == CollisionStatus::ok);
  CHECK(checked.contacts == 2);
  CHECK(std::abs(checked.vf / exact - 1) <= s.step_accuracy);
  // The model's step alone.
  const SceneGeometry g = scene_geometry(s, r161());
  s.integrator = options_for_accuracy(s.integrator, s.step_accuracy, s.ball, s.ball_speed + g.bat_speed, g.recoil, 0);
  s.step_accuracy = 0;
  const ImpactResult single = simulate_impact(r161(), s);
  CHECK(std::abs(single.vf / exact - 1) > 2 * 1e-4);
}

TEST_CASE("Over the stated range exact stepping meets accuracy = A (README, Numerics)", "[step_selection]") {
  // The range the README states: 40.5-80.5 cm, ball 1-150 m/s, e0 0.4-1 (a = 1.84), 18 and
  // auto modes, accuracy 1e-3 to 1e-8. A baseball- or softball-like ball takes the step its error
  // model gives and one run (step_selection.hpp), unless caught again, rough or closing past 130 m/s.
  double worst = 0;
  for (double z : {0.405, 0.505, 0.605, 0.705, 0.805})
    for (double speed : {1.0, 40.0, 150.0})
      for (double e0 : {0.4, 0.5, 0.7, 1.0})
        for (int modes : {18, auto_modes}) {
          ImpactScene scene = high_impact(z, modes, speed);
          scene.ball.e0 = e0;
          scene.integrator.method = Method::exact;
          const double exact = reference(scene);
          for (double accuracy : {1e-3, 1e-5, 1e-8}) {
            ImpactScene s = scene;
            s.step_accuracy = accuracy;
            const double error = std::abs(vf(s) / exact - 1);
            INFO("z " << z << ", " << speed << " m/s, e0 " << e0 << ", modes " << modes << ", accuracy " << accuracy
                      << ": error " << error);
            CHECK(error <= accuracy);
            worst = std::max(worst, error / accuracy);
          }
        }
  INFO("worst error / accuracy " << worst);
  CHECK(worst > 0.01);  // the step is not far finer than the accuracy needs (the cost: bench_accuracy)
}

TEST_CASE("A fast impact near the handle is checked, not only modelled", "[step_selection]") {
  // R161 at 25.5 cm, 80 m/s, modes auto: the ringing bat roughens the force beyond the step
  // model's constant, and the model's step alone erred 3.8x the 1e-5 asked (with the modes auto
  // keeps at mode_tolerance 1e-5; at the default 1e-4 it drops the ringing modes that rough it).
  ImpactScene s = high_impact(0.255, auto_modes, 80);
  s.mode_tolerance = 1e-5;
  s.ball.e0 = 0.5;
  s.integrator.method = Method::exact;
  const double exact = reference(s);
  s.step_accuracy = 1e-5;
  const double error = std::abs(vf(s) / exact - 1);
  INFO("error " << error);
  CHECK(error <= s.step_accuracy);
  // The model's step alone.
  const SceneGeometry g = scene_geometry(s, r161());
  s.integrator = options_for_accuracy(s.integrator, s.step_accuracy, s.ball, s.ball_speed + g.bat_speed, g.recoil, 0);
  s.step_accuracy = 0;
  CHECK(std::abs(vf(s) / exact - 1) > 1e-5);
  // What tells it from a smooth pulse: the force rises to more than one maximum.
  CHECK(collide(g.contact, s.ball, s.ball_speed, s.integrator).force_peaks > 1);
}

TEST_CASE("A smooth pulse closing faster than 70 m/s meets the accuracy at the model's step alone",
          "[step_selection]") {
  // The premise on which collide_within makes one run there: over the barrel at 50 and 80 m/s
  // (closing at 71-115 m/s), a single contact whose force has one maximum errs within the accuracy
  // at the step the model gives, with auto and all modes.
  int smooth = 0;
  for (double z : {0.455, 0.555, 0.655, 0.755})
    for (double speed : {50.0, 80.0})
      for (int modes : {auto_modes, all_modes}) {
        ImpactScene s = high_impact(z, modes, speed);
        s.integrator.method = Method::exact;
        const SceneGeometry g = scene_geometry(s, r161());
        const double closing = s.ball_speed + g.bat_speed, exact = reference(s);
        for (double accuracy : {1e-4, 1e-6}) {
          const CollisionOptions model = options_for_accuracy(s.integrator, accuracy, s.ball, closing, g.recoil, 0);
          const Collision c = collide(g.contact, s.ball, s.ball_speed, model);
          if (closing <= 70 || c.contacts != 1 || c.force_peaks != 1) continue;
          ++smooth;
          const double error = std::abs(c.ball_velocity / exact - 1);
          INFO("z " << z << ", " << speed << " m/s (closing " << closing << "), modes " << modes << ", accuracy "
                    << accuracy << ": error " << error);
          CHECK(error <= accuracy);
        }
      }
  CHECK(smooth >= 16);  // most of the 32: the barrel's pulses are smooth
}

TEST_CASE("A stated accuracy resolves a hollow barrel's ringing", "[step_selection]") {
  // The wall's hoop mode is a stiff spring in series with the ball: a step near or past its period
  // aliases the ringing, and the model's step erred 1.5x the accuracy on composite_bbcor (16.8 cm,
  // 40 m/s, e0 0.55, at 1e-4: 45 us against a 42 us period) and 1.7x on the aluminium bat (21.8 cm,
  // 1 m/s, e0 0.5, at 1e-6: 35 against 37 us). The step is held to half the period.
  struct Case {
    const char* bat;
    double z, speed, e0, accuracy;
  };
  for (const Case& c : {Case{"composite_bbcor", 0.16764, 40, 0.55, 1e-4}, Case{"aluminium", 0.2184, 1, 0.5, 1e-6}}) {
    const ModalBasis basis =
        compute_modes(load_bat(source_path(std::string("studies/bats/") + c.bat + ".toml")), BeamTheory::timoshenko);
    ImpactScene s = high_impact(c.z, auto_modes, c.speed);
    s.ball.e0 = c.e0;
    s.integrator.method = Method::exact;
    s.integrator.dt = 1e-7;
    const double exact = simulate_impact(basis, s).vf;
    const double scale = std::max(std::abs(exact), 0.05 * c.speed);
    s.step_accuracy = c.accuracy;
    const ImpactResult r = simulate_impact(basis, s);
    REQUIRE(r.status == CollisionStatus::ok);
    INFO(c.bat << " at " << c.z << " m, " << c.speed << " m/s: error " << std::abs(r.vf - exact) / scale << ", step "
               << r.step_used << " s, hoop frequency " << r.hoop_frequency << " Hz");
    CHECK(r.step_used <= 0.5 / r.hoop_frequency);
    CHECK(std::abs(r.vf - exact) <= c.accuracy * scale);
    // The step the model gives without the wall's bound, fixed: it errs past the accuracy.
    const SceneGeometry g = scene_geometry(s, basis);
    s.integrator = options_for_accuracy(s.integrator, c.accuracy, s.ball, s.ball_speed + g.bat_speed, g.recoil, 0);
    s.step_accuracy = 0;
    CHECK(s.integrator.dt > 0.5 / r.hoop_frequency);
    CHECK(std::abs(simulate_impact(basis, s).vf - exact) > c.accuracy * scale);
  }
}
