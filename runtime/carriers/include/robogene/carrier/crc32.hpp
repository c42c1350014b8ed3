// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The standard CRC-32 (zlib's crc32, polynomial 0xEDB88320) that prefixes udp and mcast datagrams
// (the name server's multicast fallback uses the same prefix).
#pragma once

#include <cstddef>
#include <cstdint>

namespace robogene::carrier {

std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc = 0);

}  // namespace robogene::carrier
