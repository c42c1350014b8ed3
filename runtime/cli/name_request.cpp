// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "name_request.hpp"

#include <sys/socket.h>

#include "robogene/error.hpp"
#include "robogene/net/stream_reader.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "yarp_conf.hpp"

namespace robogene::cli {

NameServerReply name_request(const net::Endpoint& server, const std::string& request) {
  net::TcpStream s;
  try {
    s = net::TcpStream::connect(server, net::Millis{3000});
  } catch (const NetworkError& e) {
    throw NetworkError(std::string("cannot reach the name server: ") + e.what() +
                       " (is `robogene server` running? --server HOST:PORT or " + yarp_conf_path() +
                       " say where it is)");
  }
  NameServerReply reply;
  try {
    s.set_read_timeout(net::Millis{10000});
    s.set_write_timeout(net::Millis{10000});
    const std::string line = "NAME_SERVER " + request + "\n";
    s.write_all(line.data(), line.size());
    ::shutdown(s.fd(), SHUT_WR);  // one request per connection: the server closes after replying
    net::StreamReader reader(s);
    while (reader.wait_for_data()) {
      std::string text = reader.read_line(1 << 20);
      if (text == "*** end of message") {
        reply.ended = true;
        break;
      }
      if (text.rfind("*** error: ", 0) == 0) {
        reply.error = text.substr(11);
        continue;
      }
      reply.lines.push_back(text);
    }
  } catch (const NetworkError& e) {
    throw NetworkError("name server at " + server.to_string() + " did not answer \"" + request + "\": " + e.what());
  }
  return reply;
}

}  // namespace robogene::cli
