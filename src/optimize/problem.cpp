#include "sweetspot/optimize/problem.hpp"

namespace sweetspot {

const char* to_string(ObjectiveKind kind) {
  switch (kind) {
    case ObjectiveKind::peak_bbs: return "peak_bbs";
    case ObjectiveKind::sweet_spot_width: return "sweet_spot_width";
    case ObjectiveKind::mean_bbs: return "mean_bbs";
    case ObjectiveKind::peak_distance: return "peak_distance";
  }
  return "?";
}

const char* to_string(Quantity quantity) {
  switch (quantity) {
    case Quantity::measure: return "measure";
    case Quantity::barrel_diameter: return "barrel_diameter";
    case Quantity::drop: return "drop";
    case Quantity::mass: return "mass";
    case Quantity::moi_knob: return "moi_knob";
    case Quantity::moi_pivot: return "moi_pivot";
    case Quantity::length: return "length";
  }
  return "?";
}

const char* to_string(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::cobyla: return "cobyla";
    case Algorithm::bobyqa: return "bobyqa";
    case Algorithm::mlsl: return "mlsl";
  }
  return "?";
}

std::string Constraint::label() const { return name + (upper ? "_max" : "_min"); }

BatDesign design_at(const OptimizationProblem& problem, const std::vector<double>& x) {
  BatDesign design = problem.base;
  for (std::size_t i = 0; i < problem.free.size(); ++i) set_design_parameter(design, problem.free[i].name, x.at(i));
  return design;
}

}  // namespace sweetspot
