// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/flasher.hpp"

#include <algorithm>
#include <cstdio>
#include <thread>

#include "motor_control.hpp"

namespace robogene::can {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint32_t kEnterKey = 0x544F4F42u;  // "BOOT", RG_BOOT_ENTER_KEY
constexpr Millis kPoll{100};

std::string hex32(std::uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08X", v);
  return buf;
}

std::string ms(Millis t) { return std::to_string(t.count()) + " ms"; }

BoardIdentity identity_of(int address, const BootloaderIdentifyReply& r) {
  BoardIdentity b;
  b.address = address;
  b.board_type = static_cast<std::uint8_t>(r.board_type);
  b.board_id = r.board_id;
  b.revision = r.revision;
  b.in_bootloader = r.stage == FirmwareStage::bootloader;
  b.image_valid = r.image_valid;
  b.version_major = r.version_major;
  b.version_minor = r.version_minor;
  return b;
}

// The bootloader-class conversation with one board: its replies only.
class BootLink {
 public:
  BootLink(Bus& bus, int address) : bus_(bus), address_(static_cast<std::uint8_t>(address)) {
    bus_.set_filters({{static_cast<std::uint16_t>(make_id(CanId{static_cast<std::uint8_t>(MessageClass::bootloader), address_, kHostAddress})), 0x7FF}});
  }
  ~BootLink() { bus_.set_filters({}); }

  template <class M>
  void send(const M& m) {
    bus_.send(encode(command(address_, 0, m)), Millis(100));
  }

  // The next reply of type R within `timeout`; other replies (late acknowledgements) are skipped.
  template <class R>
  std::optional<R> await(Millis timeout) {
    const auto deadline = Clock::now() + timeout;
    for (;;) {
      const auto left = std::chrono::duration_cast<Millis>(deadline - Clock::now());
      if (left.count() <= 0) return std::nullopt;
      const std::optional<Frame> f = bus_.receive(left);
      if (!f) return std::nullopt;
      try {
        const Envelope e = decode(*f);
        if (e.source != address_) continue;
        if (const R* r = std::get_if<R>(&e.message)) return *r;
      } catch (const CodecError&) {
        // not a frame of this protocol: another node's traffic
      }
    }
  }

  template <class R, class M>
  std::optional<R> ask(const M& m, Millis timeout) {
    send(m);
    return await<R>(timeout);
  }

  // A write's acknowledgement, whatever its sequence number.
  std::optional<BootloaderWriteReply> await_write(Millis timeout) { return await<BootloaderWriteReply>(timeout); }

