// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <linux/can.h>
#include <linux/can/error.h>

#include <gtest/gtest.h>

#include "robogene/can/bus_error.hpp"

namespace robogene::can {
namespace {

TEST(CanErrorFrame, EveryKindRoundTripsThroughItsErrorFrame) {
  for (BusErrorKind k : {BusErrorKind::bus_off, BusErrorKind::error_passive, BusErrorKind::error_warning,
                         BusErrorKind::no_ack, BusErrorKind::tx_timeout, BusErrorKind::lost_arbitration,
                         BusErrorKind::protocol, BusErrorKind::transceiver, BusErrorKind::restarted,
                         BusErrorKind::controller}) {
    const BusError e = decode_error_frame("virtual:x", make_error_frame(k));
    EXPECT_EQ(e.kind(), k) << name_of(k) << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find("virtual:x"), std::string::npos);
    ASSERT_TRUE(e.frame().has_value());
  }
}

TEST(CanErrorFrame, BusOffOutranksOtherClassesAndAllAreNamed) {
  ErrorFrame f;
  f.can_id = kErrFlag | CAN_ERR_BUSOFF | CAN_ERR_CRTL | CAN_ERR_CNT;
  f.data[1] = CAN_ERR_CRTL_TX_PASSIVE;
  f.data[6] = 255;
  f.data[7] = 3;
  const BusError e = decode_error_frame("socketcan:can0", f);
  EXPECT_EQ(e.kind(), BusErrorKind::bus_off);
  const std::string w = e.what();
  EXPECT_NE(w.find("bus-off"), std::string::npos) << w;
  EXPECT_NE(w.find("tx-passive"), std::string::npos) << w;
  EXPECT_NE(w.find("tx errors 255, rx errors 3"), std::string::npos) << w;
}

TEST(CanErrorFrame, PassiveControllerIsErrorPassive) {
  ErrorFrame f;
  f.can_id = kErrFlag | CAN_ERR_CRTL;
  f.data[1] = CAN_ERR_CRTL_RX_PASSIVE;
  EXPECT_EQ(decode_error_frame("b", f).kind(), BusErrorKind::error_passive);
  f.data[1] = CAN_ERR_CRTL_RX_OVERFLOW;
  EXPECT_EQ(decode_error_frame("b", f).kind(), BusErrorKind::controller);
}

}  // namespace
}  // namespace robogene::can
