// Hollow barrels (README "Hollow barrels", barrel_wall.hpp): the wall's hoop frequency against
// ring theory, exact identities of a ball in series with a wall spring, the energy balance with
// the wall, the beam-only limit of a thick wall, wooden bats untouched, and bad input refused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "barrel_scene.hpp"
#include "program.hpp"
#include "refusal.hpp"
#include "temp_dir.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/barrel_wall.hpp"
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/impact/formulas.hpp"
#include "sweetspot/impact/impact.hpp"
#include "text_edit.hpp"
#include "study_dir.hpp"

using namespace sweetspot;

namespace {

const std::string alloy_file = source_path("studies/bats/alloy_bbcor.toml");

BatDesign design_of(const std::string& file) {
  BatSource source;
  return load_bat_design(file, source);
}

// A uniform tube of the given diameters, 0.8 m long in 80 slices.
Bat tube(double outer, double inner, const Material& material) {
  Bat bat;
  bat.name = "tube";
  bat.length = 0.8;
  bat.material = material;
  bat.set_slices(std::vector<double>(80, outer), std::vector<double>(80, inner));
  return bat;
}

Material aluminium() {
  Material m;
  m.density = 2800, m.youngs_modulus = 7e10, m.shear_modulus = 2.6e10, m.shear_coefficient = 0.5;
  return m;
}

// The closed form of a thin ring's flexural modes (Soedel, Blevins), written for any n.
double ring_frequency_hz(int n, double youngs, double h, double density, double radius) {
  const double n2 = n * n;
  return std::sqrt(youngs * h * h * n2 * (n2 - 1) * (n2 - 1) / (12 * density * std::pow(radius, 4) * (n2 + 1))) /
         (2 * std::numbers::pi);
}

// The ball on a bat at rest (or an immovable body: no modes), integrated finely.
Collision hit(const ModalContact& body, const Ball& ball, double speed) {
  CollisionOptions options;
  options.method = Method::dopri;
  options.tolerance = 1e-12;
  options.dt = 1e-7;
  return collide(body, ball, speed, options);
}

Ball linear_ball(double e0) {
  Ball ball;
  ball.a = 1;
  ball.k1 = 2e6;  // N/m: about a baseball's secant stiffness at game speeds
  ball.e0 = e0;
  return ball;
}

double final_energy(const ModalContact& body, const Collision& c, const Ball& ball) {
  double e = 0.5 * ball.mass * c.ball_velocity * c.ball_velocity;
  for (int n = 0; n < body.count(); ++n) e += c.mode_energy(body, n);
  return e;
}

}  // namespace

TEST_CASE("Hoop frequency of a uniform thin tube is the ring's n = 2 closed form", "[barrel]") {
  for (const double h : {0.0015, 0.0025, 0.004}) {
    const double outer = 0.066, inner = outer - 2 * h, mid_radius = (outer + inner) / 4;
    Material m = aluminium();
    const ModalBasis basis = compute_modes(tube(outer, inner, m), BeamTheory::timoshenko, ModeRequest::rigid_only());
    REQUIRE(basis.wall_at(0.4).has_value());
    CHECK(basis.wall_at(0.4)->frequency_hz() ==
          Approx(ring_frequency_hz(2, m.youngs_modulus, h, m.density, mid_radius)).epsilon(0.01));
    // The hoop modulus, not the axial one, sets it (an orthotropic, composite wall).
    m.hoop_modulus = 2e10;
    const WallMode composite = wall_mode(outer, inner, m);
    CHECK(composite.frequency_hz() == Approx(ring_frequency_hz(2, 2e10, h, m.density, mid_radius)).epsilon(0.01));
    // A stiffer wall axially spreads the ovaling further (beta ~ (E_t / E_z)^(1/4)): stiffer, same frequency.
    m.hoop_modulus = m.youngs_modulus;
    m.youngs_modulus *= 16;
    const WallMode stiff_axially = wall_mode(outer, inner, m);
    CHECK(stiff_axially.stiffness == Approx(2 * basis.wall_at(0.4)->stiffness).epsilon(1e-12));
  }
}

