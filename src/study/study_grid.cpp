// The grid of a study and the order its points are computed in.
#include <stdexcept>

#include "study_keys.hpp"
#include "sweetspot/study/study.hpp"

namespace sweetspot {

using namespace study_detail;

std::size_t Study::points() const {
  std::size_t n = 1;
  for (const Axis& axis : axes) n *= axis.size();
  return n;
}

std::vector<std::size_t> design_axes(const Study& study) {
  std::vector<std::size_t> axes;
  for (std::size_t k = 0; k < study.axes.size(); ++k)
    if (study.axes[k].name == "bat") axes.insert(axes.begin(), k);
    else if (is_bat_parameter(study.axes[k].name)) axes.push_back(k);
    else if (study.sampled_designs && study.axes[k].name == sample_axis) axes.push_back(k);  // a bat per sample
  return axes;
}

std::size_t design_index(const Study& study, const std::vector<std::size_t>& coords) {
  std::size_t index = 0;
  for (const std::size_t k : design_axes(study)) index = index * study.axes[k].size() + coords[k];
  return index;
}

GridPoint grid_point(const Study& study, std::size_t index) {
  if (index >= study.points())
    throw std::out_of_range("grid_point: index " + std::to_string(index) + " >= " + std::to_string(study.points()) +
                            " points");
  GridPoint p;
  p.kind = study.kind;
  p.scene = study.base;
  p.omega_tau = study.omega_tau;
  p.swing_exponent = study.swing_exponent;
  p.air = study.air;
  p.flight = study.flight;
  p.standard = study.standard;
  p.rig_e0 = study.rig_e0;
  p.rig_ball_speed = study.rig_ball_speed;
  p.rig_ball = study.rig_ball;
  p.slices = study.slices;
  p.theory = study.theory;
  p.coords.resize(study.axes.size());
  for (std::size_t k = study.axes.size(); k-- > 0;) {
    const Axis& axis = study.axes[k];
    p.coords[k] = index % axis.size();
    index /= axis.size();
    if (axis.name == sample_axis) {  // every drawn key takes its value in this sample
      for (const Axis& drawn : study.sampled) find_key(drawn.name)->set(p, drawn.values[p.coords[k]]);
      continue;
    }
    const KeySpec* spec = find_key(axis.name);
    if (!spec) throw std::invalid_argument("grid_point: unknown axis '" + axis.name + "'");
    spec->set(p, axis.values[p.coords[k]]);
  }
  p.design = design_index(study, p.coords);
  if (study.kind == StudyKind::certification) p.design_spec = &study.design_specs[p.design];
  if (study.equal_effort)
    p.scene.swing = equal_effort_swing(p.scene.swing, study.reference_moi,
                                       study.design_mass[p.design].moment_of_inertia_about(0), p.swing_exponent);
  return p;
}

namespace {
bool model_axis(const Study& study, const Axis& axis) {
  return axis.name == "bat" || axis.name == "slices" || axis.name == "theory" || is_bat_parameter(axis.name) ||
         (study.sampled_designs && axis.name == sample_axis);
}
}  // namespace

std::size_t models(const Study& study) {
  std::size_t n = 1;
  for (const Axis& axis : study.axes)
    if (model_axis(study, axis)) n *= axis.size();
  return n;
}

// The task number splits into (model, rest), each row-major over its own axes; the coordinates
// then recompose row-major over all axes.
std::size_t task_point(const Study& study, std::size_t task) {
  const std::size_t points = study.points();
  if (task >= points)
    throw std::out_of_range("task_point: task " + std::to_string(task) + " >= " + std::to_string(points) + " points");
  const std::size_t per_model = points / models(study);
  std::size_t model = task / per_model, rest = task % per_model;
  std::vector<std::size_t> coords(study.axes.size());
  for (std::size_t k = coords.size(); k-- > 0;) {
    std::size_t& part = model_axis(study, study.axes[k]) ? model : rest;
    coords[k] = part % study.axes[k].size();
    part /= study.axes[k].size();
  }
  std::size_t index = 0;
  for (std::size_t k = 0; k < coords.size(); ++k) index = index * study.axes[k].size() + coords[k];
  return index;
}

std::vector<std::size_t> task_order(const Study& study) {
  std::vector<std::size_t> order(study.points());
  for (std::size_t t = 0; t < order.size(); ++t) order[t] = task_point(study, t);
  return order;
}

}  // namespace sweetspot
