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

// The lowest `count` eigenvalues. All of T's by the root-free QL/QR iteration (dsterf, O(n^2)
// with a small constant, no vectors), which costs less than bisecting even for 18 of 168 (dstebz
// took 1.9 M instructions there, dsterf a third of that, and bisection's cost grows with the count).
// Its error is absolute, eps ||T||, as the reduction's own and the dense solve's are.
VectorXd lowest_eigenvalues(const Tridiagonal& t, int count) {
  VectorXd d = t.d, e = t.e;
  check(LAPACKE_dsterf_work(static_cast<lapack_int>(d.size()), d.data(), e.data()), "dsterf");
  return d.head(std::min<Eigen::Index>(count, d.size()));
}

// K - shift M by rows: row i holds columns i - kd to i + 2 kd (room for the fill-in of row
// exchanges), so that each elimination and each solve's sum runs over contiguous entries. It is
// LU-factored with partial pivoting as dgbtf2 does, inline: at kd = 3 LAPACK's per-column BLAS
// calls (idamax, dswap, dscal, dger) cost five times the arithmetic. The matrix is padded with
// 2 kd rows and columns of the identity, so that every loop runs over kd or 2 kd entries, known
// when compiling (the padding is never chosen as a pivot: its entries in the matrix's columns are
// zero). Inverse iteration then costs O(n kd) per step.
class ShiftedPencil {
 public:
  explicit ShiftedPencil(const BeamSystem& s)
      : n_(static_cast<int>(s.mass.rows())), k_(rows(s.stiffness)), m_(rows(s.mass)), lu_(k_.size()), pivots_(n_) {
    for (int j = n_; j < n_ + pad; ++j) k_[index(j, j)] = 1;
  }
  // Factors K - shift M, overwriting the previous shift's factors.
  void factor(double shift) {
    for (std::size_t i = 0; i < lu_.size(); ++i) lu_[i] = k_[i] - shift * m_[i];
    // A shift exactly on an eigenvalue gives a zero pivot: nudged, so that the solve below only
    // needs to be finite.
    const double nudge = std::numeric_limits<double>::epsilon() * std::abs(shift);
    for (int j = 0; j < n_; ++j) {
      int p = j;
      for (int i = j + 1; i <= j + kd; ++i)
        if (std::abs(at(i, j)) > std::abs(at(p, j))) p = i;
      pivots_[j] = p;
      if (p != j) std::swap_ranges(&at(j, j), &at(j, j) + 2 * kd + 1, &at(p, j));
      if (at(j, j) == 0) at(j, j) = nudge;
      const double inverse = 1 / at(j, j);
      const double* pivot_row = &at(j, j + 1);
      for (int i = j + 1; i <= j + kd; ++i) {
        const double l = at(i, j) *= inverse;
        double* row = &at(i, j + 1);
        for (int c = 0; c < 2 * kd; ++c) row[c] -= l * pivot_row[c];
      }
    }
  }
  // Solves in place; b has n + pad entries, the last pad of them zero (and zero on return).
  void solve(VectorXd& b) const {
    for (int j = 0; j < n_; ++j) {
      std::swap(b(j), b(pivots_[j]));
      for (int i = j + 1; i <= j + kd; ++i) b(i) -= at(i, j) * b(j);
    }
    for (int j = n_ - 1; j >= 0; --j) {
      const double* row = &at(j, j + 1);
      double sum = b(j);
      for (int c = 0; c < 2 * kd; ++c) sum -= row[c] * b(j + 1 + c);
      b(j) = sum / at(j, j);
    }
  }
  static constexpr int pad = 2 * kd;

 private:
  static constexpr int width = 3 * kd + 1;
  static std::size_t index(int i, int j) { return static_cast<std::size_t>(i * width + j - i + kd); }
  double& at(int i, int j) { return lu_[index(i, j)]; }
  const double& at(int i, int j) const { return lu_[index(i, j)]; }
  // The band of one of the beam's matrices in this storage, its padding zero.
  std::vector<double> rows(const MatrixXd& a) const {
    std::vector<double> r(width * (n_ + pad), 0.0);
    for (int i = 0; i < n_; ++i)
      for (int j = std::max(0, i - kd); j <= std::min(n_ - 1, i + kd); ++j) r[index(i, j)] = a(i, j);
    return r;
  }
  int n_;
  std::vector<double> k_, m_, lu_;
  std::vector<int> pivots_;
};

// M applied to a vector: Timoshenko's lumped M by its diagonal, the same products as the sparse
// product's (0 + m x) without its per-entry bookkeeping; Euler-Bernoulli's consistent M sparse.
class MassProduct {
 public:
  MassProduct(const Eigen::SparseMatrix<double>& mass, bool diagonal)
      : mass_(mass), diagonal_(diagonal ? VectorXd(mass.diagonal()) : VectorXd()) {}
  template <class Vector>
  VectorXd operator*(const Vector& x) const {
    return diagonal_.size() ? VectorXd(diagonal_.cwiseProduct(x)) : VectorXd(mass_ * x);
  }

 private:
  const Eigen::SparseMatrix<double>& mass_;
  VectorXd diagonal_;
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

VectorXd eigenvector(ShiftedPencil& pencil, const MassProduct& mass, const VectorXd& w, int k,
                     const MatrixXd& found) {
  const int n = static_cast<int>(found.rows());
  pencil.factor(w(k));
  VectorXd x = start_vector(n, k), b(n + ShiftedPencil::pad);
  for (int step = 0; step < steps; ++step) {
    b << mass * x, VectorXd::Zero(ShiftedPencil::pad);
    pencil.solve(b);
    VectorXd y = b.head(n);
    for (int j = k - 1; j >= 2 && w(k) - w(j) <= 1e-3 * w(k); --j) y -= found.col(j).dot(mass * y) * found.col(j);
    x = y / std::sqrt(y.dot(mass * y));
  }
  return x;
}

// Inverse iteration leaves two modes M-orthogonal only to eps w_max^2 over their gap, 5e-10 for
// Euler-Bernoulli at N = 168 (its w_max grows as N^2): one Gram-Schmidt pass in the M inner
// product, O(n k^2), makes the basis orthonormal to round-off.
void orthonormalise(const MassProduct& mass, MatrixXd& vectors) {
  // Modified Gram-Schmidt, each projection against M x_j (formed once per column).
  MatrixXd mx(vectors.rows(), vectors.cols());
  for (int k = 2; k < vectors.cols(); ++k) {
    for (int j = 2; j < k; ++j) vectors.col(k) -= mx.col(j).dot(vectors.col(k)) * vectors.col(j);
    mx.col(k) = mass * vectors.col(k);
    const double norm = std::sqrt(vectors.col(k).dot(mx.col(k)));
    vectors.col(k) /= norm;
    mx.col(k) /= norm;
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
  ShiftedPencil pencil(s);
  const MassProduct m(mass, request.diagonal_mass);
  for (int k = 2; k < count; ++k) vectors.col(k) = eigenvector(pencil, m, omega_squared, k, vectors);
  orthonormalise(m, vectors);
  return true;
}

}  // namespace sweetspot
