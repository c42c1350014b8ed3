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
#include <string>

namespace robogene {

struct ResourceLimits {
  // Inbound connections of all ports of this process together, each served by a thread.
  std::size_t max_connections = 1024;               // ROBOGENE_MAX_CONNECTIONS
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

 private:
  std::atomic<std::size_t> connections_{0};
  std::atomic<std::size_t> receiving_{0};
  std::atomic<std::size_t> shmem_{0};
};

// One inbound connection's slot in the process count (movable, released on destruction).
class ConnectionSlot {
 public:
  ConnectionSlot() = default;
  static ConnectionSlot try_take();  // an empty slot (!held()) when the process is full
  ConnectionSlot(ConnectionSlot&& o) noexcept : held_(o.held_) { o.held_ = false; }
  ConnectionSlot& operator=(ConnectionSlot&& o) noexcept;
  ConnectionSlot(const ConnectionSlot&) = delete;
  ConnectionSlot& operator=(const ConnectionSlot&) = delete;
  ~ConnectionSlot();
  bool held() const noexcept { return held_; }

 private:
  bool held_ = false;
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
