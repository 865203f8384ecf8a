#include "sweetspot/study/dataset.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <variant>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include <hdf5.h>
#include <hdf5_hl.h>

namespace sweetspot {

namespace {

namespace fs = std::filesystem;

// A failure while writing; write_dataset adds the path to its message.
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The innermost entry of HDF5's error stack says most specifically what went wrong.
std::string hdf5_reason() {
  std::string reason = "no details from HDF5";
  const auto take_innermost = [](unsigned n, const H5E_error2_t* error, void* out) -> herr_t {
    if (n == 0 && error->desc) *static_cast<std::string*>(out) = error->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_innermost, &reason);
  return reason;
}

// HDF5 reports failure as a negative identifier or status.
template <typename Result>
Result check(Result result, const std::string& what) {
  if (result < 0) throw WriteError(what + ": " + hdf5_reason());
  return result;
}

// Owns one HDF5 identifier, so nothing stays open when an exception unwinds. Made from the result
// of the call that opened it, which throws saying `what` if that call failed.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer closer, const std::string& what) : id_(check(id, what)), closer_(closer) {}
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), closer_(other.closer_) {}
  ~Handle() {
    if (id_ >= 0) closer_(id_);
  }
  operator hid_t() const { return id_; }
  // Closing a file is where HDF5 flushes it, so that failure must not go unnoticed.
  void close(const std::string& what) { check(closer_(std::exchange(id_, -1)), what); }

 private:
  hid_t id_;
  Closer closer_;
};

// We report HDF5 failures as exceptions; its own printing to stderr would only repeat them.
struct QuietHdf5 {
  H5E_auto2_t printer = nullptr;
  void* data = nullptr;
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &printer, &data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, printer, data); }
};

// ---- Checking the dataset before any file is touched ----

[[noreturn]] void reject(const std::string& object, const std::string& why) {
  throw std::invalid_argument("dataset " + object + ": " + why);
}

void check_name(const std::string& object, const std::string& name, std::set<std::string>& seen) {
  if (name.empty() || name.find('/') != std::string::npos)
    reject(object, "the name must be non-empty and hold no '/'");
  if (!seen.insert(name).second) reject(object, "the name is used twice");
}

// The position of the coordinate named `name`, or the number of coordinates if none is.
std::size_t coordinate_index(const Dataset& dataset, const std::string& name) {
  const auto& coordinates = dataset.coordinates;
  const auto found = std::find_if(coordinates.begin(), coordinates.end(),
                                  [&](const Coordinate& c) { return c.name == name; });
  return std::size_t(found - coordinates.begin());
}

std::size_t value_count(const Variable& variable) {
  return std::visit([](const auto& values) { return values.size(); }, variable.values);
}

bool holds_strings(const Variable& variable) {
  return std::holds_alternative<std::vector<std::string>>(variable.values);
}

void validate(const Dataset& dataset) {
  std::set<std::string> names;  // coordinates and variables share the file's root group
  for (const Coordinate& coordinate : dataset.coordinates) {
    const std::string object = "coordinate '" + coordinate.name + "'";
    check_name(object, coordinate.name, names);
    const int kinds = !coordinate.values.empty() + !coordinate.labels.empty() + !coordinate.integers.empty();
    if (kinds != 1) reject(object, "needs exactly one of values, labels and integers");
    if (!coordinate.labels.empty() && !coordinate.units.empty())
      reject(object, "holds strings, which take no units (units '" + coordinate.units + "')");
  }
  for (const Variable& variable : dataset.variables) {
    const std::string object = "variable '" + variable.name + "'";
    check_name(object, variable.name, names);
    if (holds_strings(variable) && !variable.units.empty())
      reject(object, "holds strings, which take no units (units '" + variable.units + "')");
    std::size_t expected = 1;
    for (const std::string& dim : variable.dims) {
      const std::size_t index = coordinate_index(dataset, dim);
      if (index == dataset.coordinates.size())
        reject(object, "dimension '" + dim + "' is not a coordinate");
      expected *= dataset.coordinates[index].size();
    }
    if (value_count(variable) != expected)
      reject(object, "has " + std::to_string(value_count(variable)) +
                         " values, its dimensions make " + std::to_string(expected));
  }
}

// ---- Writing ----

// Bytes on disk for a string of `length`: null-terminated, and never one byte wide, which
// h5netcdf would leave undecoded as bytes (so "m" and "" would not come back as str) and xarray
// would read as a character array.
std::size_t string_width(std::size_t length) { return std::max<std::size_t>(length + 1, 2); }

