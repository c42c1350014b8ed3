// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/name_service.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>

#include <algorithm>
#include <chrono>
#include <future>
#include <utility>

#include "robogene/error.hpp"
#include "robogene/net/tcp_listener.hpp"

namespace robogene::name {
namespace {

double now_seconds() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

// yarpserver reads command words and names with toString(): a string as is, anything else in
// its text form (so `[list]` typed as a vocab does not match `list`).
std::string word(const Value& v) { return v.is_string() ? v.as_string() : v.to_text(); }

// How a property value is stored: strings as they are, other items in text form (Value::toString).
std::string stored_form(const Value& v) { return v.is_string() ? v.as_string() : v.to_text(); }

// Turns a stored property value back into a Value for bottle-mode replies (Value::fromString).
Value parsed_form(const std::string& text) {
  try {
    Bottle b = Bottle::from_text(text);
    if (b.size() == 1) return b[0];
  } catch (const Error&) {
  }
  return Value::string(text);
}

Bottle pair(const char* key, Value v) {
  Bottle b;
  b.add(Value::string(key));
  b.add(std::move(v));
  return b;
}

Bottle bottle_of_strings(std::initializer_list<std::string> items) {
  Bottle b;
  for (const auto& s : items) b.add(Value::string(s));
  return b;
}

// Whether a port could listen on host:port right now. Only answerable for this machine's loopback
// or the server's own address; elsewhere every number is assumed usable.
// Only numeric addresses are tried: a name would cost a DNS lookup per candidate number, and a
// peer registering "127.0.0tcp" stalled the server for minutes (found by name_service_fuzz).
bool bindable(const std::string& host, const std::string& server_host, int port) {
  const std::string address = host == "localhost" ? "127.0.0.1" : host;
  in_addr a{};
  if (inet_pton(AF_INET, address.c_str(), &a) != 1) return true;
  if ((ntohl(a.s_addr) >> 24) != 127 && address != server_host) return true;
  try {
    net::TcpListener::listen(net::Endpoint{address, port}, 1);
    return true;
  } catch (const Error&) {
    return false;  // in use by another program (or its connections): hand out another number
  }
}

}  // namespace

// A request with its `NAME_SERVER` / `bot` prefixes removed; `offset` maps back to item numbers
// of the original request for error messages.
struct NameService::Request {
  Bottle items;
  std::size_t offset = 0;
  bool bottle_mode = false;
  std::string remote_host;
  std::string original_text;

