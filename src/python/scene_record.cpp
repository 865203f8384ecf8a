#include "scene_record.hpp"

#include "sweetspot/contact/collision.hpp"

namespace py = pybind11;

namespace sweetspot::python {

py::dict scene_record(const SceneArgs& args, const std::set<std::string>& per_point) {
  const ImpactScene& s = args.scene;
  py::dict d;
  const auto number = [&](const std::string& key, double value) {
    if (!per_point.contains(key)) d[py::str("scene_" + key)] = value;
  };
  number("z", s.z);
  number("ball_speed", s.ball_speed);
  // The swing is given one way: the other key has no value to show (as in a study's dataset).
  number(s.swing.about_center ? "center" : "cm_speed", s.swing.about_center ? s.swing.center : s.swing.cm_speed);
  number("omega", s.swing.omega);
  number("e0", s.ball.e0);
  number("ball_mass", s.ball.mass);
  number("ball_radius", s.ball.radius);
  number("k1", s.ball.k1);
  number("a", s.ball.a);
  number("undercut", s.oblique.undercut);
  number("swing_tilt", s.oblique.swing_tilt);
  number("pitch_spin", s.oblique.pitch_spin);
  number("friction", s.oblique.friction);
  // The ball's speed dependence and curvature are no arguments: its name (scene_ball) gives them;
  // stored so that a result shows them and a replay can check them.
  number("cor_slope", s.ball.cor_slope);
  number("cor_speed", s.ball.cor_speed);
  d["scene_curved_contact"] = s.ball.curved_contact ? 1 : 0;
  d["scene_pivot"] = s.pivoted ? 1 : 0;
  if (s.vibrational_modes == all_modes) d["scene_modes"] = "all";
  else if (s.vibrational_modes == auto_modes) d["scene_modes"] = "auto";
  else d["scene_modes"] = s.vibrational_modes;
  d["scene_mode_tolerance"] = s.mode_tolerance;
  d["scene_accuracy"] = s.accuracy;            // 0: none stated
  d["scene_step_accuracy"] = s.step_accuracy;  // 0: the step as given (dt)
  d["scene_integrator"] = to_string(s.integrator.method);
  d["scene_dt"] = s.integrator.dt;
  d["scene_tolerance"] = s.integrator.tolerance;
  d["scene_window"] = s.integrator.window;
  d["scene_theory"] = to_string(args.theory);
  return d;
}

}  // namespace sweetspot::python
