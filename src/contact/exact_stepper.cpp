#include "contact/exact_stepper.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>
#include <cmath>

#include "contact/damped_mode.hpp"
#include "contact/mode_kernels.hpp"
#include "contact/thread_memory.hpp"

namespace sweetspot::detail {

namespace {

constexpr double event_grid = 4096;  // event steps end on this many divisions of the step
constexpr int powers = 6;            // the interpolants are polynomials of degree up to 5

// P_k = int_0^h sin(w (h - t)) / w t^k dt and Q_k = int_0^h cos(w (h - t)) t^k dt, k = 0..5:
// the response of a mode to the forcing t^k. For w h >= 4, integration by parts from P_0 =
// (1 - cos)/w^2, Q_0 = sin/w: Q_k = k P_{k-1}, P_k = (h^k - k Q_{k-1}) / w^2. Below that the
// recursion cancels, and the power series (exact at w = 0) takes over:
//   P_k = h^(k+2) k! sum_j (-x^2)^j / (k+2j+2)!,  Q_k = h^(k+1) k! sum_j (-x^2)^j / (k+2j+1)!.
void monomial_responses(double w, double h, double cos_x, double sin_x, double p[powers], double q[powers]) {
  const double x = w * h;
  double h_power[powers + 2] = {1};  // h^0 .. h^(powers + 1)
  for (int k = 1; k < powers + 2; ++k) h_power[k] = h_power[k - 1] * h;
  if (x >= 4) {
    const double w2 = w * w;
    p[0] = (1 - cos_x) / w2;
    q[0] = sin_x / w;
    for (int k = 1; k < powers; ++k) {
      q[k] = k * p[k - 1];
      p[k] = (h_power[k] - k * q[k - 1]) / w2;
    }
    return;
  }
  const double x2 = x * x;
  double factorial = 1;  // k!
  for (int k = 0; k < powers; ++k) {
    if (k > 0) factorial *= k;
    double denom_q = 1;
    for (int j = 2; j <= k + 1; ++j) denom_q *= j;  // (k + 1)!
    double denom_p = denom_q * (k + 2);             // (k + 2)!
    double sp = 0, sq = 0, term = 1;
    for (int j = 0; j < 40 && std::abs(term) > 1e-18 * denom_q; ++j) {
      sq += term / denom_q;
      sp += term / denom_p;
      term *= -x2;
      denom_q *= (k + 2 * j + 2) * (k + 2 * j + 3);
      denom_p *= (k + 2 * j + 3) * (k + 2 * j + 4);
    }
    q[k] = h_power[k + 1] * factorial * sq;
    p[k] = h_power[k + 2] * factorial * sp;
  }
}

// The damped mode's P_k = int_0^tau G(tau - t) t^k dt and Q_k = int_0^tau G'(tau - t) t^k dt
// (damped_mode.hpp; zeta = 0 gives the undamped P_k, Q_k above). By parts, Q_0 = G(tau),
// Q_k = k P_{k-1}, and from G'' + 2 sigma G' + w^2 G = 0,
//   P_k = (tau^k - k Q_{k-1} - 2 sigma Q_k) / w^2,  P_0 = (1 - G'(tau) - 2 sigma G(tau)) / w^2,
// which is the undetermined coefficients' particular polynomial plus the fitted homogeneous part,
// solved from the bottom up. It cancels for w tau < 4 as the undamped recursion does, and there
// the Taylor series of G (beta_m = G^(m)(0) tau^m: beta_0 = 0, beta_1 = tau, beta_(m+2) =
// -2 sigma tau beta_(m+1) - (w tau)^2 beta_m) integrates term by term, exactly:
//   P_k = k! tau^(k+1) sum_m beta_m / (k + m + 1)!.
void damped_monomial_responses(double w, double zeta, double tau, const ImpulseResponse& g, double p[powers],
                               double q[powers]) {
  const double x = w * tau, sigma = zeta * w;
  double tau_power[powers + 1] = {1};
  for (int k = 1; k <= powers; ++k) tau_power[k] = tau_power[k - 1] * tau;
  if (x >= 4) {
    const double w2 = w * w;
    q[0] = g.g;
    p[0] = (1 - g.g_rate - 2 * sigma * g.g) / w2;
    for (int k = 1; k < powers; ++k) {
      q[k] = k * p[k - 1];
      p[k] = (tau_power[k] - k * q[k - 1] - 2 * sigma * q[k]) / w2;
    }
    return;
  }
  constexpr int terms = 48;  // (w tau)^m / m! < 1e-28 of the leading term by m = 48 at w tau = 4
  // Only the terms that count: up to where (w tau)^m / m! falls below 1e-20 (fewer for the many
  // slow modes; 48 at w tau = 4).
  int used = 2;
  for (double term = x * x / 2; used < terms && (term > 1e-20 || used <= x); ++used) term *= x / (used + 1);
  double beta[terms] = {0, tau};
  for (int m = 0; m + 2 < used; ++m) beta[m + 2] = -2 * sigma * tau * beta[m + 1] - x * x * beta[m];
  // 1/n! for n up to the last term's: a table, not a division per term (a damped bat damps every
  // mode, and this runs for each at every step length a run meets).
  static const std::array<double, terms + powers + 1> inverse_factorial = [] {
    std::array<double, terms + powers + 1> t{1};
    for (std::size_t n = 1; n < t.size(); ++n) t[n] = t[n - 1] / static_cast<double>(n);
    return t;
  }();
  double factorial = 1;  // k!
  for (int k = 0; k < powers; ++k) {
    if (k > 0) factorial *= k;
    double sum = 0;
    for (int m = 0; m < used; ++m) sum += beta[m] * inverse_factorial[k + m + 1];
    p[k] = factorial * tau_power[k + 1] * sum;
  }
  q[0] = g.g;
  for (int k = 1; k < powers; ++k) q[k] = k * p[k - 1];
}

// An interpolant's basis: row j is the polynomial (coefficients of t^0..t^5) that datum j
// weights.
using Basis = Eigen::Matrix<double, data_count, powers>;

// The basis in s = t / h, from the conditions at the nodes s = -past_ratio (quintic only), 0 and
// 1 on the value (a force datum) or the slope (a rate datum, which enters as h F').
Basis basis_in_s(double past_ratio) {
  struct Condition {
    Datum datum;
    double node;
    bool slope;
  };
  std::vector<Condition> conditions = {{start_force, 0, false}, {start_rate, 0, true}, {end_force, 1, false},
                                       {end_rate, 1, true}};
  if (past_ratio > 0)
    conditions.insert(conditions.begin(), {{past_force, -past_ratio, false}, {past_rate, -past_ratio, true}});
  const int m = static_cast<int>(conditions.size());
  Eigen::MatrixXd conditions_matrix(m, m);  // row i: condition i on the polynomial sum_k c_k s^k
  for (int i = 0; i < m; ++i)
    for (int k = 0; k < m; ++k) {
      const Condition& c = conditions[i];
      conditions_matrix(i, k) = c.slope ? (k == 0 ? 0.0 : k * std::pow(c.node, k - 1)) : std::pow(c.node, k);
    }
  const Eigen::MatrixXd coefficients = conditions_matrix.fullPivLu().inverse();  // column i: datum i's polynomial
  Basis b = Basis::Zero();
  for (int i = 0; i < m; ++i) b.row(conditions[i].datum).head(m) = coefficients.col(i).transpose();
  return b;
}

Basis interpolant_basis(double past_ratio, double h) {
  // Each past ratio's basis is made once per thread (a run meets a few: 0, every event step's,
  // 1/2 and 1 of split and nominal steps): an LU of its conditions per response cost more than
  // the modes' responses of a small set.
  struct Hash {
    std::size_t operator()(double ratio) const { return bits_hash(ratio); }
  };
  thread_local ThreadMemory<double, Basis, Hash> in_s(64);  // a stepper halving its steps meets more
  Basis b = in_s.get(past_ratio, [&] { return basis_in_s(past_ratio); });
  for (int k = 0; k < powers; ++k) b.col(k) /= std::pow(h, k);
  for (const Datum rate : {past_rate, start_rate, end_rate}) b.row(rate) *= h;
  return b;
}

// One mode's closed-form response over a step: c, sn, w2sn, cv, then d and q for each datum.
constexpr int free_count = ModeResponse::free_columns;
using ModeCoefficients = std::array<double, ModeResponse::columns>;

void add_forced(const Basis& b, const double p[powers], const double q[powers], ModeCoefficients& m) {
  for (int j = 0; j < data_count; ++j)
    for (int k = 0; k < powers; ++k) {
      m[free_count + j] += b(j, k) * p[k];
      m[free_count + data_count + j] += b(j, k) * q[k];
    }
}

ModeCoefficients mode_coefficients(double w, double h, const Basis& b) {
  const double cos_x = std::cos(w * h), sin_x = std::sin(w * h);
  double p[powers], q[powers];
  monomial_responses(w, h, cos_x, sin_x, p, q);
  ModeCoefficients m = {cos_x, w == 0 ? h : sin_x / w, w * sin_x, cos_x};
  add_forced(b, p, q, m);
  return m;
}

// A damped mode's response at time tau into a step whose force data the basis b weights (tau = h
// for the step's end, a Gauss node for the dissipation's quadrature).
ModeCoefficients damped_mode_coefficients(double w, double zeta, double tau, const Basis& b) {
  const ImpulseResponse g = damped_impulse_response(w, zeta, tau);
  const FreeEvolution e = damped_free_evolution(w, zeta, tau);
  double p[powers], q[powers];
  damped_monomial_responses(w, zeta, tau, g, p, q);
  ModeCoefficients m = {e.aa, e.av, -e.va, e.vv};
  add_forced(b, p, q, m);
  return m;
}

// Gauss-Legendre nodes and weights of 8 points on [-1, 1] (Abramowitz & Stegun, table 25.4).
constexpr double gauss_nodes[DampedQuadrature::nodes / 2] = {0.1834346424956498, 0.5255324099163290,
                                                             0.7966664774136267, 0.9602898564975363};
constexpr double gauss_weights[DampedQuadrature::nodes / 2] = {0.3626837833783620, 0.3137066458778873,
                                                               0.2223810344533745, 0.1012285362903763};

DampedQuadrature damped_quadrature(int mode, double w, double zeta, double h, const Basis& b) {
  DampedQuadrature d;
  d.mode = mode, d.rate = 2 * zeta * w;
  for (int i = 0; i < DampedQuadrature::nodes; ++i) {
    const int k = i < DampedQuadrature::nodes / 2 ? i : i - DampedQuadrature::nodes / 2;
    const double x = i < DampedQuadrature::nodes / 2 ? -gauss_nodes[k] : gauss_nodes[k];
    const ModeCoefficients m = damped_mode_coefficients(w, zeta, h * (1 + x) / 2, b);
    d.weight[i] = h * gauss_weights[k] / 2;
    d.va[i] = -m[2], d.vv[i] = m[3];
    for (int j = 0; j < data_count; ++j) d.q[i][j] = m[free_count + data_count + j];
  }
  return d;
}

// A damped mode's step response, remembered by (omega, zeta, h, past ratio) for the step lengths
// that recur: a damped bat (Material::loss_factor) damps every vibrational mode, whose closed
// forms (an exponential, a sine and a cosine, a series) would otherwise be computed anew for every
// kept set of modes a run meets. Its dissipation quadrature (8 more times) is kept apart, and only
// where a run asks for it: most runs do not, and a small entry is cheaper to keep.
struct DampedKey {
  double w, zeta, h, past_ratio;
  bool operator==(const DampedKey&) const = default;
};
struct DampedKeyHash {
  std::size_t operator()(const DampedKey& k) const { return bits_hash(k.w, k.zeta, k.h, k.past_ratio); }
};

const ModeCoefficients& remembered_damped_response(const DampedKey& key, const Basis& b) {
  thread_local ThreadMemory<DampedKey, ModeCoefficients, DampedKeyHash> memory(8192);  // about 3 MB per thread
  return memory.get(key, [&] { return damped_mode_coefficients(key.w, key.zeta, key.h, b); });
}

const DampedQuadrature& remembered_damped_quadrature(const DampedKey& key, const Basis& b) {
  thread_local ThreadMemory<DampedKey, DampedQuadrature, DampedKeyHash> memory(4096);  // about 5 MB per thread
  return memory.get(key, [&] { return damped_quadrature(0, key.w, key.zeta, key.h, b); });
}

// Where the kernels write a response: the columns of a table laid out as ModeResponse's.
ResponseColumns response_columns(Eigen::ArrayXXd& table) {
  const auto at = [&table](int j) { return table.col(j).data(); };
  ResponseColumns r{at(0), at(1), at(2), at(3), {}, {}};
  for (int j = 0; j < data_count; ++j) r.d[j] = at(free_count + j), r.q[j] = at(free_count + data_count + j);
  return r;
}

// The undamped modes' (rows') responses to a step whose length recurs, remembered by (omega, h,
// past ratio) for this thread: `auto` keeps a different set of a bat's modes at nearly every
// impact, so a set's responses are mostly new while each mode's are not. The modes not met before
// are computed together (the kernel's result for a mode does not depend on the others: the same
// bits).
void remembered_undamped_responses(const Eigen::ArrayXd& omega, const std::vector<int>& rows, double h,
                                   double past_ratio, const double* basis, Eigen::ArrayXXd& table) {
  struct Key {
    double w, h, past_ratio;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const { return bits_hash(k.w, k.h, k.past_ratio); }
  };
  thread_local ThreadMemory<Key, ModeCoefficients, Hash> memory(8192);  // about 3 MB per thread
  thread_local std::vector<int> missing;
  missing.clear();
  for (const int i : rows) {
    if (const ModeCoefficients* kept = memory.find(Key{omega(i), h, past_ratio})) {
      for (int m = 0; m < ModeResponse::columns; ++m) table(i, m) = (*kept)[m];
    } else {
      missing.push_back(i);
    }
  }
  if (missing.empty()) return;
  const int count = static_cast<int>(missing.size());
  thread_local Eigen::ArrayXd w;
  thread_local Eigen::ArrayXXd made;
  w.resize(count), made.resize(count, ModeResponse::columns);
  for (int k = 0; k < count; ++k) w(k) = omega(missing[k]);
  undamped_responses(w.data(), count, h, basis, response_columns(made));
  for (int k = 0; k < count; ++k) {
    ModeCoefficients& kept = memory.keep(Key{w(k), h, past_ratio});
    for (int m = 0; m < ModeResponse::columns; ++m) kept[m] = table(missing[k], m) = made(k, m);
  }
}

// The basis as the kernels take it: row-major, row j the polynomial datum j weights.
std::array<double, data_count * powers> row_major(const Basis& b) {
  std::array<double, data_count * powers> basis;
  for (int j = 0; j < data_count; ++j)
    for (int k = 0; k < powers; ++k) basis[j * powers + k] = b(j, k);
  return basis;
}

double damping_of(const ModeResponse& r, int i) { return r.damping.size() ? r.damping(i) : 0.0; }

// Every mode's response made anew: all as if undamped, at once; the damped ones then made over.
void make_rows(ModeResponse& r, const Basis& b) {
  const int n = static_cast<int>(r.omega.size());
  undamped_responses(r.omega.data(), n, r.h, row_major(b).data(), response_columns(r.table));
  for (int i = 0; i < n; ++i) {
    if (damping_of(r, i) == 0) continue;
    const ModeCoefficients m = damped_mode_coefficients(r.omega(i), r.damping(i), r.h, b);
    for (int c = 0; c < ModeResponse::columns; ++c) r.table(i, c) = m[c];
  }
}

// Every mode's response from what the thread remembers: first the rows `like` has (a mode of the
// same frequency and damping, at the same step and past ratio), found by walking both sets of
// modes in step, as they mostly rise in frequency (the last set at this step, which shares most of
// its modes with this one while a study's points on one bat run); then the memories, the
// undamped modes not met before made all at once.
void remember_rows(ModeResponse& r, const Basis& b, const ModeResponse* like) {
  const int n = static_cast<int>(r.omega.size());
  const bool shared = like && like->h == r.h && like->past_ratio == r.past_ratio;
  const int like_n = shared ? static_cast<int>(like->omega.size()) : 0;
  thread_local std::vector<int> undamped;
  undamped.clear();
  for (int i = 0, j = 0; i < n; ++i) {
    while (j < like_n && like->omega(j) < r.omega(i)) ++j;
    if (j < like_n && like->omega(j) == r.omega(i) && damping_of(*like, j) == damping_of(r, i)) {
      r.table.row(i) = like->table.row(j);
    } else if (damping_of(r, i) == 0) {
      undamped.push_back(i);
    } else {
      const ModeCoefficients& m = remembered_damped_response({r.omega(i), r.damping(i), r.h, r.past_ratio}, b);
      for (int c = 0; c < ModeResponse::columns; ++c) r.table(i, c) = m[c];
    }
  }
  remembered_undamped_responses(r.omega, undamped, r.h, r.past_ratio, row_major(b).data(), r.table);
}

}  // namespace

ModeResponse::ModeResponse(const Eigen::ArrayXd& w, const Eigen::ArrayXd& zeta, double step, double ball_mass,
                           double past, bool with_quadrature, bool remember, const ModeResponse* like) {
  fill(w, zeta, step, ball_mass, past, with_quadrature, remember, like);
}

void ModeResponse::fill(const Eigen::ArrayXd& w, const Eigen::ArrayXd& zeta, double step, double ball_mass,
                        double past, bool with_quadrature, bool remember, const ModeResponse* like) {
  h = step, past_ratio = past, omega = w, damping = zeta, quadrature = with_quadrature, this->ball_mass = ball_mass;
  damped.clear();
  table.resize(omega.size(), columns);
  const Basis b = interpolant_basis(past_ratio, h);
  if (remember) remember_rows(*this, b, like);
  else make_rows(*this, b);
  for (int i = 0; quadrature && i < omega.size(); ++i) {
    if (damping_of(*this, i) == 0) continue;
    const DampedKey key{omega(i), damping(i), h, past_ratio};
    damped.push_back(remember ? remembered_damped_quadrature(key, b) : damped_quadrature(i, key.w, key.zeta, h, b));
    damped.back().mode = i;
  }
  const ModeCoefficients ball = mode_coefficients(0, h, b);
  for (int j = 0; j < data_count; ++j) {
    ball_d[j] = ball[free_count + j] / ball_mass;
    ball_q[j] = ball[free_count + data_count + j] / ball_mass;
  }
}

StepCoefficients::StepCoefficients(std::shared_ptr<const ModeResponse> r, const Eigen::ArrayXd& psi2,
                                   double compliance)
    : response(std::move(r)), psi2_sum(psi2.sum()) {
  const ModeResponse& m = *response;
  mode_dC = (psi2 * m.d(end_force)).sum(), mode_dD = (psi2 * m.d(end_rate)).sum();
  mode_qC = (psi2 * m.q(end_force)).sum(), mode_qD = (psi2 * m.q(end_rate)).sum();
  gC = mode_dC + m.ball_d[end_force] + compliance;
  gD = mode_dD + m.ball_d[end_rate];
  hC = mode_qC + m.ball_q[end_force];
  hD = mode_qD + m.ball_q[end_rate] + compliance;
}

namespace {

// The responses at the nominal step and at its split parts are the same for every impact
// that keeps the same modes (only the mode shapes at the contact differ), so each thread keeps
// them, keyed by step, past ratio, ball mass and frequencies. With modes = auto the kept set
// varies from impact to impact; the cache starts over when it grows large. Event steps, whose
// lengths never recur, are not kept (ExactStepper::event_coefficients).
std::shared_ptr<const ModeResponse> cached_response(const Eigen::ArrayXd& omega, const Eigen::ArrayXd& damping,
                                                    std::size_t omega_key, double h, double ball_mass,
                                                    double past_ratio, bool quadrature) {
  const std::size_t key = omega_key * 31 + bits_hash(h, ball_mass, past_ratio);
  thread_local std::unordered_multimap<std::size_t, std::pair<double, std::shared_ptr<const ModeResponse>>> cache;
  const auto [first, last] = cache.equal_range(key);
  for (auto it = first; it != last; ++it) {
    const auto& [mass, response] = it->second;
    if (response->h == h && response->past_ratio == past_ratio && mass == ball_mass &&
        response->omega.size() == omega.size() && (response->omega == omega).all() &&
        response->damping.size() == damping.size() && (response->damping == damping).all() &&
        response->quadrature == quadrature)
      return response;
  }
  thread_local std::size_t stored = 0;  // doubles held: at most about 3 MB per thread
  if (stored > 400'000) cache.clear(), stored = 0;
  stored += ModeResponse::columns * omega.size();
  // The last response made at each step and past ratio (a few in a run), whose modes the next
  // set mostly shares; a new step and ratio takes the slots in turn.
  thread_local std::array<std::shared_ptr<const ModeResponse>, 16> recent;
  thread_local std::size_t next_slot = 0;
  auto like = std::find_if(recent.begin(), recent.end(),
                           [&](const auto& r) { return r && r->h == h && r->past_ratio == past_ratio; });
  auto response = std::make_shared<const ModeResponse>(omega, damping, h, ball_mass, past_ratio, quadrature, true,
                                                       like == recent.end() ? nullptr : like->get());
  if (like == recent.end()) like = recent.begin() + next_slot++ % recent.size();
  *like = response;
  cache.emplace(key, std::make_pair(ball_mass, response));
  return response;
}

}  // namespace

std::size_t ExactStepper::frequencies_key(const Eigen::ArrayXd& omega, const Eigen::ArrayXd& damping) {
  return hash_range(hash_range(omega.size(), omega), damping);
}

ExactStepper::ExactStepper(const ContactState& state, const CollisionOptions& options)
    : state_(state), options_(options), psi_(state.body().psi.array()), psi2_(psi_.square()),
      psi_w2_(psi_ * state.omega2()),
      damping_(state.body().damped() ? Eigen::ArrayXd(state.body().damping_ratio.array()) : Eigen::ArrayXd()),
      omega_key_(frequencies_key(state.body().omega.array(), damping_)), nominal_(options.dt),
      slowest_force_ratio_(std::exp(-force_rate_limit * nominal_)),
      quarter_(state.size()), half_(state.size()) {
  kept_.reserve(16);  // a contact's usual lengths: split, nominal, halved and event steps
}

const StepCoefficients& ExactStepper::coefficients(double h, double past_ratio) {
  for (const StepCoefficients& k : kept_)
    if (k.h() == h && k.past_ratio() == past_ratio) return k;
  kept_.emplace_back(
      cached_response(state_.body().omega.array(), damping_, omega_key_, h, state_.ball_mass(), past_ratio,
                      options_.damping_loss),
      psi2_,
      state_.compliance());
  return kept_.back();
}

StepCoefficients ExactStepper::event_coefficients(double h) {
  // A small table per thread whose slots are responses filled in place: an event step met again
  // (a scene run again) finds its response; a new one takes its slot over, with no allocation once
  // the slot has the size. (Keeping every event step grew maps with lengths that never recur.)
  // A response is used within one call of locate() only, so a slot can be refilled at the next.
  struct Slot {
    std::size_t key = 0;
    bool filled = false;
    std::shared_ptr<ModeResponse> response = std::make_shared<ModeResponse>();
  };
  constexpr std::size_t slots = 64;
  thread_local std::array<Slot, slots> table;
  const Eigen::ArrayXd& omega = state_.body().omega.array();
  const double mass = state_.ball_mass();
  const std::size_t key = omega_key_ * 31 + bits_hash(h, mass);
  Slot& slot = table[key % slots];
  ModeResponse& r = *slot.response;
  const bool same = slot.filled && slot.key == key && r.h == h && r.ball_mass == mass &&
                    r.quadrature == options_.damping_loss && r.omega.size() == omega.size() && (r.omega == omega).all() &&
                    r.damping.size() == damping_.size() && (r.damping == damping_).all();
  if (!same) {
    r.fill(omega, damping_, h, mass, 0, options_.damping_loss, false);
    slot.key = key, slot.filled = true;
  }
  return StepCoefficients(slot.response, psi2_, state_.compliance());
}

double ExactStepper::past_ratio(const Eigen::VectorXd& y, double h, const ContactForce& law) const {
  const bool continues = past_.expanding == law.expanding() && starts_where_past_ended(y);
  // Past data far from the step (ratio over 8) add little; close to it (under 1/4) they would
  // make the interpolant ill-conditioned.
  const double ratio = past_.h / h;
  return continues && ratio >= 0.25 && ratio <= 8 ? ratio : 0.0;
}

void ExactStepper::step(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out) {
  past_at_step_start_ = past_;
  if (const double ratio = past_ratio(y, h, law); ratio > 0) return advance(coefficients(h, ratio), y, law, out);
  advance(coefficients(h / 4, 0), y, law, quarter_);
  advance(coefficients(h / 4, 1), quarter_, law, half_);
  advance(coefficients(h / 2, 0.5), half_, law, out);
}

double ExactStepper::locate(const Eigen::VectorXd& y, double h, const ContactForce& law, ContactEvent event,
                            Eigen::VectorXd& out) {
  const double f0 = event_value(state_, event, y, law), d0 = event_rate(state_, event, y, law) * h;
  const double f1 = event_value(state_, event, out, law), d1 = event_rate(state_, event, out, law) * h;
  // The root of the cubic keeps a bracket with the cubic > 0 at `lo` and <= 0 at `hi`: a step
  // ending just short of separation would leave the ball touching, and the next contact would
  // start at once.
  const auto cubic = [&](double s) { return hermite(s, f0, d0, f1, d1); };
  const double hi = falling_root(cubic, 0.0, 1.0, f0, f1, [](double a, double b) { return b - a <= 1e-14; }, 100).hi;
  if (hi >= 1) return h;  // `out` already is the state at the end of the step
  // The event step ends on a 1/4096 grid of the step just past the root. Where it lands (within
  // h/4096, ~2 ns at 10 us) changes nothing that matters: the force is stationary there (F' = 0
  // at maximum compression, F = 0 at separation) and the loop's energy is exact anyway.
  // Separation keeps the root's own time, for the contact time; free flight from there is exact.
  const double fraction = std::ceil(hi * event_grid) / event_grid;
  if (fraction >= 1) return h;
  // Its length is new at every impact, so its response is computed afresh: the cubic's, in one
  // piece (the quintic's would need its own basis, and a split step three responses).
  advance(event_coefficients(fraction * h), y, law, out);
  // Where the cubic put the root early and the ball still touches there (7.6e-6 m after a 20 us step
  // of a linear ball), the step is the state's: the contact goes on (Collision separates at u <= 0).
  const bool parted = event == ContactEvent::separation && event_value(state_, event, out, law) <= 0;
  return parted ? hi * h : fraction * h;
}

// At first touch the force grows as (u' t)^a, which no cubic follows; the slope given for it at
// t = 0 is the one that makes the cubic's impulse over the step that of the power law (through
// the end's F1 ~ F(u' h) and F1' = a F1 / h): (F1 / h) (a + 12 / (a + 1) - 6), the secant's
// k1 for a linear ball, nearly 0 for a = 1.84, and exact in the limit a = 2 (F'(0) = 0).
double touch_stiffness(const ContactForce& law, double u_end) {
  if (law.expanding() || !(u_end > 0)) return law.stiffness(0);
  const double a = law.exponent();
  return law(u_end) / u_end * (a + 12 / (a + 1) - 6);
}

// Solves for the end compression u1 with F1 = F(u1) and F1' = F'(u1) u1': Newton on
// g(u) = u - u_known + gC F(u) + gD F1'(u), kept inside [0, u_known] where g changes sign.
// `guess` is a prediction of u1 (advance: extrapolated from the past step, or a Taylor step).
constexpr int newton_patience = 8;  // a baseball's steps take 1 or 2 iterations

double end_compression(const StepCoefficients& k, const ContactForce& law, double u_known, double du_known,
                       double guess) {
  if (u_known <= 0) return u_known;  // no force can arise: the ball is clear all step
  const double e = law.exponent();
  // The force at the first iterate from the law (a pow), at the others, close to it, from its
  // binomial series: F(u) = F(u_ref) (1 + x)^e, x = u / u_ref - 1, which to the 6th power in x
  // is exact to round-off while |e x| <= 1e-3 (the rest is below (e x)^7 / 7!). Newton's steps
  // from a good guess are that small: one pow a step instead of one an iteration.
  double u_ref = -1, f_ref = 0, inverse_ref = 0;
  const auto force = [&](double u) {
    const double x = (u - u_ref) * inverse_ref;
    if (u_ref > 0 && std::abs(e * x) <= 1e-3)
      return f_ref * (1 + e * x * (1 + (e - 1) / 2 * x * (1 + (e - 2) / 3 * x * (1 + (e - 3) / 4 * x *
                                   (1 + (e - 4) / 5 * x * (1 + (e - 5) / 6 * x))))));
    u_ref = u, f_ref = law(u), inverse_ref = 1 / u;
    return f_ref;
  };
  const auto g = [&](double u, double& slope) {
    const double f = force(u), inverse_u = 1 / u, stiffness = e * f * inverse_u;
    const double stiffness_rate = (e - 1) * stiffness * inverse_u;
    const double inverse_denominator = 1 / (1 + k.hD * stiffness), numerator = du_known - k.hC * f;
    const double rate = stiffness * numerator * inverse_denominator;
    const double rate_slope = (stiffness_rate * numerator - stiffness * k.hC * stiffness -
                               rate * k.hD * stiffness_rate) * inverse_denominator;
    slope = 1 + k.gC * stiffness + k.gD * rate_slope;
    return u - u_known + k.gC * f + k.gD * rate;
  };
  double lo = 0, hi = u_known, slope = 0;
  double u = guess > 0 && guess < u_known ? guess : u_known;  // from above, Newton does not overshoot
  // Newton converges quadratically: after a step of x u the error is about K x^2 u, K = u |g''| /
  // 2 g' at most 1 + |e - 1| / 2 for the power law. It stops once that is below 1e-13 of u:
  // (x u)^2 K <= 1e-13 u^2, without a square root or a division.
  const double k_bound = 1 + std::abs(e - 1) / 2;
  double last_move = hi - lo;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double value = g(u, slope);
    (value <= 0 ? lo : hi) = u;  // a force that overflowed (NaN) lies past the root: F dominates g
    double next = u - value / slope;
    if ((next - u) * (next - u) * k_bound <= 1e-13 * u * u) {
      law.remember(next, force(next));
      return next;
    }
    // The bracket has closed on the root; a Newton step out of it (or NaN, from a force that
    // overflowed) is no answer, the bracket's end is.
    if (hi - lo <= 1e-15 * hi) return next >= lo && next <= hi ? next : u;
    // Near separation the force is all but zero and the root sits at the bracket's top, u_known:
    // Newton may land on or just past it, which bisection would approach only slowly.
    if (next >= hi && value < 0 && slope > 0) next = hi;
    else if (!(next > lo && next < hi) || !(slope > 0)) next = (lo + hi) / 2;
    // From far past the root on a steep branch (a linear ball at e0 0.06 expands as u^555),
    // Newton creeps, each step about u / e, and 100 of them stop short with a force 1e9 times
    // too large. Past the few iterations a good guess needs, a step that does not halve the last
    // one gives way to bisection, which the bracket's sign test keeps on the root.
    else if (iteration >= newton_patience && std::abs(next - u) > last_move / 2) next = (lo + hi) / 2;
    last_move = std::abs(next - u);
    u = next;
  }
  return u;
}

// The damped modes' a'(t) at the step's Gauss nodes is linear in the start state and the data the
// interpolant weights, all known once the end force is: int 2 zeta w a'^2 dt by the quadrature.
double ExactStepper::damped_dissipation(const ModeResponse& m, const Eigen::VectorXd& y,
                                        const double (&data)[data_count]) const {
  const int n = state_.modes();
  double energy = 0;
  for (const DampedQuadrature& d : m.damped) {
    const double a = y(2 + d.mode), v = y(2 + n + d.mode), psi = psi_(d.mode);
    for (int i = 0; i < DampedQuadrature::nodes; ++i) {
      double forced = 0;
      for (int j = 0; j < data_count; ++j) forced += data[j] * d.q[i][j];
      const double rate = d.va[i] * a + d.vv[i] * v - psi * forced;
      energy += d.weight[i] * d.rate * rate * rate;
    }
  }
  return energy;
}

// One pass over the modes for what is known before the end force (free rotation plus the
// response to the past and start data), summing the contact's u and u' on the way; a second adds
// the response to F1 and F1' (mode_kernels.hpp: Eigen would make a pass per expression and one
// per sum, and its sums' order would change with the vector unit).
void ExactStepper::advance(const StepCoefficients& k, const Eigen::VectorXd& y, const ContactForce& law,
                           Eigen::VectorXd& out) {
  const ModeResponse& m = *k.response;
  const int n = state_.modes();
  out.resize(y.size());
  double *out_a = out.data() + 2, *out_v = out_a + n;
  const auto d = [&m](Datum j) { return m.d(j).data(); };
  const auto q = [&m](Datum j) { return m.q(j).data(); };

  // The start: the ball's compression, its rate and acceleration, the force and its rate.
  const double u0 = state_.ball_compression(state_.compression(y), law), du0_geometric = state_.compression_rate(y);
  const double f0 = law(u0), k0 = u0 <= 0 ? touch_stiffness(law, du0_geometric * m.h) : law.stiffness(u0);
  const double du0 = du0_geometric / (1 + state_.compliance() * k0), r0 = k0 * du0;
  const bool quintic = m.past_ratio > 0;
  const double fp = quintic ? past_.force : 0.0, rp = quintic ? past_.rate : 0.0;

  const StepArrays arrays{y.data() + 2, y.data() + 2 + n, m.c().data(), m.sn().data(), m.w2sn().data(), m.cv().data(),
                          psi_.data(), psi_w2_.data(), {d(past_force), d(past_rate), d(start_force), d(start_rate)},
                          {q(past_force), q(past_rate), q(start_force), q(start_rate)}, out_a, out_v};
  const auto [psi_a, psi_v, psi_w2a] = step_known(n, arrays, {fp, rp, f0, r0});
  const double s_known = y(0) + y(1) * m.h + fp * m.ball_d[past_force] + rp * m.ball_d[past_rate] +
                         f0 * m.ball_d[start_force] + r0 * m.ball_d[start_rate];
  const double vb_known = y(1) + fp * m.ball_q[past_force] + rp * m.ball_q[past_rate] + f0 * m.ball_q[start_force] +
                          r0 * m.ball_q[start_rate];
  const double u_known = psi_a - s_known, du_known = psi_v - vb_known;

  // The geometric compression's acceleration, then the ball's own: from u_ball + c F(u_ball) = u,
  // u_ball'' (1 + c F') = u'' - c F'' u_ball'^2 (the same without a residual compliance c).
  const double ddu_geometric = -psi_w2a - f0 * (k.psi2_sum + 1 / state_.ball_mass());
  const double c = state_.compliance(), e = law.exponent();
  const double ddu0 = c == 0 || u0 <= 0 ? ddu_geometric
                                        : (ddu_geometric - c * e * (e - 1) * f0 / (u0 * u0) * du0 * du0) / (1 + c * k0);
  // Newton's first iterate: with a past step, the end force extrapolated (the cubic through the
  // past and start force and rate) and the compression the step's linear relation gives for it;
  // it is mostly within what Newton's test accepts after one evaluation (one pow a step), where the
  // Taylor guess from the start, which the modes' ringing puts off, took two. Without, that guess.
  double guess = u0 + m.h * du0 + 0.5 * m.h * m.h * ddu0;
  if (quintic) {
    const double a = past_.h, t = m.h;
    const double r1 = fp - f0 + r0 * a, r2 = rp - r0;  // p(t) = f0 + r0 t + c2 t^2 + c3 t^3
    const double c3 = (r2 + 2 * r1 / a) / (a * a), c2 = r1 / (a * a) + c3 * a;
    const double f1 = f0 + t * (r0 + t * (c2 + t * c3)), df1 = r0 + t * (2 * c2 + 3 * t * c3);
    guess = u_known - k.gC * f1 - k.gD * df1;
  }
  const double u1 = end_compression(k, law, u_known, du_known, guess);
  const double f1 = law(u1);
  const double stiffness = u1 > 0 ? law.exponent() * f1 / u1 : 0.0;
  const double r1 = stiffness * (du_known - k.hC * f1) / (1 + k.hD * stiffness);

  out(0) = s_known + f1 * m.ball_d[end_force] + r1 * m.ball_d[end_rate];
  out(1) = vb_known + f1 * m.ball_q[end_force] + r1 * m.ball_q[end_rate];
  step_end(n, out_a, out_v, psi_.data(), d(end_force), d(end_rate), q(end_force), q(end_rate), f1, r1);
  if (const int k = state_.dissipated_index(); k >= 0)
    out(k) = y(k) + damped_dissipation(m, y, {fp, rp, f0, r0, f1, r1});
  // The end's u and u' follow from the sums already made, without another pass over the modes.
  // The geometric u is the ball's own plus the residual compliance's yield (equal to the sums to
  // round-off, and exactly consistent with u1, whose force is known).
  state_.remember(out, u1 + state_.compliance() * f1, psi_v - f1 * k.mode_qC - r1 * k.mode_qD - out(1), law, u1);
  past_ = {m.h, f0, r0, out(0), out(1), law.expanding(), f1};
}

}  // namespace sweetspot::detail
