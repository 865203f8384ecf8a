#include "bat/banded_eigensolver.hpp"

#include <lapacke.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweetspot {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
constexpr int kd = beam_bandwidth;

void check(lapack_int info, const char* routine) {
  if (info != 0) throw std::runtime_error(std::string("the banded eigen-solve: LAPACK ") + routine + " failed (info " +
                                          std::to_string(info) + ")");
}

// LAPACK's symmetric band storage, upper triangle: ab[kd + i - j + j (kd + 1)] = a(i, j) scale_i
// scale_j.
std::vector<double> symmetric_band(const MatrixXd& a, const VectorXd& scale) {
  const int n = static_cast<int>(a.rows());
  std::vector<double> ab((kd + 1) * n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - kd); i <= j; ++i) ab[kd + i - j + j * (kd + 1)] = a(i, j) * scale(i) * scale(j);
  return ab;
}

// The pencil as a symmetric tridiagonal matrix with its eigenvalues: LAPACK reduces the banded
// problem by rotations it does not accumulate (O(n^2 kd)), which is what makes this cheaper than
// the dense solve. With M diagonal (Timoshenko) the problem is made standard by M^(-1/2) here;
// otherwise by M's split Cholesky factor (dpbstf, dsbgst), as dsbgvx does. The _work routines:
// no NaN scan of the input, which would cost as much as the work.
struct Tridiagonal {
  VectorXd d, e;
};

Tridiagonal tridiagonal(const BeamSystem& s, bool diagonal_mass) {
  const int n = static_cast<int>(s.mass.rows());
  const VectorXd unit = VectorXd::Ones(n);
  const VectorXd scale = diagonal_mass ? VectorXd(s.mass.diagonal().cwiseSqrt().cwiseInverse()) : unit;
  std::vector<double> k = symmetric_band(s.stiffness, scale), work(2 * n);
  double unused = 0;
  if (!diagonal_mass) {
    std::vector<double> m = symmetric_band(s.mass, unit);
    check(LAPACKE_dpbstf_work(LAPACK_COL_MAJOR, 'U', n, kd, m.data(), kd + 1), "dpbstf");
    check(LAPACKE_dsbgst_work(LAPACK_COL_MAJOR, 'N', 'U', n, kd, kd, k.data(), kd + 1, m.data(), kd + 1, &unused, 1,
                              work.data()),
          "dsbgst");
  }
  Tridiagonal t{VectorXd(n), VectorXd(std::max(n - 1, 1))};
  check(LAPACKE_dsbtrd_work(LAPACK_COL_MAJOR, 'N', 'U', n, kd, k.data(), kd + 1, t.d.data(), t.e.data(), &unused, 1,
                            work.data()),
        "dsbtrd");
  return t;
}

// How many eigenvalues lie below x: the negative pivots of T - x I (Sylvester's law, the Sturm
// count LAPACK's bisection is built on), O(n).
int count_below(const Tridiagonal& t, double x) {
  const int n = static_cast<int>(t.d.size());
  const double tiny = std::numeric_limits<double>::min();
  double pivot = t.d(0) - x;
  int count = pivot < 0;
  for (int i = 1; i < n; ++i) {
    if (pivot == 0) pivot = -tiny;
    pivot = t.d(i) - x - t.e(i - 1) * t.e(i - 1) / pivot;
    count += pivot < 0;
  }
  return count;
}

// The lowest `count` eigenvalues by bisection (dstebz), each to full relative accuracy.
VectorXd lowest_eigenvalues(const Tridiagonal& t, int count) {
  const int n = static_cast<int>(t.d.size());
  VectorXd w(n);
  std::vector<double> work(4 * n);
  std::vector<lapack_int> block(n), split(n), iwork(3 * n);
  lapack_int found = 0, splits = 0;
  check(LAPACKE_dstebz_work('I', 'E', n, 0, 0, 1, count, 2 * std::numeric_limits<double>::min(), t.d.data(),
                            t.e.data(), &found, &splits, w.data(), block.data(), split.data(), work.data(),
                            iwork.data()),
        "dstebz");
  return w.head(found);
}

