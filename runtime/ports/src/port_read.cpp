// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Port reading: the reader callback, and the hand-off from input threads to Port::read.
#include "port_core.hpp"

namespace robogene {

void Port::set_reader(Reader r) {
  core_->used_for_input = core_->used_for_input || static_cast<bool>(r);
  std::lock_guard<std::mutex> lock(core_->reader_mutex);
  core_->reader = std::move(r);
}

bool Port::read(Bottle& b, bool will_reply, net::Millis timeout, MessageInfo* info) {
  auto& c = *core_;
  c.used_for_input = true;
  if (will_reply) c.used_for_rpc = true;
  std::unique_lock<std::mutex> lk(c.hand_mutex);
  if (c.replying) {  // a previous read promised a reply it never gave: release that sender
    c.replying->done = true;
    c.replying = nullptr;
    c.hand_cv.notify_all();
  }
  auto ready = [&] { return c.closing || (c.pending && !c.pending->taken); };
  if (timeout.count() > 0) {
    if (!c.hand_cv.wait_for(lk, timeout, ready)) return false;
  } else {
    c.hand_cv.wait(lk, ready);
  }
  if (c.closing) return false;
  Core::Pending* p = c.pending;
  p->taken = true;
  b = *p->data;
  if (info) *info = p->info;
  c.pending = nullptr;
  if (will_reply && p->reply) {
    c.replying = p;
  } else {
    p->done = true;
  }
  c.hand_cv.notify_all();
  return true;
}

void Port::reply(const Bottle& b) {
  auto& c = *core_;
  std::lock_guard<std::mutex> lk(c.hand_mutex);
  if (!c.replying) return;
  *c.replying->reply = b;
  c.replying->done = true;
  c.replying = nullptr;
  c.hand_cv.notify_all();
}

}  // namespace robogene
