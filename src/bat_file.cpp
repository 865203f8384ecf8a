#include "sweetspot/bat_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "sweetspot/input_error.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

using detail::describe;
using detail::format_number;

namespace fs = std::filesystem;

// Every message is one line, "where: what", so the program can print it as it is.
[[noreturn]] void fail(const std::string& where, std::string what) {
  std::replace(what.begin(), what.end(), '\n', ' ');
  throw InputError(where + ": " + what);
}

std::string at_line(const fs::path& file, int line) {
  return file.string() + ":" + std::to_string(line);
}

// `context` says why the file was wanted, for files the user did not name directly.
constexpr std::uintmax_t max_input_bytes = 16 << 20;

std::string read_text(const fs::path& file, const std::string& context = "") {
  std::error_code ignored;  // a status we cannot get reads as "not found"
  const fs::file_status status = fs::status(file, ignored);
  if (!fs::exists(status)) fail(file.string(), "file not found" + context);
  if (!fs::is_regular_file(status)) fail(file.string(), "not a regular file" + context);
  // A bat file or a profile of 4096 rows is far smaller: do not read a mistaken path's gigabytes.
  if (const std::uintmax_t size = fs::file_size(file, ignored); !ignored && size > max_input_bytes)
    fail(file.string(), "larger than 16 MB" + context + "; expected a bat file or a profile of at most " +
                            std::to_string(max_slices) + " rows");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file.string(), "cannot open the file for reading" + context);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}


// One table of the bat file; `prefix` makes keys read "material.density" in messages.
struct Section {
  const fs::path& file;
  const toml::table& table;
  std::string prefix;

  std::string where(std::string_view key) const {
    return file.string() + ": key '" + prefix + std::string(key) + "'";
  }

  const toml::node& require(std::string_view key, const std::string& expected) const {
    const toml::node* node = table.get(key);
    if (!node) fail(where(key), "missing; expected " + expected);
    return *node;
  }

