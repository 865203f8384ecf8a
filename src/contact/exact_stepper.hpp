#pragma once
// Internal: exact modal stepping. Over a step the contact force is a polynomial interpolant of
// F and dF/dt; every mode (and the ball) then advances in closed form, so the step is limited by
// how well the polynomial follows the force pulse, never by the fastest mode. The force at the
// end of the step solves one scalar equation in the end compression u1. All 2N modes cost O(2N)
// per step.
//
// Two interpolants: the cubic Hermite of (F, F') at the step's ends (order 4), and, where the
// previous step ended at this one's start on the same branch of the force law, the quintic
// through (F, F') at its start too (order 6: the same unknowns F1, F1', the past data known).
// The past step's length over this one's, the past ratio, shapes the quintic; 0 means cubic.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_state.hpp"

namespace sweetspot::detail {

// The data an interpolant weights, in this order: F and F' a step before the start (quintic
// only), at the start, at the end.
enum Datum { past_force, past_rate, start_force, start_rate, end_force, end_rate, data_count };

// A damped mode's velocity at the Gauss-Legendre nodes of a step, each linear in the step's start
// state and data (a' = va a + vv a' - psi sum_j datum_j q[j]), with the nodes' weights: the
// energy its damping dissipates over the step is sum_i weight_i rate a'(t_i)^2, rate = 2 zeta w.
struct DampedQuadrature {
  static constexpr int nodes = 8;  // exact for polynomials of degree 15
  int mode = 0;
  double rate = 0;
  double weight[nodes] = {};
  double va[nodes] = {}, vv[nodes] = {}, q[nodes][data_count] = {};
};

// The closed-form response of every mode over a step of length h: the free evolution
// (a -> c a + sn a', a' -> cv a' - w2sn a; cv = c for an undamped mode) and the displacement (d)
// and velocity (q) driven by a unit weight of each datum's basis function (one column per Datum;
// zero for the past data of the cubic). Depends on the frequencies, damping ratios (empty: none),
// h and the past ratio only. Damped modes (damped_mode.hpp) also carry their quadrature.
struct ModeResponse {
  using Column = Eigen::Map<const Eigen::ArrayXd>;
  static constexpr int free_columns = 4;                            // c, sn, w2sn, cv
  static constexpr int columns = free_columns + 2 * data_count;  // then d and q of each datum
  double h = 0;
  double past_ratio = 0;
  double ball_mass = 0;  // kg
  Eigen::ArrayXd omega, damping;
  // One row per mode, the columns in the order above: one allocation for all of a response (a
  // study's impacts with modes = auto meet a new set of modes at nearly every impact).
  Eigen::ArrayXXd table;
  double ball_d[data_count] = {}, ball_q[data_count] = {};  // the ball (omega = 0, times 1/m)
  std::vector<DampedQuadrature> damped;  // empty without `quadrature`
  bool quadrature = true;

  // quadrature: the damped modes' dissipation quadrature too (CollisionOptions::damping_loss).
  // remember: take each mode's coefficients from (and add them to) this thread's memory, for the
  // lengths that recur from impact to impact: `auto` keeps a different set of modes at nearly
  // every impact, and a damped mode's closed forms cost an exponential and a sine and cosine at 9
  // times. like (with remember): a response whose rows for the same modes are copied first.
  ModeResponse(const Eigen::ArrayXd& omega, const Eigen::ArrayXd& damping, double h, double ball_mass,
               double past_ratio, bool quadrature = true, bool remember = false, const ModeResponse* like = nullptr);
  ModeResponse() = default;
  // Computes the response anew in place: the arrays keep their memory when the size is the same.
  void fill(const Eigen::ArrayXd& omega, const Eigen::ArrayXd& damping, double h, double ball_mass, double past_ratio,
            bool quadrature, bool remember, const ModeResponse* like = nullptr);

  Column column(int j) const { return Column(table.col(j).data(), table.rows()); }
  Column c() const { return column(0); }
  Column sn() const { return column(1); }
  Column w2sn() const { return column(2); }
  Column cv() const { return column(3); }
  Column d(Datum j) const { return column(free_columns + j); }
  Column q(Datum j) const { return column(free_columns + data_count + j); }
};

// A response with the sums over the contact point's mode shapes that tie the ball's compression
// u1 and its rate at the end of the step to F1 and F1': u1 = known - gC F1 - gD F1',
// u1' = known - hC F1 - hD F1' (the residual compliance c of dropped modes adds c F1 to the first
// and c F1' to the second).
struct StepCoefficients {
  std::shared_ptr<const ModeResponse> response;
  double gC = 0, gD = 0, hC = 0, hD = 0;
  double psi2_sum = 0;  // sum psi_n^2: how the force accelerates the compression
  // The modes' part alone of those sums (no ball, no compliance): sum psi^2 dC, dD, qC, qD.
  double mode_dC = 0, mode_dD = 0, mode_qC = 0, mode_qD = 0;

  StepCoefficients(std::shared_ptr<const ModeResponse> r, const Eigen::ArrayXd& psi2, double compliance);
  double h() const { return response->h; }
  double past_ratio() const { return response->past_ratio; }
};

class ExactStepper {
 public:
  ExactStepper(const ContactState& state, const CollisionOptions& options);

