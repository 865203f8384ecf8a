#pragma once
// A refusal of bad input as the program makes it: one line `sweetspot: error: ...` holding every
// expected fragment, and exit status 2.
#include <catch2/catch.hpp>

#include <algorithm>
#include <initializer_list>
#include <string>

#include "program.hpp"

inline void require_refused(const ProgramRun& run, std::initializer_list<std::string> fragments) {
  INFO(run.output);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::StartsWith("sweetspot: error: "));
  CHECK(std::ranges::count(run.output, '\n') == 1);
  for (const std::string& fragment : fragments) CHECK_THAT(run.output, Catch::Contains(fragment));
}
