// Time histories of an impact (N2000 Figs. 9, 13-15), checked against the collision itself and
// against the paper's claims about the handle.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

#include "n2000_scenes.hpp"
#include "program.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/histories.hpp"
#include "sweetspot/impact/impact.hpp"

using namespace sweetspot;

namespace {

const ModalBasis& r161() {
  static const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko);
  return basis;
}

// N2000's high-impact swing (Figs. 13-15) or the low-impact scene (Fig. 9), exact stepping.
ImpactScene scene(double z, bool high) {
  ImpactScene s = high ? n2000_high_impact(z) : n2000_low_impact(z);
  s.integrator.method = Method::exact;
  s.integrator.record_force = true;
  return s;
}

struct Run {
  ImpactResult result;
  Histories histories;
};

Run run(const ImpactScene& s, std::vector<double> probes, double window = 4e-3, double step = 5e-6) {
  const ImpactResult r = simulate_impact(r161(), s);
  REQUIRE(r.status == CollisionStatus::ok);
  return {r, impact_histories(r161(), scene_geometry(s, r161()), s.ball, s.ball_speed, r.force, {probes, window, step})};
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// |sum x(t) e^(-i 2 pi f t)|: the strength of frequency f in a sampled history.
double amplitude_at(const std::vector<double>& x, double step, double f) {
  std::complex<double> sum = 0;
  for (std::size_t j = 0; j < x.size(); ++j) sum += x[j] * std::exp(std::complex<double>(0, -2 * std::numbers::pi * f * j * step));
  return std::abs(sum);
}

}  // namespace

TEST_CASE("Histories reproduce the collision: the ball leaves at vf, the force is the collision's", "[histories]") {
  const Run r = run(scene(0.705, true), {0.13});
  const Histories& h = r.histories;
  const std::size_t last = h.time.size() - 1;
  const double ball_velocity = (h.ball_position[last] - h.ball_position[last - 1]) / (h.time[last] - h.time[last - 1]);
  CHECK(ball_velocity == Approx(r.result.vf).epsilon(1e-6));
  CHECK(*std::max_element(h.force.begin(), h.force.end()) == Approx(r.result.peak_force).epsilon(1e-3));
  CHECK(h.compression.front() == 0.0);
  CHECK(*std::max_element(h.compression.begin(), h.compression.end()) == Approx(r.result.u_max).epsilon(1e-3));
  // The probe starts at rest in its own frame.
  CHECK(h.probes[0].displacement.front() == 0.0);
  CHECK(h.probes[0].velocity.front() == Approx(0).margin(1e-12));
}

TEST_CASE("The handle: 13 cm has almost no rigid part for the 68-cm impact, 6 cm recoils the other way", "[histories]") {
  // Fig. 13: 13 cm is near the centre of percussion of a 68-cm impact (z_cm - r_g^2 / (z - z_cm)
  // = 13.8 cm for this profile), so its rigid motion is a small fraction of its neighbours'.
  const Run r = run(scene(0.685, true), {0.06, 0.13, 0.20});
  const auto rigid = [](const ProbeHistory& p) {
    std::vector<double> d;
    for (std::size_t j = 0; j < p.displacement.size(); ++j) d.push_back(p.displacement[j] - p.vibration_displacement[j]);
    return d;
  };
  const auto at6 = rigid(r.histories.probes[0]), at13 = rigid(r.histories.probes[1]), at20 = rigid(r.histories.probes[2]);
  INFO("rigid displacement at the end: 6 cm " << at6.back() << ", 13 cm " << at13.back() << ", 20 cm " << at20.back());
  CHECK(max_abs(at13) < 0.15 * max_abs(at6));
  CHECK(max_abs(at13) < 0.15 * max_abs(at20));
  CHECK(at6.back() * at20.back() < 0);  // the two sides of the centre of percussion move apart
}

TEST_CASE("The handle starts to move only after most of the impulse is delivered (Fig. 15)", "[histories]") {
  const Run r = run(scene(0.685, true), {0.13}, 3e-3, 2e-6);
  const std::vector<double>& v = r.histories.probes[0].velocity;
  const double peak = max_abs(v);
  const auto first = std::find_if(v.begin(), v.end(), [&](double x) { return std::abs(x) > 0.05 * peak; });
  const double onset = r.histories.time[first - v.begin()];
  INFO("velocity at 13 cm passes 5 % of its maximum at " << onset * 1e3 << " ms; 99 % impulse at "
                                                          << r.result.collision_time * 1e3 << " ms");
  CHECK(onset >= 0.4e-3);
  CHECK(onset <= 0.8e-3);
  CHECK(impulse_time(r.result.force, 0.9) < onset);
}

TEST_CASE("Vibration at 13 cm is smallest for the impact at 71 cm of 61, 71, 81 (Fig. 14)", "[histories]") {
  std::vector<double> amplitude;
  for (double z : {0.615, 0.715, 0.815}) amplitude.push_back(max_abs(run(scene(z, true), {0.13}).histories.probes[0].vibration_displacement));
  INFO("vibration amplitude at 13 cm: " << amplitude[0] << ", " << amplitude[1] << ", " << amplitude[2] << " m");
  CHECK(amplitude[1] < amplitude[0]);
  CHECK(amplitude[1] < amplitude[2]);
}

TEST_CASE("At 6 and 16 cm an impact at 72 cm shows modes 1 and 3, not mode 2 (Fig. 9)", "[histories]") {
  // The impact is at this profile's node of mode 2 (71.5 cm; N2000's is at 72), so mode 2 is
  // hardly excited; mode 1 dominates and mode 3, weighted by omega^2 in the acceleration, shows.
  const auto f = r161().vibrational_frequencies_hz();
  const Run r = run(scene(0.715, false), {0.06, 0.16}, 20e-3, 20e-6);
  // 6 cm sees mode 1 most; 16 cm, near mode 1's node (16.6 cm), sees mode 3.
  std::vector<std::array<double, 3>> spectrum;
  for (const ProbeHistory& p : r.histories.probes) {
    spectrum.push_back({amplitude_at(p.acceleration, 20e-6, f[0]), amplitude_at(p.acceleration, 20e-6, f[1]),
                        amplitude_at(p.acceleration, 20e-6, f[2])});
    const auto& m = spectrum.back();
    INFO("acceleration spectrum at modes 1, 2, 3: " << m[0] << ", " << m[1] << ", " << m[2]);
    CHECK(m[1] < 0.2 * std::max(m[0], m[2]));
  }
  CHECK(spectrum[0][0] > spectrum[0][2]);
  CHECK(spectrum[1][2] > spectrum[1][0]);
}
