// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The generated control-board dispatch against a real YARP 3 session: the request and reply
// bottles below are the bytes of the `yarp rpc /motors/rpc:i` session in the reference capture
// rpc_motors.flows.txt (controlBoard_nws_yarp + fakeMotionControl, 4 axes), replayed against
// test_motor. Replies must match byte for byte, except the 8 bytes of each timestamp's time.
#include <gtest/gtest.h>

#include "robogene/testing/vector_cases.hpp"

#include <chrono>
#include <cstring>
#include <string>
#include <vector>

#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/generated/grabber_server.hpp"
#include "robogene/dev/image_codec.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"

using namespace robogene;
using namespace robogene::dev;

namespace {

std::vector<std::uint8_t> unhex(const std::string& hex) {
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
    out.push_back(static_cast<std::uint8_t>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  }
  return out;
}

double wall_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

struct Exchange {
  const char* text;  // what was typed at `yarp rpc`
  const char* request;
  const char* reply;
};

// Straight from the capture. The last reply differs in one respect, marked below.
const Exchange kSession[] = {
    {"get axes", "0401000002000000030000006765740400000061786573",
     "000100000700000009000000697300000400000004000000617865730100000004000000090000007473746101000000000000000a0000004a7cad51a2c0da41090000006f6b0000"},
    {"[get] [axes]", "09010000020000006765740061786573",
     "0001000007000000090000006973000009000000617865730100000004000000090000007473746101000000010000000a000000d17fad51a2c0da41090000006f6b0000"},
    {"get prot", "0401000002000000030000006765740400000070726f74",
     "00010000050000000900000070726f74010000000100000001000000090000000100000000000000090000006f6b0000"},
    {"set pos 0 10", "000100000400000004000000030000007365740400000003000000706f730100000000000000010000000a000000",
     "09010000010000006f6b0000"},
    {"set vel 0 20", "00010000040000000400000003000000736574040000000300000076656c01000000000000000100000014000000",
     "09010000010000006f6b0000"},
    {"get pos 0", "000100000300000004000000030000006765740400000003000000706f730100000000000000",
     "000100000700000009000000697300000400000003000000706f730a0000000000000000002440090000007473746101000000020000000a000000fb87ad51a2c0da41090000006f6b0000"},
    {"get enc 0", "000100000300000004000000030000006765740400000003000000656e630100000000000000",
     "000100000700000009000000697300000400000003000000656e630a0000000000000000000000090000007473746101000000030000000a000000788aad51a2c0da41090000006f6b0000"},
    {"get encs", "04010000020000000300000067657404000000656e6373",
     "000100000700000009000000697300000400000004000000656e63730a010000040000000000000000000000000000000000000000000000000000000000000000000000090000007473746101000000040000000a000000cc8cad51a2c0da41090000006f6b0000"},
    {"set poss (1 2 3 4)", "000100000300000004000000030000007365740400000004000000706f7373010100000400000001000000020000000300000004000000",
     "09010000010000006f6b0000"},
    {"get done 0", "000100000300000004000000030000006765740400000004000000646f6e650100000000000000",
     "09010000010000006661696c"},
    {"set vmos (0.5 0 0 0)", "000100000300000004000000030000007365740400000004000000766d6f7300010000040000000a000000000000000000e03f010000000000000001000000000000000100000000000000",
     "09010000010000006f6b0000"},
    {"get vmo 0", "000100000300000004000000030000006765740400000003000000766d6f0100000000000000",
     "000100000700000009000000697300000400000003000000766d6f0a000000000000000000e03f090000007473746101000000060000000a000000db99ad51a2c0da41090000006f6b0000"},
    // YARP's fakeMotionControl stays in position mode after velocity moves ([pos] = 706f7300);
    // test_motor switches the axes it moves at a velocity to [vel] (76656c00).
    {"get icmd cmds", "0401000003000000030000006765740400000069636d6404000000636d6473",
     "0001000007000000090000006973000009000000636d6473090100000400000076656c0076656c0076656c0076656c00090000007473746101000000070000000a000000c49cad51a2c0da41090000006f6b0000"},
    {"get foo", "04010000020000000300000067657403000000666f6f", "09010000010000006661696c"},
};

struct Board {
  PolyDriver device;
  std::unique_ptr<ControlboardServer> server;
  Board() {
    EXPECT_TRUE(device.open(Property::from_command_line(
        {"--device", "test_motor", "--axes", "4", "--clock", "manual"})))
        << device.last_error();
    DeviceDriver* driver = nullptr;
    EXPECT_TRUE(device.view(driver));
    server = std::make_unique<ControlboardServer>(*driver);
  }
  std::string ask(const std::string& text) { return server->respond(Bottle::from_text(text)).to_text(); }
};

// Replies of queries end with [tsta] <n> <time> [ok]: the time is the 8 bytes before [ok].
void expect_same_but_time(const std::vector<std::uint8_t>& got, const std::vector<std::uint8_t>& want,
                          double before, double after, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what << "\n got " << robogene::testing::to_hex(got) << "\nwant " << robogene::testing::to_hex(want);
  const bool timed = want.size() > 20 && std::memcmp(want.data() + want.size() - 20, "\x0a\0\0\0", 4) == 0;
  if (!timed) {
    EXPECT_EQ(robogene::testing::to_hex(got), robogene::testing::to_hex(want)) << what;
    return;
  }
  const std::size_t t = want.size() - 16;
  std::vector<std::uint8_t> a = got, b = want;
  std::fill(a.begin() + static_cast<long>(t), a.begin() + static_cast<long>(t + 8), 0);
  std::fill(b.begin() + static_cast<long>(t), b.begin() + static_cast<long>(t + 8), 0);
  EXPECT_EQ(robogene::testing::to_hex(a), robogene::testing::to_hex(b)) << what;
  double time = 0;
  std::memcpy(&time, got.data() + t, 8);
  EXPECT_GE(time, before) << what;
  EXPECT_LE(time, after) << what;
}

}  // namespace

