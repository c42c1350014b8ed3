# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Every class of IDL error is reported with file:line:column and what is wrong."""
import textwrap

import pytest

from robogene_codegen.idl import IdlErrors, compile_directory

HEADER = "idl: 1\n"
TYPES = HEADER + textwrap.dedent("""\
    types:
      enums:
        - name: Mode
          doc: A mode.
          wire: vocab
          members:
            - {name: idle, value: idl}
            - {name: position, value: pos}
""")


def iface(methods: str, name: str = "IThing") -> str:
    return HEADER + f"interface: {name}\nversion: 1\ndoc: A thing.\nmethods:\n" + \
        textwrap.indent(textwrap.dedent(methods), "  ")


def errors_of(tmp_path, files: dict) -> list[str]:
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    with pytest.raises(IdlErrors) as info:
        compile_directory(tmp_path)
    return [str(e) for e in info.value.errors]


def one_error(tmp_path, files: dict) -> str:
    errs = errors_of(tmp_path, files)
    assert len(errs) == 1, errs
    return errs[0]


def test_valid_minimal_file_compiles(tmp_path):
    (tmp_path / "types.yaml").write_text(TYPES)
    (tmp_path / "ithing.yaml").write_text(iface("""\
        - name: setMode
          doc: Set.
          wire: [set, mode]
          args:
            - {name: j, type: joint}
            - {name: m, type: Mode, default: idle}
        """))
    idl = compile_directory(tmp_path)
    assert [m.name for m in idl.interfaces[0].methods] == ["setMode"]


def test_yaml_syntax_error_has_line_and_column(tmp_path):
    err = one_error(tmp_path, {"bad.yaml": "idl: 1\ninterface: [unclosed\n"})
    assert err.startswith(f"{tmp_path}/bad.yaml:3:1: error: YAML syntax")


def test_duplicate_yaml_key(tmp_path):
    err = one_error(tmp_path, {"a.yaml": "idl: 1\ntypes: {}\ntypes: {}\n"})
    assert err == f"{tmp_path}/a.yaml:3:1: error: duplicate key 'types' (first given at line 2)"


def test_unknown_key_points_at_the_key(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: stop
          doc: Stop.
          wire: [set, sto]
          colour: red
        """)})
    assert err.startswith(f"{tmp_path}/i.yaml:9:5: error: unknown key 'colour' in methods.0")


def test_schema_type_error(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: stop
          doc: Stop.
          wire: set
        """)})
    assert err.startswith(f"{tmp_path}/i.yaml:8:11: error: methods.0.wire: 'set' is not of type 'array'")


def test_missing_keys_of_an_interface(tmp_path):
    err = one_error(tmp_path, {"i.yaml": "idl: 1\ninterface: IThing\n"})
    assert err == f"{tmp_path}/i.yaml:1:1: error: interface file is missing: version, doc, methods"


def test_unsupported_language_version(tmp_path):
    err = one_error(tmp_path, {"i.yaml": "idl: 2\ntypes: {}\n"})
    assert err == f"{tmp_path}/i.yaml:1:6: error: unsupported IDL language version 2 (this compiler reads version 1)"


def test_unknown_type(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: setThing
          doc: Set.
          wire: [set, thng]
          args:
            - {name: v, type: float32}
        """)})
    assert err.startswith(f"{tmp_path}/i.yaml:10:25: error: unknown type 'float32' (known types: joint, int32")


def test_unknown_unit(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: setThing
          doc: Set.
          wire: [set, thng]
          args:
            - {name: v, type: float64, unit: furlong}
        """)})
    assert "i.yaml:10:40: error: unknown unit 'furlong'" in err


def test_duplicate_method(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: stop
          doc: Stop.
          wire: [set, sto]
        - name: stop
          doc: Stop again.
          wire: [set, stp]
        """)})
    assert err == f"{tmp_path}/i.yaml:9:11: error: duplicate method 'stop' in IThing (first at line 6)"


def test_duplicate_cpp_overload(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: stop
          doc: Stop.
          wire: [set, sto]
        - name: halt
          cpp_name: stop
          doc: Stop again.
          wire: [set, stp]
        """)})
    assert err == f"{tmp_path}/i.yaml:9:11: error: duplicate method: C++ overload stop() is already declared at line 6"


