// Partial eigen-solves (ModeRequest::lowest / below, banded_eigensolver.cpp): the modes equal the
// dense solve's, the rigid modes stay exact, the flexibility counts every vibrational mode, and
// what reads a basis (point loads, fixed counts, auto) works on a partial one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bat/banded_eigensolver.hpp"
#include "bat/beam_system.hpp"
#include "contact/mode_kernels.hpp"
#include "n2000_scenes.hpp"
#include "program.hpp"
#include "selection_scale.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"

using namespace sweetspot;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

struct Case {
  std::string bat;
  BeamTheory theory;
  int slices;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  for (const std::string bat : {"r161", "torpedo", "aluminium"})
    for (const BeamTheory theory : {BeamTheory::timoshenko, BeamTheory::euler_bernoulli})
      for (const int factor : {1, 2}) {
        const Bat b = load_bat(source_path("studies/bats/" + bat + ".toml"));
        all.push_back({bat, theory, factor * b.slices()});  // N = 84 / 168 (85 / 170 for the torpedo)
      }
  return all;
}

// A case's bat with its full basis and the lowest 18 vibrational modes.
struct Solved {
  Bat bat;
  ModalBasis full, part;
};

Solved solve(const Case& c) {
  Solved s;
  s.bat = resample(load_bat(source_path("studies/bats/" + c.bat + ".toml")), c.slices);
  s.full = compute_modes(s.bat, c.theory);
  s.part = compute_modes(s.bat, c.theory, ModeRequest::lowest(18));
  return s;
}

// The round-off every solve of K x = w^2 M x carries in w_n^2, relative: eps w_max^2 / w_n^2
// (the reduction works on the whole spectrum). Euler-Bernoulli's w_max grows as N^2, and its
// dense solve errs up to 1.5e-8 in f1 of R161 at N = 84 against a long-double solve; Timoshenko's
// stays below 1e-10 there.
double roundoff(const ModalBasis& full, int n) {
  const double top = full.omega(full.count() - 1) / full.omega(n);
  return eps * top * top;
}

// Each solved mode of `part` is the dense solve's: its frequency to 1e-10 (or the round-off both
// carry), its shape up to sign to 1e-8 (a shape errs by about that round-off over the relative gap
// to its neighbours, >= 1 here), its nodes to 1e-8 of the length.
void check_modes_match(const ModalBasis& part, const ModalBasis& full, double length) {
  for (int n = 2; n < part.count(); ++n) {
    INFO("mode " << n);
    CHECK(std::abs(part.omega(n) / full.omega(n) - 1) <= 1e-10 + roundoff(full, n));
    const double scale = full.psi.col(n).cwiseAbs().maxCoeff();
    const double same = (part.psi.col(n) - full.psi.col(n)).cwiseAbs().maxCoeff();
    const double flipped = (part.psi.col(n) + full.psi.col(n)).cwiseAbs().maxCoeff();
    CHECK(std::min(same, flipped) <= (1e-8 + roundoff(full, n) / 10) * scale);
    const std::vector<double> a = part.nodes(n), b = full.nodes(n);
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) CHECK(std::abs(a[k] - b[k]) <= 1e-8 * length);
  }
}

}  // namespace

TEST_CASE("The lowest modes of a partial solve are the dense solve's", "[partial_modes]") {
  for (const Case& c : cases()) {
    const auto [bat, full, part] = solve(c);
    INFO(c.bat << ", " << to_string(c.theory) << ", N = " << c.slices);
    REQUIRE(part.count() == 20);
    CHECK_FALSE(part.complete());
    CHECK(part.solved_below == part.omega(19));
    check_modes_match(part, full, bat.length);
  }
}

