# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The head's board configuration: generated from the head parameter file, read back by the runtime's
own Property parser and by a C compiler, and a wrong parameter refused with the field it names."""
import math
import re
import shutil
import subprocess
from pathlib import Path

import pytest
import yaml

from conftest import CC, ROOT
from robogene_codegen.generate import render
from robogene_codegen.idl import IdlErrors, compile_directory

# The first test of the module builds the C++ side (g++), which can take minutes on a busy machine.
pytestmark = pytest.mark.timeout(900)

INI = ROOT / "drivers" / "can" / "generated" / "head.ini"
FIRMWARE = ROOT / "hardware" / "electronics" / "firmware"
PARAMS = ROOT / "hardware" / "head-parameters.yaml"


def _atoms(text: str):
    """The bottle text form the Property tool prints: nested lists of numbers, words and strings."""
    tokens = re.findall(r'\(|\)|"(?:[^"\\]|\\.)*"|[^\s()]+', text)
    stack = [[]]
    for t in tokens:
        if t == "(":
            stack.append([])
        elif t == ")":
            done = stack.pop()
            stack[-1].append(done)
        elif t.startswith('"'):
            stack[-1].append(t[1:-1])
        else:
            try:
                stack[-1].append(int(t))
            except ValueError:
                try:
                    stack[-1].append(float(t))
                except ValueError:
                    stack[-1].append(t)
    return stack[0]


def _groups(items) -> dict:
    """(group (key values...) ...) lists to {group: {key: [values]}}."""
    out = {}
    for g in items:
        out[g[0]] = {entry[0]: entry[1:] for entry in g[1:]}
    return out


@pytest.fixture(scope="module")
def ini(property_tool):
    result = subprocess.run([str(property_tool), str(INI)], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return _groups(_atoms(result.stdout))


@pytest.fixture(scope="module")
def config():
    return compile_directory(ROOT / "interfaces" / "idl", root=ROOT).board_configs[0]


@pytest.fixture(scope="module")
def params():
    return yaml.safe_load(PARAMS.read_text())


def test_property_parser_reads_the_driver_config(ini, config, params):
    can, general, limits, pids = ini["CAN"], ini["GENERAL"], ini["LIMITS"], ini["PIDS"]
    assert can["device"] == ["can0"] and can["bitrate"] == [1000000] and can["host_address"] == [0]
    assert can["board_addresses"] == [1, 2, 3]
    assert can["protocol_fingerprint"] == [config.protocol.fingerprint]
    assert can["broadcast_policy"] == [0x104D]  # position, status, current, velocity, supply: bits 0 2 3 6 12
    assert general["axis_names"] == [j["name"] for j in params["control_joints"]]
    assert general["board"] == [1, 1, 2, 2, 3, 3] and general["axis"] == [0, 1, 0, 1, 0, 1]
    assert limits["min"] == [j["min"] for j in params["control_joints"]]
    assert limits["max"] == [j["max"] for j in params["control_joints"]]
    assert pids["kp"] == [params["motor_control"]["joints"][j]["kp"] for j in general["axis_names"]]
    assert ini["VELOCITY"]["timeout_ms"] == [100]


def test_reductions_and_encoders_come_from_the_parameter_file(ini, params):
    general = ini["GENERAL"]
    purchased, pulleys = params["purchased"], params["geometry"]["pulleys"]
    gear = lambda joint: purchased[params["drives"][joint]["gearhead"]]["ratio"]  # noqa: E731
    expected = [gear("neck_pitch"), gear("neck_roll"),
                gear("neck_yaw") * pulleys["yaw"]["joint_teeth"] / pulleys["yaw"]["motor_teeth"],
                gear("eyes_tilt") * pulleys["tilt"]["joint_teeth"] / pulleys["tilt"]["motor_teeth"],
                gear("left_eye_pan"), gear("right_eye_pan")]
    assert general["gear_ratio"] == pytest.approx(expected, rel=1e-12)
    per_degree = [4 * 512 * r / 360 for r in expected]
    per_degree[4] *= 2  # version travels as left + right motor counts
    assert general["encoder"] == pytest.approx(per_degree, rel=1e-12)
    assert general["joint_encoder_bits"] == [14, 14, 14, 14, 0, 0]
    coupling = ini["COUPLING_3"]
    assert coupling["type"] == ["version_vergence"] and coupling["joints"] == [4, 5]
    assert coupling["motors"] == ["left_eye_pan", "right_eye_pan"]
    assert coupling["j2m"] == [[1, 0.5], [1, -0.5]] and coupling["m2j"] == [[0.5, 0.5], [1, -1]]


def test_firmware_headers_compile(build_dir):
    if shutil.which(CC) is None:
        pytest.fail(f"{CC} is needed to check the firmware headers")
    headers = sorted((FIRMWARE / "generated").glob("robogene_*.h"))
    assert [h.name for h in headers] == ["robogene_can_motor_control.h", "robogene_head_board_config.h"]
    for header in headers:
        unit = build_dir / f"include_{header.stem}.c"
        unit.write_text(f'#include "generated/{header.name}"\n#include "generated/{header.name}"\n'
                        'typedef int translation_unit_is_not_empty;\n')
        cmd = [CC, "-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-fsyntax-only", f"-I{FIRMWARE}", str(unit)]
        result = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
        assert result.returncode == 0, f"{header.name}:\n{result.stderr}"


def test_firmware_table_matches_the_driver_config(build_dir, ini):
    program = build_dir / "print_boards.c"
    program.write_text("""