def test_vocab_collision_within_an_interface(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: stop
          doc: Stop.
          wire: [set, sto]
        - name: halt
          doc: Halt.
          wire: [set, sto]
        """)})
    assert err == f"{tmp_path}/i.yaml:9:11: error: vocab collision: [set] [sto] of 'halt' is already used by 'stop' (line 6)"


def test_vocab_collision_across_a_service(tmp_path):
    errs = errors_of(tmp_path, {
        "a.yaml": iface("- {name: stop, doc: Stop., wire: [set, sto]}\n", name="IA"),
        "b.yaml": iface("- {name: halt, doc: Halt., wire: [set, sto]}\n", name="IB"),
        "s.yaml": "idl: 1\nservice: board\nversion: 1\ndoc: Both.\nrpc_port: rpc:i\ninterfaces: [IA, IB]\n",
    })
    assert len(errs) == 1
    assert errs[0].startswith(f"{tmp_path}/s.yaml:6:13: error: vocab collision: [set] [sto] means IA.stop")


def test_shared_method_across_a_service_is_not_a_collision(tmp_path):
    same = "- {name: stop, doc: Stop., wire: [set, sto]}\n"
    (tmp_path / "a.yaml").write_text(iface(same, name="IA"))
    (tmp_path / "b.yaml").write_text(iface(same, name="IB"))
    (tmp_path / "s.yaml").write_text("idl: 1\nservice: board\nversion: 1\ndoc: Both.\n"
                                     "rpc_port: rpc:i\ninterfaces: [IA, IB]\n")
    assert [s.name for s in compile_directory(tmp_path).services] == ["board"]


def test_collision_with_protocol_request(tmp_path):
    errs = errors_of(tmp_path, {
        "a.yaml": iface("- {name: prot, doc: P., wire: [get, prot], results: [{name: v, type: int32}]}\n", name="IA"),
        "s.yaml": "idl: 1\nservice: board\nversion: 1\ndoc: B.\nrpc_port: rpc:i\ninterfaces: [IA]\n"
                  "protocol: {wire: [get, prot], reply: prot, version: [1, 9, 0]}\n",
    })
    assert len(errs) == 1 and "vocab collision: [get] [prot] of IA.prot" in errs[0]
    assert "is the protocol-version request" in errs[0]


def test_vocab_too_long(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("- {name: done, doc: D., wire: [get, donee]}\n")})
    assert err == (f"{tmp_path}/i.yaml:6:39: error: vocab 'donee' must be 1 to 4 printable ASCII "
                   "characters; YARP would truncate it to [done]")


def test_enum_value_collision(tmp_path):
    err = one_error(tmp_path, {"t.yaml": TYPES.replace("value: pos", "value: idl")})
    assert err == f"{tmp_path}/t.yaml:9:35: error: value collision: 'position' and 'idle' of enum 'Mode' are both 'idl'"


def test_duplicate_type(tmp_path):
    errs = errors_of(tmp_path, {"t.yaml": TYPES, "u.yaml": TYPES})
    assert errs == [f"{tmp_path}/u.yaml:4:13: error: duplicate type 'Mode' (first defined at {tmp_path}/t.yaml:4:13)"]


@pytest.mark.parametrize("type_,default,why", [
    ("Mode", "running", "'running' is not a member of Mode (idle, position)"),
    ("float64", "fast", "'fast' is not a number"),
    ("int32", 3000000000, "3000000000 is not an int32"),
    ("bool", 1, "1 is not true or false"),
    ("vocab", "toolong", "'toolong' is not a vocab of 1-4 characters"),
])
def test_bad_default(tmp_path, type_, default, why):
    err = one_error(tmp_path, {"t.yaml": TYPES, "i.yaml": iface(f"""\
        - name: setThing
          doc: Set.
          wire: [set, thng]
          args:
            - {{name: v, type: {type_}, default: {default}}}
        """)})
    assert err.startswith(f"{tmp_path}/i.yaml:10:")
    assert err.endswith(f"error: bad default for 'v': {why}")


def test_default_must_be_trailing(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: setThing
          doc: Set.
          wire: [set, thng]
          args:
            - {name: a, type: float64, default: 1.0}
            - {name: b, type: float64}
        """)})
    assert err == f"{tmp_path}/i.yaml:11:16: error: argument 'b' needs a default because 'a' before it has one"


def test_all_axes_needs_a_joint(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: setThing
          doc: Set.
          wire: [set, thng]
          args:
            - {name: v, type: float64}
          all_axes: {name: setThings, wire: [set, thgs]}
        """)})
    assert err == f"{tmp_path}/i.yaml:11:5: error: 'setThing' has no joint argument, so it cannot have an all-axes form"


def test_reduce_needs_bool_results(tmp_path):
    """reduce: all makes one value of every axis's (YARP's [get] [dons]); only a bool can be and-ed."""
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: getThing
          doc: Get.
          wire: [get, thng]
          args:
            - {name: j, type: joint}
          results:
            - {name: v, type: float64}
          all_axes: {name: getThings, wire: [get, thgs], reduce: all}
        """)})
    assert err == (f"{tmp_path}/i.yaml:13:60: error: 'reduce: all' makes one value of every axis's, which needs "
                   "bool results; 'getThing' returns float64")


