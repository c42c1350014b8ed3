// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <linux/can.h>
#include <linux/can/error.h>

#include <cstdio>
#include <string>
#include <vector>

#include "robogene/can/bus_error.hpp"

namespace robogene::can {

const char* name_of(BusErrorKind k) noexcept {
  switch (k) {
    case BusErrorKind::timeout: return "timeout";
    case BusErrorKind::bus_off: return "bus-off";
    case BusErrorKind::error_passive: return "error-passive";
    case BusErrorKind::error_warning: return "error-warning";
    case BusErrorKind::no_ack: return "no-ack";
    case BusErrorKind::tx_timeout: return "tx-timeout";
    case BusErrorKind::lost_arbitration: return "lost-arbitration";
    case BusErrorKind::protocol: return "protocol-violation";
    case BusErrorKind::transceiver: return "transceiver";
    case BusErrorKind::restarted: return "restarted";
    case BusErrorKind::controller: return "controller";
    case BusErrorKind::io: return "io";
  }
  return "?";
}

namespace {

struct ClassBit {
  std::uint32_t bit;
  const char* name;
};

const ClassBit kClasses[] = {
    {CAN_ERR_TX_TIMEOUT, "tx-timeout"}, {CAN_ERR_LOSTARB, "lost-arbitration"},
    {CAN_ERR_CRTL, "controller"},       {CAN_ERR_PROT, "protocol-violation"},
    {CAN_ERR_TRX, "transceiver"},       {CAN_ERR_ACK, "no-ack"},
    {CAN_ERR_BUSOFF, "bus-off"},        {CAN_ERR_BUSERROR, "bus-error"},
    {CAN_ERR_RESTARTED, "restarted"},   {CAN_ERR_CNT, "error-counters"},
};

const ClassBit kControllerBits[] = {
    {CAN_ERR_CRTL_RX_OVERFLOW, "rx-overflow"}, {CAN_ERR_CRTL_TX_OVERFLOW, "tx-overflow"},
    {CAN_ERR_CRTL_RX_WARNING, "rx-warning"},   {CAN_ERR_CRTL_TX_WARNING, "tx-warning"},
    {CAN_ERR_CRTL_RX_PASSIVE, "rx-passive"},   {CAN_ERR_CRTL_TX_PASSIVE, "tx-passive"},
    {CAN_ERR_CRTL_ACTIVE, "back-to-active"},
};

// The one condition a caller should act on first when several classes are set.
BusErrorKind most_serious(std::uint32_t classes, std::uint8_t controller) {
  if (classes & CAN_ERR_BUSOFF) return BusErrorKind::bus_off;
  if ((classes & CAN_ERR_CRTL) && (controller & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)))
    return BusErrorKind::error_passive;
  if (classes & CAN_ERR_TX_TIMEOUT) return BusErrorKind::tx_timeout;
  if (classes & CAN_ERR_ACK) return BusErrorKind::no_ack;
  if (classes & CAN_ERR_TRX) return BusErrorKind::transceiver;
  if (classes & (CAN_ERR_PROT | CAN_ERR_BUSERROR)) return BusErrorKind::protocol;
  if (classes & CAN_ERR_LOSTARB) return BusErrorKind::lost_arbitration;
  if ((classes & CAN_ERR_CRTL) && (controller & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)))
    return BusErrorKind::error_warning;
  if (classes & CAN_ERR_RESTARTED) return BusErrorKind::restarted;
  return BusErrorKind::controller;
}

}  // namespace

BusError decode_error_frame(const std::string& bus, const ErrorFrame& e) {
  const std::uint32_t classes = e.can_id & CAN_ERR_MASK;
  const std::uint8_t controller = e.data[1];
  const BusErrorKind kind = most_serious(classes, controller);
  std::string detail;
  for (const auto& c : kClasses) {
    if (!(classes & c.bit)) continue;
    if (!detail.empty()) detail += ", ";
    detail += c.name;
    if (c.bit == CAN_ERR_CRTL) {
      std::string sub;
      for (const auto& b : kControllerBits) {
        if (controller & b.bit) sub += (sub.empty() ? "" : " ") + std::string(b.name);
      }
      if (!sub.empty()) detail += " [" + sub + "]";
    }
  }
  char counters[64] = "";
  if (classes & CAN_ERR_CNT) {
    std::snprintf(counters, sizeof counters, "; tx errors %u, rx errors %u", e.data[6], e.data[7]);
  }
  return BusError(kind,
                  bus + ": " + name_of(kind) + " reported by the controller (error frame: " +
                      (detail.empty() ? std::string("no class bits") : detail) + counters + ")",
                  e);
}

ErrorFrame make_error_frame(BusErrorKind kind) {
  ErrorFrame e;
  e.can_id = kErrFlag;
  switch (kind) {
    case BusErrorKind::bus_off: e.can_id |= CAN_ERR_BUSOFF; break;
    case BusErrorKind::error_passive:
      e.can_id |= CAN_ERR_CRTL | CAN_ERR_CNT;
      e.data[1] = CAN_ERR_CRTL_TX_PASSIVE;
      e.data[6] = 128;
      break;
    case BusErrorKind::error_warning:
      e.can_id |= CAN_ERR_CRTL | CAN_ERR_CNT;
      e.data[1] = CAN_ERR_CRTL_TX_WARNING;
      e.data[6] = 96;
      break;
    case BusErrorKind::no_ack: e.can_id |= CAN_ERR_ACK; break;
    case BusErrorKind::tx_timeout: e.can_id |= CAN_ERR_TX_TIMEOUT; break;
    case BusErrorKind::lost_arbitration: e.can_id |= CAN_ERR_LOSTARB; break;
    case BusErrorKind::protocol:
      e.can_id |= CAN_ERR_PROT;
      e.data[2] = CAN_ERR_PROT_STUFF;
      break;
    case BusErrorKind::transceiver:
      e.can_id |= CAN_ERR_TRX;
      e.data[4] = CAN_ERR_TRX_CANH_NO_WIRE;
      break;
    case BusErrorKind::restarted: e.can_id |= CAN_ERR_RESTARTED; break;
    case BusErrorKind::controller:
    case BusErrorKind::timeout:
    case BusErrorKind::io:
      e.can_id |= CAN_ERR_CRTL;
      e.data[1] = CAN_ERR_CRTL_RX_OVERFLOW;
      break;
  }
  return e;
}

}  // namespace robogene::can
