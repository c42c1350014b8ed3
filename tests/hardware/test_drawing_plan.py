# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The drawing's plan, without FreeCAD: which dimensions a view gets, and where the views go on the sheet."""
import re
import sys

import pytest

from conftest import REPO

sys.path.insert(0, str(REPO / "hardware" / "mechanics" / "freecad"))
import dimension_plan as dp  # noqa: E402
import hole_callouts as hc  # noqa: E402
import hole_features as hf  # noqa: E402
import line_overlay as lo  # noqa: E402
import notes_block as nb  # noqa: E402
import sheet_layout as sl  # noqa: E402
import title_block as tb  # noqa: E402


def rectangle_with_holes():
    """A 60 x 40 outline centred on the view, two Ø6 holes and one Ø3 hole (TechDraw order: corners first,
    then per circle its seam point twice and its centre)."""
    vertices = [(-30, -20), (-30, 20), (30, -20), (30, 20)]
    circles = []
    for i, (x, y, r) in enumerate([(-20, -12, 3), (20, -12, 3), (5, 10, 1.5)]):
        vertices += [(x + r, y), (x + r, y), (x, y)]
        circles.append(dp.Circle(4 + i, x, y, r))
    ext = {"xmin": dp.Extreme(-30, (-30, 0)), "xmax": dp.Extreme(30, (30, 0)),
           "ymin": dp.Extreme(-20, (0, -20)), "ymax": dp.Extreme(20, (0, 20))}
    return vertices, circles, ext


def test_extents_run_between_the_outermost_vertices_nearest_the_dimension_line():
    vertices, circles, ext = rectangle_with_holes()
    plan = dp.plan(vertices, circles, ext, ("X", "Y"))
    (across,) = [d for d in plan.dims if d.kind == "extent" and d.type == "DistanceX"]
    (up,) = [d for d in plan.dims if d.kind == "extent" and d.type == "DistanceY"]
    assert across.value == 60 and across.axis == "X" and across.side == "below"
    # the lower corners: the dimension sits below the view
    assert across.refs == [("vertex", 0), ("vertex", 2)]
    assert up.value == 40 and up.refs == [("vertex", 0), ("vertex", 1)]
    # the overall extent is the outermost line of its stack
    assert across.row == max(d.row for d in plan.dims if d.side == "below")


def test_hole_positions_are_measured_from_the_datum_edges_once_per_coordinate():
    vertices, circles, ext = rectangle_with_holes()
    plan = dp.plan(vertices, circles, ext, ("X", "Y"))
    across = sorted(d.value for d in plan.dims if d.kind == "position" and d.type == "DistanceX")
    up = sorted(d.value for d in plan.dims if d.kind == "position" and d.type == "DistanceY")
    assert across == [10, 35, 50]      # x = -20, 5, 20 from the left edge at -30
    assert up == [8, 30]               # y = -12 (two holes), 10 from the bottom edge at -20
    for d in plan.dims:
        if d.kind == "position":
            assert d.refs[0] == ("vertex", 0)                       # the datum corner
            assert d.refs[1][0] == "vertex" and vertices[d.refs[1][1]] in [(c.x, c.y) for c in circles]


def test_one_diameter_per_size_with_its_count():
    vertices, circles, ext = rectangle_with_holes()
    plan = dp.plan(vertices, circles, ext)
    diameters = {(d.prefix, d.value) for d in plan.dims if d.kind == "diameter"}
    assert diameters == {("2× ", 6), ("", 3)}
    assert all(d.refs[0][0] == "edge" for d in plan.dims if d.kind == "diameter")


def test_a_round_outline_is_given_by_its_diameter_and_is_the_datum():
    vertices = [(5.0, 0.0), (5.0, 0.0), (0.0, 0.0), (1.5, 0.0), (1.5, 0.0)]
    circles = [dp.Circle(0, 0, 0, 5.0), dp.Circle(1, 0, 0, 1.5)]
    ext = {"xmin": dp.Extreme(-5, (-5, 0)), "xmax": dp.Extreme(5, (5, 0)),
           "ymin": dp.Extreme(-5, (0, -5)), "ymax": dp.Extreme(5, (0, 5))}
    plan = dp.plan(vertices, circles, ext)
    assert [d.kind for d in plan.dims] == ["diameter", "diameter"]    # concentric: no position, no linear extent
    assert sorted(d.value for d in plan.dims) == [3.0, 10.0]


