#include "sweetspot/impact/scan_maximum.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sweetspot {

namespace {

struct Sample {
  double x, value;
};

std::vector<Sample> uniform_scan(const std::function<double(double)>& f, double from, double to, double step) {
  std::vector<Sample> samples;
  for (const double x : scan_points(from, to, step)) samples.push_back({x, f(x)});
  return samples;
}

// Golden-section search for the maximum on [a, b], keeping the best point seen (`best`). The
// function need not be smooth (a flexible bat's measure has kinks at the slice centres), only
// unimodal on the bracket.
void golden_section(const std::function<double(double)>& f, double a, double b, double tolerance, Sample& best,
                    int& evaluations) {
  const double ratio = (std::sqrt(5.0) - 1) / 2;  // 0.618...
  double x1 = b - ratio * (b - a), x2 = a + ratio * (b - a);
  double f1 = f(x1), f2 = f(x2);
  evaluations += 2;
  const auto keep = [&](double x, double v) {
    if (v > best.value) best = {x, v};
  };
  keep(x1, f1), keep(x2, f2);
  while (b - a > tolerance) {
    if (f1 >= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - ratio * (b - a), f1 = f(x1), keep(x1, f1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + ratio * (b - a), f2 = f(x2), keep(x2, f2);
    }
    ++evaluations;
  }
}

}  // namespace

std::vector<double> scan_points(double from, double to, double step) {
  const int intervals = std::max(1, static_cast<int>(std::ceil((to - from) / step - 1e-9)));
  std::vector<double> points;
  for (int i = 0; i <= intervals; ++i) points.push_back(i == intervals ? to : from + i * step);
  return points;
}

ScanMaximum scan_maximum(const std::function<double(double)>& f, double from, double to, double step,
                         double tolerance) {
  const std::vector<Sample> samples = uniform_scan(f, from, to, step);
  const auto top = std::ranges::max_element(samples, {}, &Sample::value);
  const std::size_t k = static_cast<std::size_t>(top - samples.begin());
  Sample best = *top;
  int evaluations = static_cast<int>(samples.size());
  const double a = samples[k > 0 ? k - 1 : k].x, b = samples[k + 1 < samples.size() ? k + 1 : k].x;
  if (b > a) golden_section(f, a, b, tolerance, best, evaluations);
  return {best.x, best.value, evaluations};
}

}  // namespace sweetspot
