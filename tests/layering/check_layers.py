# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that the runtime is layered one way (docs/architecture.md).

The layers and their order come from runtime/layers.cmake; the target graph and each target's
include path come from CMake itself (its file API, from a configure into a scratch folder), so
what is checked is what the build does. Three checks, each problem printed as `path:line: what`:

- the target graph: a layer links only layers below it; no runtime layer links the drivers, an
  app or a test; nothing links an app (the CLI, the examples);
- the include path: a layer's compiler sees its own include folder and those of lower layers only;
- the sources: no file of a layer (src/ or include/) includes a header of a higher layer or reaches
  with a relative path into another folder's private headers; every public header folder has a
  source folder of the same name and the other way round (the include tree mirrors src/).

    python3 tests/layering/check_layers.py [--tree DIR]

--tree scans the sources of another copy of the repository (the tests plant a bad include in one).
Exit status 0 when layered, 1 with the problems listed, 2 when CMake cannot be run.
"""
from __future__ import annotations

import argparse
import json
import re
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
# Targets nothing may link: the apps. Their names are the executables runtime/apps builds.
APP_FOLDER = "runtime/apps"


@dataclass
class Layer:
    name: str          # "carriers"
    root: str          # "runtime/carriers", relative to the repository
    rank: int          # 0 = lowest
    links: list[str]   # the layer names given in layers.cmake
    includes: list[str] = field(default_factory=list)  # from CMake, relative to the repository

    @property
    def target(self) -> str:
        return f"robogene_{self.name}"


def read_layers(root: Path) -> list[Layer]:
    """The layers listed in runtime/layers.cmake, lowest first."""
    text = (root / "runtime/layers.cmake").read_text()
    block = re.search(r"set\(ROBOGENE_LAYERS(.*?)\)", text, re.S)
    if not block:
        raise SystemExit("runtime/layers.cmake: no set(ROBOGENE_LAYERS ...)")
    layers = []
    for entry in re.findall(r'"([^"]+)"', block.group(1)):
        name, folder, *links = entry.split()
        root_rel = "runtime" if folder == "." else f"runtime/{folder}"
        layers.append(Layer(name, root_rel, len(layers), links))
    return layers


def configure(source: Path, build: Path) -> Path:
    """Configures `source` into `build` with a file-API query; returns the reply folder."""
    query = build / ".cmake/api/v1/query/codemodel-v2"
    query.parent.mkdir(parents=True, exist_ok=True)
    query.touch()
    cmd = ["cmake", "-S", str(source), "-B", str(build), "-G", "Ninja", "-DROBOGENE_BENCH=OFF"]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        print(f"cmake could not configure {source}:\n{done.stdout}{done.stderr}", file=sys.stderr)
        raise SystemExit(2)
    return build / ".cmake/api/v1/reply"


def read_targets(reply: Path) -> dict[str, dict]:
    """Every target of the configured project by name, with its dependencies' names."""
    index = json.loads(max(reply.glob("index-*.json")).read_text())
    model_file = next(o["jsonFile"] for o in index["objects"] if o["kind"] == "codemodel")
    model = json.loads((reply / model_file).read_text())
    config = model["configurations"][0]
    targets = {t["id"]: json.loads((reply / t["jsonFile"]).read_text()) for t in config["targets"]}
    by_name = {}
    for t in targets.values():
        t["depends_on"] = sorted(targets[d["id"]]["name"] for d in t.get("dependencies", []))
        by_name[t["name"]] = t
    return by_name


def relative(path: str, source: Path) -> str:
    p = Path(path)
    try:
        return p.resolve().relative_to(source.resolve()).as_posix()
    except ValueError:
        return p.as_posix()


def check_graph(layers: list[Layer], targets: dict[str, dict], source: Path) -> list[str]:
    problems = []
    by_target = {layer.target: layer for layer in layers}
    for layer in layers:
        t = targets.get(layer.target)
        if t is None:
            problems.append(f"runtime/layers.cmake: no CMake target {layer.target}")
            continue
        for dep in t["depends_on"]:
            lower = by_target.get(dep)
            if lower is None:
                problems.append(f"{layer.root}: {layer.target} links {dep}, which is not a runtime layer "
                                f"(drivers, apps and tests sit above the runtime)")
            elif lower.rank >= layer.rank:
                problems.append(f"{layer.root}: {layer.target} links {dep}, a layer that is not below it "
                                f"(runtime/layers.cmake lists {layer.name} before {lower.name})")
        for group in t.get("compileGroups", []):
            for inc in group.get("includes", []):
                rel = relative(inc["path"], source)
                owner = next((lay for lay in layers if rel == f"{lay.root}/include"), None)
                if owner is not None and owner.rank > layer.rank:
                    problems.append(f"{layer.root}: {layer.target} compiles with {rel} on its include path, "
                                    f"the headers of the higher layer {owner.name}")
                elif owner is not None and rel not in layer.includes:
                    layer.includes.append(rel)
    apps = {name for name, t in targets.items()
            if any(relative(s["path"], source).startswith(APP_FOLDER + "/") for s in t.get("sources", []))}
    for name, t in sorted(targets.items()):
        for dep in t["depends_on"]:
            if dep in apps:
                problems.append(f"{APP_FOLDER}: {name} depends on the app {dep}; nothing may depend on an app")
    return problems