def test_an_extreme_on_a_curve_without_a_vertex_gets_a_point():
    # a slot end: the outline reaches x = 34 on an arc whose ends are at x = 30
    vertices = [(-30, -4), (-30, 4), (30, -4), (30, 4)]
    ext = {"xmin": dp.Extreme(-30, (-30, 0)), "xmax": dp.Extreme(34, (34, 0)),
           "ymin": dp.Extreme(-4, (0, -4)), "ymax": dp.Extreme(4, (0, 4))}
    plan = dp.plan(vertices, [], ext)
    (across,) = [d for d in plan.dims if d.type == "DistanceX"]
    assert across.value == 64 and across.refs == [("vertex", 0), ("point", (34, 0))]


def test_diameter_labels_do_not_overlap():
    # four sizes of hole close together: their texts must end up in four separate places
    circles = [dp.Circle(i, 20 + 0.5 * i, 20, 1 + 0.5 * i) for i in range(4)]
    vertices = [(-30, -30), (-30, 30), (30, -30), (30, 30)] + [(c.x, c.y) for c in circles]
    ext = {"xmin": dp.Extreme(-30, (-30, 0)), "xmax": dp.Extreme(30, (30, 0)),
           "ymin": dp.Extreme(-30, (0, -30)), "ymax": dp.Extreme(30, (0, 30))}
    plan = dp.plan(vertices, circles, ext)
    dp.place_labels(plan, 1.0)
    boxes = [dp._label_box(d, 1.0) for d in plan.dims if d.kind == "diameter"]
    assert len(boxes) == 4
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not dp._overlap(a, b)


def boxes_for(x, y, z):
    """ViewBoxes of a part x by y by z mm centred on its views: the front and left views carry their
    extents, the top view also hole positions and diameters."""
    plain = dict(left=12, below=12)
    holes = dict(left=21, below=21, above=14, right=14)
    iso_w, iso_h = (x + y) * 0.707 / 2, ((x + y) * 0.408 + z * 0.816) / 2
    return {"front": sl.ViewBox(-x / 2, x / 2, -z / 2, z / 2, **plain), "left": sl.ViewBox(-y / 2, y / 2, -z / 2, z / 2, **plain),
            "top": sl.ViewBox(-x / 2, x / 2, -y / 2, y / 2, **holes), "iso": sl.ViewBox(-iso_w, iso_w, -iso_h, iso_h)}


@pytest.mark.parametrize("size, sheet, scale", [
    ((11.5, 11.5, 6), "A4", 5.0),        # a small pulley: enlarged on A4
    ((44, 12, 62.5), "A4", 1.0),         # an upright: full size on A4
    ((130, 110, 8), "A3", 1.0),          # a base plate: A4 would need 1:2, A3 takes it full size
    ((400, 300, 300), "A4", 0.2),        # too big for A3 at 1:2; at 1:5 A4 takes it, its isometric view at 1:10
])
def test_sheet_and_scale_follow_the_part_size(size, sheet, scale):
    layout = sl.choose(boxes_for(*size))
    assert (layout.sheet.name, layout.scale) == (sheet, scale)
    frame = layout.sheet.border
    tb = layout.sheet.title_block
    boxes = list(layout.boxes.values())
    assert len(boxes) == 4
    for i, b in enumerate(boxes):
        assert frame[0] <= b[0] and b[2] <= frame[2] and frame[1] <= b[1] and b[3] <= frame[3]
        assert not sl._overlap(b, (tb[0], tb[1], tb[2], layout.notes[3]))
        for other in boxes[i + 1:]:
            assert not sl._overlap(b, other)
    # first-angle arrangement: the left view right of the front, the top view below it, both aligned
    (fx, fy), (lx, ly), (tx, ty) = (layout.centres[v] for v in ("front", "left", "top"))
    assert lx > fx and ly == fy and tx == fx and ty < fy


