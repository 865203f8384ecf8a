#include "sweetspot/bat/bat_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
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

#include "sweetspot/bat/barrel_wall.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/dimensions.hpp"
#include "sweetspot/bat/parameter_bounds.hpp"
#include "sweetspot/bat/profile.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_parse.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

using detail::describe;
using detail::format_number;
using detail::join;
using detail::quote;

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


// The bytes that follow a UTF-8 lead byte, or -1 for a byte that starts no sequence (or NUL).
int continuation_bytes(unsigned lead) {
  if (lead == 0) return -1;
  if (lead < 0x80) return 0;
  if ((lead >> 5) == 0x6) return 1;
  if ((lead >> 4) == 0xE) return 2;
  if ((lead >> 3) == 0x1E) return 3;
  return -1;
}

// Where `text` stops being UTF-8 text (a byte that starts no valid sequence, a sequence cut
// short, overlong or a surrogate, or a NUL), or npos. Datasets store the profile as UTF-8
// strings, which end at a NUL, and a reader cannot decode anything else.
std::size_t first_non_text_byte(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned lead = byte(i);
    const int more = continuation_bytes(lead);
    if (more < 0 || i + more >= text.size()) return i;
    unsigned code = more == 0 ? lead : lead & (0x3F >> more);
    for (int k = 1; k <= more; ++k) {
      if ((byte(i + k) >> 6) != 0x2) return i;
      code = (code << 6) | (byte(i + k) & 0x3F);
    }
    constexpr unsigned least[] = {0, 0x80, 0x800, 0x10000};
    if (code < least[more] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return i;
    i += 1 + more;
  }
  return std::string_view::npos;
}

void require_text(const fs::path& file, const std::string& text) {
  const std::size_t bad = first_non_text_byte(text);
  if (bad == std::string_view::npos) return;
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[bad])));
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(bad), '\n'));
  fail(at_line(file, line), std::string("byte ") + hex + " is not UTF-8 text; expected the profile saved as UTF-8");
}

// One table of the bat file; `prefix` makes keys read "material.density" in messages.
struct Section {
  const fs::path& file;
  const toml::table& table;
  std::string prefix;

  // "FILE:LINE: key 'material.density'", the key's line where the file gives it.
  std::string where(std::string_view key) const {
    const toml::node* node = table.get(key);
    const auto line = node ? node->source().begin.line : 0;
    return file.string() + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": key '" + prefix +
           std::string(key) + "'";
  }

  const toml::node& require(std::string_view key, const std::string& expected) const {
    const toml::node* node = table.get(key);
    if (!node) fail(where(key), "missing; expected " + expected);
    return *node;
  }

  // Unknown keys are errors: a misspelt optional key would otherwise be silently ignored.
  void reject_unknown(const std::vector<std::string_view>& known) const {
    for (const auto& [key, node] : table) {
      if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
      fail(where(key.str()), "unknown key (value " + describe(node) + "); expected one of " + join(known));
    }
  }

  // A NUL character would cut the name short where a dataset stores it (an HDF5 string ends there).
  std::string text(std::string_view key) const {
    const toml::node& node = require(key, "a non-empty string");
    const std::string* value = node.is_string() ? &node.as_string()->get() : nullptr;
    if (value && !value->empty() && value->find('\0') == std::string::npos) return *value;
    fail(where(key), "value " + describe(node) + " must be a non-empty string without NUL characters");
  }

  // A positive, finite number; `fallback` makes the key optional.
  double positive(std::string_view key, std::string_view unit,
                  std::optional<double> fallback = std::nullopt) const {
    const std::string number = "positive number (" + std::string(unit) + ")";
    if (fallback && !table.contains(key)) return *fallback;
    const toml::node& node = require(key, "a " + number);
    const auto x = detail::number(node);
    const bool nan_or_inf = x && !std::isfinite(*x);
    if (!x || nan_or_inf || !(*x > 0))
      fail(where(key), "value " + describe(node) + " must be a " + (nan_or_inf ? "finite " : "") + number);
    return bounded(key, node, *x);
  }

  // The value as the key's parameter range allows (parameter_bounds.hpp), the key naming it.
  double bounded(std::string_view key, const toml::node& node, double x) const {
    const ParameterBound* bound = parameter_bound(key);
    if (!bound || within(*bound, x)) return x;
    fail(where(key), "value " + detail::describe_quantity(node) + ": expected " + expected_range(*bound));
  }