TEST(ControlboardServer, ReplaysTheCapturedYarpSessionByteForByte) {
  Board board;
  for (const Exchange& e : kSession) {
    const Bottle request = Bottle::from_bytes(unhex(e.request));
    const double before = wall_now();
    const Bottle reply = board.server->respond(request);
    const double after = wall_now();
    expect_same_but_time(reply.to_bytes(), unhex(e.reply), before, after, e.text);
  }
}

TEST(ControlboardServer, ReferencePairsInTextForm) {
  Board board;
  EXPECT_EQ(board.ask("[get] [prot]"), "[prot] 1 9 0 [ok]");
  EXPECT_EQ(board.ask("[set] [pos] 1 25.0"), "[ok]");
  EXPECT_EQ(board.ask("[get] [pos] 1").substr(0, 24), "[is] [pos] 25.0 [tsta] 0");
  EXPECT_EQ(board.ask("[set] [vel] 0 20.0"), "[ok]");
  EXPECT_EQ(board.ask("[get] [vels]").substr(0, 39), "[is] [vels] (20.0 10.0 10.0 10.0) [tsta");
  EXPECT_EQ(board.ask("[set] [acc] 0 50.0"), "[ok]");
  EXPECT_EQ(board.ask("[get] [accs]").substr(0, 39), "[is] [accs] (50.0 50.0 50.0 50.0) [tsta");
  EXPECT_EQ(board.ask("[get] [don] 1").substr(0, 15), "[is] [don] 0 [t");  // moving to 25
  EXPECT_EQ(board.ask("[set] [icmd] [cmod] 0 [vel]"), "[ok]");
  EXPECT_EQ(board.ask("[get] [icmd] [cmod] 0").substr(0, 18), "[is] 0 [vel] [tsta");
  EXPECT_EQ(board.ask("[set] [icmd] [cmds] ([pos] [pos] [idl] [vel])"), "[ok]");
  EXPECT_EQ(board.ask("[get] [icmd] [cmds]").substr(0, 37), "[is] [cmds] ([pos] [pos] [idl] [vel])");
  EXPECT_EQ(board.ask("[bogus]"), "[nak]");
  EXPECT_EQ(board.ask("get done 0"), "[fail]");
}

