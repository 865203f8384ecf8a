// The kernels of sturm_kernels.inc for the avx512 path: compiled with its instruction set
// (CMakeLists.txt) where the compiler builds for x86-64, left empty elsewhere.
#ifdef SWEETSPOT_X86_DISPATCH
#define SWEETSPOT_KERNEL_PATH avx512
#include "bat/sturm_kernels.inc"
#endif