  // A quantity of `dimension`, as a number in SI or a string with its unit ("33 in"), finite and
  // accepted by `ok`, which `what` states ("positive, finite length"); `fallback` when absent.
  template <class Ok>
  double quantity(std::string_view key, Dimension dimension, Ok ok, std::string_view what,
                  std::optional<double> fallback = std::nullopt) const {
    const std::string expected = std::string(what) + " " + quantity_hint(dimension);
    if (fallback && !table.contains(key)) return *fallback;
    const toml::node& node = require(key, "a " + expected);
    const std::optional<double> x = detail::quantity(node, dimension);
    if (!(x && std::isfinite(*x) && ok(*x))) fail(where(key), "value " + detail::describe_quantity(node) + " must be a " + expected);
    return *x == 0 ? 0.0 : bounded(key, node, *x);  // 0: an optional dimension the bat has not
  }

  double positive_length(std::string_view key) const {
    return quantity(key, Dimension::length, [](double x) { return x > 0; }, "positive, finite length");
  }

  // A finite number in [0, 1), `fallback` when the key is absent: a loss factor.
  double fraction(std::string_view key, double fallback) const {
    if (!table.contains(key)) return fallback;
    const toml::node& node = *table.get(key);
    const auto x = detail::number(node);
    if (x && *x >= 0 && *x < 1) return *x;
    fail(where(key), "value " + describe(node) + " must be a number in [0, 1)");
  }

  // A finite length of at least 0, 0 when the key is absent (a dimension the bat does not have).
  double non_negative_length(std::string_view key) const {
    return quantity(key, Dimension::length, [](double x) { return x >= 0; }, "finite length of at least 0", 0.0);
  }

  // A string naming one of a few choices, as `parse` reads it: its refusal ("...: expected 'a' or
  // 'b'") says what was expected.
  template <class Parse>
  auto choice(std::string_view key, Parse parse) const {
    const std::string value = text(key);
    try {
      return parse(value);
    } catch (const InputError& e) {
      const std::string refusal = e.what();
      fail(where(key), "value '" + value + "'" + refusal.substr(refusal.find(": expected")));
    }
  }

  Section section(std::string_view key) const {
    const toml::node& node = require(key, "a table [" + prefix + std::string(key) + "]");
    if (!node.is_table()) fail(where(key), "value " + describe(node) + " must be a table");
    return {file, *node.as_table(), prefix + std::string(key) + "."};
  }
};

toml::table parse_toml(const fs::path& file, const std::string& text) {
  try {
    return detail::parse_toml_text(text, file.string());
  } catch (const toml::parse_error& e) {
    const toml::source_position& at = e.source().begin;
    fail(at_line(file, static_cast<int>(at.line)) + ":" + std::to_string(at.column),
         "TOML syntax error: " + std::string(e.description()));
  }
}

// The wood's constants as given, or a preset's with any of them given overriding it.
void read_material(const Section& s, BatDesign& design) {
  s.reject_unknown(
      {"preset", "density", "youngs_modulus", "shear_modulus", "shear_coefficient", "hoop_modulus", "wall_loss_factor",
       "loss_factor"});
  if (s.table.contains("preset")) {
    const std::string name = s.text("preset");
    try {
      set_material_preset(design, name);
    } catch (const InputError&) {
      fail(s.where("preset"), "value " + quote(name) + ": expected one of " + join(material_presets()));
    }
  }
  Material& m = design.material;
  const auto preset = [&](double value) { return design.material_name.empty() ? std::nullopt : std::optional(value); };
  m.density = s.positive("density", "kg/m^3", preset(m.density));
  m.youngs_modulus = s.positive("youngs_modulus", "Pa", preset(m.youngs_modulus));
  m.shear_modulus = s.positive("shear_modulus", "Pa", preset(m.shear_modulus));
  m.shear_coefficient = s.positive("shear_coefficient", "dimensionless", 1.0);
  // A hollow barrel's wall (barrel_wall.hpp): absent, the hoop modulus is youngs_modulus (0).
  m.hoop_modulus = s.positive("hoop_modulus", "Pa", 0.0);
  m.wall_loss_factor = s.fraction("wall_loss_factor", default_wall_loss_factor);
  m.loss_factor = s.fraction("loss_factor", m.loss_factor);  // a preset's, else 0
}

