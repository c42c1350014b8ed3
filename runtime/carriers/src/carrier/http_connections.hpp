// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The http carrier's connections (private to src/carrier). An inbound connection turns one
// browser request into the port commands YARP would run (HttpPlan) and the port's answers into
// one HTTP response, then ends; `GET /r` turns it around into a chunked stream of everything
// the port writes, one bottle per line, until the browser goes away.
#pragma once

#include <deque>
#include <functional>
#include <memory>
#include <string>

#include "http_request.hpp"
#include "robogene/carrier/connection.hpp"

namespace robogene::carrier::detail {

class HttpInbound final : public InboundConnection {
 public:
  // `write_refusal`, when not empty, is why requests that write (data, admin messages,
  // connection commands) are answered "403 Forbidden" instead of reaching the port; data for
  // which `harmless` says true is not a write.
  HttpInbound(std::unique_ptr<Link> link, HttpPlan plan, std::string port_name, net::Millis write_timeout,
              const std::string& write_refusal, const std::function<bool(const Bottle&)>& harmless = {});
  const std::string& carrier_name() const override;
  const std::string& remote_name() const override;
  std::string peer_text() const override { return peer_; }
  bool is_text() const override { return true; }
  void interrupt() noexcept override;
  int socket_fd() const noexcept override { return link_->stream.fd(); }

  bool read(InboundMessage& m) override;
  void reply(const Bottle& b) override;
  void reply_raw(const void* data, std::size_t size) override;
  void finish() override;
  std::unique_ptr<OutboundConnection> reverse() override;

 private:
  struct Step {
    char key;
    std::string command;
    std::string data;
    bool reply_expected;
  };
  static bool is_write(const Step& s, const std::function<bool(const Bottle&)>& harmless);
  void queue_page_lines(const std::vector<std::string>& lines);
  void respond(const std::string& status, const std::string& type, const std::string& body);
  std::string page(const std::string& text) const;

  std::unique_ptr<Link> link_;
  HttpPlan plan_;
  std::string port_name_;
  std::string peer_;
  std::deque<Step> steps_;
  char current_ = 0;
  std::string text_;        // answers collected for a page
  Bottle call_reply_;
  bool call_replied_ = false;
  bool responded_ = false;
  std::string last_data_;   // shown again in the page's form
};

// `s` with &, <, > and " escaped for HTML.
std::string html_escape(const std::string& s);
// A Bottle as JSON: lists as arrays, numbers as numbers, strings and vocabs as strings.
std::string bottle_json(const Bottle& b);

}  // namespace robogene::carrier::detail
