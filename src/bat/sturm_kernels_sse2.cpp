// The kernels of sturm_kernels.inc for the sse2 path: the build's own instruction set (SSE2 on any
// x86-64; elsewhere, the only path).
#define SWEETSPOT_KERNEL_PATH sse2
#include "bat/sturm_kernels.inc"
