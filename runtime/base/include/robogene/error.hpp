// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Errors shared by the whole runtime. Every error says where (a byte offset, a column, a port, a
// peer) and what was expected, so that bad input is reported rather than crashed on.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace robogene {

// Base class of every error the runtime throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Malformed input to a decoder (binary bottle, text bottle, handshake, index...).
// `position()` is a 0-based byte offset for binary input and a 1-based column for text input.
class ParseError : public Error {
 public:
  ParseError(std::size_t position, const std::string& what_failed)
      : Error(what_failed), position_(position) {}
  std::size_t position() const noexcept { return position_; }

 private:
  std::size_t position_;
};

// A network or protocol failure on one connection (peer vanished, timeout, refused).
class NetworkError : public Error {
 public:
  using Error::Error;
};

}  // namespace robogene
