# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Writes tests/can/vectors.json: one frame per message of the protocol, with values that exercise
every field (signs, scaling, enums, flags), from the Python codec. The hand-written vectors in the
file (`"origin": "reference"`, byte layouts from the reference facts) and the malformed frames are
kept as they are. `make generate` runs it (codegen/generated-manifest.yaml)."""
import json
import sys
import types
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
VECTORS = HERE / "vectors.json"


def _codec():
    robogene = types.ModuleType("robogene")
    robogene.__path__ = [str(ROOT / "runtime" / "python" / "robogene")]
    sys.modules.setdefault("robogene", robogene)
    from robogene import can
    return can


def sample(can, message_cls, seed: int):
    """Values far from zero in every byte, negative where the field is signed."""
    values = {}
    for k, f in enumerate(message_cls.FIELDS):
        bits = 8 * f.size
        if f.kind == "enum":
            members = list(f.type)
            values[f.name] = members[(seed + k) % len(members)]
        elif f.kind == "flags":
            bits_set = list(f.type)
            values[f.name] = f.type(bits_set[(seed + k) % len(bits_set)] | bits_set[-1])
        elif f.kind == "bool":
            values[f.name] = (seed + k) % 2 == 0
        else:
            magnitude = (0x5A3C96E1 * (seed + 7 * k + 1)) % (1 << (bits - 1))
            raw = -magnitude if f.signed and (seed + k) % 2 else magnitude
            values[f.name] = raw * f.scale + f.offset if f.kind == "real" else raw
    return message_cls(**values)


def generated(can) -> list[dict]:
    out = []
    for seed, (name, cls) in enumerate(sorted(can.MESSAGES.items())):
        m = sample(can, cls, seed)
        if cls.KIND == "request":
            env = can.command(1 + seed % 14, seed % 2, m)
        elif cls.KIND == "reply":
            env = can.reply(1 + seed % 14, seed % 2, m)
        else:
            env = can.broadcast(1 + seed % 14, m)
        out.append({"origin": "generated", "text": can.to_text(env), "frame": str(can.encode(env))})
    return out


def main(argv: list[str]) -> None:
    """`--out DIR` writes DIR/vectors.json instead (make generate: the manifest's can-vectors)."""
    out = Path(argv[argv.index("--out") + 1]) / VECTORS.name if "--out" in argv else VECTORS
    can = _codec()
    data = json.loads(VECTORS.read_text())
    data["frames"] = [v for v in data["frames"] if v["origin"] != "generated"] + generated(can)
    out.write_text(json.dumps(data, indent=1) + "\n")
    print(f"{out}: {len(data['frames'])} frames, {len(data['malformed'])} malformed")


if __name__ == "__main__":
    main(sys.argv[1:])
