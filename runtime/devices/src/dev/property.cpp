// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Property storage, lookups, merging and the bottle form.
#include <utility>

#include "robogene/dev/property.hpp"

namespace robogene::dev {
namespace {
const Value kNull;
}  // namespace

Property::Property(const Property& other) : source_(other.source_), entries_(other.entries_) {
  for (const auto& [name, group] : other.groups_) {
    groups_.emplace(name, std::make_unique<Property>(*group));
  }
}

Property& Property::operator=(const Property& other) {
  if (this != &other) {
    Property copy(other);
    *this = std::move(copy);
  }
  return *this;
}

void Property::put(std::string_view key, Value value, std::string origin) {
  Bottle values;
  values.add(std::move(value));
  put_values(key, std::move(values), std::move(origin));
}

void Property::put_values(std::string_view key, Bottle values, std::string origin) {
  Value found = values.size() == 1 ? values[0] : Value::list(values);
  entries_.insert_or_assign(std::string(key),
                            Entry{std::move(values), std::move(found), std::move(origin)});
}

Property& Property::add_group(std::string_view name, std::string origin) {
  auto it = groups_.find(name);
  if (it == groups_.end()) {
    it = groups_.emplace(std::string(name), std::make_unique<Property>(std::move(origin))).first;
  }
  return *it->second;
}

void Property::merge(const Property& other) {
  for (const auto& [key, entry] : other.entries_) entries_.insert_or_assign(key, entry);
  for (const auto& [name, group] : other.groups_) add_group(name, group->source()).merge(*group);
}

const Value& Property::find(std::string_view key) const {
  auto it = entries_.find(key);
  return it == entries_.end() ? kNull : it->second.found;
}

bool Property::check(std::string_view key) const { return entries_.find(key) != entries_.end(); }

const Searchable* Property::find_group(std::string_view name) const {
  auto it = groups_.find(name);
  return it == groups_.end() ? nullptr : it->second.get();
}

std::string Property::origin(std::string_view key) const {
  auto it = entries_.find(key);
  return it == entries_.end() ? std::string() : it->second.origin;
}

std::vector<std::string> Property::keys() const {
  std::vector<std::string> out;
  for (const auto& [key, entry] : entries_) out.push_back(key);
  return out;
}

Bottle Property::to_bottle() const {
  Bottle out;
  for (const auto& [key, entry] : entries_) {
    Bottle& item = out.add_list();
    item.add(Value::string(key));
    for (const Value& v : entry.values) item.add(v);
  }
  for (const auto& [name, group] : groups_) {
    Bottle& item = out.add_list();
    item.add(Value::string(name));
    for (const Value& v : group->to_bottle()) item.add(v);
  }
  return out;
}

}  // namespace robogene::dev
