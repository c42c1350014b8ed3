// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Bottle and Value for Python. Python values convert the way the text form reads them: int ->
// int32 (int64 when it does not fit), float -> float64, str -> string, bytes-like -> blob,
// list/tuple -> nested list. Blobs expose the buffer protocol, so memoryview(value) reads the
// bytes in place.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <limits>
#include <string>

#include "bindings.hpp"
#include "py_support.hpp"
#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

namespace py = pybind11;

namespace robogene::python {
namespace {

Value from_python(const py::handle& obj) {
  if (py::isinstance<Value>(obj)) return obj.cast<Value>();
  if (py::isinstance<Bottle>(obj)) return Value::list(obj.cast<Bottle>());
  if (py::isinstance<py::bool_>(obj)) return Value::vocab(obj.cast<bool>() ? vocab("1") : 0);
  if (py::isinstance<py::int_>(obj)) {
    const auto v = obj.cast<long long>();  // raises OverflowError beyond int64
    if (v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max()) {
      return Value::int32(static_cast<std::int32_t>(v));
    }
    return Value::int64(v);
  }
  if (py::isinstance<py::float_>(obj)) return Value::float64(obj.cast<double>());
  if (py::isinstance<py::str>(obj)) return Value::string(text_from_python(obj));
  if (py::isinstance<py::bytes>(obj) || py::isinstance<py::bytearray>(obj) ||
      py::isinstance<py::memoryview>(obj)) {
    return Value::blob(buffer_bytes(obj));
  }
  if (py::isinstance<py::list>(obj) || py::isinstance<py::tuple>(obj)) {
    return Value::list(bottle_from_sequence(obj));
  }
  throw py::type_error("cannot put a " + std::string(py::str(py::type::handle_of(obj).attr("__name__"))) +
                       " in a Bottle (use int, float, str, bytes, list, Value or Bottle)");
}

}  // namespace

Bottle bottle_from_sequence(const py::handle& seq) {
  Bottle b;
  for (const py::handle item : seq) b.add(from_python(item));
  return b;
}

namespace {

py::object to_python(const Value& v);

py::list bottle_to_python(const Bottle& b) {
  py::list out;
  for (const Value& item : b) out.append(to_python(item));
  return out;
}

py::object to_python(const Value& v) {
  switch (v.type()) {
    case Type::Null: return py::none();
    case Type::Int8:
    case Type::Int16:
    case Type::Int32:
    case Type::Int64: return py::int_(v.as_int64());
    case Type::Float32:
    case Type::Float64: return py::float_(v.as_float64());
    case Type::Vocab: return py::cast(v);  // keep vocabs distinguishable from strings
    case Type::String: return text_to_python(v.as_string());
    case Type::Blob: {
      const auto& b = v.as_blob();
      return py::bytes(reinterpret_cast<const char*>(b.data()), b.size());
    }
    case Type::List: return bottle_to_python(v.as_list());
  }
  return py::none();
}

std::string type_label(const Value& v) { return type_name(v.type()); }

}  // namespace

void bind_bottle(py::module_& m) {
  // Both classes exist before either's methods are bound, so every signature (and the type
  // stub made from them) names Python types, not C++ ones.
  py::class_<Value> value(m, "Value", py::buffer_protocol(), "One item of a Bottle.");
  py::class_<Bottle> bottle(m, "Bottle", "A list of Values: YARP 3's Bottle, in binary and text form.");
  value
      .def(py::init<>())
      .def_static("int8", &Value::int8)
      .def_static("int16", &Value::int16)
      .def_static("int32", &Value::int32)
      .def_static("int64", &Value::int64)
      .def_static("float32", &Value::float32)
      .def_static("float64", &Value::float64)
      .def_static("vocab", [](const py::object& code) {
        if (py::isinstance<py::int_>(code)) return Value::vocab(code.cast<vocab_t>());
        return Value::vocab(text_from_python(code));
      }, py::arg("code"), "A vocab from up to four characters or from its integer code.")
      .def_static("string", [](const py::str& s) { return Value::string(text_from_python(s)); })
      // Any buffer, in C order: strided or reversed views are copied as seen (buffer_bytes).
      .def_static("blob", [](const py::buffer& data) { return Value::blob(buffer_bytes(data)); })
      .def_static("list", [](const py::iterable& items) { return Value::list(bottle_from_sequence(items)); })
      .def_static("from_python", &from_python, "Convert a Python value the way Bottle.add does.")
      .def_property_readonly("type", &type_label, "Type name: int8 ... float64, vocab, string, blob, list, null.")
      .def("is_null", &Value::is_null)
      .def("is_int", &Value::is_int)
      .def("is_float", &Value::is_float)
      .def("is_number", &Value::is_number)
      .def("is_vocab", &Value::is_vocab)
      .def("is_string", &Value::is_string)
      .def("is_blob", &Value::is_blob)
      .def("is_list", &Value::is_list)
      .def("as_int", &Value::as_int64)
      .def("as_float", &Value::as_float64)
      .def("as_vocab", &Value::as_vocab)
      .def("as_vocab_text", [](const Value& v) { return text_to_python(vocab_to_string(v.as_vocab())); })
      .def("as_string", [](const Value& v) { return text_to_python(v.as_string()); })
      .def("as_bytes", [](const Value& v) {
        const auto& b = v.as_blob();
        return py::bytes(reinterpret_cast<const char*>(b.data()), b.size());
      })
      .def("as_list", [](const Value& v) { return v.as_list(); })
      .def("to_python", &to_python, "The plain Python value (vocabs stay Value).")
      .def("to_text", [](const Value& v) { return text_to_python(v.to_text()); })
      .def("__eq__", [](const Value& a, const Value& b) { return a == b; })
      .def("__hash__", [](const Value& v) { return py::hash(text_to_python(v.to_text())); })
      .def("__str__", [](const Value& v) { return text_to_python(v.to_text()); })
      .def("__repr__", [](const Value& v) { return text_to_python("Value(" + type_label(v) + ", " + v.to_text() + ")"); })
      .def_buffer([](Value& v) -> py::buffer_info {
        if (!v.is_blob()) throw py::buffer_error("only a blob Value exposes a buffer, this is " + type_label(v));
        auto& b = v.as_blob();
        return py::buffer_info(b.data(), 1, py::format_descriptor<std::uint8_t>::format(), 1,
                               {static_cast<py::ssize_t>(b.size())}, {1});
      });

  bottle
      .def(py::init<>())
      .def(py::init([](const py::iterable& items) { return bottle_from_sequence(items); }), py::arg("items"))
      .def_static("from_text", [](const py::str& text) { return Bottle::from_text(text_from_python(text)); }, py::arg("text"))
      .def_static("from_bytes", [](const py::buffer& data) {
        const std::vector<std::uint8_t> bytes = buffer_bytes(data);
        return Bottle::from_bytes(bytes.data(), bytes.size());
      }, py::arg("data"))
      .def_static("text_is_complete", [](const py::str& text) { return Bottle::text_is_complete(text_from_python(text)); })
      .def("to_text", [](const Bottle& b) { return text_to_python(b.to_text()); })
      .def("to_bytes", [](const Bottle& b) {
        const auto bytes = b.to_bytes();
        return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
      })
      .def("to_python", &bottle_to_python, "Nested Python lists of plain values (vocabs stay Value).")
      .def("add", [](Bottle& b, const py::handle& v) -> Bottle& { return b.add(from_python(v)); },
           py::return_value_policy::reference_internal, py::arg("value"))
      .def("add_list", &Bottle::add_list, py::return_value_policy::reference_internal)
      .def("clear", &Bottle::clear)
      .def("find", [](const Bottle& b, const std::string& key) { return b.find(key); }, py::arg("key"))
      .def("find_group", [](const Bottle& b, const std::string& key) -> py::object {
        const Bottle* g = b.find_group(key);
        return g ? py::cast(*g) : py::none();
      }, py::arg("key"))
      .def("__len__", &Bottle::size)
      .def("__getitem__", [](const Bottle& b, py::ssize_t i) {
        const auto n = static_cast<py::ssize_t>(b.size());
        if (i < 0) i += n;
        if (i < 0 || i >= n) throw py::index_error("Bottle index " + std::to_string(i) + " out of range (size " + std::to_string(n) + ")");
        return b[static_cast<std::size_t>(i)];
      })
      .def("__iter__", [](const Bottle& b) { return py::make_iterator(b.begin(), b.end()); }, py::keep_alive<0, 1>())
      .def("__eq__", [](const Bottle& a, const Bottle& b) { return a == b; })
      .def("__str__", [](const Bottle& b) { return text_to_python(b.to_text()); })
      .def("__repr__", [](const Bottle& b) {
        // repr escapes the surrogates of non-UTF-8 bytes: the result is plain text.
        return "Bottle.from_text(" + std::string(py::repr(text_to_python(b.to_text()))) + ")";
      });

  bind_float_buffers(bottle);

  m.def("vocab", [](const std::string& s) { return vocab(s); }, py::arg("chars"),
        "The integer code of a vocab of up to four characters.");
  m.def("vocab_to_string", [](vocab_t code) { return text_to_python(vocab_to_string(code)); }, py::arg("code"));
}

}  // namespace robogene::python
