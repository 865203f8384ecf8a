// The exact stepper's vectorised response of the modes to the force's polynomial pieces
// (src/contact/mode_kernels.hpp) against the integrals that define it, done by quadrature in long
// double: P_k = int_0^h sin(w (h - t)) / w t^k dt, Q_k = int_0^h cos(w (h - t)) t^k dt.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "contact/mode_kernels.hpp"
#include "program.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"

using namespace sweetspot;
using namespace sweetspot::detail;

namespace {

// p_k(x) = P_k / h^(k+2) and q_k(x) = Q_k / h^(k+1), x = w h: 20-point Gauss-Legendre on 64
// panels of [0, 1] (at most 5 radians of oscillation per panel for x <= 300).
void reference(long double x, long double p[6], long double q[6]) {
  static const long double node[10] = {0.0765265211334973337546404093988382L, 0.2277858511416450780804961953685746L,
                                       0.3737060887154195606725481770249272L, 0.5108670019508270980043640509552510L,
                                       0.6360536807265150254528366962262859L, 0.7463319064601507926143050703556416L,
                                       0.8391169718222188233945290617015207L, 0.9122344282513259058677524412032981L,
                                       0.9639719272779137912676661311972772L, 0.9931285991850949247861223884713203L};
  static const long double weight[10] = {0.1527533871307258506980843319550976L, 0.1491729864726037467878287370019694L,
                                         0.1420961093183820513292983250671649L, 0.1316886384491766268984944997481631L,
                                         0.1181945319615184173123773777113823L, 0.1019301198172404350367501354803499L,
                                         0.0832767415767047487247581432220463L, 0.0626720483341090635695065351870416L,
                                         0.0406014298003869413310399522749321L, 0.0176140071391521183118619623518528L};
  for (int k = 0; k < 6; ++k) p[k] = q[k] = 0;
  const int panels = 64;
  for (int panel = 0; panel < panels; ++panel) {
    const long double mid = (panel + 0.5L) / panels, half = 0.5L / panels;
    for (int i = 0; i < 20; ++i) {
      const long double s = mid + (i < 10 ? -1 : 1) * half * node[i % 10], w = half * weight[i % 10];
      const long double sine = x == 0 ? 1 - s : std::sin(x * (1 - s)) / x, cosine = std::cos(x * (1 - s));
      long double power = 1;
      for (int k = 0; k < 6; ++k, power *= s) p[k] += w * sine * power, q[k] += w * cosine * power;
    }
  }
}

}  // namespace

TEST_CASE("The modes' responses to t^k agree with their integrals within 1e-13 at any w h", "[exact]") {
  const double h = 1e-5;
  const std::vector<double> x = {0, 1e-6, 1e-3, 0.1, 0.5, 1, 2, 3, 3.9, 3.999, 4, 4.001, 5, 8, 16, 50, 120, 300};
  std::vector<double> omega;
  for (double xi : x) omega.push_back(xi / h);
  const int n = static_cast<int>(omega.size());
  // Each datum weights one power alone: d_j = P_j, q_j = Q_j.
  double identity[36] = {};  // row-major
  for (int j = 0; j < 6; ++j) identity[j * 6 + j] = 1;
  std::vector<double> c(n), sn(n), w2sn(n), cv(n), d(6 * n), q(6 * n);
  ResponseColumns out{c.data(), sn.data(), w2sn.data(), cv.data(), {}, {}};
  for (int j = 0; j < 6; ++j) out.d[j] = d.data() + j * n, out.q[j] = q.data() + j * n;
  undamped_responses(omega.data(), n, h, identity, out);
  for (int i = 0; i < n; ++i) {
    const double xi = omega[i] * h;  // as the kernel forms it
    long double p_ref[6], q_ref[6];
    reference(xi, p_ref, q_ref);
    INFO("x = " << xi);
    CHECK(c[i] == std::cos(xi));
    CHECK(cv[i] == c[i]);
    CHECK(sn[i] == (xi == 0 ? h : std::sin(xi) / omega[i]));
    CHECK(w2sn[i] == omega[i] * std::sin(xi));
    for (int k = 0; k < 6; ++k) {
      INFO("k = " << k);
      // Relative to the size of the response, |p_k| <= 1 / ((k + 1) (k + 2)) (at x = 0).
      const double p_scale = std::pow(h, k + 2) / ((k + 1) * (k + 2)), q_scale = std::pow(h, k + 1) / (k + 1);
      CHECK(std::abs(d[k * n + i] - static_cast<double>(p_ref[k] * std::pow(h, k + 2))) <= 1e-13 * p_scale);
      CHECK(std::abs(q[k * n + i] - static_cast<double>(q_ref[k] * std::pow(h, k + 1))) <= 1e-13 * q_scale);
    }
  }
}

