#include "sweetspot/study/output_lock.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

struct flock whole_file(short type) {
  struct flock lock {};
  lock.l_type = type;
  lock.l_whence = SEEK_SET;  // l_start = l_len = 0: the whole file, however long
  return lock;
}

bool same_file(int fd, const std::filesystem::path& path) {
  struct stat opened {}, named {};
  return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 && opened.st_dev == named.st_dev &&
         opened.st_ino == named.st_ino;
}

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& output) : path_(path_for(output)) {
  // A few rounds at most: each retry means the holder just ended and removed the file.
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw InputError(path_.string() + ": cannot create the lock file (" + std::strerror(errno) +
                       "); expected a writable directory for the output");
    struct flock lock = whole_file(F_WRLCK);
    if (::fcntl(fd_, F_SETLK, &lock) != 0) {
      const int error = errno;
      struct flock holder = whole_file(F_WRLCK);
      const bool held = ::fcntl(fd_, F_GETLK, &holder) == 0 && holder.l_type != F_UNLCK;
      ::close(fd_);
      fd_ = -1;
      if (error != EACCES && error != EAGAIN)
        throw InputError(path_.string() + ": cannot lock the file (" + std::strerror(error) +
                         "); expected a file system with POSIX locks");
      if (!held) continue;  // released between the two calls
      throw InputError(output.string() + ": another sweetspot run (process " + std::to_string(holder.l_pid) +
                       ") is writing it and holds " + path_.string() +
                       "; expected one run at a time per output: wait for it to end or choose another -o");
    }
    // The run that held the lock removes the file as it ends: between our open and our lock, the
    // path may have come to name a new file that another run has locked. Ours must be that one.
    if (same_file(fd_, path_)) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      // Only for a human looking: F_GETLK is what names the holder, so a failure here is no matter.
      const bool written = ::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) > 0;
      static_cast<void>(written);
      return;
    }
    ::close(fd_);
    fd_ = -1;
  }
  throw InputError(path_.string() + ": the lock file keeps being replaced; expected one run at a time per output");
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // before the release, so that no other run locks a file on its way out
  ::close(fd_);
}

}  // namespace sweetspot