TEST_CASE("A solid bat has no wall, and a hollow one's impact reports its hoop frequency", "[barrel]") {
  const ModalBasis wood = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko);
  CHECK(wood.wall.empty());
  const ImpactResult r = simulate_impact(wood, barrel_scene(0.72));
  CHECK(std::isnan(r.hoop_frequency));
  CHECK(r.energy.barrel == 0);

  const ModalBasis alloy = compute_modes(build_bat(design_of(alloy_file)), BeamTheory::timoshenko);
  const ImpactResult hollow = simulate_impact(alloy, barrel_scene(0.72));
  REQUIRE(hollow.status == CollisionStatus::ok);
  CHECK(hollow.hoop_frequency == alloy.wall_at(0.72)->frequency_hz());
  CHECK(hollow.energy.barrel > 0);
}

TEST_CASE("A hollow bat's exit speed is continuous across the slice boundaries of its taper", "[barrel]") {
  // The struck slice's own wall mode made v_f jump at every slice boundary of the alloy bat's
  // taper, by 0.09-0.36 m/s over 0.1 mm (45.9-50.9 cm), more than its total error estimate; along
  // the taper v_f's own slope moves it by about 0.013-0.015 m/s per 0.1 mm.
  const ModalBasis alloy = compute_modes(build_bat(design_of(alloy_file)), BeamTheory::timoshenko);
  double worst = 0, previous = std::nan("");
  for (int k = 0; k <= 600; ++k) {
    const ImpactResult r = simulate_impact(alloy, barrel_scene(0.455 + 1e-4 * k));
    REQUIRE(r.status == CollisionStatus::ok);
    if (k > 0) worst = std::max(worst, std::abs(r.vf - previous));
    previous = r.vf;
  }
  CHECK(worst < 0.02);
}

TEST_CASE("A wooden cup is no tube: a bore shorter than the ovaling's spread has no wall mode", "[barrel]") {
  // maple_271's cupped end: 1 in deep, half the barrel wide. Its wall would spread an ovaling over
  // more than its depth, so the beam alone takes the ball there, as on any wooden bat.
  const Bat maple = load_bat(source_path("studies/bats/maple_271.toml"));
  REQUIRE(maple.hollow());
  const ModalBasis basis = compute_modes(maple, BeamTheory::timoshenko, ModeRequest::rigid_only());
  for (const double z : {0.815, 0.825, 0.835}) CHECK_FALSE(basis.wall_at(z).has_value());
  const WallMode cup = wall_mode(maple.outer_diameter.back(), maple.inner_diameter.back(), maple.material);
  CHECK(cup.spread > 0.0254);
  // The alloy bat's bore runs its whole length, far longer than its barrel's spread (about 17 cm).
  const ModalBasis alloy = compute_modes(build_bat(design_of(alloy_file)), BeamTheory::timoshenko,
                                         ModeRequest::rigid_only());
  for (const double z : {0.6, 0.7, 0.8, 0.835}) CHECK(alloy.wall_at(z).has_value());
}

TEST_CASE("Wooden bats are bitwise what the beam alone gives, by every integrator", "[barrel]") {
  // A solid bat's basis has no wall: the same scene on a hollow bat's basis stripped of its wall
  // is the beam-only path, and a wooden bat must take exactly that path.
  const ModalBasis wood = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko);
  ModalBasis stripped = wood;
  stripped.wall.assign(wood.slices(), WallMode{});  // every slice solid, spelt out
  for (const Method method : {Method::rk4, Method::exact, Method::dopri}) {
    ImpactScene scene = barrel_scene(0.7);
    scene.integrator.method = method;
    scene.integrator.dt = default_step(method);
    const ImpactResult a = simulate_impact(wood, scene), b = simulate_impact(stripped, scene);
    CHECK(a.vf == b.vf);
    CHECK(a.energy.vibration == b.energy.vibration);
    CHECK(a.energy.residual == b.energy.residual);
    CHECK(a.mode_energy == b.mode_energy);
    const SceneGeometry g = scene_geometry(scene, wood);
    CHECK(g.wall == -1);
    CHECK(g.contact.count() == static_cast<int>(g.kept.size()));
  }
}

