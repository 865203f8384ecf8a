#include "sweetspot/bat/barrel_wall.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "sweetspot/bat/parameter_bounds.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot {

WallMode wall_mode(double outer_diameter, double inner_diameter, const Material& material) {
  const double h = (outer_diameter - inner_diameter) / 2;  // wall thickness
  const double a = (outer_diameter + inner_diameter) / 4;  // mid-surface radius
  const double hoop = material.wall_hoop_modulus(), axial = material.youngs_modulus;
  WallMode w;
  // Ring n = 2: omega^2 = 3 E_t h^2 / (5 rho a^4).
  w.omega = std::sqrt(3 * hoop * h * h / (5 * material.density * a * a * a * a));
  // Point stiffness of the ovaling as a beam on an elastic foundation (see the header).
  const double foundation = 3 * std::numbers::pi * hoop * h * h * h / (4 * a * a * a);
  const double beta = std::pow(3 * hoop / axial, 0.25) * std::sqrt(h) / std::pow(a, 1.5);
  w.stiffness = 2 * foundation / beta;
  w.spread = 2 / beta;
  w.mass = w.stiffness / (w.omega * w.omega);
  w.loss_factor = material.wall_loss_factor;
  w.outer_radius = outer_diameter / 2;
  w.radius = a;
  w.thickness = h;
  w.hoop_modulus = hoop;
  w.axial_modulus = axial;
  w.load = material.barrel.load;
  return w;
}

ShellHarmonic shell_harmonic(int n, double radius, double thickness, double hoop_modulus, double axial_modulus) {
  const double a = radius, h = thickness, n2 = static_cast<double>(n) * n;
  ShellHarmonic s;
  s.foundation = std::numbers::pi * hoop_modulus * h * h * h * (n2 - 1) * (n2 - 1) / (12 * a * a * a);
  s.bending = std::numbers::pi * axial_modulus * h * a * a * a / (n2 * n2);
  s.beta = std::pow(s.foundation / (4 * s.bending), 0.25);
  s.compliance = s.beta / (2 * s.foundation);
  return s;
}

ShellHarmonic shell_harmonic(const WallMode& wall, int n) {
  return shell_harmonic(n, wall.radius, wall.thickness, wall.hoop_modulus, wall.axial_modulus);
}

ContactPatch contact_patch(double ball_radius, double barrel_radius, double compression) {
  ContactPatch p;
  if (!(compression > 0)) return p;
  const double transverse = 1 / (1 / ball_radius + 1 / barrel_radius);  // R_t
  p.half_length = std::sqrt(2 * ball_radius * compression);
  p.half_angle = std::min(std::sqrt(2 * transverse * compression) / barrel_radius, std::numbers::pi / 2);
  return p;
}

namespace {

// 8-point Gauss-Legendre on [-1, 1]: nodes and weights (Abramowitz & Stegun, table 25.4).
constexpr std::array<double, 4> gl_node = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                           0.9602898564975363};
constexpr std::array<double, 4> gl_weight = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                             0.1012285362903763};

// Hetenyi's point-load deflection shape, W(z) / W(0), z >= 0.
double hetenyi(double beta, double z) {
  const double x = beta * z;
  return std::exp(-x) * (std::cos(x) + std::sin(x));
}

// Sums terms(n) for n = first, first + step, ... up to last: stops once three terms running are
// below harmonic_sum_tolerance of the sum.
template <class Term>
double harmonic_sum(int first, int step, int last, Term term) {
  double sum = 0;
  int small = 0;
  for (int n = first; n <= last; n += step) {
    const double t = term(n);
    sum += t;
    small = std::abs(t) < harmonic_sum_tolerance * std::abs(sum) ? small + 1 : 0;
    if (small == 3) break;
  }
  return sum;
}

}  // namespace

