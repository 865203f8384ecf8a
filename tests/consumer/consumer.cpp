// One impact through the installed library: consumer BAT.toml Z BALL_SPEED CM_SPEED OMEGA prints
// v_f as `sweetspot impact --bat BAT.toml --z Z --ball-speed V --cm-speed VCM --omega W` finds it.
#include <cstdio>
#include <cstdlib>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"

int main(int argc, char** argv) {
  if (argc != 6) return std::fprintf(stderr, "usage: consumer BAT.toml Z BALL_SPEED CM_SPEED OMEGA\n"), 2;
  using namespace sweetspot;
  const Bat bat = load_bat(argv[1]);
  ImpactScene scene;  // the library's defaults: exact stepping at 10 us, modes = auto
  scene.z = std::atof(argv[2]);
  scene.ball_speed = std::atof(argv[3]);
  scene.swing.cm_speed = std::atof(argv[4]);
  scene.swing.omega = std::atof(argv[5]);
  const ModalBasis rigid = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::rigid_only());
  const ModalBasis basis = compute_modes(bat, BeamTheory::timoshenko, auto_mode_request(scene, rigid));
  const ImpactResult result = simulate_impact(basis, scene);
  std::printf("%.17g\n", result.vf);
}