#include <stdio.h>
#include "generated/robogene_head_board_config.h"
int main(void) {
  for (size_t b = 0; b < ROBOGENE_BOARD_COUNT; ++b) {
    const robogene_board_config_t *c = robogene_board_config(robogene_board_configs[b].can_address);
    for (int a = 0; a < 2; ++a) {
      const robogene_axis_config_t *x = &c->axes[a];
      printf("%s %u %d %d %d %ld %ld %d %d %d %u %.9g\\n", x->joint, c->can_address, a, (int)c->coupling,
             x->kp, (long)x->min_position, (long)x->max_position, x->output_limit, (int)x->current_limit,
             x->joint_encoder_bits, x->shift, x->counts_per_degree);
    }
  }
  return robogene_board_config(9) == NULL ? 0 : 1;
}
""")
    exe = build_dir / "print_boards"
    cmd = [CC, "-std=c99", "-Wall", "-Wextra", "-Werror", f"-I{FIRMWARE}", str(program), "-o", str(exe)]
    result = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    run = subprocess.run([str(exe)], capture_output=True, text=True, timeout=30)
    assert run.returncode == 0
    rows = {line.split()[0]: line.split()[1:] for line in run.stdout.splitlines()}
    g, lim, pid = ini["GENERAL"], ini["LIMITS"], ini["PIDS"]
    for i, joint in enumerate(g["axis_names"]):
        addr, axis, coupling, kp, lo, hi, out_limit, current, bits, shift, cpd = rows[joint]
        assert (int(addr), int(axis)) == (g["board"][i], g["axis"][i])
        assert int(coupling) == (1 if joint.startswith("eyes_v") else 0)
        assert int(kp) == pid["kp"][i] and int(out_limit) == pid["output_limit"][i] and int(shift) == pid["shift"][i]
        assert int(lo) == round(lim["min"][i] * g["encoder"][i]) and int(hi) == round(lim["max"][i] * g["encoder"][i])
        assert int(current) == lim["current"][i] and int(bits) == g["joint_encoder_bits"][i]
        assert math.isclose(float(cpd), g["encoder"][i], rel_tol=1e-6)


def test_firmware_homing_matches_the_driver_config(build_dir, ini):
    """The homing the firmware runs is the one the driver and the simulator read, in counts."""
    program = build_dir / "print_homing.c"
    program.write_text("""
#include <stdio.h>
#include "generated/robogene_head_board_config.h"
int main(void) {
  for (size_t b = 0; b < ROBOGENE_BOARD_COUNT; ++b) {
    for (int a = 0; a < 2; ++a) {
      const robogene_axis_config_t *x = &robogene_board_configs[b].axes[a];
      printf("%s %d %ld %ld %d %ld %lu %ld\\n", x->joint, x->homing_direction, (long)x->homing_stop,
             (long)x->homing_speed, x->homing_pwm, (long)x->homing_backoff, (unsigned long)x->homing_timeout_ms,
             (long)x->homing_current_limit);
    }
  }
  return 0;
}
""")
    exe = build_dir / "print_homing"
    result = subprocess.run([CC, "-std=c99", "-Wall", "-Wextra", "-Werror", f"-I{FIRMWARE}", str(program), "-o", str(exe)],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    rows = {line.split()[0]: [int(v) for v in line.split()[1:]]
            for line in subprocess.run([str(exe)], capture_output=True, text=True, timeout=30, check=True).stdout.splitlines()}
    g, h = ini["GENERAL"], ini["HOMING"]
    for i, joint in enumerate(g["axis_names"]):
        cpd = g["encoder"][i]
        assert rows[joint] == [h["direction"][i], round(h["stop"][i] * cpd), round(h["speed"][i] * cpd), h["pwm"][i],
                               round(h["backoff"][i] * cpd), round(h["timeout"][i] * 1000), h["current"][i]], joint
    assert rows["eyes_version"][0] == 1 and rows["neck_pitch"][0] == 0


def test_the_homing_current_comes_from_the_parameter_file(ini, params):
    """The eyes press their stops with the homing run's own current limit, not the joints' run limit."""
    g, h, lim = ini["GENERAL"], ini["HOMING"], ini["LIMITS"]
    homing = params["motor_control"]["homing"]
    expected = [homing[j]["current_limit"] if j in homing else 0 for j in g["axis_names"]]
    assert h["current"] == expected
    version = g["axis_names"].index("eyes_version")
    assert 0 < h["current"][version] < lim["current"][version]


LEFT_STOPS = "left_eye_pan:  {method: hard_stop, direction: 1, stops_deg: [-56.5, 56.5], back_off_deg: 28.5}"
RIGHT_STOPS = "right_eye_pan: {method: hard_stop, direction: 1, stops_deg: [-56.5, 56.5], back_off_deg: 28.5}"
TUNING = "eyes_version:  {speed: 10, pwm: 250, timeout: 20, current_limit: 100}"


def test_homing_stops_come_from_the_physical_joints(tree):
    """The board's homing of version and vergence follows the eye pans' stops (top-level homing:): version reads
    the mean of the two stops, vergence their difference (left - right), and the back-off is the pans'."""
    _edit(tree, (LEFT_STOPS, LEFT_STOPS.replace("56.5]", "58]").replace("28.5", "29")),
          (RIGHT_STOPS, RIGHT_STOPS.replace("56.5]", "57]").replace("28.5", "29")))
    joints = {j.joint: j for j in _compile(tree).board_configs[0].joints}
    version, vergence = joints["eyes_version"].homing, joints["eyes_vergence"].homing
    assert (version.direction, version.stop_deg, version.backoff_deg) == (1, 57.5, 29)
    assert (version.speed, version.pwm, version.timeout_s, version.current_limit) == (10, 250, 20, 100)
    assert (vergence.direction, vergence.stop_deg, vergence.current_limit) == (0, 1, 0)
    assert joints["neck_pitch"].homing is None


