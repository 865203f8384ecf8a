// sweetspot._sweetspot: thin bindings over sweetspot_core and sweetspot_study. The Python package
// (src/python/sweetspot/__init__.py) gives the documented signatures, broadcasting and xarray.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bat_design_bindings.hpp"
#include "bat_handle.hpp"
#include "flight_bindings.hpp"
#include "python_values.hpp"
#include "result_dict.hpp"
#include "scene_args.hpp"
#include "scene_record.hpp"
#include "sweetspot/ball/ball_file.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/shipped_bats.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/study_results.hpp"
#include "sweetspot/version.hpp"

namespace py = pybind11;
using namespace sweetspot;
using namespace sweetspot::python;

namespace {

// The shipped bats' folder seen from this module (installed, or in the build tree: CMakeLists.txt
// sets both paths), found once, at the first Bat.load, when the module knows its __file__.
const std::filesystem::path& shipped_bats() {
  static const std::filesystem::path dir = [] {
    const auto file = py::module_::import("sweetspot._sweetspot").attr("__file__").cast<std::filesystem::path>();
    return shipped_bats_dir(std::filesystem::weakly_canonical(file).parent_path(),
                            {SWEETSPOT_DATA_INSTALLED, SWEETSPOT_DATA_BUILD});
  }();
  return dir;
}

// The bat's basis for the scene: the rigid basis, the request it asks for, the basis of that
// request, both cached on the bat (as the program's `impact` and a study's point solve it).
std::shared_ptr<const ModalBasis> scene_basis(BatHandle& bat, const SceneArgs& args) {
  return bat.basis(args.theory, impact_mode_request(args.scene, *bat.basis(args.theory, ModeRequest::rigid_only())));
}

// At a stated accuracy (error_estimates.hpp): the bat's design cut as finely as the scene needs,
// each finer bat made once and kept on the bat (BatHandle::finer).
ImpactResult run_within_accuracy(BatHandle& bat, const SceneArgs& args) {
  std::vector<std::shared_ptr<const ModalBasis>> held;  // the bases simulate_within_accuracy refers to
  const auto basis_at = [&](int slices, const ImpactScene& rung) -> const ModalBasis& {
    BatHandle* handle = &bat;
    while (handle->bat().slices() < slices) handle = handle->finer(args.theory);  // judge_level stops in time
    SceneArgs rung_args = args;
    rung_args.scene = rung;
    return *held.emplace_back(scene_basis(*handle, rung_args));
  };
  return simulate_within_accuracy(basis_at, bat.bat().slices(), args.theory, args.scene);
}

ImpactResult checked(ImpactResult r) {
  if (r.status == CollisionStatus::refused_step) throw InputError("dt: " + r.message);
  return r;
}

// One impact as `impacts` runs it: estimates only at a stated accuracy, where the modes' and the
// step's cost nothing (the modes' bound and the step's share) and the slicing's is the ladder's.
ImpactResult run_impact(BatHandle& bat, const SceneArgs& args) {
  if (args.scene.accuracy > 0) {
    SceneArgs estimated = args;
    estimated.scene.error_estimates = true;
    return checked(run_within_accuracy(bat, estimated));
  }
  return checked(simulate_impact(*scene_basis(bat, args), args.scene));
}

// One impact with every error estimate, as the program's `impact` gives it: at a stated accuracy
// as finely cut as it needs, otherwise at the bat's slices with the slicing error from its design
// at twice and four times them.
ImpactResult run_impact_with_errors(BatHandle& bat, SceneArgs args) {
  args.scene.error_estimates = true;
  if (args.scene.accuracy > 0) return checked(run_within_accuracy(bat, args));
  const auto basis = scene_basis(bat, args);  // first: its refusals are the user's
  // Twice and four times the slices, as far as it can be cut and solved in practice; where not,
  // the slicing error stays unestimated (NaN).
  std::vector<std::shared_ptr<const ModalBasis>> finer;
  try {
    BatHandle* handle = &bat;
    for (int times = 0; times < 2 && (handle = handle->finer(args.theory)); ++times)
      finer.push_back(scene_basis(*handle, args));
  } catch (const InputError&) {
    finer.clear();
  }
  std::vector<const ModalBasis*> finer_bases;
  for (const auto& b : finer) finer_bases.push_back(b.get());
  return checked(simulate_impact_with_errors(*basis, finer_bases, args.scene));
}

// impact()'s error estimates without a stated accuracy, made when the result's slicing_error,
// step_error or total_error is first read: they cost the same impact again at twice and four times
// the step and on the bat at twice and four times its slices (the bat's modes solved there on the
// first use), four to five times the impact itself, which a caller reading vf alone need not pay.
// The bat and the resolved scene are kept, so the estimates are those of the call's impact, bit for
// bit (the impact is deterministic), whenever they are read.
class LaterEstimates {
 public:
  LaterEstimates(std::shared_ptr<BatHandle> bat, SceneArgs args) : bat_(std::move(bat)), args_(std::move(args)) {}

