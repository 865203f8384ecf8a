// One ball on a bat shipped with sweetspot (r161 unless named): prints the ball's exit speed.
//   exit_speed [BAT]
#include <cstdio>
#include <exception>
#include <string>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"

int main(int argc, char** argv) try {
  using namespace sweetspot;
  const std::string name = argc > 1 ? argv[1] : "r161";
  const Bat bat = load_bat(SWEETSPOT_DATA_DIR "/bats/" + name + ".toml");

  ImpactScene scene;          // exact stepping, the modes chosen for the scene ("auto")
  scene.z = 0.7;              // impact point, m from the knob
  scene.ball_speed = 40;      // ball speed toward the bat, m/s
  scene.swing.cm_speed = 10;  // the bat's centre-of-mass speed toward the ball, m/s
  scene.swing.omega = 40;     // the bat's angular velocity, rad/s

  // The bat's normal modes that this scene needs (the rigid ones give its mass properties).
  const ModalBasis rigid = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::rigid_only());
  const ModalBasis modes = compute_modes(bat, BeamTheory::timoshenko, impact_mode_request(scene, rigid));

  const ImpactResult result = simulate_impact(modes, scene);
  std::printf("%s: exit speed %.6g m/s at z = %g m\n", bat.name.c_str(), result.vf, scene.z);
} catch (const std::exception& e) {  // a bad bat file or scene: sweetspot::InputError says what and where
  std::fprintf(stderr, "exit_speed: %s\n", e.what());
  return 1;
}
