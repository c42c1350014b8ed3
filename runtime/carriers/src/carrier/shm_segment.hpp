// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The shared memory behind one shmem connection (private to src/carrier): a POSIX shm object
// holding two single-producer single-consumer byte rings, one per direction (0: initiator to
// acceptor, 1: acceptor to initiator). Bytes move through the rings with atomics; a side that
// must wait sleeps on a process-shared robust mutex + condition variable and is woken by the
// other side, or every 100 ms to notice a closed ring or a vanished peer.
#pragma once

#include <pthread.h>
#include <sys/uio.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "robogene/net/tcp_stream.hpp"

namespace robogene::carrier::detail {

struct ShmRing {
  alignas(64) std::atomic<std::uint64_t> head;  // bytes ever written
  alignas(64) std::atomic<std::uint64_t> tail;  // bytes ever read
  alignas(64) std::atomic<std::uint32_t> reader_waiting;
  std::atomic<std::uint32_t> writer_waiting;
  std::atomic<std::uint32_t> closed;
  std::uint32_t capacity;
  std::uint64_t data_offset;  // from the start of the segment
  pthread_mutex_t mutex;
  pthread_cond_t readable;
  pthread_cond_t writable;
};

struct ShmSegmentHeader {
  std::uint32_t magic;    // "RGSM"
  std::uint32_t version;  // 1
  std::uint64_t size;     // of the whole segment
  ShmRing rings[2];
};

// Says whether the peer is still there (false = gone); polled while waiting.
using PeerCheck = std::function<bool()>;

class ShmSegment {
 public:
  ShmSegment() = default;
  ~ShmSegment();
  ShmSegment(const ShmSegment&) = delete;
  ShmSegment& operator=(const ShmSegment&) = delete;

  // Creates a fresh segment with rings of the given capacities; its name (for the peer) is
  // name(). Throws NetworkError saying what the system refused, or that the process already
  // holds ResourceLimits::max_shmem_segments of them.
  static std::unique_ptr<ShmSegment> create(std::uint32_t capacity0, std::uint32_t capacity1);
  // Maps a segment the peer created and checks that its header is sane (magic, version, sizes
  // within the object). Throws NetworkError / ParseError naming the segment.
  static std::unique_ptr<ShmSegment> open(const std::string& name);
  // Removes the name so the memory goes away with the last mapping (done once both sides mapped).
  void unlink() noexcept;

  const std::string& name() const noexcept { return name_; }
  ShmRing& ring(int i) noexcept { return header_->rings[i]; }
  // A ring's capacity and data as checked when the segment was created or opened.
  std::uint32_t capacity(int i) const noexcept { return capacity_[i]; }
  std::uint8_t* data(int i) noexcept { return base_ + offset_[i]; }

 private:
  std::string name_;
  std::uint8_t* base_ = nullptr;
  std::size_t size_ = 0;
  ShmSegmentHeader* header_ = nullptr;
  std::uint32_t capacity_[2] = {0, 0};
  std::uint64_t offset_[2] = {0, 0};
  bool owner_ = false;
  bool linked_ = false;
  bool counted_ = false;  // in ResourceUsage's count of segments this process created
};

// One direction of a shmem connection as a byte stream: write() copies gathered buffers in,
// read_exact() copies bytes out. Waiting ends with a NetworkError when the ring is closed, the
// peer check fails, the deadline passes (timeout 0 = none) or interrupt() was called.
class ShmStream {
 public:
  ShmStream(ShmSegment& seg, int ring, std::string peer, PeerCheck alive);
  void write(const iovec* iov, std::size_t count, net::Millis timeout);
  void write(const void* data, std::size_t size, net::Millis timeout);
  void read_exact(void* data, std::size_t size);
  // Waits (without a deadline) until a byte is readable; false when the ring was closed cleanly
  // or interrupted with nothing left to read.
  bool wait_readable();
  void set_read_timeout(net::Millis t) { read_timeout_ = t; }
  // Closes the ring (both sides see it) and wakes whoever waits on it.
  void close() noexcept;
  std::size_t available() const noexcept;

 private:
  std::size_t wait_for_bytes(net::Millis timeout, bool at_message_start);
  std::size_t wait_for_space(net::Millis timeout);
  // head - tail, checked: the peer can write any number into the shared counters.
  std::size_t filled(std::uint64_t head, std::uint64_t tail) const;
  [[noreturn]] void fail(const std::string& what) const;

  ShmSegment& seg_;
  ShmRing& r_;
  // Read once from the segment and checked when it was mapped: the peer can rewrite the
  // shared copy at any time, so every operation uses these.
  const std::uint32_t capacity_;
  std::uint8_t* data_;
  std::string peer_;
  PeerCheck alive_;
  net::Millis read_timeout_{0};
};

}  // namespace robogene::carrier::detail