  py::dict operator()() const {
    ImpactResult r;
    {
      py::gil_scoped_release release;
      r = run_impact_with_errors(*bat_, args_);
    }
    py::dict d;
    d["slicing_error"] = r.slicing_error, d["step_error"] = r.step_error, d["total_error"] = r.total_error;
    return d;
  }

 private:
  std::shared_ptr<BatHandle> bat_;
  SceneArgs args_;
};

// An empty instance of `type`, a subclass of dict (the package's Result), without its __init__:
// impact() fills it in place instead of copying a dict into it.
py::dict empty_instance(const py::type& type) {
  auto* t = reinterpret_cast<PyTypeObject*>(type.ptr());
  if (!PyType_IsSubtype(t, &PyDict_Type)) throw py::type_error("impact: expected a subclass of dict");
  auto made = py::reinterpret_steal<py::object>(t->tp_new(t, py::tuple().ptr(), nullptr));
  if (!made) throw py::error_already_set();
  return made;
}

// sweetspot.impact's call (below): the result as a `result_type`, its ball's compression u_max and
// radius (impact() warns past it). Without a stated accuracy its error estimates are made when
// first read: the result's `_later` makes them (LaterEstimates).
py::tuple impact_call(const std::shared_ptr<BatHandle>& bat, const SceneArgs& scene, const py::type& result_type) {
  const bool later = !(scene.scene.accuracy > 0);
  ImpactResult r;
  {
    py::gil_scoped_release release;
    r = later ? run_impact(*bat, scene) : run_impact_with_errors(*bat, scene);
  }
  py::dict result = result_dict(r, bat->bat(), empty_instance(result_type), later);
  if (later && PyObject_SetAttr(result.ptr(), "_later"_key, py::cast(LaterEstimates(bat, scene)).ptr()))
    throw py::error_already_set();
  return py::make_tuple(std::move(result), r.u_max, scene.scene.ball.radius);
}

// Ctrl-C (or any signal Python handles) during a long impacts(): the calling thread, OpenMP's
// thread 0, takes the GIL every tenth of a second to let Python run its signal handlers; when one
// raises, every thread leaves its remaining points and the call raises that exception. The clock
// is read every 64th of thread 0's points only: a rigid bat's impact takes under a microsecond.
class SignalWatch {
 public:
  bool interrupted() {
    if (omp_get_thread_num() == 0 && ++calls_ % 64 == 0 && !raised_.load(std::memory_order_relaxed)) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last_ >= std::chrono::milliseconds(100)) {
        last_ = now;
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) raised_ = true;
      }
    }
    return raised_.load(std::memory_order_relaxed);
  }
  bool raised() const { return raised_; }

 private:
  std::atomic<bool> raised_ = false;
  unsigned calls_ = 0;  // thread 0's alone
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// The scalar outputs of a study dataset that `impacts` gives, in the order of its variables.
const std::vector<std::string> impacts_outputs = {
    "vf",     "e_eff",       "bat_speed",      "e_a",         "bbcor",      "besr",
    "bpf",    "contact_time", "collision_time", "u_max",      "peak_force", "impulse",
    "energy_initial", "energy_ball", "energy_bat_translation", "energy_bat_rotation", "energy_vibration",
    "energy_ball_dissipated", "energy_residual", "modes_error", "hoop_frequency", "energy_barrel",
    "energy_damped", "barrel_compression", "slicing_error", "step_error", "total_error", "slices_used", "step_used",
    "launch_angle", "backspin", "sidespin", "energy_ball_spin", "energy_bat_tangential", "energy_friction"};