  // Unknown keys are errors: a misspelt optional key would otherwise be silently ignored.
  void reject_unknown(std::initializer_list<std::string_view> known) const {
    std::string list;
    for (const std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    for (const auto& [key, node] : table) {
      if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
      fail(where(key.str()), "unknown key (value " + describe(node) + "); expected one of " + list);
    }
  }

  std::string text(std::string_view key) const {
    const toml::node& node = require(key, "a non-empty string");
    if (node.is_string() && !node.as_string()->get().empty()) return node.as_string()->get();
    fail(where(key), "value " + describe(node) + " must be a non-empty string");
  }

  // A positive, finite number; `fallback` makes the key optional.
  double positive(std::string_view key, std::string_view unit,
                  std::optional<double> fallback = std::nullopt) const {
    const std::string number = "positive number (" + std::string(unit) + ")";
    if (fallback && !table.contains(key)) return *fallback;
    const toml::node& node = require(key, "a " + number);
    const auto x = node.is_number() ? node.value<double>() : std::nullopt;
    if (x && std::isfinite(*x) && *x > 0) return *x;
    const bool nan_or_inf = x && !std::isfinite(*x);
    fail(where(key),
         "value " + describe(node) + " must be a " + (nan_or_inf ? "finite " : "") + number);
  }

  Section section(std::string_view key) const {
    const toml::node& node = require(key, "a table [" + prefix + std::string(key) + "]");
    if (!node.is_table()) fail(where(key), "value " + describe(node) + " must be a table");
    return {file, *node.as_table(), prefix + std::string(key) + "."};
  }
};

toml::table parse_toml(const fs::path& file) {
  const std::string text = read_text(file);
  try {
    return toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    const toml::source_position& at = e.source().begin;
    fail(at_line(file, static_cast<int>(at.line)) + ":" + std::to_string(at.column),
         "TOML syntax error: " + std::string(e.description()));
  }
}

Material read_material(const Section& s) {
  s.reject_unknown({"density", "youngs_modulus", "shear_modulus", "shear_coefficient"});
  Material m;
  m.density = s.positive("density", "kg/m^3");
  m.youngs_modulus = s.positive("youngs_modulus", "Pa");
  m.shear_modulus = s.positive("shear_modulus", "Pa");
  m.shear_coefficient = s.positive("shear_coefficient", "dimensionless", 1.0);
  return m;
}

// ---- The profile CSV -------------------------------------------------------------------------

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// Where each column sits in a row; -1 for an optional column the file does not have.
struct Columns {
  std::vector<std::string> names;
  int z = -1, outer = -1, inner = -1;
};

Columns read_header(const fs::path& file, int line, std::string_view text) {
  Columns c;
  int slice = -1;  // an index column: allowed, never read
  const std::pair<std::string_view, int*> known[] = {{"slice", &slice},
                                                     {"z_center_m", &c.z},
                                                     {"outer_diameter_m", &c.outer},
                                                     {"inner_diameter_m", &c.inner}};
  const std::string where = at_line(file, line);
  for (const std::string_view name : split_fields(text)) {
    const auto it = std::ranges::find(known, name, [](const auto& k) { return k.first; });
    const std::string column = "column '" + std::string(name) + "'";
    if (it == std::end(known)) {
      fail(where, "unknown " + column + "; expected slice, z_center_m, outer_diameter_m, " +
                      "inner_diameter_m");
    }
    if (*it->second >= 0) fail(where, column + " appears twice");
    *it->second = static_cast<int>(c.names.size());
    c.names.emplace_back(name);
  }
  if (c.z < 0) fail(where, "header has no column 'z_center_m'");
  if (c.outer < 0) fail(where, "header has no column 'outer_diameter_m'");
  return c;
}

std::optional<double> parse_number(std::string_view text) {
  const std::string_view digits = text.starts_with('+') ? text.substr(1) : text;
  double x = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), x);
  const bool whole = !digits.empty() && ec == std::errc() && end == digits.data() + digits.size();
  return whole ? std::optional(x) : std::nullopt;
}

// One slice as read from the profile, with its z as written ("z_center_m = 0.015") for messages.
struct Row {
  int line;
  std::string z_text;
  double z, outer, inner;  // inner = 0 for a solid bat
};

Row read_row(const fs::path& file, int line, std::string_view text, const Columns& c) {
  const std::vector<std::string_view> fields = split_fields(text);
  const std::string where = at_line(file, line);
  if (fields.size() != c.names.size()) {
    fail(where, std::to_string(fields.size()) + " fields in '" + std::string(text) +
                    "'; expected " + std::to_string(c.names.size()) + " as in the header");
  }
  const auto what = [&](int i) { return c.names[i] + " = " + std::string(fields[i]); };
  std::vector<double> x;
  for (int i = 0; i < static_cast<int>(fields.size()); ++i) {
    const std::optional<double> value = parse_number(fields[i]);
    if (!value) fail(where, what(i) + " is not a number");
    if (!std::isfinite(*value)) fail(where, what(i) + " must be a finite number");
    x.push_back(*value);
  }
  const double inner = c.inner < 0 ? 0.0 : x[c.inner];
  if (x[c.outer] <= 0) fail(where, what(c.outer) + " must be positive");
  if (inner < 0) fail(where, what(c.inner) + " must not be negative");
  if (c.inner >= 0 && inner >= x[c.outer]) {
    fail(where, what(c.inner) + " must be less than " + what(c.outer));
  }
  return {line, what(c.z), x[c.z], x[c.outer], inner};
}

