// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "http_request.hpp"

#include <cctype>
#include <cstdlib>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier::detail {

namespace {

constexpr std::size_t kMaxLine = 8192;
constexpr int kMaxHeaderLines = 100;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool starts_with(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

// What YARP appends to a call: (REQUEST_URI "<target>") then every field as (key value), e.g.
// `set pos 1 (REQUEST_URI "set/pos/1?x=1") (x "1")` (order checked against YARP 3.5.0).
std::string fields_as_text(const HttpRequest& r) {
  Bottle b;
  b.add(Value::list(Bottle{Value("REQUEST_URI"), Value(r.target)}));
  for (const auto& f : r.fields) b.add(Value::list(Bottle{Value(f.first), Value(f.second)}));
  return b.to_text();
}

}  // namespace

const std::string* HttpRequest::field(const std::string& key) const {
  for (const auto& f : fields) {
    if (f.first == key) return &f.second;
  }
  return nullptr;
}

std::string url_decode(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '+') {
      out += ' ';
    } else if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
               std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
      out += static_cast<char>(std::strtol(s.substr(i + 1, 2).c_str(), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> parse_fields(const std::string& query) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t at = 0;
  while (at <= query.size()) {
    std::size_t end = query.find('&', at);
    if (end == std::string::npos) end = query.size();
    std::string part = query.substr(at, end - at);
    if (!part.empty()) {
      std::size_t eq = part.find('=');
      if (eq == std::string::npos) {
        out.emplace_back(url_decode(part), "");
      } else {
        out.emplace_back(url_decode(part.substr(0, eq)), url_decode(part.substr(eq + 1)));
      }
    }
    at = end + 1;
  }
  return out;
}

HttpRequest read_http_request(const Header& header, Link& link, std::size_t max_body) {
  std::string first(header.begin(), header.end());
  first += link.reader.read_line(kMaxLine);  // rest of "GET /target HTTP/1.1"
  HttpRequest r;
  std::size_t sp = first.find(' ');
  r.method = first.substr(0, sp);
  std::size_t slash = first.find('/', sp);
  std::size_t end = first.find(' ', slash);
  r.target = first.substr(slash + 1, end == std::string::npos ? std::string::npos : end - slash - 1);
  long long content_length = 0;
  bool form = false;
  for (int n = 0;; ++n) {
    if (n == kMaxHeaderLines) {
      throw ParseError(0, "http request from " + link.stream.peer_text() + " has more than " +
                              std::to_string(kMaxHeaderLines) + " header lines");
    }
    std::string line = link.reader.read_line(kMaxLine);
    if (line.empty()) break;
    std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string key = lower(line.substr(0, colon));
    // Leading spaces are skipped in one step: erasing them one by one was quadratic.
    std::size_t value_at = line.find_first_not_of(' ', colon + 1);
    std::string value = value_at == std::string::npos ? std::string() : line.substr(value_at);
    if (key == "content-length") {
      char* stop = nullptr;
      content_length = std::strtoll(value.c_str(), &stop, 10);
      if (stop == value.c_str() || content_length < 0) {
        throw ParseError(0, "http request from " + link.stream.peer_text() + ": bad Content-Length \"" + value + "\"");
      }
    } else if (key == "content-type") {
      form = starts_with(lower(value), "application/x-www-form-urlencoded");
    } else if (key == "host") {
      r.host = value;
    } else if (key == "origin") {
      r.origin = value;
    } else if (key == "referer") {
      r.referer = value;
    } else if (key == "sec-fetch-site") {
      r.sec_fetch_site = lower(value);
    }
  }
  if (static_cast<unsigned long long>(content_length) > max_body) {
    throw ParseError(0, "http request from " + link.stream.peer_text() + " announces a " +
                            std::to_string(content_length) + "-byte body, more than the limit of " +
                            std::to_string(max_body));
  }
  std::string body(static_cast<std::size_t>(content_length), '\0');
  if (content_length > 0) link.reader.read_exact(body.data(), body.size());
  // As YARP: the fields come from a form body when there is one, else from the target itself
  // ("data=1+2" or "get/axes?x=1").
  std::size_t q = r.target.find('?');
  if (form && r.method == "POST") {
    r.fields = parse_fields(body);
  } else if (q != std::string::npos) {
    r.fields = parse_fields(r.target.substr(q + 1));
  } else if (r.target.find('=') != std::string::npos) {
    r.fields = parse_fields(r.target);
  }
  return r;
}

HttpPlan plan_http_request(const HttpRequest& r) {
  HttpPlan plan;
  const std::string* cmd = r.field("cmd");
  const std::string* data = r.field("data");
  const std::string* req = r.field("req");
  const std::string* format = r.field("format");
  plan.admin = r.field("admin") != nullptr;
  plan.json = (format && *format == "json") || (req && !format);
  if (req) {  // ?req=get axes: a call whose reply comes back as JSON
    plan.kind = HttpPlan::Kind::Call;
    plan.lines = {*req + " " + fields_as_text(r)};
    return plan;
  }
  std::string s;
  if (cmd) {
    s = *cmd;
  } else if (data) {
    s = (plan.admin ? "a\n" : "d\n") + *data;
  } else {
    s = r.target;
  }
  bool classic = s.size() <= 1 || s[0] == '?' || s[1] == '?' || starts_with(s, "d\n") ||
                 starts_with(s, "a\n") || starts_with(s, "form") || starts_with(s, "data") ||
                 starts_with(s, "favi");
  if (!classic) {
    // "get/axes?x=1" -> the data message "get axes"; each segment is decoded after the split,
    // so "%2Froot" stays one word "/root"; then the fields, as YARP appends them.
    std::string path = s.substr(0, s.find('?'));
    std::string words;
    std::size_t at = 0;
    while (at <= path.size()) {
      std::size_t end = path.find('/', at);
      if (end == std::string::npos) end = path.size();
      if (!words.empty()) words += ' ';
      words += url_decode(path.substr(at, end - at));
      at = end + 1;
    }
    plan.kind = HttpPlan::Kind::Call;
    plan.lines = {words + " " + fields_as_text(r)};
    return plan;
  }
  s = url_decode(s);
  if (s == "r") {
    plan.kind = HttpPlan::Kind::Stream;
    return plan;
  }
  if (s.empty()) s = "*";
  std::size_t at = 0;
  while (at <= s.size()) {
    std::size_t end = s.find('\n', at);
    if (end == std::string::npos) end = s.size();
    plan.lines.push_back(s.substr(at, end - at));
    at = end + 1;
  }
  return plan;
}

}  // namespace robogene::carrier::detail
