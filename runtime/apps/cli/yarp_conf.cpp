// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "yarp_conf.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "robogene/error.hpp"
#include "robogene/name_config.hpp"

namespace robogene::cli {

std::string yarp_conf_path() {
  const char* ns = std::getenv("YARP_NAMESPACE");
  return NameConfig::config_dir() + "/" + NameConfig::file_name_for(ns && *ns ? ns : "/root");
}

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

void write_yarp_conf(const net::Endpoint& server) {
  ensure_directory(NameConfig::config_dir());
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