// Fixed-length strings of `width` bytes; UTF-8, so that h5netcdf decodes non-ASCII text ("ω").
Handle string_type(std::size_t width) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copying the string type");
  check(H5Tset_size(type, width), "sizing a string type");
  check(H5Tset_strpad(type, H5T_STR_NULLTERM), "setting string padding");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "setting string encoding");
  return type;
}

// Tracking creation order, as netCDF-4 files do, makes h5py, h5netcdf and xarray list
// coordinates, variables and attributes in the order written (the study's axes in their order)
// instead of by name.
Handle ordered(hid_t property_class) {
  Handle list(H5Pcreate(property_class), H5Pclose, "creating a property list");
  const unsigned flags = H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED;
  check(H5Pset_attr_creation_order(list, flags), "tracking attribute order");
  if (property_class == H5P_FILE_CREATE)
    check(H5Pset_link_creation_order(list, flags), "tracking variable order");
  return list;
}

// No extent makes a scalar.
Handle make_space(const std::vector<hsize_t>& shape) {
  const hid_t space = shape.empty() ? H5Screate(H5S_SCALAR)
                                    : H5Screate_simple(int(shape.size()), shape.data(), nullptr);
  return {space, H5Sclose, "creating a dataspace"};
}

// The file keeps data in `type`, the type `data` has in memory.
void write_attribute(hid_t object, const std::string& name, hid_t type,
                     const std::vector<hsize_t>& shape, const void* data) {
  std::array<char, 256> owner{};  // "/" for the file's own (global) attributes
  H5Iget_name(object, owner.data(), owner.size());
  const std::string what = "attribute '" + name + "' of '" + owner.data() + "'";
  const Handle space = make_space(shape);
  const Handle attribute(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                         H5Aclose, "creating " + what);
  check(H5Awrite(attribute, type, data), "writing " + what);
}

void write_text(hid_t object, const std::string& name, const std::string& value) {
  std::string text = value;
  text.resize(string_width(value.size()), '\0');
  write_attribute(object, name, string_type(text.size()), {}, text.data());
}

// No units for what has none (strings): CF gives units to quantities only.
void write_description(hid_t object, const std::string& units, const std::string& long_name) {
  if (!units.empty()) write_text(object, "units", units);
  write_text(object, "long_name", long_name);
}

void write_attributes(hid_t object, const TextAttributes& texts, const IntegerAttributes& integers) {
  for (const auto& [name, text] : texts) write_text(object, name, text);
  for (const auto& [name, numbers] : integers)
    write_attribute(object, name, H5T_NATIVE_INT32, {numbers.size()}, numbers.data());
}

// Contiguous and uncompressed: the simplest layout, and the fastest to write whole.
Handle write_array(hid_t file, const std::string& name, hid_t type,
                   const std::vector<hsize_t>& shape, const void* data) {
  const Handle space = make_space(shape);
  Handle dataset(H5Dcreate2(file, name.c_str(), type, space, H5P_DEFAULT,
                            ordered(H5P_DATASET_CREATE), H5P_DEFAULT),
                 H5Dclose, "creating '" + name + "'");
  check(H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "writing '" + name + "'");
  return dataset;
}

// Strings side by side, each padded with nulls to the width of the longest; `_Encoding` is what
// makes xarray decode them to str instead of bytes.
Handle write_strings(hid_t file, const std::string& name, const std::vector<std::string>& strings,
                     const std::vector<hsize_t>& shape) {
  std::size_t width = 0;
  for (const std::string& string : strings) width = std::max(width, string_width(string.size()));
  std::vector<char> text(width * strings.size(), '\0');
  for (std::size_t i = 0; i < strings.size(); ++i) strings[i].copy(&text[i * width], width - 1);
  Handle dataset = write_array(file, name, string_type(width), shape, text.data());
  write_text(dataset, "_Encoding", "utf-8");
  return dataset;
}

Handle write_values(hid_t file, const std::string& name, const std::vector<double>& values,
                    const std::vector<hsize_t>& shape) {
  return write_array(file, name, H5T_NATIVE_DOUBLE, shape, values.data());
}

Handle write_values(hid_t file, const std::string& name, const std::vector<std::int32_t>& values,
                    const std::vector<hsize_t>& shape) {
  return write_array(file, name, H5T_NATIVE_INT32, shape, values.data());
}

Handle write_values(hid_t file, const std::string& name, const std::vector<std::string>& values,
                    const std::vector<hsize_t>& shape) {
  return write_strings(file, name, values, shape);
}

