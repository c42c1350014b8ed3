// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/joint_data.hpp"

#include "robogene/dev/generated/icontrolmode.hpp"
#include "robogene/dev/generated/iencoders.hpp"
#include "robogene/dev/generated/itorquecontrol.hpp"

namespace robogene::dev {
namespace {

void add_doubles(Bottle& out, const std::vector<double>& values, std::size_t n, bool valid) {
  Bottle& list = out.add_list();
  for (std::size_t i = 0; i < n; ++i) list.add(Value::float64(valid ? values[i] : 0.0));
  out.add(Value::vocab(vocab(valid ? "ok" : "fail")));
}

void add_ints(Bottle& out, const std::vector<std::int32_t>& values, std::size_t n, bool valid) {
  Bottle& list = out.add_list();
  for (std::size_t i = 0; i < n; ++i) list.add(Value::int32(valid ? values[i] : 0));
  out.add(Value::vocab(vocab(valid ? "ok" : "fail")));
}

}  // namespace

bool encode_joint_data(DeviceDriver& device, Bottle& out) {
  auto* enc = interface_of<IEncoders>(device);
  std::int32_t axes = 0;
  if (!enc || !enc->getAxes(axes) || axes < 0) return false;
  const auto n = static_cast<std::size_t>(axes);
  // A reading is valid only if the device answered with one value per axis.
  auto got = [n](bool ok, const auto& v) { return ok && v.size() == n; };

  std::vector<double> pos, vel, acc, torque;
  const bool pos_ok = got(enc->getEncoders(pos), pos);
  const bool vel_ok = got(enc->getEncoderSpeeds(vel), vel);
  const bool acc_ok = got(enc->getEncoderAccelerations(acc), acc);
  auto* trq = interface_of<ITorqueControl>(device);
  const bool trq_ok = trq && got(trq->getTorques(torque), torque);
  std::vector<ControlMode> modes;
  auto* icm = interface_of<IControlMode>(device);
  const bool modes_ok = icm && got(icm->getControlModes(modes), modes);
  std::vector<std::int32_t> mode_codes;
  for (ControlMode m : modes) mode_codes.push_back(static_cast<std::int32_t>(m));

  out.clear();
  add_doubles(out, pos, n, pos_ok);
  add_doubles(out, vel, n, vel_ok);
  add_doubles(out, acc, n, acc_ok);
  add_doubles(out, {}, n, false);  // motor position: no IMotorEncoders
  add_doubles(out, {}, n, false);  // motor velocity
  add_doubles(out, {}, n, false);  // motor acceleration
  add_doubles(out, torque, n, trq_ok);
  add_doubles(out, {}, n, false);  // PWM duty cycle: no IPWMControl
  add_doubles(out, {}, n, false);  // current: no ICurrentControl
  add_ints(out, mode_codes, n, modes_ok);
  add_ints(out, {}, n, false);  // interaction mode: no IInteractionMode
  return true;
}

}  // namespace robogene::dev
