// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What every port binding needs to be safe with the GIL:
// * Owned<T>: the object Python holds. Its holder's deleter releases the GIL while the C++ object
//   closes (closing joins input threads, which may be waiting for the GIL to run a callback).
// * PyCallable: a Python callable stored in a C++ std::function. Copies never touch reference
//   counts; the last copy takes the GIL to drop the object, whatever thread it is on.
// * wait_interruptibly: a blocking wait cut into short slices with the GIL released, checking
//   for signals (Ctrl-C) and for the port closing between slices.
// * Every Owned object is remembered (weakly) and closed by an atexit hook, before the
//   interpreter stops granting the GIL to the threads that would run callbacks.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/typing.h>

#include <atomic>
#include <cstdint>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "robogene/bottle.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "robogene/port.hpp"

namespace robogene::python {

namespace py = pybind11;

template <class T>
struct Owned {
  template <class... A>
  explicit Owned(A&&... args) : obj(std::forward<A>(args)...) {}
  // The Python callback installed in `obj`, also held here so that replacing or destroying the
  // callback inside `obj` (under its locks, maybe without the GIL) never drops the last
  // reference; declared before `obj`, so it outlives it.
  std::shared_ptr<void> callback;
  T obj;
  std::mutex close_mutex;  // close() from two Python threads at once must not join twice
  std::atomic<bool> closed{false};
};

// Registers `close` to run at interpreter exit for as long as `owner` lives.
void close_at_exit(const std::weak_ptr<void>& owner, void (*close)(void* owner));
// The atexit hook (installed by module.cpp).
void close_all_at_exit();

// Deletes with the GIL released when the current thread holds it.
struct ReleaseGilDelete {
  template <class T>
  void operator()(T* p) const {
    if (PyGILState_Check()) {
      py::gil_scoped_release nogil;
      delete p;
    } else {
      delete p;
    }
  }
};

// Holds the GIL on a runtime thread (a port's input thread) while a Python callback runs. The
// thread's Python thread state is made on its first callback and kept until the thread ends,
// instead of being made and destroyed around every message as a plain PyGILState_Ensure pair
// (or py::gil_scoped_acquire) would: that pair costs more than a whole local round trip.
class CallbackGil {
 public:
  CallbackGil();
  ~CallbackGil();
  CallbackGil(const CallbackGil&) = delete;
  CallbackGil& operator=(const CallbackGil&) = delete;
};

// Marks the current thread as running a callback of `owner` (so close() from it can refuse
// instead of joining its own thread).
class ServingScope {
 public:
  explicit ServingScope(const void* owner);
  ~ServingScope();
  ServingScope(const ServingScope&) = delete;
  ServingScope& operator=(const ServingScope&) = delete;
  static bool serving(const void* owner);

 private:
  const void* previous_;
};

// Closes `o` (T::close) with the GIL released; refuses from the object's own callback.
template <class T>
void close_owned(Owned<T>& o, const std::string& what) {
  if (ServingScope::serving(&o)) {
    throw py::value_error("cannot close " + what +
                          " from its own callback (its thread would have to join itself); "
                          "close it from another thread");
  }
  py::gil_scoped_release nogil;
  std::lock_guard<std::mutex> lock(o.close_mutex);
  o.obj.close();
  o.closed = true;
}

template <class T>
void close_owned_at_exit(void* owner) {
  close_owned(*static_cast<Owned<T>*>(owner), "at exit");
}

// A new Owned<T> for Python, closed at interpreter exit if still alive then.
template <class T, class... A>
std::shared_ptr<Owned<T>> make_owned(A&&... args) {
  std::shared_ptr<Owned<T>> p(new Owned<T>(std::forward<A>(args)...), ReleaseGilDelete{});
  close_at_exit(p, &close_owned_at_exit<T>);
  return p;
}

// What Python code may pass where a Bottle is written (converted by to_bottle).
using BottleLike = py::typing::Union<Bottle, py::list, py::tuple>;

// What Python code may pass as a read callback / RPC handler (the types show in the stub).
using ReadCallback = py::typing::Callable<py::object(const Bottle&, const MessageInfo&)>;
using RpcHandler = py::typing::Callable<py::typing::Union<Bottle, py::list, py::tuple, py::none>(
    const Bottle&, const MessageInfo&)>;

class PyCallable {
 public:
  explicit PyCallable(py::object fn);
  // Call with the GIL held.
  template <class... A>
  py::object operator()(A&&... args) const {
    return (*fn_)(std::forward<A>(args)...);
  }
  const py::object& get() const { return *fn_; }
  const std::shared_ptr<py::object>& shared() const { return fn_; }

 private:
  std::shared_ptr<py::object> fn_;
};

// Reports the Python exception a callback raised through sys.unraisablehook (it has no caller
// to raise to) and returns "<Type>: <message>". Call with the GIL held.
std::string report_callback_error(py::error_already_set& e, const std::string& where);

// Seconds (None = no limit) into the runtime's milliseconds, rejecting NaN and negatives.
std::optional<net::Millis> to_millis(const std::optional<double>& seconds, const char* what);

// Runs attempt(slice) (GIL released) until it returns true, the timeout passes, `still_open()`
// turns false, or a signal handler raises (then error_already_set is thrown). A timeout of zero
// tries once for about a millisecond. Returns whether an attempt succeeded.
template <class Attempt, class StillOpen>
bool wait_interruptibly(const std::optional<double>& timeout_s, Attempt&& attempt, StillOpen&& still_open) {
  using Clock = std::chrono::steady_clock;
  constexpr net::Millis kSlice{100};
  const auto limit = to_millis(timeout_s, "timeout");
  const auto deadline = limit ? Clock::now() + *limit : Clock::time_point::max();
  for (;;) {
    net::Millis slice = kSlice;
    if (limit) {
      const auto left = std::chrono::duration_cast<net::Millis>(deadline - Clock::now());
      slice = std::max(net::Millis{1}, std::min(kSlice, left));
    }
    bool done;
    {
      py::gil_scoped_release nogil;
      done = attempt(slice);
    }
    if (done) return true;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!still_open() || (limit && Clock::now() >= deadline)) return false;
  }
}

// The name of an object's type, for messages ("str", "int", ...).
std::string type_name_of(const py::handle& obj);

// A Bottle from what Python code may pass where a Bottle is expected (Bottle, list, tuple).
Bottle to_bottle(const py::handle& obj, const char* what);

// PortOptions from the keyword arguments every port class takes.
PortOptions port_options(double timeout, double connect_timeout, std::size_t max_message_size);

// Text that came from the network as a Python str. Bytes that are not UTF-8 become lone
// surrogates (the "surrogateescape" handler, as os.fsdecode does): never an exception, and
// text_from_python gives the same bytes back.
py::str text_to_python(const std::string& text);
// A str as UTF-8 bytes, lone surrogates from text_to_python turned back into their bytes.
std::string text_from_python(const py::handle& text);
// The bytes of any buffer (bytes, bytearray, memoryview of any shape, stride or order) in C
// order: reversed or strided views are copied item by item, never read past their ends.
std::vector<std::uint8_t> buffer_bytes(const py::handle& buffer);

}  // namespace robogene::python
