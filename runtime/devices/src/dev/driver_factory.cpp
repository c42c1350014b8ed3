// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/driver_factory.hpp"

#include "robogene/dev/nws/network_devices.hpp"
#include "robogene/error.hpp"

namespace robogene::dev {

DriverFactory& DriverFactory::instance() {
  // Never destroyed: devices may outlive static destructors. Built on first use, so the drivers'
  // registrars may run in any order.
  // The framework's own devices are added here: robogene_core is a static library, whose
  // linker would drop self-registering objects.
  static DriverFactory* factory = [] {
    auto* f = new DriverFactory;
    add_network_devices(*f);
    return f;
  }();
  return *factory;
}

void DriverFactory::add(std::string name, std::string description, Creator create) {
  if (name.empty() || !create) throw Error("DriverFactory: a driver needs a name and a creator");
  std::lock_guard<std::mutex> lock(mutex_);
  if (drivers_.count(name)) throw Error("DriverFactory: driver '" + name + "' is already known");
  Entry entry{name, std::move(description), std::move(create)};
  drivers_.emplace(std::move(name), std::move(entry));
}

bool DriverFactory::has(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return drivers_.count(name) != 0;
}

std::unique_ptr<DeviceDriver> DriverFactory::create(const std::string& name) const {
  Creator creator;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = drivers_.find(name);
    if (it == drivers_.end()) {
      std::string known;
      for (const auto& [n, e] : drivers_) known += (known.empty() ? "" : ", ") + n;
      throw Error("unknown device '" + name + "' (known devices: " + known + ")");
    }
    creator = it->second.create;
  }
  auto device = creator();
  if (!device) throw Error("device '" + name + "': its creator returned nothing");
  return device;
}

std::vector<DriverFactory::Entry> DriverFactory::entries() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Entry> out;
  for (const auto& [n, e] : drivers_) out.push_back(e);
  return out;
}

}  // namespace robogene::dev
