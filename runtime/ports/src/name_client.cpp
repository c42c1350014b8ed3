// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name_client.hpp"

#include <chrono>
#include <sstream>

#include "robogene/error.hpp"
#include "robogene/name_config.hpp"
#include "robogene/net/stream_reader.hpp"

namespace robogene {

namespace {
const std::string kEnd = "*** end of message";
// A name server's answer is a few lines (a `list` of thousands of ports is a few MB). A peer that
// only pretends to be one must not make a client grow, or wait, without end.
constexpr std::size_t kMaxReplyBytes = 16u << 20;
constexpr int kReplyTimeouts = 4;  // the whole answer must arrive within this many read timeouts
}  // namespace

NameClient::NameClient(net::Endpoint server, net::Millis timeout)
    : server_(std::move(server)), timeout_(timeout) {}

NameClient NameClient::from_config() { return NameClient(NameConfig::load().server); }

std::vector<std::string> NameClient::request(const std::string& line) {
  net::TcpStream s;
  try {
    s = net::TcpStream::connect(server_, timeout_);
  } catch (const NetworkError& e) {
    throw NetworkError(std::string("name server at ") + server_.to_string() + " unreachable: " + e.what());
  }
  s.set_read_timeout(timeout_);
  s.set_write_timeout(timeout_);
  s.write_all(line.data(), line.size());
  net::StreamReader r(s);
  std::vector<std::string> lines;
  std::size_t total = 0;
  const auto deadline = std::chrono::steady_clock::now() + kReplyTimeouts * timeout_;
  for (;;) {
    if (!r.wait_for_data()) break;  // a server may simply close after its answer
    std::string l = r.read_line(1u << 20);
    if (l == kEnd) break;
    total += l.size() + 1;
    if (total > kMaxReplyBytes)
      throw NetworkError("name server at " + server_.to_string() + ": answer longer than " +
                         std::to_string(kMaxReplyBytes) + " bytes without \"" + kEnd + "\"");
    if (std::chrono::steady_clock::now() > deadline)
      throw NetworkError("name server at " + server_.to_string() + ": answer not complete after " +
                         std::to_string(kReplyTimeouts * timeout_.count()) + " ms");
    lines.push_back(std::move(l));
  }
  return lines;
}

std::optional<Contact> NameClient::parse_registration(const std::string& line) {
  std::istringstream in(line);
  std::string w, key;
  if (!(in >> w) || w != "registration") return std::nullopt;
  Contact c;
  bool have_name = false, have_port = false;
  while (in >> key) {
    std::string v;
    if (!(in >> v)) break;
    if (key == "name") { c.name = v; have_name = true; }
    else if (key == "ip") c.host = v;
    else if (key == "port") {
      try { c.port = std::stoi(v); have_port = true; } catch (...) { return std::nullopt; }
    } else if (key == "type") c.carrier = v;
  }
  if (!have_name || !have_port) return std::nullopt;
  return c;
}

std::optional<Contact> NameClient::query(const std::string& name) {
  for (const auto& l : request("NAME_SERVER query " + name + "\n")) {
    auto c = parse_registration(l);
    if (c && c->name == name) return c;
  }
  return std::nullopt;
}

Contact NameClient::register_name(const std::string& name, const std::string& carrier,
                                  const std::string& host, int port) {
  std::string line = "NAME_SERVER register " + name;
  if (!host.empty() || port != 0) {
    line += " " + carrier + " " + (host.empty() ? "..." : host) + " " +
            (port ? std::to_string(port) : "...");
  }
  line += "\r\n";
  auto lines = request(line);
  for (const auto& l : lines) {
    auto c = parse_registration(l);
    if (c) return *c;
  }
  std::string said;
  for (const auto& l : lines) said += (said.empty() ? "" : " / ") + l;
  throw Error("name server at " + server_.to_string() + " refused to register " + name + ": \"" +
              said + "\"");
}

void NameClient::unregister(const std::string& name) { request("NAME_SERVER unregister " + name + "\n"); }

void NameClient::set_property(const std::string& name, const std::string& key,
                              const std::vector<std::string>& values) {
  std::string line = "NAME_SERVER set " + name + " " + key;
  for (const auto& v : values) line += " " + v;
  request(line + "\r\n");
}

}  // namespace robogene
