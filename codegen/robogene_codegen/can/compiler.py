# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Semantic checks of a `can_protocol:` IDL file (the structure is the JSON Schema's job).

Every problem is reported with the file, line and column of the offending text: codes that
collide or do not fit their identifier bits, payloads longer than a frame, unknown field types
or units, enum values that do not fit their wire type, identifier layouts that overlap.
"""
from __future__ import annotations

import hashlib
import json
import math
from typing import Optional

from ..idl.errors import IdlError
from ..idl.loader import Document
from .model import (CAN_UNITS, SCALARS, CanClass, CanEnum, CanField, CanFlags, CanProtocol, EnumMember,
                    FlagBit, IdField, Message, scalar_range)

ID_BITS = 11
FRAME_BYTES = 8
AXIS_BIT = 0x80  # bit 7 of a command byte selects axis 1; the code keeps the other 7 bits
BROADCAST_MASK = "BroadcastMask"


class CanChecker:
    def __init__(self, errors: list[IdlError]):
        self.errors = errors

    def error(self, mark, message: str) -> None:
        self.errors.append(IdlError(mark, message))

    def check(self, doc: Document) -> Optional[CanProtocol]:
        before = len(self.errors)
        data = doc.data
        layout = self._id_layout(doc)
        addresses = data["addresses"]
        self._addresses(doc, addresses, layout)
        names: dict[str, object] = {}
        enums = [e for e in (self._enum(doc, i, raw, names) for i, raw in enumerate(data.get("enums", []))) if e]
        flags = [f for f in (self._flags(doc, i, raw, names) for i, raw in enumerate(data.get("flags", []))) if f]
        types = {e.name: e for e in enums}
        types.update({f.name: f for f in flags})
        classes = self._classes(doc, layout, types, flags)
        if len(self.errors) != before:
            return None
        v = data["protocol_version"]
        proto = CanProtocol(
            name=data["can_protocol"], version=data["version"], doc=data["doc"],
            protocol_major=v["major"], protocol_minor=v["minor"], bitrate=data["bitrate"],
            id_layout=layout, host=addresses["host"], first_board=addresses["first_board"],
            last_board=addresses["last_board"], broadcast=addresses["broadcast"],
            enums=enums, flags=flags, classes=classes, file=doc.file, mark=doc.mark(("can_protocol",)))
        proto.canonical, proto.fingerprint = _fingerprint(proto)
        return proto

    # ---- identifier layout and addresses -------------------------------------------------------

    def _id_layout(self, doc: Document) -> list[IdField]:
        layout, used, seen = [], 0, {}
        for i, raw in enumerate(doc.data["id_layout"]):
            mark = doc.mark(("id_layout", i))
            f = IdField(raw["name"], raw["shift"], raw["bits"], raw.get("doc", ""))
            if f.name in seen:
                self.error(mark, f"identifier field '{f.name}' is given twice (first at line {seen[f.name].line})")
                continue
            seen[f.name] = mark
            if f.shift + f.bits > ID_BITS:
                self.error(mark, f"identifier field '{f.name}' (bits {f.shift}..{f.shift + f.bits - 1}) "
                           f"does not fit in an {ID_BITS}-bit standard identifier")
                continue
            if used & f.mask:
                self.error(mark, f"identifier field '{f.name}' overlaps another field's bits")
                continue
            used |= f.mask
            layout.append(f)
        missing = {"message_class", "source", "destination"} - set(seen)
        if missing:
            self.error(doc.mark(("id_layout",)), "the identifier layout needs the fields "
                       "message_class, source and destination; missing: " + ", ".join(sorted(missing)))
        return layout

    def _addresses(self, doc: Document, a: dict, layout: list[IdField]) -> None:
        width = min((f.bits for f in layout if f.name in ("source", "destination")), default=4)
        top = (1 << width) - 1
        for key in ("host", "first_board", "last_board", "broadcast"):
            if a[key] > top:
                self.error(doc.mark(("addresses", key)), f"address {key} = {a[key]} does not fit in "
                           f"{width} identifier bits (0..{top})")
        if a["first_board"] > a["last_board"]:
            self.error(doc.mark(("addresses", "first_board")), "first_board is above last_board")
        for key in ("host", "broadcast"):
            if a["first_board"] <= a[key] <= a["last_board"]:
                self.error(doc.mark(("addresses", key)), f"the {key} address {a[key]} is inside the "
                           f"board range {a['first_board']}..{a['last_board']}")

    # ---- enums and flags -------------------------------------------------------------------------

    def _declare(self, doc: Document, path: tuple, name: str, names: dict) -> bool:
        mark = doc.mark(path + ("name",))
        if name in names or name == BROADCAST_MASK or name in SCALARS:
            first = f" (first at line {names[name].line})" if name in names else ""
            self.error(mark, f"type name '{name}' is already taken{first}")
            return False
        names[name] = mark
        return True

    def _enum(self, doc: Document, i: int, raw: dict, names: dict) -> Optional[CanEnum]:
        path = ("enums", i)
        if not self._declare(doc, path, raw["name"], names):
            return None
        lo, hi = scalar_range(raw["type"])
        members, seen_names, seen_values = [], {}, {}
        for k, m in enumerate(raw["members"]):
            mpath = path + ("members", k)
            if m["name"] in seen_names:
                self.error(doc.mark(mpath + ("name",)), f"duplicate member '{m['name']}' in enum "
                           f"'{raw['name']}' (first at line {seen_names[m['name']]})")
                continue
            seen_names[m["name"]] = doc.mark(mpath).line
            if not lo <= m["value"] <= hi:
                self.error(doc.mark(mpath + ("value",)), f"member '{m['name']}' = {m['value']} does not "
                           f"fit the enum's wire type {raw['type']} ({lo}..{hi})")
                continue
            if m["value"] in seen_values:
                self.error(doc.mark(mpath + ("value",)), f"value collision: '{m['name']}' and "
                           f"'{seen_values[m['value']]}' of enum '{raw['name']}' are both {m['value']}")
                continue
            seen_values[m["value"]] = m["name"]
            members.append(EnumMember(m["name"], m["value"], m.get("doc", "")))
        return CanEnum(raw["name"], raw["doc"], raw["type"], members, doc.mark(path + ("name",)))

    def _flags(self, doc: Document, i: int, raw: dict, names: dict) -> Optional[CanFlags]:
        path = ("flags", i)
        if not self._declare(doc, path, raw["name"], names):
            return None
        if raw["type"] == "bool" or SCALARS[raw["type"]][1]:
            self.error(doc.mark(path + ("type",)), f"flags '{raw['name']}' need an unsigned wire "
                       f"type (uint8, uint16, uint32), not {raw['type']}")
            return None
        width = 8 * SCALARS[raw["type"]][0]
        bits, seen = [], {}
        for k, b in enumerate(raw["bits"]):
            bmark = doc.mark(path + ("bits", k))
            if b["bit"] >= width:
                self.error(doc.mark(path + ("bits", k, "bit")), f"bit {b['bit']} of '{b['name']}' is past "
                           f"the {width} bits of {raw['type']}")
                continue
            for key, value in (("name", b["name"]), ("bit", b["bit"])):
                if (key, value) in seen:
                    self.error(bmark, f"flags '{raw['name']}': {key} {value!r} is used twice "
                               f"(first at line {seen[(key, value)]})")
                    break
            else:
                seen[("name", b["name"])] = seen[("bit", b["bit"])] = bmark.line
                bits.append(FlagBit(b["name"], b["bit"], b.get("doc", "")))
        return CanFlags(raw["name"], raw["doc"], raw["type"], bits, doc.mark(path + ("name",)))

    # ---- classes, commands, broadcasts -----------------------------------------------------------

    def _classes(self, doc: Document, layout: list[IdField], types: dict, flags: list) -> list[CanClass]:
        class_bits = next((f.bits for f in layout if f.name == "message_class"), 3)
        low_bits = next((f.bits for f in layout if f.name == "destination"), 4)
        classes, by_value, by_name, message_names = [], {}, {}, {}
        raw_classes = doc.data["classes"]
        # The broadcast mask is derived from the broadcasts: bit (type - 1) enables type.
        mask_bits = []
        for ci, raw in enumerate(raw_classes):
            for bi, b in enumerate(raw.get("broadcasts", [])):
                if isinstance(b.get("code"), int) and b["code"] >= 1:
                    mask_bits.append(FlagBit(b["name"], b["code"] - 1, b["doc"]))
        if mask_bits:
            mask = CanFlags(BROADCAST_MASK, "Which broadcasts a board sends: bit (type - 1) enables "
                            "broadcast type.", "uint32", sorted(mask_bits, key=lambda b: b.bit),
                            doc.mark(("classes",)))
            types = dict(types, **{BROADCAST_MASK: mask})
            flags.append(mask)
        for ci, raw in enumerate(raw_classes):
            path = ("classes", ci)
            mark = doc.mark(path + ("name",))
            if not 0 <= raw["value"] < (1 << class_bits):
                self.error(doc.mark(path + ("value",)), f"class value {raw['value']} does not fit the "
                           f"{class_bits} message_class bits (0..{(1 << class_bits) - 1})")
                continue
            for table, key, what in ((by_value, raw["value"], "value"), (by_name, raw["name"], "name")):
                if key in table:
                    self.error(mark, f"class {what} {key!r} is used twice (first at line {table[key]})")
            by_value.setdefault(raw["value"], mark.line)
            by_name.setdefault(raw["name"], mark.line)
            cls = CanClass(raw["name"], raw["value"], raw["addressing"], raw["doc"])
            if raw["addressing"] == "destination" and "broadcasts" in raw:
                self.error(doc.key_mark(path + ("broadcasts",)), f"class '{raw['name']}' addresses a "
                           "destination, so it carries commands, not broadcasts")
            if raw["addressing"] == "message_type" and "commands" in raw:
                self.error(doc.key_mark(path + ("commands",)), f"class '{raw['name']}' puts a message "
                           "type in the low identifier bits, so it carries broadcasts, not commands")
            codes: dict[int, int] = {}
            for k, cmd in enumerate(raw.get("commands", [])):
                cls.messages += self._command(doc, path + ("commands", k), cmd, cls, types, codes, message_names)
            for k, b in enumerate(raw.get("broadcasts", [])):
                msg = self._broadcast(doc, path + ("broadcasts", k), b, cls, types, codes, message_names, low_bits)
                if msg:
                    cls.messages.append(msg)
            classes.append(cls)
        return classes

    def _code(self, doc, path, code: int, top: int, codes: dict, what: str) -> bool:
        if not 0 <= code <= top:
            self.error(doc.mark(path + ("code",)), f"{what} code {code} is out of range (0..{top})")
            return False
        if code in codes:
            self.error(doc.mark(path + ("code",)), f"code collision: {what} code {code} is already "
                       f"used at line {codes[code]}")
            return False
        codes[code] = doc.mark(path + ("code",)).line
        return True

    def _name(self, doc, path, name: str, message_names: dict) -> bool:
        if name in message_names:
            self.error(doc.mark(path + ("name",)), f"duplicate message '{name}' (first at line "
                       f"{message_names[name]})")
            return False
        message_names[name] = doc.mark(path + ("name",)).line
        return True

    def _command(self, doc, path, raw, cls, types, codes, message_names) -> list[Message]:
        if not self._code(doc, path, raw["code"], 0x7F, codes, "command"):
            return []
        out = []
        for kind, suffix in (("request", ""), ("reply", "_reply")):
            if kind == "reply" and "reply" not in raw:
                continue
            name = raw["name"] + suffix
            if not self._name(doc, path, name, message_names):
                continue
            fields = self._fields(doc, path + (kind,), raw.get(kind, []), types, first_byte=1)
            if fields is None:
                continue
            length = self._length(doc, path, raw, fields, 1, f"{kind}_length")
            if length is None:
                continue
            out.append(Message(name, cls.name, cls.value, raw["code"], kind, raw["doc"], fields, length,
                               mark=doc.mark(path + ("name",))))
        return out

    def _broadcast(self, doc, path, raw, cls, types, codes, message_names, low_bits) -> Optional[Message]:
        if not self._code(doc, path, raw["code"], (1 << low_bits) - 1, codes, "broadcast type"):
            return None
        name = raw["name"] + "_broadcast"
        if not self._name(doc, path, name, message_names):
            return None
        fields = self._fields(doc, path + ("fields",), raw["fields"], types, first_byte=0)
        if fields is None:
            return None
        length = self._length(doc, path, raw, fields, 0, "length")
        if length is None:
            return None
        return Message(name, cls.name, cls.value, raw["code"], "broadcast", raw["doc"], fields, length,
                       period_ms=float(raw["period_ms"]), mark=doc.mark(path + ("name",)))

    def _length(self, doc, path, raw, fields, header, key) -> Optional[int]:
        used = header + sum(f.size for f in fields)
        if used > FRAME_BYTES:
            self.error(doc.mark(path + ("name",)), f"'{raw['name']}' needs {used} bytes, more than "
                       f"the {FRAME_BYTES} of a CAN frame")
            return None
        if key in raw:
            if raw[key] < used:
                self.error(doc.mark(path + (key,)), f"{key} {raw[key]} of '{raw['name']}' "
                           f"is shorter than its {used} bytes")
                return None
            return raw[key]
        return used

    def _fields(self, doc, path, raws, types, first_byte: int) -> Optional[list[CanField]]:
        fields, seen, byte, ok = [], {}, first_byte, True
        for k, raw in enumerate(raws):
            fpath = path + (k,)
            mark = doc.mark(fpath + ("name",))
            if raw["name"] in seen:
                self.error(mark, f"duplicate field '{raw['name']}' (first at line {seen[raw['name']]})")
                ok = False
                continue
            seen[raw["name"]] = mark.line
            tname = raw["type"]
            enum = flags = None
            if tname in SCALARS:
                scalar = tname
            elif tname in types:
                t = types[tname]
                scalar = t.scalar
                enum, flags = (t, None) if isinstance(t, CanEnum) else (None, t)
            else:
                known = ", ".join(list(SCALARS) + sorted(types))
                self.error(doc.mark(fpath + ("type",)), f"unknown field type '{tname}' (known: {known})")
                ok = False
                continue
            unit = raw.get("unit")
            if unit is not None and unit not in CAN_UNITS:
                self.error(doc.mark(fpath + ("unit",)), f"unknown unit '{unit}' (known units: "
                           f"{', '.join(CAN_UNITS)})")
                ok = False
                continue
            scale, offset = float(raw.get("scale", 1)), float(raw.get("offset", 0))
            if (scale != 1 or offset != 0) and (enum or flags or scalar == "bool"):
                self.error(doc.mark(fpath + ("scale" if "scale" in raw else "offset",)),
                           f"field '{raw['name']}' of type {tname} cannot be scaled")
                ok = False
                continue
            if not (math.isfinite(scale) and math.isfinite(offset)):
                self.error(doc.mark(fpath + ("scale",)), f"field '{raw['name']}': scale and offset must be finite")
                ok = False
                continue
            fields.append(CanField(raw["name"], scalar, enum, flags, unit, scale, offset,
                                   raw.get("doc", ""), byte, mark))
            byte += SCALARS[scalar][0]
        return fields if ok else None


def _fingerprint(p: CanProtocol) -> tuple[str, str]:
    canonical = {
        "can_protocol": p.name, "version": p.version, "protocol_version": [p.protocol_major, p.protocol_minor],
        "bitrate": p.bitrate, "id_layout": [[f.name, f.shift, f.bits] for f in p.id_layout],
        "addresses": [p.host, p.first_board, p.last_board, p.broadcast],
        "enums": [[e.name, e.scalar, [[m.name, m.value] for m in e.members]] for e in p.enums],
        "flags": [[f.name, f.scalar, [[b.name, b.bit] for b in f.bits]] for f in p.flags],
        "classes": [[c.name, c.value, c.addressing,
                     [[m.name, m.kind, m.code, m.length, m.period_ms,
                       [[f.name, f.type_name, f.unit, f.scale, f.offset] for f in m.fields]]
                      for m in c.messages]] for c in p.classes],
    }
    text = json.dumps(canonical, sort_keys=True, separators=(",", ":"), ensure_ascii=True)
    return text, hashlib.sha256(text.encode("ascii")).hexdigest()[:16]
