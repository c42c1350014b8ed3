// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "http_connections.hpp"

#include <cmath>
#include <cstdio>

#include "robogene/error.hpp"

namespace robogene::carrier::detail {

namespace {

const std::string kHttp = "http";
const std::string kWeb = "web";  // the sender name YARP gives every browser

std::string hex_size(std::size_t n) {
  char b[32];
  std::snprintf(b, sizeof b, "%zx", n);
  return b;
}

void json_value(std::string& out, const Value& v);

void json_string(std::string& out, const std::string& s) {
  out += '"';
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          char b[8];
          std::snprintf(b, sizeof b, "\\u%04x", c);
          out += b;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  out += '"';
}

void json_list(std::string& out, const Bottle& b) {
  out += '[';
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (i) out += ", ";
    json_value(out, b[i]);
  }
  out += ']';
}

void json_value(std::string& out, const Value& v) {
  if (v.is_list()) {
    json_list(out, v.as_list());
  } else if (v.is_string()) {
    json_string(out, v.as_string());
  } else if (v.is_vocab()) {
    json_string(out, vocab_to_string(v.as_vocab()));
  } else if (v.is_float()) {
    double d = v.as_float64();
    out += std::isfinite(d) ? v.to_text() : "null";  // JSON has no inf or nan
  } else if (v.is_int()) {
    out += v.to_text();
  } else {
    json_string(out, v.to_text());  // blobs as their text form "{1 2 3}"
  }
}

// Chunked responses start with this many spaces: browsers render nothing before ~1 KiB (YARP
// does the same).
constexpr std::size_t kBrowserPadding = 2048;

class HttpStream final : public OutboundConnection {
 public:
  HttpStream(std::unique_ptr<Link> link, std::string peer) : link_(std::move(link)), peer_(std::move(peer)) {}
  const std::string& carrier_name() const override { return kHttp; }
  const std::string& remote_name() const override { return kWeb; }
  std::string peer_text() const override { return peer_; }
  bool is_text() const override { return true; }
  void interrupt() noexcept override { link_->stream.shutdown(); }
  int socket_fd() const noexcept override { return link_->stream.fd(); }
  void write_message(const OutboundMessage& m) override {
    if (!m.bottle) return;
    std::string line = html_escape(m.bottle->to_text()) + "\r\n";
    std::string chunk = hex_size(line.size()) + "\r\n" + line + "\r\n";
    link_->stream.write_all(chunk.data(), chunk.size());
  }
  void await_completion(Bottle* reply) override {
    if (reply) reply->clear();
  }
  void set_timeout(net::Millis t) override { link_->stream.set_write_timeout(t); }
  void close() noexcept override {
    try {
      static const char kLast[] = "0\r\n\r\n";
      link_->stream.write_all(kLast, sizeof kLast - 1);
    } catch (const std::exception&) {
      // The browser left already.
    }
    link_->stream.shutdown();
  }

 private:
  std::unique_ptr<Link> link_;
  std::string peer_;
};

}  // namespace

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string bottle_json(const Bottle& b) {
  std::string out;
  json_list(out, b);
  return out;
}

HttpInbound::HttpInbound(std::unique_ptr<Link> link, HttpPlan plan, std::string port_name, net::Millis write_timeout,
                         const std::string& write_refusal, const std::function<bool(const Bottle&)>& harmless)
    : link_(std::move(link)), plan_(std::move(plan)), port_name_(std::move(port_name)),
      peer_(link_->stream.peer_text()) {
  link_->stream.set_write_timeout(write_timeout);
  switch (plan_.kind) {
    case HttpPlan::Kind::Page: queue_page_lines(plan_.lines); break;
    case HttpPlan::Kind::Stream: steps_.push_back({'r', "r", "", false}); break;
    case HttpPlan::Kind::Call:
      steps_.push_back({plan_.admin ? 'a' : 'd', plan_.admin ? "a" : "d", plan_.lines.at(0), true});
      break;
  }
  if (write_refusal.empty()) return;
  bool writes = false;
  for (const Step& s : steps_) writes = writes || is_write(s, harmless);
  if (writes) respond("403 Forbidden", "text/plain; charset=utf-8", write_refusal + "\r\n");  // ends the request
}

bool HttpInbound::is_write(const Step& s, const std::function<bool(const Bottle&)>& harmless) {
  // Reading the page ("*"), the help ("?") and the data stream ("r") change nothing; data and
  // admin messages reach the port's owner, the others make or drop connections.
  if ((s.key == 'd' || s.key == 'D') && harmless) {
    try {
      return !harmless(Bottle::from_text(s.data));
    } catch (const ParseError&) {
      return true;  // the port would refuse it anyway; not ours to judge
    }
  }
  return s.key == 'd' || s.key == 'D' || s.key == 'a' || s.key == '/' || s.key == '!' || s.key == '~';
}

const std::string& HttpInbound::carrier_name() const { return kHttp; }
const std::string& HttpInbound::remote_name() const { return kWeb; }
void HttpInbound::interrupt() noexcept { link_->stream.shutdown(); }

