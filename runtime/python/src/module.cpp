// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The `robogene._core` extension: the C++ core exposed to Python. One file per area binds its
// classes; this file only wires them together and maps C++ errors to Python exceptions.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "py_support.hpp"
#include "robogene/dev/property.hpp"
#include "robogene/error.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
  m.doc() = "Robogene core: bottles, ports and devices (YARP 3 wire compatible)";
  m.attr("__version__") = ROBOGENE_VERSION;

  static py::exception<robogene::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<robogene::ParseError> parse_error(m, "ParseError", error.ptr());
  static py::exception<robogene::NetworkError> network_error(m, "NetworkError", error.ptr());
  // A device configuration value that is missing, malformed or out of range (names where).
  static py::exception<robogene::dev::ConfigError> config_error(m, "ConfigError", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const robogene::ParseError& e) {
      // The instance carries `position` (byte offset or 1-based column) beside the message.
      // Messages quote what the peer sent: any bytes, decoded without raising (text_to_python).
      py::object instance =
          py::reinterpret_borrow<py::object>(parse_error.ptr())(robogene::python::text_to_python(e.what()));
      instance.attr("position") = e.position();
      PyErr_SetObject(parse_error.ptr(), instance.ptr());
    } catch (const robogene::dev::ConfigError& e) {
      PyErr_SetObject(config_error.ptr(), robogene::python::text_to_python(e.what()).ptr());
    } catch (const robogene::NetworkError& e) {
      PyErr_SetObject(network_error.ptr(), robogene::python::text_to_python(e.what()).ptr());
    } catch (const robogene::Error& e) {
      PyErr_SetObject(error.ptr(), robogene::python::text_to_python(e.what()).ptr());
    }
  });

  robogene::python::bind_bottle(m);
  robogene::python::bind_contact(m);
  robogene::python::bind_network(m);
  robogene::python::bind_port(m);
  robogene::python::bind_buffered_port(m);
  robogene::python::bind_rpc(m);
  robogene::python::bind_devices(m);
  robogene::python::bind_device_rpc(m);
  robogene::python::bind_joint_data(m);  // after the devices: encode_joint_data takes a DeviceDriver

  // Ports still open at exit are closed while the interpreter still grants the GIL to the
  // threads that run their callbacks (later, those threads could never finish).
  m.def("_close_all_at_exit", &robogene::python::close_all_at_exit);
  py::module_::import("atexit").attr("register")(m.attr("_close_all_at_exit"));
}
