// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What the device bindings share, hand-written and generated (generated/bind_interfaces.cpp):
// * python_method / python_value: how a trampoline reaches the Python method implementing a
//   C++ virtual and reads what it returned, naming the method when either goes wrong.
// * report_device_error: a Python device's exception, raised on a server thread that has no
//   Python caller, goes to sys.unraisablehook and the call answers false (as a C++ device that
//   fails does).
// * python_interface / view_interface: generated; an interface of a Python device by name, and
//   PolyDriver.view's lookup of an interface class.
// * Joint: an axis index as the bound methods take it: a Python int, never a bool (True would
//   silently be axis 1).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <string_view>
#include <typeinfo>

#include "robogene/dev/device_driver.hpp"
#include "robogene/error.hpp"

namespace robogene::python {

namespace py = pybind11;

// The class name of the Python object behind a trampoline (GIL held).
template <class Base>
std::string python_class_of(const Base* self) {
  py::handle obj = py::detail::get_object_handle(self, py::detail::get_type_info(typeid(Base)));
  return obj ? std::string(py::str(py::type::handle_of(obj).attr("__qualname__"))) : "a Python device";
}

// The Python method that overrides `method` of `Base` (GIL held). A class that claims the
// interface but lacks the method gets a NotImplementedError naming both.
template <class Base>
py::function python_method(const Base* self, const char* interface, const char* method) {
  py::function f = py::get_override(self, method);
  if (!f) {
    PyErr_SetString(PyExc_NotImplementedError, (python_class_of(self) + " implements " + interface +
                                                " but not its method " + method).c_str());
    throw py::error_already_set();
  }
  return f;
}

// `result` as T; a TypeError naming `where` and the type it got when it is not one (GIL held).
template <class T>
T python_value(const py::handle& result, const char* where) {
  try {
    return result.cast<T>();
  } catch (const py::cast_error&) {
    const std::string got = py::str(py::type::handle_of(result).attr("__name__"));
    PyErr_SetString(PyExc_TypeError, (std::string(where) + " returned " + got +
                                      ", which does not convert to what the interface declares").c_str());
    throw py::error_already_set();
  }
}

// The items of a method's tuple of results (GIL held); a TypeError unless there are `count`.
py::tuple python_results(const py::handle& result, const char* where, std::size_t count);

// Reports the exception of a Python device's method called from C++ (GIL held).
void report_device_error(py::error_already_set& e, const char* where);

void* python_interface(py::handle device, std::string_view name);
py::object view_interface(dev::DeviceDriver& device, py::handle interface);

void bind_generated_types(py::module_& m);
void bind_generated_interfaces(py::module_& m);

struct Joint {
  int value = 0;
  operator int() const { return value; }  // NOLINT(google-explicit-constructor): passed on as the C++ int
};

}  // namespace robogene::python

namespace pybind11::detail {

// An axis index: what converts to a C++ int except a bool, which fails the call with TypeError.
template <>
struct type_caster<robogene::python::Joint> {
  PYBIND11_TYPE_CASTER(robogene::python::Joint, const_name("int"));
  bool load(handle src, bool convert) {
    if (PyBool_Check(src.ptr())) return false;
    make_caster<int> index;
    if (!index.load(src, convert)) return false;
    value.value = cast_op<int>(index);
    return true;
  }
  static handle cast(robogene::python::Joint j, return_value_policy, handle) { return PyLong_FromLong(j.value); }
};

}  // namespace pybind11::detail
