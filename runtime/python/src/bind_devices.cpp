// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The device layer in robogene._core: Property (the Searchable a device's open() reads),
// DeviceDriver, DriverFactory, PolyDriver and the network servers. The generated interfaces are
// bound in generated/bind_interfaces.cpp.
//
// One factory serves both languages: a Python class added with DriverFactory.add is created by
// C++ (PolyDriver, a server's `subdevice`) like a C++ driver, and PolyDriver opens the C++
// drivers (test_motor, fake_grabber, the servers and clients) for Python.
//
// The GIL: every call into the C++ layer releases it (opening a server starts threads that call
// back into Python devices; closing one joins them), and every call back into Python takes it.
// Lifetime: a Python device created by the factory is held by the C++ object that owns it
// (PythonOwnedDevice) until C++ destroys it; a server keeps the device it serves alive.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "dev_support.hpp"
#include "py_support.hpp"
#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/driver_factory.hpp"
#include "robogene/dev/image.hpp"
#include "robogene/dev/image_codec.hpp"
#include "robogene/dev/nws/controlboard_nws.hpp"
#include "robogene/dev/nws/grabber_nws.hpp"
#include "robogene/dev/nws/network_devices.hpp"
#include "robogene/dev/nws/remote_grabber.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/property.hpp"
#include "robogene/dev/simulation_clock.hpp"

namespace py = pybind11;

namespace robogene::python {

using dev::ConfigError;
using dev::DeviceDriver;
using dev::DriverFactory;
using dev::ImageRgb;
using dev::PolyDriver;
using dev::Property;
using dev::Searchable;

py::tuple python_results(const py::handle& result, const char* where, std::size_t count) {
  if (!py::isinstance<py::tuple>(result) || py::len(result) != count) {
    PyErr_SetString(PyExc_TypeError, (std::string(where) + " must return None or a tuple of " +
                                      std::to_string(count) + " values")
                                         .c_str());
    throw py::error_already_set();
  }
  return py::reinterpret_borrow<py::tuple>(result);
}

void report_device_error(py::error_already_set& e, const char* where) {
  report_callback_error(e, std::string("robogene device method ") + where);
}

namespace {

// A configuration value as Python reads it: numbers, str (vocabs as their text), bytes, lists.
py::object config_value(const Value& v) {
  switch (v.type()) {
    case Type::Int32:
    case Type::Int8:
    case Type::Int16:
    case Type::Int64:
      return py::int_(v.as_int64());
    case Type::Float32:
    case Type::Float64:
      return py::float_(v.as_float64());
    case Type::String:
      return text_to_python(v.as_string());
    case Type::Vocab:
      return text_to_python(vocab_to_string(v.as_vocab()));
    case Type::Blob: {
      const auto& b = v.as_blob();
      return py::bytes(reinterpret_cast<const char*>(b.data()), b.size());
    }
    case Type::List: {
      py::list out;
      for (const Value& item : v.as_list()) out.append(config_value(item));
      return std::move(out);
    }
    default:
      return py::none();
  }
}

// A Python value (or Value) as one configuration value.
Value to_config_value(const py::handle& value) {
  if (py::isinstance<Value>(value)) return value.cast<Value>();
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    return Value::list(bottle_from_sequence(value));
  }
  Bottle one = bottle_from_sequence(py::make_tuple(value));
  return one[0];
}

// A Property from a mapping: values as Property.put takes them, nested mappings as groups; each
// entry's origin is "<source>['key']".
void fill_from_mapping(Property& into, const py::handle& data, const std::string& source) {
  const py::object items = data.attr("items")();
  const py::object mapping = py::module_::import("collections.abc").attr("Mapping");
  for (const py::handle item : items) {
    const py::tuple pair = py::reinterpret_borrow<py::tuple>(item);
    if (!py::isinstance<py::str>(pair[0])) {
      throw py::type_error(source + ": key " + py::repr(pair[0]).cast<std::string>() + " is not a str");
    }
    const std::string key = pair[0].cast<std::string>();
    const std::string origin = source + "['" + key + "']";
    if (py::isinstance(pair[1], mapping)) {
      fill_from_mapping(into.add_group(key, source), pair[1], origin);
    } else {
      into.put(key, to_config_value(pair[1]), origin);
    }
  }
}

// The exception a Python device raised in open()/close(), as the C++ exception PolyDriver turns
// into last_error: a ConfigError stays one, anything else is named by its type.
[[noreturn]] void rethrow_device_error(py::error_already_set& e, const char* what) {
  static const py::handle config_error = py::module_::import("robogene._core").attr("ConfigError");
  const std::string message = py::str(e.value());
  if (e.matches(config_error)) throw ConfigError(message);
  const std::string type = py::str(e.type().attr("__name__"));
  throw Error(std::string(what) + " raised " + type + ": " + message);
}

// DeviceDriver implemented in Python.
class PyDeviceDriver : public DeviceDriver {
 public:
  bool open(const Searchable& config) override {
    py::gil_scoped_acquire gil;
    try {
      // A copy: the device may keep its configuration after open() returns.
      const auto* property = dynamic_cast<const Property*>(&config);
      py::object arg = property ? py::cast(Property(*property)) : py::cast(&config, py::return_value_policy::reference);
      return python_value<bool>(python_method(static_cast<const DeviceDriver*>(this), "DeviceDriver", "open")(arg),
                                "DeviceDriver.open");
    } catch (py::error_already_set& e) {
      rethrow_device_error(e, "open()");
    }
  }
  bool close() override {
    py::gil_scoped_acquire gil;
    try {
      return python_value<bool>(python_method(static_cast<const DeviceDriver*>(this), "DeviceDriver", "close")(),
                                "DeviceDriver.close");
    } catch (py::error_already_set& e) {
      rethrow_device_error(e, "close()");
    }
  }
  void* find_interface(std::string_view name) override {
    py::gil_scoped_acquire gil;
    py::handle self = py::detail::get_object_handle(static_cast<const DeviceDriver*>(this),
                                                    py::detail::get_type_info(typeid(DeviceDriver)));
    return self ? python_interface(self, name) : nullptr;
  }
};

// A Python device the C++ factory created: owns the Python object (so it lives as long as the
// C++ owner, a PolyDriver or a server's subdevice) and answers for it.
class PythonOwnedDevice final : public DeviceDriver {
 public:
  PythonOwnedDevice(py::object object, DeviceDriver* device) : object_(std::move(object)), device_(device) {}
  ~PythonOwnedDevice() override {
    py::gil_scoped_acquire gil;
    object_ = py::object();
  }
  bool open(const Searchable& config) override { return device_->open(config); }
  bool close() override { return device_->close(); }
  void* find_interface(std::string_view name) override { return device_->find_interface(name); }
  py::object object() const { return object_; }

