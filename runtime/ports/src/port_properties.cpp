// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The admin message [prop] (reference section 3.4), as YARP 3 ports answer it and as
// `yarp priority-qos` / `yarp priority-sched` and process viewers use it:
//   [prop] [get]                     every user-defined property, as (key value) lists
//   [prop] [get|set] key [value]     one user-defined property
//   [prop] [get] /peer               (sched ((policy p) (priority q) (tid t))) (qos ((tos n)))
//                                    for each connection to or from /peer
//   [prop] [set] /peer (qos ((tos n)))  or ((dscp AF41|n)) or ((priority LOW|NORM|HIGH|CRIT))
//   [prop] [set] /peer (sched ((priority p) (policy q)))   the input thread's scheduling
//   [prop] [get] /thisport           (sched ...) (process ...) (platform ...) (port ...)
//   [prop] [set] /thisport (process ((priority p) (policy q)))   every thread of the process
// QoS is the IP_TOS byte of the connection's own socket; scheduling is Linux's per-thread
// policy and priority (SCHED_OTHER 0, SCHED_FIFO 1, SCHED_RR 2), which need privileges to raise.
#include <dirent.h>
#include <netinet/in.h>
#include <sched.h>
#include <sys/socket.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "port_core.hpp"
#include "robogene/log.hpp"

