#pragma once
// Runs a study over MPI ranks and OpenMP threads (design.md). Rank 0 coordinates: it hands out
// chunks of points in model-major order, so a chunk reuses one modal basis, and computes chunks
// itself between requests. Every rank caches the modes of each (design, slices, theory) it meets,
// up to cached_models of them between chunks.
// Each point is computed alone and stored by its grid index, so the dataset is bitwise the same
// for any number of ranks and threads.
#include <filesystem>
#include <functional>

#include "sweetspot/input_error.hpp"
#include "sweetspot/study/dataset.hpp"
#include "sweetspot/study/study.hpp"

namespace sweetspot {

enum class Verbosity { quiet, normal, verbose };

// Tasks run model-major, so a rank meets few models again: once it keeps more than this many
// modal bases, it forgets them all before its next chunk, which bounds memory over thousands of
// bats (a model met again is solved again, to the same bits).
inline constexpr std::size_t cached_models = 16;

struct RunOptions {
  std::filesystem::path output;  // the dataset; OUT.journal and OUT.lock beside it while running
  bool resume = false;           // keep the journal's finished points
  Verbosity verbosity = Verbosity::normal;
  // Called on rank 0 with the finished dataset before it is written: what a study kind derives
  // from all points together (an uncertainty study's statistics) goes in here.
  std::function<void(Dataset&)> finish = {};
};

// A run refused before any rank did any work: the output cannot or must not be written
// (output_paths.hpp), another run holds it (output_lock.hpp), or its journal cannot be trusted
// (journal.hpp). Thrown on every rank with rank 0's one-line reason, so that all stop together.
class RunRefused : public InputError {
 public:
  using InputError::InputError;
};

// Every rank learns rank 0's refusal (empty: none) and, if there is one, throws RunRefused with it
// (a rank that went on alone would wait for the others forever). Call on every rank.
void share_refusal(std::string refusal);

// Call between MPI_Init_thread and MPI_Finalize on every rank. Rank 0 checks the output, locks
// it for the run, reads the journal, and writes the dataset.
void run_study(const Study& study, const RunOptions& options);

}  // namespace sweetspot
