// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "shm_segment.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <random>
#include <thread>

#include "robogene/error.hpp"
#include "robogene/limits.hpp"

namespace robogene::carrier::detail {

namespace {

constexpr std::uint32_t kMagic = 0x4d534752;  // "RGSM"
constexpr std::uint32_t kVersion = 1;
constexpr auto kSlice = std::chrono::milliseconds(100);  // how often a waiter looks around

using Clock = std::chrono::steady_clock;

std::string errno_text(int err) { return std::strerror(err); }

void lock(pthread_mutex_t* m) {
  // A peer that died holding the mutex leaves it "owner dead": take it over; the ring's state
  // is in the atomics, not behind the mutex, so nothing needs repair.
  if (pthread_mutex_lock(m) == EOWNERDEAD) pthread_mutex_consistent(m);
}

void wait_until(pthread_cond_t* c, pthread_mutex_t* m, Clock::time_point until) {
  auto left = std::min<Clock::duration>(until - Clock::now(), kSlice);
  if (left <= Clock::duration::zero()) return;
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(left).count() + ts.tv_nsec;
  ts.tv_sec += static_cast<time_t>(ns / 1000000000);
  ts.tv_nsec = static_cast<long>(ns % 1000000000);
  if (pthread_cond_timedwait(c, m, &ts) == EOWNERDEAD) pthread_mutex_consistent(m);
}

void init_ring(ShmRing& r, std::uint32_t capacity, std::uint64_t offset) {
  new (&r.head) std::atomic<std::uint64_t>(0);
  new (&r.tail) std::atomic<std::uint64_t>(0);
  new (&r.reader_waiting) std::atomic<std::uint32_t>(0);
  new (&r.writer_waiting) std::atomic<std::uint32_t>(0);
  new (&r.closed) std::atomic<std::uint32_t>(0);
  r.capacity = capacity;
  r.data_offset = offset;
  pthread_mutexattr_t ma;
  pthread_mutexattr_init(&ma);
  pthread_mutexattr_setpshared(&ma, PTHREAD_PROCESS_SHARED);
  pthread_mutexattr_setrobust(&ma, PTHREAD_MUTEX_ROBUST);
  pthread_mutex_init(&r.mutex, &ma);
  pthread_mutexattr_destroy(&ma);
  pthread_condattr_t ca;
  pthread_condattr_init(&ca);
  pthread_condattr_setpshared(&ca, PTHREAD_PROCESS_SHARED);
  pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
  pthread_cond_init(&r.readable, &ca);
  pthread_cond_init(&r.writable, &ca);
  pthread_condattr_destroy(&ca);
}

// The other side usually answers within microseconds (an ack, the next block of a frame):
// looking a little while before sleeping saves the futex round trip of a wake-up.
template <typename Ready>
bool spin_until(Ready&& ready) {
  for (int i = 0; i < 4000; ++i) {
    if (ready()) return true;
    if ((i & 63) == 63) std::this_thread::yield();
  }
  return false;
}

std::string fresh_name() {
  static std::atomic<unsigned> counter{0};
  std::random_device rd;
  char buf[96];
  std::snprintf(buf, sizeof buf, "/robogene-shmem-%d-%u-%08x", static_cast<int>(::getpid()),
                counter.fetch_add(1), static_cast<unsigned>(rd()));
  return buf;
}

std::uint64_t align64(std::uint64_t v) { return (v + 63) & ~std::uint64_t{63}; }

}  // namespace

ShmSegment::~ShmSegment() {
  if (base_) ::munmap(base_, size_);
  unlink();
  if (counted_) ResourceUsage::global().remove_shmem_segment();
}

void ShmSegment::unlink() noexcept {
  if (owner_ && linked_) ::shm_unlink(name_.c_str());
  linked_ = false;
}

std::unique_ptr<ShmSegment> ShmSegment::create(std::uint32_t capacity0, std::uint32_t capacity1) {
  auto s = std::make_unique<ShmSegment>();
  if (!ResourceUsage::global().try_add_shmem_segment()) {
    throw NetworkError("cannot create another shared-memory segment: this process already holds " +
                       std::to_string(resource_limits().max_shmem_segments) +
                       " (ROBOGENE_MAX_SHMEM_SEGMENTS)");
  }
  s->counted_ = true;
  s->name_ = fresh_name();
  int fd = ::shm_open(s->name_.c_str(), O_CREAT | O_EXCL | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0) throw NetworkError("cannot create shared memory " + s->name_ + ": " + errno_text(errno));
  s->owner_ = s->linked_ = true;
  std::uint64_t off0 = align64(sizeof(ShmSegmentHeader));
  std::uint64_t off1 = align64(off0 + capacity0);
  s->size_ = static_cast<std::size_t>(off1 + capacity1);
  int rc = ::ftruncate(fd, static_cast<off_t>(s->size_));
  int err = errno;
  if (rc == 0) {
    void* p = ::mmap(nullptr, s->size_, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    err = errno;
    if (p != MAP_FAILED) s->base_ = static_cast<std::uint8_t*>(p);
  }
  ::close(fd);
  if (!s->base_) {
    throw NetworkError("cannot size or map shared memory " + s->name_ + " (" + std::to_string(s->size_) +
                       " bytes): " + errno_text(err));
  }
  s->header_ = reinterpret_cast<ShmSegmentHeader*>(s->base_);
  s->header_->magic = kMagic;
  s->header_->version = kVersion;
  s->header_->size = s->size_;
  init_ring(s->header_->rings[0], capacity0, off0);
  init_ring(s->header_->rings[1], capacity1, off1);
  s->capacity_[0] = capacity0;
  s->capacity_[1] = capacity1;
  s->offset_[0] = off0;
  s->offset_[1] = off1;
  return s;
}

std::unique_ptr<ShmSegment> ShmSegment::open(const std::string& name) {
  auto s = std::make_unique<ShmSegment>();
  s->name_ = name;
  int fd = ::shm_open(name.c_str(), O_RDWR | O_CLOEXEC, 0);
  if (fd < 0) {
    throw NetworkError("cannot open shared memory " + name + ": " + errno_text(errno) +
                       " (shmem needs both ports on one host)");
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || static_cast<std::size_t>(st.st_size) < sizeof(ShmSegmentHeader)) {
    ::close(fd);
    throw ParseError(0, "shared memory " + name + " is too small for a shmem header");
  }
  s->size_ = static_cast<std::size_t>(st.st_size);
  void* p = ::mmap(nullptr, s->size_, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  int err = errno;
  ::close(fd);
  if (p == MAP_FAILED) throw NetworkError("cannot map shared memory " + name + ": " + errno_text(err));
  s->base_ = static_cast<std::uint8_t*>(p);
  s->header_ = reinterpret_cast<ShmSegmentHeader*>(s->base_);
  const auto& h = *s->header_;
  if (h.magic != kMagic || h.version != kVersion || h.size != s->size_) {
    throw ParseError(0, "shared memory " + name + " is not a Robogene shmem segment of version " +
                            std::to_string(kVersion));
  }
  for (int i = 0; i < 2; ++i) {
    // One read of each field: the creator may change them while we look.
    const std::uint32_t capacity = h.rings[i].capacity;
    const std::uint64_t offset = h.rings[i].data_offset;
    if (capacity == 0 || offset < sizeof(ShmSegmentHeader) || offset > s->size_ ||
        capacity > s->size_ - offset) {
      throw ParseError(0, "shared memory " + name + ": a ring lies outside the segment");
    }
    s->capacity_[i] = capacity;
    s->offset_[i] = offset;
  }
  return s;
}

ShmStream::ShmStream(ShmSegment& seg, int ring, std::string peer, PeerCheck alive)
    : seg_(seg), r_(seg.ring(ring)), capacity_(seg.capacity(ring)), data_(seg.data(ring)),
      peer_(std::move(peer)), alive_(std::move(alive)) {}

void ShmStream::fail(const std::string& what) const { throw NetworkError("shmem peer " + peer_ + " " + what); }

std::size_t ShmStream::filled(std::uint64_t head, std::uint64_t tail) const {
  const std::uint64_t n = head - tail;
  if (n > capacity_) {
    fail("corrupted its ring: " + std::to_string(n) + " bytes claimed in a ring of " +
         std::to_string(capacity_));
  }
  return static_cast<std::size_t>(n);
}

std::size_t ShmStream::available() const noexcept {
  const std::uint64_t n = r_.head.load(std::memory_order_acquire) - r_.tail.load(std::memory_order_relaxed);
  return n > capacity_ ? 0 : static_cast<std::size_t>(n);
}

std::size_t ShmStream::wait_for_bytes(net::Millis timeout, bool at_message_start) {
  const auto until = timeout.count() > 0 ? Clock::now() + timeout : Clock::time_point::max();
  for (;;) {
    const std::uint64_t t = r_.tail.load(std::memory_order_relaxed);
    const std::uint64_t h = r_.head.load(std::memory_order_acquire);
    if (h != t) return filled(h, t);
    if (r_.closed.load()) {
      if (at_message_start) return 0;
      fail("closed the connection in the middle of a message");
    }
    if (!alive_()) {
      if (at_message_start) return 0;
      fail("vanished in the middle of a message");
    }
    if (Clock::now() >= until) fail("sent nothing for " + std::to_string(timeout.count()) + " ms (timed out)");
    if (spin_until([&] { return r_.head.load(std::memory_order_acquire) != t; })) continue;
    lock(&r_.mutex);
    r_.reader_waiting.store(1);
    if (r_.head.load() == t && !r_.closed.load()) wait_until(&r_.readable, &r_.mutex, until);
    r_.reader_waiting.store(0);
    pthread_mutex_unlock(&r_.mutex);
  }
}

std::size_t ShmStream::wait_for_space(net::Millis timeout) {
  const auto until = timeout.count() > 0 ? Clock::now() + timeout : Clock::time_point::max();
  for (;;) {
    const std::uint64_t h = r_.head.load(std::memory_order_relaxed);
    const std::uint64_t t = r_.tail.load(std::memory_order_acquire);
    if (r_.closed.load()) fail("closed the connection");
    const std::size_t used = filled(h, t);
    if (used < capacity_) return capacity_ - used;
    if (!alive_()) fail("vanished");
    if (Clock::now() >= until) fail("did not take our bytes for " + std::to_string(timeout.count()) + " ms (timed out)");
    if (spin_until([&] { return r_.tail.load(std::memory_order_acquire) != t; })) continue;
    lock(&r_.mutex);
    r_.writer_waiting.store(1);
    if (r_.tail.load() == t && !r_.closed.load()) wait_until(&r_.writable, &r_.mutex, until);
    r_.writer_waiting.store(0);
    pthread_mutex_unlock(&r_.mutex);
  }
}

void ShmStream::write(const void* data, std::size_t size, net::Millis timeout) {
  iovec v{const_cast<void*>(data), size};
  write(&v, 1, timeout);
}

void ShmStream::write(const iovec* iov, std::size_t count, net::Millis timeout) {
  const auto until = timeout.count() > 0 ? Clock::now() + timeout : Clock::time_point::max();
  for (std::size_t i = 0; i < count; ++i) {
    auto* p = static_cast<const std::uint8_t*>(iov[i].iov_base);
    std::size_t left = iov[i].iov_len;
    while (left > 0) {
      auto remaining = std::chrono::duration_cast<net::Millis>(until - Clock::now());
      if (timeout.count() > 0 && remaining.count() <= 0) remaining = net::Millis{1};
      std::size_t room = wait_for_space(timeout.count() > 0 ? remaining : net::kNoTimeout);
      std::size_t n = std::min(room, left);
      const std::uint64_t h = r_.head.load(std::memory_order_relaxed);
      std::size_t at = static_cast<std::size_t>(h % capacity_);
      std::size_t first = std::min<std::size_t>(n, capacity_ - at);
      std::memcpy(data_ + at, p, first);
      std::memcpy(data_, p + first, n - first);
      r_.head.store(h + n);  // sequentially consistent: pairs with reader_waiting below
      if (r_.reader_waiting.load()) {
        lock(&r_.mutex);
        pthread_cond_signal(&r_.readable);
        pthread_mutex_unlock(&r_.mutex);
      }
      p += n;
      left -= n;
    }
  }
}

void ShmStream::read_exact(void* data, std::size_t size) {
  auto* out = static_cast<std::uint8_t*>(data);
  while (size > 0) {
    std::size_t n = std::min(wait_for_bytes(read_timeout_, false), size);
    const std::uint64_t t = r_.tail.load(std::memory_order_relaxed);
    std::size_t at = static_cast<std::size_t>(t % capacity_);
    std::size_t first = std::min<std::size_t>(n, capacity_ - at);
    std::memcpy(out, data_ + at, first);
    std::memcpy(out + first, data_, n - first);
    r_.tail.store(t + n);
    if (r_.writer_waiting.load()) {
      lock(&r_.mutex);
      pthread_cond_signal(&r_.writable);
      pthread_mutex_unlock(&r_.mutex);
    }
    out += n;
    size -= n;
  }
}

bool ShmStream::wait_readable() { return wait_for_bytes(net::kNoTimeout, true) > 0; }

void ShmStream::close() noexcept {
  r_.closed.store(1);
  lock(&r_.mutex);
  pthread_cond_broadcast(&r_.readable);
  pthread_cond_broadcast(&r_.writable);
  pthread_mutex_unlock(&r_.mutex);
}

}  // namespace robogene::carrier::detail
