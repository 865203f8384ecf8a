#include "bat/banded_eigensolver.hpp"

#include <lapacke.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "bat/sturm_kernels.hpp"

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
std::vector<double> symmetric_band(const Eigen::SparseMatrix<double>& a, const VectorXd& scale) {
  const int n = static_cast<int>(a.rows());
  std::vector<double> ab((kd + 1) * n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - kd); i <= j; ++i) ab[kd + i - j + j * (kd + 1)] = a.coeff(i, j) * scale(i) * scale(j);
  return ab;
}

// The pencil as a symmetric tridiagonal matrix with its eigenvalues: LAPACK reduces the banded
// problem by rotations it does not accumulate (dsbtrd, O(n^2 kd)). With M diagonal (Timoshenko)
// the problem is made standard by M^(-1/2) here; otherwise by M's split Cholesky factor (dpbstf,
// dsbgst), as dsbgvx does. The _work routines: no NaN scan of the input, which would cost as much
// as the work.
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

// Sturm counts: how many eigenvalues lie below x (Sylvester's law of inertia, the count LAPACK's
// bisection is built on). count(x) for one shift, counts(x) for eight in one pass: independent
// recurrences, in the widest vector registers the processor has (sturm_kernels.inc), so that eight
// cost little more than one does (one is bound by its divisions' latency). bound() is Gershgorin's
// bound on the eigenvalues' size.
constexpr int shifts = detail::sturm_shifts;
using Shifts = Eigen::Array<double, shifts, 1>;

// On the tridiagonal T: the negative pivots of T - x I. In count, a zero pivot is made -tiny; in
// counts it is left to IEEE arithmetic, as LAPACK's dlaneg does: its successor is -inf (counted) and
// the next one finite again (Demmel, Dhillon and Ren, "On the correctness of some bisection-like
// parallel eigenvalue algorithms in floating point arithmetic", ETNA 3, 1995); the squared
// off-diagonal is kept above the underflow, so that 0 / 0 never happens.
class TridiagonalCounts {
 public:
  explicit TridiagonalCounts(const Tridiagonal& t) : t_(t), e2_(t.e.size()) {
    for (Eigen::Index i = 0; i < t.e.size(); ++i)
      e2_[i] = std::max(t.e(i) * t.e(i), std::numeric_limits<double>::min());
  }
  int count(double x) const {
    const int n = static_cast<int>(t_.d.size());
    const double tiny = std::numeric_limits<double>::min();
    double pivot = t_.d(0) - x;
    int count = pivot < 0;
    for (int i = 1; i < n; ++i) {
      if (pivot == 0) pivot = -tiny;
      pivot = t_.d(i) - x - t_.e(i - 1) * t_.e(i - 1) / pivot;
      count += pivot < 0;
    }
    return count;
  }
  Shifts counts(const Shifts& x) const {
    Shifts count;
    detail::tridiagonal_counts(t_.d.data(), e2_.data(), static_cast<int>(t_.d.size()), x.data(), count.data());
    return count;
  }
  double bound() const {
    const int n = static_cast<int>(t_.d.size());
    double bound = 0;
    for (int i = 0; i < n; ++i)
      bound = std::max(bound, std::abs(t_.d(i)) + (i > 0 ? std::abs(t_.e(i - 1)) : 0.0) +
                                  (i + 1 < n ? std::abs(t_.e(i)) : 0.0));
    return bound;
  }

 private:
  const Tridiagonal& t_;
  std::vector<double> e2_;  // the squared off-diagonal, kept above the underflow
};

