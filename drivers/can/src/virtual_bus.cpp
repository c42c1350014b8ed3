// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/virtual_bus.hpp"

#include <dirent.h>
#include <errno.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdlib>
#include <cstring>

#include "robogene/log.hpp"

namespace robogene::can {
namespace {

// One frame per datagram: magic, 32-bit id (SocketCAN's, so error frames keep their flag),
// length, 3 reserved bytes, 8 data bytes. Little-endian.
constexpr std::size_t kDatagramSize = 20;
constexpr char kMagic[4] = {'R', 'G', 'C', '1'};

void encode(std::uint32_t can_id, std::uint8_t len, const std::uint8_t* data, std::uint8_t* out) {
  std::memcpy(out, kMagic, 4);
  for (int i = 0; i < 4; ++i) out[4 + i] = static_cast<std::uint8_t>(can_id >> (8 * i));
  out[8] = len;
  out[9] = out[10] = out[11] = 0;
  std::memset(out + 12, 0, 8);
  std::memcpy(out + 12, data, len);
}

bool valid_name(const std::string& s) {
  if (s.empty() || s == "." || s == "..") return false;
  for (char c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
  }
  return true;
}

void make_dir(const std::string& path, const std::string& bus) {
  if (::mkdir(path.c_str(), 0700) != 0 && errno != EEXIST) {
    throw BusError(BusErrorKind::io, bus + ": cannot create directory " + path + ": " + std::strerror(errno));
  }
}

sockaddr_un address_of(const std::string& path) {
  sockaddr_un a{};
  a.sun_family = AF_UNIX;
  std::memcpy(a.sun_path, path.c_str(), path.size() + 1);
  return a;
}

std::int64_t mtime_ns(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return -1;
  return static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
}

std::atomic<unsigned> g_node_counter{0};

}  // namespace

std::string VirtualBus::directory_for(const std::string& bus_name) {
  const char* base = std::getenv("ROBOGENE_CAN_DIR");
  std::string dir = base && *base ? base : "/tmp/robogene-can-" + std::to_string(::getuid());
  return dir + "/" + bus_name;
}

VirtualBus::VirtualBus(const std::string& bus_name) : bus_name_(bus_name) {
  if (!valid_name(bus_name)) {
    throw Error("virtual CAN bus name \"" + bus_name + "\": use letters, digits, '_', '-' and '.' only");
  }
  dir_ = directory_for(bus_name);
  own_path_ = dir_ + "/" + std::to_string(::getpid()) + "-" + std::to_string(g_node_counter++);
  if (own_path_.size() >= sizeof(sockaddr_un::sun_path)) {
    throw Error(name() + ": socket path " + own_path_ + " is longer than " +
                std::to_string(sizeof(sockaddr_un::sun_path) - 1) + " bytes; set ROBOGENE_CAN_DIR to a shorter directory");
  }
  make_dir(dir_.substr(0, dir_.rfind('/')), name());
  make_dir(dir_, name());
  fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw BusError(BusErrorKind::io, name() + ": socket failed: " + std::strerror(errno));
  ::unlink(own_path_.c_str());
  const sockaddr_un a = address_of(own_path_);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    const int err = errno;
    ::close(fd_);
    throw BusError(BusErrorKind::io, name() + ": cannot bind " + own_path_ + ": " + std::strerror(err));
  }
}

VirtualBus::~VirtualBus() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& [path, peer] : peers_) ::close(peer.fd);
  ::close(fd_);
  ::unlink(own_path_.c_str());
}

void VirtualBus::set_filters(const std::vector<Filter>& filters) {
  std::lock_guard<std::mutex> lock(filters_mutex_);
  filters_ = filters;
}

std::uint64_t VirtualBus::dropped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

void VirtualBus::refresh_peers() {
  const std::int64_t now = mtime_ns(dir_);
  if (now == listed_mtime_ns_ && now >= 0) return;
  listed_mtime_ns_ = now;
  std::map<std::string, Peer> fresh;
  if (DIR* d = ::opendir(dir_.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string entry = e->d_name;
      if (entry == "." || entry == "..") continue;
      const std::string path = dir_ + "/" + entry;
      if (path == own_path_) continue;
      auto old = peers_.find(path);
      if (old != peers_.end()) {
        fresh.emplace(path, old->second);
        peers_.erase(old);
        continue;
      }
      const int fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
      if (fd < 0) continue;
      const sockaddr_un a = address_of(path);
      if (::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
        const int err = errno;
        ::close(fd);
        if (err == ECONNREFUSED) ::unlink(path.c_str());  // a node that died without cleaning up
        continue;
      }
      fresh.emplace(path, Peer{fd, {}});
    }
    ::closedir(d);
  }
  for (auto& [path, peer] : peers_) ::close(peer.fd);  // nodes that left
  peers_ = std::move(fresh);
}

