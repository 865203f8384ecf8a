// The ball strikes where it is asked, not at the nearest slice centre (beam_layout.hpp): the
// identities hold off slice centres, v_f(z) is smooth on a fine grid, and the impact point's local
// compliance makes v_f converge in the slice count between centres.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "n2000_scenes.hpp"
#include "program.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/formulas.hpp"
#include "sweetspot/impact/impact.hpp"

using namespace sweetspot;

namespace {

const Bat& r161() {
  static const Bat bat = load_bat(source_path("studies/bats/r161.toml"));
  return bat;
}

const ModalBasis& r161_modes(int slices = 84) {
  static std::map<int, ModalBasis> cache;
  auto found = cache.find(slices);
  if (found == cache.end())
    found = cache.emplace(slices, compute_modes(resample(r161(), slices), BeamTheory::timoshenko)).first;
  return found->second;
}

// Points between slice centres (R161: centres at 0.005 + k 0.01), at the end half-slices and at
// the very ends.
const double off_centre[] = {0.0, 0.0031, 0.3013, 0.5, 0.6537, 0.7087, 0.8399, 0.84};

ImpactScene exact_scene(double z, int modes, double dt = 1e-6) {
  ImpactScene s = n2000_high_impact(z, modes);
  s.integrator.method = Method::exact;
  s.integrator.dt = dt;
  return s;
}

}  // namespace

TEST_CASE("The result's z is the z asked, not a slice centre", "[impact][point]") {
  for (double z : off_centre) {
    const ImpactResult r = simulate_impact(r161_modes(), exact_scene(z, 18, 10e-6));
    CHECK(r.z == z);
  }
}

TEST_CASE("Off slice centres a rigid bat gives the rigid-bat formula at the asked z (free and pivoted)",
          "[impact][point]") {
  const ModalBasis& basis = r161_modes();
  for (bool pivoted : {false, true})
    for (double z : off_centre)
      for (double e0 : {0.5, 1.0}) {
        ImpactScene s = exact_scene(z, 0);
        s.pivoted = pivoted;
        s.swing = {56, true, 0, 0.1537};
        s.ball.e0 = e0;
        s.rigid_comparison = s.van_zandt_comparison = true;
        const double arm = z - basis.z_cm, lever = z - s.swing.center, pivot_arm = s.swing.center - basis.z_cm;
        const double recoil = pivoted ? s.ball.mass * lever * lever /
                                            (basis.moment_of_inertia_cm + basis.mass * pivot_arm * pivot_arm)
                                      : s.ball.mass * (1 / basis.mass + arm * arm / basis.moment_of_inertia_cm);
        const double bat_speed = s.swing.omega * (z - s.swing.center);
        const ImpactResult r = simulate_impact(basis, s);
        INFO("pivoted " << pivoted << ", z " << z << ", e0 " << e0);
        REQUIRE(r.status == CollisionStatus::ok);
        const double rigid = rigid_exit_speed(e0, recoil, s.ball_speed, bat_speed);
        CHECK(r.vf == Approx(rigid).epsilon(1e-9));
        CHECK(r.vf_rigid == Approx(rigid).epsilon(1e-12));
        CHECK(r.vf_van_zandt == Approx(rigid).epsilon(1e-12));  // no vibrational mode to add
      }
}

TEST_CASE("Off slice centres a lossless ball gives the R_n formula and loses no energy", "[impact][point]") {
  for (double z : {0.6537, 0.7087, 0.7839, 0.8399}) {
    ImpactScene s = exact_scene(z, 18);
    s.ball.e0 = 1;
    s.integrator.record_force = true;
    const ImpactResult r = simulate_impact(r161_modes(), s);
    REQUIRE(r.status == CollisionStatus::ok);
    REQUIRE(r.contacts == 1);
    const SceneGeometry g = scene_geometry(s, r161_modes());
    CHECK(g.contact.residual_compliance > 0);  // the segment's own yield is in series with the ball
    const auto responses = mode_responses(g.contact, s.ball.mass, r.force);
    const double sum = std::accumulate(responses.begin(), responses.end(), 0.0);
    INFO("z " << z);
    CHECK(r.vf == Approx(lossless_exit_speed(sum, s.ball_speed, g.bat_speed)).epsilon(1e-6));
    CHECK(std::abs(r.energy.residual) < 1e-9 * r.energy.initial);
  }
}

