// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// http carrier: what a web browser gets from a port (YARP's HttpCarrier behaviour): the port's
// page with its connections, data sent from the URL or the page's form, calls answered as text
// or JSON, the live `/r` stream, and bad requests closed cleanly.
#include <gtest/gtest.h>
#include <sys/socket.h>

#include <thread>

#include "../../src/carrier/http_origin.hpp"
#include "robogene/testing/port_test_util.hpp"
#include "robogene/testing/connect_from.hpp"
#include "robogene/testing/wire_helpers.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// Sends one request and reads the whole response (the server closes after it).
std::string http(const Port& p, const std::string& request) {
  auto s = net::TcpStream::connect(p.contact().endpoint());
  send(s, request);
  ::shutdown(s.fd(), SHUT_WR);  // a browser that sent all it will send
  std::string out;
  s.set_read_timeout(5000ms);
  char buf[4096];
  try {
    while (std::size_t n = s.read_some(buf, sizeof buf)) out.append(buf, n);
  } catch (const NetworkError&) {
  }
  return out;
}

std::string body_of(const std::string& response) {
  auto at = response.find("\r\n\r\n");
  return at == std::string::npos ? "" : response.substr(at + 4);
}

// HTTP writes are off by default (docs/security.md); these tests are about what they do when on.
PortOptions http_writes_on() {
  PortOptions o;
  o.access = AccessPolicy().set_http_writes(true);
  return o;
}

struct Echo {
  std::mutex mutex;
  std::vector<std::string> got;
  Port::Reader reader() {
    return [this](const Bottle& b, const MessageInfo& info, Bottle* reply) {
      std::lock_guard<std::mutex> lock(mutex);
      got.push_back(info.from + " " + info.carrier + ": " + b.to_text());
      if (reply) *reply = Bottle::from_text("is " + b.to_text() + " 4 (web_safe \"<b>\")");
    };
  }
};

}  // namespace

