// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Filling a Property from an ini text, a command line or a bottle.
#include <fstream>
#include <sstream>
#include <string>

#include "robogene/dev/property.hpp"

namespace robogene::dev {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// Cuts a `#` or `//` comment that is outside quotes.
std::string_view strip_comment(std::string_view line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '\\' && quoted) {
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (!quoted && (c == '#' || (c == '/' && i + 1 < line.size() && line[i + 1] == '/'))) {
      return line.substr(0, i);
    }
  }
  return line;
}

bool is_key_text(const Value& v) { return v.is_string() || v.is_vocab(); }

std::string key_text(const Value& v) {
  return v.is_string() ? v.as_string() : vocab_to_string(v.as_vocab());
}

Bottle parse_values(std::string_view text, const std::string& where, std::size_t column) {
  try {
    return Bottle::from_text(text);
  } catch (const ParseError& e) {
    // The bottle parser counts columns from the start of the values; re-base them on the line.
    std::string what = e.what();
    const std::string prefix = "column " + std::to_string(e.position()) + ": ";
    if (what.compare(0, prefix.size(), prefix) == 0) what.erase(0, prefix.size());
    throw ConfigError(where + ":" + std::to_string(column + e.position() - 1) + ": " + what);
  } catch (const Error& e) {
    throw ConfigError(where + ":" + std::to_string(column) + ": " + e.what());
  }
}

}  // namespace

Property Property::from_ini(std::string_view text, const std::string& source_name) {
  Property root(source_name);
  Property* current = &root;
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const auto end = text.find('\n', pos);
    const std::string_view raw = text.substr(pos, end == std::string_view::npos ? text.npos : end - pos);
    pos = end == std::string_view::npos ? text.size() + 1 : end + 1;
    ++line_no;
    const std::string where = source_name + ":" + std::to_string(line_no);
    const std::string_view line = trim(strip_comment(raw));
    if (line.empty()) continue;
    const std::size_t column = static_cast<std::size_t>(line.data() - raw.data()) + 1;
    if (line.front() == '[') {
      if (line.back() != ']' || line.size() < 3) {
        throw ConfigError(where + ":" + std::to_string(column) +
                          ": a group header is [name], got '" + std::string(line) + "'");
      }
      const std::string name(trim(line.substr(1, line.size() - 2)));
      current = &root.add_group(name, where);
      continue;
    }
    const auto split = line.find_first_of(" \t");
    const std::string key(line.substr(0, split));
    Bottle values;
    if (split != std::string_view::npos) {
      const std::string_view rest = trim(line.substr(split));
      values = parse_values(rest, where, column + static_cast<std::size_t>(rest.data() - line.data()));
    }
    if (values.empty()) {
      values.add(Value::vocab(vocab("1")));  // a bare key is a flag, as on a command line
    }
    if (current->check(key)) {
      throw ConfigError(where + ":" + std::to_string(column) + ": key '" + key +
                        "' is already set at " + current->origin(key));
    }
    current->put_values(key, std::move(values), where);
  }
  return root;
}

Property Property::from_ini_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot open the configuration file");
  std::ostringstream text;
  text << in.rdbuf();
  return from_ini(text.str(), path);
}

Property Property::from_command_line(const std::vector<std::string>& args) {
  Property root("command line");
  std::size_t i = 0;
  while (i < args.size()) {
    const std::string where = "command line argument " + std::to_string(i + 1);
    const std::string& arg = args[i];
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) {
      throw ConfigError(where + ": expected --key, got '" + arg + "'");
    }
    std::string key = arg.substr(2);
    Property* target = &root;
    if (const auto sep = key.find("::"); sep != std::string::npos) {
      target = &root.add_group(key.substr(0, sep), where);
      key = key.substr(sep + 2);
    }
    ++i;
    Bottle values;
    while (i < args.size() && !(args[i].size() > 2 && args[i].compare(0, 2, "--") == 0)) {
      // Each argument is one value; a shell already split words, so "a b" stays one string.
      Bottle one = parse_values(args[i], "command line argument " + std::to_string(i + 1), 1);
      if (one.size() == 1) {
        values.add(one[0]);
      } else {
        values.add(Value::string(args[i]));
      }
      ++i;
    }
    if (values.empty()) values.add(Value::vocab(vocab("1")));
    target->put_values(key, std::move(values), where);
  }
  return root;
}

Property Property::from_bottle(const Bottle& b, const std::string& source_name) {
  Property root(source_name);
  for (std::size_t i = 0; i < b.size(); ++i) {
    const std::string where = source_name + " item " + std::to_string(i);
    const Value& item = b[i];
    if (!item.is_list() || item.as_list().empty() || !is_key_text(item.as_list()[0])) {
      throw ConfigError(where + ": expected (key value...), got " + item.to_text());
    }
    const Bottle& list = item.as_list();
    const std::string key = key_text(list[0]);
    bool group = list.size() > 1;
    for (std::size_t k = 1; k < list.size() && group; ++k) {
      group = list[k].is_list() && !list[k].as_list().empty() && is_key_text(list[k].as_list()[0]);
    }
    if (group) {
      Bottle inner;
      for (std::size_t k = 1; k < list.size(); ++k) inner.add(list[k]);
      root.add_group(key, where).merge(from_bottle(inner, where));
      continue;
    }
    Bottle values;
    for (std::size_t k = 1; k < list.size(); ++k) values.add(list[k]);
    if (values.empty()) values.add(Value::vocab(vocab("1")));
    root.put_values(key, std::move(values), where);
  }
  return root;
}

}  // namespace robogene::dev
