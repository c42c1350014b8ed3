# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Current capacity of a net's copper between two groups of pads, read from a routed .kicad_pcb.

Every track is a conductor whose ampacity follows IPC-2221 for a given temperature rise,
    I = k * dT^0.44 * A^0.725   (A: cross-section in mil^2; k = 0.048 outer layers, 0.024 inner layers),
with the layer's copper thickness from the board's declared stackup (1 oz when the board declares none).
Every via is a barrel of its drill diameter plated VIA_PLATING_MM thick, rated as an inner conductor (its
barrel is buried in the laminate). The net's capacity between two parts is the maximum flow through that
network (tracks and via barrels in series and in parallel), so it is set by the narrowest track or the
fewest, smallest vias on the best route. Pads and filled zones count as ideal conductors: a pad is short
and carries its part's lead soldered on top (a track stub lying wholly on its own pad counts as pad), and
the zones here are whole-board planes and pours.
"""
from __future__ import annotations

import math
import sys
from collections import defaultdict, deque
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "generator"))
from sexpr import find, find1, parse  # noqa: E402

OZ1_MM = 0.035
VIA_PLATING_MM = 0.020   # IPC-6012 class 2: 20 um average barrel plating
K_OUTER, K_INNER = 0.048, 0.024
MIL = 0.0254             # mm
INF = float("inf")
GRID = 1e-4              # mm: coordinates closer than this are one node


class BoardReadError(ValueError):
    pass


def ipc2221_amps(width_mm, thickness_mm, outer, rise_c=20.0):
    area_mil2 = (width_mm / MIL) * (thickness_mm / MIL)
    return (K_OUTER if outer else K_INNER) * rise_c ** 0.44 * area_mil2 ** 0.725


def via_amps(drill_mm, rise_c=20.0, plating_mm=VIA_PLATING_MM):
    """A plated barrel: circumference of the finished hole times the plating, as an inner conductor."""
    return ipc2221_amps(math.pi * (drill_mm + plating_mm), plating_mm, outer=False, rise_c=rise_c)


@dataclass
class Pad:
    ref: str
    number: str
    x: float
    y: float
    w: float
    h: float
    angle: float
    layers: tuple
    net: str

    def contains(self, x, y, layer, slack=0.0):
        if layer not in self.layers:
            return False
        a = math.radians(self.angle)
        dx, dy = x - self.x, y - self.y
        u = dx * math.cos(a) - dy * math.sin(a)
        v = dx * math.sin(a) + dy * math.cos(a)
        return abs(u) <= self.w / 2 + slack and abs(v) <= self.h / 2 + slack


@dataclass
class Board:
    copper: dict            # layer -> thickness mm, in stack order
    declared_stackup: bool
    segments: list          # (net, layer, (x0, y0), (x1, y1), width)
    vias: list              # (net, (x, y), drill, (layers...))
    pads: list              # [Pad]
    zones: list             # (net, layer, [(x, y)...]) filled polygons
    nets: set


def _num(node, key, default=None):
    item = find1(node, key)
    return item[1] if item else default


def read_board(path):
    path = Path(path)
    try:
        root = parse(path.read_text(encoding="utf-8"), str(path))
    except OSError as exc:
        raise BoardReadError(f"{path}: cannot read: {exc.strerror}") from None
    if not root or root[0] != "kicad_pcb":
        raise BoardReadError(f"{path}: not a KiCad board file")
    names = {n[1]: n[2] for n in find(root, "net") if len(n) > 2}
    layers = [l[1] for l in find1(root, "layers")[1:] if isinstance(l, list) and str(l[1]).endswith(".Cu")]
    copper, declared = {l: OZ1_MM for l in layers}, False
    setup = find1(root, "setup")
    stackup = find1(setup, "stackup") if setup else None
    if stackup:
        for layer in find(stackup, "layer"):
            if _num(layer, "type") == "copper":
                t = _num(layer, "thickness")
                if t is None:
                    raise BoardReadError(f"{path}: stackup layer {layer[1]} has no thickness")
                copper[layer[1]] = float(t)
                declared = True

    def net_of(node):
        n = find1(node, "net")
        if not n:
            return None
        return n[2] if len(n) > 2 else names.get(n[1])

    segments = []
    for kind in ("segment", "arc"):
        for s in find(root, kind):
            start, end = find1(s, "start"), find1(s, "end")
            segments.append((net_of(s), _num(s, "layer"), (start[1], start[2]), (end[1], end[2]),
                             float(_num(s, "width"))))
    vias = []
    for v in find(root, "via"):
        at = find1(v, "at")
        span = [l for l in find1(v, "layers")[1:]]
        vias.append((net_of(v), (at[1], at[2]), float(_num(v, "drill")), tuple(span)))
    pads = []
    for fp in find(root, "footprint"):
        at = find1(fp, "at")
        fx, fy, frot = at[1], at[2], (at[3] if len(at) > 3 else 0)
        ref = next((p[2] for p in find(fp, "property") if p[1] == "Reference"), "?")
        for pad in find(fp, "pad"):
            pat, size = find1(pad, "at"), find1(pad, "size")
            a = math.radians(frot)
            px = fx + pat[1] * math.cos(a) + pat[2] * math.sin(a)
            py = fy - pat[1] * math.sin(a) + pat[2] * math.cos(a)
            pad_layers = tuple(find1(pad, "layers")[1:])
            if "*.Cu" in pad_layers:
                pad_layers = tuple(layers)
            pads.append(Pad(ref, str(pad[1]), px, py, size[1], size[2], pat[3] if len(pat) > 3 else 0,
                            tuple(l for l in pad_layers if l in copper), net_of(pad)))
    zones = []
    for z in find(root, "zone"):
        net = _num(z, "net_name")
        for fill in find(z, "filled_polygon"):
            pts = [(p[1], p[2]) for p in find1(fill, "pts")[1:] if p[0] == "xy"]
            zones.append((net, _num(fill, "layer"), pts))
    return Board(copper, declared, segments, vias, pads, zones, set(names.values()))


def _inside(poly, x, y):
    hit = False
    for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            hit = not hit
    return hit


def _key(layer, x, y):
    return (layer, round(x / GRID), round(y / GRID))


def _on_segment(p, a, b, tol):
    (px, py), (ax, ay), (bx, by) = p, a, b
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / length2))
    return math.hypot(px - (ax + t * dx), py - (ay + t * dy)) <= tol, t


class Network:
    """The net's copper as an undirected graph with a capacity (A) on every edge."""

    def __init__(self, board: Board, net: str, rise_c=20.0):
        self.cap = defaultdict(lambda: defaultdict(float))
        self.board, self.net = board, net
        outer = {next(iter(board.copper)), list(board.copper)[-1]}
        segs = [s for s in board.segments if s[0] == net]
        vias = [v for v in board.vias if v[0] == net]
        pads = [p for p in board.pads if p.net == net]
        zones = [z for z in board.zones if z[0] == net]
        points = defaultdict(list)   # layer -> connection points lying on that layer's copper
        for _, layer, a, b, _ in segs:
            points[layer] += [a, b]
        for _, at, _, span in vias:
            for layer in self._via_layers(span):
                points[layer].append(at)
        for _, layer, a, b, width in segs:
            amps = ipc2221_amps(width, board.copper[layer], layer in outer, rise_c)
            if any(p.contains(*a, layer) and p.contains(*b, layer) for p in pads):
                amps = INF   # a stub lying wholly on its own net's pad: the pad's copper carries the current
            # split the track wherever another track or a via meets it part-way (a T junction)
            stops = sorted({t for p in points[layer] for on, t in [_on_segment(p, a, b, width / 2)] if on} | {0.0, 1.0})
            nodes = [_key(layer, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])) for t in stops]
            for n0, n1 in zip(nodes, nodes[1:]):
                self._edge(n0, n1, amps)
            for p in points[layer]:
                on, t = _on_segment(p, a, b, width / 2)
                if on:
                    self._edge(_key(layer, *p), _key(layer, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])), INF)
        for i, (_, at, drill, span) in enumerate(vias):
            stack = self._via_layers(span)
            barrel = via_amps(drill, rise_c)
            for l0, l1 in zip(stack, stack[1:]):
                self._edge(_key(l0, *at), _key(l1, *at), barrel)
        for pad in pads:
            node = ("pad", pad.ref, pad.number)
            for layer in pad.layers:
                for p in points[layer]:
                    if pad.contains(*p, layer, slack=GRID):
                        self._edge(node, _key(layer, *p), INF)
        for i, (_, layer, poly) in enumerate(zones):
            node = ("zone", i)
            for p in points[layer]:
                if _inside(poly, *p):
                    self._edge(node, _key(layer, *p), INF)
            for pad in pads:
                if layer in pad.layers and _inside(poly, pad.x, pad.y):
                    self._edge(node, ("pad", pad.ref, pad.number), INF)

    def _via_layers(self, span):
        order = list(self.board.copper)
        lo, hi = order.index(span[0]), order.index(span[-1])
        return order[min(lo, hi):max(lo, hi) + 1]

    def _edge(self, a, b, amps):
        if a != b:
            self.cap[a][b] += amps
            self.cap[b][a] += amps

    def pads_of(self, ref):
        return [("pad", p.ref, p.number) for p in self.board.pads if p.net == self.net and p.ref == ref]

    def capacity(self, from_ref, to_ref):
        """Maximum current (A) the copper carries from one part's pads on the net to another's."""
        src, dst = self.pads_of(from_ref), self.pads_of(to_ref)
        if not src or not dst:
            missing = from_ref if not src else to_ref
            raise BoardReadError(f"net {self.net}: {missing} has no pad on it")
        cap = {a: dict(b) for a, b in self.cap.items()}
        for p in src:
            cap.setdefault("S", {})[p] = INF
            cap.setdefault(p, {}).setdefault("S", 0.0)
        for p in dst:
            cap.setdefault(p, {})["T"] = INF
            cap.setdefault("T", {}).setdefault(p, 0.0)
        return _max_flow(cap, "S", "T")


def _max_flow(cap, s, t):
    """Edmonds-Karp on a residual-capacity dict of dicts (modified in place)."""
    total = 0.0
    while True:
        parent = {s: None}
        queue = deque([s])
        while queue and t not in parent:
            u = queue.popleft()
            for v, c in cap.get(u, {}).items():
                if c > 1e-9 and v not in parent:
                    parent[v] = u
                    queue.append(v)
        if t not in parent:
            return total
        path, v = [], t
        while parent[v] is not None:
            path.append((parent[v], v))
            v = parent[v]
        flow = min(cap[u][v] for u, v in path)
        if flow == INF:
            return INF
        for u, v in path:
            cap[u][v] -= flow
            cap.setdefault(v, {})[u] = cap.get(v, {}).get(u, 0.0) + flow
        total += flow


def narrowest_track(board: Board, net: str):
    widths = [(w, layer) for n, layer, _, _, w in board.segments if n == net]
    return min(widths) if widths else None
