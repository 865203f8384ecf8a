#pragma once
// The journal of a study run: finished points appended to OUT.journal as they arrive, so that a
// run killed at any moment (even SIGKILL) keeps what it finished and `--resume` computes only the
// rest. Each record repeats its length at its end; a torn last record is ignored on reading.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sweetspot {

struct JournalEntry {
  std::uint64_t point;
  std::vector<double> values;  // `width` values
};

class Journal {
 public:
  // Opens `path` for appending. With resume, keeps the records already there when the header
  // matches (same study, same width) and returns them through recovered(); otherwise starts anew.
  Journal(const std::filesystem::path& path, std::uint64_t study_hash, std::uint64_t width, bool resume);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  const std::vector<JournalEntry>& recovered() const { return recovered_; }
  // Appends finished points: values holds width values per point, in the order of `points`.
  void append(const std::vector<std::uint64_t>& points, const std::vector<double>& values);
  // Removes the journal once the dataset is safely written.
  void remove();

 private:
  void read_existing(std::uint64_t study_hash);
  std::filesystem::path path_;
  std::uint64_t width_;
  int fd_ = -1;
  std::vector<JournalEntry> recovered_;
};

// FNV-1a of the study text: a journal from another study (or an edited one) is not resumed.
std::uint64_t study_hash(const std::string& text);

}  // namespace sweetspot
