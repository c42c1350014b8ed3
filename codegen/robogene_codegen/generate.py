# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the generators the manifest lists, and compares or writes what they produce.

Everything is computed in memory first: `check` then reports each file that is stale, missing, or
lies in a generated folder without being listed; `generate` writes only what changed (so timestamps
of unchanged files stay put) and removes the unlisted files. A generator that writes a file the
manifest does not list under it, or no longer writes one it lists, stops both before anything is
written: the manifest is the one list of what is generated."""
from __future__ import annotations

import importlib
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Iterable, Optional

from . import doc_blocks
from .idl import compile_directory
from .manifest import Generator, Manifest, generated_folder, read

# Groups the command line accepts besides generator names.
GROUPS = {
    "idl": lambda g: g.emitter is not None and g.input == "idl",  # the code and docs made from interfaces/idl
    "sources": lambda g: g.needs is None,                         # everything that needs nothing built first
}


class GenerateError(Exception):
    """The generators and the manifest disagree, or a generator failed; one line per problem."""

    def __init__(self, problems: list[str]):
        self.problems = problems
        super().__init__("\n".join(problems))


def select(manifest: Manifest, only: Optional[Iterable[str]] = None) -> list[Generator]:
    """The generators named (or in the groups named) by `only`, in manifest order; all when None."""
    if only is None:
        return list(manifest.generators)
    wanted = set(only)
    known = {g.name for g in manifest.generators} | set(GROUPS)
    unknown = sorted(wanted - known)
    if unknown:
        raise GenerateError([f"unknown generator or group {u!r} (known: {', '.join(sorted(known))})" for u in unknown])
    return [g for g in manifest.generators
            if g.name in wanted or any(GROUPS[w](g) for w in wanted if w in GROUPS)]


class _Run:
    def __init__(self, root: Path, fab: Path):
        self.root, self.fab, self._idl = root, fab, None

    @property
    def idl(self):
        if self._idl is None:
            self._idl = compile_directory(self.root / "interfaces" / "idl",
                                          self.root / "interfaces" / "idl" / "idl.schema.json", root=self.root)
        return self._idl

    def produce(self, g: Generator) -> dict[str, str]:
        """{name: text}: file names relative to `into`, or block names."""
        if g.emitter:
            module, function = g.emitter.split(":")
            emit = getattr(importlib.import_module(f"robogene_codegen.emitters.{module}"), function)
            return emit(self.idl if g.input == "idl" else self.root)
        with tempfile.TemporaryDirectory(prefix=f"generate-{g.name}-") as out:
            words = {"{python}": sys.executable, "{out}": out, "{fab}": str(self.fab)}
            argv = []
            for word in g.command:
                for placeholder, value in words.items():
                    word = word.replace(placeholder, value)
                argv.append(word)
            result = subprocess.run(argv, cwd=self.root, capture_output=True, text=True)
            if result.returncode != 0:
                shown = " ".join(g.command)
                needs = f"; it needs `make {g.needs}` first" if g.needs else ""
                raise GenerateError([f"{g.name}: `{shown}` failed (exit {result.returncode}{needs}):\n" +
                                     (result.stderr or result.stdout).rstrip()])
            base = Path(out)
            # Bytes decoded as they are: no newline translation, so what is compared is what was written.
            return {p.relative_to(base).as_posix(): p.read_bytes().decode("utf-8")
                    for p in sorted(base.rglob("*")) if p.is_file()}


def _agree(g: Generator, produced: set[str], listed: list[str], what: str) -> list[str]:
    where = f"{g.into}/" if g.into else ""
    problems = [f"{g.name} writes {what} {where}{n}, which the manifest does not list under it: add it to "
                f"codegen/generated-manifest.yaml" for n in sorted(produced - set(listed))]
    problems += [f"the manifest lists {what} {where}{n} under {g.name}, which no longer writes it: remove it "
                 f"from codegen/generated-manifest.yaml" for n in sorted(set(listed) - produced)]
    return problems


def render(root: Path, only: Optional[Iterable[str]] = None, fab: Optional[Path] = None,
           manifest: Optional[Manifest] = None) -> dict[str, str]:
    """{path: text} of every file the selected generators own: whole generated files, and the
    hand-written documents with their generated blocks filled in. Raises GenerateError (or IdlErrors)."""
    manifest = manifest or read(root)
    run = _Run(root, fab or root / "build" / "fab")
    files: dict[str, str] = {}
    documents: dict[str, str] = {}
    problems: list[str] = []
    for g in select(manifest, only):
        try:
            produced = run.produce(g)
        except (ValueError, LookupError, OSError) as exc:  # a bad input file (SVD, IDL lookup), bad bytes
            problems.append(f"{g.name}: {exc}")
            continue
        if g.into:
            problems += _agree(g, set(produced), list(g.files), "file")
            files.update((f"{g.into}/{name}", produced[name]) for name in g.files if name in produced)
            continue
        for document, names in g.blocks:
            problems += _agree(g, set(produced), list(names), f"block of {document}:")
            if document not in documents:
                try:
                    documents[document] = (root / document).read_bytes().decode("utf-8")
                except (OSError, UnicodeDecodeError) as exc:
                    problems.append(f"{g.name}: cannot read {document} ({getattr(exc, 'strerror', None) or exc})")
                    continue
            try:
                documents[document] = doc_blocks.replace(
                    documents[document], {n: produced[n] for n in names if n in produced}, g.name, document)
            except ValueError as exc:
                problems.append(str(exc))
    if problems:
        raise GenerateError(problems)
    return dict(sorted({**files, **documents}.items()))


def _unlisted(root: Path, manifest: Manifest, only: Optional[Iterable[str]]) -> list[str]:
    """Files in the generated folders of the selected generators that the manifest does not list."""
    listed = set(manifest.files)
    folders = {generated_folder(g.into) for g in select(manifest, only) if g.into} - {None}
    found = []
    for folder in sorted(folders):
        for p in sorted((root / folder).rglob("*")):
            if p.is_file() and "__pycache__" not in p.parts:
                rel = p.relative_to(root).as_posix()
                if rel not in listed:
                    found.append(rel)
    return found


def stale(root: Path, outputs: dict[str, str], only: Optional[Iterable[str]] = None,
          manifest: Optional[Manifest] = None) -> list[str]:
    """One line per file that `generate` would change, naming the file and why."""
    manifest = manifest or read(root)
    problems = []
    for path, text in outputs.items():
        target = root / path
        if not target.exists():
            problems.append(f"{path}: missing")
        elif target.read_bytes() != text.encode("utf-8"):
            problems.append(f"{path}: differs from what its generator writes")
    for path in _unlisted(root, manifest, only):
        problems.append(f"{path}: in a generated folder but not in the manifest (no generator writes it)")
    return problems


def write(root: Path, outputs: dict[str, str], only: Optional[Iterable[str]] = None,
          manifest: Optional[Manifest] = None) -> list[str]:
    """Writes what changed and removes unlisted files from the generated folders; returns what it touched."""
    manifest = manifest or read(root)
    touched = []
    for path, text in outputs.items():
        target = root / path
        data = text.encode("utf-8")
        if not target.exists() or target.read_bytes() != data:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data)
            touched.append(path)
    for path in _unlisted(root, manifest, only):
        (root / path).unlink()
        touched.append(f"{path} (removed)")
    return touched
