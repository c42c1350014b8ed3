// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/group_requests.hpp"

#include <cstdint>

#include "robogene/dev/rpc_codec.hpp"
#include "robogene/vocab.hpp"

namespace robogene::dev {
namespace {

struct GroupForm {
  const char* group;
  const char* single;
  bool has_values;
};

constexpr GroupForm kForms[] = {
    {"posg", "pos", true}, {"relg", "rel", true}, {"velg", "vel", true}, {"accg", "acc", true},
    {"vmog", "vmo", true}, {"dpog", "dpo", true}, {"stog", "sto", false},
};

const GroupForm* form_of(const Value& v) {
  const vocab_t code = rpc::vocab_of(v);
  for (const GroupForm& f : kForms) {
    if (code == vocab(f.group)) return &f;
  }
  return nullptr;
}

// n, (joints) and, when the form has them, (values) starting at `at` in `items`.
std::vector<Bottle> expand(const GroupForm& form, const Bottle& items, std::size_t at, const Bottle* values,
                           const char* verb = "set") {
  std::vector<Bottle> out;
  if (items.size() < at + 2 || !items[at].is_int() || !items[at + 1].is_list()) return out;
  const Bottle& joints = items[at + 1].as_list();
  const std::int64_t n = items[at].as_int64();
  if (n < 0 || static_cast<std::size_t>(n) != joints.size()) return out;
  if (form.has_values && (!values || values->size() != joints.size())) return out;
  std::vector<Bottle> requests;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (!joints[i].is_int()) return out;
    Bottle single{Value::vocab(verb), Value::vocab(form.single), joints[i]};
    if (form.has_values) single.add((*values)[i]);
    requests.push_back(std::move(single));
  }
  return requests;
}

constexpr GroupForm kMotionDoneGroup{"dong", "don", false};

}  // namespace

std::optional<std::vector<Bottle>> expand_group_request(const Bottle& request) {
  if (request.size() < 2 || rpc::vocab_of(request[0]) != vocab("set")) return std::nullopt;
  const GroupForm* form = form_of(request[1]);
  if (!form) return std::nullopt;
  const std::size_t expected = form->has_values ? 5 : 4;
  if (request.size() != expected || (form->has_values && !request[4].is_list())) {
    return std::vector<Bottle>{};
  }
  return expand(*form, request, 2, form->has_values ? &request[4].as_list() : nullptr);
}

std::optional<std::vector<Bottle>> expand_group_command(const Bottle& message) {
  if (message.size() != 2 || !message[0].is_list() || !message[1].is_list()) return std::nullopt;
  const Bottle& head = message[0].as_list();
  if (head.empty()) return std::nullopt;
  const GroupForm* form = form_of(head[0]);
  if (!form || !form->has_values) return std::nullopt;
  if (head.size() != 3) return std::vector<Bottle>{};
  return expand(*form, head, 1, &message[1].as_list());
}

std::optional<std::vector<Bottle>> expand_group_query(const Bottle& request) {
  if (request.size() < 2 || rpc::vocab_of(request[0]) != vocab("get") ||
      rpc::vocab_of(request[1]) != vocab(kMotionDoneGroup.group)) {
    return std::nullopt;
  }
  if (request.size() != 4) return std::vector<Bottle>{};
  return expand(kMotionDoneGroup, request, 2, nullptr, "get");
}

Bottle combine_group_replies(const Bottle& request, const std::vector<Bottle>& replies) {
  const Bottle fail{Value::vocab("fail")};
  if (replies.empty()) return fail;
  std::int32_t all = 1;
  for (const Bottle& r : replies) {
    if (r.size() < 3 || rpc::vocab_of(r[0]) != vocab("is") || !r[2].is_int()) return fail;
    all = all && r[2].as_int64() != 0;
  }
  Bottle out{Value::vocab("is"), request[1], Value::int32(all)};
  const Bottle& last = replies.back();
  for (std::size_t i = 3; i < last.size(); ++i) out.add(last[i]);  // its stamp and [ok], as each single has
  return out;
}

}  // namespace robogene::dev