TEST_CASE("A partial basis is mass-orthonormal and its rigid modes are exact", "[partial_modes]") {
  for (const Case& c : cases()) {
    const auto [bat, full, part] = solve(c);
    INFO(c.bat << ", " << to_string(c.theory) << ", N = " << c.slices);
    const Eigen::MatrixXd m = beam_mass_matrix(bat, c.theory);
    const Eigen::MatrixXd gram = part.vectors.transpose() * m * part.vectors;
    CHECK((gram - Eigen::MatrixXd::Identity(20, 20)).cwiseAbs().maxCoeff() <= 1e-12);
    // The rigid modes and what comes from them are the full basis's to round-off.
    CHECK(part.omega(0) == 0);
    CHECK(part.omega(1) == 0);
    CHECK(std::abs(part.mass / full.mass - 1) <= 1e-14);
    CHECK(std::abs(part.z_cm / full.z_cm - 1) <= 1e-14);
    CHECK(std::abs(part.moment_of_inertia_cm / full.moment_of_inertia_cm - 1) <= 1e-14);
    CHECK((part.vectors.leftCols(2) - full.vectors.leftCols(2)).cwiseAbs().maxCoeff() <=
          1e-14 * full.vectors.leftCols(2).cwiseAbs().maxCoeff());
    CHECK(part.translation.tail(18).isZero(0));  // vibrational modes start at rest
    CHECK(part.rotation.tail(18).isZero(0));
    CHECK(part.translation(1) == 0);
    CHECK(part.rotation(0) == 0);
  }
}

TEST_CASE("The flexibility is the sum of psi^2 / omega^2 over every vibrational mode", "[partial_modes]") {
  for (const Case& c : cases()) {
    const auto [bat, full, part] = solve(c);
    INFO(c.bat << ", " << to_string(c.theory) << ", N = " << c.slices);
    CHECK(full.unsolved_compliance_at(0.7) == 0);  // a complete basis leaves nothing unsolved
    for (double z = 0; z <= bat.length; z += bat.length / 97) {  // centres, between them, both ends
      const Eigen::VectorXd s = full.shapes_at(z);
      double sum = 0, tail = 0;
      for (int n = 2; n < full.count(); ++n) {
        sum += s(n) * s(n) / (full.omega(n) * full.omega(n));
        if (n >= part.count()) tail += s(n) * s(n) / (full.omega(n) * full.omega(n));
      }
      INFO("z = " << z);
      // The sum is dominated by the first vibrational mode: its round-off is the bound.
      const double tolerance = 1e-10 + 2 * roundoff(full, 2);
      CHECK(std::abs(full.vibrational_compliance_at(z) - sum) <= tolerance * sum);
      // The same flexibility, from rigid modes that differ in the last bit (sparse or dense M).
      CHECK(std::abs(part.vibrational_compliance_at(z) - full.vibrational_compliance_at(z)) <= 1e-10 * sum);
      CHECK(std::abs(part.unsolved_compliance_at(z) - tail) <= tolerance * sum);
      CHECK(std::abs(part.unsolved_cross_compliance(z, z) - tail) <= tolerance * sum);
    }
  }
}

TEST_CASE("What the unsolved modes share between two points is their sum over the full basis", "[partial_modes]") {
  for (const Case& c : cases()) {
    const auto [bat, full, part] = solve(c);
    INFO(c.bat << ", " << to_string(c.theory) << ", N = " << c.slices);
    CHECK(full.unsolved_cross_compliance(0.15, 0.7) == 0);
    // A rig's pivot (6 in from the knob, between slice centres) against the bat from end to end.
    for (const double pivot : {0.1524, bat.length / 2}) {
      const Eigen::VectorXd at_pivot = full.shapes_at(pivot);
      const double scale = part.unsolved_compliance_at(pivot);
      for (double z = 0; z <= bat.length; z += bat.length / 53) {
        const Eigen::VectorXd s = full.shapes_at(z);
        double tail = 0;
        for (int n = part.count(); n < full.count(); ++n) tail += s(n) * at_pivot(n) / (full.omega(n) * full.omega(n));
        INFO("pivot " << pivot << ", z = " << z << ": tail " << tail << ", unsolved at the pivot " << scale);
        const double tolerance = 1e-10 + 2 * roundoff(full, 2);
        CHECK(std::abs(part.unsolved_cross_compliance(z, pivot) - tail) <=
              tolerance * full.vibrational_compliance_at(pivot));
        CHECK(part.unsolved_cross_compliance(z, pivot) == Approx(part.unsolved_cross_compliance(pivot, z))
                                                               .margin(1e-12 * full.vibrational_compliance_at(pivot)));
      }
    }
  }
}

