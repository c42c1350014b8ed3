// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Searchable-style lookups on device configurations, both layouts YARP accepts.
#include <gtest/gtest.h>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

namespace robogene {
namespace {

TEST(Lookup, FindsValuesInGroups) {
  const Bottle cfg = Bottle::from_text("(device fakeMotor) (axes 4) (name \"/motors\") (limits 0.0 100.0)");
  EXPECT_EQ(cfg.find("axes").as_int32(), 4);
  EXPECT_EQ(cfg.find("name").as_string(), "/motors");
  EXPECT_EQ(cfg.find("limits").as_float64(), 0.0);  // the item after the key, as YARP
  EXPECT_TRUE(cfg.find("missing").is_null());
}

TEST(Lookup, FindsValuesAfterTopLevelKeys) {
  const Bottle cfg = Bottle::from_text("name /motors axes 4 last");
  EXPECT_EQ(cfg.find("axes").as_int32(), 4);
  EXPECT_EQ(cfg.find("name").as_string(), "/motors");
  EXPECT_TRUE(cfg.find("last").is_null());  // a key with nothing after it
}

TEST(Lookup, VocabKeysMatchTheirCharacters) {
  const Bottle reply = Bottle::from_text("([axes] 6) [ok]");
  EXPECT_EQ(reply.find("axes").as_int32(), 6);
  ASSERT_NE(reply.find_group("axes"), nullptr);
}

TEST(Lookup, FindGroupReturnsTheWholeList) {
  const Bottle cfg = Bottle::from_text("(general (joints 6)) (CAN (bus 0) (ids 1 2 3))");
  const Bottle* can = cfg.find_group("CAN");
  ASSERT_NE(can, nullptr);
  EXPECT_EQ(can->to_text(), "CAN (bus 0) (ids 1 2 3)");
  ASSERT_NE(can->find_group("ids"), nullptr);
  EXPECT_EQ(can->find_group("ids")->size(), 4u);
  EXPECT_EQ(cfg.find_group("general")->find("joints").as_int32(), 6);
  EXPECT_EQ(cfg.find_group("bus"), nullptr);  // not searched recursively
  EXPECT_EQ(Bottle().find_group("x"), nullptr);
  EXPECT_EQ(Bottle::from_text("() (x)").find_group("x")->size(), 1u);
}

TEST(Lookup, NumbersAreNotKeys) {
  EXPECT_TRUE(Bottle::from_text("1 2").find("1").is_null());
}

TEST(Bottle, CheckedAccessNamesIndexAndSize) {
  const Bottle b{1, 2};
  try {
    (void)b.at(5);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "bottle index 5 out of range (size 2)");
  }
  EXPECT_TRUE(b.get(5).is_null());
  EXPECT_EQ(b.get(1).as_int32(), 2);
}

TEST(Bottle, AddListReturnsTheNestedList) {
  Bottle b;
  b.add("joints").add_list().add(1).add(2);
  b.add(Value::vocab("ok"));
  EXPECT_EQ(b.to_text(), "joints (1 2) [ok]");
  b.clear();
  EXPECT_TRUE(b.empty());
}

}  // namespace
}  // namespace robogene