// Point i of the output columns (impacts_outputs' order).
void fill_point(const ImpactResult& r, double* const* columns, py::ssize_t i) {
  const double values[] = {r.vf,
                           r.e_eff,
                           r.bat_speed,
                           r.rig.e_a,
                           r.rig.bbcor,
                           r.rig.besr,
                           r.rig.bpf,
                           r.contact_time,
                           r.collision_time,
                           r.u_max,
                           r.peak_force,
                           r.impulse,
                           r.energy.initial,
                           r.energy.ball,
                           r.energy.bat_translation,
                           r.energy.bat_rotation,
                           r.energy.vibration,
                           r.energy.ball_dissipated,
                           r.energy.residual,
                           r.modes_error,
                           r.hoop_frequency,
                           r.energy.barrel,
                           r.energy.damped,
                           r.barrel_compression,
                           r.slicing_error,
                           r.step_error,
                           r.total_error,
                           static_cast<double>(r.slices_used),
                           r.step_used,
                           r.launch.angle,
                           r.launch.backspin,
                           r.launch.sidespin,
                           r.energy.ball_spin,
                           r.energy.bat_tangential,
                           r.energy.friction};
  for (std::size_t k = 0; k < std::size(values); ++k) columns[k][i] = values[k];
}

// The most threads impacts runs on: 4 per processor. More only contend for the same cores, and
// each costs a stack: 100000 crashed the interpreter, 1000 under a memory limit aborted in libgomp.
int max_threads() { return 4 * std::max(1, omp_get_num_procs()); }