TEST_CASE("A point load reads a partial basis as it reads the full one", "[partial_modes]") {
  const Bat bat = load_bat(source_path("studies/bats/r161.toml"));
  for (const BeamTheory theory : {BeamTheory::timoshenko, BeamTheory::euler_bernoulli}) {
    const ModalBasis full = compute_modes(bat, theory);
    const ModalBasis part = compute_modes(bat, theory, ModeRequest::lowest(18));
    for (const double z : {0.0, 0.003, 0.005, 0.4123, 0.705, 0.8377, 0.84}) {
      INFO(to_string(theory) << ", z = " << z);
      const PointLoad a = part.layout.point(z), b = full.layout.point(z);
      CHECK(a.dof == b.dof);
      CHECK(a.weight == b.weight);
      CHECK(a.compliance == b.compliance);
      const Eigen::VectorXd shapes = part.shapes_at(z);
      REQUIRE(shapes.size() == part.count());
      const Eigen::VectorXd expected = full.shapes_at(z).head(part.count());
      CHECK((shapes - expected).cwiseAbs().maxCoeff() <= 1e-8 * expected.cwiseAbs().maxCoeff());
    }
  }
}

TEST_CASE("A fixed mode count on a partial basis gives the full basis's result", "[partial_modes]") {
  const Bat bat = load_bat(source_path("studies/bats/r161.toml"));
  const ModalBasis full = compute_modes(bat, BeamTheory::timoshenko);
  const ModalBasis part = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::lowest(18));
  for (const double z : {0.405, 0.605, 0.705, 0.805}) {
    ImpactScene s = n2000_high_impact(z, 18);
    s.integrator.method = Method::exact;
    const ImpactResult a = simulate_impact(full, s), b = simulate_impact(part, s);
    INFO("z = " << z);
    REQUIRE(b.status == CollisionStatus::ok);
    CHECK(b.modes_kept == a.modes_kept);
    CHECK(std::abs(b.vf / a.vf - 1) <= 1e-9);
  }
}

TEST_CASE("Auto asks for the modes its pulse reaches and gives the full basis's result", "[partial_modes]") {
  // What auto needs on the high-impact scene stays within max_banded_share of the modes at every N
  // here (about 100 of 168 at N = 84), so the banded solve serves; a request the dense solve
  // serves gives the full basis's result bit for bit.
  const Bat r161 = load_bat(source_path("studies/bats/r161.toml"));
  const double tolerance = 1e-5;
  for (const int slices : {84, 168, 336}) {
    const Bat bat = resample(r161, slices);
    const ModalBasis full = compute_modes(bat, BeamTheory::timoshenko);
    const ModalBasis rigid = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::rigid_only());
    for (const double z : {0.305, 0.405, 0.605, 0.705, 0.805}) {  // handle and barrel
      ImpactScene s = n2000_high_impact(z, auto_modes);
      s.integrator.method = Method::exact;
      s.mode_tolerance = tolerance;
      const ModeRequest request = auto_mode_request(s, rigid);
      const ModalBasis part = compute_modes(bat, BeamTheory::timoshenko, request);
      const ImpactResult a = simulate_impact(full, s), b = simulate_impact(part, s);
      INFO("N = " << slices << ", z = " << z << ": " << part.count() << " modes solved, " << b.modes_kept.size()
                  << " kept; vf " << a.vf << " / " << b.vf << ", modes_error " << a.modes_error << " / "
                  << b.modes_error);
      REQUIRE(b.status == CollisionStatus::ok);
      // Every mode auto keeps was solved: the last kept lies below the frequency solved to.
      if (!b.modes_kept.empty()) CHECK(part.omega(b.modes_kept.back() + 1) < part.solved_below);
      CHECK(selection_modes_error(b, part, s) <= tolerance);
      if (part.complete()) {
        CHECK(b.vf == a.vf);
        CHECK(b.modes_error == a.modes_error);
      } else {
        // The unsolved tail's bound takes a little of the tolerance, so a mode at the edge of
        // the budget may be kept that the full basis drops: the results agree within it.
        CHECK(b.modes_error >= 0);
        CHECK(std::abs(b.vf / a.vf - 1) <= tolerance);
      }
    }
  }
}

