// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Property: the configuration a device's open() receives (the paper's Searchable). One structure,
// filled from .ini files (with [groups]), from `--key value` command lines (`--group::key` for a
// key inside a group) or from bottles of (key value...) lists. Every entry remembers where it came
// from, so a bad value is reported as "motor.ini:12: key 'axes': ..." rather than "bad config".
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

namespace robogene::dev {

// A configuration value that is missing, malformed or out of range; what() names the place.
class ConfigError : public Error {
 public:
  using Error::Error;
};

// Read access to a configuration, as devices see it.
class Searchable {
 public:
  virtual ~Searchable() = default;

  // The value of `key`: its single value, or a list when the key was given several values.
  // Null when absent.
  virtual const Value& find(std::string_view key) const = 0;
  virtual bool check(std::string_view key) const = 0;
  // A nested group ([name] in an ini file, `--name::key` on a command line), or nullptr.
  virtual const Searchable* find_group(std::string_view name) const = 0;
  // Where `key` was set ("motor.ini:12", "command line argument 3", ...), or "" when absent.
  virtual std::string origin(std::string_view key) const = 0;
  // Where the whole configuration came from, for messages about missing keys.
  virtual std::string source() const = 0;

  // Typed reads. Absent keys give the fallback; present keys of the wrong type or range throw
  // ConfigError naming the origin, the key and what was expected.
  std::string get_string(std::string_view key, std::string_view fallback) const;
  std::int32_t get_int(std::string_view key, std::int32_t fallback, std::int32_t min,
                       std::int32_t max) const;
  double get_float(std::string_view key, double fallback, double min, double max) const;
  bool get_bool(std::string_view key, bool fallback) const;
  // Throws ConfigError when `key` is absent.
  const Value& require(std::string_view key) const;
};

class Property final : public Searchable {
 public:
  explicit Property(std::string source = "configuration") : source_(std::move(source)) {}
  Property(const Property& other);
  Property& operator=(const Property& other);
  Property(Property&&) noexcept = default;
  Property& operator=(Property&&) noexcept = default;

  // An ini text: `key value...` lines, `[group]` sections, `#` and `//` comments. Values use
  // the bottle text syntax (numbers, "quoted strings", (lists), [vocabs]). `source_name` is
  // the file name used in messages. Throws ConfigError naming source:line:column.
  static Property from_ini(std::string_view text, const std::string& source_name);
  static Property from_ini_file(const std::string& path);
  // argv-style: `--key v1 v2 --flag --group::key v`. A flag without value is `true`.
  // argv[0] is not skipped; pass argv + 1 for a program's arguments.
  static Property from_command_line(const std::vector<std::string>& args);
  // (key value...) lists, optionally nested: (group (key value...) ...) for a group, as YARP's
  // Property::fromString reads them.
  static Property from_bottle(const Bottle& b, const std::string& source_name = "bottle");

  // Sets `key` (replacing any earlier value). `origin` is shown in error messages.
  void put(std::string_view key, Value value, std::string origin = "set by program");
  void put_values(std::string_view key, Bottle values, std::string origin);
  Property& add_group(std::string_view name, std::string origin = "set by program");
  // Copies every entry and group of `other` over this one (later sources win).
  void merge(const Property& other);

  const Value& find(std::string_view key) const override;
  bool check(std::string_view key) const override;
  const Searchable* find_group(std::string_view name) const override;
  std::string origin(std::string_view key) const override;
  std::string source() const override { return source_; }

  std::vector<std::string> keys() const;
  // (key value...) lists and (group ...) lists, readable back by from_bottle.
  Bottle to_bottle() const;

 private:
  struct Entry {
    Bottle values;  // as given
    Value found;    // what find() answers: the single value, or a List of all of them
    std::string origin;
  };
  std::string source_;
  std::map<std::string, Entry, std::less<>> entries_;
  std::map<std::string, std::unique_ptr<Property>, std::less<>> groups_;
};

}  // namespace robogene::dev
