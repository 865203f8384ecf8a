#include "bat_design_bindings.hpp"

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "scene_args.hpp"
#include "sweetspot/ball/ball_file.hpp"
#include "sweetspot/bat/bat_design_text.hpp"
#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/input_error.hpp"

namespace py = pybind11;

namespace sweetspot::python {

namespace {

// The material: a wood preset, any constant given beside it overriding the preset's.
void set_material(BatDesign& d, const std::string& preset, const py::dict& constants) {
  set_material_preset(d, preset);
  for (const auto& [key, value] : constants)
    if (!value.is_none()) {
      const std::string name = key.cast<std::string>();
      set_design_parameter(d, name, number(name, value));
    }
}

// Knots as a profile CSV gives them: at least two, sorted, on the bat, diameters positive and an
// inner one smaller than the outer; the messages name the argument and the knot.
Profile knot_profile(const std::vector<double>& z, const std::vector<double>& outer,
                     const std::optional<std::vector<double>>& inner, const std::string& interpolation) {
  if (z.size() < 2) throw InputError("z: " + std::to_string(z.size()) + " knots; expected at least 2");
  if (outer.size() != z.size() || (inner && inner->size() != z.size()))
    throw InputError("outer_diameter, inner_diameter: expected one diameter per knot (" + std::to_string(z.size()) + ")");
  for (std::size_t i = 0; i < z.size(); ++i) {
    const std::string knot = "knot " + std::to_string(i) + ": ";
    if (!std::isfinite(z[i]) || z[i] < 0 || (i > 0 && z[i] <= z[i - 1]))
      throw InputError(knot + "z = " + std::to_string(z[i]) + ": expected finite positions from 0 up, increasing");
    if (!(std::isfinite(outer[i]) && outer[i] > 0))
      throw InputError(knot + "outer_diameter = " + std::to_string(outer[i]) + ": expected a positive number (m)");
    if (inner && !((*inner)[i] >= 0 && (*inner)[i] < outer[i]))
      throw InputError(knot + "inner_diameter = " + std::to_string((*inner)[i]) +
                       ": expected at least 0 and less than the outer diameter");
  }
  Profile p;
  p.interpolation = parse_interpolation(interpolation);
  p.z = z;
  p.outer = outer;
  if (inner) p.inner = *inner;
  if (inner) {
    const ThinnestWall thinnest = thinnest_wall(p);
    if (thinnest.wall <= 0)
      throw InputError("knots " + std::to_string(thinnest.interval) + " and " + std::to_string(thinnest.interval + 1) +
                       ": with interpolation '" + interpolation + "' the inner diameter reaches the outer between them (wall " +
                       std::to_string(thinnest.wall) + " m at z = " + std::to_string(thinnest.z) +
                       " m); expected a wall everywhere: interpolation 'linear', or knots that keep the bore inside");
  }
  return p;
}

// The name of a bat made in Python, under a bat file's rule for its key 'name' (bat_file.cpp):
// a non-empty string, since results and datasets tell bats apart by it, without a NUL character,
// which would cut it short where a dataset stores it.
const std::string& bat_name(const std::string& name) {
  if (name.empty()) throw InputError("name '': expected a non-empty string (a bat file's 'name')");
  if (name.find('\0') != std::string::npos)
    throw InputError("name " + py::repr(py::str(name)).cast<std::string>() +
                     ": expected a string without NUL characters (a bat file's 'name')");
  return name;
}

py::dict properties(const BatHandle& b) {
  const MassProperties m = design_mass_properties(b.design());
  py::dict d;
  d["mass"] = m.mass;
  d["length"] = b.design().length;
  d["drop"] = bat_drop(b.design().length, m.mass);
  d["balance_point"] = m.z_cm;
  d["moi_knob"] = m.moment_of_inertia_about(0);
  d["moi_pivot"] = m.moment_of_inertia_about(swing_weight_pivot);
  d["moi_cm"] = m.moment_of_inertia_cm;
  return d;
}

py::dict certification(const BatHandle& b, const std::string& standard, std::optional<std::string> ball, std::optional<double> e0,
                       std::optional<double> ball_speed, std::optional<double> pivot, const py::object& modes,
                       const std::string& theory, std::optional<double> accuracy) {
  CertifyOptions options;
  if (ball) options.ball = load_ball(*ball, "ball").ball;
  options.e0 = e0;
  options.ball_speed = ball_speed;
  options.pivot = pivot;
  options.vibrational_modes = parse_modes(modes);
  options.theory = parse_beam_theory(theory);
  options.accuracy = accuracy;
  if (std::ranges::find(standards(), standard, &Standard::name) == standards().end())  // as Python writes it
    throw InputError("standard " + py::repr(py::str(standard)).cast<std::string>() +
                     ": expected \"bbcor\", \"besr\" or \"bpf\"");
  const Standard& s = find_standard(standard);
  Certification c;
  {
    py::gil_scoped_release release;
    c = certify(b.design(), s, options);
  }
  py::list checks;
  for (const RuleCheck& r : c.checks)
    checks.append(py::dict(py::arg("rule") = r.rule, py::arg("value") = r.value, py::arg("limit") = r.limit,
                           py::arg("pass") = r.pass));
  py::dict d;  // the keys of `sweetspot certify --json`, in its order
  d["standard"] = c.standard.name;
  d["z_max"] = c.z_max;
  d["e_a"] = c.at_max.e_a;
  d[py::str(to_string(c.standard.measure))] = c.measure;
  d["moi_pivot"] = c.moi_pivot;
  d["moi_pivot_model"] = c.moi_pivot_model;
  d["mass"] = c.mass;
  d["length"] = c.length;
  d["drop"] = c.drop;
  d["barrel_diameter"] = c.barrel_diameter;
  d["hoop_frequency"] = c.hoop_frequency;
  d["barrel_compression"] = c.barrel_compression;
  d["barrel_phi"] = c.barrel_phi;
  d["barrel_compliance"] = c.barrel_compliance;
  d["pivot"] = c.standard.pivot;
  d["ball_speed"] = c.standard.ball_speed;
  d["ball"] = ball.value_or("ncaa");
  d["e0"] = c.standard.ball.e0;
  d["cor_speed"] = c.standard.ball.cor_speed;
  d["cor_slope"] = c.standard.ball.cor_slope;
  d["checks"] = checks;
  d["pass"] = c.pass;
  if (accuracy) {  // the keys of `sweetspot certify --accuracy A --json`
    d["accuracy"] = *accuracy;
    d["slices_used"] = c.slices_used;
    d["slicing_error"] = c.slicing_error;
    d["modes_error"] = c.modes_error;
    d["step_error"] = c.step_error;
    d["total_error"] = c.total_error;
    d["accurate"] = c.accurate;
    if (!c.accurate) d["unmet"] = c.unmet;
  }
  if (c.hollow) {
    py::dict b;
    const double nan = std::nan("");
    b["load"] = c.barrel.load == WallLoad::point ? "point" : "patch";
    b["calibrated"] = c.barrel.calibrated();
    b["hoop_frequency_measured"] = c.barrel.hoop_frequency > 0 ? c.barrel.hoop_frequency : nan;
    b["compression_measured"] = c.barrel.compression > 0 ? c.barrel.compression : nan;
    d["barrel"] = b;
  }
  return d;
}

}  // namespace

std::shared_ptr<BatHandle> make_bat(BatDesign design, std::optional<int> slices, BatSource source) {
  if (slices) {
    if (*slices < min_slices || *slices > max_slices)
      throw InputError("slices " + std::to_string(*slices) + ": expected " + std::to_string(min_slices) + " to " +
                       std::to_string(max_slices));
    design.slices = *slices;
  }
  Bat bat = build_bat(design);  // throws InputError naming the rule an impossible bat breaks
  if (slices && bat.slices() != *slices) bat = resample(bat, *slices);  // a profile of one row per slice
  return std::make_shared<BatHandle>(std::move(bat), std::move(design), std::move(source));
}

void bind_bat_design(py::module_& m, py::class_<BatHandle, std::shared_ptr<BatHandle>>& bat) {
  bat.def_static(
         "_from_knots",
         [](const std::string& name, double length, const std::vector<double>& z, const std::vector<double>& outer,
            const std::optional<std::vector<double>>& inner, const std::string& interpolation, std::optional<int> slices,
            const std::string& material, const py::dict& constants) {
           BatDesign d;
           d.name = bat_name(name);
           d.length = length;
           d.profile = knot_profile(z, outer, inner, interpolation);
           set_material(d, material, constants);
           return make_bat(std::move(d), slices);
         })
      .def_static("_from_dimensions",
                  [](const std::string& name, double length, const py::dict& dimensions, const std::string& end,
                     std::optional<int> slices, const std::string& material, const py::dict& constants) {
                    BatDesign d;
                    d.name = bat_name(name);
                    d.length = length;
                    d.dimensions = Dimensions{};
                    d.dimensions->end = parse_end_shape(end);
                    for (const auto& [key, value] : dimensions) {
                      const std::string parameter = key.cast<std::string>();
                      set_design_parameter(d, parameter, number(parameter, value));
                    }
                    set_material(d, material, constants);
                    // Its bat file, which reads back as this design bit for bit (Bat.from_text).
                    BatSource source;
                    source.toml_text = bat_design_text(d, "made by sweetspot.Bat.from_dimensions");
                    return make_bat(std::move(d), slices, std::move(source));
                  })
      .def("properties", &properties,
           "What a designer reads, exact for the designed shape: mass (kg), length (m), drop (length in "
           "inches minus weight in ounces), balance_point (m from the knob), moi_knob, moi_pivot (6 in "
           "from the knob), moi_cm (kg m^2).");
  m.def("_certify", &certification, py::arg("bat"), py::arg("standard"), py::arg("ball"), py::arg("e0"), py::arg("ball_speed"),
        py::arg("pivot"), py::arg("modes"), py::arg("theory"), py::arg("accuracy"));
}

}  // namespace sweetspot::python