TEST(HttpCarrier, RootPageDescribesThePort) {
  PortTable t;
  Port p;
  open_local(p, "/hr", t);
  std::string r = http(p, "GET / HTTP/1.1\r\nHost: x\r\nUser-Agent: test\r\n\r\n");
  EXPECT_EQ(r.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << r;
  EXPECT_NE(r.find("Content-Type: text/html"), std::string::npos);
  std::string body = body_of(r);
  EXPECT_NE(r.find("Content-Length: " + std::to_string(body.size()) + "\r\n"), std::string::npos);
  EXPECT_NE(body.find("<h1>yarp port /hr</h1>"), std::string::npos) << body;
  EXPECT_NE(body.find("This is /hr at tcp://127.0.0.1:" + std::to_string(p.contact().port) + "/"), std::string::npos);
  EXPECT_NE(body.find("There is an input connection from web to /hr using http"), std::string::npos);
}

TEST(HttpCarrier, DataFromTheUrlOrTheFormReachesTheReaderAndItsReplyIsShown) {
  PortTable t;
  Port p(http_writes_on());
  Echo echo;
  p.set_reader(echo.reader());
  open_local(p, "/hr", t);
  std::string r = http(p, "GET /data=1+2+%22a+b%22 HTTP/1.1\r\n\r\n");
  std::string body = body_of(r);
  EXPECT_NE(body.find("is 1 2 &quot;a b&quot; 4 (web_safe &quot;&lt;b&gt;&quot;)"), std::string::npos) << body;
  EXPECT_NE(body.find("name=data value=\"1 2 &quot;a b&quot;\""), std::string::npos) << body;
  std::string form = "data=%5Bset%5D+%5Bpos%5D+1+30.5";
  r = http(p, "POST /form HTTP/1.1\r\nContent-Type: application/x-www-form-urlencoded\r\nContent-Length: " +
                  std::to_string(form.size()) + "\r\n\r\n" + form);
  EXPECT_NE(body_of(r).find("is [set] [pos] 1 30.5 4"), std::string::npos) << r;
  std::lock_guard<std::mutex> lock(echo.mutex);
  ASSERT_EQ(echo.got.size(), 2u);
  EXPECT_EQ(echo.got[0], "web http: 1 2 \"a b\"");
  EXPECT_EQ(echo.got[1], "web http: [set] [pos] 1 30.5");
}

TEST(HttpCarrier, PathCallsAnswerAsTextOrJson) {
  PortTable t;
  Port p(http_writes_on());
  Echo echo;
  p.set_reader(echo.reader());
  open_local(p, "/hr", t);
  // As YARP: the words of the path, then the request target and the fields as lists.
  std::string r = http(p, "GET /get/axes HTTP/1.1\r\n\r\n");
  EXPECT_NE(r.find("Content-Type: text/plain"), std::string::npos) << r;
  EXPECT_EQ(body_of(r), "is get axes (REQUEST_URI \"get/axes\") 4 (web_safe \"<b>\")\r\n");
  r = http(p, "GET /get/axes?format=json HTTP/1.1\r\n\r\n");
  EXPECT_NE(r.find("Content-Type: application/json"), std::string::npos) << r;
  EXPECT_EQ(body_of(r),
            "[\"is\", \"get\", \"axes\", [\"REQUEST_URI\", \"get/axes?format=json\"], [\"format\", \"json\"], 4, "
            "[\"web_safe\", \"<b>\"]]");
  r = http(p, "GET /?req=get+pos+1.5 HTTP/1.1\r\n\r\n");
  EXPECT_EQ(body_of(r),
            "[\"is\", \"get\", \"pos\", 1.5, [\"REQUEST_URI\", \"?req=get+pos+1.5\"], [\"req\", \"get pos 1.5\"], 4, "
            "[\"web_safe\", \"<b>\"]]");
  std::lock_guard<std::mutex> lock(echo.mutex);
  EXPECT_EQ(echo.got.at(0), "web http: get axes (REQUEST_URI \"get/axes\")");
}

TEST(HttpCarrier, ReadStreamsWhatThePortWritesUntilTheBrowserLeaves) {
  log::set_level(log::Level::Off);
  PortTable t;
  Port p;
  open_local(p, "/hw", t);
  auto s = net::TcpStream::connect(p.contact().endpoint());
  send(s, "GET /r HTTP/1.1\r\n\r\n");
  std::string head = read_until(s, "Reading data from port...");
  EXPECT_NE(head.find("Transfer-Encoding: chunked"), std::string::npos) << head;
  for (int i = 0; i < 100 && p.output_names().empty(); ++i) std::this_thread::sleep_for(10ms);
  ASSERT_EQ(p.output_names(), std::vector<std::string>{"web"});
  ASSERT_TRUE(p.write(Bottle::from_text("1 <two> \"three\"")));
  std::string chunk = read_until(s, "three\r\n\r\n");
  EXPECT_NE(chunk.find("\r\n1 &quot;&lt;two&gt;&quot; three\r\n\r\n"), std::string::npos) << chunk;
  s.close();
  // The browser is gone: the next writes fail on that output and it is dropped.
  for (int i = 0; i < 100 && !p.output_names().empty(); ++i) {
    p.write(Bottle::from_text("tick"));
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_TRUE(p.output_names().empty());
  log::set_level(log::Level::Warn);
}

TEST(HttpCarrier, BadRequestsAreClosedAndThePortKeepsServing) {
  log::set_level(log::Level::Off);
  PortTable t;
  Port p;
  open_local(p, "/hr", t);
  EXPECT_EQ(http(p, "GET /" + std::string(20000, 'x') + " HTTP/1.1\r\n\r\n"), "");       // line too long
  EXPECT_EQ(http(p, "POST /form HTTP/1.1\r\nContent-Length: 99999999999\r\n\r\n"), "");   // body too big
  EXPECT_EQ(http(p, "POST /form HTTP/1.1\r\nContent-Length: banana\r\n\r\n"), "");
  EXPECT_EQ(http(p, "GET /data=1 HTTP/1.1\r\nHost: x\r\n"), "");                           // cut short
  EXPECT_EQ(http(p, "GET / HTTP/1.1\r\n\r\n").rfind("HTTP/1.1 200 OK", 0), 0u);
  log::set_level(log::Level::Warn);
}

TEST(HttpCarrier, APortCannotSendOverHttp) {
  PortTable t;
  Port w, r;
  open_local(w, "/hw", t);
  open_local(r, "/hr", t);
  try {
    w.add_output("/hr", "http");
    FAIL() << "connected over http";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("http is how a web browser reaches a port"), std::string::npos) << e.what();
  }
}

// The attack: a web page the user opens sends the browser to http://robot:port/data=... (an
// <img>, a link, a form). Before, that moved the robot and the answer carried
// "Access-Control-Allow-Origin: *" for any page's script to read. Now writes are refused unless
// enabled, and no response invites other origins.
TEST(HttpCarrier, WritesAreRefusedUnlessEnabledAndNoResponseAllowsOtherOrigins) {
  PortTable t;
  Port p;  // default options: HTTP writes off
  Echo echo;
  p.set_reader(echo.reader());
  open_local(p, "/hr", t);
  const std::string form = "data=%5Bset%5D+%5Bpos%5D+1+30.5";
  for (const std::string& request :
       {std::string("GET /data=%5Bset%5D+%5Bpos%5D+1+30.5 HTTP/1.1\r\n\r\n"), std::string("GET /set/pos/1/30.5 HTTP/1.1\r\n\r\n"),
        std::string("GET /?req=set+pos+1+30.5 HTTP/1.1\r\n\r\n"), std::string("GET /a%0A%5Bdel%5D+%2Fx HTTP/1.1\r\n\r\n"),
        std::string("GET /%2Fsomewhere HTTP/1.1\r\n\r\n"),
        "POST /form HTTP/1.1\r\nContent-Type: application/x-www-form-urlencoded\r\nContent-Length: " +
            std::to_string(form.size()) + "\r\n\r\n" + form}) {
    std::string r = http(p, request);
    EXPECT_EQ(r.rfind("HTTP/1.1 403 Forbidden\r\n", 0), 0u) << request << " -> " << r;
    EXPECT_NE(body_of(r).find("HTTP writes to this port are off"), std::string::npos) << r;
    EXPECT_EQ(r.find("Access-Control-Allow-Origin"), std::string::npos) << r;
  }
  // Reading still works: the page, the help, the stream.
  std::string page = http(p, "GET / HTTP/1.1\r\n\r\n");
  EXPECT_EQ(page.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << page;
  EXPECT_EQ(page.find("Access-Control-Allow-Origin"), std::string::npos) << page;
  {
    std::lock_guard<std::mutex> lock(echo.mutex);
    EXPECT_TRUE(echo.got.empty());
  }
  EXPECT_TRUE(p.output_names().empty());

  // Enabled, writes from an allowed peer reach the reader; a stranger is still refused.
  Port q([] {
    PortOptions o;
    o.access = AccessPolicy::parse("127.0.0.1").set_http_writes(true);
    return o;
  }());
  q.set_reader(echo.reader());
  open_local(q, "/hq", t);
  auto s = connect_from("127.0.0.2", q.contact().endpoint());
  send(s, std::string("GET /data=9 HTTP/1.1\r\n\r\n"));
  std::string stranger = read_until(s, "\r\n\r\n");
  EXPECT_EQ(stranger.rfind("HTTP/1.1 403 Forbidden\r\n", 0), 0u) << stranger;
  std::string r = http(q, "GET /data=10 HTTP/1.1\r\n\r\n");
  EXPECT_EQ(r.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << r;
  std::lock_guard<std::mutex> lock(echo.mutex);
  EXPECT_EQ(echo.got, std::vector<std::string>{"web http: 10"});
}

// With writes on, an allowed machine's browser writes; a page of another site that it shows
// must not make it write for that page: a cross-site form or <img> (the browser says so in
// Sec-Fetch-Site, Origin or Referer), or a DNS-rebinding page whose own name points at the
// robot (same-origin, but the Host it names is not one of this machine's). All were served.
TEST(HttpCarrier, EnabledWritesAreRefusedWhenAPageOfAnotherSiteSendsThem) {
  PortTable t;
  Port p(http_writes_on());
  Echo echo;
  p.set_reader(echo.reader());
  open_local(p, "/hx", t);
  const std::string at = "127.0.0.1:" + std::to_string(p.contact().port);
  auto get = [&](const std::string& value, const std::string& headers) {
    return http(p, "GET /data=" + value + " HTTP/1.1\r\n" + headers + "\r\n");
  };
  const std::pair<std::string, std::string> refused[] = {
      {"Host: " + at + "\r\nOrigin: http://evil.example\r\n", "a page of http://evil.example sent it"},
      {"Host: " + at + "\r\nSec-Fetch-Site: cross-site\r\n", "(Sec-Fetch-Site: cross-site)"},
      {"Host: " + at + "\r\nReferer: http://evil.example/page.html\r\n", "the page http://evil.example/page.html"},
      {"Host: " + at + "\r\nOrigin: null\r\n", "a page of null sent it"},
      {"Host: evil.example:" + std::to_string(p.contact().port) + "\r\nOrigin: http://evil.example:" +
           std::to_string(p.contact().port) + "\r\nSec-Fetch-Site: same-origin\r\n",
       "names the host \"evil.example\", which is not an address or a name of this machine"},
  };
  for (const auto& [headers, why] : refused) {
    std::string r = get("1", headers);
    EXPECT_EQ(r.rfind("HTTP/1.1 403 Forbidden\r\n", 0), 0u) << headers << " -> " << r;
    EXPECT_NE(body_of(r).find(why), std::string::npos) << headers << " -> " << r;
  }
  // Reading from another site's page still works (the page, nothing written).
  std::string page = http(p, "GET / HTTP/1.1\r\nHost: " + at + "\r\nOrigin: http://evil.example\r\n\r\n");
  EXPECT_EQ(page.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << page;
  // The port's own page, a typed address, localhost, this machine's name, a client without headers.
  const std::string served[] = {
      "Host: " + at + "\r\nOrigin: http://" + at + "\r\nReferer: http://" + at + "/\r\nSec-Fetch-Site: same-origin\r\n",
      "Host: " + at + "\r\nSec-Fetch-Site: none\r\n",
      "Host: localhost:" + std::to_string(p.contact().port) + "\r\n",
      "Host: " + carrier::detail::this_machine_names().at(0) + "\r\n",
      "",
  };
  int n = 0;
  for (const std::string& headers : served) {
    std::string r = get(std::to_string(++n), headers);
    EXPECT_EQ(r.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << headers << " -> " << r;
  }
  std::lock_guard<std::mutex> lock(echo.mutex);
  EXPECT_EQ(echo.got, (std::vector<std::string>{"web http: 1", "web http: 2", "web http: 3", "web http: 4",
                                                "web http: 5"}));
}