// On Timoshenko's pencil itself: the negative eigenvalues of the pivots of the block LDL^T
// factorisation of K - x M, whose inertia is that of M^(-1/2) K M^(-1/2) - x I (Sylvester). The
// beam's degrees of freedom come in pairs, one per slice (its displacement and rotation), and K
// couples each slice only with its neighbours, while the lumped M is diagonal: K - x M is block
// tridiagonal, and its pivots are the 2 x 2 Schur complements S_i = A_i - B_i^T S_(i-1)^(-1) B_i.
// A count costs O(n) and needs no reduction to tridiagonal form, whose O(n^2 kd) rotations dominate
// a solve of a few modes at large n. The factorisation is made without pivoting, as the Sturm
// sequence checks of structural eigen-solvers are (K. J. Bathe, "Finite Element Procedures",
// 1996); a singular pivot's determinant is made slightly positive.
class PencilCounts {
 public:
  explicit PencilCounts(const BeamSystem& s) : slices_(static_cast<int>(s.mass.rows()) / 2), blocks_(slices_) {
    const auto k = [&](int i, int j) { return s.stiffness.coeff(i, j); };
    for (int i = 0; i < slices_; ++i) {
      Block& b = blocks_[i];
      const int y = 2 * i, phi = y + 1;
      b = {k(y, y), k(y, phi), k(phi, phi), s.mass.coeff(y, y), s.mass.coeff(phi, phi), {}};
      if (i > 0) {
        const double coupling[4] = {k(y - 2, y), k(y - 2, phi), k(y - 1, y), k(y - 1, phi)};
        std::copy(coupling, coupling + 4, b.coupling);
      }
    }
  }
  int count(double x) const { return static_cast<int>(counts(Shifts::Constant(x))(0)); }
  Shifts counts(const Shifts& x) const {
    Shifts count;
    detail::pencil_counts(blocks_.data(), slices_, x.data(), count.data());
    return count;
  }
  // Gershgorin's bound on M^(-1/2) K M^(-1/2): each row's diagonal and its entries' sizes.
  double bound() const {
    std::vector<double> row(2 * slices_, 0.0);
    const auto add = [&](int i, int j, double k) {  // K's entry (i, j) and its mirror (j, i)
      const double a = std::abs(k) / std::sqrt(mass(i) * mass(j));
      row[i] += a;
      if (j != i) row[j] += a;
    };
    for (int i = 0; i < slices_; ++i) {
      const Block& b = blocks_[i];
      add(2 * i, 2 * i, b.yy);
      add(2 * i + 1, 2 * i + 1, b.phiphi);
      add(2 * i, 2 * i + 1, b.yphi);
      if (i > 0)
        for (int a = 0; a < 2; ++a)
          for (int d = 0; d < 2; ++d) add(2 * i - 2 + a, 2 * i + d, b.coupling[2 * a + d]);
    }
    return *std::max_element(row.begin(), row.end());
  }

 private:
  using Block = detail::PencilBlock;
  double mass(int dof) const { return dof % 2 ? blocks_[dof / 2].inertia : blocks_[dof / 2].mass; }
  int slices_;
  std::vector<Block> blocks_;
};

// An interval holding exactly one eigenvalue, that of index count(lo).
struct Bracket {
  double lo = 0, hi = 0;
};

struct Sample {
  double x;
  int count;
};

// Brackets of the eigenvalues of index first to count - 1, each within 1/8 of itself, by
// multisection on Sturm counts (nine parts per pass, as many bits as three bisections). The
// points are spaced geometrically while the interval spans orders of magnitude (the beam's
// eigenvalues spread over 1e6 to 1e12). A part whose counts do not rise (round-off, within
// eps ||T|| of an eigenvalue) holds none; an eigenvalue so lost leaves its bracket empty.
constexpr double isolated_width = 1.0 / 8;

template <class Counts>
void isolate(const Counts& t, Sample lo, Sample hi, int first, int count, std::vector<Bracket>& out) {
  if (hi.count <= lo.count || hi.count <= first || lo.count >= count) return;  // nothing wanted inside
  if (hi.count - lo.count == 1 && hi.x - lo.x <= isolated_width * lo.x) {
    out[lo.count - first] = {lo.x, hi.x};
    return;
  }
  Shifts x;
  for (int s = 0; s < shifts; ++s) {
    const double part = (s + 1.0) / (shifts + 1);
    x(s) = hi.x > 4 * lo.x ? lo.x * std::pow(hi.x / lo.x, part) : lo.x + part * (hi.x - lo.x);
  }
  if (!(lo.x < x(0) && x(shifts - 1) < hi.x)) return;  // cannot be split: equal eigenvalues
  const Shifts c = t.counts(x);
  const auto sample = [&](int s) { return s < 0 ? lo : s == shifts ? hi : Sample{x(s), static_cast<int>(c(s))}; };
  for (int s = 0; s <= shifts; ++s) isolate(t, sample(s - 1), sample(s), first, count, out);
}