// Slice i of N must be centred at (i + 1/2) L/N (physics.md §1); the tolerance absorbs the
// rounding of z in the shipped profiles. Checking sorted, then evenly spaced, then spanning the
// length gives each kind of mistake its own message.
void check_slicing(const fs::path& file, const std::vector<Row>& rows, double length) {
  const int n = static_cast<int>(rows.size());
  const auto fail_at = [&](int i, const std::string& what) {
    fail(at_line(file, rows[i].line), rows[i].z_text + " " + what);
  };
  for (int i = 1; i < n; ++i) {
    if (rows[i].z <= rows[i - 1].z) {
      fail_at(i, "is not greater than the previous row's " + format_number(rows[i - 1].z) +
                     "; rows must be sorted by z, knob first");
    }
  }
  const double step = n > 1 ? (rows[n - 1].z - rows[0].z) / (n - 1) : 0.0;
  for (int i = 1; i < n - 1; ++i) {
    const double expected = rows[0].z + i * step;
    if (std::abs(rows[i].z - expected) > 1e-3 * step) {
      fail_at(i, "breaks the even spacing of the rows (" + format_number(step) +
                     " m from first to last); expected " + format_number(expected));
    }
  }
  const double dz = length / n;
  for (int i = 0; i < n; ++i) {
    if (std::abs(rows[i].z - (i + 0.5) * dz) > 1e-3 * dz) {
      fail(file.string(), "slice centres run from " + format_number(rows[0].z) + " to " +
                              format_number(rows[n - 1].z) + " m, but length " +
                              format_number(length) + " m in " + std::to_string(n) +
                              " slices needs (i + 1/2) L/N = " + format_number(0.5 * dz) + " to " +
                              format_number(length - 0.5 * dz) + " m");
    }
  }
}

// Reads the profile into bat.outer_diameter (and inner_diameter for a hollow bat).
void read_profile(const fs::path& file, const std::string& context, Bat& bat) {
  const std::string text = read_text(file, context);  // rows keep views into it
  std::optional<Columns> columns;
  std::vector<Row> rows;
  int number = 0;
  // Spreadsheets often save CSV with a UTF-8 byte-order mark; it is not part of the header.
  for (std::size_t start = text.starts_with("\xEF\xBB\xBF") ? 3 : 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view content = trim(std::string_view(text).substr(start, end - start));
    start = end + 1;
    ++number;
    if (content.empty() || content.starts_with('#')) continue;
    if (!columns)
      columns = read_header(file, number, content);
    else if (rows.size() == static_cast<std::size_t>(max_slices))
      fail(at_line(file, number), "row " + std::to_string(max_slices + 1) + ": a profile has at most " +
                                      std::to_string(max_slices) + " rows (slices), as --slices");
    else
      rows.push_back(read_row(file, number, content, *columns));
  }
  if (!columns) fail(file.string(), "no header line; expected e.g. 'z_center_m,outer_diameter_m'");
  if (rows.empty()) fail(file.string(), "the profile has no rows; expected one row per slice");
  check_slicing(file, rows, bat.length);
  if (rows.size() < static_cast<std::size_t>(min_slices))
    fail(file.string(), "the profile has " + std::to_string(rows.size()) + " rows; expected one row per slice, at least " +
                            std::to_string(min_slices) + " (as --slices)");
  for (const Row& row : rows) {
    bat.outer_diameter.push_back(row.outer);
    if (columns->inner >= 0) bat.inner_diameter.push_back(row.inner);
  }
}

}  // namespace

Bat load_bat(const std::filesystem::path& toml_path) {
  const toml::table doc = parse_toml(toml_path);
  const Section top{toml_path, doc, ""};
  top.reject_unknown({"name", "length", "material", "profile"});
  Bat bat;
  bat.name = top.text("name");
  bat.length = top.positive("length", "m");
  bat.material = read_material(top.section("material"));
  const std::string profile = top.text("profile");
  // The profile is named relative to the bat file, so a study directory can be moved whole.
  read_profile(toml_path.parent_path() / profile,
               " (the profile named by key 'profile' in " + toml_path.string() + ")", bat);
  return bat;
}

}  // namespace sweetspot
