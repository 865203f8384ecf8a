#pragma once
// The largest value of a function of one variable over an interval: a uniform scan, then a
// golden-section search between the neighbours of the largest sample, so the maximum is located
// between scan points rather than snapped to one. The certification's scan over the barrel.
#include <functional>

namespace sweetspot {

struct ScanMaximum {
  double x = 0;
  double value = 0;
  int evaluations = 0;
};

// Samples f at from, from + step, ... (to included when step divides the interval, else the
// last sample is `to`), then narrows the bracket around the largest sample until it is shorter
// than `tolerance`. Never returns less than the largest sample. A maximum at an end of the
// interval is found at that end.
ScanMaximum scan_maximum(const std::function<double(double)>& f, double from, double to, double step,
                         double tolerance);

}  // namespace sweetspot