  std::string key() const { return items.empty() ? std::string() : word(items[0]); }
  std::size_t size() const { return items.size(); }
  const Value& at(std::size_t i) const { return items.get(i); }
  // 1-based item number in the original request, for messages.
  std::size_t item_number(std::size_t i) const { return offset + i + 1; }
};

NameService::NameService(Registry& registry, NameServiceConfig config, LivenessProbe* probe)
    : registry_(registry), config_(std::move(config)), probe_(probe) {
  Registration root;
  root.name = "/root";
  root.carrier = "tcp";
  root.host = config_.host;
  root.port = config_.port;
  root.type = "*";
  root.registered_at = now_seconds();
  registry_.put(root);
}

NameReply NameService::error(const Request& r, const std::string& message) {
  NameReply reply;
  std::string text = message + " (in \"" + r.original_text + "\"; send \"help\" for the commands)";
  if (r.bottle_mode) {
    reply.old_style = false;
    reply.bottle.add(Value::string("error"));
    reply.bottle.add(Value::string(text));
  } else {
    reply.lines.push_back("*** error: " + text);
  }
  return reply;
}

bool NameService::is_read_only(const Bottle& request) {
  std::size_t at = 0;
  if (at < request.size() && word(request[at]) == "NAME_SERVER") ++at;
  if (at < request.size() && word(request[at]) == "bot") ++at;
  if (at >= request.size()) return true;  // the empty request: answered with an error
  const std::string key = word(request[at]);
  for (const char* reader : {"help", "list", "query", "get", "check", "route", "runners"}) {
    if (key == reader) return true;
  }
  return false;
}

NameReply NameService::apply(const Bottle& request, const std::string& remote_host) {
  Request r;
  r.remote_host = remote_host;
  r.original_text = request.to_text();
  r.items = request;
  auto strip = [&r](const char* prefix) {
    if (!r.items.empty() && word(r.items[0]) == prefix) {
      Bottle rest;
      for (std::size_t i = 1; i < r.items.size(); ++i) rest.add(r.items[i]);
      r.items = std::move(rest);
      ++r.offset;
      return true;
    }
    return false;
  };
  strip("NAME_SERVER");
  r.bottle_mode = strip("bot");

  const std::string key = r.key();
  try {
    if (key.empty()) return error(r, "empty request");
    if (key == "help") return cmd_help(r);
    if (key == "list") return cmd_list(r);
    if (key == "query") return cmd_query(r);
    if (key == "register") return cmd_register(r);
    if (key == "unregister") return cmd_unregister(r);
    if (key == "set") return cmd_set(r);
    if (key == "get") return cmd_get(r);
    if (key == "check") return cmd_check(r);
    if (key == "route") return cmd_route(r);
    if (key == "announce") return cmd_announce(r);
    if (key == "runners") return cmd_runners(r);
    if (key == "gc") return cmd_gc(r);
  } catch (const Error& e) {
    return error(r, e.what());
  }
  return error(r, "unknown command \"" + key + "\" at item " + std::to_string(r.item_number(0)));
}

NameReply NameService::cmd_help(const Request& r) {
  static const char* const lines[] = {
      "The name server (/root) knows where every port listens. Commands:",
      "+ help",
      "+ list [$prefix]                     every port, or those under $prefix",
      "+ register $port                     pick a port number and use the caller's IP",
      "+ register $port $carrier $ip $portnumber [$type]   ('...' = pick it for me)",
      "+ unregister $port",
      "+ query $port",
      "+ set $port $property $value...",
      "+ get $port $property",
      "+ check $port $property $value",
      "+ route $port1 $port2",
      "+ announce $port",
      "+ runners                            ports with property yarprun = true",
      "+ gc                                 drop registrations whose owner is gone",
      "Prefix a command with 'bot' for a Bottle reply instead of text lines.",
  };
  NameReply reply;
  if (r.bottle_mode) {
    reply.old_style = false;
    for (std::size_t i = 1; i < sizeof(lines) / sizeof(lines[0]); ++i) reply.bottle.add(Value::string(lines[i]));
  } else {
    reply.lines.assign(std::begin(lines), std::end(lines));
  }
  return reply;
}

bool NameService::probe_applies(const Registration& reg) const {
  if (!probe_ || reg.name == "/root") return false;
  if (reg.carrier != "tcp" && reg.carrier != "fast_tcp" && reg.carrier != "text" && reg.carrier != "text_ack") {
    return false;  // connectionless or foreign registrations cannot be probed with a tcp handshake
  }
  return now_seconds() - reg.registered_at >= config_.stale_grace_seconds;
}

std::vector<Registration> NameService::drop_stale(std::vector<Registration> regs) {
  std::vector<std::size_t> to_probe;
  const auto now = std::chrono::steady_clock::now();
  {
    std::lock_guard<std::mutex> lock(seen_mutex_);
    for (std::size_t i = 0; i < regs.size(); ++i) {
      if (!probe_applies(regs[i])) continue;
      auto it = seen_alive_.find(regs[i].name);
      if (it != seen_alive_.end() &&
          std::chrono::duration<double>(now - it->second).count() < config_.recheck_seconds) {
        continue;
      }
      to_probe.push_back(i);
    }
  }
  if (to_probe.empty()) return regs;

  // Probes run in parallel, a bounded batch at a time, so that one silent host does not make a
  // `list` wait for every other port's timeout in turn.
  constexpr std::size_t kBatch = 16;
  std::vector<Liveness> verdict(to_probe.size(), Liveness::Unknown);
  for (std::size_t start = 0; start < to_probe.size(); start += kBatch) {
    std::vector<std::future<Liveness>> running;
    const std::size_t end = std::min(to_probe.size(), start + kBatch);
    for (std::size_t k = start; k < end; ++k) {
      const Registration reg = regs[to_probe[k]];
      running.push_back(std::async(std::launch::async, [this, reg] { return probe_->probe(reg); }));
    }
    for (std::size_t k = start; k < end; ++k) verdict[k] = running[k - start].get();
  }

  std::vector<bool> dropped(regs.size(), false);
  {
    std::lock_guard<std::mutex> lock(seen_mutex_);
    for (std::size_t k = 0; k < to_probe.size(); ++k) {
      const Registration& reg = regs[to_probe[k]];
      if (verdict[k] == Liveness::Alive) {
        seen_alive_[reg.name] = now;
      } else if (verdict[k] == Liveness::Dead) {
        seen_alive_.erase(reg.name);
        if (registry_.remove_if_unchanged(reg)) dropped[to_probe[k]] = true;
      }
    }
  }
  std::vector<Registration> kept;
  for (std::size_t i = 0; i < regs.size(); ++i) {
    if (!dropped[i]) kept.push_back(std::move(regs[i]));
  }
  return kept;
}

std::vector<std::string> NameService::sweep() {
  std::vector<Registration> before = registry_.list();
  std::vector<Registration> after = drop_stale(before);
  std::vector<std::string> gone;
  std::size_t j = 0;
  for (const auto& reg : before) {
    if (j < after.size() && after[j].name == reg.name) {
      ++j;
    } else {
      gone.push_back(reg.name);
    }
  }
  return gone;
}

NameReply NameService::describe(const std::vector<Registration>& regs, bool bottle_mode, bool listing) {
  NameReply reply;
  reply.old_style = !bottle_mode;
  auto port_bottle = [](const Registration& reg) {
    Bottle b;
    b.add(Value::string("port"));
    b.add(Value::list(pair("name", Value::string(reg.name))));
    b.add(Value::list(pair("ip", Value::string(reg.host))));
    b.add(Value::list(pair("port_number", Value::int32(reg.port))));
    b.add(Value::list(pair("carrier", Value::string(reg.carrier))));
    return b;
  };
  if (!bottle_mode) {
    for (const auto& reg : regs) {
      Bottle line = bottle_of_strings({"registration", "name", reg.name, "ip", reg.host, "port"});
      line.add(Value::int32(reg.port));
      line.add(Value::string("type"));
      line.add(Value::string(reg.carrier));
      reply.lines.push_back(old_style_line(line));
    }
    return reply;
  }
  if (listing) {
    reply.bottle.add(Value::string("ports"));
    for (const auto& reg : regs) reply.bottle.add(Value::list(port_bottle(reg)));
  } else if (!regs.empty()) {
    reply.bottle = port_bottle(regs.front());
  } else {
    Bottle err;
    err.add(Value::string("error"));
    err.add(Value::int32(-2));
    err.add(Value::string("port not known"));
    reply.bottle.add(Value::string("port"));
    reply.bottle.add(Value::list(err));
  }
  return reply;
}

namespace {

// The port name at item `i`, which must be a string starting with '/' unless `allow_auto`
// permits yarpserver's "..." and "=suffix" forms.
std::string port_name_at(const Bottle& items, std::size_t i, std::size_t item_number, bool allow_auto) {
  const Value& v = items.get(i);
  if (v.is_null()) throw Error("missing port name at item " + std::to_string(item_number));
  if (!v.is_string()) {
    throw Error("item " + std::to_string(item_number) + " should be a port name, not " + type_name(v.type()) +
                " " + v.to_text());
  }
  const std::string& s = v.as_string();
  if (allow_auto && (s == "..." || (!s.empty() && s[0] == '='))) return s;
  if (s.empty() || s[0] != '/') {
    throw Error("item " + std::to_string(item_number) + " \"" + s + "\" is not a port name (it must start with '/')");
  }
  if (s.find_first_of(" \t\r\n\"") != std::string::npos) {
    throw Error("item " + std::to_string(item_number) + " \"" + s + "\": a port name cannot contain spaces or quotes");
  }
  return s;
}

void require_count(const Bottle& items, std::size_t at_least, std::size_t offset, const char* usage) {
  if (items.size() < at_least) {
    throw Error(std::string("expected ") + usage + ", missing item " + std::to_string(offset + items.size() + 1));
  }
}

}  // namespace

NameReply NameService::cmd_list(const Request& r) {
  std::string prefix;
  if (r.size() > 1) prefix = word(r.at(1));
  std::vector<Registration> all = registry_.list();
  std::vector<Registration> chosen;
  for (auto& reg : all) {
    if (prefix.empty()) {
      chosen.push_back(std::move(reg));
      continue;
    }
    // yarpserver's rule: /motors lists /motors and /motors/..., not /motorsX; /motors/ lists all below.
    if (reg.name.compare(0, prefix.size(), prefix) != 0) continue;
    if (reg.name.size() == prefix.size() || reg.name[prefix.size()] == '/' || prefix.back() == '/') {
      chosen.push_back(std::move(reg));
    }
  }
  return describe(drop_stale(std::move(chosen)), r.bottle_mode, true);
}

NameReply NameService::cmd_query(const Request& r) {
  std::string name = port_name_at(r.items, 1, r.item_number(1), false);
  std::vector<Registration> found;
  if (auto reg = registry_.find(name)) found.push_back(*reg);
  return describe(drop_stale(std::move(found)), r.bottle_mode, false);
}

NameReply NameService::cmd_register(const Request& r) {
  std::string name = port_name_at(r.items, 1, r.item_number(1), true);
  std::string carrier = r.size() > 2 ? word(r.at(2)) : "...";
  if (carrier == "...") carrier = "tcp";
  std::string host = r.size() > 3 ? word(r.at(3)) : "...";
  int port = 0;
  if (r.size() > 4) {
    const Value& p = r.at(4);
    if (p.is_int()) {
      long long n = p.as_int64();
      if (n < -1 || n > 65535) {
        throw Error("item " + std::to_string(r.item_number(4)) + ": port number " + std::to_string(n) +
                    " is outside 0..65535");
      }
      port = n < 0 ? 0 : static_cast<int>(n);
    } else if (!(p.is_string() && p.as_string() == "...")) {
      throw Error("item " + std::to_string(r.item_number(4)) + " should be a port number or '...', not " +
                  p.to_text());
    }
  }
  std::string type = r.size() > 5 ? word(r.at(5)) : "*";
  if (carrier.empty() || carrier.find_first_of(" \t\r\n\"") != std::string::npos) {
    throw Error("item " + std::to_string(r.item_number(2)) + ": \"" + carrier + "\" is not a carrier name");
  }

  std::lock_guard<std::mutex> lock(mutex_);
  if (name == "...") {
    name = registry_.allocate_name();
  } else if (name[0] == '=') {
    name = registry_.allocate_name() + name;
  }
  if (name == "/root") throw Error("/root is the name server's own name and cannot be registered again");
  if (host == "...") {
    host = carrier == "mcast" ? registry_.allocate_mcast_host()
                              : (r.remote_host.empty() ? std::string("localhost") : r.remote_host);
  }
  if (port == 0) {
    // A re-registration may keep its own number: free it first by forgetting the old entry.
    registry_.remove(name);
    port = registry_.allocate_port(name, config_.port + config_.first_offset, config_.port + config_.last_offset,
                                   [&](int n) { return bindable(host, config_.host, n); });
  }
  Registration reg;
  reg.name = name;
  reg.carrier = carrier;
  reg.host = host;
  reg.port = port;
  reg.type = type;
  reg.registered_at = now_seconds();
  registry_.put(reg);
  {
    std::lock_guard<std::mutex> seen(seen_mutex_);
    seen_alive_.erase(name);
  }
  return describe({reg}, r.bottle_mode, false);
}

NameReply NameService::cmd_unregister(const Request& r) {
  std::string name = port_name_at(r.items, 1, r.item_number(1), false);
  if (name == "/root") throw Error("/root is the name server itself and cannot be unregistered");
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // What the port owns (its mcast groups, `set /w owns /tmp/port/1`) goes with it, as in yarpserver.
    for (const auto& owned : registry_.get_property(name, "owns")) {
      if (owned != "/root" && owned != name) registry_.remove(owned);
    }
    registry_.remove(name);
  }
  std::lock_guard<std::mutex> seen(seen_mutex_);
  seen_alive_.erase(name);
  return describe({}, r.bottle_mode, false);
}

