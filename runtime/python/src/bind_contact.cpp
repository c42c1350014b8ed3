// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The small value types around ports: Contact (where a port lives), Stamp (an envelope),
// MessageInfo (what a reader learns besides the Bottle) and NameConfig (yarp.conf).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "py_support.hpp"
#include "robogene/contact.hpp"
#include "robogene/envelope.hpp"
#include "robogene/name_config.hpp"
#include "robogene/port.hpp"

namespace py = pybind11;

namespace robogene::python {
namespace {

std::string repr_contact(const Contact& c) {
  return "Contact(name=" + std::string(py::repr(py::str(c.name))) + ", carrier=" +
         std::string(py::repr(py::str(c.carrier))) + ", host=" + std::string(py::repr(py::str(c.host))) +
         ", port=" + std::to_string(c.port) + ")";
}

}  // namespace

void bind_contact(py::module_& m) {
  py::class_<Contact>(m, "Contact", "Where a port lives: its name, registered carrier, host and port number.")
      .def(py::init([](std::string name, std::string carrier, std::string host, int port) {
             return Contact{std::move(name), std::move(carrier), std::move(host), port};
           }),
           py::arg("name") = "", py::arg("carrier") = "tcp", py::arg("host") = "", py::arg("port") = 0)
      .def_readwrite("name", &Contact::name)
      .def_readwrite("carrier", &Contact::carrier)
      .def_readwrite("host", &Contact::host)
      .def_readwrite("port", &Contact::port)
      .def_property_readonly("uri", &Contact::uri, "'tcp://127.0.0.1:10003/' as YARP prints it.")
      .def("__eq__", [](const Contact& a, const Contact& b) {
        return a.name == b.name && a.carrier == b.carrier && a.host == b.host && a.port == b.port;
      })
      .def("__hash__", [](const Contact& c) { return py::hash(py::make_tuple(c.name, c.carrier, c.host, c.port)); })
      .def("__repr__", &repr_contact);

  py::class_<Stamp>(m, "Stamp", "A message envelope as YARP's Stamp writes it: sequence number and time.")
      .def(py::init([](std::int32_t sequence, double time) { return Stamp{sequence, time}; }),
           py::arg("sequence") = 0, py::arg("time") = 0.0)
      .def_readwrite("sequence", &Stamp::sequence)
      .def_readwrite("time", &Stamp::time)
      .def("to_text", &Stamp::to_text, "'<sequence> <time>' with the time printed as '%.15g'.")
      .def_static("parse", [](const std::string& text) { return Stamp::parse(text); }, py::arg("text"),
                  "The Stamp in an envelope's text, or None when it is not '<int> <number>'.")
      .def("__eq__", [](const Stamp& a, const Stamp& b) { return a.sequence == b.sequence && a.time == b.time; })
      .def("__repr__", [](const Stamp& s) {
        return "Stamp(sequence=" + std::to_string(s.sequence) + ", time=" + std::string(py::repr(py::float_(s.time))) + ")";
      });

  py::class_<MessageInfo>(m, "MessageInfo", "What a reader learns about a message besides its Bottle.")
      // Names and envelopes come from the peer: any bytes, decoded without raising (text_to_python).
      .def_property_readonly("sender", [](const MessageInfo& i) { return text_to_python(i.from); },
                             "The sending port's name ('anon_rpc' for `yarp rpc`).")
      .def_property_readonly("carrier", [](const MessageInfo& i) { return text_to_python(i.carrier); },
                             "'tcp', 'text', 'udp', ...")
      .def_property_readonly("envelope", [](const MessageInfo& i) { return text_to_python(i.envelope); },
                             "The envelope text ('' when none).")
      .def_readonly("reply_expected", &MessageInfo::reply_expected)
      .def_property_readonly("stamp", [](const MessageInfo& i) { return Stamp::parse(i.envelope); },
                             "The envelope as a Stamp, or None when there is none or it is not one.")
      .def("__repr__", [](const MessageInfo& i) {
        return "MessageInfo(sender=" + std::string(py::repr(text_to_python(i.from))) + ", carrier=" +
               std::string(py::repr(text_to_python(i.carrier))) + ", envelope=" +
               std::string(py::repr(text_to_python(i.envelope))) + ", reply_expected=" +
               (i.reply_expected ? "True" : "False") + ")";
      });

  py::class_<NameConfig>(m, "NameConfig",
                         "Where the name server is, read the YARP 3 way from yarp.conf "
                         "($YARP_CONFIG_HOME, else $XDG_CONFIG_HOME/yarp, else ~/.config/yarp).")
      .def_static("load", &NameConfig::load,
                  "Reads the configuration; raises robogene.Error naming the file when it is "
                  "missing or cannot be understood.")
      .def_static("config_dir", &NameConfig::config_dir)
      .def_readonly("name_space", &NameConfig::name_space)
      .def_property_readonly("host", [](const NameConfig& c) { return c.server.host; })
      .def_property_readonly("port", [](const NameConfig& c) { return c.server.port; })
      .def_readonly("mode", &NameConfig::mode)
      .def_readonly("source", &NameConfig::source, "The file the configuration came from.")
      .def("__repr__", [](const NameConfig& c) {
        return "NameConfig(name_space=" + std::string(py::repr(py::str(c.name_space))) + ", server=" +
               std::string(py::repr(py::str(c.server.to_string()))) + ", source=" +
               std::string(py::repr(py::str(c.source))) + ")";
      });
}

}  // namespace robogene::python
