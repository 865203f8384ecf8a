#include "sweetspot/impact/histories.hpp"

#include <algorithm>
#include <cmath>

#include "contact/exact_stepper.hpp"

namespace sweetspot {

namespace {

// F and dF/dt at time t from the force samples (cubic Hermite between them, zero outside).
ForceSample force_at(const std::vector<ForceSample>& force, double t) {
  const auto after = std::upper_bound(force.begin(), force.end(), t, [](double x, const ForceSample& s) {
    return x < s.t;
  });
  if (after == force.begin() || after == force.end()) return {t, 0, 0};
  return interpolate_force(*(after - 1), *after, t);
}

void reserve(ProbeHistory& p, std::size_t n) {
  for (auto* v : {&p.displacement, &p.velocity, &p.acceleration, &p.vibration_displacement, &p.vibration_velocity,
                  &p.vibration_acceleration})
    v->reserve(n);
}

}  // namespace

Histories impact_histories(const ModalBasis& basis, const SceneGeometry& g, const Ball& ball, double ball_speed,
                           const std::vector<ForceSample>& force, const HistoryRequest& request) {
  const ModalContact& body = g.contact;
  const int n = body.count();
  const std::size_t samples = request.samples();
  // The damped wall mode (if any) in closed form too: its free evolution and forced response.
  const Eigen::ArrayXd damping = body.damped() ? Eigen::ArrayXd(body.damping_ratio.array()) : Eigen::ArrayXd();
  const detail::ModeResponse response(body.omega.array(), damping, request.step, ball.mass, 0);  // cubic
  const Eigen::ArrayXd psi = body.psi.array(), omega2 = body.omega.array().square();
  // 2 zeta omega of each mode (0: undamped), for the accelerations.
  const Eigen::ArrayXd damping_rate = damping.size() ? Eigen::ArrayXd(2 * damping * body.omega.array()) : damping;
  const Eigen::ArrayXd vibrating = (body.omega.array() > 0).cast<double>();

  std::vector<Eigen::ArrayXd> probe_shapes;
  for (double z : request.probes) probe_shapes.push_back(g.shapes_at(basis, z).array());
  Eigen::ArrayXd a = Eigen::ArrayXd::Zero(n), v = body.velocity0.array();
  double s = 0, vb = -ball_speed;

  Histories h;
  h.probes.resize(request.probes.size());
  for (ProbeHistory& p : h.probes) reserve(p, samples);
  std::vector<double> start_velocity;
  for (const Eigen::ArrayXd& shape : probe_shapes) start_velocity.push_back((shape * v).sum());
  ForceSample f0 = force_at(force, 0);
  for (std::size_t j = 0; j < samples; ++j) {
    const double t = j * request.step;
    Eigen::ArrayXd acceleration = -omega2 * a - psi * f0.force;
    if (damping.size()) acceleration -= damping_rate * v;
    h.time.push_back(t);
    h.force.push_back(f0.force);
    // The ball's own compression: the bat's local and residual compliance yields c F of the approach.
    h.compression.push_back((psi * a).sum() - s - body.residual_compliance * f0.force);
    h.ball_position.push_back(s);
    for (std::size_t k = 0; k < probe_shapes.size(); ++k) {
      const Eigen::ArrayXd& shape = probe_shapes[k];
      ProbeHistory& p = h.probes[k];
      p.displacement.push_back((shape * a).sum() - start_velocity[k] * t);
      p.velocity.push_back((shape * v).sum() - start_velocity[k]);
      p.acceleration.push_back((shape * acceleration).sum());
      p.vibration_displacement.push_back((shape * vibrating * a).sum());
      p.vibration_velocity.push_back((shape * vibrating * v).sum());
      p.vibration_acceleration.push_back((shape * vibrating * acceleration).sum());
    }
    // Advance one interval in closed form under the cubic force through (F, F') at its ends.
    const ForceSample f1 = force_at(force, t + request.step);
    const auto forcing = [&](auto r) {  // r: the response's d or q column of a datum
      return f0.force * r(detail::start_force) + f0.rate * r(detail::start_rate) + f1.force * r(detail::end_force) +
             f1.rate * r(detail::end_rate);
    };
    const auto d = [&](detail::Datum j) { return response.d(j); };
    const auto q = [&](detail::Datum j) { return response.q(j); };
    const Eigen::ArrayXd a_next = response.c() * a + response.sn() * v - psi * forcing(d);
    v = response.cv() * v - response.w2sn() * a - psi * forcing(q);
    a = a_next;
    const auto ball = [&](const double* r) {
      return f0.force * r[detail::start_force] + f0.rate * r[detail::start_rate] + f1.force * r[detail::end_force] +
             f1.rate * r[detail::end_rate];
    };
    s += vb * request.step + ball(response.ball_d);
    vb += ball(response.ball_q);
    f0 = f1;
  }
  return h;
}

}  // namespace sweetspot