TEST(ControlboardServer, HelpListsEveryRequestWithItsArgumentsAndUnits) {
  // The paper's section 4.4 types `help` after `d`: the device answers with its commands.
  Board board;
  for (const char* request : {"help", "[help]"}) {
    const Bottle reply = board.server->respond(Bottle::from_text(request));
    ASSERT_GT(reply.size(), 40u) << request;
    EXPECT_EQ(reply[0].to_text(), "[many]");
    EXPECT_EQ(reply[1].as_string(), "[get] [axes]  # The number of axes the board controls.");
    bool pos = false;
    for (const Value& line : reply) {
      pos = pos || (line.is_string() &&
                    line.as_string() == "[set] [pos] $j $ref  # Start moving one axis to an absolute position. (ref: deg)");
    }
    EXPECT_TRUE(pos) << reply.to_text();
  }
  EXPECT_EQ(board.ask("helper"), "[nak]");
}

TEST(ControlboardServer, RequestsDriveTheDeviceAndEncodersFollow) {
  Board board;
  ISimulationClock* clock = nullptr;
  ASSERT_TRUE(board.device.view(clock));
  EXPECT_EQ(board.ask("[set] [accs] (100.0 100.0 100.0 100.0)"), "[ok]");
  EXPECT_EQ(board.ask("[set] [vel] 0 5.0"), "[ok]");
  EXPECT_EQ(board.ask("[set] [pos] 0 40.0"), "[ok]");
  EXPECT_EQ(board.ask("[set] [vmo] 1 5.0"), "[ok]");
  ASSERT_TRUE(clock->advance(10.0));
  EXPECT_EQ(board.ask("[get] [enc] 0").substr(0, 22), "[is] [enc] 40.0 [tsta]");
  // One value for all axes, as YARP's server answers (axis 1 still runs its velocity move)
  EXPECT_EQ(board.ask("[get] [dons]").substr(0, 20), "[is] [dons] 0 [tsta]");
  EXPECT_EQ(board.ask("[set] [stos]"), "[ok]");
  ASSERT_TRUE(clock->advance(1.0));
  EXPECT_EQ(board.ask("[get] [dons]").substr(0, 20), "[is] [dons] 1 [tsta]");
}

TEST(ControlboardServer, MalformedRequestsFailWithoutTouchingTheDevice) {
  Board board;
  EXPECT_EQ(board.ask("[set] [pos] 1"), "[fail]");                  // missing value
  EXPECT_EQ(board.ask("[set] [pos] 1 2.0 3.0"), "[fail]");          // one too many
  EXPECT_EQ(board.ask("[set] [pos] one 2.0"), "[fail]");            // joint not a number
  EXPECT_EQ(board.ask("[set] [pos] 9 2.0"), "[fail]");              // no such axis
  EXPECT_EQ(board.ask("[set] [pos] 4294967296 2.0"), "[fail]");     // not an int32
  EXPECT_EQ(board.ask("[set] [poss] (1.0 2.0)"), "[fail]");         // 2 values for 4 axes
  EXPECT_EQ(board.ask("[set] [poss] (1.0 two 3.0 4.0)"), "[fail]"); // not numbers
  EXPECT_EQ(board.ask("[set] [poss] 1.0"), "[fail]");               // not a list
  EXPECT_EQ(board.ask("[set] [icmd] [cmod] 0 [bogu]"), "[fail]");   // not a control mode
  EXPECT_EQ(board.ask("[set] [icmd] [cmod] 0 [icur]"), "[fail]");   // a mode test_motor lacks
  EXPECT_EQ(board.ask("[get] [torq] [trq] 9"), "[fail]");           // no such axis
  EXPECT_EQ(board.ask("[set] [torq] [ref] 0 99.0"), "[fail]");      // beyond max_torque
  EXPECT_EQ(board.ask("[get] [pid] [pid] [xyz] 0"), "[fail]");      // not a PID type
  EXPECT_EQ(board.ask("[set] [pid] [pid] [pos] 0 (1.0 2.0)"), "[fail]");  // 2 of a Pid's 10 fields
  EXPECT_EQ(board.ask("[get] [pid] [ref] [cur] 0"), "[fail]");      // test_motor has no current loop
  EXPECT_EQ(board.ask("(nested list) 1"), "[fail]");
  EXPECT_EQ(board.ask(""), "[nak]");
  EXPECT_EQ(board.ask("[get] [encs]").substr(0, 33), "[is] [encs] (0.0 0.0 0.0 0.0) [ts");
  EXPECT_EQ(board.ask("[get] [poss]").substr(0, 33), "[is] [poss] (0.0 0.0 0.0 0.0) [ts");
}

