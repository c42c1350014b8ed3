// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name_server_mcast_groups.hpp"

#include <exception>
#include <mutex>
#include <string>

#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/name_client.hpp"
#include "robogene/name_config.hpp"
#include "robogene/net/mcast_socket.hpp"

namespace robogene {

namespace {

class NameServerMcastGroups final : public carrier::McastGroupAllocator {
 public:
  explicit NameServerMcastGroups(std::optional<net::Endpoint> server) : server_(std::move(server)) {}

  std::optional<Grant> allocate(const std::string& sender, net::Millis timeout) override {
    auto at = server(sender);
    if (!at) return std::nullopt;
    try {
      NameClient names(*at, timeout);
      for (const auto& line : names.request("NAME_SERVER register ... mcast ... ...\r\n")) {
        auto c = NameClient::parse_registration(line);
        if (!c || !net::is_multicast_group(c->host) || c->port <= 0 || c->port > 65535) continue;
        // Marks the group as the port's, so the server drops it when the port unregisters.
        if (!sender.empty() && sender[0] == '/') names.set_property(sender, "owns", {c->name});
        return Grant{net::Endpoint{c->host, c->port}, c->name};
      }
      log::warn(sender, "mcast: the name server at " + at->to_string() + " did not hand out a multicast group");
    } catch (const std::exception& e) {
      log::warn(sender, std::string("mcast: asking the name server for a group failed: ") + e.what());
    }
    return std::nullopt;
  }

  void release(const Grant& grant, net::Millis timeout) noexcept override {
    if (grant.registration.empty()) return;
    try {
      auto at = server(grant.registration);
      if (at) NameClient(*at, timeout).unregister(grant.registration);
    } catch (const std::exception& e) {
      log::warn(grant.registration, std::string("mcast: could not unregister the group: ") + e.what());
    }
  }

 private:
  // The server given, or the configuration's (read once, when first needed).
  std::optional<net::Endpoint> server(const std::string& who) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (server_) return server_;
    try {
      server_ = NameConfig::load().server;
    } catch (const Error& e) {
      log::warn(who, std::string("mcast: no name server to allocate a group from: ") + e.what());
    }
    return server_;
  }

  std::mutex mutex_;
  std::optional<net::Endpoint> server_;
};

}  // namespace

std::shared_ptr<carrier::McastGroupAllocator> name_server_mcast_groups(std::optional<net::Endpoint> server) {
  return std::make_shared<NameServerMcastGroups>(std::move(server));
}

}  // namespace robogene
