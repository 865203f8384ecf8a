#pragma once
// Named balls (README "Balls", with the source of every number): N2000's model ball, a baseball
// of the league specification and the NCAA rig's, and the two rated softballs. Each but N2000's is
// given by its test values (BallTests) and fitted like a user's ball.
#include <string>
#include <string_view>
#include <vector>

#include "sweetspot/ball/ball_tests.hpp"

namespace sweetspot {

struct BallPreset {
  std::string name;    // as `preset =` and `--ball` take it
  std::string title;   // what it is, for reports
  std::string source;  // where its numbers come from
  BallTests tests;
};

const std::vector<BallPreset>& ball_presets();
// The preset of that name; throws InputError "`where`: preset = "x": expected one of n2000, ...".
const BallPreset& find_ball_preset(std::string_view name, const std::string& where);
// The fitted ball of a preset (N2000's: Ball{}'s law, bit for bit).
BallFit preset_ball(const BallPreset& preset);

}  // namespace sweetspot
