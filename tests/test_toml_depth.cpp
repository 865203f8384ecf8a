// toml++ recurses once per part of a dotted key or table header, with no bound (it bounds arrays
// and inline tables at 256): a key of 60 000 parts in a 120 KB study, bat or ball file overflowed
// the stack and killed the program (exit 139, nothing said), and Python's interpreter with
// Bat.from_text. Every file is now checked first (src/toml_parse.hpp) and such a key refused as a
// syntax error at its line, exit status 2, like any other.
#include <catch2/catch.hpp>

#include <string>

#include "program.hpp"
#include "refusal.hpp"
#include "temp_dir.hpp"
#include "toml_parse.hpp"

namespace {

using sweetspot::detail::max_key_parts;
using sweetspot::detail::overlong_dotted_key;

std::string dotted(int parts) {
  std::string key = "a";
  for (int i = 1; i < parts; ++i) key += ".a";
  return key;
}

}  // namespace

TEST_CASE("A dotted key is counted by its parts, outside strings, comments and numbers", "[toml]") {
  CHECK(overlong_dotted_key(dotted(max_key_parts) + " = 1\n").line == 0);
  const toml::source_position at = overlong_dotted_key("x = 1\n\n" + dotted(max_key_parts + 1) + " = 1\n");
  CHECK(at.line == 3);
  CHECK(overlong_dotted_key("[" + dotted(max_key_parts + 1) + "]\n").line == 1);
  CHECK(overlong_dotted_key("t = { " + dotted(max_key_parts + 1) + " = 1 }\n").line == 1);
  CHECK(overlong_dotted_key("\"a\" . 'b' . " + dotted(max_key_parts - 1) + " = 1\n").line == 1);  // 65 parts
  // What is no key: a list of numbers (one dot each), a string, a comment, a date.
  std::string numbers = "z = [0.5";
  for (int i = 0; i < 1000; ++i) numbers += ", 0.5";
  CHECK(overlong_dotted_key(numbers + "]\n").line == 0);
  CHECK(overlong_dotted_key("title = \"" + dotted(1000) + "\"\n").line == 0);
  CHECK(overlong_dotted_key("title = '''\n" + dotted(1000) + "\n'''\n").line == 0);
  CHECK(overlong_dotted_key("# " + dotted(1000) + "\n").line == 0);
  CHECK(overlong_dotted_key("when = 1979-05-27T07:32:00.999\n").line == 0);
  // A string's lines are counted: the key after it is where it is.
  CHECK(overlong_dotted_key("t = \"\"\"\n\n\"\"\"\n" + dotted(max_key_parts + 1) + " = 1\n").line == 4);
}

TEST_CASE("A study, bat or ball file with a key of 60 000 parts is refused at its line, not a crash", "[toml]") {
  TempDir dir;
  const std::string deep = dotted(60000) + " = 1\n";
  const auto study = dir.write("deep.toml", "title = \"deep\"\n" + deep);
  require_refused(run_program("run " + study.string() + " -o " + dir / "out.h5"),
                  {study.string() + ":2:", "TOML syntax error", "more than 64 parts"});
  require_refused(run_program("run " + dir.write("header.toml", "[" + dotted(60000) + "]\n").string() + " -o " +
                              dir / "out.h5"),
                  {"header.toml:1:", "more than 64 parts"});
  require_refused(run_program("modes " + dir.write("bat.toml", deep).string()), {"bat.toml:1:", "more than 64 parts"});
  require_refused(run_program("ball " + dir.write("ball.toml", deep).string()), {"ball.toml: line 1:", "more than 64"});
}