TEST_CASE("A linear lossless ball on a massless wall spring and a rigid bat conserves energy exactly", "[barrel]") {
  // Rigid free bat (mass M, inertia I, struck at arm d from the CM): its two rigid modes. The
  // wall spring without mass is a series compliance 1 / k_w.
  const double M = 0.9, I = 0.05, d = 0.15, k_wall = 5e6;
  ModalContact bat;
  bat.omega = Eigen::Vector2d(0, 0);
  bat.psi = Eigen::Vector2d(1 / std::sqrt(M), d / std::sqrt(I));
  bat.velocity0 = Eigen::Vector2d::Zero();
  bat.residual_compliance = 1 / k_wall;
  const Ball ball = linear_ball(1);
  const double v = 40;
  const Collision c = hit(bat, ball, v);
  REQUIRE(c.status == CollisionStatus::ok);
  const double initial = 0.5 * ball.mass * v * v;
  CHECK(c.dissipated == 0);
  CHECK(final_energy(bat, c, ball) == Approx(initial).epsilon(1e-9));
  // Two lossless massless springs return everything: the rigid bat's e0 = 1 exit speed.
  const double recoil = ball.mass * (1 / M + d * d / I);
  CHECK(c.ball_velocity == Approx(rigid_exit_speed(1, recoil, v, 0)).epsilon(1e-9));
}

TEST_CASE("A linear lossy ball in series with a lossless wall spring returns e_eff from energy sharing", "[barrel]") {
  // The same force F runs through both springs: at maximum compression the ball holds F^2 / 2 k1,
  // the wall F^2 / 2 k_w, together the ball's initial 1/2 m v^2 (an immovable bat). The ball
  // gives back e0^2 of its share (its loop, physics.md §3), the massless lossless wall all of
  // its own, so 1/2 m vf^2 = (e0^2 / k1 + 1 / k_w) F^2 / 2 and
  //   e_eff^2 = (e0^2 / k1 + 1 / k_w) / (1 / k1 + 1 / k_w) = (e0^2 k_w + k1) / (k_w + k1).
  for (const double e0 : {0.5, 0.7}) {
    for (const double k_wall : {5e5, 2e6, 2e7}) {
      const Ball ball = linear_ball(e0);
      ModalContact wall;  // immovable: no modes, only the wall's compliance
      wall.omega = wall.psi = wall.velocity0 = Eigen::VectorXd(0);
      wall.residual_compliance = 1 / k_wall;
      const Collision c = hit(wall, ball, 30);
      REQUIRE(c.status == CollisionStatus::ok);
      const double e_eff = std::sqrt((e0 * e0 * k_wall + ball.k1) / (k_wall + ball.k1));
      CHECK(c.ball_velocity / 30 == Approx(e_eff).epsilon(1e-6));
      // The wall as a mode of small mass (the integrators' path) tends to the same.
      ModalContact light = wall;
      const double m_wall = 1e-5;
      light.residual_compliance = 0;
      light.omega = Eigen::VectorXd::Constant(1, std::sqrt(k_wall / m_wall));
      light.psi = Eigen::VectorXd::Constant(1, 1 / std::sqrt(m_wall));
      light.velocity0 = Eigen::VectorXd::Zero(1);
      CHECK(hit(light, ball, 30).ball_velocity / 30 == Approx(e_eff).epsilon(2e-3));
    }
  }
}