def test_the_isometric_view_shrinks_rather_than_the_principal_views():
    """A side plate's views fit A3 at 1:1 but leave no corner for its isometric view at 1:1: that one is drawn at
    1:2 rather than every view at 1:2; never more than two standard scales smaller."""
    boxes = {"front": sl.ViewBox(-74, 74, -56, 56, left=75, below=75, above=14.7),
             "left": sl.ViewBox(-3, 3, -56, 56, left=30, below=21, right=15.5),
             "top": sl.ViewBox(-74, 74, -3, 3, left=21, below=30, above=15.5),
             "iso": sl.ViewBox(-54.5, 54.5, -77.2, 77.2)}
    layout = sl.choose(boxes)
    assert (layout.sheet.name, layout.scale, layout.iso_scale) == ("A3", 1.0, 0.5)
    x0, y0, x1, y1 = layout.boxes["iso"]
    il, ir, ib, ia = boxes["iso"].extents(0.5)
    assert (x1 - x0, y1 - y0) == pytest.approx((il + ir, ib + ia))
    for size in [(11.5, 11.5, 6), (44, 12, 62.5), (130, 110, 8), (400, 300, 300)]:
        layout = sl.choose(boxes_for(*size))
        assert layout.iso_scale in sl.SCALES[sl.SCALES.index(layout.scale):sl.SCALES.index(layout.scale) + 3]


def test_a_part_too_big_for_a3_is_refused():
    with pytest.raises(ValueError, match="A3"):
        sl.choose(boxes_for(5000, 4000, 3000))


def test_scale_labels():
    assert [sl.scale_label(s) for s in (5.0, 1.0, 0.5, 0.2)] == ["5:1", "1:1", "1:2", "1:5"]


def test_the_line_overlay_maps_page_millimetres_exactly_and_dashes_hidden_lines():
    """TechDraw sizes a symbol in whole pixels at 3.78 px/mm: the overlay's view box must span exactly what its
    pixel size covers, centred on the view, so its lines fall on TechDraw's; hidden lines are dashed, and every
    width is at least one SVG unit (Qt's SVG writer misscales the dashes of thinner lines)."""
    visible = [[(-30.0, -5.0), (30.0, -5.0), (30.0, 5.0)]]
    hidden = [[(10.0, 2.0), (12.0, 2.0)]]
    svg = lo.svg(visible, hidden)
    width, height = (int(v) for v in re.search(r'width="(\d+)" height="(\d+)"', svg).groups())
    x, y, w, h = (float(v) for v in re.search(r'viewBox="([^"]+)"', svg).group(1).split())
    assert w == pytest.approx(width / lo.PX_PER_MM * lo.UNITS, abs=1e-3)
    assert h == pytest.approx(height / lo.PX_PER_MM * lo.UNITS, abs=1e-3)
    assert (x, y) == pytest.approx((-w / 2, -h / 2), abs=1e-3)
    assert w / lo.UNITS >= 60 and h / lo.UNITS >= 10            # the whole view fits
    paths = re.findall(r"<path ([^>]*)/>", svg)
    dashed = [p for p in paths if "stroke-dasharray" in p]
    solid = [p for p in paths if "stroke-dasharray" not in p]
    assert len(dashed) == 1 and "M1000.0,200.0 L1200.0,200.0" in dashed[0]
    assert len(solid) == 1 and "M-3000.0,-500.0 L3000.0,-500.0 L3000.0,500.0" in solid[0]
    for p in paths:
        assert float(re.search(r'stroke-width="([\d.]+)"', p).group(1)) >= 1
    dash, gap = (float(v) / lo.UNITS for v in re.search(r'stroke-dasharray="([^"]+)"', dashed[0]).group(1).split(","))
    assert 1.0 <= dash <= 4.0 and gap >= 0.3
    with pytest.raises(ValueError):
        lo.svg([], [])


TEMPLATE = """<svg xmlns="http://www.w3.org/2000/svg" xmlns:freecad="http://www.freecadweb.org/wiki/index.php?title=Svg_Namespace">
<g id="titleblock-structure"><rect x="150" y="169" width="140" height="34"/><path d="m 237,169 v 30"/>
<path d="m 237,185 h 53"/></g>
<g id="titleblock-text-non-editable" style="font-size:3px"><text id="l1" x="238" y="184">Part number:</text>
<text id="l2" x="151" y="172">TITLE:</text></g>
<g id="titleblock-text-editable" style="font-size:3px">
<text id="v1" x="257" y="184" freecad:editable="PN"><tspan>PN</tspan></text>
<text id="v2" x="152" y="185" style="fill:#000" freecad:editable="TITLE"><tspan>x</tspan></text></g></svg>"""