 private:
  py::object object_;
  DeviceDriver* device_;
};

// The Python object of a device C++ holds: the Python device itself for one written in Python.
py::object device_object(DeviceDriver* device) {
  if (device == nullptr) return py::none();
  if (auto* owned = dynamic_cast<PythonOwnedDevice*>(device)) return owned->object();
  return py::cast(device, py::return_value_policy::reference);
}

DriverFactory::Creator python_creator(const std::string& name, py::object create) {
  // The factory keeps its creators until the program ends, after the interpreter: the reference
  // is never dropped, since no GIL can be taken then.
  const py::object* call = new py::object(std::move(create));
  return [name, call]() -> std::unique_ptr<DeviceDriver> {
    py::gil_scoped_acquire gil;
    py::object device;
    try {
      device = (*call)();
    } catch (py::error_already_set& e) {
      rethrow_device_error(e, ("the creator of " + name).c_str());
    }
    if (!py::isinstance<DeviceDriver>(device)) {
      throw Error("the creator of '" + name + "' returned " + type_name_of(device) + ", not a DeviceDriver");
    }
    DeviceDriver* raw = device.cast<DeviceDriver*>();
    return std::make_unique<PythonOwnedDevice>(std::move(device), raw);
  };
}

// A new T for Python, deleted with the GIL released and closed at interpreter exit if still
// alive then (its threads would otherwise call into Python devices after the interpreter).
template <class T>
std::shared_ptr<T> make_closed_at_exit() {
  std::shared_ptr<T> p(new T(), ReleaseGilDelete{});
  close_at_exit(p, [](void* object) {
    py::gil_scoped_release nogil;
    static_cast<T*>(object)->close();
  });
  return p;
}

// The classes of the network servers, with the GIL released while they open and close (their
// threads call into the device, which may be Python's).
template <class Server>
void bind_server(py::module_& m, const char* name, const char* doc) {
  py::class_<Server, std::shared_ptr<Server>>(m, name, doc)
      .def(py::init(&make_closed_at_exit<Server>))
      .def(py::init([](DeviceDriver& device, const Searchable& config) {
             std::shared_ptr<Server> s = make_closed_at_exit<Server>();
             py::gil_scoped_release nogil;
             s->open(device, config);
             return s;
           }),
           py::arg("device"), py::arg("config"), py::keep_alive<1, 2>(),
           "A server opened at once: Server(device, config) is Server() then open(device, config).")
      .def(
          "open",
          [](Server& s, DeviceDriver& device, const Searchable& config) {
            py::gil_scoped_release nogil;
            s.open(device, config);
          },
          py::arg("device"), py::arg("config"), py::keep_alive<1, 2>(),
          "Serves `device` as `config` says (name, period, server); the server keeps the device alive.")
      .def("close", &Server::close, py::call_guard<py::gil_scoped_release>(),
           "Stops streaming and closes every port. Idempotent.")
      .def("port_names", &Server::port_names, "The ports this server opened.")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](Server& s, py::args) {
        py::gil_scoped_release nogil;
        s.close();
      });
}