// A measured value of [barrel]: absent 0; given, a finite number in [low, high] (unit).
double measured(const Section& s, std::string_view key, double low, double high, std::string_view unit) {
  if (!s.table.contains(key)) return 0;
  const toml::node& node = *s.table.get(key);
  const auto x = detail::number(node);
  if (x && *x >= low && *x <= high) return *x;
  fail(s.where(key), "value " + describe(node) + " must be a measured " + std::string(unit) + " from " +
                         format_number(low) + " to " + format_number(high));
}

// The measured hoop frequency: a number in Hz, or a string with its unit ("1.5 kHz").
double measured_frequency(const Section& s, std::string_view key, double low, double high) {
  return s.quantity(key, Dimension::frequency, [&](double x) { return x >= low && x <= high; },
                    "measured frequency from " + format_number(low) + " to " + format_number(high) + " Hz", 0.0);
}

WallLoad parse_wall_load(const std::string& text) {
  if (text == "patch") return WallLoad::patch;
  if (text == "point") return WallLoad::point;
  throw InputError("load: expected 'patch' or 'point'");
}

// The optional [barrel] table (barrel_wall.hpp): how the ball loads a hollow wall, and measured
// values that calibrate it. Only a hollow bat has a wall.
void read_barrel(const Section& top, BatDesign& design) {
  if (!top.table.contains("barrel")) return;
  const Section s = top.section("barrel");
  s.reject_unknown({"load", "hoop_frequency", "compression"});
  const bool hollow = design.dimensions ? design.dimensions->wall_thickness > 0
                                        : std::ranges::any_of(design.profile.inner, [](double d) { return d > 0; });
  if (!hollow)
    fail(top.where("barrel"), "a [barrel] table on a solid bat; expected a hollow bat (wall_thickness in "
                              "[dimensions], or a profile with inner_diameter_m)");
  BarrelCalibration& b = design.material.barrel;
  if (s.table.contains("load")) b.load = s.choice("load", parse_wall_load);
  b.hoop_frequency = measured_frequency(s, "hoop_frequency", 100, 20000);
  b.compression = measured(s, "compression", 10, 1e6, "barrel compression (N at 0.04 in)");
}

// [dimensions] (dimensions.hpp): lengths in m or with a unit ("2.625 in"); end and its depth and the wall optional.
Dimensions read_dimension_table(const Section& s) {
  std::vector<std::string_view> known = {"end"};
  for (const DimensionField& f : dimension_fields) known.push_back(f.name);
  s.reject_unknown(known);
  Dimensions d;
  for (const DimensionField& f : dimension_fields) {
    const bool positive = !f.optional || (f.positive_when_given && s.table.contains(f.name));
    d.*f.value = positive ? s.positive_length(f.name) : s.non_negative_length(f.name);
  }
  if (s.table.contains("end")) d.end = s.choice("end", parse_end_shape);
  return d;
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
  bool knots = false;  // z_m: diameters at knots; z_center_m: one row per slice
};

Columns read_header(const fs::path& file, int line, std::string_view text) {
  Columns c;
  int slice = -1, knot = -1;  // index columns: allowed, never read
  int z_center = -1, z_knot = -1;
  const std::pair<std::string_view, int*> known[] = {{"slice", &slice},
                                                     {"knot", &knot},
                                                     {"z_center_m", &z_center},
                                                     {"z_m", &z_knot},
                                                     {"outer_diameter_m", &c.outer},
                                                     {"inner_diameter_m", &c.inner}};
  const std::string where = at_line(file, line);
  for (const std::string_view name : split_fields(text)) {
    const auto it = std::ranges::find(known, name, [](const auto& k) { return k.first; });
    const std::string column = "column '" + std::string(name) + "'";
    if (it == std::end(known)) {
      fail(where, "unknown " + column + "; expected slice, z_center_m (one row per slice) or z_m (knots), " +
                      "outer_diameter_m, inner_diameter_m");
    }
    if (*it->second >= 0) fail(where, column + " appears twice");
    *it->second = static_cast<int>(c.names.size());
    c.names.emplace_back(name);
  }
  if (z_center >= 0 && z_knot >= 0) fail(where, "columns 'z_center_m' and 'z_m' both given; expected one of them");
  if (z_center < 0 && z_knot < 0) fail(where, "header has no column 'z_center_m' (one row per slice) or 'z_m' (knots)");
  c.z = std::max(z_center, z_knot);
  c.knots = z_knot >= 0;
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
  if (const ParameterBound& outer = *parameter_bound(profile_outer_diameter); !within(outer, x[c.outer]))
    fail(where, what(c.outer) + ": expected " + expected_range(outer));
  if (const ParameterBound& wall = *parameter_bound(profile_wall); inner > 0 && !within(wall, (x[c.outer] - inner) / 2))
    fail(where, what(c.inner) + " with " + what(c.outer) + " leaves a wall of " + format_number((x[c.outer] - inner) / 2) +
                    " m: expected " + expected_range(wall));
  return {line, what(c.z), x[c.z], x[c.outer], inner};
}