// Torque and PID requests in the shapes of YARP 3's RPCMessagesParser (handleTorqueMsg,
// handlePidMsg): torque queries echo [torq] and are stamped; PID queries echo [pid], carry the
// Pid as a list of its 10 fields in YARP's order, and have no stamp, nor do they take a number.
TEST(ControlboardServer, TorqueAndPidRequestsSucceedInYarpsShapes) {
  Board board;
  auto stamp_of = [&](const char* request) {
    const Bottle reply = board.server->respond(Bottle::from_text(request));
    EXPECT_EQ(reply[reply.size() - 4].to_text(), "[tsta]") << reply.to_text();
    return reply[reply.size() - 3].as_int64();
  };
  EXPECT_EQ(board.ask("[set] [torq] [ref] 1 0.5"), "[ok]");
  EXPECT_EQ(board.ask("[get] [icmd] [cmod] 1").substr(0, 20), "[is] 1 [torq] [tsta]");
  EXPECT_EQ(board.ask("[get] [torq] [ref] 1").substr(0, 23), "[is] [torq] 0.5 [tsta] ");
  EXPECT_EQ(board.ask("[get] [torq] [trqs]").substr(0, 37), "[is] [torq] (0.0 0.5 0.0 0.0) [tsta] ");
  EXPECT_EQ(board.ask("[get] [torq] [rng] 1").substr(0, 28), "[is] [torq] -5.0 5.0 [tsta] ");
  EXPECT_EQ(board.ask("[set] [torq] [refs] (0.25 0.5 0.75 1.0)"), "[ok]");
  EXPECT_EQ(board.ask("[get] [torq] [refs]").substr(0, 39), "[is] [torq] (0.25 0.5 0.75 1.0) [tsta] ");

  const std::int64_t before = stamp_of("[get] [axes]");
  EXPECT_EQ(board.ask("[set] [pid] [pid] [pos] 2 (1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0 10.0)"), "[ok]");
  const Bottle pid = board.server->respond(Bottle::from_text("[get] [pid] [pid] [pos] 2"));
  EXPECT_EQ(pid.to_text(), "[is] [pid] (1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0 10.0) [ok]");
  // Four items; the Pid is a homogeneous float64 list (0x10a), as YARP writes a list of doubles.
  std::string fields;
  for (int k = 1; k <= 10; ++k) {
    const double v = k;
    std::vector<std::uint8_t> b(8);
    std::memcpy(b.data(), &v, 8);
    fields += robogene::testing::to_hex(b);
  }
  EXPECT_EQ(robogene::testing::to_hex(pid.to_bytes()), "0001000004000000" "0900000069730000" "0900000070696400"
                                 "0a0100000a000000" + fields + "090000006f6b0000");
  EXPECT_EQ(board.ask("[get] [pid] [pid] [vel] 2"),
            "[is] [pid] (0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0) [ok]");  // one Pid per type
  EXPECT_EQ(board.ask("[set] [pid] [pids] [trq] ((1 0 0 0 0 0 0 0 0 0) (2 0 0 0 0 0 0 0 0 0) "
                      "(3 0 0 0 0 0 0 0 0 0) (4 0 0 0 0 0 0 0 0 5))"),
            "[ok]");
  EXPECT_EQ(board.ask("[get] [pid] [pids] [trq]"),
            "[is] [pid] ((1.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0) (2.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0) "
            "(3.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0) (4.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 5.0)) [ok]");
  EXPECT_EQ(board.ask("[set] [pid] [lim] [pos] 0 2.5"), "[ok]");
  EXPECT_EQ(board.ask("[get] [pid] [lim] [pos] 0"), "[is] [pid] 2.5 [ok]");
  EXPECT_EQ(board.ask("[get] [pid] [ref] [trq] 1"), "[is] [pid] 0.5 [ok]");  // axis 1 runs its torque loop
  EXPECT_EQ(board.ask("[get] [pid] [err] [trq] 1"), "[is] [pid] 0.0 [ok]");
  EXPECT_EQ(board.ask("[get] [pid] [outs] [trq]"), "[is] [pid] (0.25 0.5 0.75 1.0) [ok]");
  EXPECT_EQ(board.ask("[get] [pid] [ref] [pos] 1"), "[fail]");  // ... not its position loop
  EXPECT_EQ(board.ask("[set] [pid] [ref] [trq] 1 0.3"), "[fail]");  // direct references: not simulated
  EXPECT_EQ(stamp_of("[get] [axes]"), before + 1);  // PID queries took no number
}

