# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A `board_config:` IDL file: the head's boards on one CAN bus, checked against its protocol.

The numbers come from the head parameter file it names (hardware/head-parameters.yaml, the single
source of truth for the head): joint limits, reductions and encoders through the head model that the
mechanics share (the robogene_head_model package, hardware/head-model: params and joint_config), and the
`motor_control:` section
(bus, board addresses, the joint on each axis, PID gains, speed and current limits) read here with
source marks, so that a wrong value is reported as `file:line:column: error: <field>: what`.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Optional

from robogene_head_model import joint_config
from robogene_head_model import params as params_mod

from ..idl.errors import IdlError, IdlErrors, Mark
from ..idl.loader import Document, load
from .model import CanProtocol, Message, scalar_range

REPO_ROOT = Path(__file__).resolve().parents[3]
COUPLING_VERSION_VERGENCE = "version_vergence"
# The PID entries of motor_control.joints.<joint>, each checked against the field that carries it.
PID_FIELDS = {"kp": ("set_position_pid", "kp"), "ki": ("set_position_pid", "ki"),
              "kd": ("set_position_pid", "kd"), "shift": ("set_position_pid", "shift"),
              "offset": ("set_position_pid_limits", "offset"),
              "output_limit": ("set_position_pid_limits", "output_limit"),
              "integral_limit": ("set_position_pid_limits", "integral_limit")}
JOINT_KEYS = tuple(PID_FIELDS) + ("max_velocity", "current_limit")
# motor_control.homing.<control joint>: only the firmware's tuning of its homing run.
HOMING_KEYS = ("speed", "pwm", "timeout", "current_limit")
# homing.<physical joint> (top level): how the joint finds its zero, the one source of its hard stops.
STOP_KEYS = ("method", "direction", "stops_deg", "back_off_deg")
HOMING_METHODS = ("absolute_encoder", "hard_stop")
# motor_control.joint_correction_limit_deg.<joint>: how far (deg at the joint) the board may shift the motor loop's
# reference to bring a joint onto its encoder's reading before it stops the axis with joint_encoder_mismatch. Every
# joint with a joint encoder needs one (the eye joints once both pans have a sensor); no other joint takes one.
CORRECTION_KEY = "joint_correction_limit_deg"
# Above this a slipped hub or a reversed sensor would drive the joint further than homing's own check of the
# encoder's angle tolerates (RG_JOINT_HOMING_RANGE_TOLERANCE_DEG in the firmware).
CORRECTION_LIMIT_MAX_DEG = 10.0


@dataclass
class Homing:
    """Homing of a control joint against hard stops: the stops, side and back-off derived from the top-level
    homing.<physical joint> of its motors, the run's tuning from motor_control.homing.<joint>. direction 0: the
    joint does not home itself; on the eye board vergence is found when version homes both eyes against their
    stops, and `stop` is the vergence read there."""
    direction: int              # +1 towards the upper stop, -1 the lower, 0 none
    stop_deg: float             # the joint's angle pressed against the stop
    speed: float = 0.0          # deg/s
    pwm: int = 0                # PWM steps
    backoff_deg: float = 0.0
    timeout_s: float = 0.0
    current_limit: int = 0      # mA per motor while seeking the stop: the torque it is pressed with


