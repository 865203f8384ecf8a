#pragma once
// The frame of the commands that run alone or under mpirun (run, optimize): the file, -o, --resume,
// --quiet and --verbose; MPI's start and end; refusals that every rank reaches before any work,
// said once by rank 0; and the abort of a rank that fails once the work has begun.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>

#include "sweetspot/study/parallel.hpp"

namespace sweetspot::app {

// What the command line says of the command.
struct MpiCommandText {
  const char* name;          // "run"
  const char* description;
  const char* file;          // the input file's argument name and help
  const char* file_help;
  const char* output_help;   // -o
  const char* resume_help;   // --resume
  const char* verbose_help;  // --verbose
};

// `load` reads and checks the input file on every rank (an InputError refuses before any work);
// `work` then runs it with the options of the command line (a RunRefused refuses, thrown on every
// rank before any work). The output defaults to the input file's name with the extension .h5.
using LoadInput = std::function<void(const std::string& file)>;
using RunWork = std::function<void(const RunOptions& options)>;
void add_mpi_command(CLI::App& app, const MpiCommandText& text, LoadInput load, RunWork work);

}  // namespace sweetspot::app
