#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Writes tests/vectors/bottles.json, the shared Bottle test vectors.
#
# Captured cases take their bytes from real YARP 3 traffic (tests/vectors/yarp3-captures/, or the
# folder given as first argument) and their canonical text from what YARP printed. Cases the captures do
# not cover state their value tree by hand and get their bytes from the small encoder below,
# which follows reference section 1 and is independent of the C++ one. The C++ and Python tests
# then check the runtime against these files. `make generate` runs it (the manifest's
# bottle-vectors generator, codegen/generated-manifest.yaml). Usage:
#   python3 tests/vectors/make_bottle_vectors.py [CAPTURES] [--out DIR]   (DIR/bottles.json; default here)
import json
import math
import re
import struct
import sys
from pathlib import Path

TAGS = {"int8": 0x20, "int16": 0x40, "int32": 0x01, "int64": 0x11, "vocab": 0x09,
        "float32": 0x80, "float64": 0x0A, "string": 0x04, "blob": 0x0C}
FORMATS = {"int8": "<b", "int16": "<h", "int32": "<i", "int64": "<q", "float32": "<f", "float64": "<d"}
BY_TAG = {v: k for k, v in TAGS.items()}


# ----------------------------------------------------------------------------- value trees
# A value is a one-key dict, as in the JSON: {"int32": 1}, {"float64": 2.5 | "nan" | "inf"},
# {"vocab": "set"}, {"string": "hi"}, {"blob": "00ff"}, {"list": [...]}.

def kind(v):
    (k,) = v.keys()
    return k


def float_of(x):
    return float(x) if isinstance(x, str) else x


def json_float(x):
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x


def vocab_code(chars):
    code = 0
    for i, c in enumerate(chars.encode("latin-1")[:4]):
        code |= c << (8 * i)
    return code


def vocab_chars(code):
    return bytes(b for b in struct.pack("<I", code & 0xFFFFFFFF) if b != 0).decode("latin-1")


# ----------------------------------------------------------------------------- encoder
def subcode(items):
    if not items:
        return 0
    kinds = {kind(v) for v in items}
    if len(kinds) != 1:
        return 0
    (k,) = kinds
    return TAGS.get(k, 0)  # lists never specialise their parent


def tag_of(v):
    k = kind(v)
    return 0x100 | subcode(v["list"]) if k == "list" else TAGS[k]


def payload(v):
    k, x = kind(v), next(iter(v.values()))
    if k in FORMATS:
        return struct.pack(FORMATS[k], float_of(x) if k.startswith("float") else x)
    if k == "vocab":
        return struct.pack("<I", vocab_code(x))
    if k == "string":
        raw = x.encode("utf-8")
        return struct.pack("<i", len(raw)) + raw
    if k == "blob":
        raw = bytes.fromhex(x)
        return struct.pack("<i", len(raw)) + raw
    return body(x, subcode(x))


def body(items, sub):
    out = struct.pack("<i", len(items))
    for v in items:
        if sub == 0:
            out += struct.pack("<i", tag_of(v))
        out += payload(v)
    return out


def encode(items):
    sub = subcode(items)
    return struct.pack("<i", 0x100 | sub) + body(items, sub)


# ----------------------------------------------------------------------------- decoder
def decode(data):
    pos = 0

    def take(n):
        nonlocal pos
        if pos + n > len(data):
            raise ValueError("truncated at %d" % pos)
        chunk = data[pos:pos + n]
        pos += n
        return chunk

    def i32():
        return struct.unpack("<i", take(4))[0]

    def item(tag):
        if tag in BY_TAG:
            k = BY_TAG[tag]
            if k in FORMATS:
                (x,) = struct.unpack(FORMATS[k], take(struct.calcsize(FORMATS[k])))
                return {k: json_float(x) if k.startswith("float") else x}
            if k == "vocab":
                return {k: vocab_chars(struct.unpack("<I", take(4))[0])}
            raw = take(i32())
            if k == "string":
                return {k: raw[:-1].decode() if raw.endswith(b"\0") else raw.decode()}
            return {k: raw.hex()}
        if tag & 0x100:
            return {"list": items(tag & 0xFF)}
        raise ValueError("tag %#x" % tag)

    def items(sub):
        return [item(sub if sub else i32()) for _ in range(i32())]

    top = i32()
    assert top & ~0xFF == 0x100, hex(top)
    out = items(top & 0xFF)
    assert pos == len(data), (pos, len(data))
    return out


