// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// encode_joint_data and decode_joint_data: the C++ codec of YARP 3's jointData (a control board's
// stateExt:o message), the one the network server and remote_controlboard use.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <vector>

#include "bindings.hpp"
#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/joint_data.hpp"

namespace py = pybind11;

namespace robogene::python {
namespace {

using dev::JointData;
using dev::JointDataField;

template <class T>
std::optional<std::vector<T>> if_valid(const JointDataField<T>& f) {
  return f.valid ? std::optional<std::vector<T>>(f.values) : std::nullopt;
}

template <class T>
void field(py::class_<JointData>& c, const char* name, JointDataField<T> JointData::*member, const char* doc) {
  c.def_property_readonly(name, [member](const JointData& d) { return if_valid(d.*member); }, doc);
}

}  // namespace

void bind_joint_data(py::module_& m) {
  py::class_<JointData> c(m, "JointData",
                          "A decoded jointData message (YARP 3's stateExt:o): each field is one value per "
                          "axis, or None when the server flagged it [fail].");
  field(c, "position", &JointData::position, "Joint positions, deg.");
  field(c, "velocity", &JointData::velocity, "Joint speeds, deg/s.");
  field(c, "acceleration", &JointData::acceleration, "Joint accelerations, deg/s^2.");
  field(c, "motor_position", &JointData::motor_position, "Motor positions, deg.");
  field(c, "motor_velocity", &JointData::motor_velocity, "Motor speeds, deg/s.");
  field(c, "motor_acceleration", &JointData::motor_acceleration, "Motor accelerations, deg/s^2.");
  field(c, "torque", &JointData::torque, "Joint torques, N m.");
  field(c, "pwm", &JointData::pwm, "PWM duty cycles.");
  field(c, "current", &JointData::current, "Motor currents.");
  field(c, "control_mode", &JointData::control_mode, "Control modes, as vocab codes (ControlMode values).");
  field(c, "interaction_mode", &JointData::interaction_mode, "Interaction modes, as vocab codes.");
  c.def_property_readonly("axes", [](const JointData& d) { return d.position.values.size(); },
                          "The number of axes (values in every field).");
  c.def("__repr__", [](const JointData& d) {
    return "JointData(axes=" + std::to_string(d.position.values.size()) + ")";
  });

  m.def(
      "encode_joint_data",
      [](dev::DeviceDriver& device) -> std::optional<Bottle> {
        Bottle out;
        bool done = false;
        {
          py::gil_scoped_release nogil;
          done = dev::encode_joint_data(device, out);
        }
        return done ? std::optional<Bottle>(std::move(out)) : std::nullopt;
      },
      py::arg("device"),
      "YARP 3's jointData of `device` (what stateExt:o publishes): what it cannot report is flagged [fail]; "
      "None when it has no IEncoders or cannot tell its axes.");
  m.def("decode_joint_data", &dev::decode_joint_data, py::arg("message"),
        "Reads a jointData message; raises robogene.Error naming the item and the field that is wrong.");
}

}  // namespace robogene::python