// Every point of flat per-point arrays (same length) over OpenMP threads without the GIL. A
// point refused as bad input raises ValueError with the first such point's message.
py::dict run_impacts(BatHandle& bat, const py::dict& scalars, const py::dict& arrays, int threads) {
  if (threads < 0 || threads > max_threads())  // 0: OpenMP's default (the package's threads=None)
    throw InputError("threads " + std::to_string(threads) + ": expected 1 to " + std::to_string(max_threads()) +
                     " (4 per processor; more only contend for the same cores)");
  std::set<std::string> per_point;
  std::vector<std::pair<int, py::array_t<double, py::array::c_style | py::array::forcecast>>> columns;
  py::ssize_t n = -1;
  for (const auto& [key, value] : arrays) {
    const std::string name = key.cast<std::string>();
    const auto& names = point_arguments();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw py::type_error("'" + name + "' cannot vary from point to point");
    const py::array given = py::array::ensure(value);
    if (given && std::string("iuf").find(given.dtype().kind()) == std::string::npos)  // complex: no silent real part
      throw InputError(name + ": expected an array of real numbers, not of dtype " + py::str(given.dtype()).cast<std::string>());
    auto column = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
    if (!column || column.ndim() != 1) throw py::type_error("'" + name + "': expected a 1-D array of numbers");
    if (n >= 0 && column.size() != n) throw py::value_error("impacts: per-point arrays of different lengths");
    n = column.size();
    per_point.insert(name);
    columns.emplace_back(static_cast<int>(it - names.begin()), std::move(column));
  }
  if (n < 0) n = 1;
  const SceneArgs base = scene_args(scalars, per_point);
  std::vector<std::pair<int, const double*>> data;
  for (const auto& [which, column] : columns) data.emplace_back(which, column.data());

  {  // every point's ball in its ranges before any point runs
    ImpactScene scene = base.scene;  // every point sets the same fields
    for (py::ssize_t i = 0; i < n; ++i) {
      for (const auto& [which, values] : data) set_point_argument(scene, which, values[i]);
      check_point_ranges(scene);
    }
  }
  // The output columns, made first and filled in place by the points (no GIL needed to write them).
  py::dict out;
  std::vector<double*> outputs;
  for (const std::string& name : impacts_outputs) {
    py::array_t<double> column(n);
    outputs.push_back(column.mutable_data());
    out[py::str(name)] = std::move(column);
  }
  py::array_t<int> status_column(n), contacts_column(n), kept_column(n);
  int* const status = status_column.mutable_data();
  int* const contacts = contacts_column.mutable_data();
  int* const kept = kept_column.mutable_data();
  std::vector<std::string> errors(n);
  SignalWatch signals;
  {
    py::gil_scoped_release release;
    if (threads == 0) threads = omp_get_max_threads();
#pragma omp parallel num_threads(threads)
    {
      SceneArgs args = base;  // each thread's; every point sets the same fields
#pragma omp for schedule(dynamic)
      for (py::ssize_t i = 0; i < n; ++i) {
        if (signals.interrupted()) continue;  // the rest are left, the loop cannot break
        try {
          for (const auto& [which, values] : data) set_point_argument(args.scene, which, values[i]);
          const ImpactResult r = run_impact(bat, args);
          fill_point(r, outputs.data(), i);
          // As a study's dataset stores it: a point of a failing status has no values.
          if (!stores_values(r.status))
            for (double* output : outputs) output[i] = std::nan("");
          status[i] = static_cast<int>(r.status), contacts[i] = r.contacts;
          kept[i] = static_cast<int>(r.modes_kept.size());
        } catch (const InputError& e) {
          errors[i] = e.what();
        } catch (const std::exception& e) {  // not bad input: the point fails, as a study's would
          for (double* output : outputs) output[i] = std::nan("");
          status[i] = static_cast<int>(CollisionStatus::failed), contacts[i] = -1, kept[i] = -1;
        }
      }
    }
  }
  if (signals.raised()) throw py::error_already_set();  // KeyboardInterrupt, say
  for (const std::string& e : errors)
    if (!e.empty()) throw InputError(e);
  out["status"] = std::move(status_column);
  out["contacts"] = std::move(contacts_column);
  out["modes_kept"] = std::move(kept_column);
  return out;
}

// The bat as a result's attributes name it (a study dataset's bat_* names): its name and slices,
// and where known the file and profile it was read from with their texts.
py::dict bat_source(const BatHandle& b) {
  py::dict d;
  d["bat"] = b.bat().name;
  d["bat_slices"] = b.bat().slices();
  const BatSource& s = b.source();
  const std::pair<const char*, std::string> texts[] = {{"bat_file", s.toml_file.string()},
                                                       {"bat_toml", s.toml_text},
                                                       {"bat_profile_file", s.profile_file.string()},
                                                       {"bat_profile", s.profile_text}};
  for (const auto& [name, text] : texts)
    if (!text.empty()) d[name] = text;
  return d;
}

