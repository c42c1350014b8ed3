// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <string>

#include "robogene/error.hpp"
#include "robogene/limits.hpp"
#include "robogene/log.hpp"

namespace robogene {

namespace {

// A positive whole number from the environment, or `fallback` (with a warning naming the
// variable when it is set to something else).
std::size_t from_env(const char* name, std::size_t fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  char* end = nullptr;
  unsigned long long n = std::strtoull(v, &end, 10);
  if (*end != '\0' || v[0] == '-') {
    log::warn("limits", std::string(name) + "=\"" + v + "\" is not a whole number; using " +
                            std::to_string(fallback));
    return fallback;
  }
  return static_cast<std::size_t>(n);
}

ResourceLimits from_environment() {
  ResourceLimits l;
  l.max_connections = from_env("ROBOGENE_MAX_CONNECTIONS", l.max_connections);
  l.max_connections_per_address = from_env("ROBOGENE_MAX_CONNECTIONS_PER_ADDRESS", l.max_connections_per_address);
  l.max_handshakes_per_address = from_env("ROBOGENE_MAX_HANDSHAKES_PER_ADDRESS", l.max_handshakes_per_address);
  l.max_receiving_bytes = from_env("ROBOGENE_MAX_RECEIVING_BYTES", l.max_receiving_bytes);
  l.max_message_size = from_env("ROBOGENE_MAX_MESSAGE_SIZE", l.max_message_size);
  l.max_decoded_values = from_env("ROBOGENE_MAX_DECODED_VALUES", l.max_decoded_values);
  l.max_datagram_inputs = from_env("ROBOGENE_MAX_DATAGRAM_INPUTS", l.max_datagram_inputs);
  l.max_shmem_segments = from_env("ROBOGENE_MAX_SHMEM_SEGMENTS", l.max_shmem_segments);
  l.handshake_deadline = std::chrono::milliseconds(
      from_env("ROBOGENE_HANDSHAKE_DEADLINE_MS", static_cast<std::size_t>(l.handshake_deadline.count())));
  l.registration_check = std::chrono::milliseconds(
      from_env("ROBOGENE_REGISTRATION_CHECK_MS", static_cast<std::size_t>(l.registration_check.count())));
  return l;
}

std::mutex& limits_mutex() {
  static std::mutex m;
  return m;
}

ResourceLimits& current() {
  static ResourceLimits l = from_environment();
  return l;
}

bool try_add(std::atomic<std::size_t>& count, std::size_t n, std::size_t limit) {
  std::size_t now = count.load();
  do {
    if (n > limit || now > limit - n) return false;
  } while (!count.compare_exchange_weak(now, now + n));
  return true;
}

}  // namespace

ResourceLimits resource_limits() {
  std::lock_guard<std::mutex> lock(limits_mutex());
  return current();
}

void set_resource_limits(const ResourceLimits& limits) {
  std::lock_guard<std::mutex> lock(limits_mutex());
  current() = limits;
}

ResourceUsage& ResourceUsage::global() {
  static ResourceUsage usage;
  return usage;
}

bool ResourceUsage::try_add_connection() {
  return try_add(connections_, 1, resource_limits().max_connections);
}
void ResourceUsage::remove_connection() noexcept { connections_.fetch_sub(1); }

bool ResourceUsage::try_reserve_receiving(std::size_t n) {
  return try_add(receiving_, n, resource_limits().max_receiving_bytes);
}
void ResourceUsage::release_receiving(std::size_t n) noexcept { receiving_.fetch_sub(n); }

bool ResourceUsage::try_add_shmem_segment() {
  return try_add(shmem_, 1, resource_limits().max_shmem_segments);
}
void ResourceUsage::remove_shmem_segment() noexcept { shmem_.fetch_sub(1); }

std::size_t ResourceUsage::connections_from(const std::string& address) const {
  std::lock_guard<std::mutex> lock(peers_mutex_);
  auto it = peers_.find(address);
  return it == peers_.end() ? 0 : it->second.connections;
}

std::size_t ResourceUsage::handshakes_from(const std::string& address) const {
  std::lock_guard<std::mutex> lock(peers_mutex_);
  auto it = peers_.find(address);
  return it == peers_.end() ? 0 : it->second.handshakes;
}

bool ResourceUsage::try_add_peer_connection(const std::string& address) {
  const ResourceLimits l = resource_limits();
  std::lock_guard<std::mutex> lock(peers_mutex_);
  PeerCounts& c = peers_[address];
  if (c.connections >= l.max_connections_per_address || c.handshakes >= l.max_handshakes_per_address) {
    if (c.connections == 0) peers_.erase(address);
    return false;
  }
  ++c.connections;
  ++c.handshakes;
  return true;
}

void ResourceUsage::end_peer_handshake(const std::string& address) noexcept {
  std::lock_guard<std::mutex> lock(peers_mutex_);
  auto it = peers_.find(address);
  if (it != peers_.end() && it->second.handshakes > 0) --it->second.handshakes;
}

void ResourceUsage::remove_peer_connection(const std::string& address, bool in_handshake) noexcept {
  std::lock_guard<std::mutex> lock(peers_mutex_);
  auto it = peers_.find(address);
  if (it == peers_.end()) return;
  if (in_handshake && it->second.handshakes > 0) --it->second.handshakes;
  if (it->second.connections > 0) --it->second.connections;
  if (it->second.connections == 0) peers_.erase(it);
}

ConnectionSlot ConnectionSlot::try_take(const std::string& peer_address, std::string* refused_because) {
  ConnectionSlot s;
  auto& usage = ResourceUsage::global();
  if (!usage.try_add_connection()) {
    if (refused_because) {
      *refused_because = "the process already serves " + std::to_string(resource_limits().max_connections) +
                         " connections (ROBOGENE_MAX_CONNECTIONS)";
    }
    return s;
  }
  if (!usage.try_add_peer_connection(peer_address)) {
    usage.remove_connection();
    if (refused_because) {
      const ResourceLimits l = resource_limits();
      const std::size_t handshakes = usage.handshakes_from(peer_address);
      *refused_because =
          handshakes >= l.max_handshakes_per_address
              ? std::to_string(handshakes) + " handshakes from " + peer_address +
                    " are already in progress (ROBOGENE_MAX_HANDSHAKES_PER_ADDRESS=" +
                    std::to_string(l.max_handshakes_per_address) + ")"
              : "the process already serves " + std::to_string(usage.connections_from(peer_address)) +
                    " connections from " + peer_address + " (ROBOGENE_MAX_CONNECTIONS_PER_ADDRESS=" +
                    std::to_string(l.max_connections_per_address) + ")";
    }
    return s;
  }
  s.held_ = true;
  s.in_handshake_ = true;
  s.address_ = peer_address;
  return s;
}

void ConnectionSlot::end_handshake() noexcept {
  if (!held_ || !in_handshake_) return;
  in_handshake_ = false;
  ResourceUsage::global().end_peer_handshake(address_);
}

void ConnectionSlot::release() noexcept {
  if (!held_) return;
  ResourceUsage::global().remove_peer_connection(address_, in_handshake_);
  ResourceUsage::global().remove_connection();
  held_ = in_handshake_ = false;
}

ConnectionSlot& ConnectionSlot::operator=(ConnectionSlot&& o) noexcept {
  if (this != &o) {
    release();
    held_ = o.held_;
    in_handshake_ = o.in_handshake_;
    address_ = std::move(o.address_);
    o.held_ = o.in_handshake_ = false;
  }
  return *this;
}

ConnectionSlot::~ConnectionSlot() { release(); }

void ReceivingBytes::add(std::size_t n) {
  constexpr std::size_t kBlock = 64 * 1024;
  if (n <= held_ - used_) {
    used_ += n;
    return;
  }
  const std::size_t more = std::max(n - (held_ - used_), kBlock);
  if (!ResourceUsage::global().try_reserve_receiving(more)) {
    throw NetworkError(who_ + ": receiving " + std::to_string(used_ + n) +
                       " more bytes would pass this process's limit of " +
                       std::to_string(resource_limits().max_receiving_bytes) +
                       " bytes of messages in transit (ROBOGENE_MAX_RECEIVING_BYTES)");
  }
  held_ += more;
  used_ += n;
}

void ReceivingBytes::release() noexcept {
  if (held_) ResourceUsage::global().release_receiving(held_);
  held_ = used_ = 0;
}

}  // namespace robogene