TEST_CASE("Off slice centres the energy balance closes for every integrator, free and pivoted", "[impact][point]") {
  for (Method method : {Method::rk4, Method::exact, Method::dopri})
    for (bool pivoted : {false, true})
      for (double z : {0.5, 0.7087, 0.8399}) {
        ImpactScene s = exact_scene(z, 18, 2e-6);
        s.integrator.method = method;
        s.pivoted = pivoted;
        const ImpactResult r = simulate_impact(r161_modes(), s);
        INFO(to_string(method) << ", pivoted " << pivoted << ", z " << z);
        REQUIRE(r.status == CollisionStatus::ok);
        CHECK(std::abs(r.energy.residual) < 1e-7 * r.energy.initial);
        // The three integrators solve the same equations.
        ImpactScene reference = exact_scene(z, 18, 0.5e-6);
        reference.pivoted = pivoted;
        CHECK(r.vf == Approx(simulate_impact(r161_modes(), reference).vf).epsilon(1e-6));
      }
}

TEST_CASE("The history's ball compression peaks at u_max off slice centres", "[impact][point][histories]") {
  // The compression recorded is the ball's own: the bat's local yield c F is taken out of it.
  ImpactScene s = exact_scene(0.7087, 18);
  s.histories = true;
  s.history.step = 1e-6;
  s.history.window = 1.5e-3;
  const ImpactResult r = simulate_impact(r161_modes(), s);
  REQUIRE(r.status == CollisionStatus::ok);
  const auto& u = r.histories.compression;
  CHECK(*std::max_element(u.begin(), u.end()) == Approx(r.u_max).epsilon(1e-4));
}

TEST_CASE("v_f on a 2.5-mm grid is smooth: no staircase of slice centres", "[impact][point]") {
  // Snapped to slice centres (1 cm apart), four neighbouring points shared one v_f and the steps
  // between them were as large as v_f's change over a centimetre.
  std::vector<double> v;
  for (int k = 0; k <= 132; ++k) {
    const ImpactResult r = simulate_impact(r161_modes(), exact_scene(0.5 + 0.0025 * k, all_modes, 10e-6));
    REQUIRE(r.status == CollisionStatus::ok);
    v.push_back(r.vf);
  }
  double largest_step = 0, largest_curvature = 0;
  for (std::size_t k = 1; k < v.size(); ++k) {
    CHECK(v[k] != v[k - 1]);
    largest_step = std::max(largest_step, std::abs(v[k] - v[k - 1]));
    if (k + 1 < v.size()) largest_curvature = std::max(largest_curvature, std::abs(v[k + 1] - 2 * v[k] + v[k - 1]));
  }
  INFO("largest first difference " << largest_step << ", second " << largest_curvature);
  // A smooth v_f has second differences of order h^2 v'': a small fraction of the first ones.
  CHECK(largest_curvature < 0.1 * largest_step);
}

TEST_CASE("Between slice centres v_f converges in the slice count", "[impact][point][convergence]") {
  // 40 m/s on the bat swung at 51 rad/s about 9 cm, all modes, e0 = 0.5. At z = 0.500 (a slice
  // boundary of the 84-slice profile, halfway between centres at every N here) the values are
  // 21.4258 / 21.4247 / 21.4243 / 21.4241 m/s at N = 84 / 168 / 336 / 672: snapped to centres
  // they were 22.05 / 21.74 / 21.58 / 21.50, and interpolated without the local compliance they
  // converged at first order.
  for (double z : {0.5, 0.7}) {
    std::vector<double> v;
    for (int n : {168, 336, 672}) v.push_back(simulate_impact(r161_modes(n), exact_scene(z, all_modes, 5e-6)).vf);
    INFO("z " << z << ": " << v[0] << ", " << v[1] << ", " << v[2]);
    CHECK(std::abs(v[2] - v[0]) < 2e-4 * std::abs(v[2]));
    CHECK(std::abs(v[2] - v[1]) < std::abs(v[1] - v[0]));
  }
}
