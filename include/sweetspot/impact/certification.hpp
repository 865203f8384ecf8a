#pragma once
// A bat certified in the virtual rig (README "Certification"): the standard's measure scanned
// over the barrel, its maximum located between scan points, and the standard's rules checked.
// Physics and rules only; `sweetspot certify` prints it and the certification study stores it.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/bat_test_rig.hpp"
#include "sweetspot/impact/scan_maximum.hpp"
#include "sweetspot/impact/standards.hpp"

namespace sweetspot {

// Where the rig strikes: from 12 in to 2 in from the barrel end every 1/2 in, then the maximum
// between scan points to 1e-5 m. 2 in keeps the ball (1.44 in in radius) on the bat; 12 in is past
// where any bat's measure peaks (wood near 6 in from the end).
struct BarrelScan {
  double far_from_end = 12 * metres_per_inch;
  double near_end = 2 * metres_per_inch;
  double step = 0.5 * metres_per_inch;
  double tolerance = 1e-5;  // m
};

// Up to this many slices a certification solves every mode of the bat once, and holds the whole
// beam at the pivot (one full solve, and one of the held bat: 1.7 s in all at 512 slices, 18 s at
// 1024); beyond it, only the modes its scan asks (partial solves: 0.7 s at 2048 slices, 1.3 s at
// 4096 for alloy_bbcor).
inline constexpr int max_certify_full_slices = 512;

// What may change from the standard's rig, each unset to keep the standard's.
struct CertifyOptions {
  std::optional<Ball> ball;  // the rig's ball, in place of the standard's
  std::optional<double> e0;  // the ball's COR (at its reference speed)
  std::optional<double> ball_speed;  // m/s
  std::optional<double> pivot;       // m from the knob
  int slices = 0;                    // 0: the bat's own
  int vibrational_modes = auto_modes;
  BeamTheory theory = BeamTheory::timoshenko;
  BarrelScan scan;
  // The total relative error the measure may carry (error_estimates.hpp), or 0 for none: its
  // modes' and step's shares set every rig hit, and the bat is cut at its own slices, twice and
  // four times them, and finer while the measure's slicing estimate exceeds what they leave.
  // Excludes `slices` and a fixed mode count.
  std::optional<double> accuracy;
};

struct RuleCheck {
  std::string rule;  // "bbcor", "barrel_diameter", "drop", "length"
  double value = 0;
  double limit = 0;
  bool pass = false;  // value <= limit
};

struct Certification {
  Standard standard;     // with the options applied: its ball, speed and pivot as used
  double z_max = 0;      // m from the knob, where the measure peaks
  double measure = 0;    // the standard's measure there
  RigMeasures at_max;    // every measure there
  // The lowest hoop frequency of the wall there (barrel_wall.hpp), Hz; NaN for a solid section.
  double hoop_frequency = std::numeric_limits<double>::quiet_NaN();
  // The same section's barrel compression (ASTM F2844 style, barrel_wall.hpp): N at 0.04 in; NaN
  // for a solid section. The wall's load there at the peak (phi_2, the other harmonics'
  // compliance m/N, NaN where no wall), and the bat's [barrel] table (load, calibration).
  double barrel_compression = std::numeric_limits<double>::quiet_NaN();
  double barrel_phi = std::numeric_limits<double>::quiet_NaN();
  double barrel_compliance = std::numeric_limits<double>::quiet_NaN();
  bool hollow = false;
  BarrelCalibration barrel;
  // The designer's numbers, exact for the designed shape (design_mass_properties), not summed
  // over slices: mass, MOI about the pivot, drop, length, the largest outer diameter.
  double mass = 0, moi_pivot = 0, drop = 0, length = 0, barrel_diameter = 0;
  // The MOI about the pivot as the model discretises the bat: the r = m d^2 / I of the measures.
  double moi_pivot_model = 0;
  int evaluations = 0;   // rig hits computed, over every slicing
  // At a stated accuracy: the slices the answer was computed at, and the measure's estimated
  // relative errors (error_estimates.hpp; the modes' and step's those of the exit speed at the
  // peak, which bound the measure's: BBCOR = e_A (1 + r) + r, BESR = e_A + 1/2, BPF = BBCOR / e0).
  // `accurate` false when the slices could not double again before the slicing met its share.
  // NaN without a stated accuracy.
  int slices_used = 0;
  double slicing_error = std::numeric_limits<double>::quiet_NaN();
  double modes_error = std::numeric_limits<double>::quiet_NaN();
  double step_error = std::numeric_limits<double>::quiet_NaN();
  double total_error = std::numeric_limits<double>::quiet_NaN();
  bool accurate = true;
  std::string unmet;  // why not accurate: the slices could not double again, or their modes be
                      // solved, or the modes and the step left the slicing nothing
  std::vector<RuleCheck> checks;
  bool pass = false;     // every check passes
};

// Why the rig, its pivot `pivot` m from the knob, cannot hold a bat of `length` before the scanned
// barrel ("expected a bat longer than 0.457 m: the bbcor rig's pivot, ..."), or nothing when it can:
// the one wording of certify, certification studies and optimisations.
std::optional<std::string> rig_misfit(const Standard& standard, double pivot, double length, const BarrelScan& scan = {});

// The rig of a standard with the options applied. Throws InputError naming the option (e0,
// ball_speed, pivot) and what was expected: e0 in (0, 1], a speed > 0, a pivot on the bat before
// the scanned barrel.
RigSettings certification_rig(const Standard& standard, const CertifyOptions& options, double length);

// The measure's largest value over the barrel of the bat `basis` describes, and where.
ScanMaximum barrel_maximum(const ModalBasis& basis, const RigSettings& rig, Measure measure, const BarrelScan& scan);

// The rules of the standard for a bat of these numbers and measure.
std::vector<RuleCheck> rule_checks(const Standard& standard, double measure, double barrel_diameter, double drop,
                                   double length);

// The whole certification of a design, at options.accuracy when one is stated. Throws InputError
// for a bad option or an impossible bat.
Certification certify(const BatDesign& design, const Standard& standard, const CertifyOptions& options);

}  // namespace sweetspot
