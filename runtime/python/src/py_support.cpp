// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "py_support.hpp"

#include <cmath>
#include <vector>

#include "bindings.hpp"

namespace robogene::python {

namespace {

struct ExitEntry {
  std::weak_ptr<void> owner;
  void (*close)(void*);
};

std::mutex& exit_mutex() {
  static std::mutex m;
  return m;
}

std::vector<ExitEntry>& exit_entries() {
  static auto* entries = new std::vector<ExitEntry>();  // never destroyed: may be used at exit
  return *entries;
}

thread_local const void* serving_owner = nullptr;

bool interpreter_stopping() {
#if PY_VERSION_HEX >= 0x030D0000
  return !Py_IsInitialized() || Py_IsFinalizing();
#else
  return !Py_IsInitialized() || _Py_IsFinalizing();
#endif
}

// This thread's Python thread state, made by PyGILState_Ensure and kept (GIL released) until
// the thread exits; then released the same way, unless the interpreter is already going away.
struct KeptThreadState {
  PyThreadState* state = nullptr;
  ~KeptThreadState() {
    if (state == nullptr || interpreter_stopping()) return;
    PyEval_RestoreThread(state);
    PyGILState_Release(PyGILState_UNLOCKED);
  }
};

thread_local KeptThreadState kept_state;

}  // namespace

CallbackGil::CallbackGil() {
  if (kept_state.state == nullptr) {
    PyGILState_Ensure();  // makes the thread state and takes the GIL
    kept_state.state = PyThreadState_Get();
    return;
  }
  PyEval_RestoreThread(kept_state.state);
}

CallbackGil::~CallbackGil() { PyEval_SaveThread(); }

void close_at_exit(const std::weak_ptr<void>& owner, void (*close)(void*)) {
  std::lock_guard<std::mutex> lock(exit_mutex());
  auto& entries = exit_entries();
  std::vector<ExitEntry> live;
  for (auto& e : entries) {
    if (!e.owner.expired()) live.push_back(std::move(e));
  }
  live.push_back({owner, close});
  entries.swap(live);
}

void close_all_at_exit() {
  std::vector<ExitEntry> entries;
  {
    std::lock_guard<std::mutex> lock(exit_mutex());
    entries.swap(exit_entries());
  }
  for (auto& e : entries) {
    if (auto alive = e.owner.lock()) {
      try {
        e.close(alive.get());
      } catch (const std::exception&) {
        // At exit there is no one left to tell; the next object still gets closed.
      }
    }
  }
}

ServingScope::ServingScope(const void* owner) : previous_(serving_owner) { serving_owner = owner; }
ServingScope::~ServingScope() { serving_owner = previous_; }
bool ServingScope::serving(const void* owner) { return owner != nullptr && serving_owner == owner; }

PyCallable::PyCallable(py::object fn)
    : fn_(new py::object(std::move(fn)), [](py::object* p) {
        py::gil_scoped_acquire gil;
        delete p;
      }) {}

std::string report_callback_error(py::error_already_set& e, const std::string& where) {
  std::string text = std::string(py::str(e.type().attr("__name__"))) + ": " + std::string(py::str(e.value()));
  e.discard_as_unraisable(where.c_str());
  return text;
}

std::optional<net::Millis> to_millis(const std::optional<double>& seconds, const char* what) {
  if (!seconds) return std::nullopt;
  if (std::isnan(*seconds) || *seconds < 0) {
    throw py::value_error(std::string(what) + " must be None or a number of seconds >= 0, got " +
                          std::to_string(*seconds));
  }
  if (std::isinf(*seconds)) return std::nullopt;
  return net::Millis{static_cast<net::Millis::rep>(std::ceil(*seconds * 1000.0))};
}

std::string type_name_of(const py::handle& obj) {
  return py::str(py::type::handle_of(obj).attr("__name__"));
}

Bottle to_bottle(const py::handle& obj, const char* what) {
  if (py::isinstance<Bottle>(obj)) return obj.cast<Bottle>();
  if (py::isinstance<py::list>(obj) || py::isinstance<py::tuple>(obj)) return bottle_from_sequence(obj);
  throw py::type_error(std::string(what) + " must be a Bottle, list or tuple, not " + type_name_of(obj) +
                       (py::isinstance<py::str>(obj) ? " (use Bottle.from_text for the text form)" : ""));
}

PortOptions port_options(double timeout, double connect_timeout, std::size_t max_message_size) {
  PortOptions o;
  const auto send = to_millis(timeout, "timeout");
  const auto connect = to_millis(connect_timeout, "connect_timeout");
  if (!send || send->count() == 0) throw py::value_error("timeout must be a finite number of seconds > 0");
  if (!connect || connect->count() == 0) {
    throw py::value_error("connect_timeout must be a finite number of seconds > 0");
  }
  if (max_message_size == 0) throw py::value_error("max_message_size must be > 0");
  o.send_timeout = *send;
  o.connect_timeout = *connect;
  o.max_message_size = max_message_size;
  return o;
}

py::str text_to_python(const std::string& text) {
  PyObject* s = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "surrogateescape");
  if (!s) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(s);
}

std::string text_from_python(const py::handle& text) {
  if (!PyUnicode_Check(text.ptr())) throw py::type_error("expected a str, not " + type_name_of(text));
  PyObject* b = PyUnicode_AsEncodedString(text.ptr(), "utf-8", "surrogateescape");
  if (!b) throw py::error_already_set();  // a surrogate that stands for no byte (e.g. '\ud800')
  py::bytes bytes = py::reinterpret_steal<py::bytes>(b);
  return std::string(PyBytes_AS_STRING(b), static_cast<std::size_t>(PyBytes_GET_SIZE(b)));
}

std::vector<std::uint8_t> buffer_bytes(const py::handle& buffer) {
  Py_buffer view;
  // Strides and suboffsets requested: the exporter describes its real layout instead of
  // pretending to be contiguous, and PyBuffer_ToContiguous follows it.
  if (PyObject_GetBuffer(buffer.ptr(), &view, PyBUF_FULL_RO) != 0) throw py::error_already_set();
  std::vector<std::uint8_t> out(static_cast<std::size_t>(view.len));
  const int rc = out.empty() ? 0 : PyBuffer_ToContiguous(out.data(), &view, view.len, 'C');
  PyBuffer_Release(&view);
  if (rc != 0) throw py::error_already_set();
  return out;
}

}  // namespace robogene::python