def layer_of(path: str, layers: list[Layer]) -> Layer | None:
    """The layer whose src/ or include/ holds `path` (relative to the repository)."""
    for layer in sorted(layers, key=lambda lay: -len(lay.root)):
        if path.startswith(f"{layer.root}/src/") or path.startswith(f"{layer.root}/include/"):
            return layer
    return None


def check_sources(layers: list[Layer], tree: Path) -> list[str]:
    problems = []
    public = {layer.name: f"{layer.root}/include" for layer in layers}
    for layer in layers:
        allowed = set(layer.includes) or {public[layer.name]}
        for folder in ("src", "include"):
            base = tree / layer.root / folder
            for file in sorted(base.rglob("*")):
                if file.suffix not in (".cpp", ".hpp", ".ipp", ".h") or not file.is_file():
                    continue
                rel = file.relative_to(tree).as_posix()
                if layer_of(rel, layers) is not layer:
                    continue  # a nested layer's file (the devices root holds the others' folders)
                for number, line in enumerate(file.read_text(errors="replace").splitlines(), 1):
                    m = INCLUDE.match(line)
                    if m:
                        problems += check_include(m.group(1), file, f"{rel}:{number}", layer, layers, allowed, tree)
    return problems


def check_include(name: str, file: Path, where: str, layer: Layer, layers: list[Layer], allowed: set[str],
                  tree: Path) -> list[str]:
    beside = (file.parent / name).resolve()
    if beside.is_file():
        # A private header: only from its own folder (or one below it), never into another's.
        if file.parent.resolve() in beside.parents:
            return []
        target = beside.relative_to(tree.resolve()).as_posix()
        return [f"{where}: includes {name} ({target}), a private header of another folder; "
                f"include a public header (robogene/...) of this layer or a lower one"]
    if any((tree / inc / name).is_file() for inc in allowed):
        return []
    for other in layers:
        if (tree / other.root / "include" / name).is_file():
            return [f"{where}: includes {name} of the layer {other.name}, which is not below {layer.name} "
                    f"(runtime/layers.cmake); the compiler does not see it"]
    return []  # a system or third-party header


def check_mirror(layers: list[Layer], tree: Path) -> list[str]:
    problems = []
    for layer in layers:
        inc = tree / layer.root / "include/robogene"
        src = tree / layer.root / "src"
        header_dirs = {h.parent.relative_to(inc).as_posix() for h in inc.rglob("*.hpp")
                       if layer_of(h.relative_to(tree).as_posix(), layers) is layer}
        source_dirs = {c.parent.relative_to(src).as_posix() for c in src.rglob("*.cpp")
                       if layer_of(c.relative_to(tree).as_posix(), layers) is layer}
        for d in sorted(header_dirs - source_dirs):
            problems.append(f"{layer.root}/include/robogene/{d}: public headers with no source folder "
                            f"{layer.root}/src/{d} (the include tree mirrors src/)")
        for d in sorted(source_dirs - header_dirs):
            problems.append(f"{layer.root}/src/{d}: sources with no public header folder "
                            f"{layer.root}/include/robogene/{d} (the include tree mirrors src/)")
    return problems


def check(tree: Path, source: Path = ROOT) -> list[str]:
    layers = read_layers(source)
    scratch = Path(tempfile.mkdtemp(prefix="robogene-layers-"))
    try:
        targets = read_targets(configure(source, scratch))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    problems = check_graph(layers, targets, source)
    problems += check_sources(layers, tree)
    problems += check_mirror(layers, tree)
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tree", type=Path, default=ROOT, help="the copy of the repository whose sources to scan")
    parser.add_argument("--source", type=Path, default=ROOT, help="the repository CMake configures")
    args = parser.parse_args(argv)
    problems = check(args.tree.resolve(), args.source.resolve())
    for p in problems:
        print(p)
    if problems:
        print(f"layering: {len(problems)} problem(s)", file=sys.stderr)
        return 1
    print("layering: one way")
    return 0


if __name__ == "__main__":
    sys.exit(main())
