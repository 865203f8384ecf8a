// One default for every entry point (the library, `sweetspot impact`, studies): exact modal
// stepping at its default step with modes = "auto", the settings the README recommends; N2000's
// (RK4 at 5 us, 18 vibrational modes) one option away.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "n2000_scenes.hpp"
#include "program.hpp"
#include "refusal.hpp"
#include "temp_dir.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/n2000_settings.hpp"
#include "sweetspot/study/study.hpp"

using namespace sweetspot;

namespace {

const ModalBasis& r161() {
  static const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko);
  return basis;
}

// N2000's 18 modes as the program solves for them (the lowest 18 only: ModeRequest::lowest).
const ModalBasis& r161_18() {
  static const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/r161.toml")),
                                                BeamTheory::timoshenko, ModeRequest::lowest(n2000_modes));
  return basis;
}

// The high-impact swing (51 rad/s about 9 cm, e0 0.5) with the library's defaults otherwise.
ImpactScene default_scene(double z, double ball_speed = 40) {
  ImpactScene s;
  s.z = z;
  s.ball_speed = ball_speed;
  s.swing = {51, true, 0, 0.09};
  return s;
}

// The number after "key": in the program's JSON.
double json_number(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": ");
  REQUIRE(at != std::string::npos);
  return std::stod(json.substr(at + key.size() + 4));
}

const std::string impact_command = "impact --bat " + source_path("studies/bats/r161.toml") +
                                   " --z 0.605 --ball-speed 40 --center 0.09 --omega 51 --json";

Study load_text(const TempDir& dir, const std::string& scene) {
  return load_study(dir.write("study.toml", "[scene]\nbat = \"" + source_path("studies/bats/r161.toml") +
                                                "\"\nz = 0.605\nball_speed = 40\ncenter = 0.09\nomega = 51\n" +
                                                scene));
}

}  // namespace

TEST_CASE("The library, the impact command and a study share one default: exact stepping, modes auto",
          "[defaults]") {
  const ImpactScene s;
  CHECK(s.integrator.method == Method::exact);
  CHECK(s.integrator.dt == default_step(Method::exact));
  CHECK(s.vibrational_modes == auto_modes);
  CHECK(s.step_accuracy == 0);
  CHECK(s.accuracy == 0);  // no stated total accuracy: the bat's own slices

  TempDir dir;
  const Study study = load_text(dir, "");
  CHECK(study.base.integrator.method == s.integrator.method);
  CHECK(study.base.integrator.dt == s.integrator.dt);
  CHECK(study.base.vibrational_modes == s.vibrational_modes);

  // The program with no integrator or mode option gives the library's default result, bit for bit,
  // on the basis the program solves for it (impact_mode_request: auto's modes, maybe a partial solve).
  const Bat bat = load_bat(source_path("studies/bats/r161.toml"));
  const ImpactScene scene = default_scene(0.605);
  const ModalBasis rigid = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::rigid_only());
  const ImpactResult library =
      simulate_impact(compute_modes(bat, BeamTheory::timoshenko, impact_mode_request(scene, rigid)), scene);
  REQUIRE(library.status == CollisionStatus::ok);
  const ProgramRun run = run_program(impact_command);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK(json_number(run.output, "vf") == library.vf);
  CHECK(json_number(run.output, "modes_error") == library.modes_error);
}