void bind_property(py::module_& m) {
  constexpr std::int32_t kIntMin = std::numeric_limits<std::int32_t>::min();
  constexpr std::int32_t kIntMax = std::numeric_limits<std::int32_t>::max();
  py::class_<Searchable>(m, "Searchable",
                         "Read access to a device configuration. Typed reads raise ConfigError naming "
                         "where a bad value came from.")
      .def("find", [](const Searchable& s, const std::string& key) { return config_value(s.find(key)); },
           py::arg("key"), "The value of `key` (a list when it has several), None when absent.")
      .def("check", [](const Searchable& s, const std::string& key) { return s.check(key); }, py::arg("key"))
      .def("__contains__", [](const Searchable& s, const std::string& key) { return s.check(key); })
      .def(
          "find_group", [](const Searchable& s, const std::string& name) { return s.find_group(name); },
          py::arg("name"), py::return_value_policy::reference_internal, "A nested [group], or None.")
      .def("origin", [](const Searchable& s, const std::string& key) { return s.origin(key); }, py::arg("key"),
           "Where `key` was set (\"motor.ini:12\"), or \"\".")
      .def("source", &Searchable::source, "Where the whole configuration came from.")
      .def(
          "get_string", [](const Searchable& s, const std::string& key, const std::string& fallback) {
            return s.get_string(key, fallback);
          },
          py::arg("key"), py::arg("fallback") = "")
      .def(
          "get_int", [](const Searchable& s, const std::string& key, std::int32_t fallback, std::int32_t low,
                        std::int32_t high) { return s.get_int(key, fallback, low, high); },
          py::arg("key"), py::arg("fallback") = 0, py::arg("low") = kIntMin, py::arg("high") = kIntMax)
      .def(
          "get_float",
          [](const Searchable& s, const std::string& key, double fallback, std::optional<double> low,
             std::optional<double> high) { return s.get_float(key, fallback, low.value_or(-std::numeric_limits<double>::infinity()),
                                                  high.value_or(std::numeric_limits<double>::infinity())); },
          py::arg("key"), py::arg("fallback") = 0.0, py::arg("low") = py::none(), py::arg("high") = py::none(),
          "The float value of `key` (fallback when absent); ConfigError unless it is a number in [low, high].")
      .def(
          "get_bool", [](const Searchable& s, const std::string& key, bool fallback) {
            return s.get_bool(key, fallback);
          },
          py::arg("key"), py::arg("fallback") = false)
      .def(
          "require", [](const Searchable& s, const std::string& key) { return config_value(s.require(key)); },
          py::arg("key"), "The value of `key`; ConfigError when absent.");

  py::class_<Property, Searchable>(m, "Property",
                                   "A device configuration from .ini text, a command line or a bottle; every "
                                   "entry remembers where it came from.")
      .def(py::init<std::string>(), py::arg("source") = "configuration")
      .def_static("from_ini", &Property::from_ini, py::arg("text"), py::arg("source_name"))
      .def_static("from_ini_file", &Property::from_ini_file, py::arg("path"))
      .def_static("from_command_line", &Property::from_command_line, py::arg("args"),
                  "`--key v1 v2 --flag --group::key v` (the first item is not skipped).")
      .def_static("from_bottle", &Property::from_bottle, py::arg("bottle"), py::arg("source_name") = "bottle")
      .def_static(
          "from_dict",
          [](const py::dict& data, const std::string& source_name) {
            Property p(source_name);
            fill_from_mapping(p, data, source_name);
            return p;
          },
          py::arg("data"), py::arg("source_name") = "dict",
          "From a dict: values as put() takes them, nested dicts as groups; origins name the keys.")
      .def(
          "put",
          [](Property& p, const std::string& key, const py::handle& value, std::string origin) {
            p.put(key, to_config_value(value), std::move(origin));
          },
          py::arg("key"), py::arg("value"), py::arg("origin") = "set by program")
      .def(
          "put_values",
          [](Property& p, const std::string& key, const py::handle& values, std::string origin) {
            p.put_values(key, bottle_from_sequence(values), std::move(origin));
          },
          py::arg("key"), py::arg("values"), py::arg("origin"))
      .def(
          "add_group", [](Property& p, const std::string& name, std::string origin) -> Property& {
            return p.add_group(name, std::move(origin));
          },
          py::arg("name"), py::arg("origin") = "set by program", py::return_value_policy::reference_internal)
      .def("merge", &Property::merge, py::arg("other"), "Copies every entry and group of `other` over this one.")
      .def("keys", &Property::keys)
      .def("to_bottle", &Property::to_bottle)
      .def("__repr__", [](const Property& p) { return "Property(" + p.to_bottle().to_text() + ")"; });
}

