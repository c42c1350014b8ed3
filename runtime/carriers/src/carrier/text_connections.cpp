// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "text_connections.hpp"

#include "grow_read.hpp"
#include "robogene/error.hpp"
#include "robogene/text_completeness.hpp"

namespace robogene::carrier::detail {

namespace {
const char kAckLine[] = "<ACK>\r\n";
}

TextInbound::TextInbound(std::unique_ptr<Link> link, std::string carrier, bool acks,
                         std::string remote, std::size_t max_message_size, std::size_t max_line)
    : link_(std::move(link)),
      carrier_(std::move(carrier)),
      acks_(acks),
      remote_(std::move(remote)),
      max_message_size_(max_message_size),
      max_line_(max_line) {
  // People type slowly: no timeout on a text connection.
  link_->stream.set_read_timeout(net::kNoTimeout);
}

bool TextInbound::read(InboundMessage& m) {
  out_.clear();
  if (!link_->reader.wait_for_data()) return false;
  std::string line = link_->reader.read_line(max_line_);
  m.command = line;
  m.key = line.empty() ? 0 : line[0];
  m.envelope.clear();
  m.text_mode = true;
  m.reply_expected = false;
  m.payload.clear();
  if (m.key == 'd' || m.key == 'D') {
    // "d" waits for a reply, "do" / "D" mean data only.
    m.reply_expected = m.key == 'd' && line != "do";
    read_bottle_text(m);
  } else if (m.key == 'a') {
    m.reply_expected = true;
    read_bottle_text(m);
  }
  return true;
}

void TextInbound::read_bottle_text(InboundMessage& m) {
  // Completeness is tracked as lines arrive, never by rescanning all the text so far (that
  // made a long message cost time quadratic in its lines). Like text_is_complete, the scan
  // leaves out the text's last line end, which a following non-empty line brings in.
  std::string text;
  TextCompleteness scan;
  bool newline_pending = false;
  for (;;) {
    std::string line = link_->reader.read_line(max_line_);
    bool continued = !line.empty() && line.back() == '\\';
    if (continued) line.pop_back();
    if (!text.empty()) {
      text += '\n';
      if (newline_pending) scan.feed("\n");
      newline_pending = true;
    }
    text += line;
    if (!line.empty()) {
      if (newline_pending) scan.feed("\n");
      newline_pending = false;
      scan.feed(line);
    }
    if (text.size() > max_message_size_) {
      throw ParseError(text.size(), "text message from " + remote_ + " (" + peer_text() +
                                        ") exceeds the maximum message size of " +
                                        std::to_string(max_message_size_) + " bytes");
    }
    if (!continued && scan.complete()) break;
  }
  m.payload.assign(text.begin(), text.end());
}

void TextInbound::reply(const Bottle& b) {
  out_ += b.to_text();
  out_ += "\r\n";
}

void TextInbound::reply_raw(const void* data, std::size_t size) {
  out_.append(static_cast<const char*>(data), size);
}

void TextInbound::finish() {
  if (acks_) out_ += kAckLine;
  if (!out_.empty()) link_->stream.write_all(out_.data(), out_.size());
  out_.clear();
}

std::unique_ptr<OutboundConnection> TextInbound::reverse() {
  return std::make_unique<TextOutbound>(std::move(link_), carrier_, acks_, remote_, max_line_,
                                        max_message_size_, true);
}

TextOutbound::TextOutbound(std::unique_ptr<Link> link, std::string carrier, bool acks,
                           std::string remote, std::size_t max_line, std::size_t max_reply_size,
                           bool reversed)
    : link_(std::move(link)),
      carrier_(std::move(carrier)),
      acks_(acks),
      remote_(std::move(remote)),
      max_line_(max_line),
      max_reply_size_(max_reply_size),
      reply_budget_("reply from " + remote_),
      reversed_(reversed) {}

void TextOutbound::set_timeout(net::Millis t) {
  link_->stream.set_read_timeout(t);
  link_->stream.set_write_timeout(t);
}

void TextOutbound::write_message(const OutboundMessage& m) {
  std::string text;
  switch (m.key) {
    case 'd': text = "d\r\n"; break;
    case 'D': text = "do\r\n"; break;  // "data only", as the paper's transcript shows
    case 'a': text = "a\r\n"; break;
    case 'r': text = "r\r\n"; break;
    case 'q': text = "q\r\n"; break;
    default: text = std::string(1, m.key) + "\r\n"; break;
  }
  if (m.bottle) {
    text += m.bottle->to_text();
    text += "\r\n";
  }
  link_->stream.write_all(text.data(), text.size());
  awaiting_ = !reversed_ && acks_;
}

void TextOutbound::await_completion(Bottle* reply) {
  if (!awaiting_) {
    if (reply) reply->clear();
    return;
  }
  awaiting_ = false;
  std::string reply_text;
  ReleaseOnExit release(reply_budget_);
  for (;;) {
    std::string line = link_->reader.read_line(max_line_);
    if (line == "<ACK>") break;
    // A reader that never sends "<ACK>" must not make the reply grow for ever.
    if (reply_text.size() + line.size() + 1 > max_reply_size_) {
      throw NetworkError("reply from " + remote_ + " (" + peer_text() + ") is more than the " +
                         std::to_string(max_reply_size_) + "-byte limit of a reply, and has not ended");
    }
    reply_budget_.add(line.size() + 1);
    if (!reply_text.empty()) reply_text += '\n';
    reply_text += line;
  }
  if (reply) *reply = Bottle::from_text(reply_text);
}

void TextOutbound::close() noexcept {
  if (closed_ || !link_) return;
  closed_ = true;
  try {
    link_->stream.set_write_timeout(net::Millis{1000});
    link_->stream.write_all("q\r\n", 3);
  } catch (const std::exception&) {
    // Peer already gone.
  }
  link_->stream.shutdown();
  link_->stream.close();
}

}  // namespace robogene::carrier::detail