TEST_CASE("A wall on an immovable bat: COR is not monotonic in the hoop frequency", "[barrel]") {
  // The ball (N2000's, 40 m/s) on a wall mode of mass m_w over an immovable bat: a very stiff wall
  // is the rigid wall (COR e0); a softer one stores energy the ball would have lost and gives it
  // back (COR above e0); a wall whose hoop period nears the collision time or exceeds it is still
  // moving when the ball leaves and keeps what it took, so the COR falls again below some
  // frequency: a maximum between the ends (README "Hollow barrels", the physics checks).
  const Ball ball;
  for (const double m_wall : {0.02, 0.15}) {
    std::vector<double> cor;
    for (const double f : {200.0, 400.0, 700.0, 1000.0, 1500.0, 2000.0, 3000.0, 5000.0, 10000.0, 30000.0}) {
      ModalContact wall;
      wall.omega = Eigen::VectorXd::Constant(1, 2 * std::numbers::pi * f);
      wall.psi = Eigen::VectorXd::Constant(1, 1 / std::sqrt(m_wall));
      wall.velocity0 = Eigen::VectorXd::Zero(1);
      const Collision c = collide(wall, ball, 40, CollisionOptions{});
      REQUIRE(c.status == CollisionStatus::ok);
      cor.push_back(c.ball_velocity / 40);
    }
    const auto peak = std::max_element(cor.begin(), cor.end());
    INFO("m_w = " << m_wall);
    CHECK(peak != cor.begin());
    CHECK(peak != cor.end() - 1);
    CHECK(*peak > ball.e0 + 0.1);
    CHECK(cor.back() == Approx(ball.e0).epsilon(0.01));
  }
}

TEST_CASE("The energy balance closes with the wall at default settings", "[barrel]") {
  const ModalBasis alloy = compute_modes(build_bat(design_of(alloy_file)), BeamTheory::timoshenko);
  for (const double z : {0.62, 0.7, 0.78}) {
    for (const bool pivoted : {false, true}) {
      ImpactScene scene = barrel_scene(z);
      if (pivoted) scene = rig_scene(RigSettings{Ball{}, 60, rig_pivot, auto_modes, {}}, z);
      const ImpactResult r = simulate_impact(alloy, scene);
      REQUIRE(r.status == CollisionStatus::ok);
      CHECK(r.energy.barrel > 0);
      CHECK(r.energy.damped > 0);  // the default loss factor, aluminium's 1e-4
      CHECK(std::abs(r.energy.residual) <= 1e-6 * r.energy.initial);
    }
  }
}

TEST_CASE("rk4, exact and dopri integrate the wall mode alike", "[barrel]") {
  const ModalBasis alloy = compute_modes(build_bat(design_of(alloy_file)), BeamTheory::timoshenko);
  ImpactScene scene = barrel_scene(0.68);
  scene.step_accuracy = 1e-7;  // each method's step (or tolerance) chosen for the pulse and the wall
  double vf[3];
  int i = 0;
  for (const Method method : {Method::rk4, Method::exact, Method::dopri}) {
    scene.integrator.method = method;
    const ImpactResult r = simulate_impact(alloy, scene);
    REQUIRE(r.status == CollisionStatus::ok);
    CHECK(r.energy.barrel > 0);
    CHECK(std::abs(r.energy.residual) <= 1e-6 * r.energy.initial);
    vf[i++] = r.vf;
  }
  CHECK(vf[0] == Approx(vf[1]).epsilon(1e-6));
  CHECK(vf[2] == Approx(vf[1]).epsilon(1e-6));
}