def test_echo_past_the_request(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: getThing
          doc: Get.
          wire: [get, thng]
          echo: 2
          results:
            - {name: v, type: float64}
        """)})
    assert err == f"{tmp_path}/i.yaml:9:11: error: echo 2 of 'getThing' is past the end of its request (2 vocabs and 0 arguments)"


def test_stamp_applies_only_to_queries(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: stop
          doc: Stop.
          wire: [set, sto]
          stamp: false
        """)})
    assert err == (f"{tmp_path}/i.yaml:9:5: error: 'stamp' concerns the reply to a query; 'stop' has no "
                   "results, so its reply is [ok] or [fail]")


def test_an_unstamped_query_changes_the_fingerprint_and_its_all_axes_form(tmp_path):
    query = """\
        - name: getThing
          doc: Get.
          wire: [get, thng]{stamp}
          args:
            - {{name: j, type: joint}}
          results:
            - {{name: v, type: float64}}
          all_axes: {{name: getThings, wire: [get, thns]}}
        """
    (tmp_path / "i.yaml").write_text(iface(query.format(stamp="")))
    stamped = compile_directory(tmp_path).interfaces[0]
    (tmp_path / "i.yaml").write_text(iface(query.format(stamp="\n          stamp: false")))
    unstamped = compile_directory(tmp_path).interfaces[0]
    assert [m.stamp for m in stamped.methods] == [True, True]
    assert [m.stamp for m in unstamped.methods] == [False, False]
    assert stamped.fingerprint != unstamped.fingerprint


def test_command_aliases_must_name_a_command_and_not_overlap(tmp_path):
    errs = errors_of(tmp_path, {
        "a.yaml": iface("- {name: stop, doc: Stop., wire: [set, sto]}\n"
                        "- {name: get, doc: Get., wire: [get, thng], results: [{name: v, type: int32}]}\n",
                        name="IA"),
        "s.yaml": "idl: 1\nservice: board\nversion: 1\ndoc: B.\nrpc_port: rpc:i\ninterfaces: [IA]\n"
                  "command:\n  port: command:i\n  doc: C.\n  prefix: [set]\n  aliases:\n"
                  "    - {head: [halt], method: IA.stop}\n"
                  "    - {head: [sto, x], method: IA.stop}\n"
                  "    - {head: [g], method: IA.get}\n"
                  "    - {head: [h], method: IB.stop}\n",
    })
    assert errs == [
        f"{tmp_path}/s.yaml:13:14: error: command alias [sto] [x] overlaps the head [sto] of IA.stop",
        f"{tmp_path}/s.yaml:14:27: error: command alias [g]: 'IA.get' is not a command (a method with a wire path "
        "and no results)",
        f"{tmp_path}/s.yaml:15:27: error: command alias [h]: 'IB.stop' is not a method of this service's interfaces",
    ]
    (tmp_path / "s.yaml").write_text((tmp_path / "s.yaml").read_text().split("    - {head: [sto")[0])
    command = compile_directory(tmp_path).services[0].command
    assert [(h, m.name) for h, m in command.aliases] == [(("halt",), "stop")]


