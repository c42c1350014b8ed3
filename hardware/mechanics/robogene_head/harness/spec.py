# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The `harness:` section of the parameter file, validated: cable classes, clamps, cables and camera cables.
A wrong entry gets a ParameterError naming its key path."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import kinematics

# Diameter of the smallest circle around n equal round wires, in wire diameters (circle packing): the outer
# diameter of a twisted group of n wires.
GROUP_FACTOR = {1: 1.0, 2: 2.0, 3: 2.155, 4: 2.414, 5: 2.701, 6: 3.0, 7: 3.0}
HOST = "host"


@dataclass(frozen=True)
class CableClass:
    name: str
    shape: str                 # round / flat
    bend_factor: float
    wire_od: float = 0.0       # round
    awg: int = 0
    twist_deg_per_m: float = 0.0
    width: float = 0.0         # flat
    thickness: float = 0.0
    edge_strain: float = 0.0
    inplane_factor: float = 0.0
    wire: str = ""             # catalog key of the wire (round classes)
    laid: str = "loose"        # round: loose parallel wires (each its own od) or twisted (the group's od)

    def od(self, wires: int) -> float:
        """Outer diameter of a round cable of `wires` wires (a flat cable: its thickness)."""
        if self.shape == "flat":
            return self.thickness
        if self.laid == "loose":
            return self.wire_od
        if wires not in GROUP_FACTOR:
            raise ValueError(f"class {self.name}: no group diameter for {wires} wires")
        return self.wire_od * GROUP_FACTOR[wires]

    def min_bend_radius(self, wires: int) -> float:
        return self.bend_factor * self.od(wires)


@dataclass(frozen=True)
class Clamp:
    name: str
    link: str
    at: np.ndarray
    dir: np.ndarray
    up: np.ndarray
    slack: float | None = None   # for the free spans that end here, instead of harness.free_slack


@dataclass(frozen=True)
class Cable:
    name: str
    cls: CableClass
    board: str
    ref: str
    to: str | tuple[str, str]    # a part name, HOST, or (board, ref)
    via: tuple[str, ...]


@dataclass(frozen=True)
class CameraCable:
    name: str
    camera: str                  # the camera part it starts at
    via: tuple[str, ...]


@dataclass(frozen=True)
class HarnessSpec:
    free_slack: float
    routed_factor: float
    service_loop: float
    sweep_samples: int
    host_lead: float
    classes: dict[str, CableClass]
    mating: dict[str, tuple[str, str]]     # header MPN -> (housing, contact) catalog keys
    clamps: dict[str, Clamp]
    cables: tuple[Cable, ...]
    camera_class: CableClass
    camera_lengths: dict[float, str]      # catalogue length (mm) -> catalog key
    camera_cables: tuple[CameraCable, ...]


def _unit(node: Node, key: str) -> np.ndarray:
    v = np.array(node.vec(key), dtype=float)
    n = float(np.linalg.norm(v))
    if n < 1e-9:
        raise node.fail(key, "must not be the zero vector")
    return v / n


def _class(name: str, node: Node) -> CableClass:
    shape = node.text("shape")
    if shape == "round":
        return CableClass(name, shape, node.num("bend_factor", positive=True), wire_od=node.num("wire_od", positive=True),
                          awg=int(node.num("awg", positive=True)), twist_deg_per_m=node.num("twist_deg_per_m", minimum=0),
                          wire=node.text("wire"), laid=_laid(node))
    if shape == "flat":
        return CableClass(name, shape, node.num("bend_factor", positive=True), width=node.num("width", positive=True),
                          thickness=node.num("thickness", positive=True), edge_strain=node.num("edge_strain", positive=True),
                          inplane_factor=node.num("inplane_factor", positive=True))
    raise node.fail("shape", f"expected round or flat, got {shape!r}")


def _laid(node: Node) -> str:
    laid = node.text("laid")
    if laid not in ("loose", "twisted"):
        raise node.fail("laid", f"expected loose or twisted, got {laid!r}")
    return laid


