#include "sweetspot/study/journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace sweetspot {

namespace {

constexpr char magic[8] = {'S', 'W', 'S', 'P', 'J', 'N', 'L', '1'};

void write_all(int fd, const void* data, std::size_t size, const std::filesystem::path& path) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0) throw std::runtime_error(path.string() + ": cannot write the journal: " + std::strerror(errno));
    p += n, size -= static_cast<std::size_t>(n);
  }
}

template <class T>
bool read_value(std::ifstream& in, T& value) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof value));
}

}  // namespace

std::uint64_t study_hash(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

Journal::Journal(const std::filesystem::path& path, std::uint64_t hash, std::uint64_t width, bool resume)
    : path_(path), width_(width) {
  if (resume) read_existing(hash);
  // Rewrite the journal with what was recovered: a torn tail must not stay in front of new records.
  const std::filesystem::path fresh = path_.string() + ".new";
  fd_ = ::open(fresh.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd_ < 0) throw std::runtime_error(fresh.string() + ": cannot create the journal: " + std::strerror(errno));
  write_all(fd_, magic, sizeof magic, fresh);
  write_all(fd_, &hash, sizeof hash, fresh);
  write_all(fd_, &width_, sizeof width_, fresh);
  std::vector<std::uint64_t> points;
  std::vector<double> values;
  for (const JournalEntry& e : recovered_) {
    points.push_back(e.point);
    values.insert(values.end(), e.values.begin(), e.values.end());
  }
  if (!points.empty()) append(points, values);
  ::fsync(fd_);
  std::filesystem::rename(fresh, path_);
}

Journal::~Journal() {
  if (fd_ >= 0) ::close(fd_);
}

void Journal::read_existing(std::uint64_t hash) {
  std::ifstream in(path_, std::ios::binary);
  char header[sizeof magic];
  std::uint64_t file_hash = 0, file_width = 0;
  if (!in.read(header, sizeof header) || std::memcmp(header, magic, sizeof magic) != 0) return;
  if (!read_value(in, file_hash) || !read_value(in, file_width) || file_hash != hash || file_width != width_) return;
  std::uint64_t count = 0;
  while (read_value(in, count)) {
    std::vector<JournalEntry> record(count, JournalEntry{0, std::vector<double>(width_)});
    bool whole = true;
    for (JournalEntry& e : record)
      whole = whole && read_value(in, e.point) &&
              in.read(reinterpret_cast<char*>(e.values.data()), static_cast<std::streamsize>(width_ * sizeof(double)));
    std::uint64_t trailer = 0;
    if (!whole || !read_value(in, trailer) || trailer != count) break;  // torn by a kill: drop it
    recovered_.insert(recovered_.end(), record.begin(), record.end());
  }
}

void Journal::append(const std::vector<std::uint64_t>& points, const std::vector<double>& values) {
  // One buffer, one write: a kill leaves at most the last record torn.
  const std::uint64_t count = points.size();
  std::vector<char> buffer(sizeof count * 2 + count * (sizeof(std::uint64_t) + width_ * sizeof(double)));
  char* p = buffer.data();
  const auto put = [&p](const void* data, std::size_t size) {
    std::memcpy(p, data, size);
    p += size;
  };
  put(&count, sizeof count);
  for (std::size_t i = 0; i < count; ++i) {
    put(&points[i], sizeof points[i]);
    put(values.data() + i * width_, width_ * sizeof(double));
  }
  put(&count, sizeof count);
  write_all(fd_, buffer.data(), buffer.size(), path_);
}

void Journal::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::filesystem::remove(path_);
}

}  // namespace sweetspot
