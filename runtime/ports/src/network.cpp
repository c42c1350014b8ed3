// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/network.hpp"

#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"

namespace robogene::network {

namespace {

Contact find(NameClient& names, const std::string& name) {
  auto c = names.query(name);
  if (!c) throw Error("port " + name + " is not registered with the name server at " + names.server().to_string());
  return *c;
}

AdminResult result_of(const Bottle& reply) {
  AdminResult r;
  r.ok = reply.get(0).is_int() && reply.get(0).as_int32() == 0;
  if (reply.get(1).is_string()) r.message = reply.get(1).as_string();
  while (!r.message.empty() && (r.message.back() == '\n' || r.message.back() == '\r')) r.message.pop_back();
  if (r.message.empty()) r.message = reply.to_text();
  return r;
}

Bottle exchange(const Contact& port, char key, const Bottle& request, const std::string& carrier,
                const std::string& sender, net::Millis timeout) {
  carrier::ConnectContext ctx;
  ctx.sender_name = sender;
  ctx.target_name = port.name;
  ctx.timeout = timeout;
  auto conn = carrier::open_connection(port.endpoint(), carrier, ctx);
  conn->set_timeout(timeout);
  carrier::OutboundMessage m;
  m.key = key;
  m.bottle = &request;
  Bottle reply;
  conn->send(m, &reply);
  conn->interrupt();  // YARP's tools just hang up after one exchange
  return reply;
}

}  // namespace

Bottle admin(const Contact& port, const Bottle& request, net::Millis timeout) {
  return exchange(port, 'a', request, "text_ack", "admin", timeout);
}

AdminResult connect(NameClient& names, const std::string& source, const std::string& target,
                    const std::string& carrier) {
  Contact src = find(names, source);
  Target t = parse_target(target);
  find(names, t.name);  // fail early, naming the missing port
  std::string car = carrier.empty() ? (t.carrier.empty() ? "tcp" : t.carrier) : carrier;
  Bottle req{Value::vocab("add"), Value(car + ":/" + t.name)};
  return result_of(admin(src, req));
}

AdminResult disconnect(NameClient& names, const std::string& source, const std::string& target) {
  Contact src = find(names, source);
  Bottle req{Value::vocab("del"), Value(parse_target(target).name)};
  return result_of(admin(src, req));
}

Bottle rpc(const Contact& port, const Bottle& request, const std::string& carrier,
           const std::string& sender, net::Millis timeout) {
  return exchange(port, 'd', request, carrier, sender, timeout);
}

}  // namespace robogene::network
