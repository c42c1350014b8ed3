// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/sim/board_sim.hpp"

#include <cmath>
#include <cstring>
#include <string>

#include "core_params.hpp"
#include "rg_board.h"
#include "rg_boot.h"
#include "rg_joint_encoder.h"
#include "robogene/can/firmware_image.hpp"
#include "robogene/can/sim/sim_flash.hpp"
#include "robogene/error.hpp"
#include "generated/robogene_can_motor_control.h"

namespace robogene::can::sim {

// The core and the hardware it runs on: two motors, their encoders, current sense, the supply,
// the bridges' fault line and the CAN transmit queue.
struct BoardSim::Model {
  rg_board_t core{};
  rg_hal_t hal{};
  std::array<DcMotor, 2> motors;
  std::array<double, 2> motor_counts_per_degree{{1.0, 1.0}};
  std::array<double, 2> duty{{0.0, 0.0}};
  // The bridges as the core last set them, and for how many whole periods each has been on.
  std::array<bool, 2> bridge_on{{false, false}};
  std::array<std::uint32_t, 2> bridge_periods{{0, 0}};
  // The holding brakes: fitted to the motors whose axis has one (the configuration's brake), their
  // gate output as the core last set it. A spring-applied brake releases only while its gate is
  // released and the coil has supply; through reset and in the bootloader the gate's pull-down
  // holds it applied.
  std::array<bool, 2> brake_fitted{{false, false}};
  std::array<bool, 2> brake_gate_released{{false, false}};
  std::vector<BrakeChange> brake_changes;
  // The joint encoders: the raw angle at the joint's 0, the fault simulated, and the zero the board's
  // settings flash keeps (it survives power cycles, as the flash page does).
  std::array<std::uint16_t, 2> magnet{{0, 0}};
  std::array<JointEncoderFault, 2> joint_fault{{JointEncoderFault::none, JointEncoderFault::none}};
  std::array<std::optional<std::uint16_t>, 2> stored_zero;
  // A sensor (or its magnet's board) mounted the other way: it counts down as its joint turns up.
  std::array<bool, 2> joint_reversed{{false, false}};
  std::uint64_t periods = 0;
  rg_board_params_t params{};  // kept for a simulated power-up
  double pwm_full_scale = 1.0;
  double supply_volts = 12.0;
  bool bridge_fault = false;
  std::vector<rg_can_frame_t> sent;
  // The bootloader, its flash and what the board runs; a stage change asked for by the firmware
  // (enter_bootloader, bootloader_start) happens once the frame that asked is handled.
  std::unique_ptr<SimFlash> flash;
  rg_boot_hal_t boot_hal{};
  rg_boot_t boot{};
  rg_image_target_t target{};
  bool in_bootloader = false;
  enum class Switch { none, to_bootloader, to_application } pending = Switch::none;
};

namespace {

using Model = BoardSim::Model;

Model& model_of(void* ctx) { return *static_cast<Model*>(ctx); }

std::uint16_t encoder_raw(void* ctx, unsigned m) {
  const Model& s = model_of(ctx);
  // The motor encoder sees the gear's output, this side of any backlash.
  const double counts = std::round(s.motors[m].output_degrees() * s.motor_counts_per_degree[m]);
  // The timer's 16-bit counter: the core extends it, as on the board.
  return static_cast<std::uint16_t>(static_cast<std::int64_t>(counts) & 0xFFFF);
}

std::int32_t current_ma(void* ctx, unsigned m) {
  return static_cast<std::int32_t>(std::lround(model_of(ctx).motors[m].current_amps() * 1000.0));
}

std::uint32_t supply_mv(void* ctx) {
  return static_cast<std::uint32_t>(std::lround(std::max(0.0, model_of(ctx).supply_volts) * 1000.0));
}

bool bridge_fault(void* ctx) { return model_of(ctx).bridge_fault; }

// The AS5048A facing the joint's magnet: 14 bits a turn, counting up with the joint angle (down when
// mounted reversed). It reads the joint, the far side of any backlash.
std::uint16_t joint_encoder_frame(void* ctx, unsigned axis) {
  const Model& s = model_of(ctx);
  const JointEncoderFault fault = s.joint_fault[axis];
  if (fault == JointEncoderFault::missing) return 0x0000;
  const double joint = s.motors[axis].joint_degrees() * (s.joint_reversed[axis] ? -1.0 : 1.0);
  const long steps = std::lround(joint * 16384.0 / 360.0) + s.magnet[axis];
  const auto raw = static_cast<std::uint16_t>(((steps % 16384) + 16384) % 16384);
  const std::uint16_t frame = rg_as5048a_frame(raw, fault == JointEncoderFault::error_flag);
  return fault == JointEncoderFault::bad_parity ? static_cast<std::uint16_t>(frame ^ 0x0004u) : frame;
}

void save_joint_zero(void* ctx, unsigned axis, std::uint16_t zero) { model_of(ctx).stored_zero[axis] = zero; }

void set_pwm(void* ctx, unsigned m, std::int32_t duty, bool enabled) {
  Model& s = model_of(ctx);
  s.duty[m] = enabled ? duty / s.pwm_full_scale : 0.0;
  s.bridge_on[m] = enabled;
}

// Brings the motor model's brake to what the gate, the supply and the running stage make it, and
// notes a change with the bridge's state at that moment.
void update_brake(Model& s, std::size_t m) {
  if (!s.brake_fitted[m]) return;
  const bool holding = !(s.brake_gate_released[m] && s.supply_volts > 0.0 && !s.in_bootloader);
  if (holding == s.motors[m].braked()) return;
  s.motors[m].set_braked(holding);
  s.brake_changes.push_back(BrakeChange{s.periods, static_cast<int>(m), !holding, s.bridge_on[m], s.bridge_periods[m]});
}

void update_brakes(Model& s) {
  for (std::size_t m = 0; m < 2; ++m) update_brake(s, m);
}

void set_brake(void* ctx, unsigned m, bool released) {
  Model& s = model_of(ctx);
  s.brake_gate_released[m] = released;
  update_brake(s, m);
}

bool can_send(void* ctx, const rg_can_frame_t* f) {
  model_of(ctx).sent.push_back(*f);
  return true;
}

rg_can_frame_t to_core(const Frame& f) {
  rg_can_frame_t c{};
  c.id = static_cast<std::uint16_t>(f.id);
  c.len = f.len;
  std::memcpy(c.data, f.data.data(), f.len);
  return c;
}

Frame from_core(const rg_can_frame_t& c) {
  Frame f;
  f.id = c.id;
  f.len = c.len;
  std::memcpy(f.data.data(), c.data, c.len);
  return f;
}

// The hard stop a homing joint runs into, on its homing side, as the motor model's limit; the
// eye board's version homes both eyes: left = version + vergence / 2, right = version - vergence / 2.
void place_stop(MotorParameters& mp, int direction, double motor_stop_degrees) {
  if (direction == 0) return;
  mp.hard_stops = true;
  mp.stop_min = direction > 0 ? -1e9 : motor_stop_degrees;
  mp.stop_max = direction > 0 ? motor_stop_degrees : 1e9;
}

void enter_bootloader(void* ctx) { model_of(ctx).pending = Model::Switch::to_bootloader; }
void start_application(void* ctx) { model_of(ctx).pending = Model::Switch::to_application; }
bool flash_erase(void* ctx, std::uint32_t page) { return model_of(ctx).flash->erase_page(page); }
bool flash_program(void* ctx, std::uint32_t offset, const std::uint8_t* data) {
  return model_of(ctx).flash->program(offset, data);
}
bool flash_read(void* ctx, std::uint32_t offset, std::uint8_t* out, std::uint32_t len) {
  return model_of(ctx).flash->read(offset, out, len);
}

// The board's reset: the bootloader starts the application when the image checks, else stays.
void reset(Model& s) {
  s.duty = {0.0, 0.0};
  s.bridge_on = {false, false};
  s.bridge_periods = {0, 0};
  s.brake_gate_released = {false, false};
  s.pending = Model::Switch::none;
  s.in_bootloader = !rg_boot_image_valid(&s.boot_hal, &s.target);
  for (std::size_t i = 0; i < 2; ++i) {  // what the firmware's start-up reads from the settings page
    s.params.axes[i].joint_zero_stored = s.stored_zero[i].has_value();
    s.params.axes[i].joint_zero = s.stored_zero[i].value_or(0);
  }
  if (s.in_bootloader) {
    rg_boot_init(&s.boot, s.params.address, &s.target, &s.boot_hal);
  } else {
    rg_board_init(&s.core, &s.params, &s.hal);
  }
  update_brakes(s);
}

void settle(Model& s) {
  const Model::Switch what = s.pending;
  s.pending = Model::Switch::none;
  if (what == Model::Switch::to_bootloader) {
    s.duty = {0.0, 0.0};
    s.bridge_on = {false, false};
    s.brake_gate_released = {false, false};
    s.in_bootloader = true;
    update_brakes(s);
    rg_boot_init(&s.boot, s.params.address, &s.target, &s.boot_hal);
  } else if (what == Model::Switch::to_application) {
    reset(s);  // the firmware resets; its reset path checks the image again
  }
}

}  // namespace

BoardSim::BoardSim(const HeadConfig& head, const BoardConfig& board, const MotorParameters& motor,
                   const std::string& flash_path)
    : model_(std::make_unique<Model>()) {
  Model& s = *model_;
  const rg_board_params_t p = core_params(head, board);
  for (std::size_t i = 0; i < 2; ++i) {
    MotorParameters mp = motor;
    const int j = board.joints[i];
    if (j >= 0) {
      const JointConfig& jc = head.joints[static_cast<std::size_t>(j)];
      mp.gear_ratio = jc.gear_ratio;
      s.motor_counts_per_degree[i] = motor_counts_per_degree(head, board, i);
      if (board.coupling) {
        const HomingConfig& version = head.joints[static_cast<std::size_t>(board.joints[0])].homing;
        const double vergence_stop = board.joints[1] >= 0 ? head.joints[static_cast<std::size_t>(board.joints[1])].homing.stop : 0.0;
        place_stop(mp, version.direction, version.stop + (i == 0 ? 0.5 : -0.5) * vergence_stop);
      } else {
        place_stop(mp, jc.homing.direction, jc.homing.stop);
      }
    }
    s.motors[i] = DcMotor(mp);
    // An arbitrary, fixed magnet angle per board and axis; the board's flash starts calibrated to it.
    s.magnet[i] = static_cast<std::uint16_t>((board.address * 5003 + static_cast<int>(i) * 7919 + 1234) % 16384);
    if (p.axes[i].present && p.axes[i].joint_encoder_bits > 0) s.stored_zero[i] = s.magnet[i];
    // As the core: a brake output only where motor i drives axis i alone.
    s.brake_fitted[i] = !board.coupling && p.axes[i].present && p.axes[i].has_brake;
    s.motors[i].set_braked(s.brake_fitted[i]);
  }
  s.pwm_full_scale = head.pwm_full_scale;
  s.hal = rg_hal_t{&s, encoder_raw, current_ma, supply_mv, bridge_fault, set_pwm, can_send, nullptr, nullptr,
                   enter_bootloader, set_brake, joint_encoder_frame, save_joint_zero};
  s.params = p;
  s.target = rg_image_target_t{ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD, p.board_id,
                               static_cast<std::uint8_t>(board_revision())};
  const std::vector<std::uint8_t> factory = make_stamped_image(p.board_id, s.target.revision, 12 * 1024);
  s.flash = std::make_unique<SimFlash>(kApplicationRegionBytes, factory, flash_path);
  s.boot_hal = rg_boot_hal_t{&s, kApplicationRegionBytes, SimFlash::kPageBytes, flash_erase, flash_program, flash_read,
                             can_send, start_application};
  reset(s);
}

bool BoardSim::in_bootloader() const { return model_->in_bootloader; }

void BoardSim::power_cycle() { reset(*model_); }

void BoardSim::power_up_at(double motor0_degrees, double motor1_degrees) {
  Model& s = *model_;
  s.motors[0].set_joint_degrees(motor0_degrees);
  s.motors[1].set_joint_degrees(motor1_degrees);
  reset(s);
}

BoardSim::~BoardSim() = default;
BoardSim::BoardSim(BoardSim&&) noexcept = default;
BoardSim& BoardSim::operator=(BoardSim&&) noexcept = default;

int BoardSim::address() const { return model_->in_bootloader ? model_->boot.address : model_->core.address; }

std::optional<Envelope> BoardSim::handle(const Envelope& command) {
  Model& s = *model_;
  s.sent.clear();
  const rg_can_frame_t in = to_core(encode(command));
  if (s.in_bootloader) {
    rg_boot_receive(&s.boot, &in);
  } else {
    rg_board_receive(&s.core, &in);
  }
  settle(s);
  if (s.sent.empty()) return std::nullopt;
  return decode(from_core(s.sent.front()));  // a command has at most one reply
}

void BoardSim::step(double /*now*/, double dt, std::vector<Envelope>& out) {
  Model& s = *model_;
  s.sent.clear();
  ++s.periods;
  if (!s.in_bootloader) rg_board_tick(&s.core);  // the bootloader leaves the bridges off
  for (std::size_t m = 0; m < 2; ++m) {
    s.motors[m].step(s.in_bootloader ? 0.0 : s.duty[m], dt);
    s.bridge_periods[m] = s.bridge_on[m] && !s.in_bootloader ? s.bridge_periods[m] + 1 : 0;
  }
  for (const auto& f : s.sent) out.push_back(decode(from_core(f)));
}

double BoardSim::motor_degrees(int m) const { return model_->motors[static_cast<std::size_t>(m)].output_degrees(); }
double BoardSim::joint_degrees(int m) const { return model_->motors[static_cast<std::size_t>(m & 1)].joint_degrees(); }
void BoardSim::set_backlash(int m, double degrees) {
  if (!(degrees >= 0.0) || !std::isfinite(degrees)) {
    throw Error("simulated board " + std::to_string(address()) + " motor " + std::to_string(m & 1) + ": backlash " +
                std::to_string(degrees) + " deg is not a width >= 0");
  }
  model_->motors[static_cast<std::size_t>(m & 1)].set_backlash(degrees);
}
void BoardSim::set_joint_encoder_reversed(int axis, bool reversed) {
  model_->joint_reversed[static_cast<std::size_t>(axis & 1)] = reversed;
}
std::int32_t BoardSim::measured_counts(int axis) const { return model_->core.axes[axis & 1].measured; }
ControlMode BoardSim::mode(int axis) const { return static_cast<ControlMode>(model_->core.axes[axis & 1].mode); }
void BoardSim::set_supply_voltage(double volts) {
  model_->supply_volts = volts;
  update_brakes(*model_);
}
bool BoardSim::has_brake(int m) const { return model_->brake_fitted[static_cast<std::size_t>(m & 1)]; }
bool BoardSim::brake_holding(int m) const { return model_->motors[static_cast<std::size_t>(m & 1)].braked(); }
std::vector<BrakeChange> BoardSim::take_brake_changes() {
  std::vector<BrakeChange> out;
  out.swap(model_->brake_changes);
  return out;
}
void BoardSim::set_bridge_fault(bool asserted) { model_->bridge_fault = asserted; }
std::uint16_t BoardSim::joint_encoder_magnet(int axis) const { return model_->magnet[static_cast<std::size_t>(axis & 1)]; }
void BoardSim::set_joint_encoder_fault(int axis, JointEncoderFault fault) {
  model_->joint_fault[static_cast<std::size_t>(axis & 1)] = fault;
}
void BoardSim::set_stored_joint_zero(int axis, std::optional<std::uint16_t> zero) {
  model_->stored_zero[static_cast<std::size_t>(axis & 1)] = zero;
}
std::optional<std::uint16_t> BoardSim::stored_joint_zero(int axis) const {
  return model_->stored_zero[static_cast<std::size_t>(axis & 1)];
}

}  // namespace robogene::can::sim
