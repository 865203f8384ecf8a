// The ball's contact patch on a hollow barrel (barrel_wall.hpp, README "Hollow barrels"): the
// patch factor's limits and its closed theta integral against a brute-force quadrature of its
// definition, the harmonic ladder against the n = 2 wall mode, the sums' convergence, the energy
// balance with the patch by every integrator, the point load as the model before it, the
// effective-compression fraction against a collision's force profile, the calibration, and the
// [barrel] table's refusals.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "barrel_scene.hpp"
#include "program.hpp"
#include "refusal.hpp"
#include "temp_dir.hpp"
#include "study_dir.hpp"
#include "text_edit.hpp"
#include "sweetspot/bat/barrel_wall.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/impact/bat_test_rig.hpp"
#include "sweetspot/impact/impact.hpp"

using namespace sweetspot;

namespace {

const std::string alloy_file = source_path("studies/bats/alloy_bbcor.toml");

Bat alloy_bat(const BarrelCalibration& barrel = {}) {
  BatSource source;
  BatDesign design = load_bat_design(alloy_file, source);
  design.material.barrel = barrel;
  return build_bat(design);
}

// The alloy bat's barrel section (2 5/8 in, 2.6 mm wall, E = 70 GPa).
WallMode alloy_section(WallLoad load = WallLoad::patch) {
  Material m;
  m.density = 2800, m.youngs_modulus = 7e10, m.shear_modulus = 2.6e10, m.shear_coefficient = 0.5;
  m.barrel.load = load;
  return wall_mode(0.066675, 0.066675 - 2 * 0.0026, m);
}

const double ball_radius = Ball{}.radius;

// The rig's hit at z, the ball at `speed`, the rig's defaults otherwise.
ImpactScene rig_at(double speed, double z) {
  RigSettings rig;
  rig.ball_speed = speed;
  return rig_scene(rig, z);
}

// phi_n by its definition: the mean of cos(n theta) W_n(z) over the ellipse (z/A)^2 + (theta/T)^2
// < 1 weighted by sqrt(1 - (z/A)^2 - (theta/T)^2), a midpoint rule on a fine grid.
double brute_phi(int n, double beta, const ContactPatch& p) {
  const int cells = 1200;
  double num = 0, den = 0;
  for (int i = 0; i < cells; ++i) {
    const double x = -1 + (i + 0.5) * 2.0 / cells;
    for (int j = 0; j < cells; ++j) {
      const double y = -1 + (j + 0.5) * 2.0 / cells;
      const double r2 = x * x + y * y;
      if (r2 >= 1) continue;
      const double w = std::sqrt(1 - r2), z = std::abs(x * p.half_length), bz = beta * z;
      num += w * std::cos(n * y * p.half_angle) * std::exp(-bz) * (std::cos(bz) + std::sin(bz));
      den += w;
    }
  }
  return num / den;
}

}  // namespace

TEST_CASE("A patch of zero size is a point: phi_n = 1 exactly, and a vanishing patch tends to it", "[barrel][patch]") {
  const WallMode wall = alloy_section();
  CHECK(contact_patch(ball_radius, wall.outer_radius, 0).half_length == 0);
  for (const int n : {2, 3, 7, 50, 200}) {
    const double beta = shell_harmonic(wall, n).beta;
    CHECK(patch_factor(n, beta, contact_patch(ball_radius, wall.outer_radius, 0)) == 1);
    CHECK(patch_factor(n, beta, ContactPatch{}) == 1);
  }
  // A nanometre's compression: phi_2 within 1e-6 of the point's.
  CHECK(patch_factor(2, shell_harmonic(wall, 2).beta, contact_patch(ball_radius, wall.outer_radius, 1e-9)) ==
        Approx(1).epsilon(1e-6));
  // The point load: phi_2 = 1 and no other harmonic, whatever the compression.
  const PatchLoad point = patch_load(alloy_section(WallLoad::point), ball_radius, 0.012);
  CHECK(point.phi == 1);
  CHECK(point.compliance == 0);
}

TEST_CASE("The patch's geometry: the overlap ellipse of ball and barrel", "[barrel][patch]") {
  const double rc = 0.0333375, delta = 0.01;
  const ContactPatch p = contact_patch(ball_radius, rc, delta);
  CHECK(p.half_length == Approx(std::sqrt(2 * ball_radius * delta)).epsilon(1e-14));
  const double rt = ball_radius * rc / (ball_radius + rc);
  CHECK(p.half_angle == Approx(std::sqrt(2 * rt * delta) / rc).epsilon(1e-14));
  CHECK(contact_patch(ball_radius, rc, 1.0).half_angle == std::numbers::pi / 2);  // capped
}

