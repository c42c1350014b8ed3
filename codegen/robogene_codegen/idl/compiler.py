# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""From IDL files to a checked model: load, validate the structure, then check the meaning.

Every problem is collected (not only the first) and reported with the file, line and column of
the offending text.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

from . import fingerprint
from .errors import IdlError, IdlErrors, Mark
from .loader import Document, load
from .model import (BUILTIN_TYPES, RESERVED_WORDS, UNITS, Command, EnumMember, EnumType, Field, Idl, Interface, Method,
                    Protocol, Service, Stream, StructType, TypeRef)
from .schema import validate

DEFAULT_SCHEMA = Path(__file__).resolve().parents[3] / "interfaces" / "idl" / "idl.schema.json"
INT32_MIN, INT32_MAX = -(2 ** 31), 2 ** 31 - 1


def compile_directory(directory: Path, schema: Path = DEFAULT_SCHEMA,
                      root: Optional[Path] = None) -> Idl:
    """Compiles every *.yaml of `directory`; file names in errors and outputs are shown relative
    to `root` when given (so generated headers do not depend on where the tree lives)."""
    return compile_files(sorted(Path(directory).glob("*.yaml")), schema, root=root)


def compile_files(paths: list[Path], schema: Path = DEFAULT_SCHEMA,
                  root: Optional[Path] = None) -> Idl:
    errors: list[IdlError] = []
    docs: list[Document] = []
    for path in paths:
        name = str(Path(path).resolve().relative_to(root.resolve())) if root else str(path)
        try:
            text = Path(path).read_text(encoding="utf-8")
        except UnicodeDecodeError as exc:
            errors.append(IdlError(Mark(name, 1, 1), f"not UTF-8 text (byte {exc.start})"))
            continue
        except OSError as exc:
            errors.append(IdlError(Mark(name, 1, 1), f"cannot read the file ({exc.strerror})"))
            continue
        try:
            doc = load(name, text)
        except IdlErrors as exc:
            errors.extend(exc.errors)
            continue
        problems = validate(doc, str(schema))
        if problems:
            errors.extend(problems)
        else:
            docs.append(doc)
    idl = _Checker(errors).check(docs)
    _check_can(docs, idl, errors, root)
    if errors:
        raise IdlErrors(errors)
    # The device emitters name these as their sources; CAN files name themselves in their outputs.
    idl.files = [d.file for d in docs if "can_protocol" not in d.data and "board_config" not in d.data]
    return idl


def _check_can(docs: list[Document], idl: Idl, errors: list[IdlError], root: Optional[Path]) -> None:
    """CAN protocols, then the board configurations that name them (and read the head's parameters)."""
    from ..can.compiler import CanChecker
    checker = CanChecker(errors)
    for doc in docs:
        if "can_protocol" in doc.data:
            proto = checker.check(doc)
            if proto is not None:
                if any(p.name == proto.name for p in idl.can_protocols):
                    errors.append(IdlError(proto.mark, f"duplicate CAN protocol '{proto.name}'"))
                else:
                    idl.can_protocols.append(proto)
    configs = [doc for doc in docs if "board_config" in doc.data]
    if not configs:
        return
    from ..can.board_config import BoardConfigChecker
    boards = BoardConfigChecker(errors, root)
    for doc in configs:
        config = boards.check(doc, idl.can_protocols)
        if config is not None:
            idl.board_configs.append(config)


def _vocab_text(path: tuple) -> str:
    return " ".join(f"[{v}]" for v in path)


