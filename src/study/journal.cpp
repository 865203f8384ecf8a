#include "sweetspot/study/journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "sweetspot/input_error.hpp"
#include "sweetspot/study/output_paths.hpp"
#include "sweetspot/version.hpp"

namespace sweetspot {

namespace {

namespace fs = std::filesystem;

constexpr char magic[8] = {'S', 'W', 'S', 'P', 'J', 'N', 'L', '2'};
constexpr std::size_t key_words = 5;
constexpr std::size_t header_size = sizeof magic + (key_words + 1) * sizeof(std::uint64_t);

// FNV-1a, 64 bits: a change confined to one byte always changes it (each step is a bijection of
// the running value), and any other damage escapes it with odds of about 2^-64.
struct Checksum {
  std::uint64_t value = 1469598103934665603ull;
  Checksum& add(const void* data, std::size_t size) {
    for (const unsigned char* p = static_cast<const unsigned char*>(data); size > 0; ++p, --size)
      value = (value ^ *p) * 1099511628211ull;
    return *this;
  }
  Checksum& add(std::uint64_t word) { return add(&word, sizeof word); }
  Checksum& add(const std::string& text) { return add(text.size()).add(text.data(), text.size()); }
};

std::array<std::uint64_t, key_words> words(const JournalKey& k) {
  return {k.study, k.inputs, k.program, k.points, k.width};
}

void write_all(int fd, const void* data, std::size_t size, const fs::path& path) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(path.string() + ": cannot write the journal: " + std::strerror(errno));
    p += n, size -= static_cast<std::size_t>(n);
  }
}

std::uint64_t word_at(const char* bytes) {
  std::uint64_t w;
  std::memcpy(&w, bytes, sizeof w);
  return w;
}

// The one line that refuses a journal; the user decides what becomes of the file.
[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
  throw InputError(path.string() + ": " + why + "; refusing to resume from it (delete it, or choose another -o, " +
                   "to start afresh)");
}

}  // namespace

JournalKey journal_key(const std::string& text, const std::vector<BatSource>& sources, std::uint64_t points,
                       std::uint64_t width) {
  // The bats' texts as the run read them, which its results are computed from: a file edited
  // since is no part of this run.
  Checksum inputs;
  for (const BatSource& source : sources) inputs.add(source.toml_text).add(source.profile_text);
  return {Checksum().add(text).value, inputs.value, Checksum().add(std::string(version) + " (" + git_commit + ")").value,
          points, width};
}

JournalKey journal_key(const Study& study, std::uint64_t width) {
  std::vector<BatSource> sources = study.bat_sources;
  sources.push_back(study.reference_source);
  return journal_key(study.text, sources, study.points(), width);
}

Journal::Journal(const fs::path& path, const JournalKey& key, bool resume, const RowCheck& check)
    : path_(path), key_(key) {
  std::error_code error;
  const bool exists = fs::exists(path_, error);
  if (exists && !resume)
    throw InputError(path_.string() + ": the journal of an earlier run on this output (" +
                     std::to_string(fs::file_size(path_, error)) +
                     " bytes) is there; expected --resume to keep its finished points, or delete it to start afresh");
  if (exists) read_existing(check);
  // Rewrite the journal with what was kept: a torn or damaged tail must not stay before new records.
  write_fresh(recovered_points_, recovered_values_);
}

void Journal::rewrite(const std::vector<std::uint64_t>& points, const std::vector<double>& values) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  write_fresh(points, values);
}

