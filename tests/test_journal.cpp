// Journals are untrusted input, and one output has one run at a time. A journal cut at any
// byte, with bytes flipped at random, or with records whose checksum is right but whose contents
// are not, resumes to the dataset of an uninterrupted run bit for bit (what cannot be trusted is
// computed again); a journal that is not this study's (edited study, bat or profile, another
// build) is refused and kept; a second run on an output in use is refused naming the process.
#include <catch2/catch.hpp>

#include <signal.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "program.hpp"
#include "study_dir.hpp"
#include "text_edit.hpp"

namespace {

namespace fs = std::filesystem;

// The journal format of journal.hpp, written out again here so that a test can craft records
// the program must refuse even though their checksum is right.
constexpr std::size_t header_size = 56;
constexpr std::size_t width = 5;  // the default outputs: vf, e_eff, contact_time, collision_time, status
constexpr std::size_t entry_size = 8 * (1 + width);
using Row = std::array<double, width>;
constexpr double missing = std::numeric_limits<double>::quiet_NaN();

std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::uint64_t word_at(const std::string& bytes, std::size_t at) {
  std::uint64_t w = 0;
  std::memcpy(&w, bytes.data() + at, sizeof w);
  return w;
}

template <class T>
void put(std::string& bytes, T value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// A record of `points` with their rows and the right checksum.
std::string record(const std::vector<std::uint64_t>& points, const std::vector<Row>& rows) {
  std::string r;
  put<std::uint64_t>(r, points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    put(r, points[i]);
    for (double x : rows[i]) put(r, x);
  }
  put(r, fnv1a(r));
  return r;
}

// Where each whole record ends (the header's end first): the journal's record boundaries.
std::vector<std::size_t> record_ends(const std::string& journal) {
  std::vector<std::size_t> ends{header_size};
  while (ends.back() + 8 <= journal.size()) {
    const std::size_t end = ends.back() + 16 + word_at(journal, ends.back()) * entry_size;
    if (end > journal.size()) break;
    ends.push_back(end);
  }
  return ends;
}

// The points the records before `end` hold.
std::set<std::uint64_t> points_before(const std::string& journal, std::size_t end) {
  std::set<std::uint64_t> points;
  for (std::size_t at = header_size; at < end;) {
    const std::uint64_t count = word_at(journal, at);
    for (std::uint64_t i = 0; i < count; ++i) points.insert(word_at(journal, at + 8 + i * entry_size));
    at += 16 + count * entry_size;
  }
  return points;
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// A program started in the background: its pid and, once it ends, its exit status, from files
// (the shell that starts it does not wait for it).
class Background {
 public:
  Background(const fs::path& dir, const std::string& name, const std::string& command)
      : pid_file_(dir / (name + ".pid")), status_file_(dir / (name + ".status")), log_(dir / (name + ".log")) {
    run_command("(sh -c 'echo $$ > " + pid_file_.string() + "; exec " + command + "' > " + log_.string() +
                " 2>&1; echo $? > " + status_file_.string() + ") > /dev/null 2>&1 &");
    REQUIRE(poll([this] { return !file_text(pid_file_).empty() && file_text(pid_file_).back() == '\n'; }));
    pid_ = std::stoi(file_text(pid_file_));
  }
  int pid() const { return pid_; }
  bool ended() const { return fs::exists(status_file_) && !file_text(status_file_).empty(); }
  // Waits for the end; the exit status as the shell gives it (128 + signal for a killed run).
  int wait() {
    REQUIRE(poll([this] { return ended(); }));
    return std::stoi(file_text(status_file_));
  }
  std::string log() const { return file_text(log_); }

  // Polls `done` every millisecond for at most a minute.
  template <class Done>
  static bool poll(Done done) {
    for (int i = 0; i < 60000; ++i) {
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }

 private:
  fs::path pid_file_, status_file_, log_;
  int pid_ = 0;
};

std::uintmax_t size_or_zero(const fs::path& path) {
  std::error_code ignored;
  const std::uintmax_t size = fs::file_size(path, ignored);
  return ignored ? 0 : size;
}

// Starts `command` in the background and waits until `journal` holds at least `bytes`, or the
// run has ended (then returns false).
bool wait_for_journal(const Background& run, const fs::path& journal, std::uintmax_t bytes) {
  REQUIRE(Background::poll([&] { return size_or_zero(journal) >= bytes || run.ended(); }));
  return !run.ended();
}

// A study of 400 points taking about 0.7 s on one thread (a fine step makes each point slow
// enough that a run can be caught mid-way by a test polling its journal every millisecond).
StudyDir slow_study() { return StudyDir(100, "dt = 2e-7\n"); }

// A study of 1600 quick points (about 0.2 s on one thread, so that the many resumes of a test
// stay cheap), its dataset from an uninterrupted run, and the journal of a run of it killed with
// SIGKILL when about half done. A run may slip past the poll on a busy machine: a few tries.
struct KilledRun {
  StudyDir s{400};
  std::string journal;
  std::size_t points = 1600;

  KilledRun() {
    const ProgramRun whole = run_program("run " + s.study.string() + " -o " + s / "whole.h5 --quiet");
    INFO(whole.output);
    REQUIRE(whole.exit_code == 0);
    for (int attempt = 0; attempt < 5 && journal.empty(); ++attempt) {
      fs::remove(s / "killed.h5");
      // One thread at the lowest priority: the journal grows by small records, slowly enough
      // to be caught.
      Background run(s.dir.path, "killed" + std::to_string(attempt),
                     "env OMP_NUM_THREADS=1 nice -n 19 " + std::string(SWEETSPOT_PROGRAM) + " run " +
                         s.study.string() + " -o " + s / "killed.h5 --quiet");
      const bool caught = wait_for_journal(run, s / "killed.h5.journal", header_size + points * entry_size / 2);
      if (caught) ::kill(run.pid(), SIGKILL);
      const int status = run.wait();
      if (!caught) continue;
      REQUIRE(status == 128 + SIGKILL);
      journal = file_text(s / "killed.h5.journal");
    }
    REQUIRE_FALSE(journal.empty());
    REQUIRE(record_ends(journal).size() >= 4);  // a header and at least three records
    CHECK(fs::exists(s / "killed.h5.lock"));    // the killed run's lock file: it must block nothing
  }

  // Resumes into `name`.h5 from a journal holding `bytes`.
  ProgramRun resume(const std::string& name, const std::string& bytes, const std::string& prefix = "") const {
    write_bytes(s / (name + ".h5.journal"), bytes);
    return run_command(prefix + SWEETSPOT_PROGRAM + " run " + s.study.string() + " -o " + s / (name + ".h5") +
                       " --resume");
  }

  // A resumed run that must have given the uninterrupted dataset, and left neither its journal
  // nor its lock behind.
  void require_resumed(const ProgramRun& run, const std::string& name) const {
    INFO(name << "\n" << run.output);
    REQUIRE(run.exit_code == 0);
    CHECK_FALSE(fs::exists(s / (name + ".h5.journal")));
    CHECK_FALSE(fs::exists(s / (name + ".h5.lock")));
  }

  // Every dataset named is bit for bit the uninterrupted one (one Python for them all).
  void require_identical(const std::vector<std::string>& names) const {
    std::string command = std::string(python) + " " + source_path("tests/compare_datasets.py") + " " + s / "whole.h5";
    for (const std::string& name : names) command.append(" ").append(s / (name + ".h5"));
    const ProgramRun compare = run_command(command);
    INFO(compare.output);
    REQUIRE(compare.exit_code == 0);
  }

  // A refused resume: the journal kept byte for byte, no dataset written.
  void require_refused_kept(const ProgramRun& run, const std::string& name, const std::string& bytes,
                            const std::string& expected) const {
    INFO(name);
    require_refused(run, expected);
    CHECK(file_text(s / (name + ".h5.journal")) == bytes);
    CHECK_FALSE(fs::exists(s / (name + ".h5")));
    CHECK_FALSE(fs::exists(s / (name + ".h5.lock")));
  }
};

}  // namespace

TEST_CASE("A journal cut at every record boundary and inside records resumes to the uninterrupted dataset",
          "[run][journal]") {
  const KilledRun k;
  const std::vector<std::size_t> ends = record_ends(k.journal);
  std::vector<std::string> resumed;
  std::vector<std::size_t> cuts;
  for (std::size_t i = 0; i < ends.size(); ++i) cuts.push_back(ends[i]);  // at a boundary: nothing to drop
  // Torn records: a count alone, inside an entry, the checksum short by a byte.
  for (std::size_t cut : {ends[1] + 8, ends[1] + 61, ends[2] - 1}) cuts.push_back(cut);
  if (k.journal.size() != ends.back()) cuts.push_back(k.journal.size());  // as the kill left it
  for (std::size_t cut : cuts) {
    const std::string name = "cut" + std::to_string(cut);
    const ProgramRun run = k.resume(name, k.journal.substr(0, cut));
    k.require_resumed(run, name);
    const bool at_boundary = std::find(ends.begin(), ends.end(), cut) != ends.end();
    if (at_boundary) CHECK_THAT(run.output, !Catch::Contains("dropped"));
    else CHECK_THAT(run.output, Catch::Contains("torn"));
    const std::size_t kept = points_before(k.journal, *std::prev(std::upper_bound(ends.begin(), ends.end(), cut))).size();
    if (kept > 0) CHECK_THAT(run.output, Catch::Contains("resuming: " + std::to_string(kept) + " of 1600"));
    resumed.push_back(name);
  }
  k.require_identical(resumed);
  // A cut inside the header leaves no journal to trust: refused, and kept for the user to judge.
  // Past its 8-byte magic, the cut is named as one.
  for (std::size_t cut : {0, 7, 8, 40, 55}) {
    const std::string name = "header" + std::to_string(cut), bytes = k.journal.substr(0, cut);
    k.require_refused_kept(k.resume(name, bytes), name, bytes,
                           cut < 8 ? "not a journal of this sweetspot"
                                   : "its header is cut short (" + std::to_string(cut) + " of 56 bytes)");
  }
}

// Every (point, row) entry of a journal's whole records, in their order.
std::vector<std::pair<std::uint64_t, Row>> entries_of(const std::string& journal) {
  std::vector<std::pair<std::uint64_t, Row>> entries;
  const std::vector<std::size_t> ends = record_ends(journal);
  for (std::size_t r = 0; r + 1 < ends.size(); ++r)
    for (std::uint64_t i = 0; i < word_at(journal, ends[r]); ++i) {
      const std::size_t at = ends[r] + 8 + i * entry_size;
      Row row;
      std::memcpy(row.data(), journal.data() + at + 8, sizeof row);
      entries.emplace_back(word_at(journal, at), row);
    }
  return entries;
}

// A journal of the header and `entries`, `per_record` of them to a record.
std::string journal_of(const std::string& header, const std::vector<std::pair<std::uint64_t, Row>>& entries,
                       std::size_t per_record) {
  std::string bytes = header;
  for (std::size_t from = 0; from < entries.size(); from += per_record) {
    std::vector<std::uint64_t> points;
    std::vector<Row> rows;
    for (std::size_t i = from; i < std::min(from + per_record, entries.size()); ++i) {
      points.push_back(entries[i].first);
      rows.push_back(entries[i].second);
    }
    bytes += record(points, rows);
  }
  return bytes;
}

TEST_CASE("Two and three ranks resume from journals of any pattern of recovered points and end", "[run][journal][mpi]") {
  // Rank 0 hands out what the journal lacks and answers every request, whatever is left: the
  // whole recovered prefix, holes between every other point, one point or none recovered.
  const KilledRun k;
  const auto entries = entries_of(k.journal);
  REQUIRE(entries.size() >= 8);
  std::vector<std::pair<std::uint64_t, Row>> every_other, all_but_first(entries.begin() + 1, entries.end());
  for (std::size_t i = 0; i < entries.size(); i += 2) every_other.push_back(entries[i]);
  const std::string header = k.journal.substr(0, header_size);
  struct Pattern {
    std::string name, bytes;
    int ranks;
  };
  const Pattern patterns[] = {
      {"mpi_all", journal_of(header, entries, entries.size()), 2},
      {"mpi_every_other", journal_of(header, every_other, 7), 2},
      {"mpi_every_other3", journal_of(header, every_other, 3), 3},
      {"mpi_all_but_first", journal_of(header, all_but_first, 50), 2},
      {"mpi_first", journal_of(header, {entries.front()}, 1), 2},
      {"mpi_last", journal_of(header, {entries.back()}, 1), 2},
      {"mpi_none", header, 2},
  };
  std::vector<std::string> resumed;
  for (const Pattern& p : patterns) {
    // A hang fails here (timeout's 124) instead of stopping the suite.
    const ProgramRun run = k.resume(p.name, p.bytes,
                                    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 "
                                    "timeout 120 mpirun -np " + std::to_string(p.ranks) +
                                        " --oversubscribe --bind-to none ");
    k.require_resumed(run, p.name);
    CHECK_THAT(run.output, Catch::Contains("points on " + std::to_string(p.ranks) + " rank(s)"));
    resumed.push_back(p.name);
  }
  k.require_identical(resumed);
}

TEST_CASE("Random byte flips in a journal never reach the dataset", "[run][journal]") {
  const KilledRun k;
  std::mt19937 random(20240611);  // fixed: the same trials every time
  std::vector<std::string> resumed;
  for (int trial = 0; trial < 12; ++trial) {
    std::string bytes = k.journal;
    bool header = false;
    const int flips = 1 + static_cast<int>(random() % 3);
    for (int f = 0; f < flips; ++f) {
      // The first trials flip inside the header, which a uniform draw would seldom hit.
      const std::size_t at = trial < 3 ? random() % header_size : random() % bytes.size();
      bytes[at] = static_cast<char>(bytes[at] ^ (1 + random() % 255));
      header = header || at < header_size;
    }
    const std::string name = "flip" + std::to_string(trial);
    const ProgramRun run = k.resume(name, bytes);
    INFO("trial " << trial << ", " << flips << " flips");
    if (header) {
      CHECK_THAT(run.output, Catch::Contains("header"));
      k.require_refused_kept(run, name, bytes, "refusing to resume from it");
    } else {
      k.require_resumed(run, name);
      resumed.push_back(name);
    }
  }
  REQUIRE(resumed.size() >= 8);
  k.require_identical(resumed);
}

TEST_CASE("Journal records with a right checksum but wrong contents are dropped, memory bounded", "[run][journal]") {
  const KilledRun k;
  const std::vector<std::size_t> ends = record_ends(k.journal);
  const std::string kept = k.journal.substr(0, ends.back());  // every whole record
  const std::set<std::uint64_t> done = points_before(k.journal, ends.back());
  std::uint64_t free_point = 0;
  while (done.count(free_point)) ++free_point;
  const Row ok{40, 0.2, 1e-3, 1e-3, 0};
  const auto with_status = [&](double status, double vf = missing) { return Row{vf, missing, missing, missing, status}; };
  std::string huge_count, short_record;
  put<std::uint64_t>(huge_count, std::uint64_t(1) << 61);
  put<std::uint64_t>(short_record, 100000000);  // 1e8 points said, a few bytes given
  short_record += std::string(200, 'x');
  struct Case {
    std::string name, tail, expected;
  };
  const Case cases[] = {
      {"past_end", record({k.points}, {ok}), "point 1600 outside the study's 1600"},
      {"far", record({1000000000000}, {ok}), "point 1000000000000 outside"},
      {"twice", record({*done.begin()}, {ok}), "recorded twice"},
      {"twice_in_one", record({free_point, free_point}, {ok, ok}), "recorded twice"},
      {"status_huge", record({free_point}, {with_status(1e300)}), "status 1e+300 is none of the statuses"},
      {"status_fraction", record({free_point}, {with_status(2.5)}), "status 2.5 is none"},
      {"status_negative", record({free_point}, {with_status(-1)}), "status -1 is none"},
      {"status_nan", record({free_point}, {with_status(missing)}), "status nan is none"},
      {"ok_without_vf", record({free_point}, {with_status(0)}), "status ok with vf = nan"},
      {"failed_with_vf", record({free_point}, {with_status(1, 40)}), "a failed point with a value 40"},
      {"count_huge", huge_count, "count 2305843009213693952 outside"},
      {"count_1e8", short_record, "count 100000000 outside"},
      {"count_zero", record({}, {}), "count 0 outside"},
  };
  std::vector<std::string> resumed;
  for (const Case& c : cases) {
    // Bounded memory: a journal that could make the run allocate by its word fails under the limit.
    // After the bad record, one that looks sound: dropped too (nothing after damage is trusted),
    // or its made-up row would reach the dataset.
    const std::string after = record({free_point + 1}, {ok});
    const ProgramRun run = k.resume(c.name, kept + c.tail + after, "ulimit -v 4000000; ");
    k.require_resumed(run, c.name);
    CHECK_THAT(run.output, Catch::Contains(c.expected) && Catch::Contains("dropped"));
    CHECK_THAT(run.output, Catch::Contains("resuming: " + std::to_string(done.size()) + " of 1600"));
    resumed.push_back(c.name);
  }
  k.require_identical(resumed);
}

TEST_CASE("A journal is refused and kept when the study, a bat, a profile or the program changed", "[run][journal]") {
  const KilledRun k;
  const std::string bat = k.s / "bats/r161.toml", profile = k.s / "bats/torpedo_profile.csv";
  const std::string bat_text = file_text(bat), profile_text = file_text(profile), study_text = file_text(k.s.study);
  // The header as another build would write it: its program word changed, its checksum right.
  std::string other_build = k.journal;
  other_build[24] = static_cast<char>(other_build[24] ^ 1);
  const std::uint64_t sum = fnv1a(std::string_view(other_build).substr(0, header_size - 8));
  std::memcpy(other_build.data() + header_size - 8, &sum, 8);
  std::string damaged_key = k.journal;
  damaged_key[16] = static_cast<char>(damaged_key[16] ^ 1);

  k.require_refused_kept(k.resume("other_build", other_build), "other_build", other_build,
                         "written by another build of sweetspot");
  k.require_refused_kept(k.resume("damaged_key", damaged_key), "damaged_key", damaged_key, "its header is damaged");
  k.require_refused_kept(k.resume("text", "results: 1 2 3\n"), "text", "results: 1 2 3\n",
                         "not a journal of this sweetspot");

  write_bytes(bat, with(bat_text, "density = 649", "density = 700"));
  k.require_refused_kept(k.resume("density", k.journal), "density", k.journal,
                         "written with other bat or profile files than the file names now");
  write_bytes(bat, bat_text);
  write_bytes(profile, with(profile_text, "2,0.0150,0.043970", "2,0.0150,0.043971"));
  k.require_refused_kept(k.resume("profile", k.journal), "profile", k.journal, "other bat or profile files");
  write_bytes(profile, profile_text);
  write_bytes(k.s.study, "# edited\n" + study_text);
  k.require_refused_kept(k.resume("study", k.journal), "study", k.journal, "written for another study (or optimisation) file's text");
  write_bytes(k.s.study, study_text);

  // Without --resume, a journal is finished work the user may want: refused, not overwritten.
  write_bytes(k.s / "fresh.h5.journal", k.journal);
  const ProgramRun fresh = run_program("run " + k.s.study.string() + " -o " + k.s / "fresh.h5");
  k.require_refused_kept(fresh, "fresh", k.journal, "expected --resume to keep its finished points");

  // Everything as it was: the journals kept resume to the uninterrupted dataset.
  for (const std::string name : {"density", "profile", "study", "fresh"}) {
    const ProgramRun run = run_command(std::string(SWEETSPOT_PROGRAM) + " run " + k.s.study.string() + " -o " +
                                       k.s / (name + ".h5") + " --resume");
    k.require_resumed(run, name);
  }
  k.require_identical({"density", "profile", "study", "fresh"});
}

TEST_CASE("A second run on an output in use is refused naming the process, and the first finishes", "[run][journal]") {
  const StudyDir s = slow_study();
  REQUIRE(run_program("run " + s.study.string() + " -o " + s / "whole.h5 --quiet").exit_code == 0);
  const std::string out = s / "out.h5";
  Background first(s.dir.path, "first",
                   "env OMP_NUM_THREADS=1 nice -n 19 " + std::string(SWEETSPOT_PROGRAM) + " run " + s.study.string() + " -o " +
                       out + " --quiet");
  const bool caught = wait_for_journal(first, out + ".journal", header_size + 100 * entry_size);
  ::kill(first.pid(), SIGSTOP);  // held mid-run, so that the second runs meet a live first
  REQUIRE(caught);
  const std::string journal = file_text(out + ".journal");
  const std::string holder = "another sweetspot run (process " + std::to_string(first.pid()) + ")";
  for (const std::string& second : {"run " + s.study.string() + " -o " + out,
                                    "run " + s.study.string() + " -o " + out + " --resume",
                                    "run " + s.study.string() + " -o " + s / "./bats/../out.h5 --resume"})
    require_refused(run_program(second), holder);
  require_refused(run_program_mpi(2, 1, "run " + s.study.string() + " -o " + out + " --resume"), holder);
  CHECK(file_text(out + ".journal") == journal);
  CHECK_FALSE(fs::exists(out));
  ::kill(first.pid(), SIGCONT);
  INFO(first.log());
  REQUIRE(first.wait() == 0);
  CHECK_FALSE(fs::exists(out + ".lock"));
  const ProgramRun compare =
      run_command(std::string(python) + " " + source_path("tests/compare_datasets.py") + " " + s / "whole.h5 " + out);
  INFO(compare.output);
  CHECK(compare.exit_code == 0);
}

TEST_CASE("Under mpirun rank 0 holds the output's lock", "[run][journal][mpi]") {
  const StudyDir s = slow_study();
  const std::string out = s / "out.h5";
  Background first(s.dir.path, "first",
                   "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 nice -n 19 mpirun -np 2 "
                   "--oversubscribe --bind-to none " +
                       std::string(SWEETSPOT_PROGRAM) + " run " + s.study.string() + " -o " + out + " --quiet");
  const bool caught = wait_for_journal(first, out + ".journal", header_size + 50 * entry_size);
  // Rank 0 wrote its pid in the lock file: hold it there (rank 1 waits for it meanwhile).
  const int rank0 = std::stoi(file_text(out + ".lock"));
  ::kill(rank0, SIGSTOP);
  REQUIRE(caught);
  require_refused(run_program("run " + s.study.string() + " -o " + out + " --resume"),
                  "another sweetspot run (process " + std::to_string(rank0) + ")");
  ::kill(rank0, SIGCONT);
  INFO(first.log());
  REQUIRE(first.wait() == 0);
  CHECK_FALSE(fs::exists(out + ".lock"));
  CHECK(fs::exists(out));
}

TEST_CASE("Valgrind finds no memory error on the journal-reading path", "[run][journal][valgrind]") {
  // The killed run's records, then records for all but a few of the other points made from the
  // uninterrupted dataset (so that the run under valgrind, ~50 times slower, has little left to
  // compute), then a record with one byte flipped and a torn one: every branch of the reading.
  const KilledRun k;
  const std::vector<std::size_t> ends = record_ends(k.journal);
  const ProgramRun dump = run_command(
      std::string(python) + " -c \"import h5py, numpy as np; f = h5py.File('" + k.s / "whole.h5" +
      "'); np.stack([f[v][()].astype('f8').ravel() for v in ('vf', 'e_eff', 'contact_time', 'collision_time', "
      "'status')], 1).tofile('" + k.s / "rows.bin" + "')\"");
  INFO(dump.output);
  REQUIRE(dump.exit_code == 0);
  const std::string rows = file_text(k.s / "rows.bin");
  REQUIRE(rows.size() == k.points * width * sizeof(double));
  const std::set<std::uint64_t> done = points_before(k.journal, ends.back());
  std::vector<std::uint64_t> points;
  std::vector<Row> values;
  for (std::uint64_t p = 0; p < k.points - 5; ++p)
    if (!done.count(p)) {
      points.push_back(p);
      values.emplace_back();
      std::memcpy(values.back().data(), rows.data() + p * sizeof(Row), sizeof(Row));
    }
  std::string flipped = record({k.points - 2}, {values.front()});
  flipped[20] = static_cast<char>(flipped[20] ^ 4);
  const std::string journal = k.journal.substr(0, ends.back()) + record(points, values) + flipped + "torn";
  // The program allocates through mimalloc: memcheck replaces its malloc and free as it does
  // glibc's (its operator delete[] is free under another name: tests/valgrind_profiles.sh).
  const ProgramRun run = k.resume(
      "valgrind", journal,
      "valgrind -q --error-exitcode=99 --soname-synonyms=somalloc='*mimalloc*' --show-mismatched-frees=no ");
  k.require_resumed(run, "valgrind");
  CHECK_THAT(run.output, Catch::Contains("checksum mismatch"));
  CHECK_THAT(run.output, Catch::Contains("resuming: 1595 of 1600"));
  k.require_identical({"valgrind"});
}
