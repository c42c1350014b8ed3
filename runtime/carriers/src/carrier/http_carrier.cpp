// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// http (YARP's HttpCarrier): a web browser talks to a port. The first 8 bytes are `GET /`
// followed by anything but `?ac` (YARP leaves `GET /?ac...` to its MJPEG carrier), or
// `POST /fo` (the page's own form). One request, one response, then the connection closes.
// A port cannot send over http: it is the browser's way in, not a transport between ports.
#include <cstring>
#include <memory>
#include <string>

#include "http_connections.hpp"
#include "http_origin.hpp"
#include "http_request.hpp"
#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier {

namespace {

bool begins(const Header& h, const char* prefix) { return std::memcmp(h.data(), prefix, std::strlen(prefix)) == 0; }

class HttpCarrier final : public Carrier {
 public:
  std::string name() const override { return "http"; }
  Header header() const override {
    Header h;
    std::memcpy(h.data(), "GET / HT", 8);
    return h;
  }
  bool matches(const Header& h) const override {
    return (begins(h, "GET /") && !begins(h, "GET /?ac")) || begins(h, "POST /fo");
  }
  bool is_text() const override { return true; }

  std::unique_ptr<InboundConnection> accept(std::unique_ptr<Link> link,
                                            const AcceptContext& ctx) const override {
    // A form body is one bottle of text at most: keep it within the line limit of text carriers.
    detail::HttpRequest req = detail::read_http_request(ctx.header, *link, ctx.max_line_length);
    detail::HttpPlan plan = detail::plan_http_request(req);
    const std::string host = link->stream.peer().host;
    std::string refusal;
    if (!ctx.access.http_writes()) {
      refusal = "HTTP writes to this port are off: a web page could send them from any browser "
                "(set ROBOGENE_HTTP_WRITES=1 to enable them for allowed peers; see docs/security.md)";
    } else if (!ctx.access.allows(host)) {
      refusal = refusal_text("HTTP write", host);
    } else if (std::string why = detail::cross_site_reason(req, detail::this_machine_names()); !why.empty()) {
      refusal = "HTTP write refused: " + why + " (see docs/security.md)";
    }
    return std::make_unique<detail::HttpInbound>(std::move(link), std::move(plan), ctx.local_name,
                                                 ctx.handshake_timeout, refusal, ctx.harmless_data);
  }

  std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link>, const ConnectContext& ctx) const override {
    throw Error("cannot connect " + ctx.sender_name + " to " + ctx.target_name +
                " over http: http is how a web browser reaches a port, not a carrier between ports "
                "(use tcp, or point a browser at the port's address)");
  }
};

}  // namespace

std::shared_ptr<const Carrier> make_http_carrier() { return std::make_shared<HttpCarrier>(); }

}  // namespace robogene::carrier