def test_title_block_texts_shrink_to_their_cells():
    """A value too long for its cell gets the largest size that fits (estimated conservatively); a short one
    keeps the template's; labels all get the tightest label's size; a text that would need less than 1.8 mm
    is refused."""
    sizes = tb.sizes(TEMPLATE, {"PN": "motor_mount_neck_pitch", "TITLE": "short"})
    assert sizes["v1"] == pytest.approx((290 - tb.GAP - 257) / (tb.EM * 22))
    assert sizes["v2"] == 3.0
    # "Part number:" ends before the value at x = 257; "TITLE:" has the whole cell, but follows it
    assert sizes["l1"] == sizes["l2"] == pytest.approx((257 - tb.GAP - 238) / (tb.EM * 12))
    # a renderer's measured width counts when it is the wider
    assert tb.sizes(TEMPLATE, {"PN": "abc", "TITLE": "x"}, measure=lambda t: 12.0 if t == "abc" else 0.0)["v1"] == pytest.approx(32.5 / 12)
    fitted = tb.fitted(TEMPLATE, {"PN": "motor_mount_neck_pitch", "TITLE": "x" * 60})
    assert re.search(r'<text style="font-size:2\.\d+px" id="v1"', fitted)
    assert re.search(r'id="v2" x="152" y="185" style="fill:#000;font-size:[\d.]+px"', fitted)     # merged into its own style
    with pytest.raises(tb.TitleBlockError, match="PN"):
        tb.sizes(TEMPLATE, {"PN": "x" * 40, "TITLE": "x"})


def block_with_holes():
    """A 60 x 40 x 10 block (z 0..10): a Ø5 hole 6 deep from the top at (10, 10); a Ø2.2 hole through at (30, 20)
    counterbored Ø4.4 x 2 from below; two Ø3 holes 8 deep from the bottom at (50, 10) and (50, 30); a closed Ø2
    cavity at (5, 35), z 4..6. Returns the cylinder segments and the block's material test."""
    segments = [hf.Segment(2, 10, 10, 5.0, 4.0, 10.0), hf.Segment(2, 30, 20, 4.4, 0.0, 2.0),
                hf.Segment(2, 30, 20, 2.2, 2.0, 10.0), hf.Segment(2, 50, 10, 3.0, 0.0, 8.0),
                hf.Segment(2, 50, 30, 3.0, 0.0, 8.0), hf.Segment(2, 5, 35, 2.0, 4.0, 6.0)]

    def inside(x, y, z):
        if not (0 <= x <= 60 and 0 <= y <= 40 and 0 <= z <= 10):
            return False
        return not any(s.lo <= z <= s.hi and (x - s.u) ** 2 + (y - s.v) ** 2 < (s.d / 2) ** 2 for s in segments)
    return segments, inside


def test_holes_are_read_from_their_faces():
    segments, inside = block_with_holes()
    holes = {(h.u, h.v): h for h in hf.classify(segments, inside)}
    assert (5, 35) not in holes                                  # a closed cavity: no hole
    blind = holes[(10, 10)]
    assert not blind.through and blind.depth == pytest.approx(6) and blind.opens == [1] and not blind.counterbores
    cb = holes[(30, 20)]
    assert cb.through and cb.depth is None and cb.main.d == 2.2
    assert [(s.d, end) for s, end in cb.counterbores] == [(4.4, -1)]
    assert holes[(50, 10)].opens == [-1] and holes[(50, 10)].depth == pytest.approx(8)
    # the build's tapped hole: only the one on its axis and span becomes M3
    hf.apply_threads(list(holes.values()), [{"thread": "M3", "diameter": 3.0, "point": [50.0, 10.0, 0.0],
                                             "direction": [0.0, 0.0, 1.0], "span": [0.0, 8.0]}])
    assert holes[(50, 10)].thread == "M3" and holes[(50, 30)].thread == ""
    assert hc.callouts_of(holes[(50, 10)]) == {3.0: ("M", " ↧8")}
    assert hc.callouts_of(cb) == {2.2: ("⌀", ""), 4.4: ("⌴⌀", " ↧2")}
    assert hc.callouts_of(blind) == {5.0: ("⌀", " ↧6")}