TEST_CASE("N2000's settings are one option away: impact --n2000 and preset = \"n2000\"", "[defaults]") {
  const ImpactScene n2000 = with_n2000_settings(default_scene(0.605));
  CHECK(n2000.integrator.method == Method::rk4);
  CHECK(n2000.integrator.dt == 5e-6);
  CHECK(n2000.vibrational_modes == 18);
  const ImpactResult library = simulate_impact(r161_18(), n2000);
  REQUIRE(library.status == CollisionStatus::ok);
  const ProgramRun run = run_program(impact_command + " --n2000");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK(json_number(run.output, "vf") == library.vf);
  // An option given beside it still applies.
  ImpactScene exact18 = n2000;
  exact18.integrator.method = Method::exact;
  exact18.integrator.dt = default_step(Method::exact);
  const ProgramRun exact = run_program(impact_command + " --n2000 --integrator exact");
  REQUIRE(exact.exit_code == 0);
  CHECK(json_number(exact.output, "vf") == simulate_impact(r161_18(), exact18).vf);

  TempDir dir;
  const Study preset = load_text(dir, "preset = \"n2000\"\n");
  CHECK(preset.base.integrator.method == Method::rk4);
  CHECK(preset.base.integrator.dt == 5e-6);
  CHECK(preset.base.vibrational_modes == 18);
  // Whatever the study writes overrides the preset, wherever it writes it.
  const Study overridden = load_text(dir, "modes = \"all\"\npreset = \"n2000\"\nintegrator = \"exact\"\n");
  CHECK(overridden.base.integrator.method == Method::exact);
  CHECK(overridden.base.integrator.dt == default_step(Method::exact));
  CHECK(overridden.base.vibrational_modes == all_modes);
  // A wall study takes it too (its integration).
  CHECK(load_study(dir.write("wall.toml", "kind = \"wall\"\n[scene]\nball_speed = 40\npreset = \"n2000\"\n"))
            .base.integrator.method == Method::rk4);
}

TEST_CASE("A bad preset is refused naming the key and the value", "[defaults][input]") {
  TempDir dir;
  CHECK_THROWS_WITH(load_text(dir, "preset = \"rk4\"\n"),
                    Catch::Contains("key 'scene.preset' = \"rk4\"") && Catch::Contains("\"n2000\""));
  CHECK_THROWS_WITH(load_text(dir, "preset = 2000\n"), Catch::Contains("key 'scene.preset' = 2000"));
  const std::string axis = "[scene]\nbat = \"" + source_path("studies/bats/r161.toml") +
                           "\"\nz = 0.605\nball_speed = 40\ncenter = 0.09\n[axes]\npreset = [\"n2000\"]\n";
  CHECK_THROWS_WITH(load_study(dir.write("axis.toml", axis)),
                    Catch::Contains("key 'axes.preset'") && Catch::Contains("cannot be an axis"));
  const ProgramRun run = run_program("run " + dir.write("bad.toml", "kind = \"wall\"\n[scene]\nball_speed = 40\n"
                                                                     "preset = \"N2000\"\n")
                                                  .string() +
                                     " -o " + dir / "out.h5");
  require_refused(run, {"preset"});
}

TEST_CASE("The default is exact to 2e-4 where N2000's 18 modes err by up to 1.3 %", "[defaults]") {
  // High-impact scenes over 50-80 cm at 34-46 m/s against all 168 modes stepped at 2.5 us (its
  // own error below 1e-9, test_integrators). The default's error is the dropped modes' (the
  // tolerance 1e-4, whose estimate can be low by about 2x) plus the 10-us step's (2e-8).
  double worst_default = 0, worst_n2000 = 0;
  for (double z = 0.505; z < 0.80; z += 0.03)
    for (double speed : {34.0, 46.0}) {
      ImpactScene reference = default_scene(z, speed);
      reference.vibrational_modes = all_modes;
      reference.integrator.dt = 2.5e-6;
      const double exact = simulate_impact(r161(), reference).vf;
      const ImpactResult by_default = simulate_impact(r161(), default_scene(z, speed));
      const ImpactResult n2000 = simulate_impact(r161(), with_n2000_settings(default_scene(z, speed)));
      REQUIRE(by_default.status == CollisionStatus::ok);
      REQUIRE(n2000.status == CollisionStatus::ok);
      worst_default = std::max(worst_default, std::abs(by_default.vf / exact - 1));
      worst_n2000 = std::max(worst_n2000, std::abs(n2000.vf / exact - 1));
    }
  INFO("worst relative vf error: default " << worst_default << ", N2000's settings " << worst_n2000);
  CHECK(worst_default < 2e-4);
  CHECK(worst_n2000 > 4e-3);
}