TEST(ControlboardServer, IntrospectionListsImplementedInterfacesWithFingerprints) {
  Board board;
  const std::string reply = board.ask("[get] [rgif]");
  auto entry = [](const char* name, const char* fingerprint) {
    return std::string("(") + name + " " + Value::string(fingerprint).to_text() + ")";
  };
  const std::string expected = "[is] [rgif] (" + entry("IEncoders", IEncoders::kFingerprint) + " " +
                               entry("IPositionControl", IPositionControl::kFingerprint) + " " +
                               entry("IVelocityControl", IVelocityControl::kFingerprint) + " " +
                               entry("ITorqueControl", ITorqueControl::kFingerprint) + " " +
                               entry("IPidControl", IPidControl::kFingerprint) + " " +
                               entry("IControlMode", IControlMode::kFingerprint) + ") [tsta] 0 ";
  EXPECT_EQ(reply.substr(0, expected.size()), expected);
  EXPECT_EQ(reply.substr(reply.size() - 5), " [ok]");
}

TEST(GrabberServer, ControlsAndSizeByRpc) {
  PolyDriver device(Property::from_command_line(
      {"--device", "fake_grabber", "--width", "32", "--height", "24", "--clock", "manual"}));
  DeviceDriver* driver = nullptr;
  ASSERT_TRUE(device.view(driver));
  GrabberServer server(*driver);
  auto ask = [&](const char* text) { return server.respond(Bottle::from_text(text)).to_text(); };
  // YARP 3's shapes (see grabber_nws_test.cpp): values after [is], sets answered as 3.12.3 does.
  EXPECT_EQ(ask("[fgi] [get] [w]"), "[fgi] [w] [is] 32");
  EXPECT_EQ(ask("[fgi] [get] [h]"), "[fgi] [h] [is] 24");
  EXPECT_EQ(ask("[fgc] [set] [feat] 8 0.25"), "[fgc] [set] 1");  // gain
  EXPECT_EQ(ask("[fgc] [get] [feat] 8"), "[fgc] [feat] [is] 0.25");
  EXPECT_EQ(ask("[fgc] [has] [feat] 10"), "[fgc] [has] [feat] 1952540006 0");  // no focus
  EXPECT_EQ(ask("[fgc] [set] [feat] 99 0.5"), "[fgc] [set] 0");  // not a CameraFeature
  EXPECT_EQ(ask("[fgc] [set] [mode] 7 2"), "[fgc] [set] 1");          // shutter: auto
  EXPECT_EQ(ask("[fgc] [get] [mode] 7"), "[fgc] [mode] [is] 2");
  EXPECT_EQ(ask("[get] [prot]"), "[nak]");  // no protocol declared; unknown requests get [nak]
}

// state:o carries the encoders as a YARP Vector: a homogeneous float64 list (capture sniff_state).
TEST(ControlboardServer, StatePortMessageIsTheEncoderVector) {
  Board board;
  EXPECT_EQ(board.ask("[set] [encs] (1.0 2.0 3.0 4.0)"), "[ok]");
  Bottle state;
  ASSERT_TRUE(board.server->publish_state(state));
  EXPECT_EQ(robogene::testing::to_hex(state.to_bytes()),
            "0a01000004000000000000000000f03f000000000000004000000000000008400000000000001040");
}

