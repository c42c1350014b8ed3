// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/sim/sim_flash.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "robogene/error.hpp"

namespace robogene::can::sim {
namespace {

std::string errno_text() { return std::strerror(errno); }

}  // namespace

SimFlash::SimFlash(std::uint32_t size, const std::vector<std::uint8_t>& initial, std::string path)
    : cells_(size, 0xFF), path_(std::move(path)) {
  std::copy_n(initial.begin(), std::min<std::size_t>(initial.size(), size), cells_.begin());
  if (path_.empty()) return;
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error(path_ + ": cannot open the simulated flash: " + errno_text());
  struct stat st {};
  ::fstat(fd_, &st);
  if (st.st_size == 0) {
    store(0, size);
    return;
  }
  if (st.st_size != static_cast<off_t>(size) || ::pread(fd_, cells_.data(), size, 0) != static_cast<ssize_t>(size)) {
    ::close(fd_);
    fd_ = -1;
    throw Error(path_ + ": a simulated flash of " + std::to_string(size) + " bytes was expected, the file holds " +
                std::to_string(st.st_size));
  }
}

SimFlash::~SimFlash() {
  if (fd_ >= 0) ::close(fd_);
}

void SimFlash::store(std::uint32_t offset, std::uint32_t len) {
  if (fd_ < 0) return;
  if (::pwrite(fd_, cells_.data() + offset, len, offset) != static_cast<ssize_t>(len)) {
    throw Error(path_ + ": cannot write the simulated flash: " + errno_text());
  }
}

bool SimFlash::erase_page(std::uint32_t page) {
  if ((std::uint64_t{page} + 1) * kPageBytes > cells_.size()) return false;
  std::fill_n(cells_.begin() + page * kPageBytes, kPageBytes, std::uint8_t{0xFF});
  store(page * kPageBytes, kPageBytes);
  return true;
}

bool SimFlash::program(std::uint32_t offset, const std::uint8_t* data) {
  if (offset % 8 != 0 || std::uint64_t{offset} + 8 > cells_.size()) return false;
  // As on the part: programming a cell that is not erased is an error (PROGERR).
  if (std::any_of(cells_.begin() + offset, cells_.begin() + offset + 8, [](std::uint8_t c) { return c != 0xFF; })) return false;
  std::copy_n(data, 8, cells_.begin() + offset);
  store(offset, 8);
  return true;
}

bool SimFlash::read(std::uint32_t offset, std::uint8_t* out, std::uint32_t len) const {
  if (std::uint64_t{offset} + len > cells_.size()) return false;
  std::copy_n(cells_.begin() + offset, len, out);
  return true;
}

}  // namespace robogene::can::sim