def test_homing_stop_inside_the_joint_range(tree):
    _edit(tree, (RIGHT_STOPS, RIGHT_STOPS.replace("56.5]", "25]")))
    errs, text = _errors(tree, LEFT_STOPS, LEFT_STOPS.replace("56.5]", "25]"))
    assert f"{_at(text, '[-56.5, 25]')}: error: homing.left_eye_pan.stops_deg: eyes_version reads 25 deg against " \
           "the upper stops, inside its range -30..30" in errs


def test_homing_backoff_that_ends_outside_the_range(tree):
    _edit(tree, (RIGHT_STOPS, RIGHT_STOPS.replace("28.5", "20")))
    errs, text = _errors(tree, LEFT_STOPS, LEFT_STOPS.replace("28.5", "20"))
    assert errs == [f"{_at(text, 'back_off_deg: 20', skip=14)}: error: homing.left_eye_pan.back_off_deg: backing "
                    "eyes_version off 20 deg from the stops at 56.5 deg ends at 36.5 deg, outside its range -30..30"]


def test_the_eyes_home_together(tree):
    """Version runs both pans against their stops at once: they must head for the same side and back off alike."""
    errs, text = _errors(tree, RIGHT_STOPS, RIGHT_STOPS.replace("direction: 1", "direction: -1"))
    assert any(e.startswith(f"{_at(text, 'direction: -1', skip=11)}: error: homing.right_eye_pan.direction: differs "
                            "from homing.left_eye_pan.direction: eyes_version runs left_eye_pan and right_eye_pan "
                            "against their stops together") for e in errs), errs


def test_homing_pwm_above_the_output_limit(tree):
    errs, text = _errors(tree, "pwm: 250,", "pwm: 950,")
    assert errs == [f"{_at(text, 'pwm: 950', skip=5)}: error: motor_control.homing.eyes_version.pwm: 950 is outside "
                    "1..output_limit (900)"]


def test_homing_current_above_the_run_limit(tree):
    errs, text = _errors(tree, "current_limit: 100}", "current_limit: 700}")
    assert errs == [f"{_at(text, 'current_limit: 700', skip=15)}: error: motor_control.homing.eyes_version.current_limit: "
                    "700 mA is outside 1..the run limit of eyes_version and eyes_vergence's motors (600 mA)"]


def test_homing_current_above_the_lower_run_limit_of_the_eye_board(tree):
    """Both eye motors run at the lower of version's and vergence's limits: the homing current must fit under it."""
    errs, text = _errors(tree, "eyes_vergence: {kp: 260, ki: 1, kd: 2600, shift: 8, offset: 0, output_limit: 900, "
                               "integral_limit: 300, max_velocity: 400, current_limit: 600}",
                         "eyes_vergence: {kp: 260, ki: 1, kd: 2600, shift: 8, offset: 0, output_limit: 900, "
                         "integral_limit: 300, max_velocity: 400, current_limit: 90}")
    assert f"{_at(text, 'current_limit: 100}', skip=15)}: error: motor_control.homing.eyes_version.current_limit: " \
           "100 mA is outside 1..the run limit of eyes_version and eyes_vergence's motors (90 mA)" in errs, errs


