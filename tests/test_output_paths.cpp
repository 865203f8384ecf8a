// Where `run` and `convergence` write, checked before any work: an output that is one of the
// run's inputs (whatever its spelling), or a path that cannot be written, is refused in one line
// with exit status 2, and every file already there stays as it was.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <filesystem>
#include <string>
#include <vector>

#include "program.hpp"
#include "sweetspot/study/output_lock.hpp"
#include "study_dir.hpp"

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& path) { return std::string(1, '\'').append(path).append(1, '\''); }

}  // namespace

TEST_CASE("An output that is one of the run's inputs is refused, however it is spelt", "[run][output]") {
  StudyDir s;
  fs::create_hard_link(s.study, s.dir.path / "hard_link.toml");
  fs::create_symlink(s.dir.path / "bats" / "torpedo_profile.csv", s.dir.path / "profile_link.csv");
  // A second copy of the study whose name is the temporary file, the journal or the lock of an
  // output: those are written too.
  for (const char* beside : {"x.h5.tmp", "y.h5.journal", "z.h5.lock"}) fs::copy_file(s.study, s.dir.path / beside);
  struct Case {
    std::string study, output, input;  // input: the file the message must name
  };
  const std::string study = s.study.string();
  const Case cases[] = {
      {study, study, "study.toml"},
      {study, s / "bats/../study.toml", "study.toml"},
      {study, s / "./hard_link.toml", "study.toml"},
      {study, s / "bats/r161.toml", "r161.toml"},
      {study, s / "bats/r161_profile.csv", "r161_profile.csv"},
      {study, s / "bats/torpedo.toml", "torpedo.toml"},
      {study, s / "profile_link.csv", "torpedo_profile.csv"},
      {s / "x.h5.tmp", s / "x.h5", "x.h5.tmp"},
      {s / "y.h5.journal", s / "y.h5", "y.h5.journal"},
      {s / "z.h5.lock", s / "z.h5", "z.h5.lock"},
  };
  const auto before = s.snapshot();
  for (const Case& c : cases) {
    for (const std::string command : {"run", "convergence"}) {
      // The lock and journal are no files of `convergence`: only its temporary file is.
      if (command == "convergence" && c.input.find(".h5.") != std::string::npos && c.input != "x.h5.tmp") continue;
      const ProgramRun run =
          run_program(command + " " + c.study + " -o " + c.output + (command == "run" ? "" : " --quick"));
      INFO(command << " -o " << c.output);
      require_refused(run, "is the run's input");
      CHECK_THAT(run.output, Catch::Contains(c.input + "' (the same file)"));
    }
  }
  // Under mpirun too: rank 0 checks, every rank stops, one line.
  require_refused(run_program_mpi(2, 1, "run " + study + " -o " + s / "bats/r161_profile.csv"), "r161_profile.csv");
  CHECK(s.snapshot() == before);
}

TEST_CASE("An output path that cannot be written is refused before any work, in one line", "[run][output]") {
  StudyDir s;
  fs::create_directory(s.dir.path / "existing_dir");
  s.dir.write("result.txt", "a file, not a directory");
  s.dir.write("notes.txt", "a user's notes");  // -o notes.txt replaced them with a dataset
  s.dir.write("out.h5", "\x89HDF\r\n\x1a\nan earlier result");
  struct Case {
    std::string output, expected;
    std::string in_the_way = "";  // a directory where a file is written beside the output
    bool mpi = false;             // tried under mpirun too (a few: each mpirun takes a second)
  };
  const Case cases[] = {
      {s / "existing_dir", "existing_dir: is a directory; expected the name of a file to write", "", true},
      {s / "missing/out.h5", "directory " + quoted(s / "missing") + " does not exist", "", true},
      {s / "missing/deeper/out.h5", "directory " + quoted(s / "missing/deeper") + " does not exist"},
      {s / "result.txt/out.h5", quoted(s / "result.txt") + " is a file, not a directory", "", true},
      {s / "result.txt/sub/out.h5", quoted(s / "result.txt") + " is a file, not a directory"},
      {"''", "the output path is empty; expected the name of a file to write", "", true},
      {s / "out.h5", "out.h5.tmp: is a directory", "out.h5.tmp", true},
      {s / "out.h5", "out.h5.journal: is a directory", "out.h5.journal"},
      {s / "out.h5", "out.h5.journal.new: is a directory", "out.h5.journal.new"},
      {s / "out.h5", "out.h5.lock: is a directory", "out.h5.lock"},
      {"/dev/null", "/dev/null: exists and is not a regular file"},
      {s / "notes.txt", "notes.txt: exists and is not an HDF5 file", "", true},
  };
  for (const Case& c : cases) {
    if (!c.in_the_way.empty()) fs::create_directory(s.dir.path / c.in_the_way);
    const auto before = s.snapshot();
    for (const std::string command : {"run", "convergence --quick"}) {
      for (const bool mpi : {false, true}) {
        // Only `run` keeps a journal beside its output; both take the lock.
        const bool run_only = !c.in_the_way.empty() && c.in_the_way != "out.h5.tmp" && c.in_the_way != "out.h5.lock";
        if ((mpi || run_only) && command != "run") continue;
        if (mpi && !c.mpi) continue;
        const std::string arguments = command + " " + s.study.string() + " -o " + c.output;
        INFO(arguments << (mpi ? " under mpirun" : ""));
        require_refused(mpi ? run_program_mpi(2, 1, arguments) : run_program(arguments), c.expected);
        CHECK(s.snapshot() == before);  // the directory in the way too: nothing deleted
      }
    }
    if (!c.in_the_way.empty()) fs::remove(s.dir.path / c.in_the_way);
  }
  CHECK(file_text(s / "out.h5") == "\x89HDF\r\n\x1a\nan earlier result");
  CHECK(file_text(s / "notes.txt") == "a user's notes");
}