@dataclass
class AxisConfig:
    joint: str
    index: int                  # position in the control board's joint order
    board_address: int
    axis: int                   # 0 or 1 on its board
    min_deg: float
    max_deg: float
    counts_per_degree: float    # on the wire
    motors: list[str]           # the physical joints (motors) that move it
    reduction: float            # of its motor(s)
    motor_encoder_lines: int
    joint_encoder_bits: int     # 0: no absolute joint encoder
    pid: dict[str, int]
    max_velocity: float         # deg/s
    current_limit: int          # mA
    homing: Optional[Homing] = None
    has_brake: bool = False     # its one motor carries a power-off holding brake (drives.<joint>.brake)
    # > 0: the board closes the joint's position on its joint encoder, correcting its motor loop by at most this
    # (deg at the joint); 0: the joint's position is its motor encoder's
    joint_correction_limit_deg: float = 0.0

    @property
    def joint_correction_limit_counts(self) -> int:
        return round(self.joint_correction_limit_deg * self.counts_per_degree)

    @property
    def homing_counts(self) -> dict[str, int]:
        """The homing parameters in the firmware's units (all 0 when the joint does not home)."""
        h = self.homing or Homing(0, 0.0)
        return {"direction": h.direction, "stop": round(h.stop_deg * self.counts_per_degree),
                "speed": round(h.speed * self.counts_per_degree), "pwm": h.pwm,
                "backoff": round(h.backoff_deg * self.counts_per_degree), "timeout_ms": round(h.timeout_s * 1000),
                "current_limit": h.current_limit}

    @property
    def min_counts(self) -> int:
        return round(self.min_deg * self.counts_per_degree)

    @property
    def max_counts(self) -> int:
        return round(self.max_deg * self.counts_per_degree)

    @property
    def max_speed_counts(self) -> float:
        return self.max_velocity * self.counts_per_degree


@dataclass
class Board:
    name: str
    address: int
    axes: list[AxisConfig]
    coupling: str               # "none" or "version_vergence"
    motors: list[str]           # motor on output 0 and output 1

    # Joint angles to motor angles and back (degrees). Version/vergence of the parameter file:
    # left = version + vergence / 2, right = version - vergence / 2.
    @property
    def j2m(self) -> list[list[float]]:
        return [[1, 0.5], [1, -0.5]] if self.coupling == COUPLING_VERSION_VERGENCE else [[1, 0], [0, 1]]

    @property
    def m2j(self) -> list[list[float]]:
        return [[0.5, 0.5], [1, -1]] if self.coupling == COUPLING_VERSION_VERGENCE else [[1, 0], [0, 1]]

    # Motor encoder counts to the axis counts on the wire: version = left + right, vergence = left - right.
    @property
    def counts_m2a(self) -> list[list[int]]:
        return [[1, 1], [1, -1]] if self.coupling == COUPLING_VERSION_VERGENCE else [[1, 0], [0, 1]]


@dataclass
class BoardConfig:
    name: str
    doc: str
    file: str
    parameters_file: str
    protocol: CanProtocol
    device: str
    bitrate: int
    host_address: int
    pwm_full_scale: int
    control_period_us: int
    reply_timeout_ms: int
    velocity_timeout_ms: int
    polling_interval_ms: int
    broadcasts: list[Message]
    boards: list[Board]
    joints: list[AxisConfig] = field(default_factory=list)  # in control order

    @property
    def broadcast_mask(self) -> int:
        return sum(1 << (m.code - 1) for m in self.broadcasts)

    @property
    def sources(self) -> list[str]:
        """The IDL files, then the parameter file the numbers come from."""
        return sorted({self.file, self.protocol.file}) + [self.parameters_file]


class _Fail(Exception):
    pass