@pytest.mark.parametrize("new, message", [
    ("timeout: 20}", "motor_control.homing.eyes_version.current_limit: missing"),
    ("timeout: 20, current_limit: 0}", "motor_control.homing.eyes_version.current_limit: 0 mA is outside 1..the run "
                                       "limit of eyes_version and eyes_vergence's motors (600 mA)"),
    ("timeout: 20, current_limit: 0.1}", "motor_control.homing.eyes_version.current_limit: expected an integer "
                                         "(mA per motor), got 0.1"),
])
def test_a_bad_homing_current_is_named(tree, new, message):
    errs, _ = _errors(tree, "timeout: 20, current_limit: 100}", new)
    assert any(e.endswith(message) for e in errs), errs


def test_the_firmware_tuning_gives_no_stop_of_its_own(tree):
    """The stop angle has one source: a stop under motor_control.homing is refused, naming where it belongs."""
    errs, text = _errors(tree, TUNING, TUNING.replace("{speed", "{stop: 55, speed"))
    assert errs == [f"{_at(text, 'stop: 55', skip=6)}: error: motor_control.homing.eyes_version.stop: unknown key (allowed: "
                    "speed, pwm, timeout, current_limit; the stops, the side and the back-off come from the top-level "
                    "homing.<joint> of its motors)"]


def test_vergence_cannot_home_on_its_own(tree):
    errs, _ = _errors(tree, TUNING + "\n", TUNING + "\n    eyes_vergence: {speed: 10, pwm: 100, timeout: 5}\n")
    assert any(e.endswith("motor_control.homing.eyes_vergence: vergence is found when version homes both eyes "
                          "against their stops: it takes no homing entry") for e in errs), errs


def test_a_hard_stop_joint_needs_the_boards_tuning(tree):
    errs, text = _errors(tree, "  homing:\n    " + TUNING + "\n", "")
    assert f"{_at(text, LEFT_STOPS, skip=len('left_eye_pan:  {method: '))}: error: homing.left_eye_pan.method: " \
           "left_eye_pan homes against a hard stop, but motor_control.homing.eyes_version gives no speed, pwm, " \
           "timeout and current_limit for the board's homing run" in errs, errs


def test_an_absolute_encoder_joint_needs_its_encoder(tree):
    errs, text = _errors(tree, LEFT_STOPS, "left_eye_pan:  {method: absolute_encoder}")
    at = _at(text, "left_eye_pan:  {method: absolute_encoder}", skip=len("left_eye_pan:  {method: "))
    assert f"{at}: error: homing.left_eye_pan.method: left_eye_pan has no " \
           "joint encoder (drives.left_eye_pan.joint_encoder)" in errs, errs


LEFT_DRIVE = "left_eye_pan:  {motor: faulhaber-1717T012SR, gearhead: faulhaber-16-7-43, encoder: faulhaber-IE2-512-17}"
RIGHT_DRIVE = "right_eye_pan: {motor: faulhaber-1717T012SR, gearhead: faulhaber-16-7-43, encoder: faulhaber-IE2-512-17}"


def _with_pan_encoder(text: str, drive: str) -> str:
    assert text.count(drive) == 1, drive
    return text.replace(drive, drive[:-1] + ", joint_encoder: ams-AS5048A}")


def test_coupled_eye_joints_get_joint_encoder_bits_when_both_pans_have_one(tree):
    """Not set in the real parameter file (the eyes have no sensor yet): an edited copy with an AS5048A per pan
    gives version and vergence the encoders' bits, which the eye board reads to derive them at start-up."""
    path = tree / "hardware" / "head-parameters.yaml"
    text = _with_pan_encoder(_with_pan_encoder(path.read_text(), LEFT_DRIVE), RIGHT_DRIVE)
    path.write_text(text.replace("eyes_tilt: 3}", "eyes_tilt: 3, eyes_version: 3, eyes_vergence: 3}"))  # closed on them
    axes = {a.joint: a for b in _compile(tree).board_configs[0].boards for a in b.axes if a}
    assert axes["eyes_version"].joint_encoder_bits == 14 and axes["eyes_vergence"].joint_encoder_bits == 14
    assert axes["neck_pitch"].joint_encoder_bits == 14


def test_the_real_eyes_have_no_joint_encoder_bits(tree):
    axes = {a.joint: a for b in _compile(tree).board_configs[0].boards for a in b.axes if a}
    assert axes["eyes_version"].joint_encoder_bits == 0 and axes["eyes_vergence"].joint_encoder_bits == 0


def test_one_pan_with_a_joint_encoder_is_refused(tree):
    errs, text = _errors(tree, LEFT_DRIVE, _with_pan_encoder(LEFT_DRIVE, LEFT_DRIVE))
    assert any(e.endswith("error: motor_control.joints.eyes_version: left_eye_pan has a joint encoder but right_eye_pan "
                          "has none: the eye board derives version and vergence from both pans' sensors "
                          "(drives.<pan>.joint_encoder)") for e in errs), errs


