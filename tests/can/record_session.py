# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Records tests/can/data/head-session.log, a candump-format log of a host bringing up the head's
three boards and moving every joint, written by our own encoder: version handshake, limits, PID
gains, broadcast policy, control mode, position and velocity moves, polled replies, and the boards'
broadcasts at their periods. `make generate` re-records it (codegen/generated-manifest.yaml)."""
import sys
import types
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
LOG = HERE / "data" / "head-session.log"
START = 1795392000.0  # a fixed clock, so the recording is the same on every run


def _codec():
    robogene = types.ModuleType("robogene")
    robogene.__path__ = [str(ROOT / "runtime" / "python" / "robogene")]
    sys.modules.setdefault("robogene", robogene)
    from robogene import can
    return can


def session(can):
    """(time in s, envelope) pairs of the session."""
    boards = {1: ("neck_pitch", "neck_roll"), 2: ("neck_yaw", "eyes_tilt"), 3: ("eyes_version", "eyes_vergence")}
    out, t = [], 0.0

    def at(dt, env):
        nonlocal t
        t += dt
        out.append((t, env))

    for b in boards:
        at(0.001, can.command(b, 0, can.GetFirmwareVersion(protocol_major=1, protocol_minor=0)))
        at(0.0004, can.reply(b, 0, can.GetFirmwareVersionReply(
            board_type=can.BoardType.ROBOGENE_MOTOR_BOARD, firmware_version=1, firmware_revision=0,
            firmware_build=7, protocol_major=1, protocol_minor=0, compatible=True)))
        at(0.001, can.command(b, 0, can.SetBroadcastPolicy(mask=can.BroadcastMask.POSITION | can.BroadcastMask.STATUS
                                                         | can.BroadcastMask.CURRENT | can.BroadcastMask.VELOCITY
                                                         | can.BroadcastMask.SUPPLY)))
        for axis in (0, 1):
            at(0.001, can.command(b, axis, can.SetPositionPid(kp=170, ki=1, kd=1700, shift=8)))
            at(0.001, can.command(b, axis, can.SetPositionPidLimits(offset=0, output_limit=900, integral_limit=300)))
            at(0.001, can.command(b, axis, can.SetMinPosition(position=-11264)))
            at(0.001, can.command(b, axis, can.SetMaxPosition(position=8260)))
            at(0.001, can.command(b, axis, can.SetMaxVelocity(speed=56320.0)))
            at(0.001, can.command(b, axis, can.SetVelocityTimeout(timeout=100)))
            at(0.001, can.command(b, axis, can.SetControlMode(mode=can.ControlMode.POSITION)))
            at(0.001, can.command(b, axis, can.GetControlMode()))
            at(0.0004, can.reply(b, axis, can.GetControlModeReply(mode=can.ControlMode.POSITION)))
    for b in boards:
        at(0.001, can.command(b, 0, can.SetDesiredAcceleration(acceleration=200000.0)))
        at(0.001, can.command(b, 0, can.PositionMove(position=3000 * b, speed=20000.0)))
        at(0.001, can.command(b, 1, can.VelocityMove(speed=-4000.0, acceleration=100000.0)))
    positions = {b: [0, 0] for b in boards}
    for step in range(40):  # 200 ms of broadcasts at 5 ms
        for b in boards:
            positions[b][0] = min(positions[b][0] + 100 * b, 3000 * b)
            positions[b][1] -= 20
            at(0.0002, can.broadcast(b, can.PositionBroadcast(position0=positions[b][0], position1=positions[b][1])))
            if step % 2 == 0:
                at(0.0002, can.broadcast(b, can.VelocityBroadcast(speed0=20000.0 if positions[b][0] < 3000 * b else 0.0,
                                                                  acceleration0=0.0, speed1=-4000.0, acceleration1=0.0)))
                at(0.0002, can.broadcast(b, can.CurrentBroadcast(current0=310 + b, current1=-120 - step)))
        if step == 20:
            for b in boards:
                at(0.0002, can.command(b, 0, can.MotionDone()))
                at(0.0003, can.reply(b, 0, can.MotionDoneReply(done=positions[b][0] >= 3000 * b)))
                at(0.0002, can.command(b, 1, can.GetEncoderPosition()))
                at(0.0003, can.reply(b, 1, can.GetEncoderPositionReply(position=positions[b][1], speed=-4000.0)))
        t += 0.005 - 0.0002 * len(boards) * 3
    for b in boards:
        at(0.0002, can.broadcast(b, can.StatusBroadcast(
            faults0=can.AxisFaults(0), mode0=can.ControlMode.POSITION, faults1=can.AxisFaults(0),
            mode1=can.ControlMode.VELOCITY, can_status=can.CanStatus(0), board_flags=can.BoardFlags(0),
            tx_errors=0, rx_errors=0)))
        at(0.0002, can.broadcast(b, can.SupplyBroadcast(voltage=12.034)))
        at(0.001, can.command(b, 1, can.StopTrajectory()))
        at(0.001, can.command(b, 0, can.SetControlMode(mode=can.ControlMode.IDLE)))
        at(0.001, can.command(b, 1, can.SetControlMode(mode=can.ControlMode.IDLE)))
    return out


def main(argv: list[str]) -> None:
    """`--out DIR` writes DIR/head-session.log instead (make generate: the manifest's can-session)."""
    out = Path(argv[argv.index("--out") + 1]) / LOG.name if "--out" in argv else LOG
    can = _codec()
    lines = [f"({START + t:.6f}) can0 {can.encode(env)}" for t, env in session(can)]
    out.write_text("\n".join(lines) + "\n")
    print(f"{out}: {len(lines)} frames")


if __name__ == "__main__":
    main(sys.argv[1:])
