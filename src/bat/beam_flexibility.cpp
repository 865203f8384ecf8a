#include "bat/beam_flexibility.hpp"

#include <lapacke.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "bat/banded_eigensolver.hpp"

namespace sweetspot {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

constexpr int kd = beam_bandwidth;

}  // namespace

// The beam held at the knob: K without its first two degrees of freedom, positive definite,
// Cholesky-factored in LAPACK's lower band storage (l[i - j + j (kd + 1)] = L(i, j)).
class HeldBeam {
 public:
  explicit HeldBeam(const Eigen::SparseMatrix<double>& k) : n_(static_cast<int>(k.rows()) - 2), l_((kd + 1) * n_, 0.0) {
    for (int j = 0; j < n_; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(k, j + 2); it; ++it)
        if (it.row() >= j + 2) l_[it.row() - 2 - j + j * (kd + 1)] = it.value();
    if (LAPACKE_dpbtrf_work(LAPACK_COL_MAJOR, 'L', n_, kd, l_.data(), kd + 1) != 0)
      throw std::runtime_error("the beam's flexibility: its stiffness held at the knob is not positive definite");
  }
  // C f: the held beam's displacement under f, zero at the two held degrees of freedom.
  MatrixXd displacement(const MatrixXd& f) const {
    MatrixXd u = f.bottomRows(n_);
    LAPACKE_dpbtrs_work(LAPACK_COL_MAJOR, 'L', n_, kd, static_cast<int>(u.cols()), l_.data(), kd + 1, u.data(), n_);
    MatrixXd full = MatrixXd::Zero(f.rows(), f.cols());
    full.bottomRows(n_) = u;
    return full;
  }
  // C's band, C(i, i + d) at (i, d), by Takahashi's recurrence on the factor: from L^T C = L^-1,
  // whose upper triangle is diag(1 / L_ii), C_ij = (delta_ij / L_ii - sum_{k = i+1}^{i+kd} L_ki
  // C_kj) / L_ii for j >= i, which only reads C inside the band: O(n kd^2), no inverse formed.
  MatrixXd band() const {
    MatrixXd c = MatrixXd::Zero(n_ + 2, kd + 1);
    const auto held = [&](int i, int j) { return i <= j ? c(i + 2, j - i) : c(j + 2, i - j); };
    for (int i = n_ - 1; i >= 0; --i)
      for (int j = std::min(n_ - 1, i + kd); j >= i; --j) {
        double sum = i == j ? 1 / factor(i, i) : 0.0;
        for (int k = i + 1; k <= std::min(n_ - 1, i + kd); ++k) sum -= factor(k, i) * held(k, j);
        c(i + 2, j - i) = sum / factor(i, i);
      }
    return c;
  }

 private:
  double factor(int i, int j) const { return l_[i - j + j * (kd + 1)]; }
  int n_;
  std::vector<double> l_;
};

VibrationalFlexibility::VibrationalFlexibility(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass,
                                               const MatrixXd& rigid)
    : held_(std::make_shared<const HeldBeam>(s.stiffness)), rigid_(rigid), mass_rigid_(mass * rigid) {
  const MatrixXd v = held_->displacement(mass_rigid_);
  const MatrixXd rigid_share = mass_rigid_.transpose() * v;  // R^T M V, M symmetric
  band_ = held_->band();
  const int n = static_cast<int>(band_.rows());
  for (int i = 0; i < n; ++i)
    for (int d = 0; d <= kd && i + d < n; ++d) {
      const int j = i + d;
      band_(i, d) += -v.row(i).dot(rigid.row(j)) - rigid.row(i).dot(v.row(j)) +
                     rigid.row(i).dot(rigid_share * rigid.row(j).transpose());
    }
}

VectorXd VibrationalFlexibility::times(const VectorXd& w) const {
  // P w = w - M R R^T w (balanced), C of it, then P^T y = y - R R^T M y.
  const VectorXd balanced = w - mass_rigid_ * (rigid_.transpose() * w);
  const VectorXd y = held_->displacement(balanced);
  return y - rigid_ * (mass_rigid_.transpose() * y);
}

}  // namespace sweetspot
