#include "result_dict.hpp"

#include <cmath>

#include "python_values.hpp"

namespace py = pybind11;

namespace sweetspot::python {

namespace {

// A hollow bat's barrel, as `impact --json` states it.
py::dict barrel_dict(const BarrelCalibration& b) {
  NamedDict d;
  const double nan = std::nan("");
  d["load"_key] = b.load == WallLoad::point ? "point" : "patch";
  d["calibrated"_key] = b.calibrated();
  d["hoop_frequency_measured"_key] = b.hoop_frequency > 0 ? b.hoop_frequency : nan;
  d["compression_measured"_key] = b.compression > 0 ? b.compression : nan;
  return d.finish();
}

}  // namespace

py::handle later_marker() {
  static const py::handle marker = py::module_::import("builtins").attr("object")().release();  // kept
  return marker;
}

py::dict result_dict(const ImpactResult& r, const Bat& bat, py::dict into, bool estimates_later) {
  static DictLayout layouts[2][2];  // with and without a message, a hollow bat's barrel
  NamedDict d(layouts[!r.message.empty()][bat.hollow()], std::move(into));
  d["status"_key] = to_string(r.status);
  if (!r.message.empty()) d["message"_key] = r.message;
  d["z"_key] = r.z, d["vf"_key] = r.vf, d["e_eff"_key] = r.e_eff, d["contact_time"_key] = r.contact_time;
  d["collision_time"_key] = r.collision_time, d["u_max"_key] = r.u_max, d["peak_force"_key] = r.peak_force;
  d["impulse"_key] = r.impulse, d["bat_speed"_key] = r.bat_speed, d["hoop_frequency"_key] = r.hoop_frequency;
  d["barrel_compression"_key] = r.barrel_compression, d["barrel_phi"_key] = r.barrel_phi;
  d["barrel_compliance"_key] = r.barrel_compliance, d["barrel_compression_eff"_key] = r.barrel_compression_eff;
  d["e_a"_key] = r.rig.e_a, d["bbcor"_key] = r.rig.bbcor;
  d["besr"_key] = r.rig.besr, d["bpf"_key] = r.rig.bpf;
  static DictLayout energy_layout;
  NamedDict e(energy_layout);
  e["initial"_key] = r.energy.initial, e["ball"_key] = r.energy.ball, e["bat_translation"_key] = r.energy.bat_translation;
  e["bat_rotation"_key] = r.energy.bat_rotation, e["vibration"_key] = r.energy.vibration;
  e["ball_dissipated"_key] = r.energy.ball_dissipated, e["barrel"_key] = r.energy.barrel,
  e["damped"_key] = r.energy.damped, e["residual"_key] = r.energy.residual;
  e["ball_spin"_key] = r.energy.ball_spin, e["bat_tangential"_key] = r.energy.bat_tangential;
  e["friction"_key] = r.energy.friction;
  d["energy"_key] = e.finish();
  d["launch_angle"_key] = r.launch.angle, d["backspin"_key] = r.launch.backspin, d["sidespin"_key] = r.launch.sidespin;
  d["mode_energy"_key] = array(r.mode_energy);
  d["modes_kept"_key] = array(r.modes_kept.data(), r.modes_kept.size());
  d["modes_error"_key] = r.modes_error;
  if (estimates_later)
    d["slicing_error"_key] = later_marker(), d["step_error"_key] = later_marker(), d["total_error"_key] = later_marker();
  else
    d["slicing_error"_key] = r.slicing_error, d["step_error"_key] = r.step_error, d["total_error"_key] = r.total_error;
  d["slices_used"_key] = r.slices_used, d["step_used"_key] = r.step_used;
  d["contacts"_key] = r.contacts;
  if (bat.hollow()) d["barrel"_key] = barrel_dict(bat.material.barrel);
  return d.finish();
}


}  // namespace sweetspot::python