 private:
  Bus& bus_;
  std::uint8_t address_;
};

void say(const FlashOptions& o, const std::string& line) {
  if (o.log) o.log(line);
}

std::optional<BoardIdentity> ask_identity(BootLink& link, int address, Millis timeout) {
  if (auto r = link.ask<BootloaderIdentifyReply>(BootloaderIdentify{}, timeout)) return identity_of(address, *r);
  return std::nullopt;
}

// Polls identify until the board answers from the stage wanted.
std::optional<BoardIdentity> await_stage(BootLink& link, int address, bool bootloader, Millis timeout) {
  const auto deadline = Clock::now() + timeout;
  while (Clock::now() < deadline) {
    const auto id = ask_identity(link, address, kPoll);
    if (id && id->in_bootloader == bootloader) return id;
    if (id) std::this_thread::sleep_for(kPoll);
  }
  return std::nullopt;
}

void write_image(BootLink& link, const FirmwareImage& image, const FlashOptions& o) {
  const std::size_t words = (image.bytes.size() + 3) / 4;
  if (words > 0x10000) throw FlashError("write", image.source + ": too big for 16-bit sequence numbers");
  auto word = [&](std::size_t seq) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      const std::size_t at = 4 * seq + i;
      v |= std::uint32_t{at < image.bytes.size() ? image.bytes[at] : std::uint8_t{0xFF}} << (8 * i);
    }
    return v;
  };
  std::size_t acked = 0, next = 0, reported = 0;
  int stalls = 0;
  std::optional<std::size_t> last_rewind;
  const std::size_t window = static_cast<std::size_t>(std::max(1, o.window));
  while (acked < words) {
    while (next < words && next - acked < window) {
      link.send(BootloaderWrite{static_cast<std::uint16_t>(next), word(next)});
      ++next;
    }
    const auto r = link.await_write(o.reply_timeout);
    if (!r) {
      if (++stalls > o.retries) {
        throw FlashError("write", "no acknowledgement of word " + std::to_string(acked) + " (byte " +
                                      std::to_string(4 * acked) + " of " + std::to_string(image.bytes.size()) + ") after " +
                                      std::to_string(o.retries + 1) + " tries of " + ms(o.reply_timeout) +
                                      "; the board stays in its bootloader: flash it again");
      }
      next = acked;  // send again everything not acknowledged
      continue;
    }
    const std::size_t seq = r->sequence;
    switch (r->status) {
      case BootStatus::ok:
        // Acknowledgements come in order; one for a word already counted is a repeat's.
        if (seq >= acked && seq < next) {
          acked = seq + 1;
          stalls = 0;
        }
        break;
      case BootStatus::bad_sequence:
        // The board expects `seq`: everything before it is in. Rewind once per gap, not per
        // reply of the frames that were in flight behind the lost one.
        if (seq > acked) acked = std::min(seq, next);
        if (last_rewind != seq) {
          next = acked;
          last_rewind = seq;
        }
        break;
      default:
        throw FlashError("write", std::string("the board refused word ") + std::to_string(seq) + ": " + to_string(r->status) +
                                      (r->status == BootStatus::wrong_board || r->status == BootStatus::wrong_revision
                                           ? " (it checked the image header: " + describe(image) + ")"
                                           : ""));
    }
    const std::size_t done = std::min(acked * 4, image.bytes.size());
    if (o.progress && done != reported) o.progress(done, image.bytes.size());
    reported = done;
  }
}

}  // namespace

std::string describe(const BoardIdentity& b) {
  std::string s = "board " + std::to_string(b.board_id) + ", revision " + std::string(1, static_cast<char>(b.revision)) +
                  " at address " + std::to_string(b.address) + ", ";
  if (b.in_bootloader) {
    s += "in its bootloader " + std::to_string(b.version_major) + "." + std::to_string(b.version_minor) +
         (b.image_valid ? " (holding a valid application)" : " (no valid application)");
  } else {
    s += "running firmware " + std::to_string(b.version_major) + "." + std::to_string(b.version_minor);
  }
  return s;
}

std::vector<BoardIdentity> find_boards(Bus& bus, Millis wait) {
  bus.set_filters({{0x700, 0x70F}});  // bootloader-class frames to the host
  bus.send(encode(command(kBroadcastAddress, 0, BootloaderIdentify{})), Millis(100));
  std::vector<BoardIdentity> found;
  const auto deadline = Clock::now() + wait;
  for (;;) {
    const auto left = std::chrono::duration_cast<Millis>(deadline - Clock::now());
    if (left.count() <= 0) break;
    const auto f = bus.receive(left);
    if (!f) break;
    try {
      const Envelope e = decode(*f);
      if (const auto* r = std::get_if<BootloaderIdentifyReply>(&e.message)) found.push_back(identity_of(e.source, *r));
    } catch (const CodecError&) {
    }
  }
  bus.set_filters({});
  std::sort(found.begin(), found.end(), [](const BoardIdentity& a, const BoardIdentity& b) { return a.address < b.address; });
  return found;
}

std::optional<BoardIdentity> identify_board(Bus& bus, int address, Millis timeout) {
  BootLink link(bus, address);
  return ask_identity(link, address, timeout);
}

