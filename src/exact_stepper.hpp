#pragma once
// Internal: exact modal stepping. Over a step the contact force is the cubic Hermite interpolant
// of F and dF/dt at its ends; every mode (and the ball) then advances in closed form, so the step
// is limited by how well the cubic follows the force pulse, never by the fastest mode. The force
// at the end of the step solves one scalar equation in the end compression u1. All 2N modes cost
// O(2N) per step.
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "contact_state.hpp"

namespace sweetspot::detail {

// The closed-form response of every mode over a step of length h: the free rotation (c, sn,
// w2sn) and the displacement (d) and velocity (q) driven by a unit weight of each Hermite basis
// function, A (F0), B (F0'), C (F1), D (F1'). Depends on the frequencies and h only.
struct ModeResponse {
  double h = 0;
  Eigen::ArrayXd omega;
  Eigen::ArrayXd c, sn, w2sn;
  Eigen::ArrayXd dA, dB, dC, dD, qA, qB, qC, qD;
  double ball_d[4] = {}, ball_q[4] = {};  // the ball (omega = 0, times 1/m), for A, B, C, D

  // memoize: take each mode's coefficients from (and add them to) this thread's memory.
  ModeResponse(const Eigen::ArrayXd& omega, double h, double ball_mass, bool memoize = false);
};

// A response for one contact point: the force drives mode n as -psi_n F, so each mode's response
// is kept times psi_n; and the sums over the modes that tie the ball's compression u1 and its rate
// at the end of the step to F1 and F1': u1 = known - gC F1 - gD F1', u1' = known - hC F1 - hD F1'
// (the residual compliance c of dropped modes adds c F1 to the first and c F1' to the second).
struct StepCoefficients {
  std::shared_ptr<const ModeResponse> response;
  enum Column { dA, dB, qA, qB, dC, dD, qC, qD };
  Eigen::ArrayXXd driven;  // psi_n times the response to A, B, C, D: one column each (Column)
  double gC = 0, gD = 0, hC = 0, hD = 0;
  double psi2_sum = 0;  // sum psi_n^2: how the force accelerates the compression
  // The modes' part alone of those sums (no ball, no compliance): sum psi^2 dC, dD, qC, qD.
  double mode_dC = 0, mode_dD = 0, mode_qC = 0, mode_qD = 0;

  StepCoefficients() = default;
  StepCoefficients(std::shared_ptr<const ModeResponse> r, const Eigen::ArrayXd& psi, double compliance);
  double h() const { return response ? response->h : 0; }
};

class ExactStepper {
 public:
  ExactStepper(const ContactState& state, const CollisionOptions& options);

  // A contact starts with steps of h/16, h/8, h/4, h/2: the force grows as t^a from first
  // touch, which no cubic follows, and short first steps keep that error below the rest.
  double first_step() const { return nominal_.h() / 16; }
  std::string refusal() const { return {}; }  // unconditionally stable
  StepOutcome attempt(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out) {
    step(y, h, law, out);
    return {true, std::min(nominal_.h(), 2 * h)};
  }
  void step(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out);
  // A step of a new length costs a new response, so an event is found as the root of the cubic
  // Hermite interpolant of its value over the step (error O(h^4) in time, and the force is
  // stationary there: F' = 0 at maximum compression, F = 0 at separation), then one step to it.
  double locate(const Eigen::VectorXd& y, double h, const ContactForce& law, ContactEvent event,
                Eigen::VectorXd& out);

 private:
  void advance(const StepCoefficients& k, const Eigen::VectorXd& y, const ContactForce& law, Eigen::VectorXd& out);
  // Responses are kept per thread by frequencies and step; the frequencies' hash is made once.
  static std::size_t frequencies_key(const Eigen::ArrayXd& omega);
  std::shared_ptr<const ModeResponse> response(double h) const;

  const ContactState& state_;
  Eigen::ArrayXd psi_, psi_w2_;  // mode shapes at the contact, and times omega^2
  std::size_t omega_key_;
  StepCoefficients nominal_, other_;
  std::vector<StepCoefficients> graded_;
};

}  // namespace sweetspot::detail
