// Normal modes: analytic beam frequencies, orthonormality, rigid modes, convergence, and the
// R161 bat against N2000 Table II.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "program.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/bat/modes.hpp"

using namespace sweetspot;

namespace {

Bat uniform_beam(double length, double diameter, int slices, double shear_modulus = 1.05e9) {
  Bat bat;
  bat.name = "uniform";
  bat.length = length;
  bat.material = {649, 1.814e10, shear_modulus, 1.0};
  bat.set_slices(std::vector<double>(slices, diameter));
  return bat;
}

// Free-free Euler-Bernoulli: omega = (beta L)^2 sqrt(E I / (rho A L^4)), cos(bL) cosh(bL) = 1.
const double beta_l[] = {4.7300, 7.8532, 10.9956, 14.1372, 17.2788, 20.4204};

double analytic_eb_hz(const Bat& bat, int mode) {
  const double bl = beta_l[mode - 1];
  const double ei = bat.material.youngs_modulus * bat.second_moment(0);
  const double rho_a = bat.material.density * bat.area(0);
  return bl * bl * std::sqrt(ei / (rho_a * std::pow(bat.length, 4))) / (2 * std::numbers::pi);
}

Bat r161() { return load_bat(std::string(SWEETSPOT_SOURCE_DIR) + "/studies/bats/r161.toml"); }

}  // namespace

TEST_CASE("Euler-Bernoulli uniform free-free beam matches cos(bL)cosh(bL) = 1 to 0.1 %", "[modes]") {
  for (int n : {200, 400}) {
    const Bat bat = uniform_beam(0.84, 0.06, n);
    const auto f = compute_modes(bat, BeamTheory::euler_bernoulli).vibrational_frequencies_hz();
    for (int mode = 1; mode <= 6; ++mode) {
      INFO("N = " << n << ", mode " << mode);
      CHECK(f[mode - 1] == Approx(analytic_eb_hz(bat, mode)).epsilon(1e-3));
    }
  }
}

TEST_CASE("Timoshenko lies below Euler-Bernoulli: shear and rotary inertia lower every mode", "[modes]") {
  const Bat bat = uniform_beam(0.84, 0.06, 200);
  const auto t = compute_modes(bat, BeamTheory::timoshenko).vibrational_frequencies_hz();
  for (int mode = 1; mode <= 6; ++mode) {
    INFO("mode " << mode);
    CHECK(t[mode - 1] < analytic_eb_hz(bat, mode));
  }
}

TEST_CASE("Timoshenko converges at second order in the slice thickness", "[modes]") {
  // Differences of successive halvings shrink by 2^p; the scheme is central, so p = 2.
  std::vector<std::vector<double>> f;
  for (int n : {50, 100, 200}) f.push_back(compute_modes(uniform_beam(0.84, 0.06, n), BeamTheory::timoshenko)
                                               .vibrational_frequencies_hz());
  for (int mode = 1; mode <= 4; ++mode) {
    const double coarse = f[0][mode - 1] - f[1][mode - 1];
    const double fine = f[1][mode - 1] - f[2][mode - 1];
    const double order = std::log2(std::abs(coarse / fine));
    INFO("mode " << mode << ": observed order " << order);
    CHECK(order == Approx(2.0).margin(0.15));
  }
}

TEST_CASE("Timoshenko approaches Euler-Bernoulli as the beam gets slender", "[modes]") {
  double previous_gap = 1;
  for (double diameter : {0.04, 0.01, 0.0025}) {
    const Bat bat = uniform_beam(0.84, diameter, 200);
    const auto t = compute_modes(bat, BeamTheory::timoshenko).vibrational_frequencies_hz();
    const auto e = compute_modes(bat, BeamTheory::euler_bernoulli).vibrational_frequencies_hz();
    const double gap = 1 - t[2] / e[2];  // mode 3: shear matters most at higher modes
    INFO("diameter " << diameter << ": 1 - f_T/f_EB = " << gap);
    CHECK(gap > 0);
    CHECK(gap < previous_gap / 4);  // the gap scales as (radius / wavelength)^2
    previous_gap = gap;
  }
  CHECK(previous_gap < 2e-3);
}