void flash_firmware(Bus& bus, const FirmwareImage& image, const FlashOptions& o) {
  // find
  int address = 0;
  if (o.address) {
    address = *o.address;
    if (address < kFirstBoardAddress || address > kLastBoardAddress) {
      throw FlashError("find", "address " + std::to_string(address) + " is not a board address (" +
                                   std::to_string(kFirstBoardAddress) + ".." + std::to_string(kLastBoardAddress) + ")");
    }
  } else {
    const auto boards = find_boards(bus, o.reply_timeout);
    std::string seen;
    for (const auto& b : boards) seen += (seen.empty() ? "" : "; ") + describe(b);
    std::vector<BoardIdentity> fits;
    for (const auto& b : boards) {
      if (b.board_id == image.board_id) fits.push_back(b);
    }
    if (fits.size() != 1) {
      throw FlashError("find", (fits.empty() ? "no board built for board " : "several boards built for board ") +
                                   std::to_string(image.board_id) + " answered (" + (seen.empty() ? "none answered" : seen) +
                                   "); give --address");
    }
    address = fits.front().address;
  }
  BootLink link(bus, address);
  auto id = ask_identity(link, address, o.reply_timeout);
  if (!id) id = ask_identity(link, address, o.reply_timeout);
  if (!id) {
    throw FlashError("find", "no board answered bootloader_identify at address " + std::to_string(address) + " within " +
                                 ms(o.reply_timeout) + " (powered? on this bus? at this address?)");
  }
  say(o, "found " + describe(*id));

  // check
  if (o.check_board) {
    if (id->board_type != image.board_type || id->board_id != image.board_id) {
      throw FlashError("check", image.source + " is built for board " + std::to_string(image.board_id) +
                                    "; the board at address " + std::to_string(address) + " is board " +
                                    std::to_string(id->board_id) + ": wrong board, nothing was erased");
    }
    if (id->revision != image.revision) {
      throw FlashError("check", image.source + " is built for revision " + std::string(1, static_cast<char>(image.revision)) +
                                    "; the board is revision " + std::string(1, static_cast<char>(id->revision)) +
                                    ": wrong revision, nothing was erased");
    }
  }

  // enter
  if (!id->in_bootloader) {
    say(o, "restarting board " + std::to_string(address) + " into its bootloader");
    link.send(EnterBootloader{kEnterKey});
    id = await_stage(link, address, true, o.enter_timeout);
    if (!id) {
      throw FlashError("enter", "board " + std::to_string(address) + " did not answer from its bootloader within " +
                                    ms(o.enter_timeout) + " of enter_bootloader");
    }
  }

  // erase
  say(o, "erasing " + std::to_string(image.bytes.size()) + " bytes");
  const auto erased = link.ask<BootloaderEraseReply>(BootloaderErase{static_cast<std::uint32_t>(image.bytes.size())}, o.erase_timeout);
  if (!erased) throw FlashError("erase", "no answer within " + ms(o.erase_timeout));
  if (erased->status != BootStatus::ok) throw FlashError("erase", std::string("the board answered ") + to_string(erased->status));

  // write
  say(o, "writing " + describe(image));
  write_image(link, image, o);

  // verify
  const auto verified = link.ask<BootloaderVerifyReply>(BootloaderVerify{}, o.verify_timeout);
  if (!verified) throw FlashError("verify", "no answer within " + ms(o.verify_timeout));
  if (verified->status != BootStatus::ok) {
    throw FlashError("verify", std::string("the board answered ") + to_string(verified->status) + ": it computed CRC-32 " +
                                   hex32(verified->crc) + ", the image header says " + hex32(image.crc) +
                                   "; the board stays in its bootloader and will not start this image");
  }
  if (verified->crc != image.crc) {
    throw FlashError("verify", "the board computed CRC-32 " + hex32(verified->crc) + ", the image " + hex32(image.crc));
  }
  say(o, "verified: CRC-32 " + hex32(verified->crc));
  if (!o.start) return;

  // start
  const auto started = link.ask<BootloaderStartReply>(BootloaderStart{}, o.reply_timeout);
  if (!started) throw FlashError("start", "no answer within " + ms(o.reply_timeout));
  if (started->status != BootStatus::ok) throw FlashError("start", std::string("the board answered ") + to_string(started->status));
  const auto running = await_stage(link, address, false, o.enter_timeout);
  if (!running) {
    throw FlashError("start", "the application did not answer within " + ms(o.enter_timeout) + " of starting it");
  }
  say(o, "started: " + describe(*running));
}

}  // namespace robogene::can
