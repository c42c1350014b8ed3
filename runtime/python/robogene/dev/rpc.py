# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""RPC in Python, driven by the generated wire tables (generated/wire.py): a server that answers
request Bottles by calling a device, and the base of the generated clients. The bottles and the
reply shapes are YARP 3's, as in the generated C++ (runtime/src/dev/generated/*_server.cpp):
[ok] / [fail] for commands, [is] <echo> <values> [tsta] <n> <t> [ok] for queries (no stamp for
those the IDL marks `stamp: false`), [nak] for requests of fewer than two items. In "scoped"
services (YARP's frame grabbers) a failure is [nak], a command is answered as COMMAND_REPLIES says
(YARP 3.12.3's [fgc] [set] 1 or 0; an empty bottle where the IDL gives no form), and a query with a
reply head (REPLY_HEADS) is that head and its values. Needs the compiled core (robogene.Bottle)."""
from __future__ import annotations

import math
import threading
import time
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

from .. import Bottle, Error, Value, vocab
from .generated import interfaces as _interfaces
from .generated import types as _types
from .generated.wire import (COMMAND_REPLIES, COMMANDS, ENUMS, INTERFACES, REPLIES, REPLY_HEADS, SERVICES,
                             STREAMS, STRUCTS, USAGE)
from .image import ImageRgb

_INT32 = (-(2 ** 31), 2 ** 31 - 1)
_OK, _FAIL, _IS, _NAK, _TSTA = (vocab(w) for w in ("ok", "fail", "is", "nak", "tsta"))


class _Bad(Exception):
    """A request item that does not decode as its declared type."""


def vocab_of(v: Value) -> int:
    """The vocab of a vocab or string item (strings truncated to 4 chars, as YARP), else 0."""
    if v.is_vocab():
        return v.as_vocab()
    if v.is_string() and v.as_string():
        return vocab(v.as_string()[:4])
    return 0


def decode(v: Value, type_name: str) -> Any:
    if type_name.endswith("[]"):
        if not v.is_list():
            raise _Bad
        return [decode(item, type_name[:-2]) for item in v.as_list()]
    if type_name in ("joint", "int32"):
        if not v.is_int() or not _INT32[0] <= v.as_int() <= _INT32[1]:
            raise _Bad
        return int(v.as_int())
    if type_name == "float64":
        if not v.is_number():
            raise _Bad
        return float(v.as_float())
    if type_name == "bool":
        if v.is_int() and v.as_int() in (0, 1):
            return v.as_int() == 1
        if v.is_vocab() and v.as_vocab() in (0, vocab("1")):
            return v.as_vocab() != 0
        raise _Bad
    if type_name == "string":
        if not v.is_string():
            raise _Bad
        return v.as_string()
    if type_name == "vocab":
        code = vocab_of(v)
        if not code:
            raise _Bad
        return code
    if type_name in ENUMS:
        kind, members = ENUMS[type_name]
        raw = decode(v, "int32") if kind == "int32" else vocab_of(v)
        if raw not in members.values():
            raise _Bad
        return getattr(_types, type_name)(raw)
    if type_name in STRUCTS:
        fields = STRUCTS[type_name]
        if not v.is_list() or len(v.as_list()) != len(fields):
            raise _Bad
        items = v.as_list()
        return getattr(_types, type_name)(**{name: decode(items[i], t) for i, (name, t) in enumerate(fields)})
    raise _Bad


def encode(b: Bottle, value: Any, type_name: str) -> None:
    if type_name.endswith("[]"):
        inner = b.add_list()
        for item in value:
            encode(inner, item, type_name[:-2])
    elif type_name in ("joint", "int32"):
        b.add(Value.int32(int(value)))
    elif type_name == "float64":
        b.add(Value.float64(float(value)))
    elif type_name == "bool":
        b.add(Value.int32(1 if value else 0))
    elif type_name == "string":
        b.add(Value.string(str(value)))
    elif type_name == "vocab":
        b.add(Value.vocab(int(value)))
    elif type_name in ENUMS:
        kind = ENUMS[type_name][0]
        b.add(Value.vocab(int(value)) if kind == "vocab" else Value.int32(int(value)))
    elif type_name in STRUCTS:
        inner = b.add_list()
        for name, t in STRUCTS[type_name]:
            encode(inner, getattr(value, name), t)
    else:
        raise TypeError(f"cannot encode type {type_name!r}")


def _single(word: str) -> Bottle:
    b = Bottle()
    b.add(Value.vocab(vocab(word)))
    return b


def _head_item(request: Bottle, item) -> Value:
    """An item of a reply head: a request item, a vocab, or ("#vocab") a vocab's code as int32."""
    if isinstance(item, int):
        return request[item]
    if item.startswith("#"):
        return Value.int32(vocab(item[1:]))
    return Value.vocab(vocab(item))


def _finish(reply: Bottle, stamp: int) -> None:
    reply.add(Value.vocab(_TSTA))
    reply.add(Value.int32(stamp))
    reply.add(Value.float64(time.time()))
    reply.add(Value.vocab(_OK))


class RpcServer:
    """Answers requests for one service by calling `device` through the interfaces it implements."""

    def __init__(self, service: str, device: Any):
        if service not in SERVICES:
            raise LookupError(f"unknown service {service!r} (known: {', '.join(sorted(SERVICES))})")
        self.service = service
        self.fingerprint, names, self._protocol, self._introspection = SERVICES[service]
        self._device = device
        self._scoped = REPLIES.get(service) == "scoped"
        self._failure = "nak" if self._scoped else "fail"
        self._command_reply = COMMAND_REPLIES.get(service)
        self._implemented = [n for n in names if isinstance(device, getattr(_interfaces, n))]
        self._routes: Dict[Tuple[int, ...], Tuple] = {}
        for iface in names:
            for method, (wire, echo, args, results, stamped) in INTERFACES[iface][1].items():
                if wire is None:
                    continue
                key = tuple(vocab(w) for w in wire)
                head = REPLY_HEADS.get(iface, {}).get(method)
                entry = self._routes.setdefault(key, (echo if head is None else head, args, results,
                                                      bool(results) and stamped, []))
                entry[4].append((iface, method))
        self._lock = threading.Lock()
        self._stamps = 0

    def interfaces(self) -> List[Tuple[str, str]]:
        return [(n, INTERFACES[n][0]) for n in self._implemented]

    def _stamp(self) -> int:
        with self._lock:
            n = self._stamps
            self._stamps += 1
            return n

    def _matches(self, request: Bottle, path) -> bool:
        return len(request) >= len(path) and all(vocab_of(request[i]) == vocab(w) for i, w in enumerate(path))

    def respond(self, request: Bottle) -> Bottle:
        if len(request) >= 1 and ((request[0].is_vocab() and request[0].as_vocab() == vocab("help")) or
                                  (request[0].is_string() and request[0].as_string() == "help")):
            reply = _single("many")
            for line in USAGE[self.service]:
                reply.add(Value.string(line))
            return reply
        if len(request) < 2:
            return _single("nak")
        if self._protocol and len(request) == len(self._protocol[0]) and self._matches(request, self._protocol[0]):
            reply = _single(self._protocol[1])
            for n in self._protocol[2]:
                reply.add(Value.int32(n))
            reply.add(Value.vocab(_OK))
            return reply
        if self._introspection and len(request) == len(self._introspection) and \
                self._matches(request, self._introspection):
            reply = _single("is")
            reply.add(request[len(self._introspection) - 1])
            listed = reply.add_list()
            for name, fp in self.interfaces():
                pair = listed.add_list()
                pair.add(Value.string(name))
                pair.add(Value.string(fp))
            _finish(reply, self._stamp())
            return reply
        codes = [vocab_of(request[i]) for i in range(len(request))]
        # Longest paths first, so that a longer path is never shadowed by a shorter one.
        for key in sorted(self._routes, key=len, reverse=True):
            if tuple(codes[:len(key)]) != key:
                continue
            echo, args, results, stamped, candidates = self._routes[key]
            stamp = self._stamp() if stamped else 0
            reply = self._call(request, len(key), echo, args, results, candidates)
            if not results and self._command_reply:
                return self._command_answer(request, reply is not None)
            if reply is None:
                return _single(self._failure)
            if stamped:
                _finish(reply, stamp)
            elif not isinstance(echo, list) and not self._scoped:
                reply.add(Value.vocab(_OK))  # no tail after a reply head, nor in scoped services
            return reply
        self._stamp()  # an unknown query still takes a number, as in YARP
        return _single(self._failure)

    def _command_answer(self, request: Bottle, done: bool) -> Bottle:
        """YARP 3.12.3's answer to a frame-grabber set (commit e3442205f): the request's items as
        vocabs, whatever spelling the request used, then int32 1 if the device did it, else 0."""
        reply = Bottle()
        for item in self._command_reply:
            reply.add(Value.int32(1 if done else 0) if item == "result" else Value.vocab(vocab_of(request[item])))
        return reply

    def publish(self, stream: str) -> Optional[Bottle]:
        """The message the stream port publishes now (None when the device cannot provide it):
        a per-axis list is the message itself (a YARP Vector), an image a YARP 3 image."""
        port, period, iface, method, result = STREAMS[self.service][stream]
        if iface not in self._implemented:
            return None
        value = getattr(self._device, method)()
        if value is None:
            return None
        if result == "image_rgb":
            return encode_image(value)
        out = Bottle()
        for item in value if result.endswith("[]") else [value]:
            encode(out, item, result[:-2] if result.endswith("[]") else result)
        return out

    def command(self, message: Bottle) -> bool:
        """A message of the streaming command port, ([head...]) (values...), with no reply:
        the head is a request path without the service's command prefix. Returns whether the
        device carried it out."""
        if self.service not in COMMANDS or len(message) != 2 or not message[0].is_list() \
                or not message[1].is_list():
            return False
        prefix = [vocab(w) for w in COMMANDS[self.service][1]]
        head, values = message[0].as_list(), message[1].as_list()
        codes = [vocab_of(head[i]) for i in range(len(head))]
        # (head, the request path it stands for): the service's commands without the prefix, and
        # the aliases (YARP's [dtq] for [set] [torq] [ref]).
        heads = [(key[len(prefix):], key) for key in self._routes
                 if list(key[:len(prefix)]) == prefix and len(key) > len(prefix) and not self._routes[key][2]]
        heads += [(tuple(vocab(w) for w in alias), tuple(vocab(w) for w in path))
                  for alias, path in COMMANDS[self.service][2].items()]
        for path, key in sorted(heads, key=lambda h: len(h[0]), reverse=True):
            if tuple(codes[:len(path)]) != path or key not in self._routes:
                continue
            request = Bottle()
            for code in key:
                request.add(Value.vocab(code))
            for item in list(head)[len(path):]:
                request.add(item)
            args = self._routes[key][1]
            if args and args[-1].endswith("[]"):
                request.add(Value.list(values))
            else:
                for v in values:
                    request.add(v)
            reply = self.respond(request)
            return len(reply) == 1 and vocab_of(reply[0]) == _OK
        return False

    def _call(self, request, start, echo, args, results, candidates) -> Optional[Bottle]:
        if len(request) != start + len(args):
            return None
        try:
            values = [decode(request[start + k], t) for k, t in enumerate(args)]
        except _Bad:
            return None
        target = next(((i, m) for i, m in candidates if i in self._implemented), None)
        if target is None:
            return None
        try:
            answer = getattr(self._device, target[1])(*values)
        except Exception:  # a device that raises answers like one that fails
            return None
        if not results:
            return Bottle() if answer is True else None
        if answer is None:
            return None
        answer = answer if len(results) > 1 else (answer,)
        if isinstance(echo, list):  # the IDL's own reply head
            reply = Bottle()
            for item in echo:
                reply.add(_head_item(request, item))
        else:
            reply = _single("is")
            reply.add(Value.vocab(vocab(echo)) if isinstance(echo, str) else request[echo])
        try:
            for value, t in zip(answer, results):
                encode(reply, value, t)
        except (TypeError, ValueError, AttributeError):
            return None
        return reply


class RpcClient:
    """Base of the generated clients: sends requests through `transport(request) -> reply`."""

    SERVICE = ""

    def __init__(self, transport: Callable[[Bottle], Bottle]):
        self._transport = transport

    def _request(self, wire: Sequence[str], arg_types, args) -> Optional[Bottle]:
        request = Bottle()
        for w in wire:
            request.add(Value.vocab(vocab(w)))
        try:
            for value, t in zip(args, arg_types):
                encode(request, value, t)
        except (TypeError, ValueError, AttributeError):
            return None
        return self._transport(request)

    def _command(self, wire, arg_types, args) -> bool:
        reply = self._request(wire, arg_types, args)
        if REPLIES.get(self.SERVICE) == "scoped":
            return reply is not None and _scoped_command_done(self.SERVICE, wire, reply)
        return reply is not None and len(reply) >= 1 and vocab_of(reply[0]) == _OK

    def _query(self, wire, arg_types, args, result_types, reply=None):
        head = reply
        request = Bottle()
        for w in wire:
            request.add(Value.vocab(vocab(w)))
        reply = self._request(wire, arg_types, args)
        if reply is None:
            return None
        if head is not None:
            try:
                for k, v in enumerate(args):
                    encode(request, v, arg_types[k])
            except (TypeError, ValueError, AttributeError):
                return None
            if len(reply) != len(head) + len(result_types) or any(
                    reply[k].to_text() != _head_item(request, item).to_text() for k, item in enumerate(head)):
                return None
            start = len(head)
        elif len(reply) < 2 + len(result_types) or vocab_of(reply[0]) != _IS:
            return None
        else:
            start = 2
        try:
            values = [decode(reply[start + k], t) for k, t in enumerate(result_types)]
        except _Bad:
            return None
        return values[0] if len(values) == 1 else tuple(values)

    def check_server(self, robogene_server: bool) -> List[Tuple[str, str]]:
        """The (name, fingerprint) of the server's interfaces; raises robogene.Error naming an
        interface built from different IDL, or a YARP 3 server of another protocol version. Only
        a server known to be Robogene's (`robogene_server`: its port says so,
        robogene.dev.server_identity) is asked for its fingerprints: YARP 3's log every request
        they do not know as an error. Any other is checked by its protocol version where the
        service has one."""
        fingerprint, names, protocol, introspection = SERVICES[self.SERVICE]
        if introspection and robogene_server:
            reply = self._transport(_path(introspection))
            if len(reply) < 3 or vocab_of(reply[0]) != _IS or not reply[2].is_list():
                raise Error(f"{self.SERVICE} server says it is Robogene's but does not list its interfaces: "
                            f"{reply.to_text()}")
            theirs = []
            for item in reply[2].as_list():
                pair = item.as_list() if item.is_list() else None
                if pair is None or len(pair) != 2 or not pair[0].is_string() or not pair[1].is_string():
                    raise Error(f"{self.SERVICE} server: malformed interface entry {item.to_text()}")
                name, fp = pair[0].as_string(), pair[1].as_string()
                if name in names and INTERFACES[name][0] != fp:
                    raise Error(f"{self.SERVICE} server: interface {name} has fingerprint {fp}, this "
                                f"client was generated for {INTERFACES[name][0]} (the two sides were "
                                "built from different IDL)")
                theirs.append((name, fp))
            return theirs
        if not protocol:
            return []  # a YARP 3 server of a service without a protocol request: nothing to ask
        reply = self._transport(_path(protocol[0]))
        if len(reply) < 3 or vocab_of(reply[0]) != vocab(protocol[1]) or not reply[1].is_int() \
                or not reply[2].is_int():
            raise Error(f"{self.SERVICE} server: unexpected reply to the protocol request: {reply.to_text()}")
        if (reply[1].as_int(), reply[2].as_int()) != tuple(protocol[2][:2]):
            raise Error(f"{self.SERVICE} server speaks protocol {reply[1].as_int()}.{reply[2].as_int()}, "
                        f"this client speaks {protocol[2][0]}.{protocol[2][1]}")
        return []


def _scoped_command_done(service: str, wire, reply: Bottle) -> bool:
    """Whether a frame grabber did a set, from its reply: YARP 3.12.3's form (COMMAND_REPLIES,
    [fgc] [set] 1 or 0), or the empty bottle of Robogene's servers before it. YARP 3.5's servers
    answer [nak] to every set, done or not, and 3.12.3's to one they cannot parse: a failure."""
    form = COMMAND_REPLIES.get(service)
    if len(reply) == 0:
        return True
    if not form or len(reply) != len(form):
        return False
    for k, item in enumerate(form):
        if item == "result":
            if not reply[k].is_int():
                return False
        elif vocab_of(reply[k]) != vocab(wire[item]):
            return False
    return reply[len(form) - 1].as_int() != 0


_ROWS_BOTTOM_UP = 1 << 16
_MAX_SIDE = 1 << 16


def encode_image(image: ImageRgb, quantum: int = 8) -> Bottle:
    """A YARP 3 image: [mat] [rgb] (3 size quantum|1<<16 width height) {pixels}, rows padded to
    `quantum` bytes, bottom row first as bit 16 says (the same bytes as the C++ encode_image)."""
    row = (image.width * 3 + quantum - 1) // quantum * quantum
    packed = image.width * 3
    pixels = bytearray(row * image.height)
    for y in range(image.height):
        at = (image.height - 1 - y) * row
        pixels[at:at + packed] = image.pixels[y * packed:(y + 1) * packed]
    b = Bottle()
    b.add(Value.vocab(vocab("mat")))
    b.add(Value.vocab(vocab("rgb")))
    header = b.add_list()
    for n in (3, len(pixels), quantum | _ROWS_BOTTOM_UP, image.width, image.height):
        header.add(Value.int32(n))
    b.add(Value.blob(bytes(pixels)))
    return b


class ImageError(ValueError):
    """A message that is not a YARP 3 RGB image; the text says what is wrong with it."""


def decode_image(m: Bottle) -> ImageRgb:
    """The image in a YARP 3 image message, by the rules of the C++ decode_image: rows bottom
    row first when bit 16 of the quantum field is set (as YARP 3.5 reads it), top row first
    otherwise; raises ImageError with the reason for anything else."""
    if len(m) != 4 or not m[0].is_vocab() or m[0].as_vocab() != vocab("mat"):
        raise ImageError(f"not an image: expected [mat] <pixel code> (header) {{pixels}}, got {len(m)} items")
    if not m[1].is_vocab() or m[1].as_vocab() != vocab("rgb"):
        raise ImageError(f"pixel code {m[1].to_text()} is not [rgb]")
    if not m[2].is_list() or len(m[2].as_list()) != 5:
        raise ImageError(f"image header is not a list of 5 integers: {m[2].to_text()}")
    f = []
    for i, v in enumerate(m[2].as_list()):
        if not v.is_int():
            raise ImageError(f"image header field {i} is not an integer: {v.to_text()}")
        f.append(v.as_int())
    quantum, width, height = f[2] & 0xFFFF, f[3], f[4]
    if f[0] != 3:
        raise ImageError(f"image depth {f[0]} is not 3 (RGB)")
    if width < 0 or height < 0 or width > _MAX_SIDE or height > _MAX_SIDE or quantum < 1:
        raise ImageError(f"image size {width}x{height} or quantum {quantum} is out of range")
    row = (width * 3 + quantum - 1) // quantum * quantum
    expected = row * height
    blob = m[3].as_bytes() if m[3].is_blob() else None
    if blob is None or len(blob) != expected or f[1] != expected:
        raise ImageError(f"image of {width}x{height} with quantum {quantum} needs {expected} pixel bytes, "
                         f"header says {f[1]}, blob has {len(blob) if blob is not None else 'none'}")
    bottom_up = bool(f[2] & _ROWS_BOTTOM_UP)
    image = ImageRgb()
    image.resize(width, height)
    packed = width * 3
    source = memoryview(blob)
    for y in range(height):
        at = (height - 1 - y if bottom_up else y) * row
        image.pixels[y * packed:(y + 1) * packed] = source[at:at + packed]
    return image


def _path(words: Sequence[str]) -> Bottle:
    b = Bottle()
    for w in words:
        b.add(Value.vocab(vocab(w)))
    return b
