#include "flight_bindings.hpp"

#include <pybind11/numpy.h>

#include "sweetspot/flight/flight.hpp"

namespace py = pybind11;

namespace sweetspot::python {

namespace {

py::dict trajectory(const std::vector<FlightSample>& samples) {
  const auto column = [&](double FlightSample::*member) {
    py::array_t<double> out(static_cast<py::ssize_t>(samples.size()));
    auto view = out.mutable_unchecked<1>();
    for (std::size_t i = 0; i < samples.size(); ++i) view(static_cast<py::ssize_t>(i)) = samples[i].*member;
    return out;
  };
  py::dict out;
  out["t"] = column(&FlightSample::t);
  out["x"] = column(&FlightSample::x);
  out["y"] = column(&FlightSample::y);
  out["z"] = column(&FlightSample::z);
  out["vx"] = column(&FlightSample::vx);
  out["vy"] = column(&FlightSample::vy);
  out["vz"] = column(&FlightSample::vz);
  return out;
}

py::dict run_flight(const Launch& launch, const Air& air, const FlightOptions& options) {
  FlightResult r;
  {
    py::gil_scoped_release release;
    r = simulate_flight(launch, air, options);
  }
  py::dict out;
  out["distance"] = r.distance;
  out["apex"] = r.apex;
  out["apex_time"] = r.apex_time;
  out["hang_time"] = r.hang_time;
  out["landing_angle"] = r.landing_angle;
  out["landing_speed"] = r.landing_speed;
  out["landing_spin"] = r.landing_spin;
  out["bearing"] = r.bearing;
  out["landing_x"] = r.landing_x;
  out["landing_y"] = r.landing_y;
  out["air_density"] = r.air_density;
  if (!r.samples.empty()) out["trajectory"] = trajectory(r.samples);
  return out;
}

}  // namespace

void bind_flight(py::module_& m) {
  m.def(
      "_flight",
      [](double speed, double angle, double direction, double backspin, double sidespin, double height,
         double temperature, double pressure, double altitude, double humidity, double wind_speed,
         double wind_direction, double spin_decay_time, bool vacuum, double samples) {
        const Launch launch{speed, angle, direction, backspin, sidespin, height};
        const Air air{temperature, pressure, altitude, humidity / 100, wind_speed, wind_direction};
        FlightOptions options;
        options.aerodynamics.spin_decay_time = spin_decay_time;
        options.drag = options.lift = !vacuum;
        options.sample_interval = samples;
        // Named as this function's argument, not as the library's field.
        if (auto problem = flight_options_problem(options); problem && problem->key == "sample_interval")
          refuse({"samples", problem->value, problem->expected}, "");
        return run_flight(launch, air, options);
      },
      py::arg("speed"), py::arg("angle"), py::arg("direction"), py::arg("backspin"), py::arg("sidespin"),
      py::arg("height"), py::arg("temperature"), py::arg("pressure"), py::arg("altitude"), py::arg("humidity"),
      py::arg("wind_speed"), py::arg("wind_direction"), py::arg("spin_decay_time"), py::arg("vacuum"),
      py::arg("samples"));
}

}  // namespace sweetspot::python
