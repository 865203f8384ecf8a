#pragma once
// The journal of a study run: finished points appended to OUT.journal as they arrive, so that a
// run killed at any moment (even SIGKILL) keeps what it finished and `--resume` computes only the
// rest.
//
// A journal is untrusted input: anyone can edit, truncate or swap the file between the kill and
// the resume. Format (little-endian as the machine writes it; a journal does not move between
// machines):
//   header, 56 bytes: "SWSPJNL2", then the key as 5 x uint64 (study text, bat and profile bytes,
//     program version, points, values per point; JournalKey) and a checksum of those 48 bytes.
//   records, each one write(): uint64 count (1..points), count x (uint64 point, `width` doubles),
//     then a checksum (FNV-1a, 64 bits) of the record's bytes before it.
// A journal whose header is damaged or whose key is not the study's is refused (InputError),
// never deleted. In the records, the first one that is torn, fails its checksum or holds anything
// out of place (a count or point outside the study, a point twice, a row the caller's check
// refuses) is dropped with everything after it: those points are computed again. Nothing is
// allocated from a count before it is checked against the study and the file's size, so memory
// stays bounded by the study whatever the file says.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sweetspot/study/study.hpp"

namespace sweetspot {

// Everything that determines a study's results: a journal keyed otherwise is another run's.
struct JournalKey {
  std::uint64_t study = 0;    // the study file's text
  std::uint64_t inputs = 0;   // the bytes of every bat file and profile, in the study's bat order
  std::uint64_t program = 0;  // the program's version and commit
  std::uint64_t points = 0;   // grid points
  std::uint64_t width = 0;    // values per point

  bool operator==(const JournalKey&) const = default;
};

// The key of `study` with rows of `width` values; reads every bat file and profile again (throws
// InputError if one has become unreadable).
JournalKey journal_key(const Study& study, std::uint64_t width);
// The key of any run read from one file (`text`) and the bats it names (`sources`, as read),
// with `points` rows of `width` values: what the optimiser's journal is keyed on.
JournalKey journal_key(const std::string& text, const std::vector<BatSource>& sources, std::uint64_t points,
                       std::uint64_t width);

// Why a recovered row cannot be kept (e.g. a status outside the enumeration), or "" to keep it.
using RowCheck = std::function<std::string(const double* row)>;

class Journal {
 public:
  // Opens the journal at `path`. Without resume, an existing journal is refused (InputError: it
  // holds finished work the user may want). With resume, the records of an existing journal with
  // this key are kept (recovered_points()); a journal with another key or a damaged header is
  // refused. Either way the journal is then rewritten holding just the records kept.
  Journal(const std::filesystem::path& path, const JournalKey& key, bool resume, const RowCheck& check);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  // The points recovered, and their rows (width values each, in the same order).
  const std::vector<std::uint64_t>& recovered_points() const { return recovered_points_; }
  const std::vector<double>& recovered_values() const { return recovered_values_; }
  // Why records were dropped on reading ("" when none were): for the log.
  const std::string& dropped() const { return dropped_; }

  // Appends finished points: values holds width values per point, in the order of `points`.
  void append(const std::vector<std::uint64_t>& points, const std::vector<double>& values);
  // Replaces the journal by one holding just these points (width values each): for a run that
  // finds a recovered record it cannot use, so that the records after it are not kept twice.
  void rewrite(const std::vector<std::uint64_t>& points, const std::vector<double>& values);
  // Removes the journal once the dataset is safely written.
  void remove();

  static std::filesystem::path path_for(const std::filesystem::path& output) { return output.string() + ".journal"; }
  // Where the journal is rewritten before it replaces the old one.
  static std::filesystem::path rewrite_path(const std::filesystem::path& journal) {
    return journal.string() + ".new";
  }

 private:
  void read_existing(const RowCheck& check);
  void write_fresh(const std::vector<std::uint64_t>& points, const std::vector<double>& values);
  std::filesystem::path path_;
  JournalKey key_;
  int fd_ = -1;
  std::vector<std::uint64_t> recovered_points_;
  std::vector<double> recovered_values_;
  std::string dropped_;
};

}  // namespace sweetspot