// The brackets (of indices first, first + 1, ...) narrowed until each is within 1e-8 of its
// eigenvalue's distance to the next bracket (1e-11 of itself for the last, whose upper neighbour
// is unknown), or within T's round-off, `floor`. Two steps of inverse iteration at its midpoint
// then leave a neighbour's share at (1e-8)^2 times its share of the start over the mode's own:
// at 1e-6, that ratio (about 1e4 on the torpedo's crowded modes 72-74 at N = 170) left 3e-9 in their
// shapes. Each pass shares the counts' eight shifts among the brackets still open: one each
// (LAPACK's dlaebz bisects many intervals at once the same way), or several each, evenly spaced,
// when fewer than eight are left.
constexpr double gap_share = 1e-8, last_width = 1e-11;

template <class Counts>
void narrow(const Counts& t, int first, double floor, std::vector<Bracket>& brackets) {
  const int last = static_cast<int>(brackets.size()) - 1;
  // The eigenvalue's distance to its neighbours is at least that to their brackets (the rigid
  // ones' lie at 0).
  const auto gap = [&](int k) {
    const Bracket& b = brackets[k];
    return std::min(k > 0 ? b.lo - brackets[k - 1].hi : b.lo, brackets[k + 1].lo - b.hi);
  };
  const auto wide = [&](int k) {
    const Bracket& b = brackets[k];
    const double mid = (b.lo + b.hi) / 2, enough = k < last ? gap_share * gap(k) : last_width * b.lo;
    return b.hi - b.lo > std::max(enough, floor) && b.lo < mid && mid < b.hi;
  };
  std::vector<int> open;
  for (int k = 0; k < static_cast<int>(brackets.size()); ++k) open.push_back(k);
  for (;;) {
    open.erase(std::remove_if(open.begin(), open.end(), [&](int k) { return !wide(k); }), open.end());
    if (open.empty()) return;
    const int served = std::min<int>(shifts, static_cast<int>(open.size())), points = shifts / served;
    Shifts x = Shifts::Constant(brackets[open[0]].lo);  // lanes left over count at a known point
    for (int b = 0; b < served; ++b)
      for (int i = 0; i < points; ++i) {
        const Bracket& bracket = brackets[open[b]];
        x(b * points + i) = bracket.lo + (bracket.hi - bracket.lo) * (i + 1) / (points + 1);
      }
    const Shifts c = t.counts(x);
    for (int b = 0; b < served; ++b) {
      Bracket& bracket = brackets[open[b]];
      for (int i = b * points; i < (b + 1) * points; ++i) {
        if (c(i) > first + open[b]) {
          bracket.hi = x(i);
          break;
        }
        bracket.lo = x(i);
      }
    }
  }
}

// Brackets of the vibrational eigenvalues 2 to count - 1. The rigid two lie within round-off,
// eps ||T||, of 0, the first vibrational one far above (5e-10 ||T|| for Euler-Bernoulli at
// N = 168, whose ||T|| grows as N^4): the search starts at 1e4 eps ||T||, and must find exactly
// the two rigid eigenvalues below it. False when that fails or an eigenvalue is left without a
// bracket.
template <class Counts>
bool vibrational_brackets(const Counts& t, int count, std::vector<Bracket>& out) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double top = t.bound(), bottom = 1e4 * eps * top;
  const Sample lo{bottom, t.count(bottom)};
  out.assign(std::max(count - 2, 0), Bracket{});
  if (lo.count != 2) return false;
  isolate(t, lo, {top, t.count(top)}, 2, count, out);
  if (!std::all_of(out.begin(), out.end(), [](const Bracket& b) { return b.lo < b.hi; })) return false;
  narrow(t, 2, 16 * eps * top, out);
  return true;
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
      const double inverse = at(j, j) = 1 / at(j, j);  // kept inverted: the solve multiplies
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
    double* v = b.data();
    for (int j = 0; j < n_; ++j) {  // the row exchange through a register, not a reload
      const double pivot = v[pivots_[j]];
      v[pivots_[j]] = v[j];
      v[j] = pivot;
      for (int i = j + 1; i <= j + kd; ++i) v[i] -= at(i, j) * pivot;
    }
    // The terms that do not wait for the entry just solved first: the recurrence's latency is
    // then one product and one difference per row, not the whole sum's.
    for (int j = n_ - 1; j >= 0; --j) {
      const double* row = &at(j, j + 1);
      double rest = 0;
      for (int c = 1; c < 2 * kd; ++c) rest += row[c] * v[j + 1 + c];
      v[j] = (v[j] - rest - row[0] * v[j + 1]) * at(j, j);
    }
  }
  static constexpr int pad = 2 * kd;

 private:
  static constexpr int width = 3 * kd + 1;
  static std::size_t index(int i, int j) { return static_cast<std::size_t>(i * width + j - i + kd); }
  double& at(int i, int j) { return lu_[index(i, j)]; }
  const double& at(int i, int j) const { return lu_[index(i, j)]; }
  // The band of one of the beam's matrices in this storage, its padding zero.
  std::vector<double> rows(const Eigen::SparseMatrix<double>& a) const {
    std::vector<double> r(width * (n_ + pad), 0.0);
    for (int j = 0; j < n_; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it) r[index(static_cast<int>(it.row()), j)] = it.value();
    return r;
  }
  int n_;
  std::vector<double> k_, m_, lu_;
  std::vector<int> pivots_;
};

