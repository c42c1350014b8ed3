// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: the name server's commands. Each input line is one request, as a text peer
// types it, applied to a fresh registry. Properties: apply() never throws (bad requests get an
// error reply naming the item at fault); every reply has its text and binary wire forms; a
// request NameService::is_read_only() calls reading changes no registration (the multicast
// fallback and browsers rely on that); and a registration made with an explicit address is
// answered back as registered.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "robogene/error.hpp"
#include "robogene/name/name_service.hpp"
#include "robogene/name/registry.hpp"

using namespace robogene;

namespace {

// Every registration and the properties anyone could have set on it.
std::string snapshot(name::Registry& db) {
  std::string out;
  for (const auto& r : db.list()) {
    out += r.name + " " + r.carrier + " " + r.host + " " + std::to_string(r.port) + " " + r.type + "\n";
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // One registry for the whole run (a fresh SQLite database per input costs most of the time):
  // inputs see each other's registrations, which only widens what they exercise.
  static name::Registry db(":memory:");
  static name::NameService service(db, name::NameServiceConfig{}, nullptr);
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::size_t at = 0;
  for (int n = 0; n < 32 && at < input.size(); ++n) {
    std::size_t end = input.find('\n', at);
    if (end == std::string::npos) end = input.size();
    const std::string line = input.substr(at, end - at);
    at = end + 1;
    Bottle request;
    try {
      request = Bottle::from_text(line);
    } catch (const ParseError&) {
      continue;  // the transports refuse it before the service sees it
    }
    const bool reads = name::NameService::is_read_only(request);
    const std::string before = reads ? snapshot(db) : "";
    name::NameReply reply = service.apply(request, "127.0.0.1");
    (void)reply.to_text_wire();
    (void)reply.to_binary_wire();
    if (reads && snapshot(db) != before) __builtin_trap();  // a "read" that wrote
  }
  // Round trip: what is registered with an explicit address is what a query returns.
  const std::string name = "/fuzz/" + std::to_string(size);
  service.apply(Bottle::from_text("register " + name + " tcp 10.0.0.1 12345"), "127.0.0.1");
  const std::string got = service.apply(Bottle::from_text("query " + name), "127.0.0.1").to_text_wire();
  if (got.find("registration name " + name + " ip 10.0.0.1 port 12345 type tcp") == std::string::npos) {
    __builtin_trap();
  }
  return 0;
}
