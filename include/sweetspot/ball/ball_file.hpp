#pragma once
// A ball named on a command line (`--ball`): a preset's name, or a TOML file whose [ball] table
// states it (README "Balls").
#include <string>

#include "sweetspot/ball/ball_tests.hpp"

namespace sweetspot {

// Throws InputError naming the file (or `option`, the preset list) and what was wrong.
BallFit load_ball(const std::string& preset_or_file, const std::string& option = "--ball");

}  // namespace sweetspot
