#pragma once
// Python values the module makes on every call, made cheaply: numpy arrays of C++ values, and dicts
// filled under names spelt in the code ("vf"_key) that are made once.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sweetspot::python {

// A numpy array of the values, made once and filled (array_t's constructor from a pointer makes a
// view and then its copy).
template <class T>
pybind11::array_t<T> array(const T* values, std::size_t n) {
  pybind11::array_t<T> a(static_cast<pybind11::ssize_t>(n));
  std::copy(values, values + n, a.mutable_data());
  return a;
}
inline pybind11::array_t<double> array(const std::vector<double>& v) { return array(v.data(), v.size()); }
inline pybind11::array_t<double> array(const Eigen::VectorXd& v) {
  return array(v.data(), static_cast<std::size_t>(v.size()));
}

// A name spelt in the code, as a Python str made once and kept (interned): "vf"_key. A result's
// ~60 names are the same on every call, and making and hashing each anew cost about as much as the
// rest of the result's dict. Used with the GIL held.
template <std::size_t N>
struct Literal {
  char text[N];
  constexpr Literal(const char (&s)[N]) { std::copy_n(s, N, text); }  // implicit: from the literal
};
template <Literal name>
PyObject* operator""_key() {
  static PyObject* const key = [] {
    PyObject* made = PyUnicode_InternFromString(name.text);
    if (!made) throw pybind11::error_already_set();
    return made;
  }();
  return key;
}

// The keys of the first dict filled with it, kept (values None), for dicts of the same keys in the
// same order: such a dict starts as their copy, which Python makes at once, where a dict grown key
// by key rehashes its table at 6, 11, 22 and 43 keys. Used with the GIL held.
class DictLayout {
 public:
  void start(pybind11::dict& d) const {
    if (keys_ && PyDict_Update(d.ptr(), keys_) != 0) throw pybind11::error_already_set();
  }
  void keep(const pybind11::dict& d) {
    if (keys_) return;
    keys_ = PyObject_CallMethod(reinterpret_cast<PyObject*>(&PyDict_Type), "fromkeys", "O", d.ptr());  // kept
    if (!keys_) throw pybind11::error_already_set();
  }

 private:
  PyObject* keys_ = nullptr;
};

// A dict filled under such names: d["vf"_key] = r.vf; finish() gives it. With a layout, every key
// of the layout must be set (finish() checks: a key left at the layout's None would be a wrong value).
class NamedDict {
 public:
  struct Slot {
    NamedDict& to;
    PyObject* key;
    template <class T>
    void operator=(T&& value) const {
      if (PyDict_SetItem(to.dict_.ptr(), key, pybind11::detail::object_or_cast(std::forward<T>(value)).ptr()) != 0)
        throw pybind11::error_already_set();
      ++to.set_;
    }
  };
  explicit NamedDict(DictLayout& layout, pybind11::dict into = {}) : dict_(std::move(into)), layout_(&layout) {
    layout.start(dict_);
  }
  NamedDict() = default;
  Slot operator[](PyObject* key) { return {*this, key}; }
  pybind11::dict finish() {
    if (layout_) {
      if (set_ != PyDict_GET_SIZE(dict_.ptr())) throw std::logic_error("NamedDict: a key of the layout left unset");
      layout_->keep(dict_);
    }
    return std::move(dict_);
  }

 private:
  pybind11::dict dict_;
  DictLayout* layout_ = nullptr;
  Py_ssize_t set_ = 0;
};

}  // namespace sweetspot::python