// A dimension scale named after itself is netCDF-4's coordinate variable.
Handle write_coordinate(hid_t file, const Coordinate& coordinate) {
  const std::vector<hsize_t> shape{coordinate.size()};
  Handle dataset = !coordinate.labels.empty()     ? write_strings(file, coordinate.name, coordinate.labels, shape)
                   : !coordinate.integers.empty() ? write_values(file, coordinate.name, coordinate.integers, shape)
                                                  : write_values(file, coordinate.name, coordinate.values, shape);
  write_description(dataset, coordinate.units, coordinate.long_name);
  write_attributes(dataset, coordinate.text_attributes, coordinate.int_attributes);
  check(H5DSset_scale(dataset, coordinate.name.c_str()),
        "making '" + coordinate.name + "' a dimension scale");
  return dataset;
}

// `scales` holds the coordinates' datasets, in the order of dataset.coordinates.
void write_variable(hid_t file, const Dataset& dataset, const std::vector<Handle>& scales,
                    const Variable& variable) {
  std::vector<std::size_t> axes;  // coordinate index of each axis
  std::vector<hsize_t> shape;
  for (const std::string& dim : variable.dims) {
    axes.push_back(coordinate_index(dataset, dim));
    shape.push_back(dataset.coordinates[axes.back()].size());
  }
  const Handle data =
      std::visit([&](const auto& values) { return write_values(file, variable.name, values, shape); }, variable.values);
  for (unsigned axis = 0; axis < axes.size(); ++axis)
    check(H5DSattach_scale(data, scales[axes[axis]], axis),
          "attaching '" + variable.dims[axis] + "' to '" + variable.name + "'");
  write_description(data, variable.units, variable.long_name);
  write_attributes(data, variable.text_attributes, variable.int_attributes);
}

void write_contents(hid_t file, const Dataset& dataset) {
  std::vector<Handle> scales;
  for (const Coordinate& coordinate : dataset.coordinates)
    scales.push_back(write_coordinate(file, coordinate));
  for (const Variable& variable : dataset.variables)
    write_variable(file, dataset, scales, variable);
  // Attributes of the file are those of its root group: netCDF's global attributes.
  for (const auto& [name, text] : dataset.text_attributes) write_text(file, name, text);
  for (const auto& [name, number] : dataset.number_attributes)
    write_attribute(file, name, H5T_NATIVE_DOUBLE, {}, &number);
  // One value is a scalar attribute (ranks = 4, not [4]); more make a list.
  for (const auto& [name, numbers] : dataset.int_attributes)
    write_attribute(file, name, H5T_NATIVE_INT32, numbers.size() == 1 ? std::vector<hsize_t>{} : std::vector<hsize_t>{numbers.size()},
                    numbers.data());
  for (const auto& [name, numbers] : dataset.number_list_attributes)
    write_attribute(file, name, H5T_NATIVE_DOUBLE, {numbers.size()}, numbers.data());
}

void write_file(const fs::path& path, const Dataset& dataset) {
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, ordered(H5P_FILE_CREATE), H5P_DEFAULT),
              H5Fclose, "creating the file");
  write_contents(file, dataset);  // every object it opened is closed again when it returns
  file.close("closing the file");
}

// Without this, a crash of the machine soon after the rename could leave the new name pointing
// at data that never reached the disk.
void flush_to_disk(const fs::path& path) {
  const int descriptor = ::open(path.c_str(), O_RDONLY);
  const bool synced = descriptor >= 0 && ::fsync(descriptor) == 0;
  const std::error_code error(errno, std::generic_category());
  if (descriptor >= 0) ::close(descriptor);
  if (!synced) throw WriteError("flushing " + path.string() + " to disk: " + error.message());
}

// Removes the temporary file on every way out; after the rename there is nothing left to remove.
// A directory of that name is not ours (creating the file failed on it): it stays.
struct TemporaryFile {
  fs::path path;
  ~TemporaryFile() {
    std::error_code ignored;
    if (!fs::is_directory(fs::symlink_status(path, ignored))) fs::remove(path, ignored);
  }
};

}  // namespace

fs::path dataset_temporary_path(const fs::path& path) { return fs::path(path) += ".tmp"; }

void write_dataset(const fs::path& path, const Dataset& dataset) {
  validate(dataset);
  const TemporaryFile temporary{dataset_temporary_path(path)};
  try {
    const QuietHdf5 quiet;
    write_file(temporary.path, dataset);
    flush_to_disk(temporary.path);
  } catch (const WriteError& error) {
    throw std::runtime_error(path.string() + ": " + error.what());
  }
  fs::rename(temporary.path, path);
}

}  // namespace sweetspot
