// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What one process lets its peers make it hold: connections (one thread each), bytes of
// messages being received, shared-memory segments, datagram inputs. The defaults suit a robot
// (camera frames of tens of MB, a few hundred connections); each can be changed by an
// environment variable read on first use or by set_resource_limits() before ports open.
// docs/security.md ("Limits") gives the threat model and every default.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>
#include <unordered_map>

namespace robogene {

struct ResourceLimits {
  // Inbound connections of all ports of this process together, each served by a thread.
  std::size_t max_connections = 1024;               // ROBOGENE_MAX_CONNECTIONS
  // Of those, the ones from one remote address, so that one host cannot take them all; and
  // of those, the ones still in their handshake (the cheapest to hold open: nothing valid
  // need be sent). All of a robot's own processes share one address (127.0.0.1 or the
  // host's), hence room for hundreds; a start-up connects one port at a time per tool.
  std::size_t max_connections_per_address = 256;    // ROBOGENE_MAX_CONNECTIONS_PER_ADDRESS
  std::size_t max_handshakes_per_address = 64;      // ROBOGENE_MAX_HANDSHAKES_PER_ADDRESS
  // Bytes of messages received but not yet complete, all connections together. A peer that
  // sends part of a big message and stalls holds what it sent, never what it announced.
  std::size_t max_receiving_bytes = 512u << 20;     // ROBOGENE_MAX_RECEIVING_BYTES
  // One message, announced or received (the default of PortOptions::max_message_size).
  std::size_t max_message_size = 64u << 20;         // ROBOGENE_MAX_MESSAGE_SIZE
  // Values decoded from one message: a 1-byte int on the wire becomes a 16-byte Value.
  std::size_t max_decoded_values = 4u << 20;        // ROBOGENE_MAX_DECODED_VALUES
  // udp / mcast inputs one port keeps; a new one beyond it evicts the longest-silent one.
  std::size_t max_datagram_inputs = 32;             // ROBOGENE_MAX_DATAGRAM_INPUTS
  // Shared-memory segments this process has created for shmem inputs.
  std::size_t max_shmem_segments = 32;              // ROBOGENE_MAX_SHMEM_SEGMENTS
  // The whole acceptor handshake (header, name, carrier exchange), however slowly it drips.
  std::chrono::milliseconds handshake_deadline{10000};     // ROBOGENE_HANDSHAKE_DEADLINE_MS
  // How often an open port checks that the name server still knows it (0 = never).
  std::chrono::milliseconds registration_check{5000};      // ROBOGENE_REGISTRATION_CHECK_MS
};

// The limits in force: the defaults overridden by the environment, or the last set_.
ResourceLimits resource_limits();
// Replaces the limits for connections and ports opened afterwards (tests, embedding programs).
void set_resource_limits(const ResourceLimits& limits);

// The process-wide counts the limits bound; every reservation is returned by its destructor.
class ResourceUsage {
 public:
  static ResourceUsage& global();
  std::size_t connections() const noexcept { return connections_.load(); }
  std::size_t receiving_bytes() const noexcept { return receiving_.load(); }
  std::size_t shmem_segments() const noexcept { return shmem_.load(); }

  // Each try_ returns false (and reserves nothing) when the limit would be passed.
  bool try_add_connection();
  void remove_connection() noexcept;
  bool try_reserve_receiving(std::size_t n);
  void release_receiving(std::size_t n) noexcept;
  bool try_add_shmem_segment();
  void remove_shmem_segment() noexcept;

  // Inbound connections from one remote address, and those of them still in their handshake.
  std::size_t connections_from(const std::string& address) const;
  std::size_t handshakes_from(const std::string& address) const;
  bool try_add_peer_connection(const std::string& address);  // also counts it as a handshake
  void end_peer_handshake(const std::string& address) noexcept;
  void remove_peer_connection(const std::string& address, bool in_handshake) noexcept;

 private:
  struct PeerCounts {
    std::size_t connections = 0;
    std::size_t handshakes = 0;
  };
  std::atomic<std::size_t> connections_{0};
  std::atomic<std::size_t> receiving_{0};
  std::atomic<std::size_t> shmem_{0};
  mutable std::mutex peers_mutex_;
  std::unordered_map<std::string, PeerCounts> peers_;  // only addresses with a connection
};

// One inbound connection's slot in the process count and in its remote address's counts
// (movable, released on destruction). It starts in the handshake.
class ConnectionSlot {
 public:
  ConnectionSlot() = default;
  // An empty slot (!held()) when the process, or the address `peer_address`, is full; then
  // `refused_because` (if given) says which limit, naming its variable.
  static ConnectionSlot try_take(const std::string& peer_address, std::string* refused_because = nullptr);
  ConnectionSlot(ConnectionSlot&& o) noexcept
      : held_(o.held_), in_handshake_(o.in_handshake_), address_(std::move(o.address_)) {
    o.held_ = o.in_handshake_ = false;
  }
  ConnectionSlot& operator=(ConnectionSlot&& o) noexcept;
  ConnectionSlot(const ConnectionSlot&) = delete;
  ConnectionSlot& operator=(const ConnectionSlot&) = delete;
  ~ConnectionSlot();
  bool held() const noexcept { return held_; }
  // The handshake is over (accepted or not): the connection stops counting as one in flight.
  void end_handshake() noexcept;

 private:
  void release() noexcept;
  bool held_ = false;
  bool in_handshake_ = false;
  std::string address_;
};

// Bytes one message holds while it arrives, counted in the process total; grows as bytes
// come in (reserved 64 KB at a time, so that counting costs nothing per item) and is returned
// when the message is complete (or its connection fails).
class ReceivingBytes {
 public:
  explicit ReceivingBytes(std::string who) : who_(std::move(who)) {}
  ~ReceivingBytes() { release(); }
  ReceivingBytes(const ReceivingBytes&) = delete;
  ReceivingBytes& operator=(const ReceivingBytes&) = delete;
  // Throws NetworkError naming `who` and the limit when the process total would pass it.
  void add(std::size_t n);
  void release() noexcept;

 private:
  std::string who_;
  std::size_t used_ = 0;
  std::size_t held_ = 0;
};

}  // namespace robogene