// K - shift M in LAPACK's general band storage, factored with partial pivoting (dgbtrf), so that
// inverse iteration costs O(n kd) per step.
class ShiftedPencil {
 public:
  ShiftedPencil(const BeamSystem& s, double shift) : n_(static_cast<int>(s.mass.rows())), ab_(ld * n_, 0.0), pivots_(n_) {
    for (int j = 0; j < n_; ++j)
      for (int i = std::max(0, j - kd); i <= std::min(n_ - 1, j + kd); ++i)
        ab_[2 * kd + i - j + j * ld] = s.stiffness(i, j) - shift * s.mass(i, j);
    // A shift exactly on an eigenvalue gives a zero pivot; LAPACK reports it and leaves the
    // factors usable, and the solve below then only needs to be finite: nudge that pivot.
    const lapack_int info = LAPACKE_dgbtrf_work(LAPACK_COL_MAJOR, n_, n_, kd, kd, ab_.data(), ld, pivots_.data());
    if (info < 0) check(info, "dgbtrf");
    if (info > 0) ab_[2 * kd + (info - 1) * ld] = std::numeric_limits<double>::epsilon() * std::abs(shift);
  }
  void solve(VectorXd& b) const {
    check(LAPACKE_dgbtrs_work(LAPACK_COL_MAJOR, 'N', n_, kd, kd, 1, ab_.data(), ld, pivots_.data(), b.data(), n_),
          "dgbtrs");
  }

 private:
  static constexpr int ld = 3 * kd + 1;
  int n_;
  std::vector<double> ab_;
  std::vector<lapack_int> pivots_;
};

// A fixed pseudo-random start (the same on every run), with a component along every mode.
VectorXd start_vector(int n, int seed) {
  std::minstd_rand engine(static_cast<unsigned>(seed) + 1);
  VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = static_cast<double>(engine()) / std::minstd_rand::max() - 0.5;
  return x;
}

// Inverse iteration at an eigenvalue accurate to round-off: each step divides the other modes by
// their distance from it over its own error (at least 1e-3 / 1e-12 here), so two steps leave
// round-off. Modes closer than
// 1e-3 in relative frequency (the top of the bending branch crowds) are kept M-orthogonal to
// those already found, as LAPACK's dstein does.
constexpr int steps = 2;

VectorXd eigenvector(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass, const VectorXd& w, int k,
                     const MatrixXd& found) {
  const ShiftedPencil pencil(s, w(k));
  VectorXd x = start_vector(static_cast<int>(s.mass.rows()), k);
  for (int step = 0; step < steps; ++step) {
    VectorXd b = mass * x;
    pencil.solve(b);
    for (int j = k - 1; j >= 2 && w(k) - w(j) <= 1e-3 * w(k); --j) b -= found.col(j).dot(mass * b) * found.col(j);
    x = b / std::sqrt(b.dot(mass * b));
  }
  return x;
}

// Inverse iteration leaves two modes M-orthogonal only to eps w_max^2 over their gap, 5e-10 for
// Euler-Bernoulli at N = 168 (its w_max grows as N^2): one Gram-Schmidt pass in the M inner
// product, O(n k^2), makes the basis orthonormal to round-off.
void orthonormalise(const Eigen::SparseMatrix<double>& mass, MatrixXd& vectors) {
  for (int k = 2; k < vectors.cols(); ++k) {
    for (int j = 2; j < k; ++j) vectors.col(k) -= vectors.col(j).dot(mass * vectors.col(k)) * vectors.col(j);
    vectors.col(k) /= std::sqrt(vectors.col(k).dot(mass * vectors.col(k)));
  }
}

}  // namespace

bool solve_lowest(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass, BandedRequest request,
                  VectorXd& omega_squared, MatrixXd& vectors) {
  const Tridiagonal t = tridiagonal(s, request.diagonal_mass);
  const int dofs = static_cast<int>(s.mass.rows());
  // The two rigid modes always (they lie at 0 however low the frequency asked).
  const int count = std::max(2, request.count >= 0 ? request.count : count_below(t, request.upper));
  if (count > dofs * max_banded_share) return false;
  omega_squared = lowest_eigenvalues(t, count);
  vectors = MatrixXd::Zero(dofs, count);
  for (int k = 2; k < count; ++k) vectors.col(k) = eigenvector(s, mass, omega_squared, k, vectors);
  orthonormalise(mass, vectors);
  return true;
}

}  // namespace sweetspot