namespace robogene {

namespace {

std::string word(const Value& v) {
  if (v.is_string()) return v.as_string();
  if (v.is_vocab()) return vocab_to_string(v.as_vocab());
  return "";
}

Bottle fail(const std::string& why) { return Bottle{Value::vocab("fail"), Value(why)}; }
Bottle ok() { return Bottle{Value::vocab("ok")}; }

// (name ((k1 v1) (k2 v2) ...)): YARP's Property written inside a Bottle.
Value group(const std::string& name, std::vector<std::pair<std::string, Value>> fields) {
  Bottle dict;
  for (auto& [k, v] : fields) dict.add(Value(Bottle{Value(k), std::move(v)}));
  return Value(Bottle{Value(name), Value(std::move(dict))});
}

struct Sched {
  int policy = -1, priority = -1;
};

Sched sched_of(int tid) {
  Sched s;
  if (tid < 0) return s;
  int policy = sched_getscheduler(tid);
  sched_param p{};
  if (policy < 0 || sched_getparam(tid, &p) != 0) return s;
  return {policy, p.sched_priority};
}

bool set_sched(int tid, int priority, int policy) {
  if (tid < 0) return false;
  sched_param p{};
  p.sched_priority = priority;
  return sched_setscheduler(tid, policy, &p) == 0;
}

Value sched_group(int tid) {
  Sched s = sched_of(tid);
  return group("sched", {{"policy", Value(s.policy)}, {"priority", Value(s.priority)}, {"tid", Value(tid)}});
}

int type_of_service(int fd) {
  if (fd < 0) return -1;
  int tos = 0;
  socklen_t len = sizeof tos;
  return getsockopt(fd, IPPROTO_IP, IP_TOS, &tos, &len) == 0 ? tos : -1;
}

// A connection that sends nothing of its own (shmem, a udp reader) has nothing to set: fine.
bool set_type_of_service(int fd, int tos) {
  return fd < 0 || setsockopt(fd, IPPROTO_IP, IP_TOS, &tos, sizeof tos) == 0;
}

// DSCP classes by name (RFC 2474, 2597, 3246, 5865).
std::optional<int> dscp_class(const std::string& name) {
  static const std::pair<const char*, int> kClasses[] = {
      {"CS0", 0},   {"CS1", 8},   {"CS2", 16},  {"CS3", 24},  {"CS4", 32},  {"CS5", 40},
      {"CS6", 48},  {"CS7", 56},  {"AF11", 10}, {"AF12", 12}, {"AF13", 14}, {"AF21", 18},
      {"AF22", 20}, {"AF23", 22}, {"AF31", 26}, {"AF32", 28}, {"AF33", 30}, {"AF41", 34},
      {"AF42", 36}, {"AF43", 38}, {"VA", 44},   {"EF", 46}};
  for (auto& [n, v] : kClasses) {
    if (name == n) return v;
  }
  return std::nullopt;
}

// The TOS byte a (qos ((tos n))), ((dscp X)) or ((priority LEVEL)) asks for.
std::optional<int> requested_tos(const Bottle& qos) {
  const Value& tos = qos.find("tos");
  if (tos.is_int()) {
    int v = tos.as_int32();
    if (v >= 0 && v < 256) return v;
    return std::nullopt;
  }
  const Value& dscp = qos.find("dscp");
  if (!dscp.is_null()) {
    std::optional<int> d = dscp.is_int() ? std::optional<int>(dscp.as_int32()) : dscp_class(word(dscp));
    if (d && *d >= 0 && *d < 64) return *d << 2;
    return std::nullopt;
  }
  const std::string level = word(qos.find("priority"));
  static const std::pair<const char*, int> kLevels[] = {{"LOW", 10}, {"NORM", 0}, {"HIGH", 36}, {"CRIT", 44}};
  for (auto& [n, d] : kLevels) {
    if (level == n) return d << 2;
  }
  return std::nullopt;
}

// (sched ((priority p) (policy q))) -> p, q; absent fields are -1 as in YARP.
std::pair<int, int> requested_sched(const Bottle& fields) {
  const Value& prio = fields.find("priority");
  const Value& policy = fields.find("policy");
  return {prio.is_int() ? prio.as_int32() : -1, policy.is_int() ? policy.as_int32() : -1};
}

// The inner list of (name ((k v) ...)) found in `cmd`, or nullptr.
const Bottle* fields_of(const Bottle& cmd, const char* name) {
  const Bottle* g = cmd.find_group(name);
  if (!g || g->size() < 2 || !g->get(1).is_list()) return nullptr;
  return &g->get(1).as_list();
}

std::string read_file(const char* path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Value process_group() {
  // argv[0] is the name, the rest the arguments, as /proc/self/cmdline lists them.
  std::string cmdline = read_file("/proc/self/cmdline");
  std::vector<std::string> argv;
  std::string cur;
  for (char c : cmdline) {
    if (c == '\0') {
      argv.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  std::string args;
  for (std::size_t i = 1; i < argv.size(); ++i) args += (i > 1 ? " " : "") + argv[i];
  Sched s = sched_of(static_cast<int>(getpid()));
  return group("process", {{"arguments", Value(args)},
                           {"name", Value(argv.empty() ? std::string("unknown") : argv[0])},
                           {"pid", Value(static_cast<std::int32_t>(getpid()))},
                           {"policy", Value(s.policy)},
                           {"priority", Value(s.priority)}});
}

Value platform_group(const std::string& host) {
  utsname u{};
  std::string os = uname(&u) == 0 ? u.sysname : "unknown";
  return group("platform", {{"hostname", Value(host)}, {"os", Value(os)}});
}

// Every thread of this process, as YARP's setProcessSchedulingParam does.
bool set_process_sched(int priority, int policy) {
  DIR* dir = opendir("/proc/self/task");
  if (!dir) return false;
  bool all = true;
  while (dirent* e = readdir(dir)) {
    if (e->d_name[0] == '.') continue;
    all = set_sched(std::stoi(e->d_name), priority, policy) && all;
  }
  closedir(dir);
  return all;
}

}  // namespace

void Port::Core::put_property(const std::string& key, const Value& value) {
  Bottle kept;
  for (const Value& item : properties) {
    if (!(item.is_list() && word(item.as_list().get(0)) == key)) kept.add(item);
  }
  kept.add(Value(Bottle{Value(key), value}));
  properties = std::move(kept);
}

void Port::set_property(const std::string& key, const Value& value) {
  std::lock_guard<std::mutex> lock(core_->mutex);
  core_->put_property(key, value);
}

Bottle Port::Core::admin_prop(const Bottle& cmd) {
  const std::string action = word(cmd.get(1));
  const std::string key = word(cmd.get(2));
  const bool is_port = !key.empty() && key[0] == '/';
  std::lock_guard<std::mutex> lock(mutex);

  if (action == "get") {
    if (key.empty()) return properties;
    if (!is_port) {
      const Value& v = properties.find(key);
      return v.is_null() ? Bottle{} : Bottle{v};
    }
    if (key == name) {
      return Bottle{sched_group(acceptor_tid), process_group(), platform_group(address.host),
                    group("port", {{"is_input", Value(used_for_input ? 1 : 0)},
                                   {"is_output", Value(used_for_output ? 1 : 0)},
                                   {"is_rpc", Value(used_for_rpc ? 1 : 0)},
                                   {"type", Value("")}})};  // no declared message type
    }
    Bottle r;
    for (auto& in : inputs) {
      if (in->done || !in->conn || in->from != key) continue;
      r.add(sched_group(in->tid));
      r.add(group("qos", {{"tos", Value(type_of_service(in->conn->socket_fd()))}}));
    }
    for (auto& out : outputs) {
      if (out->target != key || !out->conn) continue;
      r.add(sched_group(-1));  // outputs are written by the writer's thread: none of their own
      r.add(group("qos", {{"tos", Value(type_of_service(out->conn->socket_fd()))}}));
    }
    if (r.empty()) return fail("cannot find any connection to/from " + key);
    return r;
  }

  if (action != "set") return fail("property action not known");  // YARP's words
  if (key.empty()) return fail("[prop] [set] needs a property name or a port name");
  if (!is_port) {
    put_property(key, cmd.get(3));
    return ok();
  }

  const Bottle* qos = fields_of(cmd, "qos");
  const Bottle* sched = fields_of(cmd, "sched");
  const Bottle* process = fields_of(cmd, "process");
  if (!qos && !sched && !process) {
    return fail("[prop] [set] " + key + " needs (qos ((tos n))), (sched ((priority p) (policy q))) or (process (...))");
  }
  if (process) {
    if (key != name) return fail("(process ...) applies to this port's own name, " + name);
    auto [prio, policy] = requested_sched(*process);
    return set_process_sched(prio, policy) ? ok() : fail("cannot set the scheduling of this process");
  }
  std::optional<int> tos;
  if (qos) {
    tos = requested_tos(*qos);
    if (!tos) return fail("(qos ...) needs (tos 0..255), (dscp 0..63 | CS0..CS7 | AF11..AF43 | VA | EF) or (priority LOW|NORM|HIGH|CRIT)");
  }
  bool found = false;
  bool done = true;
  for (auto& in : inputs) {
    if (in->done || !in->conn || in->from != key) continue;
    found = true;
    if (tos) done = set_type_of_service(in->conn->socket_fd(), *tos) && done;
    if (sched) {
      auto [prio, policy] = requested_sched(*sched);
      done = set_sched(in->tid, prio, policy) && done;
    }
  }
  for (auto& out : outputs) {
    if (out->target != key || !out->conn) continue;
    found = true;
    if (tos) done = set_type_of_service(out->conn->socket_fd(), *tos) && done;
    if (sched) done = false;  // no thread of its own to schedule
  }
  if (!found) return fail("cannot find any connection to/from " + key);
  if (!done) log::warn(name, "could not apply " + cmd.to_text());
  return done ? ok() : Bottle{Value::vocab("fail")};
}

}  // namespace robogene
