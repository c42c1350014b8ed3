// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Float vectors between Bottles and Python buffers (memoryview, array.array, numpy arrays...).
// A Bottle keeps each item as a tagged Value, not as one contiguous array of doubles, so a
// vector cannot be shared in place: it crosses in exactly one copy loop, C++ to C++, without
// creating a Python float per item. Blobs, which are contiguous, are shared in place through
// Value's buffer protocol instead (see bind_bottle.cpp).
#include <pybind11/pybind11.h>

#include <cstring>
#include <string>
#include <type_traits>

#include "bindings.hpp"

namespace py = pybind11;

namespace robogene::python {
namespace {

std::string describe_format(const py::buffer_info& info) {
  return "format '" + info.format + "', item size " + std::to_string(info.itemsize);
}

// Calls put(i, double or float) for every item of a 1-D (any stride) or C-contiguous buffer.
template <class Put>
void for_each_float(const py::buffer& data, Put&& put) {
  py::buffer_info info = data.request();
  const bool f64 = info.item_type_is_equivalent_to<double>();
  const bool f32 = info.item_type_is_equivalent_to<float>();
  if (!f64 && !f32) {
    throw py::type_error("expected a buffer of float64 ('d') or float32 ('f') items, got " +
                         describe_format(info));
  }
  py::ssize_t count = 1;
  py::ssize_t expected_stride = info.itemsize;
  bool contiguous = true;
  for (py::ssize_t d = info.ndim - 1; d >= 0; --d) {
    if (info.strides[d] != expected_stride) contiguous = false;
    expected_stride *= info.shape[d];
    count *= info.shape[d];
  }
  if (info.ndim != 1 && !contiguous) {
    throw py::value_error("expected a 1-D or C-contiguous buffer, got " + std::to_string(info.ndim) +
                          " dimensions with strides that are not C order");
  }
  const py::ssize_t stride = info.ndim == 1 ? info.strides[0] : info.itemsize;
  const auto* base = static_cast<const char*>(info.ptr);
  for (py::ssize_t i = 0; i < count; ++i) {
    const char* p = base + i * stride;
    if (f64) {
      double v;
      std::memcpy(&v, p, sizeof v);
      put(v);
    } else {
      float v;
      std::memcpy(&v, p, sizeof v);
      put(v);
    }
  }
}

void append_floats(Bottle& b, const py::buffer& data) {
  for_each_float(data, [&](auto v) {
    if constexpr (std::is_same_v<decltype(v), float>) {
      b.add(Value::float32(v));
    } else {
      b.add(Value::float64(v));
    }
  });
}

double item_as_double(const Bottle& b, std::size_t i) {
  const Value& v = b[i];
  if (!v.is_number()) {
    throw py::type_error("Bottle item " + std::to_string(i) + " is a " + type_name(v.type()) +
                         ", not a number: " + v.to_text());
  }
  return v.as_float64();
}

py::object to_floats(const Bottle& b) {
  const std::size_t n = b.size();
  py::object storage = py::reinterpret_steal<py::object>(
      PyByteArray_FromStringAndSize(nullptr, static_cast<py::ssize_t>(n * sizeof(double))));
  if (!storage) throw py::error_already_set();
  char* out = PyByteArray_AS_STRING(storage.ptr());
  for (std::size_t i = 0; i < n; ++i) {
    const double v = item_as_double(b, i);
    std::memcpy(out + i * sizeof(double), &v, sizeof v);
  }
  return py::memoryview(storage).attr("cast")("d");
}

std::size_t floats_into(const Bottle& b, const py::buffer& out) {
  py::buffer_info info = out.request(true);
  if (!info.item_type_is_equivalent_to<double>()) {
    throw py::type_error("floats_into needs a writable buffer of float64 ('d') items, got " +
                         describe_format(info));
  }
  if (info.ndim != 1) {
    throw py::value_error("floats_into needs a 1-D buffer, got " + std::to_string(info.ndim) + " dimensions");
  }
  if (static_cast<std::size_t>(info.shape[0]) < b.size()) {
    throw py::value_error("floats_into: the buffer holds " + std::to_string(info.shape[0]) +
                          " items, the Bottle has " + std::to_string(b.size()));
  }
  auto* base = static_cast<char*>(info.ptr);
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double v = item_as_double(b, i);
    std::memcpy(base + static_cast<py::ssize_t>(i) * info.strides[0], &v, sizeof v);
  }
  return b.size();
}

}  // namespace

void bind_float_buffers(py::class_<Bottle>& bottle) {
  bottle
      .def_static("from_floats", [](const py::buffer& data) {
        Bottle b;
        append_floats(b, data);
        return b;
      }, py::arg("data"),
         "A Bottle of the float64 ('d') or float32 ('f') items of a buffer (memoryview, array, "
         "numpy array), copied once without Python floats.")
      .def("add_floats", [](Bottle& b, const py::buffer& data) -> Bottle& {
        append_floats(b, data);
        return b;
      }, py::arg("data"), py::return_value_policy::reference_internal,
         "Appends the float items of a buffer (see from_floats); returns this Bottle.")
      .def("to_floats", &to_floats,
           "Every item as float64 in a new memoryview of format 'd' (one copy). Raises TypeError "
           "naming the first item that is not a number.")
      .def("floats_into", &floats_into, py::arg("out"),
           "Writes every item as float64 into a writable 1-D 'd' buffer at least len(self) long; "
           "returns the number written.");
}

}  // namespace robogene::python
