// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One HTTP request from a web browser, as the http carrier needs it (private to src/carrier):
// the target after the first '/', its path and form fields, and how YARP turns that into port
// commands (classic page, reverse stream, or a data message; see HttpCarrier in YARP 3).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "robogene/carrier/connection.hpp"
#include "robogene/carrier/yarp_number.hpp"

namespace robogene::carrier::detail {

struct HttpRequest {
  std::string method;  // "GET" or "POST"
  std::string target;  // after the first '/', undecoded: "data=1+2", "get/axes?format=json"
  std::vector<std::pair<std::string, std::string>> fields;  // query / form fields, decoded
  // What a browser says about who asked (empty when the header is absent): http_origin.hpp.
  std::string host;            // Host: "192.168.1.20:10002"
  std::string origin;          // Origin: "http://192.168.1.20:10002", or "null"
  std::string referer;         // Referer: the page the request came from
  std::string sec_fetch_site;  // Sec-Fetch-Site: "same-origin", "cross-site", "none", ...

  const std::string* field(const std::string& key) const;
};

// Reads the rest of the request whose first 8 bytes were `header` ("GET /dat", "POST /fo"):
// request line, header lines up to the blank one, and a form body when one is announced.
// Throws ParseError naming what is wrong (line too long, too many headers, body too large).
HttpRequest read_http_request(const Header& header, Link& link, std::size_t max_body);

// "%41+b" -> "A b" (form encoding); a bad escape is kept as typed.
std::string url_decode(const std::string& s);
// "a=1&b=x+y" -> {(a, 1), (b, x y)}.
std::vector<std::pair<std::string, std::string>> parse_fields(const std::string& query);

// What a request asks the port to do, following YARP's HttpTwoWayStream.
struct HttpPlan {
  enum class Kind { Page, Stream, Call } kind = Kind::Page;
  // Page: text-protocol lines run one after another ("*", "d" + bottle, "?"...), their answers
  // shown in an HTML page. Call: one data (or admin) message whose reply is the response body.
  std::vector<std::string> lines;
  bool admin = false;
  bool json = false;
};
HttpPlan plan_http_request(const HttpRequest& r);

}  // namespace robogene::carrier::detail
