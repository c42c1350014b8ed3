// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/remote_grabber.hpp"

#include <exception>

#include "robogene/dev/image_codec.hpp"
#include "robogene/dev/nws/device_port.hpp"
#include "robogene/dev/nws/server_identity.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/network.hpp"

namespace robogene::dev {

RemoteGrabber::RemoteGrabber()
    : GrabberClient([this](const Bottle& request, Bottle& reply) { return call(request, reply); }) {}

bool RemoteGrabber::call(const Bottle& request, Bottle& reply) {
  try {
    return rpc_.write(request, reply);
  } catch (const std::exception& e) {
    log::warn(local_ + "/rpc_client", std::string("request to ") + remote_ + "/rpc failed: " + e.what());
    return false;
  }
}

bool RemoteGrabber::open(const Searchable& config) {
  close();
  remote_ = port_name_option(config, "remote");
  local_ = port_name_option(config, "local");
  const std::string carrier = config.get_string("stream", config.get_string("carrier", "tcp"));
  timeout_ = std::chrono::milliseconds(
      static_cast<long>(config.get_float("timeout", 1.0, 0.001, 3600.0) * 1000.0));
  names_ = device_name_client(config);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = false;
  }
  images_.set_reader([this](const Bottle& data, const MessageInfo&, Bottle*) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = data;
    ++frames_;
    arrived_.notify_all();
  });
  try {
    rpc_.open(local_ + "/rpc_client", *names_);
    rpc_.add_output(remote_ + "/rpc", "tcp");
    check_server(serves_robogene(*names_, remote_ + "/rpc", kServiceName));  // server_identity.hpp
    images_.open(local_, *names_);
    auto r = network::connect(*names_, remote_, local_, carrier);
    if (!r.ok) throw Error("connecting " + remote_ + " to " + local_ + ": " + r.message);
    image_connected_ = true;
  } catch (const ConfigError&) {
    close();
    throw;
  } catch (const std::exception& e) {
    close();
    throw Error("remote_grabber " + local_ + " -> " + remote_ + ": " + e.what());
  }
  return true;
}

bool RemoteGrabber::close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  arrived_.notify_all();
  if (image_connected_ && names_) {
    try {
      network::disconnect(*names_, remote_, local_);
    } catch (const std::exception& e) {
      log::warn(local_, std::string("could not disconnect: ") + e.what());
    }
    image_connected_ = false;
  }
  images_.close();
  rpc_.close();
  return true;
}

bool RemoteGrabber::getImage(ImageRgb& image) {
  Bottle message;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    const std::uint64_t seen = frames_;
    if (!arrived_.wait_for(lock, timeout_, [&] { return closing_ || frames_ != seen; }) || closing_) {
      return false;
    }
    message = latest_;
  }
  std::string error;
  if (!decode_image(message, image, error)) {
    log::warn(local_, "a frame from " + remote_ + " cannot be decoded: " + error);
    return false;
  }
  return true;
}

bool RemoteGrabber::frame_size(std::int32_t& cols, std::int32_t& rows) {
  Bottle message;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!arrived_.wait_for(lock, timeout_, [&] { return closing_ || frames_ != 0; }) || closing_) {
      return false;
    }
    message = latest_;
  }
  ImageRgb image;
  std::string error;
  if (!decode_image(message, image, error)) return false;
  cols = static_cast<std::int32_t>(image.width);
  rows = static_cast<std::int32_t>(image.height);
  return true;
}

bool RemoteGrabber::width(std::int32_t& cols) {
  std::int32_t rows = 0;
  if (frames_received() == 0 && GrabberClient::width(cols)) return true;
  return frame_size(cols, rows);
}

bool RemoteGrabber::height(std::int32_t& rows) {
  std::int32_t cols = 0;
  if (frames_received() == 0 && GrabberClient::height(rows)) return true;
  return frame_size(cols, rows);
}

std::uint64_t RemoteGrabber::frames_received() {
  std::lock_guard<std::mutex> lock(mutex_);
  return frames_;
}

}  // namespace robogene::dev
