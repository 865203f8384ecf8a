#pragma once
// A refusal of bad input as the program makes it: exit status 2 and, of sweetspot's own lines,
// exactly one, `sweetspot: error: ...`, holding every expected fragment. Lines the MPI library
// adds to stderr (a start-up warning, mpirun's note on the exit status) are not sweetspot's and
// are let be (own_lines.hpp).
#include <catch2/catch.hpp>

#include <initializer_list>
#include <string>
#include <vector>

#include "own_lines.hpp"
#include "program.hpp"

// The one line of sweetspot's own that a refusal printed, checked to be a refusal's; "" unless
// there is exactly one.
inline std::string refusal_line(const ProgramRun& run) {
  INFO(run.output);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, !Catch::Contains("MPI_ABORT"));
  const std::vector<std::string> own = own_lines(run.output);
  CHECK(own.size() == 1);
  if (own.size() != 1) return "";
  CHECK_THAT(own.front(), Catch::StartsWith("sweetspot: error: "));
  return own.front();
}

inline void require_refused(const ProgramRun& run, std::initializer_list<std::string> fragments) {
  INFO(run.output);
  const std::string line = refusal_line(run);
  for (const std::string& fragment : fragments) CHECK_THAT(line, Catch::Contains(fragment));
}