// M applied to a vector or a matrix's columns: Timoshenko's lumped M by its diagonal, the same
// products as the sparse product's (0 + m x) without its per-entry bookkeeping; Euler-Bernoulli's
// consistent M sparse.
class MassProduct {
 public:
  MassProduct(const Eigen::SparseMatrix<double>& mass, bool diagonal)
      : mass_(mass), diagonal_(diagonal ? VectorXd(mass.diagonal()) : VectorXd()) {}
  template <class Derived>
  typename Derived::PlainObject operator*(const Eigen::MatrixBase<Derived>& x) const {
    using Plain = typename Derived::PlainObject;
    return diagonal_.size() ? Plain(diagonal_.asDiagonal() * x) : Plain(mass_ * x);
  }

 private:
  const Eigen::SparseMatrix<double>& mass_;
  VectorXd diagonal_;
};

// A fixed pseudo-random start (the same on every run), with a component along every mode. One
// for every mode: inverse iteration at each mode's own shift draws that mode out of it (drawing
// the numbers anew for each mode cost 3 % of an 18-mode solve at N = 84).
VectorXd start_vector(int n) {
  std::minstd_rand engine(1);
  VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = static_cast<double>(engine()) / std::minstd_rand::max() - 0.5;
  return x;
}

// One step of inverse iteration at the factored shift: x <- (K - shift M)^-1 M x, M-normalised.
// Returns the Rayleigh quotient of the new x, y = (K - shift M)^-1 M x, as shift + y^T M x /
// y^T M y (the same by (K - shift M) y = M x), which needs no product with K and so none of its
// cancellation.
double inverse_step(const ShiftedPencil& pencil, const MassProduct& mass, double shift, VectorXd& x) {
  const Eigen::Index n = x.size();
  const VectorXd mx = mass * x;
  VectorXd b(n + ShiftedPencil::pad);
  b << mx, VectorXd::Zero(ShiftedPencil::pad);
  pencil.solve(b);
  x = b.head(n);
  const double norm = x.dot(mass * x);
  const double quotient = shift + x.dot(mx) / norm;
  x /= std::sqrt(norm);
  return quotient;
}

// Eigenpair k (its eigenvalue into w(k)) by inverse iteration at its bracket's midpoint: each
// step divides the other modes by their distance from it over its error (1e-8 at least, narrow),
// so two steps leave round-off. The eigenvalue is the last step's Rayleigh quotient,
// whose error is the solve's round-off. Modes closer than 1e-3 in relative frequency (the top of
// the bending branch crowds) are kept M-orthogonal to those already found, as LAPACK's dstein
// does.
constexpr int steps = 2;

VectorXd eigenvector(ShiftedPencil& pencil, const MassProduct& mass, const VectorXd& start, Bracket bracket, int k,
                     VectorXd& w, const MatrixXd& found) {
  const double shift = (bracket.lo + bracket.hi) / 2;
  pencil.factor(shift);
  VectorXd x = start;
  for (int step = 0; step < steps; ++step) {
    w(k) = inverse_step(pencil, mass, shift, x);
    for (int j = k - 1; j >= 2 && shift - w(j) <= 1e-3 * shift; --j) x -= found.col(j).dot(mass * x) * found.col(j);
  }
  return x / std::sqrt(x.dot(mass * x));
}

