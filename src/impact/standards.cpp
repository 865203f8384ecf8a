#include "sweetspot/impact/standards.hpp"

#include <algorithm>

#include "sweetspot/ball/ball_presets.hpp"
#include "sweetspot/impact/bat_test_rig.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

constexpr double mph = metres_per_second_per_mph, inch = metres_per_inch;

// The rig's baseball, the preset "ncaa" (ball_presets.hpp): the league specification's COR with
// its fall with speed, on the barrel's curvature. The NCAA protocol's own ball specification did
// not come up in the project's reference search (README "Balls").
Ball rig_ball() { return preset_ball(find_ball_preset("ncaa", "standards")).ball; }

std::vector<Standard> make_standards() {
  // NCAA's statement of 16 Sep 2008: BBCOR <= 0.50 from 1 Jan 2011, "the actual testing procedure
  // has not changed" from BESR's, which fired 70 mph at a bat swung at 66 mph (Nathan, SABR BRJ
  // 2003): the rig at rest takes the relative 136 mph. Length-to-weight -3, barrel 2 5/8 in,
  // non-wood bats at most 36 in (NCAA rule 1-12).
  Standard bbcor{"bbcor", "NCAA/NFHS BBCOR (2011 on)", Measure::bbcor, 0.500, 136 * mph, rig_ball(), rig_pivot,
                 2.625 * inch, 3.0, 36 * inch};
  // BESR <= 0.728 (97 mph exit at 70 mph pitch, 66 mph bat; Nathan, SABR BRJ 2003), same rules.
  Standard besr{"besr", "NCAA BESR (1999-2010)", Measure::besr, 0.728, 136 * mph, rig_ball(), rig_pivot,
                2.625 * inch, 3.0, 36 * inch};
  // USSSA BPF 1.15 with a 2 3/4 in barrel; the BPF test fires 60 mph at a stationary, free-swinging
  // bat (NCAA News, 8 Dec 1997). No drop or length rule found for it.
  Standard bpf{"bpf", "USSSA BPF 1.15", Measure::bpf, 1.15, 60 * mph, rig_ball(), rig_pivot, 2.75 * inch,
               std::nullopt, std::nullopt};
  return {bbcor, besr, bpf};
}

}  // namespace

const char* to_string(Measure measure) {
  switch (measure) {
    case Measure::bbcor:
      return "bbcor";
    case Measure::besr:
      return "besr";
    case Measure::bpf:
      return "bpf";
  }
  return "?";
}

double measure_value(const RigMeasures& m, Measure measure) {
  switch (measure) {
    case Measure::bbcor:
      return m.bbcor;
    case Measure::besr:
      return m.besr;
    case Measure::bpf:
      return m.bpf;
  }
  return m.bbcor;
}

const std::vector<Standard>& standards() {
  static const std::vector<Standard> all = make_standards();
  return all;
}

const Standard& find_standard(std::string_view name) {
  const std::vector<Standard>& all = standards();
  const auto it = std::ranges::find(all, name, &Standard::name);
  if (it == all.end()) throw InputError("--standard " + std::string(name) + ": expected bbcor, besr or bpf");
  return *it;
}

}  // namespace sweetspot
