// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "robogene/dev/property.hpp"

using robogene::Bottle;
using robogene::Value;
using robogene::dev::ConfigError;
using robogene::dev::Property;

namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kIni =
    "# a test motor\n"
    "device test_motor   // trailing comment\n"
    "axes 2\n"
    "name \"/motors # not a comment\"\n"
    "limits 0.0 90.5 (1 2)\n"
    "verbose\n"
    "\n"
    "[GENERAL]\n"
    "Joints 4\n"
    "[ LIMITS ]\n"
    "Max 1.5\n";

}  // namespace

TEST(Property, IniKeysGroupsCommentsAndMultipleValues) {
  const Property p = Property::from_ini(kIni, "motor.ini");
  EXPECT_EQ(p.get_string("device", ""), "test_motor");
  EXPECT_EQ(p.get_int("axes", 0, 1, 64), 2);
  EXPECT_EQ(p.get_string("name", ""), "/motors # not a comment");
  EXPECT_TRUE(p.get_bool("verbose", false));
  EXPECT_EQ(p.find("limits").to_text(), "(0.0 90.5 (1 2))");
  EXPECT_EQ(p.origin("axes"), "motor.ini:3");
  ASSERT_NE(p.find_group("GENERAL"), nullptr);
  EXPECT_EQ(p.find_group("GENERAL")->get_int("Joints", 0, 0, 100), 4);
  EXPECT_EQ(p.find_group("LIMITS")->get_float("Max", 0, 0, 10), 1.5);
  EXPECT_FALSE(p.check("Joints"));  // group keys stay in their group
  EXPECT_EQ(p.find_group("NOPE"), nullptr);
}

TEST(Property, IniFileErrorsNameFileLineAndColumn) {
  EXPECT_EQ(error_of([] { Property::from_ini("axes 2\n  speed (1 2\n", "m.ini"); }),
            "m.ini:2:9: '(' has no matching ')'");
  EXPECT_EQ(error_of([] { Property::from_ini("axes 2\n[broken\n", "m.ini"); }),
            "m.ini:2:1: a group header is [name], got '[broken'");
  EXPECT_EQ(error_of([] { Property::from_ini("axes 2\naxes 3\n", "m.ini"); }),
            "m.ini:2:1: key 'axes' is already set at m.ini:1");
  EXPECT_EQ(error_of([] { Property::from_ini_file("/nonexistent/motor.ini"); }),
            "/nonexistent/motor.ini: cannot open the configuration file");
}

TEST(Property, IniFileFromDisk) {
  const std::string path = ::testing::TempDir() + "robogene_property_test.ini";
  std::ofstream(path) << "axes 3\n[g]\nk v\n";
  const Property p = Property::from_ini_file(path);
  EXPECT_EQ(p.get_int("axes", 0, 0, 9), 3);
  EXPECT_EQ(p.origin("axes"), path + ":1");
  EXPECT_EQ(p.find_group("g")->get_string("k", ""), "v");
  std::remove(path.c_str());
}

TEST(Property, TypedReadsNameTheOriginOfABadValue) {
  const Property p = Property::from_ini("axes two\nspeed 1e9\nrate nan\nflag maybe\n", "m.ini");
  EXPECT_EQ(error_of([&] { p.get_int("axes", 0, 1, 64); }),
            "m.ini:1: key 'axes': expected an integer, got two");
  EXPECT_EQ(error_of([&] { p.get_float("speed", 0, 0, 100); }),
            "m.ini:2: key 'speed': 1000000000.0 is outside [0, 100]");
  EXPECT_EQ(error_of([&] { p.get_float("rate", 0, 0, 100); }),
            "m.ini:3: key 'rate': nan is outside [0, 100]");
  EXPECT_EQ(error_of([&] { p.get_bool("flag", false); }),
            "m.ini:4: key 'flag': expected true or false, got maybe");
  EXPECT_EQ(error_of([&] { p.require("missing"); }), "m.ini: missing key 'missing'");
  EXPECT_EQ(p.get_int("absent", 7, 0, 9), 7);
}

TEST(Property, CommandLineWithFlagsGroupsAndSeveralValues) {
  const Property p = Property::from_command_line(
      {"--device", "test_motor", "--axes", "2", "--single_port", "--name", "/motors",
       "--GENERAL::Joints", "4", "--pos", "1", "2.5", "--label", "two words"});
  EXPECT_EQ(p.get_string("device", ""), "test_motor");
  EXPECT_EQ(p.get_int("axes", 0, 0, 9), 2);
  EXPECT_TRUE(p.get_bool("single_port", false));
  EXPECT_EQ(p.get_string("name", ""), "/motors");
  EXPECT_EQ(p.find_group("GENERAL")->get_int("Joints", 0, 0, 9), 4);
  EXPECT_EQ(p.find("pos").to_text(), "(1 2.5)");
  EXPECT_EQ(p.get_string("label", ""), "two words");
  EXPECT_EQ(p.origin("axes"), "command line argument 3");
  EXPECT_EQ(error_of([] { Property::from_command_line({"axes", "2"}); }),
            "command line argument 1: expected --key, got 'axes'");
}

TEST(Property, AFlagIsNoWord) {
  // `--from` given without its file is the flag true, not the file "1".
  const Property p = Property::from_command_line({"--from", "--name", "/m"});
  EXPECT_EQ(error_of([&] { p.get_string("from", ""); }),
            "command line argument 1: key 'from': expected a word or a \"string\", got true");
  const Property ini = Property::from_ini("verbose\noff false\n", "m.ini");
  EXPECT_EQ(error_of([&] { ini.get_string("verbose", ""); }),
            "m.ini:1: key 'verbose': expected a word or a \"string\", got true");
  EXPECT_EQ(error_of([&] { ini.get_string("off", ""); }),
            "m.ini:2: key 'off': expected a word or a \"string\", got false");
  EXPECT_EQ(Property::from_ini("mode vel\n", "m.ini").get_string("mode", ""), "vel");  // a word stays one
}

TEST(Property, BottleFormRoundTripsWithGroups) {
  const Bottle b = Bottle::from_text("(device test_motor) (axes 2) (pos 1 2) (GENERAL (Joints 4))");
  const Property p = Property::from_bottle(b);
  EXPECT_EQ(p.get_int("axes", 0, 0, 9), 2);
  EXPECT_EQ(p.find("pos").to_text(), "(1 2)");
  EXPECT_EQ(p.find_group("GENERAL")->get_int("Joints", 0, 0, 9), 4);
  EXPECT_EQ(p.to_bottle().to_text(), "(axes 2) (device test_motor) (pos 1 2) (GENERAL (Joints 4))");
  EXPECT_EQ(Property::from_bottle(p.to_bottle()).to_bottle(), p.to_bottle());
  EXPECT_EQ(error_of([] { Property::from_bottle(Bottle::from_text("(axes 2) 7")); }),
            "bottle item 1: expected (key value...), got 7");
}

TEST(Property, MergeLetsLaterSourcesWin) {
  Property p = Property::from_ini("axes 2\nname a\n", "m.ini");
  p.merge(Property::from_command_line({"--axes", "5"}));
  EXPECT_EQ(p.get_int("axes", 0, 0, 9), 5);
  EXPECT_EQ(p.origin("axes"), "command line argument 1");
  EXPECT_EQ(p.get_string("name", ""), "a");
  const Property copy = p;  // deep copy, groups included
  EXPECT_EQ(copy.to_bottle(), p.to_bottle());
}