void set_pixels(ImageRgb& image, const py::handle& data) {
  std::vector<std::uint8_t> bytes = buffer_bytes(data);
  if (bytes.size() != image.pixels.size()) {
    throw py::value_error("an image of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                          " needs " + std::to_string(image.pixels.size()) + " pixel bytes, got " +
                          std::to_string(bytes.size()));
  }
  image.pixels = std::move(bytes);
}

void bind_image(py::module_& m) {
  py::class_<ImageRgb>(m, "ImageRgb", "An RGB image: width x height pixels of 3 bytes, top row first.")
      .def(py::init([](int width, int height, const std::optional<py::object>& pixels) {
             if (width < 0 || height < 0) throw py::value_error("an image cannot have a negative size");
             ImageRgb image;
             image.resize(width, height);
             if (pixels) set_pixels(image, *pixels);
             return image;
           }),
           py::arg("width") = 0, py::arg("height") = 0, py::arg("pixels") = py::none(),
           "A black image, or one of `pixels` (width x height x 3 bytes, top row first).")
      .def("__eq__", [](const ImageRgb& a, const ImageRgb& b) {
             return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
           }, py::is_operator())
      .def("__repr__", [](const ImageRgb& image) {
        return "ImageRgb(" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")";
      })
      .def_readonly("width", &ImageRgb::width)
      .def_readonly("height", &ImageRgb::height)
      .def("resize", &ImageRgb::resize, py::arg("width"), py::arg("height"), "Resizes to black pixels.")
      .def_property(
          "pixels",
          [](const ImageRgb& image) {
            return py::bytes(reinterpret_cast<const char*>(image.pixels.data()), image.pixels.size());
          },
          [](ImageRgb& image, const py::handle& data) { set_pixels(image, data); },
          "The pixels, row by row, 3 bytes (R, G, B) each.")
      .def(
          "pixel",
          [](const ImageRgb& image, int x, int y) {
            if (x < 0 || y < 0 || x >= image.width || y >= image.height) {
              throw py::index_error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside " +
                                    std::to_string(image.width) + "x" + std::to_string(image.height));
            }
            const std::uint8_t* p = image.at(x, y);
            return py::make_tuple(p[0], p[1], p[2]);
          },
          py::arg("x"), py::arg("y"));

  // A malformed image message: a ValueError saying which field is wrong.
  static py::exception<std::invalid_argument> image_error(m, "ImageError", PyExc_ValueError);
  m.def(
      "encode_image", [](const ImageRgb& image, int quantum) { return dev::encode_image(image, quantum); },
      py::arg("image"), py::arg("quantum") = 8,
      "The image as YARP 3 sends it: [mat] [rgb] (3 size quantum|1<<16 width height) {rows, bottom first}.");
  m.def(
      "decode_image",
      [](const Bottle& message) {
        ImageRgb image;
        std::string error;
        if (!dev::decode_image(message, image, error)) {
          PyErr_SetString(image_error.ptr(), error.c_str());
          throw py::error_already_set();
        }
        return image;
      },
      py::arg("message"), "The image of a YARP 3 image message (either row order); ImageError naming the bad field.");
}

