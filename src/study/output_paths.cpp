#include "sweetspot/study/output_paths.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& path) {
  std::string text(1, '\'');
  return text.append(path.string()).append(1, '\'');
}

[[noreturn]] void refuse(const fs::path& path, const std::string& what) {
  throw InputError(path.string() + ": " + what);
}

fs::file_status status_of(const fs::path& path) {
  std::error_code ignored;  // a status we cannot get reads as "not found"
  return fs::status(path, ignored);
}

// The directory the output goes in must exist and take new files: checked now, not at the
// rename after the whole study.
void check_directory(const fs::path& output) {
  const fs::path directory = output.has_parent_path() ? output.parent_path() : fs::path(".");
  const fs::file_status status = status_of(directory);
  if (!fs::exists(status)) {
    // A path under a regular file ("result.txt/out.h5") is not a missing directory: name the file.
    for (fs::path up = directory.parent_path(); !up.empty() && up != up.parent_path(); up = up.parent_path()) {
      const fs::file_status above = status_of(up);
      if (fs::exists(above) && !fs::is_directory(above))
        refuse(output, quoted(up) + " is a file, not a directory; expected the output in an existing directory");
      if (fs::exists(above)) break;
    }
    refuse(output, "directory " + quoted(directory) + " does not exist; expected the output in an existing directory");
  }
  if (!fs::is_directory(status))
    refuse(output, quoted(directory) + " is a file, not a directory; expected the output in an existing directory");
  // Creating a file is the one test that holds for every user and file system: permission bits
  // do not stop root, while a read-only mount or /proc stop everyone.
  std::string probe = (directory / ".sweetspot-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0)
    refuse(output, "cannot create files in directory " + quoted(directory) + " (" + std::strerror(errno) +
                       "); expected a writable directory");
  ::close(fd);
  ::unlink(probe.c_str());
}

void check_not_an_input(const fs::path& written, const std::vector<fs::path>& inputs) {
  if (!fs::exists(status_of(written))) return;  // a file not there yet is no input
  for (const fs::path& input : inputs) {
    std::error_code error;
    if (fs::equivalent(written, input, error))
      refuse(written, "is the run's input " + quoted(input) +
                          " (the same file); expected an output that is none of the run's input files (its study or optimisation file, bat and profile files)");
  }
}

// Every file the run writes must have a name the directory's file system can hold: a name that
// fits for the output can be too long once ".journal.new" is added, which would fail mid-run.
void check_name_length(const fs::path& output, const fs::path& file) {
  const fs::path directory = file.has_parent_path() ? file.parent_path() : fs::path(".");
  const long limit = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  const std::size_t length = file.filename().string().size();
  if (limit > 0 && length > static_cast<std::size_t>(limit))
    refuse(output, "the name " + quoted(file.filename()) + " that sweetspot writes beside it is " + std::to_string(length) +
                       " bytes long, over the " + std::to_string(limit) +
                       " its file system allows; expected a shorter output name");
}

// An output named like another output's side file would be taken by that output's run for its
// own, and deleted or overwritten (`-o out.h5.lock` by the lock of a run with `-o out.h5`).
void check_not_a_side_file(const fs::path& output) {
  const std::string name = output.filename().string();
  const std::pair<const char*, const char*> sides[] = {
      {".lock", "lock"}, {".tmp", "temporary file"}, {".journal", "journal"}, {".journal.new", "rewritten journal"}};
  for (const auto& [suffix, what] : sides)
    if (name.size() > std::strlen(suffix) && name.ends_with(suffix))
      refuse(output, std::string("ends with '") + suffix + "', the name of the " + what + " sweetspot writes beside " +
                         "another output; expected an output name without it (e.g. a .h5 file)");
}

// An existing output is replaced only when it is an HDF5 file, as every dataset sweetspot writes
// (an earlier run's, to run again): `-o notes.txt` replaced a user's text file with one. An empty
// file (one a script made ready) is no one's work either.
void check_replaceable(const fs::path& output) {
  std::ifstream in(output, std::ios::binary);
  char head[8] = {};
  in.read(head, sizeof head);
  if (in.gcount() == 0) return;  // none there, or empty
  constexpr std::string_view hdf5_signature("\x89HDF\r\n\x1a\n", 8);
  if (std::string_view(head, static_cast<std::size_t>(in.gcount())) != hdf5_signature)
    refuse(output, "exists and is not an HDF5 file, as a dataset sweetspot writes is; expected a new name, or an "
                   "earlier dataset to replace (nothing was written)");
}

}  // namespace

std::vector<fs::path> study_inputs(const Study& study) {
  std::vector<fs::path> inputs{study.file};
  std::vector<BatSource> bats = study.bat_sources;
  if (study.equal_effort) bats.push_back(study.reference_source);
  for (const BatSource& bat : bats) {
    inputs.push_back(bat.toml_file);
    if (!bat.profile_file.empty()) inputs.push_back(bat.profile_file);  // none for a bat given by dimensions
  }
  return inputs;
}

void check_output_paths(const fs::path& output, const std::vector<fs::path>& beside,
                        const std::vector<fs::path>& inputs) {
  if (output.empty()) throw InputError("the output path is empty; expected the name of a file to write");
  const fs::file_status status = status_of(output);
  if (fs::is_directory(status))
    refuse(output, "is a directory; expected the name of a file to write (e.g. " + (output / "result.h5").string() + ")");
  if (fs::exists(status) && !fs::is_regular_file(status))
    refuse(output, "exists and is not a regular file; expected the name of a file to write");
  check_not_a_side_file(output);
  check_directory(output);
  check_name_length(output, output);
  for (const fs::path& file : beside) check_name_length(output, file);
  for (const fs::path& file : beside) {
    // Written through, a link would overwrite whatever file it points to.
    std::error_code ignored;
    if (fs::is_symlink(fs::symlink_status(file, ignored)))
      refuse(file, "is a symbolic link; expected no file there or a regular one (sweetspot writes it beside " +
                       output.string() + ")");
    const fs::file_status s = status_of(file);
    if (fs::exists(s) && !fs::is_regular_file(s))
      refuse(file, std::string(fs::is_directory(s) ? "is a directory" : "is not a regular file") +
                       "; expected no file there or a regular one (sweetspot writes it beside " + output.string() +
                       ")");
  }
  check_not_an_input(output, inputs);
  for (const fs::path& file : beside) check_not_an_input(file, inputs);
  check_replaceable(output);
}

}  // namespace sweetspot
