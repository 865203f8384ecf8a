#pragma once
// The sweet spot of one line of v_f(z): where v_f peaks and how wide the zone is within a
// fraction of that peak, both located between the grid points (not snapped to them) by the
// parabola through the three points around each place. Exact for a v_f(z) that is a parabola.
#include <span>

namespace sweetspot {

struct SweetSpot {
  double z;      // m: the vertex of the parabola through the largest v_f and its neighbours
  double vf;     // m/s: v_f there
  double width;  // m: from where v_f first falls below (1 - fraction) vf on the left to the right
};

// z strictly ascending, vf the exit speeds there, fraction in (0, 1). Every field is NaN when a
// value is not finite, there are fewer than 3 points, the largest v_f is at an end of the line
// (the peak is not inside the scan), or (width alone) the zone does not close within the scan.
SweetSpot sweet_spot(std::span<const double> z, std::span<const double> vf, double fraction);

}  // namespace sweetspot
