// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// robogene.RpcClient and robogene.RpcServer. The server's handler is a Python callable run on
// the connection's thread with the GIL; what it returns (Bottle, list, tuple or None) is the
// reply. If it raises, the client gets [fail] "<Type>: <message>" and the exception goes to
// sys.unraisablehook, so one bad request neither kills the connection nor goes unseen.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <variant>

#include "bindings.hpp"
#include "port_common.hpp"
#include "robogene/rpc.hpp"

namespace py = pybind11;

namespace robogene::python {
namespace {

using ServerTarget = std::variant<std::string, Contact>;

void connect_client(Owned<RpcClient>& o, const ServerTarget& server, const std::string& carrier) {
  py::gil_scoped_release nogil;
  if (const auto* name = std::get_if<std::string>(&server)) {
    o.obj.connect(*name, carrier);
  } else {
    Contact c = std::get<Contact>(server);
    if (!carrier.empty()) c.carrier = carrier;
    o.obj.connect(c);
  }
}

Bottle handler_reply(const PyCallable& call, const void* owner, const Bottle& request, const MessageInfo& info) {
  CallbackGil gil;
  ServingScope serving(owner);
  try {
    py::object r = call(py::cast(request), py::cast(info));
    if (r.is_none()) return Bottle{};
    try {
      return to_bottle(r, "an RpcServer handler's reply");
    } catch (const py::builtin_exception& e) {
      e.set_error();
      throw py::error_already_set();
    }
  } catch (py::error_already_set& e) {
    const std::string what = report_callback_error(e, "robogene.RpcServer handler");
    return Bottle{Value::vocab("fail"), Value::string(what)};
  }
}

void serve(Owned<RpcServer>& o, const std::optional<RpcHandler>& handler) {
  std::shared_ptr<void> previous = std::move(o.callback);  // dropped at the end, with the GIL
  if (!handler) {
    o.callback = nullptr;
    py::gil_scoped_release nogil;
    o.obj.port().set_reader(nullptr);
    return;
  }
  PyCallable call(*handler);
  o.callback = call.shared();
  const void* owner = &o;
  py::gil_scoped_release nogil;
  o.obj.serve([call, owner](const Bottle& request, const MessageInfo& info) {
    return handler_reply(call, owner, request, info);
  });
}

}  // namespace

void bind_rpc(py::module_& m) {
  py::class_<Owned<RpcClient>, std::shared_ptr<Owned<RpcClient>>> client(
      m, "RpcClient",
      "Sends requests to one server port and waits for each reply. Without a name it connects "
      "anonymously, as `yarp rpc` does.");
  client.def(py::init([](const std::optional<std::string>& name, const std::optional<ServerTarget>& server,
                         const std::string& carrier, const std::optional<NameClient>& network,
                         const std::optional<Address>& at, double timeout, double connect_timeout,
                         std::size_t max_message_size) {
               auto o = make_owned<RpcClient>(port_options(timeout, connect_timeout, max_message_size));
               open_if_named(*o, name, network, at);
               if (server) connect_client(*o, *server, carrier);
               return o;
             }),
             py::arg("name") = py::none(), py::arg("server") = py::none(), py::kw_only(),
             py::arg("carrier") = "tcp", py::arg("network") = py::none(), py::arg("at") = py::none(),
             py::arg("timeout") = 2.0, py::arg("connect_timeout") = 5.0,
             py::arg("max_message_size") = PortOptions{}.max_message_size,
             "timeout: seconds to wait for each reply (the connection is dropped after it).");
  def_port_common<RpcClient>(client, "RpcClient", true);
  client
      .def("connect", &connect_client, py::arg("server"), py::arg("carrier") = "tcp",
           "Connects to the server port (a name, or a Contact to skip the name server), replacing "
           "any previous one.")
      .def("call",
           [](Owned<RpcClient>& o, const BottleLike& request) {
             BottleArg b(request, "RpcClient.call");
             py::gil_scoped_release nogil;
             return o.obj.call(b.get());
           },
           py::arg("request"),
           "Sends `request` and returns the reply; raises NetworkError naming the server when "
           "not connected or the connection failed.");

  py::class_<Owned<RpcServer>, std::shared_ptr<Owned<RpcServer>>> server(
      m, "RpcServer",
      "Answers requests: with handler(request, info) -> reply on each connection's thread, or "
      "one by one through read() and reply().");
  server.def(py::init([](const std::optional<std::string>& name, const std::optional<RpcHandler>& handler,
                         const std::optional<NameClient>& network, const std::optional<Address>& at,
                         double timeout, double connect_timeout, std::size_t max_message_size) {
               auto o = make_owned<RpcServer>(port_options(timeout, connect_timeout, max_message_size));
               if (handler) serve(*o, handler);  // before opening: no request can miss it
               open_if_named(*o, name, network, at);
               return o;
             }),
             py::arg("name") = py::none(), py::arg("handler") = py::none(), py::kw_only(),
             py::arg("network") = py::none(), py::arg("at") = py::none(), py::arg("timeout") = 2.0,
             py::arg("connect_timeout") = 5.0, py::arg("max_message_size") = PortOptions{}.max_message_size);
  def_port_common<RpcServer>(server, "RpcServer", true);
  server
      .def("serve", &serve, py::arg("handler"),
           "Answers every request with handler(request, info) -> Bottle | list | tuple | None; "
           "None goes back to read()/reply(). Do not close this server from its handler.")
      .def("read",
           [](Owned<RpcServer>& o, const std::optional<double>& timeout) -> std::optional<Bottle> {
             auto r = read_port(o.obj.port(), timeout, true);
             if (!r) return std::nullopt;
             return std::move(r->first);
           },
           py::arg("timeout") = py::none(),
           "The next request (timeout in seconds, None = wait); answer it with reply().")
      .def("read_with_info",
           [](Owned<RpcServer>& o, const std::optional<double>& timeout) { return read_port(o.obj.port(), timeout, true); },
           py::arg("timeout") = py::none(), "As read(), returning (request, MessageInfo).")
      .def("reply",
           [](Owned<RpcServer>& o, const BottleLike& bottle) {
             BottleArg b(bottle, "RpcServer.reply");
             py::gil_scoped_release nogil;
             o.obj.reply(b.get());
           },
           py::arg("reply"), "Answers the request taken by the last read().");
}

}  // namespace robogene::python