void HttpInbound::queue_page_lines(const std::vector<std::string>& lines) {
  // The text protocol's lines (docs/protocol/connections.md section 4): "d", "do", "a" take
  // the next line as their bottle; every other line is a command of its own.
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    char key = line.empty() ? 0 : line[0];
    if (key == 'd' || key == 'D' || key == 'a') {
      std::string data = i + 1 < lines.size() ? lines[++i] : "";
      bool reply = key == 'a' || (key == 'd' && line != "do");
      last_data_ = data;
      steps_.push_back({key, line, data, reply});
    } else if (key != 'q') {
      steps_.push_back({key, line, "", false});
    }
  }
}

bool HttpInbound::read(InboundMessage& m) {
  if (steps_.empty()) {
    if (!responded_ && plan_.kind == HttpPlan::Kind::Page) respond("200 OK", "text/html; charset=utf-8", page(text_));
    return false;  // one request per connection, as YARP serves them
  }
  Step s = std::move(steps_.front());
  steps_.pop_front();
  current_ = s.key;
  m.key = s.key;
  m.command = s.command;
  m.envelope.clear();
  m.text_mode = true;
  m.reply_expected = s.reply_expected;
  m.payload.assign(s.data.begin(), s.data.end());
  m.detached_blobs.clear();
  m.detached_blob_ordinals.clear();
  return true;
}

void HttpInbound::reply(const Bottle& b) {
  if (plan_.kind == HttpPlan::Kind::Call) {
    call_reply_ = b;
    call_replied_ = true;
    return;
  }
  text_ += b.to_text();
  text_ += "\r\n";
}

void HttpInbound::reply_raw(const void* data, std::size_t size) {
  if (plan_.kind == HttpPlan::Kind::Call) {
    // Raw answers (text commands) have no Bottle form: show them as they are.
    std::string raw(static_cast<const char*>(data), size);
    call_reply_ = Bottle{Value(raw)};
    call_replied_ = true;
    return;
  }
  text_.append(static_cast<const char*>(data), size);
}

void HttpInbound::finish() {
  if (plan_.kind == HttpPlan::Kind::Stream && current_ == 'r') {
    std::string head =
        "HTTP/1.1 200 OK\r\nContent-Type: text/html; charset=utf-8\r\nTransfer-Encoding: chunked\r\n"
        "Cache-Control: no-cache\r\n\r\n";
    std::string first = std::string(kBrowserPadding, ' ') + page("").substr(0, page("").find("<pre>") + 6) +
                        "Reading data from port...\r\n";
    head += hex_size(first.size()) + "\r\n" + first + "\r\n";
    link_->stream.write_all(head.data(), head.size());
    responded_ = true;
    return;
  }
  if (plan_.kind != HttpPlan::Kind::Call || responded_) return;
  if (plan_.json) {
    respond("200 OK", "application/json", bottle_json(call_replied_ ? call_reply_ : Bottle{}));
    return;
  }
  if (call_replied_ && call_reply_.size() >= 1) {
    // A reply with a (web "<html>") pair is a page of its own, as in YARP.
    for (std::size_t i = 0; i < call_reply_.size(); ++i) {
      const Value& v = call_reply_[i];
      if (v.is_list() && v.as_list().size() == 2 && v.as_list()[0].is_string() &&
          v.as_list()[0].as_string() == "web") {
        respond("200 OK", "text/html; charset=utf-8", v.as_list()[1].is_string() ? v.as_list()[1].as_string()
                                                                                 : v.as_list()[1].to_text());
        return;
      }
    }
  }
  respond("200 OK", "text/plain; charset=utf-8", call_replied_ ? call_reply_.to_text() + "\r\n" : "");
}

void HttpInbound::respond(const std::string& status, const std::string& type, const std::string& body) {
  std::string out = "HTTP/1.1 " + status + "\r\nContent-Type: " + type +
                    "\r\nContent-Length: " + std::to_string(body.size()) +
                    "\r\nConnection: close\r\n\r\n" + body;
  link_->stream.write_all(out.data(), out.size());
  responded_ = true;
  steps_.clear();
}

std::string HttpInbound::page(const std::string& text) const {
  std::string name = html_escape(port_name_);
  return "<html><head><title>yarp port " + name + "</title></head>\n"
         "<body bgcolor='#ffffcc'><h1>yarp port " + name + "</h1>\n"
         "<p>(<a href=\"/\">connections</a>)&nbsp;&nbsp;\n"
         "(<a href=\"/data=help\">help</a>)&nbsp;&nbsp;\n"
         "(<a href=\"/r\">read</a>)&nbsp;&nbsp;\n</p>\n"
         "<p><form method=\"post\" action=\"/form\"><input type=text name=data value=\"" +
         html_escape(last_data_) + "\"><input type=submit value=\"send data\"></form></p>\n<pre>\n" +
         html_escape(text) + "</pre>\n</body></html>\n";
}

std::unique_ptr<OutboundConnection> HttpInbound::reverse() {
  return std::make_unique<HttpStream>(std::move(link_), peer_);
}

}  // namespace robogene::carrier::detail