py::dict modes_dict(BatHandle& bat, std::optional<int> count, const std::string& theory_text) {
  const BeamTheory theory = parse_beam_theory(theory_text);
  if (count && *count < 1) throw InputError("count " + std::to_string(*count) + ": expected at least 1");
  const auto basis = bat.basis(theory, count ? ModeRequest::lowest(*count) : ModeRequest::all());
  const int solved = basis->count() - 2;
  if (count && *count > solved)
    throw InputError("count " + std::to_string(*count) + ": the bat has only " + std::to_string(solved) +
                     " vibrational modes at " + std::to_string(bat.bat().slices()) + " slices");
  const int k = count.value_or(solved);
  const std::vector<double> f = basis->vibrational_frequencies_hz();
  py::array_t<double> shapes({k, basis->slices()});
  py::list nodes;
  for (int mode = 1; mode <= k; ++mode) {  // as `sweetspot modes --shapes`: max |psi| = 1, + at the barrel end
    const Eigen::VectorXd psi = basis->psi.col(mode + 1);
    const double scale = psi.cwiseAbs().maxCoeff() * (psi(psi.size() - 1) < 0 ? -1 : 1);
    for (int i = 0; i < basis->slices(); ++i) shapes.mutable_at(mode - 1, i) = psi(i) / scale;
    nodes.append(array(basis->nodes(mode + 1)));
  }
  py::dict d;
  d["theory"] = to_string(theory);
  d["frequencies_hz"] = py::array_t<double>(k, f.data());
  d["nodes_m"] = nodes;
  d["z_m"] = array(basis->z);
  d["shapes"] = shapes;
  d["omega"] = array(Eigen::VectorXd(basis->omega.head(k + 2)));
  d["mass_kg"] = basis->mass;
  d["z_cm_m"] = basis->z_cm;
  d["moment_of_inertia_cm_kg_m2"] = basis->moment_of_inertia_cm;
  return d;
}

}  // namespace