TEST_CASE("Modes are mass-orthonormal with exactly two rigid modes", "[modes]") {
  for (BeamTheory theory : {BeamTheory::timoshenko, BeamTheory::euler_bernoulli}) {
    const Bat bat = r161();
    const ModalBasis basis = compute_modes(bat, theory);
    const Eigen::MatrixXd m = beam_mass_matrix(bat, theory);
    const Eigen::MatrixXd gram = basis.vectors.transpose() * m * basis.vectors;
    INFO(to_string(theory));
    CHECK((gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff() < 1e-10);
    CHECK(basis.omega(0) == 0.0);
    CHECK(basis.omega(1) == 0.0);
    CHECK(basis.omega(2) > 2 * std::numbers::pi * 100);  // nothing else near zero
    // Mode 0 is a uniform translation, mode 1 a rotation about the centre of mass.
    const Eigen::VectorXd p0 = basis.psi.col(0), p1 = basis.psi.col(1);
    CHECK((p0.array() - p0(0)).abs().maxCoeff() < 1e-14);
    for (int i = 0; i < basis.slices(); ++i)
      CHECK(p1(i) == Approx((basis.z[i] - basis.z_cm) / std::sqrt(basis.moment_of_inertia_cm)).margin(1e-12));
  }
}

TEST_CASE("R161 Timoshenko frequencies and nodes agree with N2000 Table II", "[modes][r161]") {
  const double paper_hz[] = {165, 568, 1177, 1851, 2580, 3359, 4163, 4972, 5783, 6598};
  const ModalBasis basis = compute_modes(r161(), BeamTheory::timoshenko);
  const auto f = basis.vibrational_frequencies_hz();
  for (int mode = 1; mode <= 10; ++mode) {
    const double tolerance = mode == 1 ? 0.07 : mode == 2 ? 0.03 : 0.02;  // physics.md §2
    INFO("mode " << mode << ": " << f[mode - 1] << " Hz, paper " << paper_hz[mode - 1]);
    CHECK(f[mode - 1] == Approx(paper_hz[mode - 1]).epsilon(tolerance));
  }
  const std::vector<std::vector<double>> paper_nodes_cm = {{17, 68}, {7, 39, 72}, {5, 25, 50, 74}};
  for (int mode = 1; mode <= 3; ++mode) {
    const auto nodes = basis.nodes(mode + 1);
    REQUIRE(nodes.size() == paper_nodes_cm[mode - 1].size());
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      INFO("mode " << mode << " node " << k << ": " << nodes[k] * 100 << " cm");
      CHECK(nodes[k] * 100 == Approx(paper_nodes_cm[mode - 1][k]).margin(1.5));
    }
  }
}

TEST_CASE("R161 Euler-Bernoulli frequencies agree with N2000 f'", "[modes][r161]") {
  const double paper_hz[] = {169, 612, 1334, 2220, 3304, 4637};
  const auto f = compute_modes(r161(), BeamTheory::euler_bernoulli).vibrational_frequencies_hz();
  for (int mode = 2; mode <= 6; ++mode) {
    INFO("mode " << mode << ": " << f[mode - 1] << " Hz, paper " << paper_hz[mode - 1]);
    CHECK(f[mode - 1] == Approx(paper_hz[mode - 1]).epsilon(0.03));
  }
}

TEST_CASE("R161 frequencies converge at second order as the slices are refined from 84 to 672", "[modes][r161]") {
  // Refining by whole factors keeps the stepped profile exactly, so the frequencies converge to
  // that profile's continuum values. A joint spans half of each of two slices, in series
  // (harmonic means): observed order 2.00 for modes 1-5. With the arithmetic mean of the two
  // slices' rigidities the joint across every step of the profile was too stiff, and the observed
  // order was 1.2-1.6 (f1 = 174.72 / 174.64 / 174.60 / 174.59 Hz against 174.62 / 174.59 /
  // 174.58 / 174.58 now).
  const Bat bat = r161();
  std::vector<std::vector<double>> f;
  for (int n : {84, 168, 336, 672})
    f.push_back(compute_modes(resample(bat, n), BeamTheory::timoshenko).vibrational_frequencies_hz());
  for (int mode = 1; mode <= 5; ++mode) {
    const double d1 = f[1][mode - 1] - f[0][mode - 1];
    const double d2 = f[2][mode - 1] - f[1][mode - 1];
    const double d3 = f[3][mode - 1] - f[2][mode - 1];
    const double order = std::log2(d2 / d3);
    INFO("mode " << mode << ": changes " << d1 << ", " << d2 << ", " << d3 << " Hz; observed order "
                 << std::log2(d1 / d2) << ", " << order);
    CHECK(std::log2(d1 / d2) == Approx(2).margin(0.1));
    CHECK(order == Approx(2).margin(0.1));
    CHECK(std::abs(d3 / f[3][mode - 1]) < 1e-4);
  }
}

TEST_CASE("Euler-Bernoulli bats of more slices than its dense solve resolves are refused", "[modes]") {
  const Bat bat = resample(r161(), max_euler_bernoulli_slices + 1);
  CHECK_THROWS_AS(compute_modes(bat, BeamTheory::euler_bernoulli), InputError);
  CHECK_NOTHROW(compute_modes(resample(r161(), max_euler_bernoulli_slices), BeamTheory::euler_bernoulli));
  // Up to the bound the first frequency holds to 1e-6 (it converges from above as h^4).
  const double f84 = compute_modes(r161(), BeamTheory::euler_bernoulli).vibrational_frequencies_hz()[0];
  const double f336 = compute_modes(resample(r161(), 336), BeamTheory::euler_bernoulli).vibrational_frequencies_hz()[0];
  CHECK(f336 == Approx(f84).epsilon(1e-6));
}

TEST_CASE("modes --count solves only the modes it prints, so thousands of slices stay practical", "[modes][program]") {
  // The dense solve of all 8192 modes at 4096 slices took longer than 15 minutes; the lowest three,
  // a partial banded solve, well under a second. Same frequencies as at the profile's 84 slices to
  // the discretisation's second-order error (0.06 % at 84).
  const ProgramRun run = run_program("modes " + source_path("studies/bats/r161.toml") + " --slices 4096 --count 3 --json");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun coarse = run_program("modes " + source_path("studies/bats/r161.toml") + " --count 3 --json");
  const auto first_frequency = [](const std::string& json) {
    const std::size_t at = json.find("\"frequencies_hz\": [");
    return std::stod(json.substr(at + 19));
  };
  CHECK(first_frequency(run.output) == Approx(first_frequency(coarse.output)).epsilon(1e-3));
}
