// sweetspot modes: the normal modes and mass properties of one bat (N2000 Table II).
#include <cstdio>
#include <memory>
#include <string>

#include "bat_argument.hpp"
#include "commands.hpp"
#include "display_units.hpp"
#include "json.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/bat/modes.hpp"

namespace sweetspot::app {

namespace {

struct ModesOptions {
  std::string bat_file;
  std::string theory = "timoshenko";
  int slices = 0;  // 0: the profile's own
  int count = 10;
  bool json = false;
  bool shapes = false;
  DisplayUnits units;
};

// psi of vibrational mode `mode` (1 = the first) at the slice centres, scaled to max |psi| = 1
// and signed positive at the barrel end: the eigensolver's sign and normalisation are arbitrary.
std::vector<double> unit_shape(const ModalBasis& basis, int mode) {
  const Eigen::VectorXd psi = basis.psi.col(mode + 1);
  const double scale = psi.cwiseAbs().maxCoeff() * (psi(psi.size() - 1) < 0 ? -1 : 1);
  const Eigen::VectorXd unit = psi / scale;
  return {unit.begin(), unit.end()};
}

void print_table(const Bat& bat, const MassProperties& mp, const ModalBasis& basis, int count, const DisplayUnits& u) {
  std::printf("bat %s: L = %s, %d slices, %s\n", bat.name.c_str(), u.length(bat.length, "%.4g").c_str(), bat.slices(),
              to_string(basis.theory));
  std::printf("mass %s, centre of mass %s from the knob, radius of gyration %s\n", u.mass(mp.mass, "%.4f").c_str(),
              u.length(mp.z_cm, "%.4f").c_str(), u.length(mp.radius_of_gyration(), "%.4f").c_str());
  // The swing weight in oz in^2 needs no decimals; kg m^2 needs five.
  const char* moi_format = u.us() ? "%.0f" : "%.5f";
  std::printf("moment of inertia %s about the CM, %s about the knob\n\n",
              u.moment_of_inertia(mp.moment_of_inertia_cm, moi_format).c_str(),
              u.moment_of_inertia(mp.moment_of_inertia_about(0), moi_format).c_str());
  // Nodes in cm (SI) or in (US), one decimal either way.
  const double node_scale = u.us() ? 1 / metres_per_inch : 100;
  std::printf("%5s %12s   %s\n", "mode", "frequency/Hz", u.us() ? "nodes/in from the knob" : "nodes/cm from the knob");
  const auto f = basis.vibrational_frequencies_hz();
  for (int mode = 1; mode <= count; ++mode) {
    std::printf("%5d %12.1f  ", mode, f[mode - 1]);
    for (double z : basis.nodes(mode + 1)) std::printf(" %5.1f", node_scale * z);
    std::printf("\n");
  }
}

void print_json(const Bat& bat, const MassProperties& mp, const ModalBasis& basis, int count, bool shapes) {
  const auto all = basis.vibrational_frequencies_hz();
  std::vector<Json> nodes;
  for (int mode = 1; mode <= count; ++mode) nodes.push_back(Json::numbers(basis.nodes(mode + 1)));
  Json::Object out;
  out.add("bat", bat.name)
      .add("theory", to_string(basis.theory))
      .add("slices", Json::integer(bat.slices()))
      .add("length_m", bat.length)
      .add("mass_kg", mp.mass)
      .add("z_cm_m", mp.z_cm)
      .add("r_g_m", mp.radius_of_gyration())
      .add("moment_of_inertia_cm_kg_m2", mp.moment_of_inertia_cm)
      .add("frequencies_hz", Json::numbers({all.begin(), all.begin() + count}))
      .add("nodes_m", Json::array(nodes));
  if (shapes) {  // N2000 Fig. 6
    std::vector<Json> unit_shapes;
    for (int mode = 1; mode <= count; ++mode) unit_shapes.push_back(Json::numbers(unit_shape(basis, mode)));
    out.add("z_m", Json::numbers(basis.z)).add("shapes", Json::array(unit_shapes));
  }
  std::printf("%s\n", Json(out).text().c_str());
}

void run_modes(const ModesOptions& o) {
  Bat bat = load_bat(bat_argument(o.bat_file, "bat"));
  if (o.slices > 0) bat = resample(bat, o.slices);
  const BeamTheory theory = parse_beam_theory(o.theory);
  const int available = vibrational_mode_count(bat.slices(), theory);
  if (o.count > available)
    throw InputError("--count " + std::to_string(o.count) + ": the bat has only " + std::to_string(available) +
                     " vibrational modes at " + std::to_string(bat.slices()) + " slices");
  if (const int most = practical_mode_count(available + 2) - 2; o.count > most)
    throw InputError("--count " + std::to_string(o.count) + ": more than is practical at " +
                     std::to_string(bat.slices()) + " slices (a solve's time grows as the slices times the modes "
                     "squared); expected at most " + std::to_string(most));
  // Only the modes printed: a partial solve, which stays fast at thousands of slices.
  const ModalBasis basis = compute_modes(bat, theory, ModeRequest::lowest(o.count));
  const MassProperties mp = mass_properties(bat);
  if (o.json) print_json(bat, mp, basis, o.count, o.shapes);
  else print_table(bat, mp, basis, o.count, o.units);
}

}  // namespace

void add_modes_command(CLI::App& app) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand("modes", "Normal modes and mass properties of a bat (N2000 Table II)");
  cmd->add_option("bat", options->bat_file, "bat file (TOML) or a shipped bat's name (r161, torpedo, ...)")->required();
  cmd->add_option("--theory", options->theory, "beam theory")
      ->check(CLI::IsMember({"timoshenko", "euler-bernoulli"}))
      ->capture_default_str();
  cmd->add_option("--slices", options->slices, "slice count N (default: the profile's own)")
      ->check(CLI::Range(min_slices, max_slices));
  cmd->add_option("--count", options->count, "vibrational modes to print")
      ->check(CLI::Range(1, 2 * max_slices))
      ->capture_default_str();
  CLI::Option* json = cmd->add_flag("--json", options->json, "print one JSON object (in SI units)");
  options->units.add_option(*cmd);
  cmd->add_flag("--shapes", options->shapes,
                "with --json: add the slice centres z_m and the shapes of the modes there (max |psi| = 1)")
      ->needs(json);
  cmd->callback([options] {
    options->units.check_text_output("modes", options->json);
    run_modes(*options);
  });
}

}  // namespace sweetspot::app
