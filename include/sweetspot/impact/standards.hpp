#pragma once
// The bat-performance standards `sweetspot certify` applies (README "Certification", with the
// sources of every number): what each measures, its limit, the rig's conditions and the rules on
// the bat's dimensions. Every rule is "value <= limit".
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/contact/ball.hpp"
#include "sweetspot/impact/rig_measures.hpp"

namespace sweetspot {

enum class Measure { bbcor, besr, bpf };
const char* to_string(Measure measure);
double measure_value(const RigMeasures& m, Measure measure);

struct Standard {
  std::string name;   // as --standard takes it: "bbcor", "besr", "bpf"
  std::string title;  // who sets it, for the report
  Measure measure = Measure::bbcor;
  double limit = 0;       // the measure at its maximum over the barrel may not exceed this
  double ball_speed = 0;  // m/s, the rig's inbound ball speed
  Ball ball;              // the ball the rig fires: the preset "ncaa" (ball_presets.hpp)
  double pivot = 0;       // m from the knob
  double max_barrel_diameter = 0;    // m, the largest outer diameter
  std::optional<double> max_drop;    // length in inches minus weight in ounces, at most this
  std::optional<double> max_length;  // m
};

// bbcor (NCAA/NFHS, 2011 on), besr (NCAA 1999-2010), bpf (USSSA).
const std::vector<Standard>& standards();
// The standard of that name; throws InputError "--standard NAME: expected bbcor, besr or bpf".
const Standard& find_standard(std::string_view name);

}  // namespace sweetspot
