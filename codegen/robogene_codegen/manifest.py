# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""codegen/generated-manifest.yaml: every generated file of the repository and the generator that writes it.

Read by `make generate` and `make check-generated` (through generate.py) and by the test that scans
the tree for do-not-edit headers. A wrong manifest is reported as `file:line:column: error: what`."""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Optional

from .idl.errors import IdlError, IdlErrors, Mark
from .idl.loader import Document, load

MANIFEST = "codegen/generated-manifest.yaml"
GENERATED = "generated"  # the name of every folder that holds nothing but generated files
INPUTS = ("idl", "root")
PLACEHOLDERS = ("{python}", "{out}", "{fab}")
_KEYS = {"name", "doc", "emitter", "input", "command", "needs", "into", "files", "why", "no_header", "blocks"}
_NAME = re.compile(r"[a-z][a-z0-9-]*\Z")
_BLOCK = re.compile(r"[A-Z][A-Z0-9_]*\Z")


@dataclass(frozen=True)
class Generator:
    name: str
    doc: str
    emitter: Optional[str]            # "module:function" under robogene_codegen.emitters, run in-process
    input: str                        # what the emitter is given: the compiled IDL or the repository root
    command: Optional[tuple]          # or a program run in the repository root that writes into {out}
    needs: Optional[str]              # the make target that must be built first (mk/codegen.mk reads it)
    into: Optional[str]               # the folder of its files ...
    files: tuple = ()                 # ... named relative to it
    blocks: tuple = ()                # or ((document, (BLOCK, ...)), ...)
    no_header: Optional[str] = None   # why its files cannot carry the do-not-edit header

    @property
    def paths(self) -> list[str]:
        return [f"{self.into}/{f}" for f in self.files]


@dataclass(frozen=True)
class Manifest:
    generators: tuple

    def generator(self, name: str) -> Generator:
        for g in self.generators:
            if g.name == name:
                return g
        raise KeyError(name)

    @property
    def files(self) -> dict[str, str]:
        """Every generated file: path -> the generator that writes it."""
        return {p: g.name for g in self.generators for p in g.paths}

    @property
    def block_documents(self) -> dict[str, list[str]]:
        """Every hand-written document with generated blocks: path -> its block names."""
        out: dict[str, list[str]] = {}
        for g in self.generators:
            for doc, names in g.blocks:
                out.setdefault(doc, []).extend(names)
        return out

    @property
    def generated_folders(self) -> list[str]:
        """The folders named `generated`: each holds (in it and below) exactly the files listed here."""
        return sorted({generated_folder(g.into) for g in self.generators if g.into and generated_folder(g.into)})


def generated_folder(into: str) -> Optional[str]:
    """The `generated` folder `into` lies in (docs/generated for docs/generated/can), or None."""
    parts = PurePosixPath(into).parts
    return "/".join(parts[:parts.index(GENERATED) + 1]) if GENERATED in parts else None


def read(root: Path) -> Manifest:
    path = root / MANIFEST
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise IdlErrors([IdlError(Mark(MANIFEST, 1, 1), f"cannot read the manifest ({exc.strerror})")]) from None
    return parse(load(MANIFEST, text))


def parse(doc: Document) -> Manifest:
    errors: list[IdlError] = []

    def fail(path: tuple, message: str) -> None:
        errors.append(IdlError(doc.mark(path), message))

    def relative(path: tuple, value) -> bool:
        if not isinstance(value, str) or not value:
            fail(path, f"expected a path relative to the repository root, got {value!r}")
            return False
        p = PurePosixPath(value)
        if p.is_absolute() or ".." in p.parts or str(p) != value:
            fail(path, f"{value!r} is not a plain relative path (no leading /, no .., no trailing /)")
            return False
        return True

    data = doc.data
    if not isinstance(data, dict) or set(data) != {"generators"} or not isinstance(data["generators"], list):
        fail((), "expected one key, `generators:`, holding a list")
        raise IdlErrors(errors)
    generators, names, owners = [], set(), {}
    for i, entry in enumerate(data["generators"]):
        at = ("generators", i)
        if not isinstance(entry, dict):
            fail(at, "expected a mapping")
            continue
        for key in sorted(set(entry) - _KEYS):
            fail(at + (key,), f"unknown key {key!r} (allowed: {', '.join(sorted(_KEYS))})")
        name = entry.get("name")
        if not isinstance(name, str) or not _NAME.match(name):
            fail(at + ("name",), f"expected a lower-case name like `cpp-interfaces`, got {name!r}")
            continue
        if name in names:
            fail(at + ("name",), f"generator {name!r} is listed twice")
        names.add(name)
        if not isinstance(entry.get("doc"), str):
            fail(at + ("doc",), f"{name}: `doc:` (what it generates, from what) is missing")
        emitter, command = entry.get("emitter"), entry.get("command")
        if (emitter is None) == (command is None):
            fail(at, f"{name}: give exactly one of `emitter:` (module:function) and `command:` (a list)")
        if emitter is not None and not (isinstance(emitter, str) and re.fullmatch(r"[a-z_.]+:[a-z_]+", emitter)):
            fail(at + ("emitter",), f"{name}: expected module:function under robogene_codegen.emitters, got {emitter!r}")
        if command is not None:
            if not (isinstance(command, list) and command and all(isinstance(c, str) for c in command)):
                fail(at + ("command",), f"{name}: expected a list of words")
            elif not any("{out}" in word for word in command):
                fail(at + ("command",), f"{name}: the command must write into {{out}}")
        input_ = entry.get("input", "idl")
        if input_ not in INPUTS or (command is not None and "input" in entry):
            fail(at + ("input",), f"{name}: `input:` is one of {', '.join(INPUTS)}, for an emitter only")
        if "no_header" in entry and not (isinstance(entry["no_header"], str) and "files" in entry):
            fail(at + ("no_header",), f"{name}: `no_header:` says why its files cannot carry the header (files only)")
        needs = entry.get("needs")
        if needs is not None and not (isinstance(needs, str) and re.fullmatch(r"[a-z][a-z0-9-]*", needs)):
            fail(at + ("needs",), f"{name}: expected one make target, got {needs!r}")
        into, files, blocks = entry.get("into"), entry.get("files"), entry.get("blocks")
        if (files is None) == (blocks is None) or (files is not None) != (into is not None):
            fail(at, f"{name}: give either `into:` with `files:`, or `blocks:`")
            continue
        parsed_blocks: list = []
        if files is not None:
            if not relative(at + ("into",), into):
                continue
            if not isinstance(files, list) or not files:
                fail(at + ("files",), f"{name}: expected a non-empty list of file names")
                continue
            for k, f in enumerate(files):
                if relative(at + ("files", k), f):
                    full = f"{into}/{f}"
                    if full in owners:
                        fail(at + ("files", k), f"{full} is listed under {owners[full]} too")
                    owners[full] = name
            if files != sorted(files):
                fail(at + ("files",), f"{name}: keep the files sorted (a new one then has one place to go)")
            if generated_folder(into) is None and not isinstance(entry.get("why"), str):
                fail(at + ("into",), f"{name}: {into} is not in a folder named `{GENERATED}`: say `why:` the files "
                     "must live there")
        else:
            if not isinstance(blocks, dict) or not blocks:
                fail(at + ("blocks",), f"{name}: expected a mapping of document -> [BLOCK, ...]")
                continue
            for document, block_names in blocks.items():
                ok = relative(at + ("blocks", document), document)
                if not (isinstance(block_names, list) and block_names and
                        all(isinstance(b, str) and _BLOCK.match(b) for b in block_names)):
                    fail(at + ("blocks", document), f"{name}: expected a list of upper-case block names")
                    ok = False
                if ok:
                    parsed_blocks.append((document, tuple(block_names)))
        generators.append(Generator(
            name=name, doc=entry.get("doc", ""), emitter=emitter, input=input_,
            command=tuple(command) if isinstance(command, list) else None, needs=needs,
            into=into, files=tuple(files or ()), blocks=tuple(parsed_blocks), no_header=entry.get("no_header")))
    if errors:
        raise IdlErrors(errors)
    return Manifest(tuple(generators))
