// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The generated RPC halves of each device service in robogene._core, without ports: a server
// dispatch (ControlboardServer, GrabberServer: request bottle in, reply bottle out, over any
// device C++ or Python) and a client (ControlboardClient, GrabberClient: the service's
// interfaces over a Python transport, a callable from request Bottle to reply Bottle). The
// network servers and remote devices are these halves on ports; bound alone they let a program
// or a test speak the service's bytes to anything (a recording, a relay, a tampering peer).
//
// The GIL: respond() and every client method release it (a Python device or transport takes it
// back); the transport and the device are held by the objects that call them.
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "py_support.hpp"
#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/controlboard_client.hpp"
#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/generated/grabber_client.hpp"
#include "robogene/dev/generated/grabber_server.hpp"
#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/nws/remote_grabber.hpp"

namespace py = pybind11;

namespace robogene::python {
namespace {

using dev::DeviceDriver;

// A Python transport as the generated clients' Transport: `transport(request)` returns the reply
// Bottle, or None when the exchange failed. One that raises is reported through
// sys.unraisablehook and fails the exchange, as a failing network does.
template <class Client>
typename Client::Transport python_transport(py::object transport) {
  std::shared_ptr<py::object> fn(new py::object(std::move(transport)), [](py::object* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
  return [fn](const Bottle& request, Bottle& reply) {
    py::gil_scoped_acquire gil;
    try {
      py::object got = (*fn)(request);
      if (got.is_none()) return false;
      if (!py::isinstance<Bottle>(got)) {
        PyErr_SetString(PyExc_TypeError, ("a client transport must return a Bottle or None, got " +
                                          type_name_of(got))
                                             .c_str());
        throw py::error_already_set();
      }
      reply = got.cast<Bottle>();
      return true;
    } catch (py::error_already_set& e) {
      report_callback_error(e, "robogene client transport");
      return false;
    }
  };
}

template <class Server>
py::class_<Server> bind_server(py::module_& m, const char* name, const char* doc) {
  py::class_<Server> c(m, name, doc);
  c.def(py::init<DeviceDriver&>(), py::arg("device"), py::keep_alive<1, 2>(),
        "Answers for `device` (kept alive by the server), through the interfaces it implements.")
      .def_property_readonly_static("SERVICE", [](py::object) { return Server::kServiceName; })
      .def_property_readonly_static("FINGERPRINT", [](py::object) { return Server::kFingerprint; })
      .def("respond", &Server::respond, py::arg("request"), py::call_guard<py::gil_scoped_release>(),
           "The reply to one request bottle: [is] ... for a query, [ok] or [fail] for a command, [nak] for "
           "a request the service does not know, a usage line per request for `help`.")
      .def("interfaces", &Server::interfaces,
           "(name, fingerprint) of each interface of the service the device implements.");
  return c;
}

// A publisher (Server::publish_state, publish_image) as a method returning the message or None.
template <class Server>
auto publisher(bool (Server::*publish)(Bottle&)) {
  return [publish](Server& s) -> std::optional<Bottle> {
    Bottle out;
    bool done = false;
    {
      py::gil_scoped_release nogil;
      done = (s.*publish)(out);
    }
    return done ? std::optional<Bottle>(std::move(out)) : std::nullopt;
  };
}

template <class Client, class... Interfaces>
void bind_client(py::module_& m, const char* name, const char* doc) {
  py::class_<Client, Interfaces...>(m, name, doc)
      .def(py::init([name](py::object transport) {
             if (!PyCallable_Check(transport.ptr())) {
               throw py::type_error(std::string(name) + ": `transport` must be callable");
             }
             return std::make_unique<Client>(python_transport<Client>(std::move(transport)));
           }),
           py::arg("transport"), "A client whose requests go to `transport(request) -> reply Bottle | None`.")
      .def_property_readonly_static("SERVICE", [](py::object) { return Client::kServiceName; })
      .def("check_server", &Client::check_server, py::arg("robogene_server"),
           py::call_guard<py::gil_scoped_release>(),
           "Checks the server speaks this client's interfaces: a Robogene server by their fingerprints "
           "(returned as (name, fingerprint) pairs), any other one by its protocol version only (never "
           "asked for fingerprints). Raises robogene.Error naming what differs.");
}

}  // namespace

void bind_device_rpc(py::module_& m) {
  bind_server<dev::ControlboardServer>(m, "ControlboardServer",
                                       "The control board service's RPC dispatch over one device, without ports.")
      .def(
          "command",
          [](dev::ControlboardServer& s, const Bottle& message) {
            py::gil_scoped_release nogil;
            return s.command(message);
          },
          py::arg("message"),
          "Carries out one message of <name>/command:i, ([head...]) (values...); False when malformed or refused.")
      .def("publish_state", publisher(&dev::ControlboardServer::publish_state),
           "What <name>/state:o publishes (the joint positions), or None when the device cannot say.");
  bind_server<dev::GrabberServer>(m, "GrabberServer", "The camera service's RPC dispatch over one device, without ports.")
      .def("publish_image", publisher(&dev::GrabberServer::publish_image),
           "The next image as <name> publishes it ([mat] [rgb] ...), or None when the camera has none.");
  bind_client<dev::ControlboardClient, dev::IEncoders, dev::IPositionControl, dev::IVelocityControl,
              dev::ITorqueControl, dev::IPidControl, dev::IControlMode>(
      m, "ControlboardClient", "The control board service's interfaces, spoken through a transport.");
  bind_client<dev::GrabberClient, dev::IFrameGrabberImage, dev::IFrameGrabberControls>(
      m, "GrabberClient", "The camera service's interfaces, spoken through a transport.");
  // remote_grabber is a GrabberClient on ports: any view of it comes back as this class.
  py::class_<dev::RemoteGrabber, DeviceDriver, dev::GrabberClient>(
      m, "RemoteGrabber", "remote_grabber, as PolyDriver.view(RemoteGrabber) gives it: a camera on the network.")
      .def("frames_received", &dev::RemoteGrabber::frames_received, py::call_guard<py::gil_scoped_release>(),
           "Frames received on the image port since the device opened.");
}

}  // namespace robogene::python