TEST_CASE("phi_n's closed arc integral matches a brute-force quadrature of its definition", "[barrel][patch]") {
  const WallMode wall = alloy_section();
  for (const double delta : {0.003, 0.012}) {
    const ContactPatch p = contact_patch(ball_radius, wall.outer_radius, delta);
    for (const int n : {2, 3, 5, 9}) {
      const double beta = shell_harmonic(wall, n).beta;
      INFO("delta " << delta << ", n " << n);
      CHECK(patch_factor(n, beta, p) == Approx(brute_phi(n, beta, p)).margin(2e-5));
    }
  }
}

TEST_CASE("phi_2 and the other harmonics' compliance fall as the ball compresses further", "[barrel][patch]") {
  const WallMode wall = alloy_section();
  PatchLoad previous = patch_load(wall, ball_radius, 0);
  CHECK(previous.phi == 1);
  for (double delta = 0.0005; delta <= 0.02; delta += 0.0005) {
    const PatchLoad load = patch_load(wall, ball_radius, delta);
    INFO("delta " << delta);
    CHECK(load.phi < previous.phi);
    CHECK(load.phi > 0);
    CHECK(load.compliance < previous.compliance);
    previous = load;
  }
}

TEST_CASE("The harmonic ladder's n = 2 is the wall mode's beam on an elastic foundation", "[barrel][patch]") {
  for (const double h : {0.0015, 0.0026, 0.006}) {
    Material m;
    m.density = 1600, m.youngs_modulus = 9e10, m.hoop_modulus = 4e10, m.shear_modulus = 5e9;
    const double outer = 0.066675, inner = outer - 2 * h, a = (outer + inner) / 4;
    const WallMode w = wall_mode(outer, inner, m);
    const ShellHarmonic s = shell_harmonic(w, 2);
    // The semi-membrane formulas at n = 2 (barrel_wall.hpp): k_f = 3 pi E_t h^3 / (4 a^3),
    // EI = pi E_z h a^3 / 16, beta = 2 / spread, and the point compliance 1 / k_w.
    CHECK(s.foundation == Approx(3 * std::numbers::pi * 4e10 * h * h * h / (4 * a * a * a)).epsilon(1e-12));
    CHECK(s.bending == Approx(std::numbers::pi * 9e10 * h * a * a * a / 16).epsilon(1e-12));
    CHECK(s.beta == Approx(2 / w.spread).epsilon(1e-12));
    CHECK(s.foundation == Approx(w.stiffness * s.beta / 2).epsilon(1e-12));
    CHECK(s.compliance == Approx(1 / w.stiffness).epsilon(1e-12));
  }
}

TEST_CASE("The harmonic sums converge: truncation at n = 200 and at 400 agree", "[barrel][patch]") {
  const WallMode wall = alloy_section();
  for (const double delta : {0.001, 0.005, 0.015}) {
    const ContactPatch p = contact_patch(ball_radius, wall.outer_radius, delta);
    INFO("delta " << delta);
    CHECK(harmonics_compliance(wall, p, 200) == Approx(harmonics_compliance(wall, p, 400)).epsilon(1e-6));
  }
  CHECK(barrel_compression(wall, compression_approach, default_platen_width, 200) ==
        Approx(barrel_compression(wall, compression_approach, default_platen_width, 400)).epsilon(1e-6));
  // Two opposite point loads through the n = 2 mode alone would see k_w / 4; the other even
  // harmonics only add compliance, a platen's width only takes it away from n = 2.
  CHECK(barrel_compression(wall, compression_approach, 0) < wall.stiffness / 4 * compression_approach);
}

TEST_CASE("The effective compression's fraction is the force-weighted mean compression of a rigid-wall hit",
          "[barrel][patch]") {
  for (const double e0 : {0.5, 0.8}) {
    Ball ball;
    ball.e0 = e0;
    CollisionOptions options;
    options.method = Method::dopri;
    options.tolerance = 1e-12;
    options.dt = 1e-8;
    options.record_force = true;
    ModalContact immovable;  // no modes: a rigid, immovable wall
    const Collision c = collide(immovable, ball, 40, options);
    REQUIRE(c.status == CollisionStatus::ok);
    // The ball's compression from its force law, branch by the force's rate: rising on compression.
    const double fm = ball.k1 * std::pow(c.u_max, ball.a), b = ball.expansion_exponent();
    const auto u = [&](const ForceSample& s) {
      return s.rate >= 0 ? std::pow(s.force / ball.k1, 1 / ball.a) : c.u_max * std::pow(s.force / fm, 1 / b);
    };
    double fu = 0, f = 0;
    for (std::size_t i = 1; i < c.force.size(); ++i) {
      const double dt = c.force[i].t - c.force[i - 1].t;
      fu += dt / 2 * (c.force[i].force * u(c.force[i]) + c.force[i - 1].force * u(c.force[i - 1]));
      f += dt / 2 * (c.force[i].force + c.force[i - 1].force);
    }
    INFO("e0 " << e0);
    CHECK(mean_compression_fraction(ball) == Approx(fu / f / c.u_max).epsilon(1e-4));
  }
}

