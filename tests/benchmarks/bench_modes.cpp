// Time to build the normal modes of the R161 bat at N = 84, 168, 336, 672 slices (median).
#include <cstdio>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/modes.hpp"
#include "timing.hpp"

int main(int argc, char** argv) {
  using namespace sweetspot;
  const Bat bat = load_bat(argc > 1 ? argv[1] : SWEETSPOT_R161);
  std::printf("%8s %16s %16s\n", "slices", "timoshenko/ms", "euler-bern./ms");
  for (int n : {84, 168, 336, 672}) {
    const Bat sliced = resample(bat, n);
    const int repeats = n <= 168 ? 21 : n <= 336 ? 5 : 3;
    const double t = median_seconds(repeats, [&] { compute_modes(sliced, BeamTheory::timoshenko); });
    // Euler-Bernoulli is refused past max_euler_bernoulli_slices (its dense solve's round-off).
    if (n > max_euler_bernoulli_slices) {
      std::printf("%8d %16.2f %16s\n", n, 1e3 * t, "(refused)");
      continue;
    }
    const double e = median_seconds(repeats, [&] { compute_modes(sliced, BeamTheory::euler_bernoulli); });
    std::printf("%8d %16.2f %16.2f\n", n, 1e3 * t, 1e3 * e);
  }
}
