// Which build of the kernels runs: the widest vector unit the processor has, chosen once (GCC's
// and Clang's __builtin_cpu_supports), or the one a test asks for.
#include "contact/mode_kernels.hpp"

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace sweetspot::detail {

// The paths' kernels, each in its own namespace (mode_kernels.inc).
#define SWEETSPOT_DECLARE_KERNELS(path)                                                                         \
  namespace path {                                                                                            \
  void undamped_responses(const double* omega, int n, double h, const double* basis, const ResponseColumns& out); \
  StepSums step_known(int n, const StepArrays& s, const double (&data)[4]);                                   \
  void step_end(int n, double* a, double* v, const double* psi, const double* dC, const double* dD,            \
                const double* qC, const double* qD, double f1, double r1);                                    \
  }
SWEETSPOT_DECLARE_KERNELS(sse2)
#ifdef SWEETSPOT_X86_DISPATCH
SWEETSPOT_DECLARE_KERNELS(avx2)
SWEETSPOT_DECLARE_KERNELS(avx512)
#endif
#undef SWEETSPOT_DECLARE_KERNELS

namespace {

struct Kernels {
  VectorPath path;
  decltype(&sse2::undamped_responses) undamped_responses;
  decltype(&sse2::step_known) step_known;
  decltype(&sse2::step_end) step_end;
};

constexpr Kernels sse2_kernels{VectorPath::sse2, sse2::undamped_responses, sse2::step_known, sse2::step_end};
#ifdef SWEETSPOT_X86_DISPATCH
constexpr Kernels avx2_kernels{VectorPath::avx2, avx2::undamped_responses, avx2::step_known, avx2::step_end};
constexpr Kernels avx512_kernels{VectorPath::avx512, avx512::undamped_responses, avx512::step_known,
                                 avx512::step_end};
#endif

const Kernels* kernels_for(VectorPath path) {
#ifdef SWEETSPOT_X86_DISPATCH
  // The instruction sets the paths were built for (CMakeLists.txt): x86-64-v3 and -v4.
  __builtin_cpu_init();
  const bool v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
  const bool v4 = v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                  __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl") &&
                  __builtin_cpu_supports("avx512cd");
  if (path == VectorPath::avx512) return v4 ? &avx512_kernels : nullptr;
  if (path == VectorPath::avx2) return v3 ? &avx2_kernels : nullptr;
#endif
  return path == VectorPath::sse2 ? &sse2_kernels : nullptr;
}

// The widest path, or the one SWEETSPOT_VECTOR_PATH names (sse2, avx2 or avx512) if the
// processor has it: to compare their speed.
const Kernels* chosen() {
  if (const char* name = std::getenv("SWEETSPOT_VECTOR_PATH"))
    for (VectorPath path : {VectorPath::sse2, VectorPath::avx2, VectorPath::avx512})
      if (std::strcmp(name, to_string(path)) == 0)
        if (const Kernels* k = kernels_for(path)) return k;
  for (VectorPath path : {VectorPath::avx512, VectorPath::avx2})
    if (const Kernels* k = kernels_for(path)) return k;
  return &sse2_kernels;
}

std::atomic<const Kernels*>& current() {
  static std::atomic<const Kernels*> kernels{chosen()};
  return kernels;
}

}  // namespace

const char* to_string(VectorPath path) {
  switch (path) {
    case VectorPath::sse2: return "sse2";
    case VectorPath::avx2: return "avx2";
    case VectorPath::avx512: return "avx512";
  }
  return "unknown";
}

VectorPath vector_path() { return current().load(std::memory_order_relaxed)->path; }

bool vector_path_supported(VectorPath path) { return kernels_for(path) != nullptr; }

bool use_vector_path(VectorPath path) {
  const Kernels* k = kernels_for(path);
  if (k) current().store(k, std::memory_order_relaxed);
  return k != nullptr;
}

void undamped_responses(const double* omega, int n, double h, const double* basis, const ResponseColumns& out) {
  current().load(std::memory_order_relaxed)->undamped_responses(omega, n, h, basis, out);
}

StepSums step_known(int n, const StepArrays& s, const double (&data)[4]) {
  return current().load(std::memory_order_relaxed)->step_known(n, s, data);
}

void step_end(int n, double* a, double* v, const double* psi, const double* dC, const double* dD, const double* qC,
              const double* qD, double f1, double r1) {
  current().load(std::memory_order_relaxed)->step_end(n, a, v, psi, dC, dD, qC, qD, f1, r1);
}

}  // namespace sweetspot::detail
