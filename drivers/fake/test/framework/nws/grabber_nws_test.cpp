// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The camera on real ports: frameGrabber_nws_yarp serving fake_grabber at 640x480, and
// remote_grabber receiving its stream.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "nws_test_util.hpp"
#include "robogene/dev/generated/grabber_client.hpp"
#include "robogene/dev/generated/grabber_server.hpp"
#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/nws/remote_grabber.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/port.hpp"

using namespace robogene;
using namespace robogene::dev;
using robogene::test::LocalNameServer;

namespace {

// fake_grabber's frame n (docs/devices.md): red x + 2n, green y + n (mod 256), blue a 16 px
// checkerboard flipping every 8 frames. The green of pixel (0, 0) is n mod 256, which fixes
// the whole frame.
bool is_pattern_frame(const ImageRgb& image, std::int64_t& n) {
  n = image.at(0, 0)[1];
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      if (p[0] != static_cast<std::uint8_t>((x + 2 * n) % 256) ||
          p[1] != static_cast<std::uint8_t>((y + n) % 256) ||
          p[2] != (((x / 16 + y / 16 + n / 8) % 2) ? 200 : 40)) {
        return false;
      }
    }
  }
  return true;
}

struct ServedCamera {
  ServedCamera(LocalNameServer& ns, double framerate) {
    Property config = ns.config("(device frameGrabber_nws_yarp) (subdevice fake_grabber) (width 640) "
                                "(height 480) (name /camera)");
    config.put("framerate", Value(framerate));
    if (!server.open(config)) throw Error(server.last_error());
  }
  PolyDriver server;
};

}  // namespace

TEST(GrabberNws, Streams640x480RgbAtTheConfiguredRateToARemoteClient) {
  LocalNameServer ns;
  ServedCamera served(ns, 30.0);
  PolyDriver client;
  ASSERT_TRUE(client.open(ns.config("(device remote_grabber) (remote /camera) (local /viewer)")))
      << client.last_error();
  IFrameGrabberImage* frames = nullptr;
  ASSERT_TRUE(client.view(frames));
  std::int32_t w = 0, h = 0;
  ASSERT_TRUE(frames->width(w));
  ASSERT_TRUE(frames->height(h));
  EXPECT_EQ(w, 640);
  EXPECT_EQ(h, 480);

  // Content: every frame is the test pattern, and frames move on.
  std::int64_t previous = -1;
  for (int i = 0; i < 3; ++i) {
    ImageRgb image;
    ASSERT_TRUE(frames->getImage(image));
    ASSERT_EQ(image.width, 640);
    ASSERT_EQ(image.height, 480);
    std::int64_t n = 0;
    EXPECT_TRUE(is_pattern_frame(image, n)) << "frame " << i << " is not the fake_grabber pattern";
    EXPECT_NE(n, previous);
    previous = n;
  }

  // Rate: frames counted over 2 s at the client, within 25% of 30 Hz (a shared 2-core CI machine).
  auto* remote = dynamic_cast<RemoteGrabber*>(frames);
  ASSERT_NE(remote, nullptr);
  const std::uint64_t before = remote->frames_received();
  const auto start = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::seconds(2));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double rate = static_cast<double>(remote->frames_received() - before) / seconds;
  EXPECT_NEAR(rate, 30.0, 7.5);
}

TEST(GrabberNws, ControlsGoThroughRpc) {
  LocalNameServer ns;
  ServedCamera served(ns, 10.0);
  PolyDriver client;
  ASSERT_TRUE(client.open(ns.config("(device remote_grabber) (remote /camera) (local /viewer)")))
      << client.last_error();
  IFrameGrabberControls* controls = nullptr;
  ASSERT_TRUE(client.view(controls));
  ASSERT_TRUE(controls->setFeature(CameraFeature::shutter, 0.25));
  double v = 0;
  ASSERT_TRUE(controls->getFeature(CameraFeature::shutter, v));
  EXPECT_EQ(v, 0.25);
  bool has = true;
  ASSERT_TRUE(controls->hasFeature(CameraFeature::focus, has));
  EXPECT_FALSE(has);
}

