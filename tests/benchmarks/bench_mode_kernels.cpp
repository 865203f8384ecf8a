// The exact stepper's two passes over the modes per step (src/contact/mode_kernels.hpp:
// step_known, then step_end), alone, on arrays that stay in the core's first-level cache, for 16,
// 44 (auto's on the high-impact scene) and 168 modes (all of R161's at N = 84), on each vector
// path the processor has. Prints ns per step, ns per mode and GFLOP/s (40 floating-point
// operations per mode and step: 30 in step_known, 10 in step_end): how near the core's peak the
// step's own arithmetic runs, apart from everything else an impact does. Asserts nothing.
#include <cstdio>
#include <vector>

#include "contact/mode_kernels.hpp"
#include "timing.hpp"

namespace {

using namespace sweetspot::detail;

constexpr double flops_per_mode = 40;

// Median ns of one step's two passes over n modes.
double step_ns(int n) {
  std::vector<std::vector<double>> columns(20, std::vector<double>(n));
  for (std::vector<double>& column : columns)
    for (int i = 0; i < n; ++i) column[i] = 0.5 + 1e-3 * i;  // values of a response's size
  std::vector<double> a(n), v(n);
  const auto at = [&columns](int k) { return columns[k].data(); };
  const StepArrays arrays{at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7),
                          {at(8), at(9), at(10), at(11)}, {at(12), at(13), at(14), at(15)}, a.data(), v.data()};
  double data[4] = {1e-3, 2e-3, 3e-3, 4e-3}, sink = 0;
  const int steps = 2'000'000 / n;
  const double seconds = median_seconds(7, [&] {
    for (int step = 0; step < steps; ++step) {
      const StepSums sums = step_known(n, arrays, data);
      sink += sums.psi_a;
      data[0] += 1e-15;  // each step's data new, as in a collision
      step_end(n, a.data(), v.data(), at(6), at(16), at(17), at(18), at(19), 1e-3, 2e-3);
    }
  });
  if (sink == 0.125) std::printf(" ");  // keeps the work
  return seconds / steps * 1e9;
}

}  // namespace

int main() {
  std::printf("%-7s %6s %12s %12s %10s\n", "path", "modes", "ns/step", "ns/mode", "GFLOP/s");
  for (const VectorPath path : {VectorPath::sse2, VectorPath::avx2, VectorPath::avx512}) {
    if (!use_vector_path(path)) continue;
    for (const int n : {16, 44, 168}) {
      const double ns = step_ns(n);
      std::printf("%-7s %6d %12.1f %12.2f %10.1f\n", to_string(path), n, ns, ns / n, flops_per_mode * n / ns);
    }
  }
}