TEST(GrabberServer, ImageStreamMessageIsAYarpImageOfTheCurrentFrame) {
  PolyDriver device(Property::from_command_line(
      {"--device", "fake_grabber", "--width", "16", "--height", "8", "--clock", "manual"}));
  DeviceDriver* driver = nullptr;
  IFrameGrabberImage* img = nullptr;
  ASSERT_TRUE(device.view(driver) && device.view(img));
  GrabberServer server(*driver);
  Bottle message;
  ASSERT_TRUE(server.publish_image(message));
  EXPECT_EQ(message[2].to_text(), "(3 384 65544 16 8)");
  ImageRgb sent, local;
  std::string error;
  ASSERT_TRUE(decode_image(message, sent, error)) << error;
  ASSERT_TRUE(img->getImage(local));  // same simulated time: the same frame
  EXPECT_EQ(sent.pixels, local.pixels);
}

// command:i: velocityMove(2, 7.5) exactly as remote_controlboard sends it (reference 5.5).
TEST(ControlboardServer, CommandPortCarriesStreamedMoves) {
  Board board;
  const Bottle vmo = Bottle::from_bytes(unhex(
      "0001000002000000"
      "000100000200000009000000766d6f000100000002000000"
      "0a01000001000000000000000000" "1e40"));
  EXPECT_EQ(vmo.to_text(), "([vmo] 2) (7.5)");
  EXPECT_TRUE(board.server->command(vmo));
  EXPECT_EQ(board.ask("[get] [vmo] 2").substr(0, 20), "[is] [vmo] 7.5 [tsta");
  EXPECT_TRUE(board.server->command(Bottle::from_text("([vmos]) (1.0 2.0 3.0 4.0)")));
  EXPECT_EQ(board.ask("[get] [vmos]").substr(0, 32), "[is] [vmos] (1.0 2.0 3.0 4.0) [t");
  EXPECT_TRUE(board.server->command(Bottle::from_text("([poss]) (10.0 20.0 30.0 40.0)")));
  EXPECT_EQ(board.ask("[get] [poss]").substr(0, 36), "[is] [poss] (10.0 20.0 30.0 40.0) [t");
  EXPECT_FALSE(board.server->command(Bottle::from_text("([vmo] 9) (1.0)")));     // no axis 9
  EXPECT_FALSE(board.server->command(Bottle::from_text("([bogus] 1) (1.0)")));   // unknown head
  EXPECT_FALSE(board.server->command(Bottle::from_text("([vmo] 1)")));           // no values
  EXPECT_FALSE(board.server->command(Bottle::from_text("([vmo] 1) (1.0 2.0)")));  // too many
  EXPECT_FALSE(board.server->command(Bottle::from_text("([encs]) ()")));         // a query
  EXPECT_FALSE(board.server->command(Bottle::from_text("[vmo] 1 1.0")));         // not a pair
}

// YARP 3.5's remote_controlboard streams torque references with heads of their own
// (RemoteControlBoard::setRefTorque/setRefTorques): the IDL's command aliases [dtq] and [dtqs].
TEST(ControlboardServer, CommandPortTakesYarpsTorqueHeads) {
  Board board;
  EXPECT_TRUE(board.server->command(Bottle::from_text("([dtq] 1) (0.5)")));
  EXPECT_EQ(board.ask("[get] [torq] [ref] 1").substr(0, 23), "[is] [torq] 0.5 [tsta] ");
  EXPECT_EQ(board.ask("[get] [icmd] [cmod] 1").substr(0, 13), "[is] 1 [torq]");
  EXPECT_TRUE(board.server->command(Bottle::from_text("([dtqs]) (0.25 0.5 0.75 1.0)")));
  EXPECT_EQ(board.ask("[get] [torq] [refs]").substr(0, 39), "[is] [torq] (0.25 0.5 0.75 1.0) [tsta] ");
  EXPECT_TRUE(board.server->command(Bottle::from_text("([torq] [ref] 0) (1.5)")));  // the [set] path works too
  EXPECT_FALSE(board.server->command(Bottle::from_text("([dtq] 1) (9.0)")));     // beyond max_torque
  EXPECT_FALSE(board.server->command(Bottle::from_text("([dtq]) (0.5)")));       // no joint
  EXPECT_FALSE(board.server->command(Bottle::from_text("([dtqs]) (0.5 0.5)")));  // 2 values for 4 axes
}