// The replies of YARP 3's frame grabbers (3.5's captured from its frameGrabber_nws_yarp and
// grabberDual, tests/interop/test_grabber_devices.py; 3.12.3's in tests/vectors/yarp312/): no
// [is]-first shape, no [tsta]/[ok]; a set answered as 3.12.3 answers it.
TEST(GrabberServer, AnswersInTheShapeOfYarp3FrameGrabbers) {
  LocalNameServer ns;
  PolyDriver camera;
  ASSERT_TRUE(camera.open(ns.config("(device fake_grabber) (width 640) (height 480)"))) << camera.last_error();
  GrabberServer server(*camera.device());
  auto ask = [&](const char* text) { return server.respond(Bottle::from_text(text)).to_text(); };
  EXPECT_EQ(ask("[fgi] [get] [w]"), "[fgi] [w] [is] 640");
  EXPECT_EQ(ask("[fgi] [get] [h]"), "[fgi] [h] [is] 480");
  EXPECT_EQ(ask("[fgc] [set] [feat] 7 0.25"), "[fgc] [set] 1");
  EXPECT_EQ(ask("fgc set feat 7 0.5"), "[fgc] [set] 1");  // answered in vocabs, as YARP does
  EXPECT_EQ(ask("[fgc] [set] [feat] 10 0.5"), "[fgc] [set] 0");  // focus: refused
  EXPECT_EQ(ask("[fgc] [set] [feat] 7"), "[fgc] [set] 0");        // no value: refused too
  EXPECT_EQ(ask("[fgc] [get] [feat] 7"), "[fgc] [feat] [is] 0.5");
  EXPECT_EQ(ask("[fgc] [has] [feat] 7"), "[fgc] [has] [feat] 1952540006 1");
  EXPECT_EQ(ask("[fgc] [has] [feat] 10"), "[fgc] [has] [feat] 1952540006 0");
  EXPECT_EQ(ask("[fgc] [get] [feat] 10"), "[nak]");  // focus: fake_grabber has none
  EXPECT_EQ(ask("[fgc] [bogus] [feat] 7"), "[nak]");
}

// What each server's answer to a set means to our client: YARP 3.12.3's [fgc] [set] <int32> says
// whether it was done; Robogene's servers before it answered success with an empty bottle;
// YARP 3.5's answer [nak] to every set and 3.12.3's to one they cannot parse.
TEST(GrabberClient, ReadsEveryFormOfASetReply) {
  Bottle next;
  std::vector<Bottle> sent;
  GrabberClient client([&](const Bottle& request, Bottle& reply) {
    sent.push_back(request);
    reply = next;
    return true;
  });
  auto set_with = [&](const char* reply_text) {
    next = Bottle::from_text(reply_text);
    return client.setFeature(CameraFeature::shutter, 0.25);
  };
  EXPECT_TRUE(set_with("[fgc] [set] 1"));
  EXPECT_FALSE(set_with("[fgc] [set] 0"));
  EXPECT_TRUE(set_with(""));
  EXPECT_FALSE(set_with("[nak]"));
  EXPECT_FALSE(set_with("[fgc] [set]"));          // no result
  EXPECT_FALSE(set_with("[fgc] [set] [ok]"));     // a result that is not an int
  EXPECT_FALSE(set_with("[fgc] [get] 1"));        // not the request's head
  EXPECT_FALSE(set_with("[fgc] [set] 1 [ok]"));   // not YARP's form
  next = Bottle::from_text("[fgc] [set] 1");
  EXPECT_TRUE(client.setActive(CameraFeature::shutter, true));
  EXPECT_TRUE(client.setMode(CameraFeature::shutter, FeatureMode::automatic));
  next = Bottle::from_text("[fgc] [set] 0");
  EXPECT_FALSE(client.setActive(CameraFeature::shutter, true));
  EXPECT_FALSE(client.setMode(CameraFeature::shutter, FeatureMode::automatic));
  ASSERT_EQ(sent.size(), 12u);
  EXPECT_EQ(sent[0].to_text(), "[fgc] [set] [feat] 7 0.25");
}

// A camera client never asks a server that does not say it is Robogene's for its fingerprints
// (YARP 3.12's frame grabbers log "Command not recognized"); a frame grabber has no protocol
// request, so it is asked nothing at all.
TEST(GrabberClient, AsksOnlyARobogeneServerForItsFingerprints) {
  LocalNameServer ns;
  PolyDriver camera;
  ASSERT_TRUE(camera.open(ns.config("(device fake_grabber) (width 64) (height 48)"))) << camera.last_error();
  GrabberServer server(*camera.device());
  std::vector<std::string> sent;
  GrabberClient client([&](const Bottle& request, Bottle& reply) {
    sent.push_back(request.to_text());
    reply = server.respond(request);
    return true;
  });
  EXPECT_TRUE(client.check_server(false).empty());
  EXPECT_TRUE(sent.empty());
  const auto listed = client.check_server(true);
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[0].first, "IFrameGrabberImage");
  EXPECT_EQ(sent, std::vector<std::string>{"[get] [rgif]"});
}

TEST(GrabberNws, OpensYarp35PortNamesAndAnswersOnTheImagePort) {
  LocalNameServer ns;
  ServedCamera served(ns, 10.0);
  // YARP's remote_grabber sends its requests to <name> itself, frameGrabber_nwc_yarp to <name>/rpc.
  PolyDriver client;
  ASSERT_TRUE(client.open(ns.config("(device remote_grabber) (remote /camera) (local /viewer)")))
      << client.last_error();
  Port asker;
  asker.open("/asker", ns.client());
  asker.add_output("/camera", "tcp");
  Bottle reply;
  ASSERT_TRUE(asker.write(Bottle::from_text("[fgi] [get] [w]"), reply));
  EXPECT_EQ(reply.to_text(), "[fgi] [w] [is] 640");
}
