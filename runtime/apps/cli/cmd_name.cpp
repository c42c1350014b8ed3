// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene name ...`: talk to the name server as `yarp name` does, printing its replies.
#include <cstdio>

#include "commands.hpp"
#include "yarp_conf.hpp"
#include "robogene/error.hpp"
#include "robogene/name_client.hpp"

namespace robogene::cli {
namespace {

struct NameServerReply {
  std::vector<std::string> lines;  // "*** end of message" and error lines excluded
  std::string error;               // text of a "*** error: ..." line, if any
};

NameServerReply name_request(const net::Endpoint& server, const std::string& request) {
  NameServerReply reply;
  try {
    for (auto& line : NameClient(server).request("NAME_SERVER " + request + "\n")) {
      if (line.rfind("*** error: ", 0) == 0) {
        reply.error = line.substr(11);
      } else {
        reply.lines.push_back(std::move(line));
      }
    }
  } catch (const NetworkError& e) {
    throw NetworkError(std::string(e.what()) + " (is `robogene server` running? --server HOST:PORT or " +
                       yarp_conf_path() + " says where it is)");
  }
  return reply;
}

void print_lines(const NameServerReply& r) {
  for (const auto& line : r.lines) std::printf("%s\n", line.c_str());
  std::printf("*** end of message\n");
}

// Fails with the server's own explanation when it sent one.
void check_error(const NameServerReply& r) {
  if (!r.error.empty()) throw Error("the name server says: " + r.error);
}

std::string join(const std::vector<std::string>& words, std::size_t from) {
  std::string out;
  for (std::size_t i = from; i < words.size(); ++i) {
    if (i > from) out += ' ';
    // Words with spaces or quotes travel quoted, as a bottle string.
    if (words[i].find_first_of(" \t\"\\") != std::string::npos || words[i].empty()) {
      out += '"';
      for (char c : words[i]) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
      }
      out += '"';
    } else {
      out += words[i];
    }
  }
  return out;
}

void need(const std::vector<std::string>& w, std::size_t n, const char* usage) {
  if (w.size() < n) throw UsageError(std::string("usage: robogene name ") + usage);
}

}  // namespace

int cmd_name(Args& args) {
  net::Endpoint server = name_server_address(args);
  std::vector<std::string> w = args.positional();
  if (w.empty()) throw UsageError("robogene name needs a sub-command: query, list, register, unregister, set, get, check");
  const std::string& sub = w[0];
  if (sub == "query") {
    need(w, 2, "query /port");
    NameServerReply r = name_request(server, join(w, 0));
    check_error(r);
    if (r.lines.empty()) throw Error("port " + w[1] + " is not registered with the name server at " + server.to_string());
    std::printf("%s\n\n", r.lines[0].c_str());
    return 0;
  }
  if (sub == "register") {
    need(w, 2, "register /port [carrier ip portnumber [type]]");
    NameServerReply r = name_request(server, join(w, 0));
    check_error(r);
    if (r.lines.empty()) throw Error("the name server at " + server.to_string() + " did not register " + w[1]);
    std::printf("%s\n\n", r.lines[0].c_str());
    return 0;
  }
  if (sub == "unregister") {
    need(w, 2, "unregister /port");
    NameServerReply q = name_request(server, "query " + join(w, 1));
    check_error(q);
    if (q.lines.empty()) throw Error("port " + w[1] + " is not registered with the name server at " + server.to_string());
    NameServerReply r = name_request(server, join(w, 0));
    check_error(r);
    std::printf("Unregistered name.\n");
    return 0;
  }
  if (sub == "list" || sub == "check" || sub == "get" || sub == "set" || sub == "route" || sub == "help" ||
      sub == "gc" || sub == "runners") {
    if (sub == "check") need(w, 4, "check /port property value");
    if (sub == "get") need(w, 3, "get /port property");
    if (sub == "set") need(w, 3, "set /port property value...");
    if (sub == "route") need(w, 3, "route /from /to");
    NameServerReply r = name_request(server, join(w, 0));
    check_error(r);
    print_lines(r);
    return 0;
  }
  throw UsageError("unknown name sub-command \"" + sub +
                   "\" (try query, list, register, unregister, set, get, check, route, gc, help)");
}

}  // namespace robogene::cli