// Rows must run strictly from the knob to the barrel end.
void check_sorted(const fs::path& file, const std::vector<Row>& rows) {
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i].z <= rows[i - 1].z)
      fail(at_line(file, rows[i].line), rows[i].z_text + " is not greater than the previous row's " +
                                            format_number(rows[i - 1].z) + "; rows must be sorted by z, knob first");
}

// Slice centres within 1 % of a slice of where they belong: enough to place every row on its
// slice, and it admits positions rounded to 0.1 mm (a 33-in bat's centres written to 4 decimals
// are up to 0.5 % of a slice off).
constexpr double slice_centre_tolerance = 1e-2;

// Slice i of N must be centred at (i + 1/2) L/N (physics.md §1). Checking sorted, then evenly
// spaced, then spanning the length gives each kind of mistake its own message.
void check_slicing(const fs::path& file, const std::vector<Row>& rows, double length) {
  const int n = static_cast<int>(rows.size());
  const auto fail_at = [&](int i, const std::string& what) {
    fail(at_line(file, rows[i].line), rows[i].z_text + " " + what);
  };
  check_sorted(file, rows);
  const double step = n > 1 ? (rows[n - 1].z - rows[0].z) / (n - 1) : 0.0;
  for (int i = 1; i < n - 1; ++i) {
    const double expected = rows[0].z + i * step;
    if (std::abs(rows[i].z - expected) > slice_centre_tolerance * step) {
      fail_at(i, "breaks the even spacing of the rows (" + format_number(step) +
                     " m from first to last); expected " + format_number(expected));
    }
  }
  const double dz = length / n;
  for (int i = 0; i < n; ++i) {
    if (std::abs(rows[i].z - (i + 0.5) * dz) > slice_centre_tolerance * dz) {
      fail(file.string(), "slice centres run from " + format_number(rows[0].z) + " to " +
                              format_number(rows[n - 1].z) + " m, but length " +
                              format_number(length) + " m in " + std::to_string(n) +
                              " slices needs (i + 1/2) L/N = " + format_number(0.5 * dz) + " to " +
                              format_number(length - 0.5 * dz) + " m");
    }
  }
}

// What the bat file says of how to read its profile: both keys are optional.
struct ProfileOptions {
  std::optional<Interpolation> interpolation;
  std::optional<int> slices;
  std::string interpolation_where;  // "FILE: key 'interpolation'", for messages
};

// Knots: sorted, at least two, and on the bat (a rounding's worth beyond its ends is allowed).
void check_knots(const fs::path& file, const std::vector<Row>& rows, double length) {
  check_sorted(file, rows);
  if (rows.size() < 2) fail(file.string(), "a knot profile (z_m) needs at least 2 knots; it has 1");
  const double tolerance = 1e-9 * length;
  for (const Row& row : rows)
    if (row.z < -tolerance || row.z > length + tolerance)
      fail(at_line(file, row.line), row.z_text + " lies outside the bat; expected 0 to " + format_number(length) +
                                        " m (its length)");
}