PYBIND11_MODULE(_sweetspot, m) {
  m.doc() = "sweetspot's C++ engine (use the package sweetspot)";
  // The program's bad input (one line naming what was wrong) is Python's ValueError.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  py::class_<BatHandle, std::shared_ptr<BatHandle>> bat(m, "Bat", R"(A bat cut into slices, its normal modes solved on demand and kept.

Make one with Bat.load (a bat file), Bat.from_text (a bat file's text, as results store it),
Bat.from_knots or Bat.from_dimensions. Properties: name, length (m), slices, mass (kg), z_cm (m
from the knob), moment_of_inertia_cm (kg m^2), radius_of_gyration (m), z (slice centres, m),
outer_diameter and inner_diameter (per slice, m).)");
  bat
      // load, modes and moment_of_inertia_about are the package's (__init__.py), which check their
      // arguments' types first: a wrong one is a ValueError naming it, not pybind11's TypeError.
      .def_static("_load", [](const std::filesystem::path& path, std::optional<int> slices) {
            BatSource source;
            BatDesign design = load_bat_design(find_bat_file(path.string(), shipped_bats(), "path"), source);
            return make_bat(std::move(design), slices, std::move(source));
          }, py::arg("path"), py::arg("slices") = py::none())
      .def_static("_from_text", [](const std::string& toml, const std::string& profile, const std::string& name,
                                   std::optional<int> slices) {
            BatSource source{name, {}, toml, profile};
            BatDesign design = bat_design_from_texts(source);
            return make_bat(std::move(design), slices, std::move(source));
          })
      .def("_source", &bat_source)
      .def_property_readonly("name", [](const BatHandle& b) { return b.bat().name; }, "the bat's name (its file's `name`)")
      .def_property_readonly("length", [](const BatHandle& b) { return b.bat().length; }, "length, m")
      .def_property_readonly("slices", [](const BatHandle& b) { return b.bat().slices(); }, "number of slices it is cut into")
      .def_property_readonly("mass", [](const BatHandle& b) { return b.mass().mass; }, "mass of the sliced bat, kg")
      .def_property_readonly("z_cm", [](const BatHandle& b) { return b.mass().z_cm; }, "centre of mass, m from the knob")
      .def_property_readonly("moment_of_inertia_cm", [](const BatHandle& b) { return b.mass().moment_of_inertia_cm; },
                             "kg m^2 about the centre of mass")
      .def_property_readonly("radius_of_gyration", [](const BatHandle& b) { return b.mass().radius_of_gyration(); }, "radius of gyration about the centre of mass, m")
      .def("_moment_of_inertia_about", [](const BatHandle& b, double z) { return b.mass().moment_of_inertia_about(z); },
           py::arg("z"))
      .def_property_readonly("z", [](const BatHandle& b) {
            std::vector<double> z(b.bat().slices());
            for (int i = 0; i < b.bat().slices(); ++i) z[i] = b.bat().slice_center(i);
            return array(z);
          }, "slice centres, m from the knob")
      .def_property_readonly("outer_diameter", [](const BatHandle& b) { return array(b.bat().outer_diameter); }, "outer diameter of each slice, m")
      .def_property_readonly("inner_diameter", [](const BatHandle& b) { return array(b.bat().inner_diameter); },
                             "inner diameter of each slice, m (empty for a solid bat)")
      .def("_modes", &modes_dict, py::arg("count") = py::none(), py::arg("theory") = "timoshenko")
      .def("__repr__", [](const BatHandle& b) {
        return "<sweetspot.Bat '" + b.bat().name + "': " + std::to_string(b.bat().length) + " m, " +
               std::to_string(b.bat().slices()) + " slices>";
      });
  bind_bat_design(m, bat);
  bind_quantity_arguments(m);

  // impact(): see impact_call. _impact takes the arguments as they were given and gives None where
  // the package must check and convert one first (plain_scene_args); _impact_checked takes them as
  // the package made them.
  py::class_<LaterEstimates>(m, "_LaterEstimates").def("__call__", &LaterEstimates::operator());
  m.attr("_LATER") = later_marker();
  m.def("_impact", [](const std::shared_ptr<BatHandle>& bat, const py::tuple& values, const py::type& result_type) -> py::object {
    const std::optional<SceneArgs> scene = plain_scene_args(values);
    if (!scene) return py::none();
    return impact_call(bat, *scene, result_type);
  });
  m.def("_impact_checked", [](const std::shared_ptr<BatHandle>& bat, const py::dict& args, const py::type& result_type) {
    return impact_call(bat, scene_args(args), result_type);
  });
  m.def("_max_threads", &max_threads);
  bind_flight(m);
  m.attr("_min_slices") = min_slices;
  m.attr("_max_slices") = max_slices;
  m.def("_impacts", &run_impacts, py::arg("bat"), py::arg("scalars"), py::arg("arrays"), py::arg("threads") = 0);
  m.def("_describe", [](const std::string& name) {
    const OutputDescription d = describe_output(name);
    return py::make_tuple(d.units, d.long_name);
  });
  m.def("_status_names", [] {
    py::list names;
    for (int k = 0; k <= static_cast<int>(last_collision_status); ++k)
      names.append(to_string(static_cast<CollisionStatus>(k)));
    return names;
  });
  m.def("_point_arguments", [] { return point_arguments(); });
  m.def("_scene_arguments", [] { return scene_arguments(); });
  m.def("_scene_record", [](const py::dict& scalars, const std::set<std::string>& per_point) {
    return scene_record(scene_args(scalars, per_point), per_point);
  });
  // The program's --version, and the commit it was built from: every result records both.
  m.attr("_installed_program") = SWEETSPOT_PROGRAM_INSTALLED;  // relative to the package (run_study)
  m.attr("__version__") = version;
  m.attr("_git_commit") = git_commit;
  m.def("_ball", [](const std::string& name) {
    const BallFit fit = load_ball(name, "ball");
    const Ball& b = fit.ball;
    py::dict d;  // the fitted ball, as `sweetspot ball --json` states it
    d["mass"] = b.mass, d["radius"] = b.radius, d["k1"] = b.k1, d["a"] = b.a, d["e0"] = b.e0;
    d["cor_speed"] = b.cor_speed, d["cor_slope"] = b.cor_slope, d["curved_contact"] = b.curved_contact;
    d["stiffness_from"] = fit.stiffness_from, d["cor_residual"] = fit.cor_residual;
    d["stiffness_residual"] = fit.stiffness_residual;
    return d;
  });
}