# ---- a wrong parameter file is refused, naming the field --------------------------------------

@pytest.fixture
def tree(tmp_path):
    """A copy of what the board config reads: the IDL files, the schema and the parameter file."""
    idl = tmp_path / "interfaces" / "idl"
    idl.mkdir(parents=True)
    for name in ("can_motor_control.yaml", "head_boards.yaml", "idl.schema.json"):
        shutil.copy(ROOT / "interfaces" / "idl" / name, idl / name)
    (tmp_path / "hardware").mkdir()
    shutil.copy(PARAMS, tmp_path / "hardware" / "head-parameters.yaml")
    (tmp_path / "codegen").mkdir()
    shutil.copy(ROOT / "codegen" / "generated-manifest.yaml", tmp_path / "codegen")
    return tmp_path


def _compile(tree):
    return compile_directory(tree / "interfaces" / "idl", tree / "interfaces" / "idl" / "idl.schema.json", root=tree)


def _errors(tree, old: str, new: str) -> tuple[list[str], str]:
    path = tree / "hardware" / "head-parameters.yaml"
    text = path.read_text()
    assert text.count(old) == 1, old
    text = text.replace(old, new)
    path.write_text(text)
    with pytest.raises(IdlErrors) as info:
        _compile(tree)
    return [str(e) for e in info.value.errors], text


def _at(text: str, needle: str, skip: int = 0) -> str:
    at = text.index(needle) + skip
    return f"hardware/head-parameters.yaml:{text.count(chr(10), 0, at) + 1}:{at - text.rfind(chr(10), 0, at)}"


def test_the_copy_compiles(tree):
    assert [b.address for b in _compile(tree).board_configs[0].boards] == [1, 2, 3]


def test_gain_that_does_not_fit_its_field(tree):
    errs, text = _errors(tree, "neck_yaw:      {kp: 66,", "neck_yaw:      {kp: 40000,")
    assert errs == [f"{_at(text, '40000')}: error: motor_control.joints.neck_yaw.kp: 40000 does not fit "
                    "set_position_pid.kp (int16: -32768..32767)"]


def test_board_address_out_of_range(tree):
    errs, text = _errors(tree, "address: 2,", "address: 20,")
    assert errs == [f"{_at(text, '20, axes')}: error: motor_control.boards[1].address: 20 is not a board address (1..14)"]


def test_duplicate_board_address(tree):
    errs, text = _errors(tree, "address: 3,", "address: 1,")
    assert errs == [f"{_at(text, '1, axes: [eyes')}: error: motor_control.boards[2].address: 1 is already the "
                    "address of 'neck-pitch-roll'"]


def test_coupled_eye_joints_stay_on_one_board(tree):
    errs, _ = _errors(tree, "axes: [neck_yaw, eyes_tilt]}", "axes: [neck_yaw, eyes_version]}")
    assert any("motor_control.boards[2].axes[0]: 'eyes_version' is already on board 'neck-yaw-eyes-tilt'" in e
               for e in errs), errs
    assert any("no board drives 'eyes_tilt'" in e for e in errs), errs


def test_unknown_joint_on_an_axis(tree):
    errs, text = _errors(tree, "axes: [neck_pitch, neck_roll]}", "axes: [neck_pitch, neck_twist]}")
    assert f"{_at(text, 'neck_twist')}: error: motor_control.boards[0].axes[1]: unknown joint 'neck_twist' " \
           "(the control joints are neck_pitch, neck_roll, neck_yaw, eyes_tilt, eyes_version, eyes_vergence)" in errs


def test_missing_value(tree):
    errs, text = _errors(tree, "kd: 1140, shift: 8, offset: 0, output_limit: 900, integral_limit: 300, max_velocity: 150,",
                         "kd: 1140, shift: 8, offset: 0, output_limit: 900, integral_limit: 300,")
    assert errs == [f"{_at(text, '{kp: 114,')}: error: motor_control.joints.eyes_tilt.max_velocity: missing"]


def test_speed_limit_beyond_the_wire(tree):
    errs, text = _errors(tree, "integral_limit: 300, max_velocity: 150, current_limit: 620}",
                         "integral_limit: 300, max_velocity: 2000, current_limit: 620}")
    assert len(errs) == 2 and errs[0].startswith(
        f"{_at(text, 'max_velocity: 2000', skip=14)}: error: motor_control.joints.eyes_tilt.max_velocity: 2000 deg/s "
        "is 838705 count/s, which does not fit set_max_velocity.speed (int16: -327680..327670 count/s)")
    assert "2000 deg/s is faster than the drive can turn the joint" in errs[1]   # test_speed_limit_beyond_the_drive