class BoardConfigChecker:
    def __init__(self, errors: list[IdlError], root: Optional[Path]):
        self.errors = errors
        self.root = Path(root) if root else REPO_ROOT

    def check(self, doc: Document, protocols: list[CanProtocol]) -> Optional[BoardConfig]:
        data = doc.data
        proto = next((p for p in protocols if p.name == data["protocol"]), None)
        if proto is None:
            known = ", ".join(p.name for p in protocols) or "none"
            self.errors.append(IdlError(doc.mark(("protocol",)), f"unknown CAN protocol "
                                        f"'{data['protocol']}' (known: {known})"))
            return None
        broadcasts = []
        for k, name in enumerate(data["broadcasts"]):
            m = proto.message(name + "_broadcast")
            if m is None:
                known = ", ".join(b.name[:-len("_broadcast")] for b in proto.broadcasts)
                self.errors.append(IdlError(doc.mark(("broadcasts", k)), f"unknown broadcast '{name}' "
                                            f"(the {proto.name} protocol has: {known})"))
                return None
            broadcasts.append(m)
        param_path = self.root / data["parameters"]
        try:
            param_name = str(param_path.resolve().relative_to(self.root.resolve()))
        except ValueError:
            param_name = str(param_path)
        try:
            text = param_path.read_text(encoding="utf-8")
        except OSError as exc:
            self.errors.append(IdlError(doc.mark(("parameters",)), f"cannot read the parameter file "
                                        f"{param_name} ({exc.strerror})"))
            return None
        try:
            params_doc = load(param_name, text)
        except IdlErrors as exc:
            self.errors.extend(exc.errors)
            return None
        before = len(self.errors)
        try:
            mechanics = self._mechanics(params_doc, param_path, param_name)
            config = _Reader(self, params_doc, proto, mechanics).read(doc, broadcasts)
        except _Fail:
            return None
        return config if len(self.errors) == before else None

    def _mechanics(self, pdoc: Document, path: Path, name: str) -> dict:
        """Limits, reductions and encoders as the mechanics package derives them."""
        try:
            params = params_mod.parse(pdoc.data, name, path)
            cfg = joint_config.config(params)
            reductions = {j: joint_config.reduction(params, j) for j in params_mod.CHAIN_JOINTS}
        except params_mod.ParameterError as exc:
            message = str(exc)
            where = message[len(name) + 2:] if message.startswith(name + ": ") else message
            key = where.split(":", 1)[0]
            self.errors.append(IdlError(pdoc.mark(_key_path(key)), where))
            raise _Fail from None
        return {"config": cfg, "reductions": reductions, "limits": params.control_limits}


def _key_path(dotted: str) -> tuple:
    """'control_joints[2].name' -> ('control_joints', 2, 'name')."""
    path: list[Any] = []
    for part in dotted.split("."):
        m = re.fullmatch(r"([^\[\]]*)((?:\[\d+\])*)", part)
        if not m:
            return tuple(path)
        if m.group(1):
            path.append(m.group(1))
        path += [int(i) for i in re.findall(r"\[(\d+)\]", m.group(2))]
    return tuple(path)


def _dotted(path: tuple) -> str:
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else p)
    return out


