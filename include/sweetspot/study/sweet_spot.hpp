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
  // The most the width can change, relative to itself, per unit relative error of every v_f (each
  // off by at most that fraction e, either way), to first order: each end moves by the error of
  // the parabola read there less the level's, over |v_f'|, about 2 e level / |v_f'| (the parabolas'
  // Lagrange weights add up to a little more between grid points). About (1 - fraction) / fraction
  // on a parabola: a zone within 1 % of the peak is some 99 times as sensitive as the speeds it is
  // read from.
  double width_sensitivity;
};

// z strictly ascending, vf the exit speeds there, fraction in (0, 1). Every field is NaN when a
// value is not finite, there are fewer than 3 points, the largest v_f is at an end of the line
// (the peak is not inside the scan), or (width alone) the zone does not close within the scan.
SweetSpot sweet_spot(std::span<const double> z, std::span<const double> vf, double fraction);

}  // namespace sweetspot
