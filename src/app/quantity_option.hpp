#pragma once
// Command-line options that take a length, mass or speed: "--z 28in", "--z '28 in'",
// "--ball-speed 136mph". A plain number is read as before (SI, or the option's own unit).
#include <CLI/CLI.hpp>
#include <string_view>

#include "sweetspot/units/quantity.hpp"

namespace sweetspot::app {

// A CLI11 transform that rewrites a value with a unit as the plain number CLI11 then reads: in
// SI, or in `plain_unit` for an option whose plain numbers are not SI (ball --speeds, in mph).
// A value that is neither a plain number nor a quantity of `dimension` is refused (exit 2):
// "--z: "31oz": expected a length (a number in m, or a string such as "28 in"; units ...)".
CLI::Validator quantity_option(Dimension dimension, std::string_view plain_unit = {});

}  // namespace sweetspot::app