TEST_CASE("The energy balance closes with a patch-loaded wall, by every integrator", "[barrel][patch]") {
  const ModalBasis alloy = compute_modes(alloy_bat(), BeamTheory::timoshenko);
  for (const Method method : {Method::exact, Method::rk4, Method::dopri}) {
    for (const double z : {0.62, 0.7, 0.78}) {
      for (const bool pivoted : {false, true}) {
        ImpactScene scene = pivoted ? rig_at(60, z) : barrel_scene(z);
        scene.integrator.method = method;
        scene.integrator.dt = default_step(method);
        const ImpactResult r = simulate_impact(alloy, scene);
        INFO(to_string(method) << " z " << z << (pivoted ? " pivoted" : " free"));
        REQUIRE(r.status == CollisionStatus::ok);
        CHECK(r.barrel_phi < 1);
        CHECK(r.barrel_phi > 0.5);
        CHECK(r.barrel_compliance > 0);
        CHECK(r.energy.barrel > 0);
        CHECK(std::abs(r.energy.residual) <= 1e-6 * r.energy.initial);
      }
    }
  }
}

TEST_CASE("The patch's effective compression is self-consistent: the last run's u_max gives its phi_2",
          "[barrel][patch]") {
  const Bat bat = alloy_bat();
  const ModalBasis alloy = compute_modes(bat, BeamTheory::timoshenko);
  for (const double z : {0.64, 0.72}) {
    const ImpactResult r = simulate_impact(alloy, rig_at(60.8, z));
    REQUIRE(r.status == CollisionStatus::ok);
    const PatchLoad load = patch_load(*alloy.wall_at(z), Ball{}.radius, mean_compression_fraction(Ball{}) * r.u_max);
    CHECK(std::abs(load.phi - r.barrel_phi) < 1e-4);
    CHECK(patch_load(*alloy.wall_at(z), Ball{}.radius, r.barrel_compression_eff).phi == r.barrel_phi);
  }
}

TEST_CASE("A point-loaded wall is the model before the patch: the scene's contact as it is, collided once",
          "[barrel][patch]") {
  BarrelCalibration point;
  point.load = WallLoad::point;
  const ModalBasis basis = compute_modes(alloy_bat(point), BeamTheory::timoshenko);
  const ModalBasis patched = compute_modes(alloy_bat(), BeamTheory::timoshenko);
  for (const Method method : {Method::exact, Method::rk4, Method::dopri}) {
    for (const double z : {0.62, 0.7, 0.78}) {
      ImpactScene scene = barrel_scene(z);
      scene.integrator.method = method;
      scene.integrator.dt = default_step(method);
      const ImpactResult r = simulate_impact(basis, scene);
      REQUIRE(r.status == CollisionStatus::ok);
      // Without any patch machinery: the wall mode at 1 / sqrt(m_w), no added compliance.
      const SceneGeometry g = scene_geometry(scene, basis);
      CHECK(g.contact.psi(g.wall) == 1 / std::sqrt(basis.wall_at(z)->mass));
      const Collision c = collide(g.contact, scene.ball, scene.ball_speed, scene.integrator);
      CHECK(r.vf == c.ball_velocity);
      CHECK(r.barrel_phi == 1);
      CHECK(r.barrel_compliance == 0);
      // The same wall patch-loaded is another model: another exit speed.
      CHECK(simulate_impact(patched, scene).vf != r.vf);
    }
  }
}

