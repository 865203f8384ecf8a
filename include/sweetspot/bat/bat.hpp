#pragma once
// A bat: a free-free beam cut into N slices of equal thickness L/N (physics.md §1-2).
// Plain data plus the geometry and mass properties that follow from it; no I/O here.
// A slice's mechanics is its section area A and second moment I, the means over the slice: a
// slice cut from a finer profile (resample) has the mean A and I of what it covers, which no
// single diameter gives, so the two are kept beside the diameters that describe its shape.
#include <string>
#include <vector>

namespace sweetspot {

// A hollow barrel's wall loss factor unless a bat gives one (barrel_wall.hpp, README "Hollow
// barrels"): aluminium alloys', the default material of hollow bats, of order 1e-4 (Cremer, Heckl
// & Petersson, "Structure-Borne Sound", table of material loss factors).
inline constexpr double default_wall_loss_factor = 1e-4;

// How the ball loads a hollow barrel's wall (barrel_wall.hpp): over its contact patch (the
// default), or at a point (the model before the patch: phi = 1, no other harmonics).
enum class WallLoad { patch, point };

// The bat file's optional [barrel] table (README "Hollow barrels"): the wall's load, and measured
// values that calibrate the wall's effective hoop modulus (and, both given, its mode's mass).
struct BarrelCalibration {
  WallLoad load = WallLoad::patch;
  double hoop_frequency = 0;  // Hz, a measured lowest hoop frequency; 0: not given
  double compression = 0;     // N at 0.04 in (ASTM F2844), a measured barrel compression; 0: not given

  bool calibrated() const { return hoop_frequency > 0 || compression > 0; }
};

struct Material {
  double density = 0;            // kg/m^3
  double youngs_modulus = 0;     // Pa
  double shear_modulus = 0;      // Pa
  double shear_coefficient = 1;  // kappa; N2000 folds it into S (kappa = 1)
  // A hollow barrel's wall (barrel_wall.hpp). youngs_modulus is the axial modulus; a composite
  // wall's hoop (circumferential) modulus may differ: 0 means an isotropic wall (youngs_modulus).
  double hoop_modulus = 0;      // Pa
  double wall_loss_factor = default_wall_loss_factor;  // eta of the wall's ovaling, in [0, 1)
  // The bat's own structural loss factor eta, in [0, 1): every vibrational mode of the beam is
  // damped at zeta = eta / 2 (README "Damping"). 0, the default of a material given by its
  // constants (N2000's R161), leaves the beam undamped, bit for bit as before; the wood presets
  // carry wood's 0.01.
  double loss_factor = 0;
  BarrelCalibration barrel{};   // the [barrel] table: load and calibration of the wall

  double wall_hoop_modulus() const { return hoop_modulus > 0 ? hoop_modulus : youngs_modulus; }
};

// The slice counts a bat may have, from its profile or resampled (--slices, `slices`): fewer
// than 4 cannot bend; more than 4096 add nothing (the lowest modes at 336 slices are within 1e-4
// of 4096's) and cost time. Every mode (the dense solve) is practical only to 1024 (modes.hpp).
inline constexpr int min_slices = 4;
inline constexpr int max_slices = 4096;

struct Bat {
  std::string name;
  double length = 0;                   // m
  Material material;
  std::vector<double> outer_diameter;  // m, one per slice (its mean over the slice), knob first
  std::vector<double> inner_diameter;  // m, one per slice; empty for a solid bat
  std::vector<double> section_area;    // m^2, one per slice: the mean of A over the slice
  std::vector<double> section_second_moment;  // m^4, one per slice: the mean of I about a diameter

  // Slices of uniform section with these diameters (inner empty: solid), A and I from them.
  void set_slices(std::vector<double> outer, std::vector<double> inner = {});

  int slices() const { return static_cast<int>(outer_diameter.size()); }
  double slice_thickness() const { return length / slices(); }
  double slice_center(int i) const { return (i + 0.5) * slice_thickness(); }
  bool hollow() const { return !inner_diameter.empty(); }

  double area(int i) const { return section_area[i]; }
  double second_moment(int i) const { return section_second_moment[i]; }
  double slice_mass(int i) const { return material.density * area(i) * slice_thickness(); }
  // Rotary inertia of slice i about its own transverse axis, as the Timoshenko model has it.
  double slice_rotary_inertia(int i) const {
    return material.density * second_moment(i) * slice_thickness();
  }
};

// The same bat cut into n slices. Each new slice takes the overlap-weighted means of A and I of
// the old slices it covers (so the mass is exact for any n; refining by a whole factor leaves the
// bat exactly as it was), and of their diameters to describe its shape.
Bat resample(const Bat& bat, int n);

// Mass properties of the sliced bat: the slices' masses at their centres plus their own rotary
// inertia, which is exactly the inertia the Timoshenko rigid modes carry.
struct MassProperties {
  double mass = 0;               // kg
  double z_cm = 0;               // m from the knob
  double moment_of_inertia_cm = 0;  // kg m^2 about the centre of mass
  double radius_of_gyration() const;  // about the centre of mass, m
  double moment_of_inertia_about(double z) const;  // parallel-axis theorem
};

MassProperties mass_properties(const Bat& bat);

}  // namespace sweetspot