# ----------------------------------------------------------------------------- text rendering
def render_float(x):
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    s = "%.21g" % x
    return s if ("." in s or "e" in s) else s + ".0"


def render_string(s):
    bare = s and s not in ("true", "false", "null", "inf", "nan") and all(
        c.isascii() and (c.isalpha() or c == "_" or (i > 0 and (c.isdigit() or c in ".-")))
        for i, c in enumerate(s))
    if bare:
        return s
    esc = {"\n": "\\n", "\r": "\\r", "\0": "\\0", "\\": "\\\\", '"': '\\"'}
    return '"' + "".join(esc.get(c, c) for c in s) + '"'


def render(v):
    k, x = kind(v), next(iter(v.values()))
    if k.startswith("int"):
        return str(x)
    if k.startswith("float"):
        return render_float(float_of(x))
    if k == "vocab":
        return "false" if x == "" else "true" if x == "1" else "[" + x + "]"
    if k == "string":
        return render_string(x)
    if k == "blob":
        return "{" + " ".join(str(b) for b in bytes.fromhex(x)) + "}"
    return "(" + render_items(x) + ")"


def render_items(items):
    return " ".join(render(v) for v in items)


# ----------------------------------------------------------------------------- captures
ACK = b"YA\x00\x00\x00\x00RP"


def captured_bottles(path):
    """Bottle payloads in a *.flows.txt dump, in order: data messages (after the index and the
    PortCommand) and raw replies (before the ack)."""
    chunks, chunk = [], None
    for line in path.read_text().splitlines():
        m = re.match(r"\s+(C->S|S->C) \d+ bytes", line)
        if m:
            chunk = [m.group(1), bytearray()]
            chunks.append(chunk)
            continue
        m = re.match(r"\s+[0-9a-f]{4}  ((?:[0-9a-f]{2} ?)+)", line)
        if m and chunk is not None:
            chunk[1] += bytes.fromhex(m.group(1).replace(" ", ""))
        elif line.startswith("connection"):
            chunk = None
    out = []
    for direction, data in chunks:
        data = bytes(data)
        if direction == "C->S" and data.startswith(b"YA\n\x00\x00\x00RP"):
            n = data[8] + data[9]
            blocks = data[18 + 4 * n:]
            length, ch = struct.unpack_from("<i", blocks)[0], blocks[5]
            bottle = blocks[8 + (length if ch == 0 else 0):]
            if bottle:
                out.append(bottle)
        elif direction == "S->C" and data.endswith(ACK) and data[1:4] == b"\x01\x00\x00":
            out.append(data[:-len(ACK)])
    return out


def sniffed_bottles(path):
    """Bottles in a sniffer log (sniff_*.txt): the hex dump of each message, framing removed."""
    out, dump = [], bytearray()
    for line in path.read_text().splitlines() + ["-- end"]:
        m = re.match(r"\s+[0-9a-f]{4}  ((?:[0-9a-f]{2} ?)+)", line)
        if m:
            dump += bytes.fromhex(m.group(1).replace(" ", ""))
            continue
        if line.startswith("-- ") and dump.startswith(b"YA\n\x00\x00\x00RP"):
            n = dump[8] + dump[9]
            lengths = struct.unpack_from("<%di" % n, dump, 18)
            blocks = bytes(dump[18 + 4 * n:])
            if len(blocks) == sum(lengths):
                length, ch = struct.unpack_from("<i", blocks)[0], blocks[5]
                bottle = blocks[8 + (length if ch == 0 else 0):]
                if bottle:
                    out.append(bottle)
        if line.startswith("-- ") or line.startswith("== "):
            dump = bytearray()
    return out


