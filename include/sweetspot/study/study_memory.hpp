#pragma once
// What a study needs in memory, estimated before any work, so that a grid too large for the
// machine is refused with a message instead of ending in std::bad_alloc with a journal left.
#include <cstdint>

#include "sweetspot/study/study.hpp"

namespace sweetspot {

// Bytes rank 0 needs at most: every point's row of values twice (the results, then the
// dataset's copy of each output), the task order, a chunk in flight, and the modal bases of
// every (bat, slices, theory) with the eigen-solve of the largest.
double study_memory_bytes(const Study& study);

// The machine's physical memory, bytes.
double machine_memory_bytes();

// Throws InputError naming the axes and their sizes when study_memory_bytes(study) exceeds
// `available` bytes.
void check_study_memory(const Study& study, double available);

}  // namespace sweetspot