TEST_CASE("The unsolved modes' bound is honest: the partial auto result is within its error of all modes",
          "[partial_modes]") {
  const Bat bat = resample(load_bat(source_path("studies/bats/r161.toml")), 168);
  const ModalBasis full = compute_modes(bat, BeamTheory::timoshenko);
  const ModalBasis part = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::lowest(40));
  for (const double z : {0.605, 0.705, 0.805}) {
    ImpactScene s = n2000_high_impact(z, auto_modes);
    s.integrator.method = Method::exact;
    s.integrator.dt = 2e-6;  // integration error far below the tolerance
    s.mode_tolerance = 1e-3;
    const ImpactResult r = simulate_impact(part, s);
    s.vibrational_modes = all_modes;
    const ImpactResult all = simulate_impact(full, s);
    INFO("z = " << z << ": error " << std::abs(r.vf / all.vf - 1) << ", estimated " << r.modes_error);
    CHECK(std::abs(r.vf / all.vf - 1) <= r.modes_error);
    CHECK(r.modes_error <= 1e-3);
  }
}

TEST_CASE("Auto's request leaves the unsolved tail within the tolerance, from 1e-3 to 1e-7", "[partial_modes]") {
  // The request grows as the tolerance's cube root (auto_solve_factor): the estimate stays within
  // the tolerance per contact (a ball struck again counts the unsolved modes once per contact),
  // and on barrel impacts the result within it of all modes. A request too short shows as
  // modes_error over the tolerance (a fixed 48 x 4 pi / T reached 2.4 x at 1e-7).
  for (const std::string name : {"r161", "torpedo"}) {
    const Bat b = load_bat(source_path("studies/bats/" + name + ".toml"));
    const Bat bat = resample(b, 2 * b.slices());
    const ModalBasis full = compute_modes(bat, BeamTheory::timoshenko);
    const ModalBasis rigid = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::rigid_only());
    for (const double tolerance : {1e-3, 1e-5, 1e-7})
      for (const double z : {0.405, 0.705})
        for (const double speed : {10.0, 50.0})
          for (const double e0 : {0.5, 1.0}) {
            ImpactScene s = n2000_high_impact(z, auto_modes);
            s.ball_speed = speed;
            s.ball.e0 = e0;
            s.ball.a = e0 == 1 ? 1.5 : 2.2;
            s.integrator.method = Method::exact;
            s.integrator.dt = 4e-6;
            s.mode_tolerance = tolerance;
            const ModalBasis part = compute_modes(bat, BeamTheory::timoshenko, auto_mode_request(s, rigid));
            const ImpactResult r = simulate_impact(part, s);
            INFO(name << ", tolerance " << tolerance << ", z " << z << ", " << speed << " m/s, e0 " << e0 << ": "
                      << part.count() - 2 << " modes solved, " << r.modes_kept.size() << " kept, modes_error "
                      << r.modes_error);
            REQUIRE(r.status == CollisionStatus::ok);
            CHECK(selection_modes_error(r, part, s) <= r.contacts * tolerance);
            if (z > 0.5 && tolerance >= 1e-5) {  // barrel: honest to the measured 1.32 x (README)
              s.vibrational_modes = all_modes;
              const ImpactResult all = simulate_impact(full, s);
              CHECK(std::abs(r.vf / all.vf - 1) <= 1.5 * std::max(r.modes_error, 1e-9));
            }
          }
  }
}

TEST_CASE("A partial solve of most of the modes is still the dense solve's", "[partial_modes]") {
  // What auto asks for at N = 84 on the high-impact scene: about 100 of 168 modes, up into the
  // crowded top of the bending branch.
  for (const std::string name : {"r161", "torpedo", "aluminium"}) {
    const Bat bat = load_bat(source_path("studies/bats/" + name + ".toml"));
    const ModalBasis full = compute_modes(bat, BeamTheory::timoshenko);
    const ModalBasis part = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::lowest(110));
    INFO(name);
    REQUIRE(part.count() == 112);
    const Eigen::MatrixXd gram = part.vectors.transpose() * beam_mass_matrix(bat, BeamTheory::timoshenko) * part.vectors;
    CHECK((gram - Eigen::MatrixXd::Identity(112, 112)).cwiseAbs().maxCoeff() < 1e-12);
    check_modes_match(part, full, bat.length);
  }
}

