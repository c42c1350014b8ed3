# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Load hardware/mechanics/assembly-sequence.yaml: the order a lab builds the head in, as data.

Each step names the parts it adds (or a subassembly built before), the path they travel from outside to their
place, the parts they may touch on the way (fits and guides), and the screws that fix them with the driver
that turns them. checks/assembly_sequence.py proves every step possible; render_steps.py draws them.
A wrong file gets a SequenceError naming the step and the key."""
from __future__ import annotations

import fnmatch
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import yaml

from robogene_head_model import strict_yaml

DEFAULT_PATH = Path(__file__).resolve().parents[1] / "assembly-sequence.yaml"
PRESS_RINGS = ("inner", "outer")
STEP_KEYS = {"name", "parts", "subassembly", "from", "fits", "fasteners", "driver", "press", "flexible", "access",
             "fixture", "why"}


class SequenceError(ValueError):
    """A problem with the sequence file: the message names the file, the step and the key."""


@dataclass(frozen=True)
class Driver:
    name: str
    blade: float          # diameter of the blade (hex key, pliers' jaws) from the screw head outwards
    length: float         # blade length
    handle: float         # diameter of the handle beyond the blade


@dataclass
class Step:
    context: str                  # "main" or the subassembly being built
    number: int                   # 1-based within its context
    name: str
    parts: list[str]              # what this step moves into place (a subassembly: all its parts)
    path: list[np.ndarray]        # offsets from the final place, world mm: the start, waypoints, ending at 0
    fits: list[str] = field(default_factory=list)        # patterns of parts it may touch on its way
    fasteners: list[str] = field(default_factory=list)   # screws put in after the parts are in place
    driver: str | None = None     # the fasteners' driver, when not the catalogue default
    press: bool = False           # pressed in: straight along its axis, with an arbor (a pin) or a tool on one ring
    press_ring: str = ""          # a bearing's ring the tool bears on: "inner" (a sleeve, onto a journal) or "outer"
    flexible: str = ""            # placed by hand, not swept (belts, circlips): why
    access: tuple[str, np.ndarray] | None = None   # flexible part: a tool (driver name) along this axis
    straddles: list[str] = field(default_factory=list)   # parts the tool goes round (an external ring's shaft)
    fixture: bool = False         # the first part of a context: it is held, not moved
    subassembly: str = ""
    why: str = ""

    @property
    def label(self) -> str:
        where = "" if self.context == "main" else f"{self.context} "
        return f"{where}step {self.number} '{self.name}'"

    def picture(self, index: int) -> str:
        """The file name of its picture (assembly/steps/), `index` its 1-based place in the whole sequence."""
        return f"{index:02d}-{self.context}-{self.number:02d}.png"


@dataclass
class Sequence:
    path: Path
    drivers: dict[str, Driver]
    screw_drivers: dict[str, str]   # catalogue key prefix (iso7380-M3) -> driver
    contexts: dict[str, list[Step]]  # subassemblies in order of definition, then "main"
    owner: dict[str, str]           # part name -> the context that places it

    def steps(self) -> list[Step]:
        return [s for steps in self.contexts.values() for s in steps]

    def driver_for(self, screw_key: str, override: str | None) -> Driver:
        if override:
            return self.drivers[override]
        for prefix, name in self.screw_drivers.items():
            if screw_key.startswith(prefix):
                return self.drivers[name]
        raise SequenceError(f"{self.path}: screw_drivers: no driver for {screw_key}")


def _vec(value, where: str) -> np.ndarray:
    if (not isinstance(value, list) or len(value) != 3
            or any(isinstance(v, bool) or not isinstance(v, (int, float)) for v in value)):
        raise SequenceError(f"{where}: expected [x, y, z] in mm, got {value!r}")
    return np.array(value, dtype=float)


def _names(patterns, where: str, names: list[str]) -> list[str]:
    if isinstance(patterns, str):
        patterns = [patterns]
    if not isinstance(patterns, list) or not all(isinstance(p, str) for p in patterns):
        raise SequenceError(f"{where}: expected a list of part names or patterns, got {patterns!r}")
    out = []
    for p in patterns:
        hits = [n for n in names if fnmatch.fnmatchcase(n, p)]
        if not hits:
            raise SequenceError(f"{where}: {p!r} matches no part of the assembly")
        out += [h for h in hits if h not in out]
    return out


def load(part_names: list[str], path: Path | str | None = None) -> Sequence:
    path = Path(path) if path else DEFAULT_PATH
    try:
        data = strict_yaml.load(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise SequenceError(f"{path}: cannot read: {exc.strerror}") from None
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        raise SequenceError(f"{path}:{mark.line + 1 if mark else '?'}: YAML error: {exc.problem}") from None
    if not isinstance(data, dict):
        raise SequenceError(f"{path}: top level must be a mapping")
    return parse(data, path, part_names)


def parse(data: dict, path: Path, part_names: list[str]) -> Sequence:
    drivers = {}
    for name, d in (data.get("drivers") or {}).items():
        where = f"{path}: drivers.{name}"
        if not isinstance(d, dict) or not all(isinstance(d.get(k), (int, float)) and d.get(k) > 0
                                              for k in ("blade", "length", "handle")):
            raise SequenceError(f"{where}: expected positive blade, length and handle (mm), got {d!r}")
        drivers[name] = Driver(name, float(d["blade"]), float(d["length"]), float(d["handle"]))
    screw_drivers = data.get("screw_drivers") or {}
    for key, name in screw_drivers.items():
        if name not in drivers:
            raise SequenceError(f"{path}: screw_drivers.{key}: no driver {name!r} under drivers")
    subs = data.get("subassemblies") or {}
    main = data.get("sequence")
    if not isinstance(subs, dict) or not isinstance(main, list) or not main:
        raise SequenceError(f"{path}: expected `subassemblies:` (a mapping) and `sequence:` (a list of steps)")
    contexts: dict[str, list[Step]] = {}
    owner: dict[str, str] = {}
    content: dict[str, list[str]] = {}   # context -> every part it places
    for context, raw_steps in list(subs.items()) + [("main", main)]:
        if not isinstance(raw_steps, list) or not raw_steps:
            raise SequenceError(f"{path}: subassemblies.{context}: expected a list of steps")
        steps = []
        for i, raw in enumerate(raw_steps):
            where = f"{path}: {'sequence' if context == 'main' else 'subassemblies.' + context}[{i}]"
            step = _step(raw, where, context, i + 1, part_names, drivers, content)
            where = f"{path}: {step.label}"
            for name in step.parts if not step.subassembly else []:
                if name in owner:
                    raise SequenceError(f"{where}: {name} is already placed by {owner[name]}")
                owner[name] = context
            for name in step.fasteners:
                if name in owner:
                    raise SequenceError(f"{where}: fastener {name} is already placed by {owner[name]}")
                owner[name] = context
            if step.fixture and i > 0:
                raise SequenceError(f"{where}: only the first step of a subassembly or the sequence is a fixture")
            if not step.fixture and not step.flexible and not step.subassembly and not step.parts and not step.fasteners:
                raise SequenceError(f"{where}: places nothing")
            steps.append(step)
            content.setdefault(context, []).extend(step.parts + step.fasteners)
        contexts[context] = steps
    used = [s.subassembly for steps in contexts.values() for s in steps if s.subassembly]
    for name in subs:
        if used.count(name) != 1:
            raise SequenceError(f"{path}: subassemblies.{name}: inserted {used.count(name)} times (expected once)")
    missing = [n for n in part_names if n not in owner]
    if missing:
        raise SequenceError(f"{path}: {len(missing)} parts of the assembly are in no step: {', '.join(missing)}")
    return Sequence(path, drivers, screw_drivers, contexts, owner)


def _step(raw, where: str, context: str, number: int, names: list[str], drivers: dict, content: dict) -> Step:
    if not isinstance(raw, dict):
        raise SequenceError(f"{where}: expected a mapping")
    unknown = set(raw) - STEP_KEYS
    if unknown:
        raise SequenceError(f"{where}: unknown key {sorted(unknown)[0]!r} (known: {', '.join(sorted(STEP_KEYS))})")
    name = raw.get("name")
    if not isinstance(name, str) or not name:
        raise SequenceError(f"{where}.name: expected a description of the step")
    where = f"{where} '{name}'"
    sub = raw.get("subassembly", "")
    if sub:
        if sub not in content:
            raise SequenceError(f"{where}.subassembly: {sub!r} is not defined above")
        parts = list(content[sub])
    else:
        parts = _names(raw.get("parts", []), f"{where}.parts", names) if "parts" in raw else []
    fixture = bool(raw.get("fixture", False))
    flexible = raw.get("flexible", "")
    if flexible and not isinstance(flexible, str):
        raise SequenceError(f"{where}.flexible: expected the reason it is placed by hand")
    path = [np.zeros(3)]
    if "from" in raw:
        if fixture or flexible:
            raise SequenceError(f"{where}.from: a fixture or a flexible part has no path")
        points = raw["from"]
        if not isinstance(points, list) or not points:
            raise SequenceError(f"{where}.from: expected a list of [x, y, z] offsets from the final place")
        path = [_vec(p, f"{where}.from[{k}]") for k, p in enumerate(points)] + [np.zeros(3)]
        if np.linalg.norm(path[0]) == 0:
            raise SequenceError(f"{where}.from[0]: the start must be away from the final place")
    elif parts and not fixture and not flexible:
        raise SequenceError(f"{where}: moves {parts[0]}... but has no `from` path (or say fixture / flexible)")
    driver = raw.get("driver")
    if driver is not None and driver not in drivers:
        raise SequenceError(f"{where}.driver: no driver {driver!r} under drivers")
    access = None
    if "access" in raw:
        a = raw["access"]
        if not isinstance(a, dict) or a.get("driver") not in drivers:
            raise SequenceError(f"{where}.access: expected {{driver: <a driver>, along: [x, y, z]}}")
        along = _vec(a.get("along"), f"{where}.access.along")
        access = (a["driver"], along / np.linalg.norm(along))
    straddles = _names(raw["access"].get("straddles", []), f"{where}.access.straddles", names) \
        if access and raw["access"].get("straddles") else []
    press, press_ring = _press(raw.get("press"), where)
    step = Step(context, number, name, parts, path,
                fits=_names(raw.get("fits", []), f"{where}.fits", names) if raw.get("fits") else [],
                fasteners=_names(raw.get("fasteners", []), f"{where}.fasteners", names) if raw.get("fasteners") else [],
                driver=driver, press=press, press_ring=press_ring, flexible=flexible, access=access, straddles=straddles,
                fixture=fixture, subassembly=sub, why=str(raw.get("why", "")))
    if step.press and (len(step.parts) != 1 or len(step.path) != 2):
        raise SequenceError(f"{where}.press: a pressed step moves one bearing along one straight line")
    return step


def _press(value, where: str) -> tuple[bool, str]:
    """`press: true` (a pin, an arbor behind it) or `press: inner` / `press: outer` (the bearing's ring the tool bears
    on)."""
    if value in (None, False):
        return False, ""
    if value is True:
        return True, ""
    if value in PRESS_RINGS:
        return True, value
    raise SequenceError(f"{where}.press: expected true (a pin) or the bearing's ring the tool bears on "
                        f"({' or '.join(PRESS_RINGS)}), got {value!r}")