TEST_CASE("Calibration reproduces the measured hoop frequency and barrel compression", "[barrel][patch]") {
  const Bat plain = alloy_bat();
  const std::vector<WallMode> model = barrel_wall(plain);
  const int ref = barrel_reference_slice(plain, model);
  REQUIRE(ref >= 0);
  // The reference: largest outer diameter, nearest 6 in from the barrel end.
  CHECK(std::abs(plain.slice_center(ref) - (plain.length - 0.1524)) <= plain.slice_thickness() / 2 + 1e-12);

  BarrelCalibration frequency;
  frequency.hoop_frequency = 1200;
  std::vector<WallMode> w = barrel_wall(alloy_bat(frequency));
  CHECK(w[ref].frequency_hz() == Approx(1200).epsilon(1e-9));
  // E_t scaled by (f / f_model)^2: the whole barrel's frequencies by the same ratio.
  CHECK(w[ref].hoop_modulus == Approx(7e10 * std::pow(1200 / model[ref].frequency_hz(), 2)).epsilon(1e-12));

  BarrelCalibration compression;
  compression.compression = 2000;
  w = barrel_wall(alloy_bat(compression));
  CHECK(barrel_compression(w[ref]) == Approx(2000).epsilon(1e-9));

  BarrelCalibration both;
  both.compression = 2000, both.hoop_frequency = 1200;
  const std::vector<WallMode> wb = barrel_wall(alloy_bat(both));
  CHECK(barrel_compression(wb[ref]) == Approx(2000).epsilon(1e-9));
  CHECK(wb[ref].frequency_hz() == Approx(1200).epsilon(1e-9));
  CHECK(wb[ref].stiffness == w[ref].stiffness);  // the stiffness is the compression's; the mass the frequency's
  CHECK(wb[ref].mass == Approx(wb[ref].stiffness / std::pow(2 * std::numbers::pi * 1200, 2)).epsilon(1e-12));
}

TEST_CASE("The [barrel] table: calibration reported, point load bitwise, bad input refused", "[barrel][patch]") {
  const std::string text = file_text(alloy_file);
  {
    const TempDir dir;
    const auto file = dir.write("bat.toml", text + "\n[barrel]\nhoop_frequency = 1300\ncompression = 2500\n");
    const ProgramRun run = run_program("certify '" + file.string() + "'");
    CHECK(run.exit_code == 3);  // this lively wall fails BBCOR: checked, and failed
    CHECK_THAT(run.output, Catch::Contains("calibrated wall to hoop_frequency 1300 Hz and compression 2500 N"));
    const ProgramRun json = run_program("certify --json '" + file.string() + "'");
    CHECK_THAT(json.output, Catch::Contains("\"hoop_frequency_measured\": 1300"));
    CHECK_THAT(json.output, Catch::Contains("\"compression_measured\": 2500"));
    const ProgramRun impact = run_program("impact --json --z 0.7 --ball-speed 40 --cm-speed 0 --bat '" + file.string() + "'");
    CHECK_THAT(impact.output, Catch::Contains("\"calibrated\": true"));
  }
  const struct {
    std::string table, key, value, expected;
  } cases[] = {
      {"hoop_frequency = 0", "barrel.hoop_frequency", "0", "100 to 20000"},
      {"hoop_frequency = -1500", "barrel.hoop_frequency", "-1500", "100 to 20000"},
      {"hoop_frequency = nan", "barrel.hoop_frequency", "nan", "100 to 20000"},
      {"hoop_frequency = inf", "barrel.hoop_frequency", "inf", "100 to 20000"},
      {"hoop_frequency = 50", "barrel.hoop_frequency", "50", "100 to 20000"},
      {"hoop_frequency = 30000", "barrel.hoop_frequency", "30000", "100 to 20000"},
      {"compression = 0", "barrel.compression", "0", "10 to 1000000"},
      {"compression = -3000", "barrel.compression", "-3000", "10 to 1000000"},
      {"compression = 5", "barrel.compression", "5", "10 to 1000000"},
      {"compression = 2e6", "barrel.compression", "2000000", "10 to 1000000"},
      {"compression = nan", "barrel.compression", "nan", "10 to 1000000"},
      {"compression = \"stiff\"", "barrel.compression", "stiff", "10 to 1000000"},
      {"load = \"area\"", "barrel.load", "area", "'patch' or 'point'"},
      {"stiffness = 3", "barrel.stiffness", "3", "expected one of"},
  };
  for (const auto& c : cases) {
    DYNAMIC_SECTION(c.table) {
      const TempDir dir;
      const auto file = dir.write("bat.toml", text + "\n[barrel]\n" + c.table + "\n");
      require_refused(run_program("certify '" + file.string() + "'"), {"bat.toml", c.key, c.value, c.expected});
    }
  }
  SECTION("a [barrel] table on a solid bat") {
    const TempDir dir;
    const auto file = dir.write("bat.toml", file_text(source_path("studies/bats/maple_271.toml")) +
                                                "\n[barrel]\nhoop_frequency = 1500\n");
    require_refused(run_program("certify '" + file.string() + "'"), {"bat.toml", "barrel", "solid bat"});
  }
}
