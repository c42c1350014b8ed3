// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The name_ser carrier (reference sections 3.1 and 4.1): header `NAME_SER`, then the rest of a
// text line, so that on the wire a request reads `NAME_SERVER query /w\n`. Replies are raw text,
// with no ack. YARP's clients send one request per connection. Add it to a CarrierRegistry to
// let a port (the name server /root) accept it:
//   carrier::CarrierRegistry::global().add(name::make_name_ser_carrier());
#pragma once

#include <memory>

#include "robogene/carrier/carrier.hpp"

namespace robogene::name {

std::shared_ptr<const carrier::Carrier> make_name_ser_carrier();

}  // namespace robogene::name
