#pragma once
// A bat's shape along its length: outer (and, for a hollow bat, inner) diameters at knots, and
// how the diameter runs between them. Cutting it into slices integrates the section area A and
// second moment I over each slice, so a slice carries the exact mean A and I of the shape it
// covers whatever the knots' spacing. No I/O here: bat_file.hpp reads profiles.
#include <vector>

#include "sweetspot/bat/bat.hpp"

namespace sweetspot {

// How the diameter runs between knots:
//   stepped  each knot's diameter holds to halfway to its neighbours (a measured profile that
//            lists one diameter per slice: knots at slice centres give exactly those slices)
//   linear   straight between knots (frustums)
//   pchip    the shape-preserving piecewise cubic of Fritsch and Carlson (SIAM J. Numer. Anal.
//            17, 238 (1980)) with Fritsch-Butland slopes, as scipy's PchipInterpolator and
//            MATLAB's pchip: smooth, and it never overshoots the knots (no bulge in a taper)
// Beyond the first and last knot the diameter stays at the end knot's.
enum class Interpolation { stepped, linear, pchip };

struct Profile {
  Interpolation interpolation = Interpolation::linear;
  // Knots, m from the knob, increasing. A knot repeated (linear only) is a step: the diameter
  // jumps there, as at a knob's shoulder or a cupped end's bore (dimensions.hpp).
  std::vector<double> z;
  std::vector<double> outer;  // m, at each knot
  std::vector<double> inner;  // m, at each knot; empty for a solid bat

  // The outer or inner diameter at z (`inner` false or true).
  double diameter(double z, bool inner = false) const;
};

// Fills the bat's slices: `slices` of equal thickness over bat.length, each with the means of A,
// I and the diameters over it, integrated exactly for every interpolation (Gauss-Legendre on each
// piece between knots, of a degree that covers D^4 of a cubic).
void cut_into_slices(const Profile& profile, int slices, Bat& bat);

// The exact mass properties of the shape over [0, length] at a uniform density, integrated as
// cut_into_slices integrates (exact for linear pieces, for D^4 of cubic ones): mass, CM and the
// MOI about the CM, each cross-section's own rotary inertia included.
MassProperties mass_properties(const Profile& profile, double length, double density);

// Where a hollow profile's wall (outer less inner diameter) is thinnest, over the knots and between
// them: the knot interval it lies in (0: between knots 0 and 1) and its z. A pchip profile's two
// curves are interpolated apart, so a wall positive at every knot can still cross between them.
struct ThinnestWall {
  std::size_t interval = 0;
  double z = 0, wall = 0;
};
ThinnestWall thinnest_wall(const Profile& profile);  // the profile must be hollow

const char* to_string(Interpolation interpolation);
// Throws InputError for anything but "stepped", "linear" or "pchip".
Interpolation parse_interpolation(const std::string& text);

}  // namespace sweetspot