void VirtualBus::forget(const std::string& path, bool stale) {
  auto it = peers_.find(path);
  if (it == peers_.end()) return;
  ::close(it->second.fd);
  peers_.erase(it);
  if (stale) ::unlink(path.c_str());
  listed_mtime_ns_ = -1;
}

void VirtualBus::broadcast(const std::uint8_t* datagram, std::size_t size, Millis timeout,
                           const std::string& what) {
  std::lock_guard<std::mutex> lock(mutex_);
  refresh_peers();
  const auto wait = std::min(timeout, kCongestionWait);
  std::vector<std::pair<std::string, bool>> gone;
  for (auto& [path, peer] : peers_) {
    const auto now = std::chrono::steady_clock::now();
    const auto deadline = now < peer.congested_until ? now : now + wait;
    for (;;) {
      const ssize_t n = ::send(peer.fd, datagram, size, MSG_DONTWAIT | MSG_NOSIGNAL);
      if (n == static_cast<ssize_t>(size)) {
        peer.congested_until = {};
        break;
      }
      const int err = n < 0 ? errno : EIO;
      if (err == EINTR) continue;
      if (err == EAGAIN) {
        const auto left = std::chrono::duration_cast<Millis>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
          // The peer is not reading: drop for it and stop waiting for it for a while.
          ++dropped_;
          if (peer.congested_until == std::chrono::steady_clock::time_point{}) {
            log::warn(name(), "node " + path + " is not reading; dropping " + what + " for it");
          }
          peer.congested_until = std::chrono::steady_clock::now() + std::chrono::seconds(1);
          break;
        }
        pollfd p{peer.fd, POLLOUT, 0};
        ::poll(&p, 1, static_cast<int>(std::min<Millis::rep>(left.count(), 2)));
        continue;
      }
      gone.emplace_back(path, err == ECONNREFUSED);  // the node closed or died
      break;
    }
  }
  for (const auto& [path, stale] : gone) forget(path, stale);
}

void VirtualBus::send(const Frame& frame, Millis timeout) {
  validate(frame);
  std::uint8_t d[kDatagramSize];
  encode(frame.id, frame.len, frame.data.data(), d);
  broadcast(d, sizeof d, timeout, to_string(frame));
}

void VirtualBus::inject_error(const ErrorFrame& e) {
  std::uint8_t d[kDatagramSize];
  encode(e.can_id | kErrFlag, 8, e.data.data(), d);
  broadcast(d, sizeof d, kCongestionWait, "an error frame");
}

std::optional<Frame> VirtualBus::receive(Millis timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::duration_cast<Millis>(deadline - std::chrono::steady_clock::now());
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, left.count() > 0 ? static_cast<int>(left.count()) : 0);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) throw BusError(BusErrorKind::io, name() + ": poll failed: " + std::strerror(errno));
    if (ready == 0) return std::nullopt;
    std::uint8_t d[kDatagramSize + 1];
    const ssize_t n = ::recv(fd_, d, sizeof d, MSG_DONTWAIT);
    if (n < 0) {
      if (errno == EAGAIN || errno == EINTR) continue;
      throw BusError(BusErrorKind::io, name() + ": recv failed: " + std::strerror(errno));
    }
    if (n != static_cast<ssize_t>(kDatagramSize) || std::memcmp(d, kMagic, 4) != 0 || d[8] > 8) {
      log::warn(name(), "dropped a " + std::to_string(n) + "-byte datagram that is not a virtual CAN frame");
      continue;
    }
    std::uint32_t can_id = 0;
    for (int i = 0; i < 4; ++i) can_id |= static_cast<std::uint32_t>(d[4 + i]) << (8 * i);
    if (can_id & kErrFlag) {
      ErrorFrame e;
      e.can_id = can_id;
      std::memcpy(e.data.data(), d + 12, 8);
      throw decode_error_frame(name(), e);
    }
    if (can_id > kMaxStandardId) continue;
    Frame f;
    f.id = static_cast<std::uint16_t>(can_id);
    f.len = d[8];
    std::memcpy(f.data.data(), d + 12, f.len);
    {
      std::lock_guard<std::mutex> lock(filters_mutex_);
      if (!passes(filters_, f.id)) continue;
    }
    return f;
  }
}

}  // namespace robogene::can
