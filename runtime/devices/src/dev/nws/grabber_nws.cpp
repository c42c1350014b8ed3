// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/grabber_nws.hpp"

#include <thread>

#include "robogene/dev/nws/device_port.hpp"
#include "robogene/dev/nws/server_identity.hpp"
#include "robogene/envelope.hpp"

namespace robogene::dev {

void GrabberNws::open(DeviceDriver& device, const Searchable& config) {
  close();
  const std::string name = port_name_option(config, "name");
  const double period = config.get_float("period", 0.0, 0.0, 10.0);
  NameClient names = device_name_client(config);
  auto server_of_device = std::make_unique<GrabberServer>(device);
  if (server_of_device->interfaces().empty()) {
    throw ConfigError(name + ": the device to serve implements none of the interfaces of the " +
                      GrabberServer::kServiceName + " service");
  }
  server_ = std::move(server_of_device);
  auto* server = server_.get();
  auto answer = [server](const Bottle& data, const MessageInfo&, Bottle* reply) {
    Bottle answer = server->respond(data);
    if (reply) *reply = std::move(answer);
  };
  rpc_.set_reader(answer);
  // YARP 3.5's remote_grabber sends its requests to the image port itself.
  image_.set_reader(answer);
  // Both ports answer requests, so both say they may be asked [get] [rgif].
  announce_service(rpc_, GrabberServer::kServiceName);
  announce_service(image_, GrabberServer::kServiceName);
  try {
    rpc_.open(name + "/rpc", names);
    image_.open(name, names);
  } catch (...) {
    close();
    throw;
  }
  sequence_ = 0;
  publisher_.start(period, [this] { publish(); });
}

void GrabberNws::publish() {
  Bottle image;
  if (!server_->publish_image(image)) {
    // A device with no frame to give: do not spin.
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return;
  }
  image_.set_envelope(Stamp{sequence_++, wall_time_now()}.to_text());
  image_.write(image);
}

void GrabberNws::close() {
  publisher_.stop();
  image_.close();
  rpc_.close();
  server_.reset();
}

std::vector<std::string> GrabberNws::port_names() const {
  std::vector<std::string> out;
  for (const Port* p : {&rpc_, &image_}) {
    if (p->is_open()) out.push_back(p->name());
  }
  return out;
}

}  // namespace robogene::dev