void bind_driver_and_factory(py::module_& m) {
  py::class_<DeviceDriver, PyDeviceDriver>(
      m, "DeviceDriver",
      "What every device implements: open(config) and close(). A Python subclass that also derives "
      "from generated interfaces (IEncoders...) is a device C++ can open, view and serve.")
      .def(py::init<>())
      .def(
          "open",
          [](DeviceDriver& d, const Searchable& config) {
            py::gil_scoped_release nogil;
            return d.open(config);
          },
          py::arg("config"), "Starts the device; False (or ConfigError naming the bad key) when it cannot.")
      .def("close", &DeviceDriver::close, py::call_guard<py::gil_scoped_release>(), "Releases what open() took.");

  py::class_<dev::INetworkWrapper>(m, "INetworkWrapper", "A server device: it lists the ports it opened.")
      .def("port_names", &dev::INetworkWrapper::port_names);

  py::class_<dev::ISimulationClock>(m, "ISimulationClock",
                                    "The time of a simulated device: with `clock manual` it only moves on advance().")
      .def("now", &dev::ISimulationClock::now, py::call_guard<py::gil_scoped_release>(),
           "Seconds since the device opened.")
      .def("advance", &dev::ISimulationClock::advance, py::arg("seconds"), py::call_guard<py::gil_scoped_release>(),
           "Moves a manual clock on; False with a wall clock or a negative step.");

  py::class_<DriverFactory>(m, "DriverFactory",
                            "The devices by name, C++ and Python alike (DriverFactory.instance()).")
      .def_static("instance", &DriverFactory::instance, py::return_value_policy::reference)
      .def(
          "add",
          [](DriverFactory& f, const std::string& name, const std::string& description,
             py::typing::Callable<DeviceDriver()> create) {
            if (!py::isinstance<py::function>(create) && !PyCallable_Check(create.ptr())) {
              throw py::type_error("DriverFactory.add: `create` must be callable");
            }
            f.add(name, description, python_creator(name, create));
          },
          py::arg("name"), py::arg("description"), py::arg("create"),
          "Adds a Python device: `create()` returns a new DeviceDriver (usually the class itself).")
      .def("has", &DriverFactory::has, py::arg("name"))
      .def("names",
           [](const DriverFactory& f) {
             std::vector<std::string> out;
             for (const auto& e : f.entries()) out.push_back(e.name);
             return out;
           })
      .def("descriptions",
           [](const DriverFactory& f) {
             std::vector<std::pair<std::string, std::string>> out;
             for (const auto& e : f.entries()) out.emplace_back(e.name, e.description);
             return out;
           })
      .def(
          "create",
          [](const DriverFactory& f, const std::string& name) -> py::object {
            std::unique_ptr<DeviceDriver> device;
            {
              py::gil_scoped_release nogil;
              device = f.create(name);
            }
            if (auto* owned = dynamic_cast<PythonOwnedDevice*>(device.get())) return owned->object();
            return py::cast(std::move(device));
          },
          py::arg("name"), "A new, unopened device of the driver `name`.");

  m.def(
      "wrapper_for", [](DeviceDriver& device) { return dev::wrapper_for(device); }, py::arg("device"),
      "The server device that fits `device` (controlBoard_nws_yarp, frameGrabber_nws_yarp) or \"\".");
}

// The views a PolyDriver handed out of a C++ device, as weak references (dynamic attribute).
py::list views_of(const py::object& poly) {
  if (!py::hasattr(poly, "_views")) poly.attr("_views") = py::list();
  return poly.attr("_views");
}

// Closes the device. One a view still refers to is kept (closed) until the PolyDriver goes, so a
// view used after close() reaches a closed device, never freed memory.
bool close_keeping_viewed(const py::object& self) {
  std::unique_ptr<DeviceDriver, ReleaseGilDelete> device(self.cast<PolyDriver&>().release().release());
  if (!device) return true;
  bool ok = false;
  {
    py::gil_scoped_release nogil;
    ok = device->close();
  }
  bool viewed = false;
  for (const py::handle ref : views_of(self)) viewed = viewed || !ref().is_none();
  self.attr("_views") = py::list();
  if (viewed) {
    if (!py::hasattr(self, "_closed_devices")) self.attr("_closed_devices") = py::list();
    self.attr("_closed_devices").cast<py::list>().append(
        py::capsule(device.release(), [](void* closed) { ReleaseGilDelete{}(static_cast<DeviceDriver*>(closed)); }));
  }
  return ok;
}