def test_speed_limit_beyond_the_drive(tree):
    """neck_yaw: 7800 rpm through 66 x 20/14 is 496.4 deg/s; 600 fits the wire (321800 count/s) but not the drive."""
    errs, text = _errors(tree, "integral_limit: 300, max_velocity: 200, current_limit: 550}",
                         "integral_limit: 300, max_velocity: 600, current_limit: 550}")
    assert errs == [f"{_at(text, 'max_velocity: 600', skip=14)}: error: motor_control.joints.neck_yaw.max_velocity: "
                    "600 deg/s is faster than the drive can turn the joint: 496.4 deg/s (faulhaber-2224U012SR at its "
                    "no-load speed through the 94.29:1 reduction)"]


def test_slower_motor_lowers_the_speed_limit(tree):
    """The check follows the motor's catalogue speed: at 1500 rpm the 1724 tilt drive reaches 122.1 deg/s."""
    errs, _ = _errors(tree, "no_load_speed_rpm: 8200,", "no_load_speed_rpm: 1500,")
    assert any(e.endswith("motor_control.joints.eyes_tilt.max_velocity: 150 deg/s is faster than the drive can turn "
                          "the joint: 122.1 deg/s (faulhaber-1724T012SR at its no-load speed through the 73.71:1 "
                          "reduction)") for e in errs), errs


def _edit(tree, *pairs: tuple[str, str]) -> None:
    path = tree / "hardware" / "head-parameters.yaml"
    text = path.read_text()
    for old, new in pairs:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    path.write_text(text)


@pytest.mark.parametrize("vergence, refused", [(1100, False), (1200, True)])
def test_vergence_may_run_at_twice_the_pan_speed(tree, vergence, refused):
    """Each eye turns by half the vergence. With 4000 rpm eye motors a pan turns at most 558 deg/s through its
    43:1 gearhead, so vergence reaches 1116 deg/s (the wire takes up to 1339 deg/s of vergence)."""
    _edit(tree, ("no_load_speed_rpm: 12800,", "no_load_speed_rpm: 4000,"),
          ("kd: 1140, shift: 8, offset: 0, output_limit: 900, integral_limit: 300, max_velocity: 150,",
           "kd: 1140, shift: 8, offset: 0, output_limit: 900, integral_limit: 300, max_velocity: 50,"),
          ("kd: 2600, shift: 8, offset: 0, output_limit: 900, integral_limit: 300, max_velocity: 400,",
           f"kd: 2600, shift: 8, offset: 0, output_limit: 900, integral_limit: 300, max_velocity: {vergence},"))
    if not refused:
        assert _compile(tree).board_configs[0].joints[5].max_velocity == vergence
        return
    with pytest.raises(IdlErrors) as info:
        _compile(tree)
    assert [str(e).split(": error: ")[1] for e in info.value.errors] == [
        "motor_control.joints.eyes_vergence.max_velocity: 1200 deg/s is faster than the drive can turn the joint: "
        "1116 deg/s (faulhaber-1717T012SR at its no-load speed through the 43:1 reduction)"]


def test_bitrate_must_match_the_protocol(tree):
    errs, text = _errors(tree, "bitrate: 1000000, host_address: 0}", "bitrate: 500000, host_address: 0}")
    assert errs == [f"{_at(text, '500000')}: error: motor_control.bus.bitrate: 500000 differs from the "
                    "motor_control protocol's 1000000 bit/s (interfaces/idl/can_motor_control.yaml)"]


def test_mechanics_errors_are_placed_too(tree):
    errs, text = _errors(tree, "faulhaber-16-7-43:    {kind: gearhead, ratio: 43,", "faulhaber-16-7-43:    {kind: gearhead, ratio: -43,")
    assert errs == [f"{_at(text, 'ratio: -43', skip=7)}: error: purchased.faulhaber-16-7-43.ratio: must be > 0, got -43"]


def test_a_parameter_change_travels_to_every_output(tree):
    path = tree / "hardware" / "head-parameters.yaml"
    text = path.read_text()
    assert "yaw: {motor_teeth: 14, joint_teeth: 20," in text
    path.write_text(text.replace("yaw: {motor_teeth: 14, joint_teeth: 20,", "yaw: {motor_teeth: 14, joint_teeth: 40,"))
    configs = ["can-driver-config", "firmware-can"]
    outputs = render(tree, configs)
    ini = outputs["drivers/can/generated/head.ini"]
    assert f"gear_ratio 66 246 {66 * 40 / 14!r} " in ini
    header = outputs["hardware/electronics/firmware/generated/robogene_head_board_config.h"]
    assert f"{4 * 512 * 66 * 40 / 14 / 360!r}f" in header
    assert render(tree, configs) == outputs  # byte-identical across runs


def _idl_errors(tree, old: str, new: str) -> tuple[list[str], str]:
    path = tree / "interfaces" / "idl" / "head_boards.yaml"
    text = path.read_text().replace(old, new)
    path.write_text(text)
    with pytest.raises(IdlErrors) as info:
        _compile(tree)
    return [str(e) for e in info.value.errors], text