# ----------------------------------------------------------------------------- the cases
# (name, capture file, index of the bottle in that file, input text or None for the canonical
#  text, canonical text as YARP printed it or None to render it, where the proof is)
CAPTURED = [
    ("yarp_write_worked_example", "sniff_yarp_write.txt", 0, '1 2.5 "hi" [set]', "1 2.5 hi [set]",
     "wire-protocol 1.6; sniff_yarp_write.txt (bytes), yarp_read_out.txt (text)"),
    ("yarp_write_all_types", "write_connect_read.flows.txt", 1,
     '(nested (list 1 2) "with space") {1 2 255} 0.1 -3 100000 1e300 inf -inf nan 12345678901 true false 0x10',
     '(nested (list 1 2) "with space") {1 2 255} 0.100000000000000005551 -3 100000 '
     "1.0000000000000000525e+300 inf -inf nan 12345678901 true false 16",
     "write_connect_read.flows.txt message 2 from yarp write (bytes), yarp_read_out.txt (text); "
     "the input text is ours, chosen to produce exactly those bytes"),
    ("python_writer_homogeneous_lists", "write_connect_read.flows.txt", 3, None,
     '(1.0 2.0 3.0) (1 2 3) (a b) {0 1} 1099511627776 "quote\\"back\\\\slash" "" "new\\nline"',
     "wire-protocol 1.6; write_connect_read.flows.txt message 2 from /pywriter (bytes), yarp_read_out.txt (text)"),
    ("rpc_get_axes_strings", "rpc_motors.flows.txt", 0, None, "get axes",
     "rpc_motors.flows.txt: typed at yarp rpc, a homogeneous string list 0x104"),
    ("rpc_reply_is_axes_string", "rpc_motors.flows.txt", 1, None,
     "[is] axes 4 [tsta] 0 1795328326.71071100235 [ok]", "rpc_motors.flows.txt (bytes), yarp_rpc_motors.txt (text)"),
    ("rpc_get_axes_vocabs", "rpc_motors.flows.txt", 2, None, "[get] [axes]",
     "wire-protocol 3.3; rpc_motors.flows.txt: a homogeneous vocab list 0x109"),
    ("rpc_reply_is_axes_vocab", "rpc_motors.flows.txt", 3, None,
     "[is] [axes] 4 [tsta] 1 1795328326.71092629433 [ok]", "rpc_motors.flows.txt (bytes), yarp_rpc_motors.txt (text)"),
    ("rpc_get_prot", "rpc_motors.flows.txt", 4, None, "get prot", "rpc_motors.flows.txt"),
    ("rpc_reply_prot", "rpc_motors.flows.txt", 5, None, "[prot] 1 9 0 [ok]",
     "wire-protocol 5.4; rpc_motors.flows.txt (bytes), yarp_rpc_motors.txt (text)"),
    ("rpc_set_pos", "rpc_motors.flows.txt", 6, None, "set pos 0 10", "rpc_motors.flows.txt: mixed list 0x100"),
    ("rpc_reply_ok", "rpc_motors.flows.txt", 7, None, "[ok]",
     "wire-protocol 5.4 (09 01 00 00 01 00 00 00 6f 6b 00 00); rpc_motors.flows.txt"),
    ("rpc_set_vel", "rpc_motors.flows.txt", 8, None, "set vel 0 20", "rpc_motors.flows.txt"),
    ("rpc_get_pos", "rpc_motors.flows.txt", 10, None, "get pos 0", "rpc_motors.flows.txt"),
    ("rpc_reply_is_pos", "rpc_motors.flows.txt", 11, None, "[is] pos 10.0 [tsta] 2 1795328326.71142458916 [ok]",
     "rpc_motors.flows.txt (bytes), yarp_rpc_motors.txt (text)"),
    ("rpc_reply_is_enc", "rpc_motors.flows.txt", 13, None, "[is] enc 0.0 [tsta] 3 1795328326.71157646179 [ok]",
     "rpc_motors.flows.txt (bytes), yarp_rpc_motors.txt (text)"),
    ("rpc_get_encs", "rpc_motors.flows.txt", 14, None, "get encs", "rpc_motors.flows.txt"),
    ("rpc_reply_is_encs", "rpc_motors.flows.txt", 15, None,
     "[is] encs (0.0 0.0 0.0 0.0) [tsta] 4 1795328326.71171855927 [ok]",
     "rpc_motors.flows.txt: nested float64 list 0x10a (bytes), yarp_rpc_motors.txt (text)"),
    ("rpc_set_poss_int_list", "rpc_motors.flows.txt", 16, None, "set poss (1 2 3 4)",
     "rpc_motors.flows.txt: nested int32 list 0x101"),
    ("rpc_get_done", "rpc_motors.flows.txt", 18, None, "get done 0", "rpc_motors.flows.txt"),
    ("rpc_reply_fail", "rpc_motors.flows.txt", 19, None, "[fail]", "rpc_motors.flows.txt, yarp_rpc_motors.txt"),
    ("rpc_set_vmos_mixed_nested", "rpc_motors.flows.txt", 20, None, "set vmos (0.5 0 0 0)",
     "rpc_motors.flows.txt: nested mixed list 0x100"),
    ("rpc_reply_is_vmo", "rpc_motors.flows.txt", 23, None, "[is] vmo 0.5 [tsta] 6 1795328326.71251559258 [ok]",
     "rpc_motors.flows.txt (bytes), yarp_rpc_motors.txt (text)"),
    ("rpc_get_icmd_cmds", "rpc_motors.flows.txt", 24, None, "get icmd cmds", "rpc_motors.flows.txt"),
    ("rpc_reply_cmds_vocab_list", "rpc_motors.flows.txt", 25, None,
     "[is] [cmds] ([pos] [pos] [pos] [pos]) [tsta] 7 1795328326.71269321442 [ok]",
     "rpc_motors.flows.txt: nested vocab list 0x109 (bytes), yarp_rpc_motors.txt (text)"),
    ("rpc_get_foo", "rpc_motors.flows.txt", 26, None, "get foo", "rpc_motors.flows.txt"),
    ("state_port_vector", "sniff_state.txt", 0, None, "1.0 2.0 3.0 4.0",
     "sniff_state.txt: top-level float64 list 0x10a, 40 bytes"),
    ("state_ext_port", "sniff_stateExt.txt", 0, None,
     "(1.0 2.0 3.0 4.0) [ok] (0.0 0.0 0.0 0.0) [ok] (0.0 0.0 0.0 0.0) [ok] (10.0 20.0 30.0 40.0) [ok] "
     "(0.0 0.0 0.0 0.0) [ok] (0.0 0.0 0.0 0.0) [ok] (0.0 0.0 0.0 0.0) [ok] (33.0 34.0 35.0 36.0) [ok] "
     "(3300.0 3400.0 3500.0 3600.0) [ok] (7565168 7565168 7565168 7565168) [ok] (0 0 0 0) [ok]",
     "sniff_stateExt.txt: 504 bytes; control modes travel as an int32 list 0x101 holding vocab codes"),
]


