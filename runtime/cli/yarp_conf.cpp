// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "yarp_conf.hpp"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "robogene/error.hpp"

namespace robogene::cli {
namespace {

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

}  // namespace

void ensure_directory(const std::string& path) {
  for (std::size_t i = 1; i <= path.size(); ++i) {
    if (i == path.size() || path[i] == '/') {
      std::string part = path.substr(0, i);
      if (::mkdir(part.c_str(), 0755) != 0 && errno != EEXIST) {
        throw Error("cannot create directory " + part + ": " + std::strerror(errno));
      }
    }
  }
}

std::string yarp_config_dir() {
  std::string dir = env("YARP_CONFIG_HOME");
  if (!dir.empty()) return dir;
  dir = env("XDG_CONFIG_HOME");
  if (!dir.empty()) return dir + "/yarp";
  return env("HOME") + "/.config/yarp";
}

std::string yarp_conf_path() {
  std::string ns = env("YARP_NAMESPACE");
  if (ns.empty() || ns == "/root") return yarp_config_dir() + "/yarp.conf";
  for (char& c : ns) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return yarp_config_dir() + "/" + ns + ".conf";
}

std::optional<net::Endpoint> read_yarp_conf() {
  const std::string path = yarp_conf_path();
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::string line;
  int number = 0;
  bool in_name_section = false;
  net::Endpoint e;
  bool have_host = false, have_port = false;
  while (std::getline(in, line)) {
    ++number;
    auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    if (first.front() == '[') {
      in_name_section = first == "[name]";
      continue;
    }
    std::string second;
    words >> second;
    if (in_name_section || first == "host" || first == "port") {
      if (first == "host") {
        e.host = second;
        have_host = !second.empty();
      } else if (first == "port") {
        char* end = nullptr;
        long p = std::strtol(second.c_str(), &end, 10);
        if (second.empty() || *end || p < 1 || p > 65535) {
          throw Error(path + ":" + std::to_string(number) + ": port \"" + second + "\" is not a number from 1 to 65535");
        }
        e.port = static_cast<int>(p);
        have_port = true;
      }
      continue;
    }
    // The one-line form: HOST PORT [MODE]
    char* end = nullptr;
    long p = std::strtol(second.c_str(), &end, 10);
    if (second.empty() || *end || p < 1 || p > 65535) {
      throw Error(path + ":" + std::to_string(number) + ": expected \"HOST PORT [yarp]\", got \"" + line + "\"");
    }
    e.host = first;
    e.port = static_cast<int>(p);
    return e;
  }
  if (have_host && have_port) return e;
  throw Error(path + ": no name server address in it (expected \"HOST PORT yarp\")");
}

void write_yarp_conf(const net::Endpoint& server) {
  const std::string dir = yarp_config_dir();
  ensure_directory(dir);
  const std::string path = yarp_conf_path();
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << server.host << " " << server.port << " yarp\n";
    if (!out) throw Error("cannot write " + tmp + ": " + std::strerror(errno));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    throw Error("cannot replace " + path + ": " + std::strerror(errno));
  }
}

}  // namespace robogene::cli
