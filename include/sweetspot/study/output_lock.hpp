#pragma once
// One run per output: OUT.lock beside the output, locked with a POSIX record lock (fcntl
// F_SETLK) for as long as the run lives. The kernel releases the lock when its process ends,
// however it ends (SIGKILL included), so a killed run's lock file blocks nothing: only a live run
// does. F_GETLK names the holder's pid; the file also holds it as text, for a human looking.
// Record locks are those NFS forwards to its lock manager (flock locks are local to a client).
#include <filesystem>

namespace sweetspot {

class OutputLock {
 public:
  // Takes the lock or throws InputError naming the process that holds it.
  explicit OutputLock(const std::filesystem::path& output);
  ~OutputLock();  // removes the lock file, then releases the lock
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  static std::filesystem::path path_for(const std::filesystem::path& output) { return output.string() + ".lock"; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace sweetspot