def v(kind_, x):
    return {kind_: x}


def i32(x):
    return v("int32", x)


def f64(x):
    return v("float64", x)


def s(x):
    return v("string", x)


def voc(x):
    return v("vocab", x)


def lst(*xs):
    return v("list", list(xs))


# (name, input text, value tree, canonical text, where it comes from)
STATED = [
    ("paper_integers", "10 20 30", [i32(10), i32(20), i32(30)], "10 20 30",
     "paper, text-form table: a list of three integers"),
    ("paper_floats", "10.0 20.5 31.4159", [f64(10.0), f64(20.5), f64(31.4159)],
     "10.0 20.5 31.4159000000000006025", "paper, text-form table: a list of three floating point numbers"),
    ("paper_strings_and_list", 'action "go left" (10 20 30)',
     [s("action"), s("go left"), lst(i32(10), i32(20), i32(30))], 'action "go left" (10 20 30)',
     "paper, text-form table: two strings and a nested list of integers"),
    ("paper_vocabs", "[set] [pos] 1 30.3", [voc("set"), voc("pos"), i32(1), f64(30.3)],
     "[set] [pos] 1 30.3000000000000007105", "paper, text-form table: two vocabs, an integer, a float"),
    ("text_edge_cases",
     '- + 1. .5 1e5 -nan 0x1F 010 +5 null x,y 2147483648 -2147483648 "esc\\"q\\\\b" [toolong] 3000000000 0.1',
     [i32(0), i32(0), f64(1.0), f64(0.5), f64(100000.0), s("-nan"), i32(31), i32(8), i32(5), voc("null"),
      s("x"), s("y"), v("int64", 2147483648), i32(-2147483648), s('esc"q\\b'), voc("tool"),
      v("int64", 3000000000), f64(0.1)],
     '0 0 1.0 0.5 100000.0 "-nan" 31 8 5 [null] x y 2147483648 -2147483648 "esc\\"q\\\\b" [tool] 3000000000 '
     "0.100000000000000005551",
     "wire-protocol 2; text_parse_edge_cases.txt (YARP's text and the 189-byte length)"),
    ("rpc_set_pos_vocabs", "[set] [pos] 1 25.0", [voc("set"), voc("pos"), i32(1), f64(25.0)],
     "[set] [pos] 1 25.0", "wire-protocol 5.4"),
    ("rpc_reply_llim", "[is] [llim] 0.0 100.0 [tsta] 2022 1795328514.60050964355 [ok]",
     [voc("is"), voc("llim"), f64(0.0), f64(100.0), voc("tsta"), i32(2022), f64(1795328514.60050964355), voc("ok")],
     "[is] [llim] 0.0 100.0 [tsta] 2022 1795328514.60050964355 [ok]", "wire-protocol 5.4"),
    ("rpc_set_cmod", "[set] [icmd] [cmod] 0 [vel]", [voc("set"), voc("icmd"), voc("cmod"), i32(0), voc("vel")],
     "[set] [icmd] [cmod] 0 [vel]", "wire-protocol 5.4"),
    ("rpc_set_vmos_floats", "[set] [vmos] (0.5 0.0 0.0 0.0)",
     [voc("set"), voc("vmos"), lst(f64(0.5), f64(0.0), f64(0.0), f64(0.0))],
     "[set] [vmos] (0.5 0.0 0.0 0.0)", "wire-protocol 5.4"),
    ("rpc_nak", "[nak]", [voc("nak")], "[nak]", "wire-protocol 5.4"),
    ("admin_list_out_reply", '(from "/w") (to "/r") (carrier tcp)',
     [lst(s("from"), s("/w")), lst(s("to"), s("/r")), lst(s("carrier"), s("tcp"))],
     '(from "/w") (to "/r") (carrier tcp)', "write_connect_read.flows.txt: text admin reply of /w"),
    ("admin_add_reply", '0 "Added connection from /w to tcp://r\\r\\n"',
     [i32(0), s("Added connection from /w to tcp://r\r\n")],
     '0 "Added connection from /w to tcp://r\\r\\n"', "write_connect_read.flows.txt: text admin reply of /w"),
    ("text_carrier_input", '(hello world) 42 3.5 "a string" [vocb]',
     [lst(s("hello"), s("world")), i32(42), f64(3.5), s("a string"), voc("vocb")],
     '(hello world) 42 3.5 "a string" [vocb]', "yarp_read_text_input.txt: printed by yarp read"),
    ("true_false_are_vocabs", "true false", [voc("1"), voc("")], "true false",
     "wire-protocol 1.6: true = 09 00 00 00 31 00 00 00, false = vocab 0"),
    ("empty_bottle", "", [], "", "wire-protocol 1.2: an empty bottle is not specialised"),
    ("empty_nested_list_and_blob", "() {} \"\"", [lst(), v("blob", ""), s("")], '() {} ""',
     "wire-protocol 1.2/1.3: empty lists are not specialised"),
    ("homogeneous_nested_lists_stay_mixed", "(1 2) (3 4)", [lst(i32(1), i32(2)), lst(i32(3), i32(4))],
     "(1 2) (3 4)", "wire-protocol 1.2: lists never specialise their parent"),
    ("homogeneous_blobs", "{1} {2 3}", [v("blob", "01"), v("blob", "0203")], "{1} {2 3}",
     "wire-protocol 1.2: subCoder applies to every scalar type"),
    ("homogeneous_int64", "3000000000 -3000000000", [v("int64", 3000000000), v("int64", -3000000000)],
     "3000000000 -3000000000", "wire-protocol 1.2 and 2: ints beyond int32 are int64 (tag 0x11)"),
    ("separators", "1,2\t3\r\n4  ,  5", [i32(1), i32(2), i32(3), i32(4), i32(5)], "1 2 3 4 5",
     "wire-protocol 2: space, tab, CR, LF and comma separate items"),
    ("quoting_rules", 'hi x.y a-b_c "/r" "127.0.0.1" "with space" "true" "9lives" "tab\there"',
     [s("hi"), s("x.y"), s("a-b_c"), s("/r"), s("127.0.0.1"), s("with space"), s("true"), s("9lives"),
      s("tab\there")],
     'hi x.y a-b_c "/r" "127.0.0.1" "with space" "true" "9lives" "tab\there"',
     "wire-protocol 2, quotedString: bare only for [A-Za-z_] (digits . - after the first)"),
    ("escapes", '"a\\nb" "c\\rd" "nul\\0x" "back\\\\slash" "q\\"uote"',
     [s("a\nb"), s("c\rd"), s("nul\0x"), s("back\\slash"), s('q"uote')],
     '"a\\nb" "c\\rd" "nul\\0x" "back\\\\slash" "q\\"uote"', "wire-protocol 2: escapes \\n \\r \\0 \\\\ \\\""),
    ("float_rendering", "1e21 -0.0 2.5e-8 123456789012345678901234.0 0.30000000000000004",
     [f64(1e21), f64(-0.0), f64(2.5e-8), f64(123456789012345678901234.0), f64(0.30000000000000004)],
     "1e+21 -0.0 2.49999999999999988687e-08 1.23456789012345685803e+23 0.300000000000000044409",
     "wire-protocol 2: %.21g with .0 appended only without '.' or 'e'"),
    ("hex_and_octal", "0xff 0XA -0x10 017 0x 08", [i32(255), i32(10), i32(-16), i32(15), i32(0), i32(0)],
     "255 10 -16 15 0 0", "wire-protocol 2: strtoll base 0 (08 stops at the 8 and reads 0)"),
    ("not_numbers", "0x123456789 1.2.3 --1 . e5 inf1 -nan NaN",
     [s("0x123456789"), s("1.2.3"), s("--1"), s("."), s("e5"), s("inf1"), s("-nan"), s("NaN")],
     '"0x123456789" "1.2.3" "--1" "." e5 inf1 "-nan" NaN', "wire-protocol 2: smartAdd's number-like rule"),
    ("nested_deep", "(((1) [a]) {7})", [lst(lst(lst(i32(1)), voc("a")), v("blob", "07"))], "(((1) [a]) {7})",
     "wire-protocol 1.3: nested lists carry 0x100|subcode and no repeated tag"),
    ("utf8_string", '"h\u00e9llo"', [s("h\u00e9llo")], '"h\u00e9llo"', "strings are raw bytes; UTF-8 passes through"),
]