  // A contact's first step has no past, so it is split (below): the quarter steps also follow
  // the force's t^a growth from first touch, which no polynomial does, closely enough.
  double first_step() const { return nominal_; }
  std::string refusal() const { return {}; }  // stable at any step for the modes
  StepOutcome attempt(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out) {
    // The force the last step ended with, where this one starts (no pow), else the law's.
    const double start_force = !law.expanding()              ? 0.0
                               : starts_where_past_ended(y) ? past_.end_force
                                                            : state_.force(y, law);
    step(y, h, law, out);
    if (too_stiff_at_end(state_, out, h, law, options_) || outruns(start_force, past_.end_force, h, law)) {
      past_ = past_at_step_start_;  // as if the step had not been made
      return {false, h / 2};
    }
    return {true, std::min(nominal_, 2 * h)};
  }
  // A step with no past to weight (a contact's first, the first after maximum compression) is
  // made as a cubic quarter step and quintic quarter and half steps: its error then falls below
  // the quintic steps' own. After a step halved for stiffness, steps grow back by doubling.
  void step(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out);
  // Forgets the last step made, a trial whose state is not taken: the next step weights the past
  // of the one before it, as if the trial had not been made.
  void forget_step() { past_ = past_at_step_start_; }
  // A step of a new length costs a new response, so an event is found as the root of the cubic
  // Hermite interpolant of its value over the step (error O(h^4) in time, and the force is
  // stationary there: F' = 0 at maximum compression, F = 0 at separation), then one step to it.
  // Returns the time to the event; where the ball proves to touch still, to the state.
  double locate(const Eigen::VectorXd& y, double h, const ContactForce& law, ContactEvent event,
                Eigen::VectorXd& out);

 private:
  // The start of the last step made: its length, branch, force and rate, and where it ended (and
  // with what force). The next step may weight that force and rate only if it starts there, as long,
  // on the same branch (the force's second derivative jumps at maximum compression).
  struct PastStep {
    double h = 0, force = 0, rate = 0, end_s = 0, end_v = 0;
    bool expanding = false;
    double end_force = 0;
  };

  // Whether the expanding ball's force rises or falls over a step of length h faster than the
  // step's polynomial in time can follow. A nearly dead ball's can fall from F_m to nothing
  // within a step (a linear ball at e0 0.06 expands as F ~ u^555, which vanishes as u falls 1 %),
  // and the energy such a step makes or loses shows in no balance (the bat holds it: the torpedo
  // on the rig came back 34 % slow at 10 us). Where the force at either end counts (over 0.1 %
  // of F_m: the impulse of a tail left below 1 % moved v_f by 4e-4), it may change by at most a
  // factor exp(force_rate_limit * dt) (4 at 10 us), else the step is halved: the parts scale with
  // the nominal step, so step doubling sees their error too.
  bool outruns(double start_force, double end_force, double h, const ContactForce& law) const {
    if (!law.expanding() || !(h > smallest_step)) return false;
    const double larger = std::max(start_force, end_force), smaller = std::min(start_force, end_force);
    return larger > 1e-3 * law.f_max() && smaller < larger * slowest_force_ratio_;
  }
  // 1/s: ln 4 per 10 us, twice the fastest a baseball's force falls (2-fold in a 10 us step).
  static constexpr double force_rate_limit = 1.386e5;

  // Whether a step from y starts where the last one ended (the ball's place and speed the same).
  bool starts_where_past_ended(const Eigen::VectorXd& y) const { return y(0) == past_.end_s && y(1) == past_.end_v; }
  // The past ratio a step from y of length h can use (0: none, cubic).
  double past_ratio(const Eigen::VectorXd& y, double h, const ContactForce& law) const;
  void advance(const StepCoefficients& k, const Eigen::VectorXd& y, const ContactForce& law, Eigen::VectorXd& out);
  // The coefficients of a step whose length recurs (the nominal step, its split parts, halved
  // steps): kept for this impact, and their responses for the thread's later impacts.
  const StepCoefficients& coefficients(double h, double past_ratio);
  // An event step's: its length is new at every impact of a study, so its response is made in
  // one slot of a small per-thread table, filled in place (keeping every one filled the thread's
  // memory with lengths that never recur, an allocation and a cache miss each).
  StepCoefficients event_coefficients(double h);
  // Responses are kept per thread by frequencies, damping and step; the hash is made once.
  static std::size_t frequencies_key(const Eigen::ArrayXd& omega, const Eigen::ArrayXd& damping);
  // The energy the damped modes dissipate over the step from y, given the data it weighted.
  double damped_dissipation(const ModeResponse& m, const Eigen::VectorXd& y, const double (&data)[data_count]) const;

  const ContactState& state_;
  CollisionOptions options_;
  Eigen::ArrayXd psi_, psi2_, psi_w2_;  // mode shapes at the contact, squared, and times omega^2
  Eigen::ArrayXd damping_;              // the modes' damping ratios, empty when none is damped
  std::size_t omega_key_;
  double nominal_;
  double slowest_force_ratio_;  // exp(-force_rate_limit * nominal_): outruns()
  std::vector<StepCoefficients> kept_;  // this impact's steps so far, by length and past ratio
  PastStep past_, past_at_step_start_;  // the latter restored when a step is redone shorter
  Eigen::VectorXd quarter_, half_;      // the states inside a split step
};

}  // namespace sweetspot::detail
