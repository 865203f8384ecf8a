#pragma once
// Internal: TOML text parsed by toml++, after a check its parser lacks. toml++ bounds the nesting
// of arrays and inline tables (256) but not the parts of a dotted key or a table header, and
// recurses once per part: a key of 60 000 parts ("a.a.a...", a 120 KB file) overflowed the stack
// and killed the program, and the Python interpreter with it. No sweetspot file needs more than 3.
#include <cctype>
#include <memory>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace sweetspot::detail {

inline constexpr int max_key_parts = 64;

// The position of the first dotted key (or header) of more than max_key_parts parts, outside
// strings and comments, or line 0. A chain is names ("a", "b", or quoted) joined by dots, spaces
// around them allowed; anything else (=, a comma, a bracket, a newline) ends it. A number's one
// dot ("0.5") makes a chain of two parts, a date's too.
inline toml::source_position overlong_dotted_key(std::string_view text) {
  toml::source_position at{1, 1};
  int parts = 0;              // of the chain so far
  bool after_name = false;    // the chain's last token is a name, not a dot
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++at.line, at.column = 1, parts = 0, after_name = false;
      continue;
    }
    ++at.column;
    if (c == '#') {  // a comment, to the end of the line
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
    } else if (c == '"' || c == '\'') {  // a string (or a quoted name): its end, lines counted
      const bool triple = text.substr(i, 3) == std::string_view(c == '"' ? "\"\"\"" : "'''");
      const std::string_view close = triple ? text.substr(i, 3) : text.substr(i, 1);
      for (i += close.size(); i < text.size() && text.substr(i, close.size()) != close; ++i) {
        if (text[i] == '\\' && c == '"') ++i;  // an escaped character, the quote too
        else if (text[i] == '\n') ++at.line, at.column = 1;
      }
      i += close.size() - 1;
      if (!after_name) ++parts, after_name = true;
    } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '+' || c == ':') {
      if (!after_name) ++parts, after_name = true;
    } else if (c == '.') {
      if (!after_name) parts = 0;  // two dots in a row: no key (toml++ says so)
      after_name = false;
    } else if (c != ' ' && c != '\t') {
      parts = 0, after_name = false;
    }
    if (parts > max_key_parts) return at;
  }
  return {0, 0};
}

// toml::parse, refusing first (as a toml::parse_error, which every caller reports as a syntax
// error at its line) what would overflow its stack.
inline toml::table parse_toml_text(std::string_view text, const std::string& path) {
  if (const toml::source_position at = overlong_dotted_key(text); at.line > 0)
    throw toml::parse_error(("a dotted key or table header of more than " + std::to_string(max_key_parts) +
                             " parts (no sweetspot file nests more than 3)").c_str(),
                            at, std::make_shared<const std::string>(path));
  return toml::parse(text, path);
}

}  // namespace sweetspot::detail