TEST_CASE("An output in a directory the program cannot write in is refused before any work", "[run][output]") {
  // As root, permission bits stop no one: a directory of /proc takes no new file whoever asks.
  // Permission bits are tried too when the tests do not run as root.
  StudyDir s;
  std::vector<std::string> directories{"/proc"};
  if (::geteuid() != 0) {
    fs::create_directory(s.dir.path / "read_only");
    fs::permissions(s.dir.path / "read_only", fs::perms::owner_read | fs::perms::owner_exec);
    directories.push_back(s / "read_only");
  }
  const auto before = s.snapshot();
  for (const std::string& directory : directories)
    for (const std::string command : {"run", "convergence --quick"})
      require_refused(run_program(command + " " + s.study.string() + " -o " + directory + "/out.h5"),
                      "cannot create files in directory '" + directory + "'");
  CHECK(s.snapshot() == before);
  if (::geteuid() != 0) fs::permissions(s.dir.path / "read_only", fs::perms::owner_all);
}

TEST_CASE("convergence takes the output's lock as run does: neither can overwrite the other's file",
          "[run][output]") {
  // Held by a child of this process (a POSIX lock is released when its holder closes any descriptor
  // of the file, as reading it for a snapshot would): the program finds the lock taken, names the
  // holder, and touches nothing.
  StudyDir s;
  s.dir.write("out.h5", "\x89HDF\r\n\x1a\nan earlier result");
  int ready[2];
  REQUIRE(::pipe(ready) == 0);
  const pid_t holder = ::fork();
  REQUIRE(holder >= 0);
  if (holder == 0) {
    const sweetspot::OutputLock lock(s / "out.h5");
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) ::_exit(1);
    ::pause();  // until the test kills it
  }
  char byte = 0;
  REQUIRE(::read(ready[0], &byte, 1) == 1);
  const auto before = s.snapshot();
  for (const std::string command : {"run", "convergence --quick"}) {
    const std::string arguments = command + " " + s.study.string() + " -o " + (s / "out.h5");
    INFO(arguments);
    require_refused(run_program(arguments), "another sweetspot run (process " + std::to_string(holder) + ")");
    CHECK(s.snapshot() == before);
  }
  ::kill(holder, SIGKILL);
  ::waitpid(holder, nullptr, 0);
  ::close(ready[0]);
  ::close(ready[1]);
}

TEST_CASE("An output name too long for what is written beside it is refused before any work", "[run][output]") {
  // Each name fits the file system's 255 bytes, what is written beside it does not: `run`'s
  // "NAME.journal.new", convergence's "NAME.lock". Refused in one line, not an MPI_ABORT later.
  StudyDir s;
  const auto before = s.snapshot();
  for (const auto& [command, name] : {std::pair<std::string, std::string>{"run", std::string(242, 'o') + ".h5"},
                                      {"convergence --quick", std::string(248, 'o') + ".h5"}}) {
    const std::string arguments = command + " " + s.study.string() + " -o " + (s / name);
    INFO(arguments);
    require_refused(run_program(arguments), "bytes long, over the 255 its file system allows");
    CHECK(s.snapshot() == before);
  }
}

TEST_CASE("An output named like another output's side file, or whose side file is a link, is refused before any work",
          "[run][output]") {
  // `-o out.h5.lock` would be taken (and deleted) by a run with `-o out.h5` as its lock; a link at
  // a side file's name would be written through, over the file it points to.
  StudyDir s;
  s.dir.write("victim.txt", "somebody's file");
  const auto refused_everywhere = [&](const std::string& output, const std::string& expected, bool convergence) {
    const auto before = s.snapshot();
    for (const std::string command : {"run", "convergence --quick"}) {
      if (command != "run" && !convergence) continue;
      const std::string arguments = command + " " + s.study.string() + " -o " + output;
      INFO(arguments);
      require_refused(run_program(arguments), expected);
      CHECK(s.snapshot() == before);
    }
  };
  for (const char* side : {"out.h5.lock", "out.h5.tmp", "out.h5.journal", "out.h5.journal.new"})
    refused_everywhere(s / side, "the name of the", true);
  // The journal and its rewrite are `run`'s alone; both commands take the lock and a temporary file.
  for (const auto& [side, convergence] : {std::pair{".lock", true}, {".tmp", true}, {".journal", false},
                                         {".journal.new", false}}) {
    const fs::path link = s.dir.path / (std::string("out.h5") + side);
    fs::create_symlink(s.dir.path / "victim.txt", link);
    refused_everywhere(s / "out.h5", std::string("out.h5") + side + ": is a symbolic link", convergence);
    fs::remove(link);
  }
  CHECK(file_text(s / "victim.txt") == "somebody's file");
}
