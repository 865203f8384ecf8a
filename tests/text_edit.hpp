#pragma once
// Bad input files for tests are good ones with one thing changed.
#include <catch2/catch.hpp>

#include <string>
#include <string_view>

// `text` with its first occurrence of `from` replaced by `to` (which must be there).
inline std::string with(std::string_view text, std::string_view from, std::string_view to) {
  std::string out(text);
  const auto at = out.find(from);
  REQUIRE(at != std::string::npos);
  return out.replace(at, from.size(), to);
}