def test_circles_of_a_view_get_their_holes_callouts_and_counts():
    """The top view of the block (across X, up Y), centred 0.3 mm off the box's centre as TechDraw may: each
    circle finds its hole; two holes behind each other on one circle count twice; a circle of no hole gets none."""
    segments, inside = block_with_holes()
    segments.append(hf.Segment(2, 50, 10, 3.0, 9.0, 10.0))      # a second Ø3 from the top, in line with (50, 10)
    holes = hf.classify(segments, inside)
    cx, cy = 30.3, 20.0
    circles = [dp.Circle(1, 10 - cx, 10 - cy, 2.5), dp.Circle(2, 30 - cx, 20 - cy, 1.1), dp.Circle(3, 30 - cx, 20 - cy, 2.2),
               dp.Circle(4, 50 - cx, 10 - cy, 1.5), dp.Circle(5, 50 - cx, 30 - cy, 1.5), dp.Circle(6, 0.0, 0.0, 7.0)]
    callouts = hc.label(circles, holes, 2, (1, 0, 0), (0, 1, 0), (30, 20, 5))
    assert [(k.symbol, k.suffix, len(k.holes)) for k in callouts[1]] == [("⌀", " ↧6", 1)]
    assert [(k.symbol, k.suffix) for k in callouts[3]] == [("⌴⌀", " ↧2")]
    assert [(k.symbol, k.suffix, len(k.holes)) for k in callouts[4]] == [("⌀", " ↧1", 1), ("⌀", " ↧8", 1)]
    assert 6 not in callouts
    # a front view (looking along Y) sees none of these holes
    assert hc.label(circles, holes, 1, (1, 0, 0), (0, 0, 1), (30, 20, 5)) == {}
    # in the plan, the two Ø3 8 deep count as two holes however many circles show them
    marked = [dp.Circle(c.edge, c.x, c.y, c.r, k) for c in circles for k in callouts.get(c.edge, [None])]
    ext = {"xmin": dp.Extreme(-30.3, (-30.3, 0)), "xmax": dp.Extreme(29.7, (29.7, 0)),
           "ymin": dp.Extreme(-20, (0, -20)), "ymax": dp.Extreme(20, (0, 20))}
    plan = dp.plan([(-30.3, -20), (29.7, 20)] + [(c.x, c.y) for c in circles], marked, ext)
    texts = sorted(f"{d.prefix}{d.symbol}{d.value:g}{d.suffix}" for d in plan.dims if d.kind == "diameter")
    assert texts == ["2× ⌀3 ↧8", "⌀14", "⌀2.2", "⌀3 ↧1", "⌀5 ↧6", "⌴⌀4.4 ↧2"]


def test_diameter_texts_get_the_room_they_need_at_each_scale():
    """A circle near the right edge: its text reaches past the outline, further at a small scale than at a large
    one relative to the part; the view's box in the layout takes the larger of that and its linear dimensions."""
    circle = dp.Circle(1, 25.0, 0.0, 2.0, hc.Callout("⌴⌀", " ↧2.2", frozenset({0})))
    ext = {"xmin": dp.Extreme(-30, (-30, 0)), "xmax": dp.Extreme(30, (30, 0)),
           "ymin": dp.Extreme(-10, (0, -10)), "ymax": dp.Extreme(10, (0, 10))}
    plan = dp.plan([(-30, -10), (30, 10), (25, 0)], [circle], ext)
    (diameter,) = [d for d in plan.dims if d.kind == "diameter"]
    left, right, below, above = dp.label_room(plan, 1.0, ext)
    assert right > dp.label_width(diameter) - 5 + dp.LEADER * 0.7 - 1 and left == 0
    assert diameter.refs == [("edge", 1)] and diameter.extra == 0.0      # the plan itself is untouched
    box = sl.ViewBox(-30, 30, -10, 10, plan.left, plan.right, plan.below, plan.above,
                     lambda s: dp.label_room(plan, s, ext))
    assert box.extents(1.0)[1] == pytest.approx(30 + right)
    assert box.extents(2.0)[0] == pytest.approx(60 + plan.left)


def test_notes_wrap_to_their_strip():
    lines = nb.wrap(["short", "a note " * 30], 110.0, 3.5)
    assert lines[0] == "short" and len(lines) > 2
    assert all(len(line) * nb.EM * 3.5 <= 110.0 for line in lines)
    assert " ".join(lines[1:]) == ("a note " * 30).strip()
    assert nb.height(len(lines), 3.5) == pytest.approx(len(lines) * nb.LINE_PITCH * 3.5 + 2 * nb.MARGIN)