NameReply NameService::cmd_set(const Request& r) {
  require_count(r.items, 3, r.offset, "set $port $property $value...");
  std::string name = port_name_at(r.items, 1, r.item_number(1), false);
  std::string key = word(r.at(2));
  std::vector<std::string> values;
  for (std::size_t i = 3; i < r.size(); ++i) values.push_back(stored_form(r.at(i)));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!registry_.set_property(name, key, values)) throw Error("port " + name + " is not registered");
  }
  Request get = r;
  get.items = Bottle{Value::string("get"), Value::string(name), Value::string(key)};
  return cmd_get(get);
}

NameReply NameService::cmd_get(const Request& r) {
  require_count(r.items, 3, r.offset, "get $port $property");
  std::string name = port_name_at(r.items, 1, r.item_number(1), false);
  std::string key = word(r.at(2));
  if (!registry_.find(name)) throw Error("port " + name + " is not registered");
  std::vector<std::string> values = registry_.get_property(name, key);
  NameReply reply;
  if (r.bottle_mode) {
    reply.old_style = false;
    for (const auto& v : values) reply.bottle.add(parsed_form(v));
    return reply;
  }
  Bottle line = bottle_of_strings({"port", name, "property", key, "="});
  for (const auto& v : values) line.add(Value::string(v));
  reply.lines.push_back(old_style_line(line));
  return reply;
}