# Malformed input: text (1-based column) and binary (byte offset), with a fragment of the message.
MALFORMED_TEXT = [
    ('"abc', 1, "no closing '\"'"),
    ("1 (2 3", 3, "'(' has no matching ')'"),
    ("{1 300}", 4, "outside 0..255"),
    ("{1 x}", 4, "not an integer 0..255"),
    ("{1 2.5}", 4, "not an integer 0..255"),
    ("{1 2", 1, "'{' has no matching '}'"),
    ("1 2)", 4, "')' has no matching '('"),
    (")", 1, "')' has no matching '('"),
    ("}", 1, "'}' has no matching '{'"),
    ("[set", 1, "'[' has no closing ']'"),
    ("[se t]", 1, "'[' has no closing ']'"),
    ('"a"b', 4, "separate items with a space"),
    ("x(1)", 2, "separate items with a space"),
    ("(1)(2)", 4, "separate items with a space"),
    ("abc\\", 4, "continues nothing"),
    ("1 2\n(3 4", 5, "line 2 column 1"),
]

MALFORMED_HEX = [
    ("", 0, "expected 4 bytes of bottle tag, only 0 remain"),
    ("000100", 0, "expected 4 bytes of bottle tag, only 3 remain"),
    ("04000000", 0, "expected a bottle tag 0x100..0x1ff, got 0x4"),
    ("03010000 00000000", 0, "unknown list item type 0x3"),
    ("00010000", 4, "expected 4 bytes of length, only 0 remain"),
    ("00010000 01000000 04000000 ffffffff 616263", 12, "string length 4294967295 exceeds the 3 bytes remaining"),
    ("00010000 01000000 0c000000 05000000 0102", 12, "blob length 5 exceeds the 2 bytes remaining"),
    ("00010000 ffffff7f", 4, "list count 2147483647 needs at least"),
    ("0a010000 02000000 0000000000000000", 4, "list count 2 needs at least 16 bytes, only 8 remain"),
    ("00010000 01000000 07000000 00000000", 8, "unknown item tag 0x7"),
    ("00010000 01000000 0a000000 0000", 12, "expected 8 bytes of float64, only 2 remain"),
    ("00010000 01000000 03010000 00000000", 8, "unknown list item type 0x3"),
    ("00010000 01000000 00040000 00000000", 8, "unknown item tag 0x400"),
    ("00010000 00000000 00", 8, "1 unexpected byte after the end of the bottle"),
    ("09010000 01000000 6f6b0000 ffff", 12, "2 unexpected bytes after the end of the bottle"),
]