def test_image_cannot_travel_by_rpc(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: getImage
          doc: Get.
          wire: [get, img]
          results:
            - {name: i, type: image_rgb}
        """)})
    assert "i.yaml:8:11: error: 'getImage' returns an image_rgb" in err


def test_service_names_unknown_interface_and_bad_stream(tmp_path):
    errs = errors_of(tmp_path, {
        "a.yaml": iface("- {name: go, doc: Go., wire: [set, go], args: [{name: j, type: joint}]}\n", name="IA"),
        "s.yaml": textwrap.dedent("""\
            idl: 1
            service: board
            version: 1
            doc: B.
            rpc_port: rpc:i
            interfaces: [IA, IZ]
            streams:
              - {name: s, port: state:o, doc: S., source: IA.go, period: 0.02}
              - {name: t, port: rpc:i, doc: T., source: IA.go, period: 0.02}
            """),
    })
    assert errs == [
        f"{tmp_path}/s.yaml:6:18: error: unknown interface 'IZ' (known: IA)",
        f"{tmp_path}/s.yaml:8:47: error: stream source 'IA.go' must take no arguments and return exactly one result",
        f"{tmp_path}/s.yaml:9:21: error: port 'rpc:i' is already the RPC port",
    ]


def test_errors_from_several_files_are_all_reported(tmp_path):
    errs = errors_of(tmp_path, {
        "a.yaml": "idl: 1\ntypes: {}\ntypes: {}\n",
        "b.yaml": iface("- {name: x, doc: X., wire: [get, toolong]}\n"),
    })
    assert len(errs) == 2 and "a.yaml:3:1" in errs[0] and "b.yaml:6:36" in errs[1]


def test_kind_must_be_exactly_one(tmp_path):
    err = one_error(tmp_path, {"a.yaml": "idl: 1\ndoc: Nothing.\n"})
    assert "a file describes exactly one of" in err and err.endswith("found none")


def test_reserved_words_cannot_name_things(tmp_path):
    err = one_error(tmp_path, {"t.yaml": TYPES.replace("name: idle", "name: auto")})
    assert err == (f"{tmp_path}/t.yaml:8:18: error: 'auto' is a reserved word in C++ or Python "
                   "and cannot name anything in the IDL")


def test_echo_vocab_must_be_a_vocab(tmp_path):
    err = one_error(tmp_path, {"i.yaml": iface("""\
        - name: getThing
          doc: Get.
          wire: [get, thng]
          echo: things
          results:
            - {name: v, type: float64}
        """)})
    assert err == (f"{tmp_path}/i.yaml:9:11: error: vocab 'things' must be 1 to 4 printable ASCII "
                   "characters; YARP would truncate it to [thin]")


def test_aliases_are_refused_rather_than_expanded(tmp_path):
    bomb = "idl: 1\ntypes:\n  a: &a [x, x, x, x, x, x, x, x, x]\n  b: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
    errs = errors_of(tmp_path, {"bomb.yaml": bomb})
    assert errs[0] == f"{tmp_path}/bomb.yaml:3:6: error: this value is reused through an alias (*name); aliases are not allowed in IDL files"


def test_absurd_nesting_is_refused(tmp_path):
    deep = "idl: 1\ntypes: " + "[" * 200 + "]" * 200 + "\n"
    err = errors_of(tmp_path, {"deep.yaml": deep})[0]
    assert "deep.yaml:2:" in err and "nested more than 32 levels deep" in err


def test_non_utf8_file(tmp_path):
    (tmp_path / "bin.yaml").write_bytes(b"idl: 1\n\xff\xfe\n")
    with pytest.raises(IdlErrors) as info:
        compile_directory(tmp_path)
    assert str(info.value) == f"{tmp_path}/bin.yaml:1:1: error: not UTF-8 text (byte 7)"


def service_with(extra: str) -> str:
    return textwrap.dedent("""\
        idl: 1
        service: cam
        version: 1
        doc: C.
        rpc_port: rpc
        interfaces: [IA]
        """) + extra


def test_command_reply_needs_scoped_replies_a_trailing_result_and_items_every_command_has(tmp_path):
    ia = iface("- {name: go, doc: Go., wire: [set, go], args: [{name: j, type: joint}]}\n", name="IA")
    (tmp_path / "1").mkdir()
    assert one_error(tmp_path / "1", {"a.yaml": ia, "s.yaml": service_with("command_reply: [0, result]\n")}) == \
        f"{tmp_path}/1/s.yaml:7:16: error: command_reply belongs only to a service with 'replies: scoped'"
    (tmp_path / "2").mkdir()
    assert one_error(tmp_path / "2", {"a.yaml": ia, "s.yaml": service_with(
        "replies: scoped\ncommand_reply: [result, 0]\n")}) == \
        f"{tmp_path}/2/s.yaml:8:16: error: command_reply must end with 'result' and name it once"
    (tmp_path / "3").mkdir()
    assert one_error(tmp_path / "3", {"a.yaml": ia, "s.yaml": service_with(
        "replies: scoped\ncommand_reply: [0, 3, result]\n")}) == \
        f"{tmp_path}/3/s.yaml:8:20: error: command_reply item 3 is past the end of the shortest command " \
        "of this service (3 items)"
    (tmp_path / "4").mkdir()
    idl = compile_directory_ok(tmp_path / "4", {"a.yaml": ia, "s.yaml": service_with(
        "replies: scoped\ncommand_reply: [0, 1, result]\n")})
    assert idl.services[0].command_reply == (0, 1, "result")


def compile_directory_ok(path, files: dict):
    for name, text in files.items():
        (path / name).write_text(text, encoding="utf-8")
    return compile_directory(path)
