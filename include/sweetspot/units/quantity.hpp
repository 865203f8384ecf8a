#pragma once
// A physical quantity written with its unit ("33 in", "31 oz", "136 mph", "0.84 m"), read into SI.
// Every reader of user input (bat, ball, study and optimisation files, the command line, Python)
// goes through parse_quantity, so that one list of units and one rounding hold everywhere.
//
// Conversion is exact in decimal and rounded once: "28.3 in" reads as the double nearest
// 0.71882, bitwise what a file saying 0.71882 gives. The units whose factor is not a terminating
// decimal (km/h, rpm) are rounded twice, within an ulp.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace sweetspot {

enum class Dimension { length, mass, speed, angular_speed, frequency, angle, temperature, pressure };

// One unit a user may write; `si` is its value in SI units as exact decimal text, then times
// `multiplier` and divided by `divisor` where the factor is not a decimal (rpm: pi / 30), plus
// `offset` (in SI) for the temperature scales whose zero is not absolute (deg C, deg F).
struct Unit {
  std::string_view name;
  Dimension dimension;
  std::string_view si;
  double multiplier = 1;
  double divisor = 1;
  double offset = 0;
};

// Every unit, SI's own first within each dimension.
std::span<const Unit> units();

// The unit of that name (case matters: "mm" is not "Mm"), or nullptr.
const Unit* find_unit(std::string_view name);

// "length", "mass", "speed", "angular speed", "frequency", "angle", "temperature", "pressure".
std::string_view dimension_name(Dimension dimension);

// The SI unit a plain number is read in: "m", "kg", "m/s", "rad/s", "Hz", "rad", "K", "Pa".
std::string_view si_unit(Dimension dimension);

// What a reader expects, for messages: `a length (a number in m, or a string such as "28 in";
// units m, cm, mm, in, ft)`.
std::string expected_quantity(Dimension dimension);

// The same without its leading "a length ": the parenthesis, for a message that has already said
// what the value is ("a finite number >= 0 from the knob (a number in m, or ...)").
std::string quantity_hint(Dimension dimension);

// `text` as SI, or nothing when it is not a finite number followed by a unit of `dimension`
// (spaces around and between allowed: "28in", " 28 in "). A plain number without a unit is
// refused here: whether it is SI is for the caller to say (files and the command line: yes).
std::optional<double> parse_quantity(std::string_view text, Dimension dimension);

// `si` in `unit` (for display): the inverse of parse_quantity's factor, rounded in double.
double in_unit(double si, const Unit& unit);

}  // namespace sweetspot
