#pragma once
// The largest value of a function of one variable over an interval: a uniform scan, then a
// golden-section search between the neighbours of the largest sample, so the maximum is located
// between scan points rather than snapped to one. The certification's scan over the barrel.
#include <functional>
#include <vector>

namespace sweetspot {

struct ScanMaximum {
  double x = 0;
  double value = 0;
  int evaluations = 0;
};

// The uniform scan's sample points: from, from + step, ... and `to` last (to itself when step
// divides the interval). Whoever computes the samples elsewhere (spread over ranks, say) and
// hands them back through f gets exactly scan_maximum's samples.
std::vector<double> scan_points(double from, double to, double step);

// Samples f at from, from + step, ... (to included when step divides the interval, else the
// last sample is `to`), then narrows the bracket around the largest sample until it is shorter
// than `tolerance`. Never returns less than the largest sample. A maximum at an end of the
// interval is found at that end.
ScanMaximum scan_maximum(const std::function<double(double)>& f, double from, double to, double step,
                         double tolerance);

}  // namespace sweetspot