def test_board_config_names_a_known_protocol(tree):
    errs, text = _idl_errors(tree, "protocol: motor_control", "protocol: motor_kontrol")
    line = text[:text.index("motor_kontrol")].count("\n") + 1
    assert errs == [f"interfaces/idl/head_boards.yaml:{line}:11: error: unknown CAN protocol 'motor_kontrol' "
                    "(known: motor_control)"]


def test_board_config_names_known_broadcasts(tree):
    errs, text = _idl_errors(tree, "broadcasts: [position, status,", "broadcasts: [position, stat,")
    line = text[:text.index("stat,")].count("\n") + 1
    assert errs == [f"interfaces/idl/head_boards.yaml:{line}:24: error: unknown broadcast 'stat' (the "
                    "motor_control protocol has: position, pid_output, status, current, velocity, supply)"]


def test_board_config_needs_its_parameter_file(tree):
    errs, _ = _idl_errors(tree, "parameters: hardware/head-parameters.yaml", "parameters: hardware/no-such.yaml")
    assert len(errs) == 1 and "cannot read the parameter file hardware/no-such.yaml (No such file or directory)" in errs[0]


# ---- holding brakes: the firmware's has_brake from drives.<joint>.brake ------------------------

def test_the_compiled_table_marks_the_braked_axes(build_dir, params, ini):
    """has_brake is 1 exactly on the axes whose motor carries a brake in the parameter file (pitch and roll), and the
    driver config's [GENERAL] brake, which the board simulator reads, says the same."""
    program = build_dir / "print_brakes.c"
    program.write_text("""
#include <stdio.h>
#include "generated/robogene_head_board_config.h"
int main(void) {
  for (size_t b = 0; b < ROBOGENE_BOARD_COUNT; ++b)
    for (int a = 0; a < 2; ++a) printf("%s %u\\n", robogene_board_configs[b].axes[a].joint,
                                       robogene_board_configs[b].axes[a].has_brake);
  return 0;
}
""")
    exe = build_dir / "print_brakes"
    cmd = [CC, "-std=c99", "-Wall", "-Wextra", "-Werror", f"-I{FIRMWARE}", str(program), "-o", str(exe)]
    result = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    run = subprocess.run([str(exe)], capture_output=True, text=True, timeout=30)
    table = {line.split()[0]: int(line.split()[1]) for line in run.stdout.splitlines()}
    braked = {j for j, d in params["drives"].items() if d.get("brake")}
    assert braked == {"neck_pitch", "neck_roll"}
    assert table == {j: int(j in braked) for j in table}
    assert dict(zip(ini["GENERAL"]["axis_names"], ini["GENERAL"]["brake"])) == {j: table[j] for j in ini["GENERAL"]["axis_names"]}


def test_a_brake_travels_to_the_firmware_table(tree):
    """Taking roll's brake out of the parameter file clears its has_brake; pitch keeps its own."""
    _edit(tree, (", bearing: skf-61800-2RS, bearings: 1, brake: spec-brake-23-12V-8mNm}",
                 ", bearing: skf-61800-2RS, bearings: 1}"))
    header = render(tree, ["firmware-can"])["hardware/electronics/firmware/generated/robogene_head_board_config.h"]
    # has_brake, then the joint correction limit, end each axis's entry
    rows = re.findall(r'\{"(\w+)", -?\d+,.*?(\d)u, -?\d+\}', header, re.S)
    assert dict(rows) == {"neck_pitch": "1", "neck_roll": "0", "neck_yaw": "0", "eyes_tilt": "0",
                          "eyes_version": "0", "eyes_vergence": "0"}, rows


def test_a_brake_on_a_coupled_eye_motor_is_refused(tree):
    """An eye pan motor serves both version and vergence: the board's brake output follows one axis."""
    errs, text = _errors(tree, "left_eye_pan:  {motor: faulhaber-1717T012SR, gearhead: faulhaber-16-7-43, "
                               "encoder: faulhaber-IE2-512-17}",
                         "left_eye_pan:  {motor: faulhaber-1717T012SR, gearhead: faulhaber-16-7-43, "
                         "encoder: faulhaber-IE2-512-17, brake: spec-brake-23-12V-8mNm}")
    assert any("motor_control.joints.eyes_version: left_eye_pan carries a brake, but a board drives brakes only "
               "on uncoupled axes" in e for e in errs), errs


# ---- the joint loop: motor_control.joint_correction_limit_deg ---------------------------------

LIMITS_LINE = "  joint_correction_limit_deg: {neck_pitch: 3, neck_roll: 3, neck_yaw: 3, eyes_tilt: 3}\n"


