// Impacts per second per core on N2000's high-impact scene (z = 70.5 cm): 18 modes at the paper's
// 5 us, and all modes at the largest stable RK4 step.
#include <cstdio>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/n2000_settings.hpp"
#include "timing.hpp"

int main(int argc, char** argv) {
  using namespace sweetspot;
  const ModalBasis basis =
      compute_modes(load_bat(argc > 1 ? argv[1] : SWEETSPOT_R161), BeamTheory::timoshenko);
  ImpactScene scene = with_n2000_settings(ImpactScene{});
  scene.z = 0.705;
  scene.ball_speed = 40;
  scene.swing = {51, true, 0, 0.09};
  const auto report = [&](const char* label, const ImpactScene& s) {
    const int batch = 50;
    const double t = median_seconds(7, [&] {
      for (int i = 0; i < batch; ++i) simulate_impact(basis, s);
    });
    std::printf("%-36s dt = %8.3g s: %10.0f impacts/s\n", label, s.integrator.dt, batch / t);
  };
  scene.vibrational_modes = 18;
  report("18 modes", scene);
  scene.vibrational_modes = all_modes;
  scene.integrator.dt = 0.999 * rk4_stability_limit / basis.omega.maxCoeff();
  report("all modes (N = 84, 168 modes)", scene);
}