TEST_CASE("The Sturm counts find as many eigenvalues below a shift as the dense solve does", "[partial_modes]") {
  // Sylvester's law of inertia: K - x M has as many negative pivots as the pencil has eigenvalues
  // below x. Shifts halfway (geometrically) between neighbouring dense eigenvalues, over the whole
  // spectrum: Timoshenko's counts factor K - x M itself, Euler-Bernoulli's a tridiagonal form.
  // Every shipped bat, hollow and wood ones too, at its own slices and twice them.
  std::vector<Case> all;
  for (const std::string bat : {"r161", "torpedo", "aluminium", "alloy_bbcor", "composite_bbcor", "maple_271"})
    for (const BeamTheory theory : {BeamTheory::timoshenko, BeamTheory::euler_bernoulli})
      for (const int factor : {1, 2})
        all.push_back({bat, theory, factor * load_bat(source_path("studies/bats/" + bat + ".toml")).slices()});
  for (const Case& c : all) {
    const Bat bat = resample(load_bat(source_path("studies/bats/" + c.bat + ".toml")), c.slices);
    const ModalBasis full = compute_modes(bat, c.theory);
    const bool timoshenko = c.theory == BeamTheory::timoshenko;
    const BeamSystem system = timoshenko ? timoshenko_system(bat) : euler_bernoulli_system(bat);
    INFO(c.bat << ", " << to_string(c.theory) << ", N = " << c.slices);
    int wrong = 0;
    for (int n = 2; n + 1 < full.count(); ++n) {
      const double below = full.omega(n) * full.omega(n + 1);  // the geometric mean of w_n^2, w_(n+1)^2
      if (full.omega(n + 1) / full.omega(n) - 1 < 1e-6) continue;  // closer than the dense solve's round-off
      wrong += count_below(system, timoshenko, below) != n + 1;
    }
    CHECK(wrong == 0);
    const double top = full.omega(full.count() - 1);
    CHECK(count_below(system, timoshenko, 2 * top * top) == full.count());
    CHECK(count_below(system, timoshenko, full.omega(2) * full.omega(2) / 2) == 2);
  }
}

TEST_CASE("Every vector path solves a partial basis bit for bit as SSE2 does", "[partial_modes]") {
  // The Sturm counts (src/bat/sturm_kernels.inc) steer every bisection: a count one off on a path
  // would move a bracket, its shift and so the mode. The tridiagonal form's counts (Timoshenko at
  // its own slices; Euler-Bernoulli, whose mass is not diagonal) and the pencil's (many slices,
  // few modes).
  struct Solve {
    std::string bat;
    BeamTheory theory;
    int slices, modes;
  };
  using detail::VectorPath;
  const VectorPath chosen = detail::vector_path();
  int compared = 0;
  for (const Solve& c : {Solve{"r161", BeamTheory::timoshenko, 84, 60}, Solve{"r161", BeamTheory::timoshenko, 336, 30},
                         Solve{"aluminium", BeamTheory::euler_bernoulli, 84, 40}}) {
    INFO(c.bat << ", " << to_string(c.theory) << ", N = " << c.slices << ", " << c.modes << " modes");
    const Bat bat = resample(load_bat(source_path("studies/bats/" + c.bat + ".toml")), c.slices);
    const auto solve = [&] { return compute_modes(bat, c.theory, ModeRequest::lowest(c.modes)); };
    REQUIRE(detail::use_vector_path(VectorPath::sse2));
    const ModalBasis reference = solve();
    REQUIRE_FALSE(reference.complete());
    for (const VectorPath path : {VectorPath::avx2, VectorPath::avx512}) {
      if (!detail::use_vector_path(path)) continue;
      INFO("path " << detail::to_string(path));
      const ModalBasis basis = solve();
      CHECK(basis.omega == reference.omega);
      CHECK(basis.vectors == reference.vectors);
      ++compared;
    }
  }
  detail::use_vector_path(chosen);
  WARN(compared << " solves on wider paths compared with SSE2 on this processor");
}
