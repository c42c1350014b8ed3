// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Administrative messages (reference section 3.4), as `yarp connect` / `yarp disconnect` and
// remote_controlboard send them: [help] [ver] [add] [del] [list] [in|out]; [prop] is in
// port_properties.cpp.
#include <string>

#include "port_core.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/log.hpp"

namespace robogene {

namespace {

// Commands and arguments may come as vocabs ([add]) or strings ("add").
std::string word(const Value& v) {
  if (v.is_string()) return v.as_string();
  if (v.is_vocab()) return vocab_to_string(v.as_vocab());
  if (v.is_null()) return "";
  return v.to_text();
}

void describe_route(Bottle& out, const std::string& from, const std::string& to,
                    const std::string& carrier) {
  out.add(Value::list(Bottle{Value("from"), Value(from)}));
  out.add(Value::list(Bottle{Value("to"), Value(to)}));
  out.add(Value::list(Bottle{Value("carrier"), Value(carrier)}));
  auto c = carrier::CarrierRegistry::global().find(carrier);
  if (c && c->is_connectionless()) out.add(Value::list(Bottle{Value("connectionless"), Value(1)}));
}

Bottle fail(const std::string& why) { return Bottle{Value::vocab("fail"), Value(why)}; }

// "127.0.0.1:40012" -> "127.0.0.1".
std::string host_of(const std::string& peer_text) { return peer_text.substr(0, peer_text.rfind(':')); }

}  // namespace

bool Port::Core::is_end_of(const std::string& target, const std::string& peer_host) const {
  std::lock_guard<std::mutex> lock(mutex);
  for (auto& in : inputs) {
    if (!in->done && in->from == target && in->peer_host == peer_host) return true;
  }
  for (auto& o : outputs) {
    if (o->target == target && o->conn && host_of(o->conn->peer_text()) == peer_host) return true;
  }
  return false;
}

Bottle Port::Core::admin(const Bottle& cmd, const std::string& peer_host) {
  const std::string op = word(cmd.get(0));
  // [add] and [prop] [set] are control; [del] also, except from the host at the other end of
  // the connection it drops (a writer on another machine closing its udp input here).
  const bool control = op == "add" || op == "del" || (op == "prop" && word(cmd.get(1)) == "set");
  if (control && !access.allows(peer_host) && !(op == "del" && is_end_of(word(cmd.get(1)), peer_host))) {
    const std::string why = refusal_text("[" + op + "]", peer_host);
    log::warn(name, why);
    if (op == "prop") return fail(why);
    return Bottle{Value(-1), Value(why + "\r\n")};
  }
  if (op == "help") {
    Bottle r;
    r.add(Value::vocab("many"));
    for (const char* line : {
             "[help]                  # this list",
             "[ver]                   # version of the administrative protocol",
             "[add] $portname         # add an output connection",
             "[add] $portname $car    # add an output with a given carrier",
             "[del] $portname         # remove an input or output connection",
             "[list] [in]             # list input connections",
             "[list] [out]            # list output connections",
             "[list] [in]  $portname  # details of one input",
             "[list] [out] $portname  # details of one output",
             "[prop] [get]            # every user-defined port property",
             "[prop] [get] $prop      # one user-defined port property",
             "[prop] [set] $prop $val # set a user-defined port property",
             "[prop] [get] $portname  # scheduling and QoS of the connection to/from $portname",
             "[prop] [set] $portname (qos ((tos $n))) | (sched ((priority $p) (policy $q)))",
             "[prop] [get] $thisport  # this port's thread, process and platform",
         }) {
      r.add(Value(std::string(line)));
    }
    return r;
  }
  if (op == "ver") return Bottle{Value::vocab("ver"), Value(1), Value(2), Value(3)};
  if (op == "add") {
    std::string target = word(cmd.get(1));
    std::string carrier = word(cmd.get(2));
    if (target.empty()) return Bottle{Value(-1), Value(std::string("[add] needs a port name\r\n"))};
    if (!carrier.empty()) target = carrier + ":/" + target;
    std::string report;
    bool ok = add_output_report(target, report);
    return Bottle{Value(ok ? 0 : -1), Value(report)};
  }
  if (op == "del") {
    std::string target = word(cmd.get(1));
    std::string r1, r2;
    bool out = remove_output_report(target, r1);
    bool in = remove_input_report(target, r2);
    std::string report = out && !in ? r1 : (!out && in ? r2 : r1 + r2);
    return Bottle{Value(out || in ? 0 : -1), Value(report)};
  }
  if (op == "list") {
    std::string dir = word(cmd.get(1));
    std::string target = word(cmd.get(2));
    if (dir != "in" && dir != "out") return fail("[list] must be followed by [in] or [out]");
    Bottle r;
    std::lock_guard<std::mutex> lock(mutex);
    if (dir == "out") {
      for (auto& o : outputs) {
        if (target.empty()) r.add(Value(o->target));
        else if (o->target == target) describe_route(r, name, o->target, o->carrier);
      }
    } else {
      for (auto& in : inputs) {
        if (in->done || !in->conn) continue;
        if (target.empty()) r.add(Value(in->from));
        else if (in->from == target) describe_route(r, in->from, name, in->carrier);
      }
    }
    return r;
  }
  if (op == "prop") return admin_prop(cmd);
  return fail("send [help] for list of valid commands");
}

}  // namespace robogene