NameReply NameService::cmd_check(const Request& r) {
  require_count(r.items, 4, r.offset, "check $port $property $value");
  std::string name = port_name_at(r.items, 1, r.item_number(1), false);
  std::string key = word(r.at(2));
  std::string value = stored_form(r.at(3));
  if (!registry_.find(name)) throw Error("port " + name + " is not registered");
  std::vector<std::string> values = registry_.get_property(name, key);
  bool present = std::find(values.begin(), values.end(), value) != values.end();
  // yarpserver answers check in text lines even after `bot`.
  NameReply reply;
  reply.lines.push_back(old_style_line(
      bottle_of_strings({"port", name, "property", key, "value", value, "present", present ? "true" : "false"})));
  return reply;
}

NameReply NameService::cmd_route(const Request& r) {
  require_count(r.items, 3, r.offset, "route $port1 $port2");
  std::string from = port_name_at(r.items, 1, r.item_number(1), false);
  std::string to = port_name_at(r.items, 2, r.item_number(2), false);
  NameReply reply;
  reply.lines.push_back(old_style_line(bottle_of_strings({"port", from, "route", to, "=", "tcp:/" + to})));
  return reply;
}

NameReply NameService::cmd_announce(const Request& r) {
  port_name_at(r.items, 1, r.item_number(1), false);
  NameReply reply;
  reply.old_style = false;
  reply.bottle.add(Value::vocab("ok"));
  return reply;
}

NameReply NameService::cmd_runners(const Request& r) {
  std::vector<Registration> runners;
  for (const auto& name : registry_.names_with_property("yarprun", "true")) {
    if (auto reg = registry_.find(name)) runners.push_back(*reg);
  }
  return describe(drop_stale(std::move(runners)), r.bottle_mode, true);
}

NameReply NameService::cmd_gc(const Request& r) {
  std::vector<std::string> gone = sweep();
  NameReply reply;
  if (r.bottle_mode) {
    reply.old_style = false;
    reply.bottle.add(Value::string("dropped"));
    for (const auto& g : gone) reply.bottle.add(Value::string(g));
    return reply;
  }
  reply.lines.push_back("garbage collection done: " + std::to_string(gone.size()) + " stale registration" +
                        (gone.size() == 1 ? "" : "s") + " dropped");
  for (const auto& g : gone) reply.lines.push_back("dropped " + g);
  return reply;
}

}  // namespace robogene::name