def main(captures, out_dir):
    captures = Path(captures)
    cache = {}
    cases = []
    for name, fname, index, text, canonical, source in CAPTURED:
        if fname not in cache:
            reader = sniffed_bottles if fname.startswith("sniff_") else captured_bottles
            cache[fname] = reader(captures / fname)
        data = cache[fname][index]
        value = decode(data)
        rendered = render_items(value)
        assert rendered == canonical, (name, rendered, canonical)
        assert encode(value) == data, name  # our rule-based encoder agrees with real YARP
        cases.append({"name": name, "text": canonical if text is None else text, "canonical_text": canonical,
                      "hex": data.hex(), "hex_from": "capture", "value": value, "source": source})
    for name, text, value, canonical, source in STATED:
        assert render_items(value) == canonical, (name, render_items(value), canonical)
        data = encode(value)
        assert decode(data) == value, name
        cases.append({"name": name, "text": text, "canonical_text": canonical, "hex": data.hex(),
                      "hex_from": "rules", "value": value, "source": source})
    edge = next(c for c in cases if c["name"] == "text_edge_cases")
    assert len(edge["hex"]) // 2 == 189, len(edge["hex"]) // 2  # the length YARP's capture shows
    doc = {
        "about": "Bottle test vectors shared by the C++ and Python tests; see docs/protocol/bottle.md. "
                 "Generated by tests/vectors/make_bottle_vectors.py from the YARP 3 captures in tests/vectors/yarp3-captures. "
                 "Do not" " edit: change that script and run make generate. hex_from=capture: bytes sent by real YARP 3; "
                 "hex_from=rules: bytes from the section-1 rules, checked against the captures' layouts.",
        "cases": cases,
        "malformed_text": [{"text": t, "column": c, "message": m} for t, c, m in MALFORMED_TEXT],
        "malformed_hex": [{"hex": h.replace(" ", ""), "offset": o, "message": m} for h, o, m in MALFORMED_HEX],
    }
    out = Path(out_dir) / "bottles.json"
    # One entry per line: readable diffs without a line per number.
    lines = ["{", '"about": %s,' % json.dumps(doc["about"])]
    for key in ("cases", "malformed_text", "malformed_hex"):
        entries = [json.dumps(e, ensure_ascii=False) for e in doc[key]]
        lines.append('"%s": [' % key)
        lines.append(",\n".join(" " + e for e in entries))
        lines.append("]," if key != "malformed_hex" else "]")
    lines.append("}")
    out.write_text("\n".join(lines) + "\n")
    assert json.loads(out.read_text()) == json.loads(json.dumps(doc))
    print("wrote %s: %d cases, %d malformed text, %d malformed binary" %
          (out, len(cases), len(MALFORMED_TEXT), len(MALFORMED_HEX)))


if __name__ == "__main__":
    args = sys.argv[1:]
    out_dir = Path(__file__).parent
    if "--out" in args:
        at = args.index("--out")
        out_dir = Path(args[at + 1])
        del args[at:at + 2]
    main(args[0] if args else Path(__file__).with_name("yarp3-captures"), out_dir)