double patch_factor(int n, double beta, const ContactPatch& patch) {
  const double A = patch.half_length, T = patch.half_angle;
  if (!(A > 0) || !(T > 0)) return 1;
  // Over the arc at z, int_{-c}^{c} sqrt(c^2 - t^2) cos(n t) dt = pi c J1(n c) / n, c the arc's
  // half-width there (the pressure's 1 / T cancels against the normalisation).
  const auto arc = [&](double z) {
    const double c = T * std::sqrt(std::max(0.0, 1 - (z / A) * (z / A)));
    return c > 0 ? std::numbers::pi * c * std::cyl_bessel_j(1.0, n * c) / n : 0.0;
  };
  const double reach = std::min(A, 40 / beta);
  const int panels = std::max(1, static_cast<int>(std::ceil(reach * beta / 2)));
  const double width = reach / panels;
  double integral = 0;  // int_0^A arc(z) W(z) dz
  for (int k = 0; k < panels; ++k) {
    const double mid = (k + 0.5) * width, half = width / 2;
    for (std::size_t i = 0; i < gl_node.size(); ++i)
      for (const double side : {-1.0, 1.0}) {
        const double z = mid + side * half * gl_node[i];
        integral += half * gl_weight[i] * arc(z) * hetenyi(beta, z);
      }
  }
  // The pressure's integral over the ellipse, both halves in z: 2 pi A T^2 / 3.
  return 3 * integral / (std::numbers::pi * A * T * T);
}

double harmonics_compliance(const WallMode& wall, const ContactPatch& patch, int last_harmonic) {
  return harmonic_sum(3, 1, last_harmonic, [&](int n) {
    const ShellHarmonic s = shell_harmonic(wall, n);
    const double phi = patch_factor(n, s.beta, patch);
    return phi * phi * s.compliance;
  });
}

PatchLoad patch_load(const WallMode& wall, double ball_radius, double compression) {
  if (wall.load == WallLoad::point) return {};
  const ContactPatch patch = contact_patch(ball_radius, wall.outer_radius, compression);
  PatchLoad p;
  p.phi = patch_factor(2, shell_harmonic(wall, 2).beta, patch);
  p.compliance = harmonics_compliance(wall, patch);
  return p;
}

double barrel_compression(const WallMode& wall, double approach, double platen_width, int last_harmonic) {
  const double half = platen_width / 2;
  const double sum = harmonic_sum(2, 2, last_harmonic, [&](int n) {
    const ShellHarmonic s = shell_harmonic(wall, n);
    // The mean of W over the platen: (2 / w) int_0^{w/2} W = 2 (1 - e^{-beta w/2} cos(beta w/2)) / (beta w).
    const double x = s.beta * half;
    const double chi = half > 0 ? (1 - std::exp(-x) * std::cos(x)) / x : 1.0;
    return s.compliance * chi * chi;
  });
  return approach / (4 * sum);
}

namespace {

bool bored(const Bat& bat, int i) { return bat.inner_diameter[i] > 0 && bat.inner_diameter[i] < bat.outer_diameter[i]; }

// The wall modes of the bat's material as given (no calibration).
std::vector<WallMode> uncalibrated_wall(const Bat& bat, const Material& material) {
  std::vector<WallMode> wall(bat.slices());
  for (int first = 0; first < bat.slices();) {
    if (!bored(bat, first)) {
      ++first;
      continue;
    }
    int end = first;  // the run of hollow slices [first, end)
    while (end < bat.slices() && bored(bat, end)) ++end;
    // The bore is a tube only if it is longer than the widest spread of an ovaling along it.
    double spread = 0;
    for (int i = first; i < end; ++i) {
      wall[i] = wall_mode(bat.outer_diameter[i], bat.inner_diameter[i], material);
      spread = std::max(spread, wall[i].spread);
    }
    if ((end - first) * bat.slice_thickness() < spread) std::fill(wall.begin() + first, wall.begin() + end, WallMode{});
    first = end;
  }
  return wall;
}

// The hoop modulus's factor that gives the reference section this barrel compression: the
// compression grows with E_t (about as E_t^(3/4)); a secant on the logarithms.
double compression_scale(const Bat& bat, int reference, double target) {
  const auto compression = [&](double scale) {
    Material m = bat.material;
    m.hoop_modulus = m.wall_hoop_modulus() * scale;
    return barrel_compression(wall_mode(bat.outer_diameter[reference], bat.inner_diameter[reference], m));
  };
  double x0 = 0, f0 = std::log(compression(1.0) / target);
  double x1 = -f0 * 4 / 3, f1 = std::log(compression(std::exp(x1)) / target);
  for (int iteration = 0; iteration < 100 && std::abs(f1) > 1e-14 && f1 != f0; ++iteration) {
    const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    x0 = x1, f0 = f1;
    x1 = x2, f1 = std::log(compression(std::exp(x1)) / target);
  }
  return std::exp(x1);
}

// "[barrel] compression = 10: the hoop modulus that gives it (3.71e+07 Pa)": what a refused
// calibration was given and made.
std::string calibration_given(const BarrelCalibration& barrel, double hoop_modulus) {
  char text[120];
  std::snprintf(text, sizeof text, "[barrel] %s = %g: the hoop modulus that gives it (%.3g Pa)",
                barrel.compression > 0 ? "compression" : "hoop_frequency",
                barrel.compression > 0 ? barrel.compression : barrel.hoop_frequency, hoop_modulus);
  return text;
}

}  // namespace

