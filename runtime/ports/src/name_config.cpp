// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name_config.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "robogene/error.hpp"

namespace robogene {

namespace {

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

int parse_port(const std::string& text, const std::string& where) {
  char* end = nullptr;
  long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v <= 0 || v > 65535) {
    throw Error(where + ": port \"" + text + "\" is not a number in 1..65535");
  }
  return static_cast<int>(v);
}

bool read_file(const std::string& path, std::string& out) {
  std::ifstream f(path);
  if (!f) return false;
  std::ostringstream s;
  s << f.rdbuf();
  out = s.str();
  return true;
}

}  // namespace

std::string NameConfig::config_dir() {
  std::string d = env("YARP_CONFIG_HOME");
  if (!d.empty()) return d;
  d = env("XDG_CONFIG_HOME");
  if (!d.empty()) return d + "/yarp";
  return env("HOME") + "/.config/yarp";
}

std::string NameConfig::file_name_for(std::string_view ns) {
  if (ns.empty() || ns == "/root") return "yarp.conf";
  std::string out;
  for (char c : ns) out.push_back(std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  return out + ".conf";
}

NameConfig NameConfig::parse(std::string_view text, const std::string& where) {
  NameConfig c;
  c.source = where;
  std::istringstream in{std::string(text)};
  std::string line;
  int number = 0;
  bool in_name_group = false, saw_group = false, done = false;
  while (std::getline(in, line)) {
    ++number;
    auto hash = line.find_first_of("#;");
    if (hash != std::string::npos && line.find('[') == std::string::npos) line.resize(hash);
    auto w = words(line);
    if (w.empty()) continue;
    std::string at = where + ":" + std::to_string(number);
    if (w[0].front() == '[') {
      in_name_group = w[0] == "[name]";
      saw_group = true;
      continue;
    }
    if (saw_group) {
      if (!in_name_group) continue;
      if (w.size() < 2) throw Error(at + ": expected \"<key> <value>\" in [name], got \"" + line + "\"");
      if (w[0] == "host") c.server.host = w[1];
      else if (w[0] == "port") c.server.port = parse_port(w[1], at);
      else if (w[0] == "mode") c.mode = w[1];
      done = true;
      continue;
    }
    if (done) continue;
    if (w.size() < 2) throw Error(at + ": expected \"<host> <port> [mode]\", got \"" + line + "\"");
    c.server.host = w[0];
    c.server.port = parse_port(w[1], at);
    if (w.size() > 2) c.mode = w[2];
    done = true;
  }
  if (!done) throw Error(where + ": no name server address (expected \"<host> <port> [mode]\")");
  return c;
}

NameConfig NameConfig::load() {
  std::string dir = config_dir();
  std::string ns = env("YARP_NAMESPACE");
  if (ns.empty()) {
    std::string text;
    if (read_file(dir + "/yarp_namespace.conf", text)) {
      auto w = words(text);
      if (!w.empty()) ns = w[0];
    }
  }
  if (ns.empty()) ns = "/root";
  std::string path = dir + "/" + file_name_for(ns);
  std::string text;
  if (!read_file(path, text)) {
    throw Error("cannot find the name server: no " + path +
                " (write \"127.0.0.1 10000 yarp\" there, or give the server address explicitly)");
  }
  NameConfig c = parse(text, path);
  c.name_space = ns;
  return c;
}

net::Endpoint NameConfig::parse_server(std::string_view text) {
  auto colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) {
    throw Error("server address \"" + std::string(text) + "\" is not host:port");
  }
  return {std::string(text.substr(0, colon)),
          parse_port(std::string(text.substr(colon + 1)), "server address \"" + std::string(text) + "\"")};
}

}  // namespace robogene