// Inverse iteration leaves two modes M-orthogonal only to eps w_max^2 over their gap, 5e-10 for
// Euler-Bernoulli at N = 168 (its w_max grows as N^2). Cholesky QR in the M inner product makes
// the basis orthonormal to round-off: X <- X R^(-1), R^T R = X^T M X. For a basis already that
// close to orthonormal its Gram matrix is within 5e-10 of the identity, and one pass leaves an
// error of order eps times its condition number squared (Y. Yamamoto et al., "Roundoff error
// analysis of the CholeskyQR2 algorithm", ETNA 44, 306 (2015)). It is made of matrix products,
// not Gram-Schmidt's column at a time. False if the Gram matrix is not positive definite (a basis
// not close to orthonormal).
bool orthonormalise(const MassProduct& mass, MatrixXd& vectors) {
  auto modes = vectors.rightCols(vectors.cols() - 2);  // the rigid columns are set apart (modes.cpp)
  const Eigen::LLT<MatrixXd> gram(modes.transpose() * (mass * modes));
  if (gram.info() != Eigen::Success) return false;
  gram.matrixU().solveInPlace<Eigen::OnTheRight>(modes);
  return true;
}

// The request's `count` eigenpairs (rigid ones included), bracketed by `counts`.
template <class Counts>
bool solve_lowest(const Counts& counts, int count, const BeamSystem& s, const Eigen::SparseMatrix<double>& mass,
                  BandedRequest request, VectorXd& omega_squared, MatrixXd& vectors, int* counted) {
  const int dofs = static_cast<int>(s.mass.rows());
  if (counted) *counted = count;
  if (count > dofs * max_banded_share || count > request.most) return false;
  std::vector<Bracket> brackets;
  if (!vibrational_brackets(counts, count, brackets)) return false;
  omega_squared = VectorXd::Zero(count);
  vectors = MatrixXd::Zero(dofs, count);
  ShiftedPencil pencil(s);
  const MassProduct m(mass, request.diagonal_mass);
  const VectorXd start = start_vector(dofs);
  for (int k = 2; k < count; ++k)
    vectors.col(k) = eigenvector(pencil, m, start, brackets[k - 2], k, omega_squared, vectors);
  return orthonormalise(m, vectors);
}

// How many eigenpairs a request covers: the two rigid ones always (they lie at 0 however low the
// frequency asked).
template <class Counts>
int request_count(const Counts& counts, BandedRequest request) {
  return std::max(2, request.count >= 0 ? request.count : counts.count(request.upper));
}

// Whether Timoshenko's counts on the pencil itself cost less than the tridiagonal reduction and its
// counts. On the AVX2 path a count on the pencil costs about four times one on the tridiagonal
// form, and bracketing k eigenvalues takes about 4k passes, while the reduction costs O(n^2): the
// pencil pays for up to one mode per four degrees of freedom. Maple 271 in turns (medians of 7,
// Zen 3): 90 modes at N = 336 in 8.8 against 12.8 ms, 120 in 12.2 against 14.2, 20 in 2.2 against
// 4.1; at N = 168, 90 modes about even (4.6-5.8 against 5.0-6.1), 120 in 6.5-8.4 against 7.1-7.2;
// at N = 84 the two cost about the same, and there the results stay those of the reduction. The
// choice is the same on every vector path, so that all solve the same modes bit for bit (SSE2's
// pencil counts cost more, and there the reduction would pay from about one mode in eight).
constexpr int pencil_counts_from = 300;  // degrees of freedom
bool pencil_counts_pay(int dofs, int count) { return dofs >= pencil_counts_from && dofs >= 4 * (count - 2); }

}  // namespace

bool solve_lowest(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass, BandedRequest request,
                  VectorXd& omega_squared, MatrixXd& vectors, int* counted) {
  const int dofs = static_cast<int>(s.mass.rows());
  if (request.diagonal_mass && dofs >= pencil_counts_from) {
    const PencilCounts counts(s);
    const int count = request_count(counts, request);
    if (pencil_counts_pay(dofs, count))
      return solve_lowest(counts, count, s, mass, request, omega_squared, vectors, counted);
  }
  const Tridiagonal t = tridiagonal(s, request.diagonal_mass);
  const TridiagonalCounts counts(t);
  return solve_lowest(counts, request_count(counts, request), s, mass, request, omega_squared, vectors, counted);
}

int count_below(const BeamSystem& s, bool diagonal_mass, double x) {
  if (diagonal_mass) return PencilCounts(s).count(x);
  const Tridiagonal t = tridiagonal(s, false);
  return TridiagonalCounts(t).count(x);
}

}  // namespace sweetspot