// A hollow knot profile keeps a wall between its knots, not only at them (pchip interpolates the
// two diameters apart).
void check_wall_between_knots(const fs::path& file, const std::vector<Row>& rows, const Profile& profile) {
  const ThinnestWall thinnest = thinnest_wall(profile);
  const ParameterBound& wall = *parameter_bound(profile_wall);
  if (thinnest.wall > 0 && within(wall, thinnest.wall / 2)) return;
  const Row &from = rows[thinnest.interval], &to = rows[thinnest.interval + 1];
  fail(file.string() + ": lines " + std::to_string(from.line) + "-" + std::to_string(to.line),
       std::string("with interpolation '") + to_string(profile.interpolation) +
           "' the inner diameter " + (thinnest.wall > 0 ? "comes close to" : "reaches") +
           " the outer between these knots (wall " + format_number(thinnest.wall / 2) + " m at z = " +
           format_number(thinnest.z) + " m); expected a wall everywhere, at least " + format_number(wall.low) +
           " m thick (" + std::string(wall.why) + "): interpolation 'linear', or knots that keep the bore inside");
}

ProfileOptions read_profile_options(const Section& top) {
  ProfileOptions o;
  o.interpolation_where = top.where("interpolation");
  if (top.table.contains("interpolation")) o.interpolation = top.choice("interpolation", parse_interpolation);
  if (const toml::node* node = top.table.get("slices")) {
    const auto n = node->value<int64_t>();
    if (!node->is_integer() || !n || *n < min_slices || *n > max_slices)
      fail(top.where("slices"), "value " + describe(*node) + " must be an integer slice count from " +
                                    std::to_string(min_slices) + " to " + std::to_string(max_slices));
    o.slices = static_cast<int>(*n);
  }
  return o;
}

// Reads the profile text into the design's shape: rows that are slices (z_center_m) as stepped
// knots at their centres, or knots (z_m) with the file's interpolation.
void read_profile(const fs::path& file, const std::string& text, const ProfileOptions& options, BatDesign& design) {
  std::optional<Columns> columns;
  std::vector<Row> rows;
  int number = 0;
  // Spreadsheets often save CSV with a UTF-8 byte-order mark; it is not part of the header.
  for (std::size_t start = text.starts_with("\xEF\xBB\xBF") ? 3 : 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    // '#' starts a comment, on a line of its own or after a row's values.
    const std::string_view line = std::string_view(text).substr(start, end - start);
    const std::string_view content = trim(line.substr(0, line.find('#')));
    start = end + 1;
    ++number;
    if (content.empty()) continue;
    if (!columns)
      columns = read_header(file, number, content);
    else if (rows.size() == static_cast<std::size_t>(max_slices))
      fail(at_line(file, number), "row " + std::to_string(max_slices + 1) + ": a profile has at most " +
                                      std::to_string(max_slices) + " rows (slices), as --slices");
    else
      rows.push_back(read_row(file, number, content, *columns));
  }
  if (!columns) fail(file.string(), "no header line; expected e.g. 'z_center_m,outer_diameter_m'");
  if (rows.empty()) fail(file.string(), "the profile has no rows; expected one row per slice or knot");
  Profile& profile = design.profile;
  for (const Row& row : rows) {
    profile.z.push_back(row.z);
    profile.outer.push_back(row.outer);
    if (columns->inner >= 0) profile.inner.push_back(row.inner);
  }
  design.slice_profile = !columns->knots;
  if (design.slice_profile) {
    if (options.interpolation && *options.interpolation != Interpolation::stepped)
      fail(options.interpolation_where, std::string("value '") + to_string(*options.interpolation) + "' with " +
                                            file.string() + ", which lists one diameter per slice (z_center_m): " +
                                            "expected 'stepped', or knots in a z_m column");
    check_slicing(file, rows, design.length);
    if (rows.size() < static_cast<std::size_t>(min_slices))
      fail(file.string(), "the profile has " + std::to_string(rows.size()) + " rows; expected one row per slice, at least " +
                              std::to_string(min_slices) + " (as --slices)");
    profile.interpolation = Interpolation::stepped;
    return;
  }
  check_knots(file, rows, design.length);
  profile.interpolation = options.interpolation.value_or(Interpolation::linear);
  if (!profile.inner.empty()) check_wall_between_knots(file, rows, profile);
}

// The profile is named relative to the bat file, so a study directory can be moved whole; a bat
// of named dimensions has none.
fs::path profile_path(const fs::path& toml_path, const Section& top) {
  if (!top.table.contains("profile") && top.table.contains("dimensions")) return {};
  return toml_path.parent_path() / top.text("profile");
}

