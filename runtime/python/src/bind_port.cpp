// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// robogene.Port: robogene::Port for Python. Reads wait in short slices with the GIL released
// (Ctrl-C and close() from another thread end them); writes release the GIL for their whole
// duration, which the port's send timeout bounds.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "port_common.hpp"

namespace py = pybind11;

namespace robogene::python {

std::optional<std::pair<Bottle, MessageInfo>> read_port(Port& p, const std::optional<double>& timeout,
                                                        bool will_reply) {
  if (!p.is_open()) throw Error("cannot read from a port that is not open (open it first)");
  Bottle b;
  MessageInfo info;
  const bool got = wait_interruptibly(
      timeout, [&](net::Millis slice) { return p.read(b, will_reply, slice, &info); },
      [&] { return p.is_open(); });
  if (!got) return std::nullopt;
  return std::make_pair(std::move(b), std::move(info));
}

void bind_port(py::module_& m) {
  py::class_<Owned<Port>, std::shared_ptr<Owned<Port>>> cls(
      m, "Port",
      "A named port (YARP 3 wire compatible): any number of inputs and outputs, read and reply, "
      "write and wait for a reply. `Port('/x')` opens at once; `with Port('/x') as p:` closes "
      "(and unregisters) at the end.");
  cls.def(py::init([](const std::optional<std::string>& name, const std::optional<NameClient>& network,
                      const std::optional<Address>& at, double timeout, double connect_timeout,
                      std::size_t max_message_size) {
            auto o = make_owned<Port>(port_options(timeout, connect_timeout, max_message_size));
            open_if_named(*o, name, network, at);
            return o;
          }),
          py::arg("name") = py::none(), py::kw_only(), py::arg("network") = py::none(),
          py::arg("at") = py::none(), py::arg("timeout") = 2.0, py::arg("connect_timeout") = 5.0,
          py::arg("max_message_size") = PortOptions{}.max_message_size,
          "timeout: seconds a write waits for each reader's ack or reply before dropping that "
          "connection; connect_timeout: seconds to connect; max_message_size: larger incoming "
          "messages are refused.");
  def_port_common<Port>(cls, "Port", true);
  cls.def("write",
          [](Owned<Port>& o, const BottleLike& bottle) {
            BottleArg b(bottle, "Port.write");
            py::gil_scoped_release nogil;
            return o.obj.write(b.get());
          },
          py::arg("bottle"), "Sends to every output; False when there is none that took it.")
      .def("write_with_reply",
           [](Owned<Port>& o, const BottleLike& bottle) -> std::optional<Bottle> {
             BottleArg b(bottle, "Port.write_with_reply");
             Bottle reply;
             py::gil_scoped_release nogil;
             if (!o.obj.write(b.get(), reply)) return std::nullopt;
             return reply;
           },
           py::arg("bottle"),
           "Sends to the first output and waits for its reply; None when there is no output or "
           "the connection failed (it is then dropped).")
      .def("read",
           [](Owned<Port>& o, const std::optional<double>& timeout, bool will_reply) -> std::optional<Bottle> {
             auto r = read_port(o.obj, timeout, will_reply);
             if (!r) return std::nullopt;
             return std::move(r->first);
           },
           py::arg("timeout") = py::none(), py::kw_only(), py::arg("will_reply") = false,
           "Waits for a message (timeout in seconds, None = no limit, 0 = only what is waiting); "
           "None on timeout or close. With will_reply=True the sender gets what reply() is given.")
      .def("read_with_info", [](Owned<Port>& o, const std::optional<double>& timeout,
                                bool will_reply) { return read_port(o.obj, timeout, will_reply); },
           py::arg("timeout") = py::none(), py::kw_only(), py::arg("will_reply") = false,
           "As read(), returning (bottle, MessageInfo) with the sender, carrier and envelope.")
      .def("reply",
           [](Owned<Port>& o, const BottleLike& bottle) {
             BottleArg b(bottle, "Port.reply");
             py::gil_scoped_release nogil;
             o.obj.reply(b.get());
           },
           py::arg("bottle"), "Answers the message taken by the last read(will_reply=True).");
}

}  // namespace robogene::python
