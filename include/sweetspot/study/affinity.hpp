#pragma once
// The cores this process may run on (its affinity mask), which a rank logs: a rank bound to
// fewer cores than it has OpenMP threads runs them in turn (cluster/README.md, "Binding").
#include <string>
#include <vector>

namespace sweetspot {

// The CPU numbers of the process's affinity mask, ascending; empty if the system will not say.
std::vector<int> allowed_cores();

// "0-3,8,10-11": runs of consecutive numbers as ranges, as taskset and Slurm write them.
std::string core_list(const std::vector<int>& cores);

}  // namespace sweetspot
