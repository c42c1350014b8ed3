// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "http_origin.hpp"

#include <arpa/inet.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>

namespace robogene::carrier::detail {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// "host:port" -> "host"; "[::1]:80" -> "::1".
std::string host_name_of(const std::string& host) {
  if (!host.empty() && host[0] == '[') {
    const std::size_t close = host.find(']');
    return close == std::string::npos ? host : host.substr(1, close - 1);
  }
  return host.substr(0, host.find(':'));
}

bool is_address(const std::string& name) {
  unsigned char buf[16];
  return ::inet_pton(AF_INET, name.c_str(), buf) == 1 || ::inet_pton(AF_INET6, name.c_str(), buf) == 1;
}

// "http://a:1/x/y" -> "http://a:1"
std::string origin_of(const std::string& url) {
  const std::size_t scheme = url.find("://");
  if (scheme == std::string::npos) return url;
  return url.substr(0, url.find('/', scheme + 3));
}

}  // namespace

std::string cross_site_reason(const HttpRequest& r, const std::vector<std::string>& machine_names) {
  if (!r.sec_fetch_site.empty() && r.sec_fetch_site != "same-origin" && r.sec_fetch_site != "none") {
    return "the browser says a page of another site sent it (Sec-Fetch-Site: " + r.sec_fetch_site + ")";
  }
  const std::string own = "http://" + lower(r.host);
  if (!r.origin.empty() && lower(r.origin) != own) {
    return "a page of " + r.origin + " sent it, not this port's page " + own;
  }
  if (!r.referer.empty() && lower(origin_of(r.referer)) != own) {
    return "it comes from the page " + r.referer + ", not from this port's page " + own;
  }
  const std::string name = lower(host_name_of(r.host));
  if (name.empty() || name == "localhost" || is_address(name)) return "";
  for (const std::string& m : machine_names) {
    if (lower(m) == name) return "";
  }
  return "it names the host \"" + name + "\", which is not an address or a name of this machine: "
         "a page can point a name of its own at the robot (DNS rebinding); use the robot's address "
         "or its host name";
}

std::vector<std::string> this_machine_names() {
  char buf[256] = {};
  if (::gethostname(buf, sizeof buf - 1) != 0 || !buf[0]) return {};
  const std::string full = buf;
  const std::string short_name = full.substr(0, full.find('.'));
  return {full, short_name, short_name + ".local"};
}

}  // namespace robogene::carrier::detail