def test_the_joints_closed_on_their_encoders_get_their_correction_limit(tree):
    """Every joint with a joint encoder on an uncoupled board has its limit, in counts in the firmware's table and in
    degrees in head.ini; the eye joints have none (0: on their motor encoders)."""
    axes = {a.joint: a for b in _compile(tree).board_configs[0].boards for a in b.axes if a}
    assert {j: a.joint_correction_limit_deg for j, a in axes.items()} == {
        "neck_pitch": 3, "neck_roll": 3, "neck_yaw": 3, "eyes_tilt": 3, "eyes_version": 0, "eyes_vergence": 0}
    assert axes["neck_yaw"].joint_correction_limit_counts == round(3 * axes["neck_yaw"].counts_per_degree)


def test_the_compiled_table_and_head_ini_carry_the_correction_limit(build_dir, ini):
    program = build_dir / "print_correction.c"
    program.write_text('#include <stdio.h>\n#include "robogene_head_board_config.h"\nint main(void) {\n'
                       '  for (unsigned b = 0; b < ROBOGENE_BOARD_COUNT; ++b) for (unsigned a = 0; a < 2; ++a)\n'
                       '    printf("%s %d %.9g\\n", robogene_board_configs[b].axes[a].joint,\n'
                       '           (int)robogene_board_configs[b].axes[a].joint_correction_limit,\n'
                       '           (double)robogene_board_configs[b].axes[a].counts_per_degree);\n  return 0;\n}\n')
    exe = build_dir / "print_correction"
    subprocess.run([CC, "-std=c99", "-Wall", "-Werror", f"-I{FIRMWARE / 'generated'}", str(program), "-o", str(exe)],
                   check=True, timeout=120)
    rows = [line.split() for line in subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout.splitlines()]
    table = {name: (int(counts), float(cpd)) for name, counts, cpd in rows}
    general = ini["GENERAL"]
    for name, deg in zip(general["axis_names"], general["joint_correction_limit"]):
        counts, cpd = table[name]
        assert counts == round(deg * cpd), name
    assert dict(zip(general["axis_names"], general["joint_correction_limit"]))["neck_pitch"] == 3


def test_a_joint_with_an_encoder_needs_its_correction_limit(tree):
    errs, _ = _errors(tree, LIMITS_LINE, LIMITS_LINE.replace(" neck_yaw: 3,", ""))
    assert any(e.endswith("error: motor_control.joint_correction_limit_deg: neck_yaw has a joint encoder, which its "
                          "board closes the position on: give motor_control.joint_correction_limit_deg.neck_yaw (deg)")
               for e in errs), errs


@pytest.mark.parametrize("value", ["0", "-1", "10.5"])
def test_a_correction_limit_outside_its_range_is_refused(tree, value):
    errs, text = _errors(tree, LIMITS_LINE, LIMITS_LINE.replace("neck_roll: 3", f"neck_roll: {value}"))
    assert any(e.startswith(_at(text, "neck_roll: " + value, len("neck_roll: "))) and
               "motor_control.joint_correction_limit_deg.neck_roll: " in e and "outside 0 (excluded)..10" in e
               for e in errs), errs


def test_a_joint_without_an_encoder_takes_no_correction_limit(tree):
    errs, _ = _errors(tree, LIMITS_LINE, LIMITS_LINE.replace("eyes_tilt: 3}", "eyes_tilt: 3, eyes_version: 2}"))
    assert any(e.endswith("error: motor_control.joint_correction_limit_deg.eyes_version: eyes_version takes no joint "
                          "correction limit: it has no joint encoder to close its position on") for e in errs), errs


def test_with_pan_sensors_the_eye_joints_need_their_correction_limit_too(tree):
    """With an AS5048A on each pan (an edited copy; the real eyes have none) version and vergence are closed on the
    two sensors like the neck on its own: each needs its limit, and takes it."""
    path = tree / "hardware" / "head-parameters.yaml"
    path.write_text(_with_pan_encoder(_with_pan_encoder(path.read_text(), LEFT_DRIVE), RIGHT_DRIVE))
    errs, _ = _errors(tree, LIMITS_LINE, LIMITS_LINE.replace("eyes_tilt: 3}", "eyes_tilt: 3, eyes_vergence: 2}"))
    assert any(e.endswith("error: motor_control.joint_correction_limit_deg: eyes_version has a joint encoder, which "
                          "its board closes the position on: give motor_control.joint_correction_limit_deg.eyes_version "
                          "(deg)") for e in errs), errs
    text = path.read_text().replace("eyes_tilt: 3, eyes_vergence: 2}", "eyes_tilt: 3, eyes_version: 1.5, eyes_vergence: 2}")
    path.write_text(text)
    axes = {a.joint: a for b in _compile(tree).board_configs[0].boards for a in b.axes if a}
    assert axes["eyes_version"].joint_correction_limit_deg == 1.5 and axes["eyes_vergence"].joint_correction_limit_deg == 2
