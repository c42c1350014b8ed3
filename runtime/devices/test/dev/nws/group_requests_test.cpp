// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// YARP's joint-group forms, as a YARP controlboardwrapper2 over remote_controlboard sends them
// (seen on the wire: ([vmog] 4 (0 1 2 3)) (0.0 5.0 0.0 0.0) on command:o).
#include "robogene/dev/nws/group_requests.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace robogene;
using namespace robogene::dev;

namespace {

std::vector<std::string> texts(const std::vector<Bottle>& bs) {
  std::vector<std::string> out;
  for (const Bottle& b : bs) out.push_back(b.to_text());
  return out;
}

}  // namespace

TEST(GroupRequests, RpcGroupFormsExpandJointByJoint) {
  auto posg = expand_group_request(Bottle::from_text("[set] [posg] 2 (0 3) (10.0 -5.5)"));
  ASSERT_TRUE(posg);
  EXPECT_EQ(texts(*posg), (std::vector<std::string>{"[set] [pos] 0 10.0", "[set] [pos] 3 -5.5"}));
  auto stog = expand_group_request(Bottle::from_text("[set] [stog] 1 (2)"));
  ASSERT_TRUE(stog);
  EXPECT_EQ(texts(*stog), std::vector<std::string>{"[set] [sto] 2"});
}

TEST(GroupRequests, CommandPortGroupFormsExpandJointByJoint) {
  auto vmog = expand_group_command(Bottle::from_text("([vmog] 4 (0 1 2 3)) (0.0 5.0 0.0 0.0)"));
  ASSERT_TRUE(vmog);
  EXPECT_EQ(texts(*vmog), (std::vector<std::string>{"[set] [vmo] 0 0.0", "[set] [vmo] 1 5.0",
                                                    "[set] [vmo] 2 0.0", "[set] [vmo] 3 0.0"}));
}

TEST(GroupRequests, OtherRequestsAreLeftAloneAndBadGroupsExpandToNothing) {
  EXPECT_FALSE(expand_group_request(Bottle::from_text("[set] [pos] 0 1.0")));
  EXPECT_FALSE(expand_group_request(Bottle::from_text("[get] [posg] 1 (0)")));
  EXPECT_FALSE(expand_group_command(Bottle::from_text("([vmo] 1) (7.5)")));
  for (const char* bad : {"[set] [posg] 3 (0 1) (1.0 2.0)", "[set] [posg] 2 (0 1) (1.0)",
                          "[set] [posg] 1 (a) (1.0)", "[set] [posg] 1 (0)", "[set] [stog] x (0)"}) {
    auto e = expand_group_request(Bottle::from_text(bad));
    ASSERT_TRUE(e) << bad;
    EXPECT_TRUE(e->empty()) << bad;
  }
  auto e = expand_group_command(Bottle::from_text("([vmog] 2 (0 1)) (1.0)"));
  ASSERT_TRUE(e);
  EXPECT_TRUE(e->empty());
}

TEST(GroupRequests, MotionDoneGroupAsksEachJointAndAndsTheAnswers) {
  // A YARP controlboardwrapper2 over remote_controlboard asks checkMotionDone() of all its joints so.
  const Bottle request = Bottle::from_text("[get] [dong] 2 (0 3)");
  auto singles = expand_group_query(request);
  ASSERT_TRUE(singles);
  EXPECT_EQ(texts(*singles), (std::vector<std::string>{"[get] [don] 0", "[get] [don] 3"}));
  const Bottle done = Bottle::from_text("[is] [don] 1 [tsta] 7 12.5 [ok]");
  const Bottle moving = Bottle::from_text("[is] [don] 0 [tsta] 8 12.75 [ok]");
  EXPECT_EQ(combine_group_replies(request, {done, done}).to_text(), "[is] [dong] 1 [tsta] 7 12.5 [ok]");
  EXPECT_EQ(combine_group_replies(request, {done, moving}).to_text(), "[is] [dong] 0 [tsta] 8 12.75 [ok]");
  EXPECT_EQ(combine_group_replies(request, {done, Bottle::from_text("[fail]")}).to_text(), "[fail]");
}

TEST(GroupRequests, MalformedMotionDoneGroupsAreRefused) {
  EXPECT_FALSE(expand_group_query(Bottle::from_text("[get] [don] 0")));         // not a group form
  EXPECT_FALSE(expand_group_query(Bottle::from_text("[set] [dong] 1 (0)")));    // not a query
  for (const char* bad : {"[get] [dong] 3 (0 1)", "[get] [dong] 1", "[get] [dong] 1 (zero)", "[get] [dong] -1 ()"}) {
    auto singles = expand_group_query(Bottle::from_text(bad));
    ASSERT_TRUE(singles) << bad;
    EXPECT_TRUE(singles->empty()) << bad;
    EXPECT_EQ(combine_group_replies(Bottle::from_text(bad), *singles).to_text(), "[fail]") << bad;
  }
}
