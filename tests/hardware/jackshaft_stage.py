# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""What the tests of each jackshaft stage (test_tilt_jackshaft.py, test_yaw_jackshaft.py) read back from the CAD:
where torque_paths.<joint> and the drawn stage disagree. Parts are measured in the stage's own frame (its axis
along +y from the gearhead to the pulley), whatever way the stage stands in its link."""
from robogene_head.geom import distance, exact_bounds
from robogene_head.parts import jackshaft, mounts

ELEMENTS = ["clamp", "clamp", "set_screw", "belt", "set_screw"]


def span_y(stage: jackshaft.Stage, part) -> tuple[float, float]:
    """A part's extent along the stage's axis (stage frame y)."""
    shape = part.shape if stage.placement is None else part.shape.moved(stage.placement.inverse)
    (_, y0, _), (_, y1, _) = exact_bounds(shape)
    return y0, y1


def mismatches(params, parts, stage: jackshaft.Stage) -> list[str]:
    """Where torque_paths.<joint> and the CAD disagree (empty: they agree)."""
    j = stage.joint
    out = []
    path = list(params.root.node("torque_paths").raw(j))
    kinds = [e["element"] for e in path]
    if kinds != ELEMENTS:
        return [f"elements {kinds}"]
    n = jackshaft.node(params, stage)
    coupling = jackshaft.coupling(params, stage)
    screw_key = coupling.text("screw")
    screw = params.purchased(screw_key)
    gear = params.purchased(params.drive(j).text("gearhead"))
    shaft = n.node("shaft").num("diameter")
    lay = jackshaft.layout(params, stage)
    jack = span_y(stage, parts[f"{j}_jackshaft"])
    gear_shaft_end = span_y(stage, parts[f"{j}_gearhead"])[1]
    screws = [span_y(stage, parts[f"{j}_coupling_screw_{i}"]) for i in range(2)]
    # each clamp element: its shaft is the bore of the half whose screw sits over that shaft, one screw per half
    for element, bore, over in ((path[0], coupling.vec("bores", 2)[0], (lay.gearhead_face, gear_shaft_end)),
                                (path[1], coupling.vec("bores", 2)[1], jack)):
        d = gear.num("shaft_diameter") if element["shaft"] == "gearhead" else element["shaft"]
        if d != bore:
            out.append(f"clamp on {d:g} mm, the coupling's bore is {bore:g}")
        held = [s for s in screws if over[0] <= s[0] and s[1] <= over[1]]
        if element["count"] != len(held):
            out.append(f"clamp of {element['count']} screws, {len(held)} drawn over its shaft")
        if element["screw_diameter"] != screw.num("diameter") or element["strength_class"] != screw.text("strength_class"):
            out.append(f"clamp screw M{element['screw_diameter']:g} {element['strength_class']}, drawn {screw_key}")
    # the motor pulley's set screws on the jackshaft, each reaching its flat
    hub = mounts.motor_hub(params, j)
    drawn = [p for name, p in parts.items() if name.startswith(f"{j}_motor_pulley_set_screw_")]
    if path[2]["shaft"] != shaft or path[2]["count"] != len(drawn) or path[2]["screw"] != hub.text("set_screw"):
        out.append(f"pulley set screws {path[2]}, drawn {len(drawn)} x {hub.text('set_screw')} on {shaft:g}")
    fit = params.geometry("clearances").num("fit_tolerance")
    if any(distance(s.shape, parts[f"{j}_jackshaft"].shape) > fit for s in drawn):
        out.append("a set screw does not reach the jackshaft")
    # the belt stage's stock is the one its pulleys are drawn for
    profile = params.purchased(mounts.belt_key(params, j)).text("profile")
    teeth = int(mounts.stage(params, j).num("motor_teeth"))
    if not parts[f"{j}_motor_pulley"].design.startswith(f"{profile.lower()}-pulley-{teeth}T"):
        out.append(f"the motor pulley {parts[f'{j}_motor_pulley'].design} is not a {teeth}T {profile} pulley")
    return out
