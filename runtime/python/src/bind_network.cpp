// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Network: the name-server client (robogene::NameClient) and the one-shot operations on other
// ports (robogene::network), as one Python object. Every call blocks for at most its timeout
// and runs with the GIL released.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "py_support.hpp"
#include "robogene/error.hpp"
#include "robogene/name_client.hpp"
#include "robogene/name_config.hpp"
#include "robogene/network.hpp"

namespace py = pybind11;

namespace robogene::python {
namespace {

using ServerArg = std::optional<std::variant<std::string, std::pair<std::string, int>>>;

net::Endpoint server_endpoint(const ServerArg& server) {
  if (!server) return NameConfig::load().server;
  if (const auto* text = std::get_if<std::string>(&*server)) return NameConfig::parse_server(*text);
  const auto& pair = std::get<std::pair<std::string, int>>(*server);
  if (pair.first.empty() || pair.second <= 0 || pair.second > 65535) {
    throw py::value_error("name server address (" + pair.first + ", " + std::to_string(pair.second) +
                          ") needs a host and a port number 1..65535");
  }
  return {pair.first, pair.second};
}

Contact registered(NameClient& names, const std::string& port) {
  auto c = names.query(port);
  if (!c) {
    throw NetworkError("no port " + port + " is registered with the name server at " +
                       names.server().to_string());
  }
  return *c;
}

std::vector<Contact> list_ports(NameClient& names, const std::string& prefix) {
  std::vector<Contact> out;
  for (const auto& line : names.request("NAME_SERVER list" + (prefix.empty() ? "" : " " + prefix) + "\n")) {
    if (auto c = NameClient::parse_registration(line)) out.push_back(*c);
  }
  return out;
}

std::string checked(const network::AdminResult& r, const std::string& what) {
  std::string message = r.message;
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
  if (!r.ok) throw NetworkError(what + ": " + message);
  return message;
}

}  // namespace

void bind_network(py::module_& m) {
  py::class_<NameClient>(m, "Network",
                         "The name server and operations on other ports. Without `server`, the "
                         "address comes from yarp.conf; `server` may be 'host:port' or (host, port).")
      .def(py::init([](const ServerArg& server, double timeout) {
             const auto t = to_millis(timeout, "timeout");
             if (!t || t->count() == 0) throw py::value_error("timeout must be a finite number of seconds > 0");
             return NameClient(server_endpoint(server), *t);
           }),
           py::arg("server") = py::none(), py::arg("timeout") = 5.0)
      .def_property_readonly("host", [](const NameClient& n) { return n.server().host; })
      .def_property_readonly("port", [](const NameClient& n) { return n.server().port; })
      .def_property_readonly("address", [](const NameClient& n) { return n.server().to_string(); },
                             "'host:port' of the name server.")
      .def("query", &NameClient::query, py::arg("name"), py::call_guard<py::gil_scoped_release>(),
           "Where `name` is registered, or None.")
      .def("register", &NameClient::register_name, py::arg("name"), py::arg("carrier") = "tcp",
           py::arg("host") = "", py::arg("port") = 0, py::call_guard<py::gil_scoped_release>(),
           "Registers a name (empty host / port 0: the server chooses); returns what it recorded.")
      .def("unregister", &NameClient::unregister, py::arg("name"), py::call_guard<py::gil_scoped_release>())
      .def("list", &list_ports, py::arg("prefix") = "", py::call_guard<py::gil_scoped_release>(),
           "Every registered port (whose name starts with `prefix`).")
      .def("set_property", &NameClient::set_property, py::arg("name"), py::arg("key"), py::arg("values"),
           py::call_guard<py::gil_scoped_release>())
      .def("request", &NameClient::request, py::arg("line"), py::call_guard<py::gil_scoped_release>(),
           "Sends one raw name-server line ('NAME_SERVER ...\\n'); returns the reply lines.")
      .def("connect", [](NameClient& n, const std::string& source, const std::string& target,
                         const std::string& carrier) {
             return checked(network::connect(n, source, target, carrier), "connect " + source + " -> " + target);
           },
           py::arg("source"), py::arg("target"), py::arg("carrier") = "", py::call_guard<py::gil_scoped_release>(),
           "Asks `source` to send its output to `target` (as `robogene connect`); returns the "
           "port's report, raises NetworkError with it when refused.")
      .def("disconnect", [](NameClient& n, const std::string& source, const std::string& target) {
             return checked(network::disconnect(n, source, target), "disconnect " + source + " -> " + target);
           },
           py::arg("source"), py::arg("target"), py::call_guard<py::gil_scoped_release>())
      .def("rpc", [](NameClient& n, const std::string& port, const BottleLike& request, const std::string& carrier,
                     double timeout) {
             const auto t = to_millis(timeout, "timeout");
             const Bottle b = to_bottle(request, "Network.rpc's request");
             py::gil_scoped_release nogil;
             Contact to = registered(n, port);
             return network::rpc(to, b, carrier, "anon_rpc", t ? *t : net::kNoTimeout);
           },
           py::arg("port"), py::arg("request"), py::arg("carrier") = "tcp", py::arg("timeout") = 5.0,
           "Sends one request (Bottle, list or tuple) to `port` as an anonymous sender and returns "
           "the reply (as `yarp rpc`).")
      .def("admin", [](NameClient& n, const std::string& port, const BottleLike& request) {
             const Bottle b = to_bottle(request, "Network.admin's request");
             py::gil_scoped_release nogil;
             return network::admin(registered(n, port), b);
           },
           py::arg("port"), py::arg("request"),
           "Sends one administrative Bottle ([list] [out], [ver] ...) to `port`; returns the reply.")
      .def("__repr__", [](const NameClient& n) { return "Network(server=" + std::string(py::repr(py::str(n.server().to_string()))) + ")"; });
}

}  // namespace robogene::python
