#include "sweetspot/study/affinity.hpp"

#include <sched.h>

#include <set>

namespace sweetspot {

std::vector<int> allowed_cores() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  std::vector<int> cores;
  if (sched_getaffinity(0, sizeof mask, &mask) != 0) return cores;  // 0: the calling thread
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &mask)) cores.push_back(cpu);
  return cores;
}

std::vector<int> team_cores() {
  std::set<int> cores;
  bool unknown = false;  // a thread whose mask the system would not give: the union is unknown
#pragma omp parallel
  {
    const std::vector<int> mine = allowed_cores();
#pragma omp critical(sweetspot_team_cores)
    {
      if (mine.empty()) unknown = true;
      cores.insert(mine.begin(), mine.end());
    }
  }
  if (unknown) return {};
  return {cores.begin(), cores.end()};
}

std::string core_list(const std::vector<int>& cores) {
  std::string list;
  for (std::size_t i = 0; i < cores.size();) {
    std::size_t last = i;
    while (last + 1 < cores.size() && cores[last + 1] == cores[last] + 1) ++last;
    if (!list.empty()) list += ',';
    list += std::to_string(cores[i]);
    if (last > i) list.append("-").append(std::to_string(cores[last]));
    i = last + 1;
  }
  return list;
}

}  // namespace sweetspot