void Journal::write_fresh(const std::vector<std::uint64_t>& points, const std::vector<double>& values) {
  const fs::path fresh = rewrite_path(path_);
  fd_ = ::open(fresh.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error(fresh.string() + ": cannot create the journal: " + std::strerror(errno));
  std::array<char, header_size> header;
  std::memcpy(header.data(), magic, sizeof magic);
  const auto key_words_ = words(key_);
  std::memcpy(header.data() + sizeof magic, key_words_.data(), sizeof key_words_);
  const std::uint64_t sum = Checksum().add(header.data(), header_size - sizeof sum).value;
  std::memcpy(header.data() + header_size - sizeof sum, &sum, sizeof sum);
  write_all(fd_, header.data(), header.size(), fresh);
  if (!points.empty()) append(points, values);
  ::fsync(fd_);
  fs::rename(fresh, path_);
}

Journal::~Journal() {
  if (fd_ >= 0) ::close(fd_);
}

void Journal::read_existing(const RowCheck& check) {
  std::ifstream in(path_, std::ios::binary);
  std::error_code error;
  const std::uint64_t size = fs::file_size(path_, error);
  if (!in || error) refuse(path_, "cannot read the journal (" + error.message() + ")");

  std::array<char, header_size> header{};
  in.read(header.data(), static_cast<std::streamsize>(std::min<std::uint64_t>(size, header_size)));
  if (std::memcmp(header.data(), magic, sizeof magic))
    refuse(path_, "not a journal of this sweetspot (no \"SWSPJNL2\" header)");
  // Its magic there but not the rest: a journal cut inside its header, not another file.
  if (size < header_size || !in)
    refuse(path_, "its header is cut short (" + std::to_string(size) + " of " + std::to_string(header_size) +
                      " bytes)");
  const std::uint64_t sum = word_at(header.data() + header_size - sizeof sum);
  if (Checksum().add(header.data(), header_size - sizeof sum).value != sum) refuse(path_, "its header is damaged");
  JournalKey found;
  found.study = word_at(header.data() + 8);
  found.inputs = word_at(header.data() + 16);
  found.program = word_at(header.data() + 24);
  found.points = word_at(header.data() + 32);
  found.width = word_at(header.data() + 40);
  if (found.study != key_.study) refuse(path_, "written for another study (or optimisation) file's text than this one");
  if (found.inputs != key_.inputs)
    refuse(path_, "written with other bat or profile files than the file names now (one changed since)");
  if (found.program != key_.program)
    refuse(path_, std::string("written by another build of sweetspot than this one, ") + version + " (" +
                      git_commit + ")");
  if (!(found == key_)) refuse(path_, "its layout (points, values per point) is not the study's");

  // Records: the first that is not whole and sound ends what is kept.
  const std::uint64_t entry = sizeof(std::uint64_t) + key_.width * sizeof(double);
  std::vector<bool> seen(key_.points, false);
  std::vector<char> record;
  std::uint64_t offset = header_size;
  const auto drop = [&](const std::string& why) {
    dropped_ = "record at byte " + std::to_string(offset) + ": " + why + "; dropped with the " +
               std::to_string(size - offset) + " bytes from there on (their points are computed again)";
  };
  while (offset < size) {
    const std::uint64_t left = size - offset;
    std::uint64_t count = 0;
    if (left < sizeof count || !in.read(reinterpret_cast<char*>(&count), sizeof count))
      return drop("torn (" + std::to_string(left) + " bytes)");
    if (count == 0 || count > key_.points - recovered_points_.size())
      return drop("count " + std::to_string(count) + " outside 1.." +
                  std::to_string(key_.points - recovered_points_.size()) + " (the points left to recover)");
    const std::uint64_t body = count * entry + sizeof(std::uint64_t);  // entries and checksum
    if (body > left - sizeof count) return drop("torn (" + std::to_string(left) + " bytes)");
    record.resize(body);
    if (!in.read(record.data(), static_cast<std::streamsize>(body))) return drop("unreadable");
    const std::uint64_t stored = word_at(record.data() + body - sizeof stored);
    if (Checksum().add(count).add(record.data(), body - sizeof stored).value != stored)
      return drop("checksum mismatch");
    std::vector<double> row(key_.width);
    for (std::uint64_t i = 0; i < count; ++i) {
      const char* at = record.data() + i * entry;
      const std::uint64_t point = word_at(at);
      if (point >= key_.points)
        return drop("point " + std::to_string(point) + " outside the study's " + std::to_string(key_.points));
      if (seen[point]) return drop("point " + std::to_string(point) + " recorded twice");
      seen[point] = true;  // within this record too; a record dropped ends the reading anyway
      std::memcpy(row.data(), at + sizeof point, key_.width * sizeof(double));
      if (const std::string why = check(row.data()); !why.empty())
        return drop("point " + std::to_string(point) + ": " + why);
    }
    // Sound: keep it whole (a record is kept or dropped entirely).
    for (std::uint64_t i = 0; i < count; ++i) {
      const char* at = record.data() + i * entry;
      recovered_points_.push_back(word_at(at));
      recovered_values_.resize(recovered_values_.size() + key_.width);
      std::memcpy(recovered_values_.data() + recovered_values_.size() - key_.width, at + sizeof(std::uint64_t),
                  key_.width * sizeof(double));
    }
    offset += sizeof count + body;
  }
}

void Journal::append(const std::vector<std::uint64_t>& points, const std::vector<double>& values) {
  // One buffer, one write: a kill leaves at most the last record torn.
  const std::uint64_t count = points.size();
  std::vector<char> buffer(sizeof count * 2 + count * (sizeof(std::uint64_t) + key_.width * sizeof(double)));
  char* p = buffer.data();
  const auto put = [&p](const void* data, std::size_t size) {
    std::memcpy(p, data, size);
    p += size;
  };
  put(&count, sizeof count);
  for (std::size_t i = 0; i < count; ++i) {
    put(&points[i], sizeof points[i]);
    put(values.data() + i * key_.width, key_.width * sizeof(double));
  }
  const std::uint64_t sum = Checksum().add(buffer.data(), buffer.size() - sizeof sum).value;
  put(&sum, sizeof sum);
  write_all(fd_, buffer.data(), buffer.size(), path_);
}

void Journal::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::filesystem::remove(path_);
}

}  // namespace sweetspot
