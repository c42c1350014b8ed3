// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/registry.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "robogene/error.hpp"

using robogene::name::Registration;
using robogene::name::Registry;

namespace {

Registration reg(const std::string& name, int port, const std::string& host = "127.0.0.1",
                 const std::string& carrier = "tcp") {
  Registration r;
  r.name = name;
  r.carrier = carrier;
  r.host = host;
  r.port = port;
  r.type = "*";
  r.registered_at = 1000.0;
  return r;
}

// A database file that is removed (with its WAL companions) when the test ends.
struct TempDb {
  std::string path;
  TempDb() {
    char tmpl[] = "/tmp/robogene-registry-XXXXXX";
    int fd = mkstemp(tmpl);
    close(fd);
    path = tmpl;
    std::remove(path.c_str());
  }
  ~TempDb() {
    std::remove(path.c_str());
    std::remove((path + "-wal").c_str());
    std::remove((path + "-shm").c_str());
  }
};

}  // namespace

TEST(NameRegistry, StoresFindsAndListsInNameOrder) {
  Registry db(":memory:");
  db.put(reg("/motors/state:o", 10006));
  db.put(reg("/motors/command:i", 10005));
  db.put(reg("/a", 12345, "10.0.0.2"));
  auto found = db.find("/a");
  ASSERT_TRUE(found);
  EXPECT_EQ(found->host, "10.0.0.2");
  EXPECT_EQ(found->port, 12345);
  EXPECT_FALSE(db.find("/nope"));
  auto all = db.list();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].name, "/a");
  EXPECT_EQ(all[1].name, "/motors/command:i");
  EXPECT_EQ(all[2].name, "/motors/state:o");
}

TEST(NameRegistry, RemoveDropsPropertiesToo) {
  Registry db(":memory:");
  db.put(reg("/w", 10002));
  ASSERT_TRUE(db.set_property("/w", "process", {"7332"}));
  EXPECT_TRUE(db.remove("/w"));
  EXPECT_FALSE(db.remove("/w"));
  db.put(reg("/w", 10002));
  EXPECT_TRUE(db.get_property("/w", "process").empty());
}

TEST(NameRegistry, PropertiesAreSortedAndNeedARegisteredPort) {
  Registry db(":memory:");
  EXPECT_FALSE(db.set_property("/w", "offers", {"tcp"}));
  db.put(reg("/w", 10002));
  ASSERT_TRUE(db.set_property("/w", "offers", {"http", "name_ser", "tcp", "fast_tcp", "udp"}));
  EXPECT_EQ(db.get_property("/w", "offers"),
            (std::vector<std::string>{"fast_tcp", "http", "name_ser", "tcp", "udp"}));
  ASSERT_TRUE(db.set_property("/w", "offers", {"text"}));  // set replaces
  EXPECT_EQ(db.get_property("/w", "offers"), std::vector<std::string>{"text"});
  db.put(reg("/x", 10003));
  db.set_property("/x", "yarprun", {"true"});
  EXPECT_EQ(db.names_with_property("yarprun", "true"), std::vector<std::string>{"/x"});
}

TEST(NameRegistry, RemoveIfUnchangedSparesAReRegistration) {
  Registry db(":memory:");
  Registration old = reg("/w", 10002);
  db.put(old);
  Registration fresh = old;
  fresh.port = 10009;
  db.put(fresh);
  EXPECT_FALSE(db.remove_if_unchanged(old));
  EXPECT_TRUE(db.find("/w"));
  EXPECT_TRUE(db.remove_if_unchanged(fresh));
  EXPECT_FALSE(db.find("/w"));
}

TEST(NameRegistry, AllocatesFromTheRangeSkippingHeldNumbersAndWraps) {
  Registry db(":memory:");
  db.put(reg("/held", 10003));
  EXPECT_EQ(db.allocate_port("/a", 10002, 10005), 10002);
  db.put(reg("/a", 10002));
  EXPECT_EQ(db.allocate_port("/b", 10002, 10005), 10004);  // 10003 is held
  db.put(reg("/b", 10004));
  EXPECT_EQ(db.allocate_port("/c", 10002, 10005), 10005);
  db.put(reg("/c", 10005));
  EXPECT_THROW(db.allocate_port("/d", 10002, 10005), robogene::Error);
  db.remove("/a");
  EXPECT_EQ(db.allocate_port("/d", 10002, 10005), 10002);  // wrapped round to the freed number
}

TEST(NameRegistry, APortGetsItsPreviousNumberBackWhenFree) {
  Registry db(":memory:");
  db.put(reg("/a", db.allocate_port("/a", 10002, 10100)));
  db.put(reg("/b", db.allocate_port("/b", 10002, 10100)));
  EXPECT_EQ(db.find("/b")->port, 10003);
  db.remove("/a");
  db.remove("/b");
  EXPECT_EQ(db.allocate_port("/b", 10002, 10100), 10003);
}

TEST(NameRegistry, AllocatesNamesAndMulticastGroups) {
  Registry db(":memory:");
  EXPECT_EQ(db.allocate_name(), "/tmp/port/1");
  db.put(reg("/tmp/port/2", 10010));
  EXPECT_EQ(db.allocate_name(), "/tmp/port/3");
  std::string group = db.allocate_mcast_host();
  EXPECT_EQ(group, "224.1.1.2");
  db.put(reg("/m", 11000, group, "mcast"));
  EXPECT_EQ(db.allocate_mcast_host(), "224.1.1.3");
}

TEST(NameRegistry, SurvivesAReopen) {
  TempDb file;
  {
    Registry db(file.path);
    db.put(reg("/persist", 10042));
    db.set_property("/persist", "process", {"99"});
    db.allocate_port("/persist", 10002, 10100);
  }
  Registry again(file.path);
  auto found = again.find("/persist");
  ASSERT_TRUE(found);
  EXPECT_EQ(found->port, 10042);
  EXPECT_EQ(again.get_property("/persist", "process"), std::vector<std::string>{"99"});
}

TEST(NameRegistry, RejectsAFileThatIsNotADatabaseNamingIt) {
  TempDb file;
  {
    std::ofstream out(file.path);
    out << "this is not an sqlite database, just some text long enough to fill a header page\n";
  }
  try {
    Registry db(file.path);
    FAIL() << "opened a text file as a database";
  } catch (const robogene::Error& e) {
    EXPECT_NE(std::string(e.what()).find(file.path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a database"), std::string::npos) << e.what();
  }
}

TEST(NameRegistry, RejectsAnUnwritableLocationNamingIt) {
  try {
    Registry db("/nonexistent-dir/for/robogene/names.db");
    FAIL() << "opened a database in a missing directory";
  } catch (const robogene::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/for/robogene/names.db"), std::string::npos) << e.what();
  }
}
