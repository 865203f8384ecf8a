#pragma once
// Internal: a [ball] table of a TOML file (bat-test rig, study, optimisation, ball file) read into
// a fitted ball (README "Balls"). `preset` starts from a named ball; any test value given beside
// it replaces the preset's (a COR key its COR data, a stiffness key its stiffness).
#include <string>

#include <toml++/toml.h>

#include "sweetspot/ball/ball_tests.hpp"

namespace sweetspot::detail {

// Throws InputError "FILE:LINE: [ball]: key = value: expected ..." for an unknown key or a bad
// value, `file` the file's name.
BallFit read_ball_table(const toml::table& table, const std::string& file);

}  // namespace sweetspot::detail