TEST_CASE("A wall far stiffer than the pulse gives the beam-only result within 0.5 %", "[barrel]") {
  BatDesign thick = design_of(alloy_file);
  set_design_parameter(thick, "wall_thickness", 0.011);
  const ModalBasis basis = compute_modes(build_bat(thick), BeamTheory::timoshenko);
  ModalBasis beam_only = basis;
  beam_only.wall.clear();
  for (const double z : {0.65, 0.72}) {
    const ImpactResult with = simulate_impact(basis, barrel_scene(z));
    const ImpactResult without = simulate_impact(beam_only, barrel_scene(z));
    REQUIRE(with.status == CollisionStatus::ok);
    CHECK(with.hoop_frequency * with.collision_time > 5);  // far above 1 / (collision time)
    CHECK(with.vf == Approx(without.vf).epsilon(0.005));
  }
}

TEST_CASE("A hollow alloy bat with a realistic wall certifies above the wooden R161", "[barrel]") {
  CertifyOptions options;
  const Certification alloy = certify(design_of(alloy_file), find_standard("bbcor"), options);
  const Certification wood = certify(design_of(source_path("studies/bats/r161.toml")), find_standard("bbcor"), options);
  CHECK(alloy.measure > wood.measure);
  // Above the ball's own e0 too, which a solid bat reaches only at the node (README "Certification").
  CHECK(alloy.measure > alloy.standard.ball.e0);
}

TEST_CASE("Bad wall input is refused with the file, key and value", "[barrel]") {
  const std::string text = file_text(alloy_file);
  const struct {
    std::string from, to, key, value, expected;
  } cases[] = {
      {"shear_coefficient = 0.5", "shear_coefficient = 0.5\nhoop_modulus = 0", "material.hoop_modulus", "0", "positive"},
      {"shear_coefficient = 0.5", "shear_coefficient = 0.5\nhoop_modulus = -2e10", "material.hoop_modulus", "-2e+10",
       "positive"},
      {"shear_coefficient = 0.5", "shear_coefficient = 0.5\nwall_loss_factor = 1", "material.wall_loss_factor", "1",
       "[0, 1)"},
      {"shear_coefficient = 0.5", "shear_coefficient = 0.5\nwall_loss_factor = -0.01", "material.wall_loss_factor",
       "-0.01", "[0, 1)"},
      {"youngs_modulus = 7.0e10", "youngs_modulus = -7.0e10", "material.youngs_modulus", "-7", "positive"},
      {"shear_coefficient = 0.5", "shear_coefficient = 0.5\nwall_loss_factor = -0.1", "material.wall_loss_factor",
       "-0.1", "[0, 1)"},
      {"shear_coefficient = 0.5", "shear_coefficient = 0.5\nwall_loss_factor = 1.5", "material.wall_loss_factor",
       "1.5", "[0, 1)"},
      {"wall_thickness = 0.0026", "wall_thickness = 0.02", "dimensions.wall_thickness", "0.02", "radius"},
      {"wall_thickness = 0.0026", "wall_thickness = -0.0026", "dimensions.wall_thickness", "-0.0026", "positive"},
      {"wall_thickness = 0.0026", "wall_thickness = 0", "dimensions.wall_thickness", "0", "positive"},
      // In the documented range, but calibrated so soft that the wall is no tube: refused on
      // reading, naming the file (it was a bare "[barrel]" line when the modes were solved).
      {"wall_thickness = 0.0026", "wall_thickness = 0.0026\n[barrel]\ncompression = 10", "compression", "10",
       "expected a stiffer barrel"},
      // ... or so stiff that its hoop modulus is no material's (past 1e12 Pa, the moduli's bound).
      {"wall_thickness = 0.0026", "wall_thickness = 0.0026\n[barrel]\nhoop_frequency = 20000", "hoop_frequency",
       "20000", "is no material's"},
  };
  for (const auto& c : cases) {
    DYNAMIC_SECTION(c.to) {
      const TempDir dir;
      const auto file = dir.write("bat.toml", with(text, c.from, c.to));
      require_refused(run_program("modes '" + file.string() + "'"), {"bat.toml", c.key, c.value, c.expected});
    }
  }
}