class _Reader:
    """Reads motor_control from the parameter file; every error names the field and its place."""

    def __init__(self, checker: BoardConfigChecker, pdoc: Document, proto: CanProtocol, mech: dict):
        self.checker, self.pdoc, self.proto, self.mech = checker, pdoc, proto, mech
        self.stops: dict[str, tuple[int, float, float]] = {}

    def fail(self, path: tuple, message: str) -> None:
        self.checker.errors.append(IdlError(self.pdoc.mark(path), f"{_dotted(path)}: {message}"))

    def get(self, path: tuple, kind: type, what: str) -> Any:
        node: Any = self.pdoc.data
        for i, key in enumerate(path):
            ok = isinstance(node, dict) and key in node if isinstance(key, str) else \
                isinstance(node, list) and key < len(node)
            if not ok:
                self.fail(path[:i + 1] if isinstance(node, (dict, list)) else path[:i],
                          "missing" if isinstance(node, (dict, list)) else f"expected a mapping, got {node!r}")
                raise _Fail
            node = node[key]
        if kind is float:
            good = isinstance(node, (int, float)) and not isinstance(node, bool)
        elif kind is int:
            good = isinstance(node, int) and not isinstance(node, bool)
        else:
            good = isinstance(node, kind)
        if not good:
            self.fail(path, f"expected {what}, got {node!r}")
            raise _Fail
        return node

    def fits(self, path: tuple, value: float, message: str, field_name: str, given: str = "") -> None:
        """The raw wire value of `value` (in the field's unit) must fit the protocol field; `given`
        says what the parameter file wrote when the value was converted from it."""
        f = next(f for f in self.proto.message(message).fields if f.name == field_name)
        lo, hi = scalar_range(f.scalar)
        raw = round((value - f.offset) / f.scale)
        if not lo <= raw <= hi:
            unit = f" {f.unit}" if f.unit else ""
            what = f"{given} is {round(value)}{unit}, which" if given else f"{value:g}{unit}"
            self.fail(path, f"{what} does not fit {message}.{field_name} ({f.scalar}: "
                      f"{lo * f.scale + f.offset:g}..{hi * f.scale + f.offset:g}{unit})")

    def read(self, doc: Document, broadcasts: list[Message]) -> BoardConfig:
        mc = ("motor_control",)
        self.get(mc, dict, "a mapping")
        device = self.get(mc + ("bus", "device"), str, "a CAN interface name")
        bitrate = self.get(mc + ("bus", "bitrate"), int, "an integer (bit/s)")
        host = self.get(mc + ("bus", "host_address"), int, "an integer address")
        if bitrate != self.proto.bitrate:
            self.fail(mc + ("bus", "bitrate"), f"{bitrate} differs from the {self.proto.name} protocol's "
                      f"{self.proto.bitrate} bit/s ({self.proto.file})")
        if host != self.proto.host:
            self.fail(mc + ("bus", "host_address"), f"{host} differs from the {self.proto.name} protocol's "
                      f"host address {self.proto.host}")
        pwm = self.get(mc + ("pwm_full_scale",), int, "an integer")
        period = self.get(mc + ("control_period_us",), int, "an integer (microseconds)")
        for key, value in (("pwm_full_scale", pwm), ("control_period_us", period)):
            if value <= 0:
                self.fail(mc + (key,), f"must be > 0, got {value}")
        axes = self._joints(mc, pwm)
        self._homing(mc, axes)
        boards = self._boards(mc, axes)
        self._coupled_homing(mc, boards)
        self._joint_correction(mc, axes, boards)
        data = doc.data
        t = data["timeouts"]
        config = BoardConfig(
            name=data["board_config"], doc=data["doc"], file=doc.file, parameters_file=self.pdoc.file,
            protocol=self.proto, device=device, bitrate=bitrate, host_address=host, pwm_full_scale=pwm,
            control_period_us=period, reply_timeout_ms=t["reply_ms"], velocity_timeout_ms=t["velocity_ms"],
            polling_interval_ms=t["polling_interval_ms"], broadcasts=broadcasts, boards=boards,
            joints=sorted(axes.values(), key=lambda a: a.index))
        return config

    def _joints(self, mc: tuple, pwm: int) -> dict[str, AxisConfig]:
        cfg = self.mech["config"]
        chain = {j["name"]: j for j in cfg["joints"]}
        coupled = {c["motors"][0]: c for c in cfg["couplings"].values() if c["type"] == "version-vergence"}
        joints_node = self.get(mc + ("joints",), dict, "a mapping of control joints")
        order = [c["name"] for c in cfg["control_board"]]
        for extra in sorted(set(joints_node) - set(order)):
            self.fail(mc + ("joints", extra), f"unknown joint (the control joints are {', '.join(order)})")
        axes = {}
        for index, name in enumerate(order):
            path = mc + ("joints", name)
            entry = self.get(path, dict, "a mapping")
            for extra in sorted(set(entry) - set(JOINT_KEYS)):
                self.fail(path + (extra,), f"unknown key (allowed: {', '.join(JOINT_KEYS)})")
            motors = [name] if name in chain else []
            if not motors:  # a virtual eye joint: the two pan motors of the version/vergence coupling
                c = next(iter(coupled.values()), None)
                motors = list(c["motors"]) if c else []
            if not motors:
                self.fail(path, "no motor drives this joint in the parameter file")
                raise _Fail
            lines = {chain[m]["motor_encoder_lines"] for m in motors}
            reductions = {self.mech["reductions"][m] for m in motors}
            if len(lines) != 1 or len(reductions) != 1:
                self.fail(path, f"the coupled motors {', '.join(motors)} need the same reduction and encoder "
                          "(drives and purchased in the parameter file)")
                raise _Fail
            per_motor = 4 * lines.pop() * reductions.pop() / 360.0
            # version = (L + R) / 2 travels as L + R counts, vergence = L - R as L - R counts.
            counts = 2 * per_motor if name == "eyes_version" else per_motor
            pid = {}
            for key, (message, field_name) in PID_FIELDS.items():
                pid[key] = self.get(path + (key,), int, "an integer")
                self.fits(path + (key,), pid[key], message, field_name)
            for key in ("output_limit", "integral_limit"):
                if not 0 <= pid[key] <= pwm:
                    self.fail(path + (key,), f"{pid[key]} is outside 0..pwm_full_scale ({pwm})")
            max_velocity = float(self.get(path + ("max_velocity",), float, "a number (deg/s)"))
            current = self.get(path + ("current_limit",), int, "an integer (mA)")
            if max_velocity <= 0:
                self.fail(path + ("max_velocity",), f"must be > 0, got {max_velocity:g}")
            if current <= 0:
                self.fail(path + ("current_limit",), f"must be > 0, got {current}")
            self.fits(path + ("max_velocity",), max_velocity * counts, "set_max_velocity", "speed",
                      f"{max_velocity:g} deg/s")
            self._within_drive(path + ("max_velocity",), name, max_velocity, [chain[m] for m in motors])
            self.fits(path + ("current_limit",), current, "set_current_limit", "current")
            lo, hi = self.mech["limits"][name]
            first = chain.get(motors[0], {})
            bits = first.get("joint_encoder", {}).get("bits", 0) if len(motors) == 1 else self._coupled_bits(path, motors, chain)
            braked = [m for m in motors if chain[m].get("brake")]
            if braked and len(motors) > 1:
                # the board's brake output follows one axis; a coupled motor serves both
                self.fail(path, f"{', '.join(braked)} carries a brake, but a board drives brakes only on uncoupled "
                          "axes (drives.<joint>.brake in the parameter file)")
                raise _Fail
            axis = AxisConfig(name, index, 0, 0, lo, hi, counts, motors, self.mech["reductions"][motors[0]],
                              chain[motors[0]]["motor_encoder_lines"], bits, pid, max_velocity, current,
                              has_brake=bool(braked))
            for bound in (lo, hi):
                self.fits(path, bound * counts, "set_min_position", "position", f"the limit {bound:g} deg")
            axes[name] = axis
        return axes

    def _coupled_bits(self, path: tuple, motors: list, chain: dict) -> int:
        """A coupled joint's joint-encoder bits: the eye board derives version and vergence from both pans'
        sensors at start-up, so both pans need one (drives.<pan>.joint_encoder), of the same bits; none: 0."""
        have = [m for m in motors if chain[m].get("joint_encoder")]
        if not have:
            return 0
        if len(have) != len(motors):
            missing = [m for m in motors if m not in have]
            self.fail(path, f"{', '.join(have)} has a joint encoder but {', '.join(missing)} has none: the eye board "
                      "derives version and vergence from both pans' sensors (drives.<pan>.joint_encoder)")
            raise _Fail
        bits = {chain[m]["joint_encoder"].get("bits", 0) for m in have}
        if len(bits) != 1:
            self.fail(path, f"the pans' joint encoders differ in bits ({', '.join(str(b) for b in sorted(bits))}): "
                      "the eye board reads both alike")
            raise _Fail
        return bits.pop()

    def _stops(self) -> dict[str, tuple[int, float, float]]:
        """homing.<physical joint> (top level): (direction, the stop's angle on that side, back-off) of each joint
        that homes against a hard stop; a joint read by an absolute encoder must have one."""
        if "homing" not in self.pdoc.data:
            return {}
        node = self.get(("homing",), dict, "a mapping of physical joints")
        chain = {j["name"]: j for j in self.mech["config"]["joints"]}
        out = {}
        for name in node:
            path = ("homing", name)
            if name not in chain:
                self.fail(path, f"unknown joint (the joints are {', '.join(chain)})")
                continue
            entry = self.get(path, dict, "a mapping")
            for extra in sorted(set(entry) - set(STOP_KEYS)):
                self.fail(path + (extra,), f"unknown key (allowed: {', '.join(STOP_KEYS)})")
            method = self.get(path + ("method",), str, f"one of {', '.join(HOMING_METHODS)}")
            if method not in HOMING_METHODS:
                self.fail(path + ("method",), f"expected one of {', '.join(HOMING_METHODS)}, got {method!r}")
                continue
            if method == "absolute_encoder":
                for extra in sorted(set(entry) - {"method"}):
                    self.fail(path + (extra,), "a joint read by its absolute encoder takes only 'method'")
                if not chain[name].get("joint_encoder"):
                    self.fail(path + ("method",), f"{name} has no joint encoder (drives.{name}.joint_encoder)")
                continue
            direction = self.get(path + ("direction",), int, "1 (upper stop) or -1 (lower stop)")
            stops = self.get(path + ("stops_deg",), list, "[lower, upper] (deg)")
            if len(stops) != 2 or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in stops) \
                    or not stops[0] < stops[1]:
                self.fail(path + ("stops_deg",), f"expected [lower, upper] in degrees, lower < upper, got {stops!r}")
                continue
            back = float(self.get(path + ("back_off_deg",), float, "a number (deg)"))
            if direction not in (1, -1):
                self.fail(path + ("direction",), f"expected 1 (upper stop) or -1 (lower stop), got {direction}")
                continue
            if back <= 0:
                self.fail(path + ("back_off_deg",), f"must be > 0, got {back:g}")
            out[name] = (direction, float(stops[1] if direction == 1 else stops[0]), back)
        return out

    def _homing(self, mc: tuple, axes: dict[str, AxisConfig]) -> None:
        """Each control joint whose motors home against hard stops: where the stops are, which way it runs and how
        far it backs off from the top-level homing.<motor>; its run's tuning from motor_control.homing.<joint>."""
        stops = self.stops = self._stops()
        tuning = self.get(mc + ("homing",), dict, "a mapping of control joints") \
            if "homing" in self.pdoc.data["motor_control"] else {}
        coupled = {a.joint for a in axes.values() if len(a.motors) > 1}
        for motor in stops:
            runs = [a.joint for a in axes.values() if motor in a.motors and a.joint in tuning]
            if not runs:
                drivers = [a.joint for a in axes.values() if motor in a.motors and a.joint != "eyes_vergence"]
                self.fail(("homing", motor, "method"), f"{motor} homes against a hard stop, but "
                          f"motor_control.homing.{drivers[0] if drivers else motor} gives no speed, pwm, timeout "
                          "and current_limit for the board's homing run")
        for name in tuning:
            path = mc + ("homing", name)
            if name not in axes:
                self.fail(path, f"unknown joint (the control joints are {', '.join(axes)})")
                continue
            entry = self.get(path, dict, "a mapping")
            for extra in sorted(set(entry) - set(HOMING_KEYS)):
                self.fail(path + (extra,), f"unknown key (allowed: {', '.join(HOMING_KEYS)}; the stops, the side "
                          "and the back-off come from the top-level homing.<joint> of its motors)")
            a = axes[name]
            if name == "eyes_vergence" and name in coupled:
                self.fail(path, "vergence is found when version homes both eyes against their stops: it takes no "
                          "homing entry")
                continue
            missing = [m for m in a.motors if m not in stops]
            if missing:
                self.fail(path, f"its motors must home against hard stops: give homing.{missing[0]} the method "
                          "hard_stop with its stops_deg, direction and back_off_deg")
                continue
            first = a.motors[0]
            for m in a.motors[1:]:
                for i, key in ((0, "direction"), (2, "back_off_deg")):
                    if stops[m][i] != stops[first][i]:
                        self.fail(("homing", m, key), f"differs from homing.{first}.{key}: {name} runs "
                                  f"{' and '.join(a.motors)} against their stops together")
            direction, back = stops[first][0], stops[first][2]
            # the control joint's angle with every motor at its stop (version = (left + right) / 2)
            stop = sum(stops[m][1] for m in a.motors) / len(a.motors)
            source = ("homing", first, "stops_deg")
            self.fits(source, stop * a.counts_per_degree, "set_encoder_position", "position",
                      f"{name} at the stops, {stop:g} deg,")
            speed = float(self.get(path + ("speed",), float, "a number (deg/s)"))
            if not 0 < speed <= a.max_velocity:
                self.fail(path + ("speed",), f"{speed:g} deg/s is outside 0..max_velocity ({a.max_velocity:g})")
            self.fits(path + ("speed",), speed * a.counts_per_degree, "calibrate_encoder", "speed", f"{speed:g} deg/s")
            pwm = self.get(path + ("pwm",), int, "an integer (PWM steps)")
            if not 0 < pwm <= a.pid["output_limit"]:
                self.fail(path + ("pwm",), f"{pwm} is outside 1..output_limit ({a.pid['output_limit']})")
            timeout = float(self.get(path + ("timeout",), float, "a number (s)"))
            if timeout <= 0:
                self.fail(path + ("timeout",), f"must be > 0, got {timeout:g}")
            current = self._homing_current(path, a, [axes[j] for j in axes if set(axes[j].motors) & set(a.motors)])
            beyond = stop >= a.max_deg if direction == 1 else stop <= a.min_deg
            if not beyond:
                side = "upper" if direction == 1 else "lower"
                self.fail(source, f"{name} reads {stop:g} deg against the {side} stops, inside its range "
                          f"{a.min_deg:g}..{a.max_deg:g}")
            rest = stop - direction * back
            if not a.min_deg <= rest <= a.max_deg:
                self.fail(("homing", first, "back_off_deg"), f"backing {name} off {back:g} deg from the stops at "
                          f"{stop:g} deg ends at {rest:g} deg, outside its range {a.min_deg:g}..{a.max_deg:g}")
            a.homing = Homing(direction, stop, speed, pwm, back, timeout, current)

    def _homing_current(self, path: tuple, a: AxisConfig, sharing: list[AxisConfig]) -> int:
        """motor_control.homing.<joint>.current_limit: mA per motor while the joint seeks its stops, within what its
        motors may draw at all (on the eye board both motors serve version and vergence: the lower of their limits)."""
        current = self.get(path + ("current_limit",), int, "an integer (mA per motor)")
        run = min(x.current_limit for x in sharing)
        if not 0 < current <= run:
            names = " and ".join(x.joint for x in sharing)
            self.fail(path + ("current_limit",), f"{current} mA is outside 1..the run limit of {names}'s motors "
                      f"({run} mA)")
        return current

    def _coupled_homing(self, mc: tuple, boards: list[Board]) -> None:
        """On the eye board version homes both eyes against their stops, which fixes vergence too: the vergence read
        there follows from the two eyes' stops (vergence = left - right)."""
        for b in boards:
            if b.coupling != COUPLING_VERSION_VERGENCE:
                continue
            version, vergence = b.axes
            if not (version.homing and version.homing.direction):
                continue
            stops = self.stops
            left, right = version.motors
            if left not in stops or right not in stops:
                continue
            stop = stops[left][1] - stops[right][1]
            self.fits(("homing", left, "stops_deg"), stop * vergence.counts_per_degree, "set_encoder_position",
                      "position", f"{vergence.joint} at the stops, {stop:g} deg,")
            if not vergence.min_deg <= stop <= vergence.max_deg:
                self.fail(("homing", left, "stops_deg"), f"{vergence.joint} reads {stop:g} deg with both eyes at "
                          f"their stops, outside its range {vergence.min_deg:g}..{vergence.max_deg:g}")
            vergence.homing = Homing(0, stop)

    def _joint_correction(self, mc: tuple, axes: dict[str, AxisConfig], boards: list[Board]) -> None:
        """motor_control.joint_correction_limit_deg: each joint the board closes on its joint encoder needs its limit (on
        the eye board version and vergence, once both pans have a sensor); no other joint takes one."""
        closed = {a.joint for b in boards for a in b.axes if a.joint_encoder_bits}
        node = self.get(mc + (CORRECTION_KEY,), dict, "a mapping of joints to degrees") \
            if CORRECTION_KEY in self.pdoc.data["motor_control"] else {}
        for name in node:
            path = mc + (CORRECTION_KEY, name)
            if name not in axes:
                self.fail(path, f"unknown joint (the control joints are {', '.join(axes)})")
                continue
            if name not in closed:
                self.fail(path, f"{name} takes no joint correction limit: it has no joint encoder to close its "
                          "position on")
                continue
            deg = float(self.get(path, float, "a number (deg at the joint)"))
            if not 0 < deg <= CORRECTION_LIMIT_MAX_DEG:
                self.fail(path, f"{deg:g} deg is outside 0 (excluded)..{CORRECTION_LIMIT_MAX_DEG:g}: the board "
                          "corrects its motor loop by at most this before it stops the joint")
                continue
            axes[name].joint_correction_limit_deg = deg
        for name in sorted(closed - set(node), key=lambda j: axes[j].index):
            self.fail(mc + (CORRECTION_KEY,) if CORRECTION_KEY in self.pdoc.data["motor_control"] else mc,
                      f"{name} has a joint encoder, which its board closes the position on: give "
                      f"motor_control.{CORRECTION_KEY}.{name} (deg)")

    def _within_drive(self, path: tuple, name: str, max_velocity: float, motors: list[dict]) -> None:
        """A speed limit the drive cannot reach is a typo or a wrong part: the joint's top speed is its motors'
        no-load speed through the reduction (the mechanics' drive_limits). Vergence turns each eye by half of
        it (left = version + vergence / 2), so it reaches twice its motors' speed."""
        slowest = min(motors, key=lambda m: m["drive_limits"]["velocity_deg_s"])
        reach = slowest["drive_limits"]["velocity_deg_s"] * (2 if name == "eyes_vergence" else 1)
        if max_velocity > reach:
            self.fail(path, f"{max_velocity:g} deg/s is faster than the drive can turn the joint: {reach:.4g} deg/s "
                      f"({slowest['motor']} at its no-load speed through the {slowest['reduction']:.4g}:1 reduction)")

    def _boards(self, mc: tuple, axes: dict[str, AxisConfig]) -> list[Board]:
        names = self.get(("boards", "names"), list, "a list of board names")
        raw = self.get(mc + ("boards",), list, "a list of boards")
        if len(raw) != len(names):
            self.fail(mc + ("boards",), f"lists {len(raw)} boards, boards.names lists {len(names)}")
            raise _Fail
        boards, used_addresses, placed = [], {}, {}
        for i, expected in enumerate(names):
            path = mc + ("boards", i)
            name = self.get(path + ("name",), str, "a board name")
            if name != expected:
                self.fail(path + ("name",), f"expected '{expected}' (boards.names[{i}]), got '{name}'")
            address = self.get(path + ("address",), int, "an integer address")
            if not self.proto.first_board <= address <= self.proto.last_board:
                self.fail(path + ("address",), f"{address} is not a board address "
                          f"({self.proto.first_board}..{self.proto.last_board})")
            elif address in used_addresses:
                self.fail(path + ("address",), f"{address} is already the address of "
                          f"'{used_addresses[address]}'")
            used_addresses.setdefault(address, name)
            joints = self.get(path + ("axes",), list, "a list of two joints")
            if len(joints) != 2:
                self.fail(path + ("axes",), f"a board drives 2 axes, got {len(joints)}")
                continue
            board_axes = []
            for k, joint in enumerate(joints):
                if joint not in axes:
                    self.fail(path + ("axes", k), f"unknown joint '{joint}' (the control joints are "
                              f"{', '.join(axes)})")
                    continue
                if joint in placed:
                    self.fail(path + ("axes", k), f"'{joint}' is already on board '{placed[joint]}'")
                    continue
                placed[joint] = name
                axes[joint].board_address, axes[joint].axis = address, k
                board_axes.append(axes[joint])
            if len(board_axes) != 2:
                continue
            motor_sets = [a.motors for a in board_axes]
            if motor_sets[0] == motor_sets[1] and len(motor_sets[0]) == 2:
                if [a.joint for a in board_axes] != ["eyes_version", "eyes_vergence"]:
                    self.fail(path + ("axes",), "the coupled eye joints go on axes 0 and 1 in the order "
                              "eyes_version, eyes_vergence")
                boards.append(Board(name, address, board_axes, COUPLING_VERSION_VERGENCE, motor_sets[0]))
            elif any(len(m) != 1 for m in motor_sets):
                self.fail(path + ("axes",), "eyes_version and eyes_vergence share the two eye motors, so "
                          "they must be on the same board")
            else:
                boards.append(Board(name, address, board_axes, "none", [m[0] for m in motor_sets]))
        for joint in axes:
            if joint not in placed:
                self.fail(mc + ("boards",), f"no board drives '{joint}'")
        return boards
