#pragma once
// Runs the sweetspot program from a test and captures what it prints and how it exits.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

struct ProgramRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline ProgramRun run_program(const std::string& arguments) {
  const std::string command = std::string(SWEETSPOT_PROGRAM) + " " + arguments + " 2>&1";
  ProgramRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) run.output += buffer.data();
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

inline std::string source_path(const std::string& relative) {
  return std::string(SWEETSPOT_SOURCE_DIR) + "/" + relative;
}
