#pragma once
// sweetspot's own lines in what a run printed, told apart from lines the MPI library writes to the
// same stderr. Open MPI may warn at start-up (no sysfs topology, a missing network interface, an
// unknown MCA parameter), and mpirun adds its notes on exit statuses: none of that is sweetspot's,
// and none of it breaks the promise that sweetspot's own refusal is one line. sweetspot's lines
// are known by their prefix, not the library's by a list of its messages (which change with its
// version and its plugins): "sweetspot..." (its errors and warnings, "sweetspot: error: ...") and
// the log's time stamp, "[12:00:00] " or "[12:00:00 rank 1] ".
#include <regex>
#include <sstream>
#include <string>
#include <vector>

inline bool is_own_line(const std::string& line) {
  static const std::regex log_stamp(R"(\[\d\d:\d\d:\d\d( rank \d+)?\] .*)");
  return line.starts_with("sweetspot") || std::regex_match(line, log_stamp);
}

// The output's lines, without their newlines, that are sweetspot's own (`own`) or not.
inline std::vector<std::string> output_lines(const std::string& output, bool own) {
  std::vector<std::string> lines;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (is_own_line(line) == own) lines.push_back(line);
  return lines;
}

inline std::vector<std::string> own_lines(const std::string& output) { return output_lines(output, true); }
inline std::vector<std::string> foreign_lines(const std::string& output) { return output_lines(output, false); }
