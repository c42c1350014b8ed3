// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The methods Port, BufferedPort, RpcClient and RpcServer share in Python: opening (with the
// name server from yarp.conf, a given Network, or at an address without one), closing, context
// management, connections and envelopes. Each is defined once here over the underlying Port.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "py_support.hpp"
#include "robogene/contact.hpp"
#include "robogene/envelope.hpp"
#include "robogene/error.hpp"
#include "robogene/name_client.hpp"
#include "robogene/port.hpp"

namespace robogene::python {

using Address = std::pair<std::string, int>;

inline Port& port_of(Port& p) { return p; }
template <class T>
Port& port_of(T& obj) {
  return obj.port();
}

// Name lookups for connections go to `names`, or to the yarp.conf name server when none was
// given (read at lookup time, so an unopened port that never connects needs no yarp.conf).
inline void resolve_with(Port& p, std::optional<NameClient> names) {
  if (names) {
    p.set_resolver([names](const std::string& name) mutable { return names->query(name); });
  } else {
    p.set_resolver([](const std::string& name) { return NameClient::from_config().query(name); });
  }
}

inline std::string envelope_text(const py::handle& envelope) {
  if (envelope.is_none()) return "";
  if (py::isinstance<Stamp>(envelope)) return envelope.cast<Stamp>().to_text();
  if (py::isinstance<py::str>(envelope)) return envelope.cast<std::string>();
  throw py::type_error("an envelope is a Stamp, a str or None, not " + type_name_of(envelope));
}

// A Bottle argument without copying when it already is one (the caller keeps it alive).
class BottleArg {
 public:
  BottleArg(const py::handle& obj, const char* what) {
    if (py::isinstance<Bottle>(obj)) {
      ptr_ = &obj.cast<const Bottle&>();
    } else {
      storage_ = to_bottle(obj, what);
      ptr_ = &storage_;
    }
  }
  const Bottle& get() const { return *ptr_; }

 private:
  Bottle storage_;
  const Bottle* ptr_ = nullptr;
};

template <class T>
void open_owned(Owned<T>& o, const std::string& name, const std::optional<NameClient>& network,
                const std::optional<Address>& at) {
  if (network && at) throw py::value_error("open " + name + ": give either network= or at=, not both");
  Port& p = port_of(o.obj);
  py::gil_scoped_release nogil;
  if (at) {
    p.open_at(name, {at->first, at->second});
  } else if (network) {
    resolve_with(p, network);
    p.open(name, *network);
  } else {
    p.open(name);
  }
}

template <class T>
std::string describe_owned(Owned<T>& o, const char* kind) {
  Port& p = port_of(o.obj);
  if (!p.is_open()) return std::string("<robogene.") + kind + " (not open)>";
  return std::string("<robogene.") + kind + " " + p.name() + " at " + p.contact().uri() + ">";
}

// Adds the shared methods to `cls`. `reopen` says whether a closed object may be opened again.
template <class T, class Cls>
void def_port_common(Cls& cls, const char* kind, bool reopen) {
  cls.def("open",
          [kind, reopen](Owned<T>& o, const std::string& name, const std::optional<NameClient>& network,
                         const std::optional<Address>& at) {
            if (!reopen && o.closed) {
              throw py::value_error(std::string("a closed ") + kind + " cannot be opened again; make a new one");
            }
            open_owned(o, name, network, at);
          },
          py::arg("name"), py::kw_only(), py::arg("network") = py::none(), py::arg("at") = py::none(),
          "Opens and registers `name` with the name server of `network` (default: yarp.conf), "
          "or listens at `at` = (host, port) without any name server. Raises robogene.Error / "
          "NetworkError naming the port and the server.")
      .def("close", [kind](Owned<T>& o) { close_owned(o, std::string(kind) + " " + port_of(o.obj).name()); },
           "Unregisters, tells every peer, and joins the port's threads. Idempotent.")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [kind](Owned<T>& o, const py::object&, const py::object&, const py::object&) {
        close_owned(o, std::string(kind) + " " + port_of(o.obj).name());
      })
      .def_property_readonly("name", [](Owned<T>& o) { return port_of(o.obj).name(); })
      .def_property_readonly("is_open", [](Owned<T>& o) { return port_of(o.obj).is_open(); })
      .def_property_readonly("contact", [](Owned<T>& o) { return port_of(o.obj).contact(); },
                             "Where the port listens (meaningful once open).")
      .def("add_output",
           [](Owned<T>& o, const std::variant<std::string, Contact>& target, const std::string& carrier) {
             Port& p = port_of(o.obj);
             py::gil_scoped_release nogil;
             if (const auto* name = std::get_if<std::string>(&target)) {
               p.add_output(*name, carrier);
             } else {
               Contact c = std::get<Contact>(target);
               if (!carrier.empty()) c.carrier = carrier;
               p.add_output(c);
             }
           },
           py::arg("target"), py::arg("carrier") = "",
           "Sends this port's output to `target`: a name ('/r' or 'tcp://r', looked up with the "
           "name server) or a Contact (used as it is); `carrier` overrides.")
      .def("remove_output",
           [](Owned<T>& o, const std::string& target) {
             Port& p = port_of(o.obj);
             py::gil_scoped_release nogil;
             return p.remove_output(target);
           },
           py::arg("target"))
      .def("remove_input",
           [](Owned<T>& o, const std::string& source) {
             Port& p = port_of(o.obj);
             py::gil_scoped_release nogil;
             return p.remove_input(source);
           },
           py::arg("source"))
      .def_property_readonly("outputs", [](Owned<T>& o) { return port_of(o.obj).output_names(); },
                             "Names of the ports this one sends to.")
      .def_property_readonly("inputs", [](Owned<T>& o) { return port_of(o.obj).input_names(); },
                             "Names of the ports sending to this one.")
      .def("set_envelope",
           [](Owned<T>& o, const py::object& envelope) { port_of(o.obj).set_envelope(envelope_text(envelope)); },
           py::arg("envelope"),
           "Attaches a Stamp (or raw envelope text) to every later write; None removes it.")
      .def("set_property",
           [](Owned<T>& o, const std::string& key, const std::string& value) {
             port_of(o.obj).set_property(key, Value(value));
           },
           py::arg("key"), py::arg("value"),
           "Sets a user-defined property of the port, which any peer reads with the admin message "
           "[prop] [get] key (as [prop] [set] key value would set it).")
      .def("__repr__", [kind](Owned<T>& o) { return describe_owned(o, kind); });
}

// Port.read for every class built on a Port (bind_port.cpp): (bottle, info), or nullopt on
// timeout or close.
std::optional<std::pair<Bottle, MessageInfo>> read_port(Port& p, const std::optional<double>& timeout,
                                                        bool will_reply);

// The keyword arguments every constructor takes, applied after construction.
template <class T>
void open_if_named(Owned<T>& o, const std::optional<std::string>& name, const std::optional<NameClient>& network,
                   const std::optional<Address>& at) {
  resolve_with(port_of(o.obj), network);
  if (name) open_owned(o, *name, network, at);
  else if (at) throw py::value_error("at= needs a port name");
}

}  // namespace robogene::python