void bind_poly_driver(py::module_& m) {
  py::class_<PolyDriver, std::shared_ptr<PolyDriver>>(
      m, "PolyDriver", "Opens one device through the factory and hands out its interfaces with view().",
      py::dynamic_attr())
      .def(py::init([](std::optional<std::variant<std::string, const Searchable*>> config) {
             std::shared_ptr<PolyDriver> p = make_closed_at_exit<PolyDriver>();
             if (config) {
               py::gil_scoped_release nogil;
               if (const auto* name = std::get_if<std::string>(&*config)) {
                 p->open(*name);
               } else {
                 p->open(*std::get<const Searchable*>(*config));
               }
             }
             return p;
           }),
           py::arg("config") = py::none())
      .def(
          "open",
          [](const py::object& self, const std::variant<std::string, const Searchable*>& config) {
            close_keeping_viewed(self);  // the device open() would close, kept if still viewed
            PolyDriver& p = self.cast<PolyDriver&>();
            py::gil_scoped_release nogil;
            if (const auto* name = std::get_if<std::string>(&config)) return p.open(*name);
            return p.open(*std::get<const Searchable*>(config));
          },
          py::arg("config"),
          "Opens the driver named `config`, or named by the `device` key of a Property; False (see "
          "last_error) when it cannot.")
      .def("close", &close_keeping_viewed,
           "Closes the device. Its views answer as a closed device does (a C++ device they still refer to "
           "is kept until this PolyDriver goes).")
      .def("is_valid", &PolyDriver::is_valid)
      .def_property_readonly("last_error", &PolyDriver::last_error, "Why the last open() failed (\"\" after a success).")
      .def(
          "view",
          [](const py::object& self, const py::type& asked) -> py::object {
            // robogene.dev's DeviceDriver, the base of Python devices (core.py), stands for the
            // bound one: it says so in its own __dict__ (its subclasses, the devices, do not).
            const py::type interface = asked.attr("__dict__").contains("_views_as_device_driver")
                                           ? py::type::of<DeviceDriver>()
                                           : asked;
            DeviceDriver* device = self.cast<const PolyDriver&>().device();
            if (device == nullptr) return py::none();
            // A Python device is its own view, and needs no PolyDriver to live (a keep-alive
            // there would be a cycle through C++ that the collector cannot see).
            if (dynamic_cast<PythonOwnedDevice*>(device)) {
              return interface.is(py::type::of<DeviceDriver>()) || py::isinstance(device_object(device), interface)
                         ? device_object(device)
                         : py::none();
            }
            py::object view;
            if (interface.is(py::type::of<DeviceDriver>())) {
              view = device_object(device);
            } else if (interface.is(py::type::of<dev::INetworkWrapper>())) {
              auto* wrapper = dynamic_cast<dev::INetworkWrapper*>(device);
              view = wrapper ? py::cast(wrapper, py::return_value_policy::reference) : py::none();
            } else if (interface.is(py::type::of<dev::ISimulationClock>())) {
              auto* clock = dynamic_cast<dev::ISimulationClock*>(device);
              view = clock ? py::cast(clock, py::return_value_policy::reference) : py::none();
            } else if (interface.is(py::type::of<dev::RemoteGrabber>())) {
              auto* remote = dynamic_cast<dev::RemoteGrabber*>(device);
              view = remote ? py::cast(remote, py::return_value_policy::reference) : py::none();
            } else {
              view = view_interface(*device, interface);
            }
            if (!view.is_none()) {
              py::detail::keep_alive_impl(view, self);  // the C++ device lives in self
              views_of(self).append(py::module_::import("weakref").attr("ref")(view));
            }
            return view;
          },
          py::arg("interface"),
          "The device as `interface` (IEncoders, IPositionControl, DeviceDriver...) or None when it does not "
          "implement it. Valid until close().")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](const py::object& self, py::args) { close_keeping_viewed(self); });
}

}  // namespace

void bind_devices(py::module_& m) {
  bind_property(m);
  bind_image(m);
  bind_generated_types(m);
  bind_driver_and_factory(m);
  bind_generated_interfaces(m);
  bind_poly_driver(m);
  bind_server<dev::ControlboardNws>(
      m, "ControlboardNws",
      "The control board's network server: <name>/rpc:i, command:i, state:o, stateExt:o (YARP 3's).");
  bind_server<dev::GrabberNws>(m, "GrabberNws", "The camera's network server: <name>/rpc and <name> (the images).");
}

}  // namespace robogene::python
