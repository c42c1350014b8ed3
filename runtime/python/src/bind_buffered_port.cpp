// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// robogene.BufferedPort: a port whose input threads never wait for Python. Messages are kept
// (latest only, or every one up to a bound) until read; or a Python callback is called on the
// input thread, which takes the GIL for it. close() releases the GIL before joining that thread.
#include <pybind11/native_enum.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <variant>

#include "bindings.hpp"
#include "port_common.hpp"
#include "robogene/buffered_port.hpp"

namespace py = pybind11;

namespace robogene::python {
namespace {

using PolicyArg = std::variant<BufferPolicy, std::string>;

BufferPolicy to_policy(const PolicyArg& arg) {
  if (const auto* p = std::get_if<BufferPolicy>(&arg)) return *p;
  const auto& text = std::get<std::string>(arg);
  if (text == "latest" || text == "latest_only") return BufferPolicy::LatestOnly;
  if (text == "strict") return BufferPolicy::Strict;
  throw py::value_error("unknown buffer policy \"" + text + "\" (use \"latest\" or \"strict\")");
}

std::optional<std::pair<Bottle, MessageInfo>> read_buffered(BufferedPort& bp, const std::optional<double>& timeout) {
  if (!bp.port().is_open()) throw Error("cannot read from a BufferedPort that is not open (open it first)");
  MessageInfo info;
  std::optional<Bottle> got;
  if (timeout && *timeout == 0) {
    py::gil_scoped_release nogil;
    got = bp.poll(&info);
  } else {
    wait_interruptibly(
        timeout, [&](net::Millis slice) { return (got = bp.read(slice, &info)).has_value(); },
        [&] { return bp.port().is_open(); });
  }
  if (!got) return std::nullopt;
  return std::make_pair(std::move(*got), std::move(info));
}

void set_callback(Owned<BufferedPort>& o, const std::optional<ReadCallback>& fn) {
  BufferedPort::Callback cb;
  std::shared_ptr<void> keep;
  if (fn) {
    PyCallable call(*fn);
    keep = call.shared();
    const void* owner = &o;
    cb = [call, owner](const Bottle& b, const MessageInfo& info) {
      CallbackGil gil;
      ServingScope serving(owner);
      try {
        call(py::cast(b), py::cast(info));
      } catch (py::error_already_set& e) {
        report_callback_error(e, "robogene.BufferedPort read callback");
      }
    };
  }
  std::shared_ptr<void> previous = std::move(o.callback);  // dropped below, with the GIL
  o.callback = keep;
  py::gil_scoped_release nogil;
  o.obj.set_callback(std::move(cb));
}

}  // namespace

void bind_buffered_port(py::module_& m) {
  py::native_enum<BufferPolicy>(m, "BufferPolicy", "enum.Enum",
                                "What a BufferedPort keeps while nobody reads: the newest message "
                                "only, or every message (up to its capacity, then the oldest goes).")
      .value("LATEST_ONLY", BufferPolicy::LatestOnly)
      .value("STRICT", BufferPolicy::Strict)
      .finalize();

  py::class_<Owned<BufferedPort>, std::shared_ptr<Owned<BufferedPort>>> cls(
      m, "BufferedPort",
      "A port with a receive buffer: input threads never wait for the reader. policy is "
      "BufferPolicy.LATEST_ONLY / 'latest' (a slow reader skips stale data) or BufferPolicy.STRICT "
      "/ 'strict' (every message, up to `capacity`); or on_read(callback) handles each message.");
  cls.def(py::init([](const std::optional<std::string>& name, const PolicyArg& policy, std::size_t capacity,
                      const std::optional<NameClient>& network, const std::optional<Address>& at,
                      double timeout, double connect_timeout, std::size_t max_message_size) {
            if (capacity == 0) throw py::value_error("capacity must be at least 1");
            auto o = make_owned<BufferedPort>(to_policy(policy), capacity,
                                              port_options(timeout, connect_timeout, max_message_size));
            open_if_named(*o, name, network, at);
            return o;
          }),
          py::arg("name") = py::none(), py::kw_only(), py::arg_v("policy", BufferPolicy::LatestOnly, "BufferPolicy.LATEST_ONLY"),
          py::arg("capacity") = 1000, py::arg("network") = py::none(), py::arg("at") = py::none(),
          py::arg("timeout") = 2.0, py::arg("connect_timeout") = 5.0,
          py::arg("max_message_size") = PortOptions{}.max_message_size);
  def_port_common<BufferedPort>(cls, "BufferedPort", false);
  cls.def("prepare", [](Owned<BufferedPort>& o) -> Bottle& { return o.obj.prepare(); },
          py::return_value_policy::reference_internal,
          "The (cleared) Bottle the next write() without argument sends; fill it in place.")
      .def("write",
           [](Owned<BufferedPort>& o, const std::optional<BottleLike>& bottle) {
             if (!bottle) {
               py::gil_scoped_release nogil;
               return o.obj.write();
             }
             BottleArg b(*bottle, "BufferedPort.write");
             py::gil_scoped_release nogil;
             return o.obj.port().write(b.get());
           },
           py::arg("bottle") = py::none(),
           "Sends `bottle`, or the prepared one, to every output; False when no output took it.")
      .def("read",
           [](Owned<BufferedPort>& o, const std::optional<double>& timeout) -> std::optional<Bottle> {
             auto r = read_buffered(o.obj, timeout);
             if (!r) return std::nullopt;
             return std::move(r->first);
           },
           py::arg("timeout") = py::none(),
           "The next buffered message (timeout in seconds, None = wait, 0 = only what is "
           "buffered); None on timeout or close.")
      .def("read_with_info",
           [](Owned<BufferedPort>& o, const std::optional<double>& timeout) { return read_buffered(o.obj, timeout); },
           py::arg("timeout") = py::none(), "As read(), returning (bottle, MessageInfo).")
      .def_property_readonly("pending", [](Owned<BufferedPort>& o) { return o.obj.pending(); },
                             "Messages waiting in the buffer.")
      .def_property_readonly("dropped", [](Owned<BufferedPort>& o) { return o.obj.dropped(); },
                             "Messages thrown away: replaced (latest only) or over capacity (strict).")
      .def("on_read", &set_callback, py::arg("callback"),
           "Calls callback(bottle, info) on the input thread (holding the GIL) for every message "
           "instead of buffering it; None goes back to buffering. An exception in the callback "
           "goes to sys.unraisablehook. Do not close this port from its own callback.");
}

}  // namespace robogene::python
