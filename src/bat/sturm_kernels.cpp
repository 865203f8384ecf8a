// Which build of the Sturm counts runs: the one of the path the library takes for the exact
// stepper's kernels (contact/mode_kernels.cpp), so that a test or SWEETSPOT_VECTOR_PATH switches
// both.
#include "bat/sturm_kernels.hpp"

#include "contact/mode_kernels.hpp"

namespace sweetspot::detail {

#define SWEETSPOT_DECLARE_KERNELS(path)                                                            \
  namespace path {                                                                               \
  void pencil_counts(const PencilBlock* blocks, int n, const double* x, double* count);          \
  void tridiagonal_counts(const double* d, const double* e2, int n, const double* x, double* count); \
  }
SWEETSPOT_DECLARE_KERNELS(sse2)
#ifdef SWEETSPOT_X86_DISPATCH
SWEETSPOT_DECLARE_KERNELS(avx2)
SWEETSPOT_DECLARE_KERNELS(avx512)
#endif
#undef SWEETSPOT_DECLARE_KERNELS

void pencil_counts(const PencilBlock* blocks, int n, const double* x, double* count) {
#ifdef SWEETSPOT_X86_DISPATCH
  switch (vector_path()) {
    case VectorPath::avx512: return avx512::pencil_counts(blocks, n, x, count);
    case VectorPath::avx2: return avx2::pencil_counts(blocks, n, x, count);
    case VectorPath::sse2: break;
  }
#endif
  sse2::pencil_counts(blocks, n, x, count);
}

void tridiagonal_counts(const double* d, const double* e2, int n, const double* x, double* count) {
#ifdef SWEETSPOT_X86_DISPATCH
  switch (vector_path()) {
    case VectorPath::avx512: return avx512::tridiagonal_counts(d, e2, n, x, count);
    case VectorPath::avx2: return avx2::tridiagonal_counts(d, e2, n, x, count);
    case VectorPath::sse2: break;
  }
#endif
  sse2::tridiagonal_counts(d, e2, n, x, count);
}

}  // namespace sweetspot::detail