def _names(node: Node, key: str, known: dict) -> tuple[str, ...]:
    value = node.raw(key) if node.has(key) else []
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise node.fail(key, "expected a list of clamp names")
    for v in value:
        if v not in known:
            raise node.fail(key, f"{v!r} is not a clamp under harness.clamps")
    return tuple(value)


def _board_ref(node: Node, key: str, boards: list[str]) -> tuple[str, str]:
    value = node.raw(key)
    if not (isinstance(value, list) and len(value) == 2 and all(isinstance(v, str) for v in value)):
        raise node.fail(key, f"expected [board name, connector reference], got {value!r}")
    if value[0] not in boards:
        raise node.fail(key, f"{value[0]!r} is not one of boards.names ({', '.join(boards)})")
    return value[0], value[1]


def load(params: HeadParameters) -> HarnessSpec:
    h = params.root.node("harness")
    links = set(kinematics.links(params))
    boards = list(params.root.node("boards").raw("names"))
    classes = {k: _class(k, h.node("classes").node(k)) for k in h.node("classes").keys()}
    mating = {}
    for mpn in h.node("mating").keys():
        m = h.node("mating").node(mpn)
        mating[mpn] = (m.text("housing"), m.text("contact"))
    clamps = {}
    for name in h.node("clamps").keys():
        c = h.node("clamps").node(name)
        if c.text("link") not in links:
            raise c.fail("link", f"{c.text('link')!r} is not a link ({', '.join(sorted(links))})")
        d, up = _unit(c, "dir"), _unit(c, "up")
        if abs(float(np.dot(d, up))) > 0.999:
            raise c.fail("up", "must not be parallel to dir")
        slack = c.num("slack", minimum=0) if c.has("slack") else None
        clamps[name] = Clamp(name, c.text("link"), np.array(c.vec("at"), dtype=float), d, up, slack)
    cables = []
    listed = h.raw("cables")
    if not isinstance(listed, list) or not listed:
        raise ParameterError(f"{params.path}: harness.cables: expected a list of cables")
    for i, entry in enumerate(listed):
        c = Node(entry, f"harness.cables[{i}]", str(params.path))
        if c.text("class") not in classes:
            raise c.fail("class", f"{c.text('class')!r} is not under harness.classes")
        board, ref = _board_ref(c, "from", boards)
        to = c.raw("to")
        to = _board_ref(c, "to", boards) if isinstance(to, list) else c.text("to")
        cables.append(Cable(c.text("name"), classes[c.text("class")], board, ref, to, _names(c, "via", clamps)))
    names = [c.name for c in cables]
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise ParameterError(f"{params.path}: harness.cables: duplicate name(s) {', '.join(dupes)}")
    cam = h.node("camera_cables")
    lengths = cam.raw("lengths")
    if (not isinstance(lengths, dict) or not lengths or
            not all(isinstance(k, str) and isinstance(v, (int, float)) and not isinstance(v, bool) and v > 0
                    for k, v in lengths.items())):
        raise cam.fail("lengths", "expected a mapping of catalog keys to their positive lengths (mm)")
    camera_class = next((c for c in classes.values() if c.shape == "flat"), None)
    if camera_class is None:
        raise h.fail("classes", "the camera cables need a flat class")
    cams = []
    for i, entry in enumerate(cam.raw("routes")):
        c = Node(entry, f"harness.camera_cables.routes[{i}]", str(params.path))
        cams.append(CameraCable(c.text("name"), c.text("from"), _names(c, "via", clamps)))
    samples = int(h.num("sweep_samples", minimum=2))
    return HarnessSpec(h.num("free_slack", minimum=0), h.num("routed_factor", minimum=1), h.num("service_loop", minimum=0),
                       samples, h.num("host_lead", minimum=0), classes, mating, clamps, tuple(cables), camera_class,
                       {float(mm): key for key, mm in sorted(lengths.items(), key=lambda kv: kv[1])}, tuple(cams))
