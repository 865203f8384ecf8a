#pragma once
// The cores a rank's OpenMP threads may run on, which each rank logs: a rank bound to fewer cores
// than it has threads runs them in turn (cluster/sweetspot.slurm, "Binding").
#include <string>
#include <vector>

namespace sweetspot {

// The CPU numbers of the calling thread's affinity mask, ascending; empty if the system will not say.
std::vector<int> allowed_cores();

// The CPU numbers the rank's OpenMP team may use between them: the union of every thread's mask,
// read inside a parallel region, ascending; empty if the system will not say. Not the calling
// thread's mask: with OMP_PROC_BIND set, the OpenMP runtime pins the initial thread to its one
// place before main, so that mask shows one core even when the rank has a core per thread. A
// rank confined to one core has every thread pinned there, and the union is that one core.
std::vector<int> team_cores();

// "0-3,8,10-11": runs of consecutive numbers as ranges, as taskset and Slurm write them.
std::string core_list(const std::vector<int>& cores);

}  // namespace sweetspot