// Exactly one shape: a profile CSV or a [dimensions] table.
void require_one_shape(const Section& top) {
  const bool profile = top.table.contains("profile"), dimensions = top.table.contains("dimensions");
  if (profile && dimensions)
    fail(top.where("dimensions"), "given with key 'profile'; expected one shape, a profile CSV or a [dimensions] table");
  if (!profile && !dimensions)
    fail(top.where("profile"), "missing; expected a profile CSV (profile = \"FILE.csv\") or a [dimensions] table");
}

// [dimensions] makes a linear profile (frustums): no other interpolation, no CSV to read.
void read_dimensions(const Section& top, const ProfileOptions& options, BatDesign& design) {
  if (options.interpolation && *options.interpolation != Interpolation::linear)
    fail(options.interpolation_where, std::string("value '") + to_string(*options.interpolation) +
                                          "' with [dimensions], whose taper is a frustum: expected 'linear' or no "
                                          "key 'interpolation'");
  design.dimensions = read_dimension_table(top.section("dimensions"));
  if (const auto rule = dimensions_rule_break(*design.dimensions, design.length))
    fail(top.where("dimensions." + rule->parameter), rule->message);
}

// The key a rule of a possible bat is about: "material.density", "dimensions.wall_thickness",
// "length", or "profile" for the profile's rows.
std::string rule_key(const BatDesign& design, const std::string& parameter) {
  if (parameter == "length" || parameter == "profile") return parameter;
  if (design.dimensions && std::ranges::find(dimension_fields, parameter, &DimensionField::name) != dimension_fields.end())
    return "dimensions." + parameter;
  return "material." + parameter;
}

// Every rule of a possible bat (bat_design.hpp) checked here too, so that a file breaking one is
// refused naming itself and the key, not later by build_bat.
void check_possible(const Section& top, const BatDesign& design) {
  if (const auto rule = rule_break(design)) fail(top.where(rule_key(design, rule->parameter)), rule->message);
  // A calibration the wall cannot take (a compression so low that the calibrated wall is no tube)
  // is refused here, naming the file, not when the bat's modes are first solved.
  if (design.material.barrel.calibrated()) try {
      barrel_wall(build_bat(design));
    } catch (const InputError& e) {
      fail(top.where("barrel"), e.what());
    }
}

}  // namespace

namespace {

// The design source.toml_text describes (source.toml_file names it in messages and places its
// profile); `profile_text` gives the text of the profile the TOML names, at its path.
template <class ProfileText>
BatDesign parse_bat_design(BatSource& source, ProfileText profile_text) {
  const fs::path& toml_path = source.toml_file;
  const toml::table doc = parse_toml(toml_path, source.toml_text);
  const Section top{toml_path, doc, ""};
  top.reject_unknown({"name", "length", "material", "profile", "dimensions", "interpolation", "slices", "barrel"});
  BatDesign design;
  design.name = top.text("name");
  design.length = top.positive_length("length");
  read_material(top.section("material"), design);
  const ProfileOptions options = read_profile_options(top);
  design.slices = options.slices;
  require_one_shape(top);
  if (top.table.contains("dimensions")) {
    read_dimensions(top, options, design);
    read_barrel(top, design);
    check_possible(top, design);
    return design;
  }
  source.profile_file = profile_path(toml_path, top);
  source.profile_text = profile_text(source.profile_file);
  require_text(source.profile_file, source.profile_text);  // TOML itself must be UTF-8 already
  read_profile(source.profile_file, source.profile_text, options, design);
  read_barrel(top, design);
  check_possible(top, design);
  return design;
}

}  // namespace

BatDesign load_bat_design(const std::filesystem::path& toml_path, BatSource& source) {
  source = {toml_path, {}, read_text(toml_path), {}};
  return parse_bat_design(source, [&](const fs::path& profile) {
    return read_text(profile, " (the profile named by key 'profile' in " + toml_path.string() + ")");
  });
}

BatDesign bat_design_from_texts(BatSource& source) {
  return parse_bat_design(source, [&](const fs::path& profile) {
    if (source.profile_text.empty())
      throw InputError(source.toml_file.string() + ": key 'profile' names " + profile.string() +
                       ", whose text was not given; expected the profile's text beside the bat file's");
    return source.profile_text;
  });
}

Bat load_bat(const std::filesystem::path& toml_path) {
  BatSource ignored;
  return load_bat(toml_path, ignored);
}

Bat load_bat(const std::filesystem::path& toml_path, BatSource& source) {
  return build_bat(load_bat_design(toml_path, source));
}

}  // namespace sweetspot
