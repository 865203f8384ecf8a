#pragma once
// One study's results as one HDF5 file in netCDF-4 layout, so that both
// `xarray.open_dataset(path, engine="h5netcdf")` and h5py read it as it is.
//
// Layout: every coordinate is a 1-D dataset made a dimension scale named after itself and attached
// to every variable along the matching axis; every variable and coordinate has a `long_name`, and
// `units` unless it holds strings (CF: units belong to quantities, and a string is none); all
// strings are fixed-length, null-terminated UTF-8 (the parallel HDF5 build cannot write
// variable-length strings in parallel, so the project never uses them). A string coordinate or
// variable carries `_Encoding = "utf-8"`, which is what makes xarray decode its bytes to str.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace sweetspot {

using TextAttributes = std::vector<std::pair<std::string, std::string>>;
using IntegerAttributes = std::vector<std::pair<std::string, std::vector<std::int32_t>>>;

// A dimension of the dataset with its coordinate variable (netCDF: a 1-D variable named like the
// dimension). Exactly one of `values`, `labels` and `integers` is filled, and it is not empty.
struct Coordinate {
  std::string name, units, long_name;
  std::vector<double> values;          // a numeric coordinate (speeds, impact locations...), or
  std::vector<std::string> labels;     // a string coordinate (bat names), fixed-length strings on disk,
  std::vector<std::int32_t> integers = {};  // or a count (mode numbers, slices), 32-bit integers on disk
  TextAttributes text_attributes = {};      // e.g. flag_meanings
  IntegerAttributes int_attributes = {};    // e.g. flag_values
  std::size_t size() const { return values.size() + labels.size() + integers.size(); }
};

// A data variable over some of the dimensions, row-major (last dimension fastest). No dimensions
// makes a scalar.
struct Variable {
  std::string name, units, long_name;
  std::vector<std::string> dims;  // coordinate names, slowest first
  // Strings (texts such as a bat's file) are fixed-length on disk, as wide as the longest.
  std::variant<std::vector<double>, std::vector<std::int32_t>, std::vector<std::string>> values;
  TextAttributes text_attributes;    // e.g. flag_meanings
  IntegerAttributes int_attributes;  // e.g. flag_values
};

// Global attributes (netCDF's attributes of the root group).
struct Dataset {
  std::vector<Coordinate> coordinates;
  std::vector<Variable> variables;
  TextAttributes text_attributes;                                 // study file, version
  std::vector<std::pair<std::string, double>> number_attributes;  // e.g. wall time
  IntegerAttributes int_attributes;                               // ranks, threads (one value each)
  std::vector<std::pair<std::string, std::vector<double>>> number_list_attributes;  // e.g. probes
};

// Writes `dataset` to `path` atomically: into `path` + ".tmp" beside it, flushed to disk, then
// renamed, so a crash never leaves a half-written file under the final name and an existing file
// is replaced only by a complete one.
//
// Checks the dataset before touching any file and throws std::invalid_argument naming the
// coordinate or variable that is wrong: names empty, repeated or holding '/'; a coordinate with
// more or fewer than one of values, labels and integers; strings with units; a dimension that is
// not a coordinate; a variable whose size is not the product of its dimensions' sizes.
// Throws std::runtime_error naming `path` (and the object being written) on any HDF5 failure, and
// std::filesystem::filesystem_error if the rename fails; either way the temporary file is removed
// and an existing `path` left as it was.
void write_dataset(const std::filesystem::path& path, const Dataset& dataset);

// The temporary file write_dataset writes before renaming it to `path`: `path` + ".tmp".
std::filesystem::path dataset_temporary_path(const std::filesystem::path& path);

}  // namespace sweetspot