int barrel_reference_slice(const Bat& bat, const std::vector<WallMode>& wall) {
  double largest = 0;
  for (std::size_t i = 0; i < wall.size(); ++i)
    if (wall[i].mass > 0) largest = std::max(largest, bat.outer_diameter[i]);
  const double target = bat.length - 0.1524;  // 6 in from the barrel end
  int best = -1;
  for (int i = 0; i < static_cast<int>(wall.size()); ++i) {
    if (!(wall[i].mass > 0) || bat.outer_diameter[i] < largest * (1 - 1e-9)) continue;
    if (best < 0 || std::abs(bat.slice_center(i) - target) < std::abs(bat.slice_center(best) - target)) best = i;
  }
  return best;
}

std::vector<WallMode> barrel_wall(const Bat& bat) {
  if (!bat.hollow()) return {};
  std::vector<WallMode> wall = uncalibrated_wall(bat, bat.material);
  const BarrelCalibration& barrel = bat.material.barrel;
  if (!barrel.calibrated()) return wall;
  const int reference = barrel_reference_slice(bat, wall);
  if (reference < 0)
    throw InputError("[barrel]: a calibration (hoop_frequency, compression) needs a hollow barrel that is a tube; "
                     "this bat has no wall mode");
  double scale = 1;
  if (barrel.compression > 0) {
    scale = compression_scale(bat, reference, barrel.compression);
  } else {
    const double ratio = barrel.hoop_frequency / wall[reference].frequency_hz();
    scale = ratio * ratio;
  }
  Material calibrated = bat.material;
  calibrated.hoop_modulus = bat.material.wall_hoop_modulus() * scale;
  // The calibrated modulus is a material's too (a hoop frequency of 20 kHz asked 1.2e13 Pa).
  const ParameterBound& moduli = *parameter_bound("hoop_modulus");
  if (!within(moduli, calibrated.hoop_modulus))
    throw InputError(calibration_given(barrel, calibrated.hoop_modulus) + " is no material's; expected " +
                     expected_range(moduli));
  wall = uncalibrated_wall(bat, calibrated);
  if (!(wall[reference].mass > 0))
    throw InputError(calibration_given(barrel, calibrated.hoop_modulus) +
                     " leaves the barrel no tube (its ovaling would spread past the bore); expected a stiffer barrel");
  if (barrel.compression > 0 && barrel.hoop_frequency > 0) {
    // Both measured: E_t from the compression, the modes' mass from the frequency (every section
    // of the barrel by the reference's ratio).
    const double ratio = barrel.hoop_frequency / wall[reference].frequency_hz();
    for (WallMode& w : wall) {
      if (!(w.mass > 0)) continue;
      w.omega *= ratio;
      w.mass = w.stiffness / (w.omega * w.omega);
    }
  }
  return wall;
}

}  // namespace sweetspot
