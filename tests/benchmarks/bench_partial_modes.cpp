// Eigen-solve time per bat, full (dense) against partial (banded: LAPACK's reduction without
// accumulated rotations, bisection, inverse iteration), at N = 84, 168 and 336 slices
// (Timoshenko): for 18 vibrational modes and for what modes = "auto" needs (the largest
// auto_mode_request) on N2000's high-impact scene over 40.5-83.5 cm at 30-50 m/s and on the
// low-impact one (ball at 1 m/s on the bat at rest, e0 = 0.66) over the same points. Then the
// partial solves alone at 1024 to 4096 slices, where the full one is refused (modes.hpp,
// max_full_solve_slices). Medians; prints, asserts nothing.
#include <algorithm>
#include <cstdio>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/scene.hpp"
#include "timing.hpp"

namespace {

using namespace sweetspot;

// The largest request auto makes over the high-impact range (the shortest pulse), or over the
// low-impact scene's points.
ModeRequest auto_request(const ModalBasis& rigid, bool high_impact) {
  ModeRequest widest = ModeRequest::below(0);
  for (double z = 0.405; z < 0.84; z += 0.01)
    for (double speed = 30; speed <= 50; speed += 5) {
      ImpactScene s;
      s.z = z;
      s.ball_speed = high_impact ? speed : 1;
      s.swing = {51, true, 0, 0.09};
      if (!high_impact) {
        s.ball.e0 = 0.66;
        s.swing = {0, false, 0, 0};
      }
      const ModeRequest r = auto_mode_request(s, rigid);
      if (r.below_omega > widest.below_omega) widest = r;
    }
  return widest;
}

void row(const char* what, int slices, const Bat& bat, ModeRequest request, double full, int repeats = 21) {
  const ModalBasis basis = compute_modes(bat, BeamTheory::timoshenko, request);
  const double t = median_seconds(repeats, [&] { compute_modes(bat, BeamTheory::timoshenko, request); });
  if (full > 0)
    std::printf("%6d  %-28s %5d %s %10.2f %10.2f %8.1fx\n", slices, what, basis.count() - 2,
                basis.complete() ? "(dense)  " : "(partial)", 1e3 * full, 1e3 * t, full / t);
  else
    std::printf("%6d  %-28s %5d %s %10s %10.2f\n", slices, what, basis.count() - 2,
                basis.complete() ? "(dense)  " : "(partial)", slices > max_full_solve_slices ? "refused" : "-", 1e3 * t);
}

}  // namespace

int main(int argc, char** argv) {
  const Bat bat = load_bat(argc > 1 ? argv[1] : SWEETSPOT_R161);
  std::printf("%6s  %-28s %5s %9s %10s %10s %9s\n", "slices", "modes", "solved", "", "full/ms", "asked/ms", "speed-up");
  for (const int n : {84, 168, 336}) {
    const Bat sliced = resample(bat, n);
    const double full = median_seconds(n > 168 ? 5 : 21, [&] { compute_modes(sliced, BeamTheory::timoshenko); });
    const ModalBasis rigid = compute_modes(sliced, BeamTheory::timoshenko, ModeRequest::rigid_only());
    row("18 vibrational", n, sliced, ModeRequest::lowest(18), full);
    row("auto, high-impact (40 m/s)", n, sliced, auto_request(rigid, true), full);
    row("auto, low-impact (1 m/s)", n, sliced, auto_request(rigid, false), full);
    char text[64];
    for (const int k : {40, 60}) {
      std::snprintf(text, sizeof text, "%d vibrational", k);
      row(text, n, sliced, ModeRequest::lowest(k), full);
    }
  }
  for (const int n : {1024, 2048, 4096}) {
    const Bat sliced = resample(bat, n);
    const ModalBasis rigid = compute_modes(sliced, BeamTheory::timoshenko, ModeRequest::rigid_only());
    row("18 vibrational", n, sliced, ModeRequest::lowest(18), 0, 5);
    row("auto, high-impact (40 m/s)", n, sliced, auto_request(rigid, true), 0, 5);
  }
}
