#include "mpi_command.hpp"

#include <mpi.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot::app {

namespace {

struct MpiCommandOptions {
  std::string file;
  std::string output;
  bool output_given = false;  // `-o ""` is a mistake to refuse, not a wish for the default
  bool resume = false, quiet = false, verbose = false;
};

// Rank 0 says why, and the others wait until it has: mpirun stops the job at the first non-zero
// exit, which could otherwise cut rank 0 off before its message.
[[noreturn]] void refuse(const std::string& message, int rank) {
  if (rank == 0) std::fprintf(stderr, "sweetspot: error: %s\n", printable(message).c_str());
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  std::exit(2);
}

RunOptions run_options(const MpiCommandOptions& o) {
  RunOptions options;
  options.output = o.output_given ? o.output : std::filesystem::path(o.file).stem().string() + ".h5";
  options.resume = o.resume;
  options.verbosity = o.quiet ? Verbosity::quiet : o.verbose ? Verbosity::verbose : Verbosity::normal;
  return options;
}

void run_command(const MpiCommandOptions& o, const LoadInput& load, const RunWork& work) {
  int provided = 0, rank = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  spdlog::set_pattern(rank == 0 ? "[%H:%M:%S] %v" : "[%H:%M:%S rank " + std::to_string(rank) + "] %v");
  if (o.quiet) spdlog::set_level(spdlog::level::warn);
  try {
    load(o.file);  // every rank validates; a bad file stops before any work
  } catch (const InputError& e) {
    refuse(e.what(), rank);
  }
  try {
    work(run_options(o));
  } catch (const RunRefused& e) {  // thrown on every rank, before any work
    refuse(e.what(), rank);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweetspot: error on rank %d: %s\n", rank, printable(e.what()).c_str());
    MPI_Abort(MPI_COMM_WORLD, 1);  // the other ranks would wait for this one forever
  }
  MPI_Finalize();
}

}  // namespace

void add_mpi_command(CLI::App& app, const MpiCommandText& text, LoadInput load, RunWork work) {
  auto o = std::make_shared<MpiCommandOptions>();
  CLI::App* cmd = app.add_subcommand(text.name, text.description);
  cmd->add_option(text.file, o->file, text.file_help)->required();
  CLI::Option* output = cmd->add_option("-o,--output", o->output, text.output_help);
  cmd->add_flag("--resume", o->resume, text.resume_help);
  auto* quiet = cmd->add_flag("--quiet", o->quiet, "only warnings and errors");
  auto* verbose = cmd->add_flag("--verbose", o->verbose, text.verbose_help);
  quiet->excludes(verbose);
  cmd->callback([o, output, load = std::move(load), work = std::move(work)] {
    o->output_given = output->count() > 0;
    run_command(*o, load, work);
  });
}

}  // namespace sweetspot::app