class _Checker:
    def __init__(self, errors: list[IdlError]):
        self.errors = errors
        self.enums: dict[str, EnumType] = {}
        self.structs: dict[str, StructType] = {}
        self.type_marks: dict[str, Mark] = {}

    def error(self, mark: Mark, message: str) -> None:
        self.errors.append(IdlError(mark, message))

    def check(self, docs: list[Document]) -> Idl:
        for doc in docs:
            self._reserved_names(doc, doc.data, ())
        for doc in docs:
            if "types" in doc.data:
                self._types(doc)
        for doc in docs:
            if "types" in doc.data:
                self._struct_fields(doc)
        interfaces: dict[str, Interface] = {}
        for doc in docs:
            if "interface" in doc.data:
                iface = self._interface(doc)
                if iface.name in interfaces:
                    first = interfaces[iface.name].mark
                    self.error(doc.mark(("interface",)),
                               f"duplicate interface '{iface.name}' (first defined at {first})")
                elif iface.name in self.type_marks:
                    self.error(doc.mark(("interface",)),
                               f"interface '{iface.name}' has the name of a type defined at "
                               f"{self.type_marks[iface.name]}")
                else:
                    interfaces[iface.name] = iface
        services: dict[str, Service] = {}
        for doc in docs:
            if "service" in doc.data:
                service = self._service(doc, interfaces)
                if service.name in services:
                    self.error(doc.mark(("service",)), f"duplicate service '{service.name}' "
                               f"(first defined at {services[service.name].mark})")
                else:
                    services[service.name] = service
        if not self.errors:
            for iface in interfaces.values():
                fingerprint.assign_interface(iface)
            for service in services.values():
                fingerprint.assign_service(service)
        return Idl(interfaces=sorted(interfaces.values(), key=lambda i: i.name),
                   services=sorted(services.values(), key=lambda s: s.name),
                   enums=sorted(self.enums.values(), key=lambda e: e.name),
                   structs=sorted(self.structs.values(), key=lambda s: s.name), files=[])

    def _reserved_names(self, doc: Document, data: Any, path: tuple) -> None:
        """Names become C++ and Python identifiers; a keyword there would break the build."""
        if isinstance(data, dict):
            for key, value in data.items():
                if key in ("name", "cpp_name", "interface", "service") and value in RESERVED_WORDS:
                    self.error(doc.mark(path + (key,)), f"'{value}' is a reserved word in C++ or "
                               "Python and cannot name anything in the IDL")
                else:
                    self._reserved_names(doc, value, path + (key,))
        elif isinstance(data, list):
            for i, value in enumerate(data):
                self._reserved_names(doc, value, path + (i,))

    # ---- shared types ------------------------------------------------------------------------

    def _declare_type(self, name: str, mark: Mark) -> bool:
        if name in BUILTIN_TYPES:
            self.error(mark, f"type '{name}' has the name of a built-in type")
            return False
        if name in self.type_marks:
            self.error(mark, f"duplicate type '{name}' (first defined at {self.type_marks[name]})")
            return False
        self.type_marks[name] = mark
        return True

    def _types(self, doc: Document) -> None:
        types = doc.data["types"]
        for i, raw in enumerate(types.get("enums", [])):
            path = ("types", "enums", i)
            mark = doc.mark(path + ("name",))
            members: list[EnumMember] = []
            seen_names: dict[str, Mark] = {}
            seen_values: dict[Any, str] = {}
            for k, m in enumerate(raw["members"]):
                mpath = path + ("members", k)
                mmark = doc.mark(mpath + ("name",))
                vmark = doc.mark(mpath + ("value",))
                value = m["value"]
                if m["name"] in seen_names:
                    self.error(mmark, f"duplicate member '{m['name']}' in enum '{raw['name']}' "
                               f"(first at line {seen_names[m['name']].line})")
                    continue
                seen_names[m["name"]] = mmark
                if raw["wire"] == "vocab":
                    if not isinstance(value, str) or not self._vocab_ok(value, vmark):
                        if not isinstance(value, str):
                            self.error(vmark, f"member '{m['name']}' of vocab enum '{raw['name']}'"
                                       f" needs a vocab (1-4 characters), not {value!r}")
                        continue
                else:
                    if isinstance(value, bool) or not isinstance(value, int) or \
                            not INT32_MIN <= value <= INT32_MAX:
                        self.error(vmark, f"member '{m['name']}' of int32 enum '{raw['name']}' "
                                   f"needs an int32 value, not {value!r}")
                        continue
                if value in seen_values:
                    self.error(vmark, f"value collision: '{m['name']}' and "
                               f"'{seen_values[value]}' of enum '{raw['name']}' are both {value!r}")
                    continue
                seen_values[value] = m["name"]
                members.append(EnumMember(m["name"], value, m.get("doc", ""), mmark))
            if self._declare_type(raw["name"], mark):
                self.enums[raw["name"]] = EnumType(raw["name"], raw["doc"], raw["wire"], members, mark)
        for i, raw in enumerate(types.get("structs", [])):
            mark = doc.mark(("types", "structs", i, "name"))
            if self._declare_type(raw["name"], mark):
                self.structs[raw["name"]] = StructType(raw["name"], raw["doc"], [], mark)

    def _struct_fields(self, doc: Document) -> None:
        for i, raw in enumerate(doc.data["types"].get("structs", [])):
            struct = self.structs.get(raw["name"])
            if struct is None or struct.mark != doc.mark(("types", "structs", i, "name")):
                continue
            path = ("types", "structs", i, "fields")
            struct.fields = self._fields(doc, raw["fields"], path, role="field")

    # ---- fields, types, defaults -------------------------------------------------------------

    def _vocab_ok(self, text: str, mark: Mark) -> bool:
        if not 1 <= len(text) <= 4 or not all(33 <= ord(c) <= 126 for c in text):
            hint = f"; YARP would truncate it to [{text[:4]}]" if len(text) > 4 else ""
            self.error(mark, f"vocab '{text}' must be 1 to 4 printable ASCII characters{hint}")
            return False
        return True

    def _resolve(self, name: str, mark: Mark) -> Optional[TypeRef]:
        if name in BUILTIN_TYPES:
            return TypeRef(name)
        if name in self.enums:
            return TypeRef(name, enum=self.enums[name])
        if name in self.structs:
            return TypeRef(name, struct=self.structs[name])
        known = ", ".join(list(BUILTIN_TYPES) + sorted(self.enums) + sorted(self.structs))
        self.error(mark, f"unknown type '{name}' (known types: {known})")
        return None

    def _fields(self, doc: Document, raws: list, path: tuple, role: str) -> list[Field]:
        fields: list[Field] = []
        seen: dict[str, Mark] = {}
        for k, raw in enumerate(raws):
            fpath = path + (k,)
            mark = doc.mark(fpath + ("name",))
            if raw["name"] in seen:
                self.error(mark, f"duplicate {role} '{raw['name']}' (first at line {seen[raw['name']].line})")
                continue
            seen[raw["name"]] = mark
            tref = self._resolve(raw["type"], doc.mark(fpath + ("type",)))
            if tref is None:
                continue
            tmark = doc.mark(fpath + ("type",))
            if tref.name == "joint" and role != "argument":
                self.error(tmark, f"'joint' is an axis index and can only be an argument, not a {role}")
                continue
            if tref.name == "image_rgb" and role != "result":
                self.error(tmark, f"'image_rgb' can only be the result of a local method, not a {role}")
                continue
            unit = raw.get("unit")
            if unit is not None and unit not in UNITS:
                self.error(doc.mark(fpath + ("unit",)),
                           f"unknown unit '{unit}' (known units: {', '.join(UNITS)})")
                continue
            f = Field(raw["name"], tref, unit, raw.get("doc", ""), mark)
            if "default" in raw:
                dmark = doc.mark(fpath + ("default",))
                if role != "argument":
                    self.error(dmark, f"only arguments take defaults, not a {role}")
                    continue
                problem = self._default_problem(tref, raw["default"])
                if problem:
                    self.error(dmark, f"bad default for '{raw['name']}': {problem}")
                    continue
                f.has_default, f.default = True, raw["default"]
            elif fields and fields[-1].has_default and role == "argument":
                self.error(mark, f"argument '{raw['name']}' needs a default because "
                           f"'{fields[-1].name}' before it has one")
                continue
            fields.append(f)
        return fields

    @staticmethod
    def _default_problem(tref: TypeRef, value: Any) -> Optional[str]:
        name = tref.name
        if tref.enum:
            if not isinstance(value, str) or tref.enum.member(value) is None:
                members = ", ".join(m.name for m in tref.enum.members)
                return f"{value!r} is not a member of {name} ({members})"
            return None
        if tref.struct or name in ("image_rgb", "joint"):
            return f"arguments of type {name} cannot have a default"
        if name == "bool":
            return None if isinstance(value, bool) else f"{value!r} is not true or false"
        if name == "int32":
            ok = isinstance(value, int) and not isinstance(value, bool) and INT32_MIN <= value <= INT32_MAX
            return None if ok else f"{value!r} is not an int32"
        if name == "float64":
            ok = isinstance(value, (int, float)) and not isinstance(value, bool)
            return None if ok else f"{value!r} is not a number"
        if name == "string":
            return None if isinstance(value, str) else f"{value!r} is not a string"
        if name == "vocab":
            ok = isinstance(value, str) and 1 <= len(value) <= 4
            return None if ok else f"{value!r} is not a vocab of 1-4 characters"
        return f"type {name} has no defaults"

    # ---- interfaces ----------------------------------------------------------------------------

    def _interface(self, doc: Document) -> Interface:
        data = doc.data
        iface = Interface(data["interface"], data["version"], data["doc"], [], doc.file,
                          doc.mark(("interface",)))
        names: dict[str, Mark] = {}
        overloads: dict[tuple, Mark] = {}
        paths: dict[tuple, tuple[str, Mark]] = {}
        for i, raw in enumerate(data["methods"]):
            for method in self._method_forms(doc, iface.name, raw, ("methods", i)):
                if method.name in names:
                    self.error(method.mark, f"duplicate method '{method.name}' in {iface.name} "
                               f"(first at line {names[method.name].line})")
                    continue
                signature = (method.cpp_name,) + tuple(_cpp_signature(f) for f in method.args)
                if signature in overloads:
                    self.error(method.mark, f"duplicate method: C++ overload {method.cpp_name}"
                               f"({', '.join(signature[1:])}) is already declared at line "
                               f"{overloads[signature].line}")
                    continue
                if method.wire is not None:
                    if method.wire in paths:
                        other, omark = paths[method.wire]
                        self.error(method.mark, f"vocab collision: {_vocab_text(method.wire)} of "
                                   f"'{method.name}' is already used by '{other}' (line {omark.line})")
                        continue
                    paths[method.wire] = (method.name, method.mark)
                names[method.name] = method.mark
                overloads[signature] = method.mark
                iface.methods.append(method)
        iface.enums, iface.structs = _types_used(iface)
        return iface

    def _method_forms(self, doc: Document, iface: str, raw: dict, path: tuple) -> list[Method]:
        mark = doc.mark(path + ("name",))
        args = self._fields(doc, raw.get("args", []), path + ("args",), role="argument")
        results = self._fields(doc, raw.get("results", []), path + ("results",), role="result")
        if len(args) != len(raw.get("args", [])) or len(results) != len(raw.get("results", [])):
            return []  # already reported
        wire = tuple(raw["wire"]) if "wire" in raw else None
        if wire is not None and not all(self._vocab_ok(v, doc.mark(path + ("wire", k)))
                                        for k, v in enumerate(wire)):
            return []
        if wire is None:
            for key in ("echo", "stamp", "all_axes", "reply"):
                if key in raw:
                    self.error(doc.key_mark(path + (key,)), f"'{key}' needs a 'wire' path; "
                               f"'{raw['name']}' is local-only")
                    return []
        elif any(f.type.name == "image_rgb" for f in results):
            self.error(doc.mark(path + ("wire",)), f"'{raw['name']}' returns an image_rgb, which "
                       "travels on a stream, so the method cannot have a 'wire' path")
            return []
        joints = [k for k, a in enumerate(args) if a.type.name == "joint"]
        if len(joints) > 1:
            self.error(args[joints[1]].mark, f"'{raw['name']}' has more than one joint argument")
            return []
        echo = self._echo(doc, path, raw.get("echo"), wire, len(args), raw["name"])
        if echo is False:
            return []
        stamp = raw.get("stamp", True)
        if "stamp" in raw and not results:
            self.error(doc.key_mark(path + ("stamp",)), f"'stamp' concerns the reply to a query; "
                       f"'{raw['name']}' has no results, so its reply is [ok] or [fail]")
            return []
        reply = self._reply_head(doc, path, raw, wire, len(args), results)
        if reply is False:
            return []
        single = Method(iface, raw["name"], raw.get("cpp_name", raw["name"]), raw["doc"], wire,
                        echo, args, results, mark, stamp=stamp and reply is None, reply_head=reply)
        forms = [single]
        all_raw = raw.get("all_axes")
        if all_raw is not None:
            apath = path + ("all_axes",)
            if not joints:
                self.error(doc.key_mark(apath), f"'{raw['name']}' has no joint argument, so it "
                           "cannot have an all-axes form")
                return []
            awire = tuple(all_raw["wire"])
            if not all(self._vocab_ok(v, doc.mark(apath + ("wire", k))) for k, v in enumerate(awire)):
                return []
            j = joints[0]
            aargs = [_replace(a, per_axis=(k > j)) for k, a in enumerate(args) if k != j]
            if any(a.has_default for a in aargs):
                self.error(doc.key_mark(apath), f"'{raw['name']}' has defaults, which its "
                           "all-axes form cannot carry")
                return []
            reduce = all_raw.get("reduce")
            if reduce is not None and not (results and all(r.type.name == "bool" for r in results)):
                self.error(doc.mark(apath + ("reduce",)), f"'reduce: {reduce}' makes one value of every axis's, "
                           f"which needs bool results; '{raw['name']}' returns "
                           f"{', '.join(r.type.name for r in results) or 'nothing'}")
                return []
            # reduce: all -- the wire carries one value, true when every axis's is (YARP's [get] [dons])
            aresults = [_replace(r, per_axis=reduce is None) for r in results]
            aecho = self._echo(doc, apath, all_raw.get("echo", raw.get("echo")), awire,
                               len(aargs), all_raw["name"])
            if aecho is False:
                return []
            single.form, single.twin = "axis", all_raw["name"]
            forms.append(Method(iface, all_raw["name"], all_raw.get("cpp_name", all_raw["name"]),
                                all_raw.get("doc", f"{raw['doc']} All axes at once."), awire, aecho, aargs, aresults,
                                doc.mark(apath + ("name",)), form="all", twin=raw["name"], stamp=stamp))
        return forms

    def _reply_head(self, doc: Document, path: tuple, raw: dict, wire, nargs: int, results):
        """A query's own reply head (YARP's frame-grabber shape, `[fgc] [feat] [is] <value>`):
        ints repeat a request item, strings are vocabs, `#vocab` is a vocab's code as an int32.
        None when the method uses the [is] <echo> ... [tsta] [ok] shape."""
        if "reply" not in raw:
            return None
        name = raw["name"]
        if not results:
            self.error(doc.key_mark(path + ("reply",)), f"'reply' concerns the reply to a query; "
                       f"'{name}' has no results")
            return False
        for key in ("echo", "stamp", "all_axes"):
            if key in raw:
                self.error(doc.key_mark(path + (key,)), f"'{name}' has a 'reply' head, which "
                           f"replaces '{key}'")
                return False
        head = []
        for k, item in enumerate(raw["reply"]):
            mark = doc.mark(path + ("reply", k))
            if isinstance(item, int):
                if item >= len(wire) + nargs:
                    self.error(mark, f"reply item {item} of '{name}' is past the end of its "
                               f"request ({len(wire)} vocabs and {nargs} arguments)")
                    return False
            elif not self._vocab_ok(item[1:] if item.startswith("#") and len(item) > 1 else item, mark):
                return False
            head.append(item)
        return tuple(head)

    def _echo(self, doc: Document, path: tuple, echo, wire, nargs: int, name: str):
        if wire is None:
            return None
        if echo is None:
            return len(wire) - 1
        if isinstance(echo, str):  # a vocab the reply carries instead of a request item
            return echo if self._vocab_ok(echo, doc.mark(path + ("echo",))) else False
        if echo >= len(wire) + nargs:
            self.error(doc.mark(path + ("echo",)), f"echo {echo} of '{name}' is past the end of "
                       f"its request ({len(wire)} vocabs and {nargs} arguments)")
            return False
        return echo

    # ---- services ------------------------------------------------------------------------------

    def _service(self, doc: Document, interfaces: dict[str, Interface]) -> Service:
        data = doc.data
        members: list[Interface] = []
        for k, name in enumerate(data["interfaces"]):
            iface = interfaces.get(name)
            if iface is None:
                self.error(doc.mark(("interfaces", k)), f"unknown interface '{name}' (known: "
                           f"{', '.join(sorted(interfaces))})")
            elif iface in members:
                self.error(doc.mark(("interfaces", k)), f"interface '{name}' is listed twice")
            else:
                members.append(iface)
        protocol = None
        if "protocol" in data:
            p = data["protocol"]
            if all(self._vocab_ok(v, doc.mark(("protocol", "wire", k))) for k, v in enumerate(p["wire"])) \
                    and self._vocab_ok(p["reply"], doc.mark(("protocol", "reply"))):
                protocol = Protocol(tuple(p["wire"]), p["reply"], tuple(p["version"]))
        introspection = None
        if "introspection" in data:
            w = data["introspection"]
            if all(self._vocab_ok(v, doc.mark(("introspection", k))) for k, v in enumerate(w)):
                introspection = tuple(w)
        self._service_collisions(doc, members, protocol, introspection)
        streams: list[Stream] = []
        seen_ports: dict[str, str] = {data["rpc_port"]: "the RPC port"}
        for k, raw in enumerate(data.get("streams", [])):
            spath = ("streams", k)
            if raw["port"] in seen_ports:
                self.error(doc.mark(spath + ("port",)), f"port '{raw['port']}' is already "
                           f"{seen_ports[raw['port']]}")
                continue
            seen_ports[raw["port"]] = f"used by stream '{raw['name']}'"
            iname, mname = raw["source"].split(".")
            iface = interfaces.get(iname)
            method = iface.method(mname) if iface else None
            smark = doc.mark(spath + ("source",))
            if iface is None or iface not in members:
                self.error(smark, f"stream source '{raw['source']}': interface '{iname}' is not "
                           "one of this service's interfaces")
            elif method is None:
                self.error(smark, f"stream source '{raw['source']}': {iname} has no method '{mname}'")
            elif method.args or len(method.results) != 1:
                self.error(smark, f"stream source '{raw['source']}' must take no arguments and "
                           "return exactly one result")
            else:
                streams.append(Stream(raw["name"], raw["port"], raw["doc"], iname, method,
                                      float(raw["period"])))
        command = None
        if "command" in data:
            c = data["command"]
            if c["port"] in seen_ports:
                self.error(doc.mark(("command", "port")), f"port '{c['port']}' is already "
                           f"{seen_ports[c['port']]}")
            elif all(self._vocab_ok(v, doc.mark(("command", "prefix", k)))
                     for k, v in enumerate(c["prefix"])):
                prefix = tuple(c["prefix"])
                routes, seen = [], set()
                for iface in members:
                    for m in iface.methods:
                        if m.wire and m.wire[:len(prefix)] == prefix and len(m.wire) > len(prefix) \
                                and not m.results and m.wire not in seen:
                            seen.add(m.wire)
                            routes.append((m.wire[len(prefix):], m))
                if not routes:
                    self.error(doc.mark(("command", "prefix")), "no command of this service starts "
                               f"with {_vocab_text(prefix)}")
                aliases = self._command_aliases(doc, c.get("aliases", []), members, routes)
                command = Command(c["port"], c["doc"], prefix, routes + aliases, aliases)
        replies = data.get("replies", "stamped")
        return Service(data["service"], data["version"], data["doc"], data["rpc_port"], members,
                       protocol, introspection, streams, command, doc.file, doc.mark(("service",)),
                       replies=replies, command_reply=self._command_reply(doc, replies, members))

    def _command_reply(self, doc: Document, replies: str, members: list[Interface]) -> Optional[tuple]:
        """The reply to a scoped command: request items (each present in every command of the
        service) and "result" once, last."""
        if "command_reply" not in doc.data:
            return None
        items = tuple(doc.data["command_reply"])
        mark = doc.mark(("command_reply",))
        if replies != "scoped":
            self.error(mark, "command_reply belongs only to a service with 'replies: scoped'")
            return None
        if items.count("result") != 1 or items[-1] != "result":
            self.error(mark, "command_reply must end with 'result' and name it once")
            return None
        shortest = min((len(m.wire) + len(m.args) for i in members for m in i.methods
                        if m.wire and not m.results), default=0)
        for k, item in enumerate(items[:-1]):
            if item >= shortest:
                self.error(doc.mark(("command_reply", k)), f"command_reply item {item} is past the end "
                           f"of the shortest command of this service ({shortest} items)")
                return None
        return items

    def _command_aliases(self, doc: Document, raws: list, members: list[Interface], routes: list) -> list:
        """Other heads for commands of the service (YARP's [dtq] j for setRefTorque(j, t)): each
        names a command (a method without results) of a member interface, and no head shadows
        another."""
        heads = {head: f"{m.interface}.{m.name}" for head, m in routes}
        aliases = []
        for k, raw in enumerate(raws):
            mark = doc.mark(("command", "aliases", k, "method"))
            head = tuple(raw["head"])
            if not all(self._vocab_ok(v, doc.mark(("command", "aliases", k, "head", n))) for n, v in enumerate(head)):
                continue
            iname, mname = raw["method"].split(".")
            iface = next((i for i in members if i.name == iname), None)
            method = next((m for m in iface.methods if m.name == mname), None) if iface else None
            if method is None:
                self.error(mark, f"command alias {_vocab_text(head)}: '{raw['method']}' is not a method of "
                           "this service's interfaces")
            elif method.results or not method.wire:
                self.error(mark, f"command alias {_vocab_text(head)}: '{raw['method']}' is not a command "
                           "(a method with a wire path and no results)")
            elif any(h[:len(head)] == head or head[:len(h)] == h for h in heads):
                other = next(h for h in heads if h[:len(head)] == head or head[:len(h)] == h)
                self.error(doc.mark(("command", "aliases", k, "head")), f"command alias {_vocab_text(head)} "
                           f"overlaps the head {_vocab_text(other)} of {heads[other]}")
            else:
                heads[head] = raw["method"]
                aliases.append((head, method))
        return aliases

    def _service_collisions(self, doc: Document, members: list[Interface],
                            protocol: Optional[Protocol], introspection: Optional[tuple]) -> None:
        """One RPC port dispatches every member interface: a vocab path may be shared only by
        methods that mean the same thing (same C++ name, arguments and results)."""
        owners: dict[tuple, Method] = {}
        reserved = {}
        if protocol:
            reserved[protocol.wire] = "the protocol-version request"
        if introspection:
            reserved[introspection] = "the introspection request"
        for iface in members:
            for method in iface.methods:
                if method.wire is None:
                    continue
                if method.wire in reserved:
                    self.error(doc.mark(("interfaces",)), f"vocab collision: {_vocab_text(method.wire)}"
                               f" of {iface.name}.{method.name} ({method.mark}) is {reserved[method.wire]}")
                    continue
                other = owners.get(method.wire)
                if other is None:
                    owners[method.wire] = method
                elif fingerprint.method_shape(other) != fingerprint.method_shape(method):
                    self.error(doc.mark(("interfaces",)), f"vocab collision: {_vocab_text(method.wire)}"
                               f" means {other.interface}.{other.name} ({other.mark}) and "
                               f"{iface.name}.{method.name} ({method.mark}), which differ")


def _replace(f: Field, **changes) -> Field:
    from dataclasses import replace
    return replace(f, **changes)


def _cpp_signature(f: Field) -> str:
    return f"{f.type.name}[]" if f.per_axis else f.type.name


def _types_used(iface: Interface) -> tuple[list[EnumType], list[StructType]]:
    enums: dict[str, EnumType] = {}
    structs: dict[str, StructType] = {}

    def visit(f: Field) -> None:
        if f.type.enum:
            enums[f.type.name] = f.type.enum
        if f.type.struct and f.type.name not in structs:
            structs[f.type.name] = f.type.struct
            for sub in f.type.struct.fields:
                visit(sub)

    for m in iface.methods:
        for f in m.args + m.results:
            visit(f)
    return sorted(enums.values(), key=lambda e: e.name), sorted(structs.values(), key=lambda s: s.name)