namespace {

// What every path the processor has gives for the same work, compared with what SSE2 gives.
template <class Work>
void compare_paths(Work work) {
  const VectorPath chosen = vector_path();
  REQUIRE(use_vector_path(VectorPath::sse2));
  const auto reference = work();
  int compared = 0;
  for (VectorPath path : {VectorPath::avx2, VectorPath::avx512}) {
    if (!use_vector_path(path)) continue;
    INFO("path " << to_string(path));
    CHECK(work() == reference);
    ++compared;
  }
  use_vector_path(chosen);
  WARN(compared << " wider path(s) compared with SSE2 on this processor");
}

std::vector<double> ramp(int n, double first, double step) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = first + step * i + 0.3 * std::sin(7.0 * i);
  return v;
}

}  // namespace

TEST_CASE("Every vector path gives the modes' responses and steps bit for bit as SSE2 does", "[exact]") {
  for (int n : {1, 7, 8, 9, 30, 168}) {
    INFO(n << " modes");
    compare_paths([n] {
      const std::vector<double> omega = ramp(n, 0, 4e4);  // w h from 0 to past 4 at h = 1e-5
      double basis[36];
      for (int i = 0; i < 36; ++i) basis[i] = std::cos(1.0 + i);
      std::vector<double> out(16 * n);
      ResponseColumns columns{out.data(), out.data() + n, out.data() + 2 * n, out.data() + 3 * n, {}, {}};
      for (int j = 0; j < 6; ++j) columns.d[j] = out.data() + (4 + j) * n, columns.q[j] = out.data() + (10 + j) * n;
      undamped_responses(omega.data(), n, 1e-5, basis, columns);
      // A step with those responses, from a state and data of every sign and size.
      const std::vector<double> a0 = ramp(n, -1e-3, 3e-5), v0 = ramp(n, 0.2, -0.01), psi = ramp(n, 1.5, -0.02),
                                psi_w2 = ramp(n, 10, 5);
      std::vector<double> a(n), v(n);
      const StepArrays s{a0.data(), v0.data(), columns.c, columns.sn, columns.w2sn, columns.cv, psi.data(),
                         psi_w2.data(), {columns.d[0], columns.d[1], columns.d[2], columns.d[3]},
                         {columns.q[0], columns.q[1], columns.q[2], columns.q[3]}, a.data(), v.data()};
      const StepSums sums = step_known(n, s, {1200, -3e6, 2500, 4e7});
      step_end(n, a.data(), v.data(), psi.data(), columns.d[4], columns.d[5], columns.q[4], columns.q[5], 3100, -2e7);
      out.insert(out.end(), a.begin(), a.end());
      out.insert(out.end(), v.begin(), v.end());
      out.insert(out.end(), {sums.psi_a, sums.psi_v, sums.psi_w2a});
      return out;
    });
  }
}

TEST_CASE("Every vector path gives whole impacts bit for bit as SSE2 does: modes auto and all, a damped bat",
          "[exact]") {
  for (const char* file : {"studies/bats/r161.toml", "studies/bats/maple_271.toml"}) {
    INFO(file);
    const ModalBasis basis = compute_modes(load_bat(source_path(file)), BeamTheory::timoshenko);
    compare_paths([&basis] {
      std::vector<double> results;
      for (int modes : {auto_modes, all_modes})
        for (double z : {0.45, 0.62, 0.71}) {
          ImpactScene s;  // the defaults: exact stepping, modes auto
          s.z = z, s.ball_speed = 40, s.swing = {51, true, 0, 0.09}, s.vibrational_modes = modes;
          const ImpactResult r = simulate_impact(basis, s);
          results.insert(results.end(), {r.vf, r.collision_time, r.peak_force, r.energy.vibration, r.energy.damped});
        }
      return results;
    });
  }
}
