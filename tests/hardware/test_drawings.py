# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The machined parts' drawings are real FreeCAD TechDraw pages, and the dimensions printed on them are
right: checked against the STEP files read independently (CadQuery/OpenCASCADE), and on a test part
whose dimensions are known."""
import json
import math
import re
import subprocess
from collections import Counter
from pathlib import Path

import cadquery as cq
import pytest
from OCP.Bnd import Bnd_Box
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepLProp import BRepLProp_SLProps
from OCP.GeomAbs import GeomAbs_Cylinder
from OCP.TopAbs import TopAbs_REVERSED

import step_holes
from drawing_svg import circle_of, ring_gaps, strokes, title_block
from robogene_head import freecad, threads

NUMBER = re.compile(r"(?<![\d.])\d+(?:\.\d+)?")
# pdftotext puts each character of a vertical label on a line of its own ("⌀\n4\n.\n4"), so
# whitespace may stand between the digits and the decimal point; it is dropped before the number is read.
DIAMETER = re.compile(r"⌀\s*(\d+(?:\s*\.\s*\d+)?)")


def pdf_text(pdf: Path) -> str:
    return unsplit(subprocess.run(["pdftotext", "-raw", str(pdf), "-"], capture_output=True, text=True, check=True,
                                  timeout=60).stdout)


def unsplit(text: str) -> str:
    """Join the characters of a vertical label back into one line. A run of one-character lines is a label when
    it holds a decimal point or starts with ⌀ ("⌀\n1\n1\n.\n5\n5" is ⌀11.55); other runs stay as they are,
    since two one-digit labels print the same as a vertical two-digit one."""
    out, run = [], []

    def flush():
        out.extend(["".join(run)] if len(run) > 1 and ("." in run or run[0] == "⌀") else run)
        run.clear()
    for line in text.split("\n"):
        if len(line.strip()) == 1:
            if line.strip() == "⌀":   # a diameter starts a new label
                flush()
            run.append(line.strip())
            continue
        flush()
        out.append(line)
    flush()
    return "\n".join(out)


def test_vertical_labels_are_read_whole():
    text = unsplit("4× ⌀2.2\n⌀\n1\n1\n.\n5\n5\n⌀\n5\n.\n8\n⌀19\n6\n8\n112\n1\n6\n.\n5\nSCALE 1:1")
    assert [float(d) for d in DIAMETER.findall(text)] == [2.2, 11.55, 5.8, 19]
    assert numbers(text) == [4, 2.2, 11.55, 5.8, 19, 6, 8, 112, 16.5, 1, 1]


def svg_text(svg: Path) -> str:
    return "\n".join(t for t in re.findall(r">([^<>]+)</t", svg.read_text()) if t.strip())


def numbers(text: str) -> list:
    return [float(n) for n in NUMBER.findall(text)]


def exact_extents(step: Path) -> tuple:
    """Size along X, Y, Z from OpenCASCADE's optimal bounding box (no tolerance gap, curves exact)."""
    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(cq.importers.importStep(str(step)).val().wrapped, box, False, False)
    x0, y0, z0, x1, y1, z1 = box.Get()
    return x1 - x0, y1 - y0, z1 - z0


def cylinders(step: Path) -> list:
    """(diameter, is_hole) of every cylindrical face: a hole's material lies outside its radius."""
    out = []
    for face in cq.importers.importStep(str(step)).val().Faces():
        surf = BRepAdaptor_Surface(face.wrapped)
        if surf.GetType() != GeomAbs_Cylinder:
            continue
        u = (surf.FirstUParameter() + surf.LastUParameter()) / 2
        v = (surf.FirstVParameter() + surf.LastVParameter()) / 2
        props = BRepLProp_SLProps(surf, u, v, 1, 1e-6)
        normal = props.Normal()
        if face.wrapped.Orientation() == TopAbs_REVERSED:
            normal.Reverse()
        cyl = surf.Cylinder()
        p, o, a = props.Value(), cyl.Location(), cyl.Axis().Direction()
        d = [p.X() - o.X(), p.Y() - o.Y(), p.Z() - o.Z()]
        along = d[0] * a.X() + d[1] * a.Y() + d[2] * a.Z()
        radial = (d[0] - along * a.X(), d[1] - along * a.Y(), d[2] - along * a.Z())
        dot = radial[0] * normal.X() + radial[1] * normal.Y() + radial[2] * normal.Z()
        out.append((2 * cyl.Radius(), dot < 0))
    return out


def missing(wanted, printed, tol=0.1) -> list:
    return [w for w in wanted if not any(abs(w - p) <= tol for p in printed)]


@pytest.fixture(scope="module")
def machined(assembly):
    return sorted({p.design for p in assembly.parts if p.kind == "machined"})


def test_every_machined_part_has_a_pdf_and_an_svg_drawing(fab, machined):
    drawings = fab / "drawings"
    assert sorted(p.stem for p in drawings.glob("*.pdf")) == machined
    assert sorted(p.stem for p in drawings.glob("*.svg")) == machined
    for name in machined:
        assert (drawings / f"{name}.pdf").read_bytes().startswith(b"%PDF"), name
        assert "FreeCAD SVG Export" in (drawings / f"{name}.svg").read_text(), name


def test_the_overall_extents_printed_are_those_of_the_step(fab, machined):
    for name in machined:
        extents = exact_extents(fab / "step" / f"{name}.step")
        for text in (pdf_text(fab / "drawings" / f"{name}.pdf"), svg_text(fab / "drawings" / f"{name}.svg")):
            assert missing(extents, numbers(text)) == [], (name, extents, numbers(text))


def test_hole_diameters_are_printed_and_every_diameter_is_a_real_one(fab, machined):
    report = {d["name"]: d for d in json.loads((fab / "reports" / "drawings.json").read_text())["drawings"]}
    for name in machined:
        cyl = cylinders(fab / "step" / f"{name}.step")
        printed = sorted(float(re.sub(r"\s", "", d)) for d in DIAMETER.findall(pdf_text(fab / "drawings" / f"{name}.pdf")))
        assert printed == sorted(float(re.sub(r"\s", "", d)) for d in DIAMETER.findall(svg_text(fab / "drawings" / f"{name}.svg"))), name
        # a tapped hole is called out by its thread ("M3"), drawn at its size
        sizes = printed + [d["value"] for d in report[name]["dimensions"] if d.get("symbol") == "M"]
        holes = [d for d, hole in cyl if hole]
        if holes:
            assert any(abs(p - h) <= 0.01 for p in sizes for h in holes), (name, holes, sizes)
        # every ⌀ on the sheet is the diameter of a cylinder of the part, or of its round outline
        outline = max(exact_extents(fab / "step" / f"{name}.step")[:2])
        assert missing(printed, [d for d, _ in cyl] + [outline], tol=0.01) == [], (name, printed, cyl)


def test_the_report_lists_the_techdraw_dimensions_of_each_view(fab, machined):
    report = {d["name"]: d for d in json.loads((fab / "reports" / "drawings.json").read_text())["drawings"]}
    assert sorted(report) == machined
    for name in machined:
        entry = report[name]
        assert entry["sheet"] in ("A4", "A3") and entry["pdf"] == f"{name}.pdf"
        views = {d["view"] for d in entry["dimensions"]}
        assert views == {"front", "left", "top"}, name
        printed = numbers(pdf_text(fab / "drawings" / f"{name}.pdf"))
        assert missing([d["value"] for d in entry["dimensions"]], printed, tol=0.006) == [], name


def test_the_title_block_and_notes_are_filled(fab, machined, params):
    report = {d["name"]: d for d in json.loads((fab / "reports" / "drawings.json").read_text())["drawings"]}
    parts = json.loads((fab / "parts.json").read_text())
    materials = {p["design"]: p["material"] for p in parts}
    for name in machined:
        text = svg_text(fab / "drawings" / f"{name}.svg")
        scale = report[name]["scale"]
        label = f"{scale:g}:1" if scale >= 1 else f"1:{1 / scale:g}"
        for field in (name, materials[name], label, "CERN-OHL-S-2.0", f"step/{name}.step", "UNITS: mm",
                      "FIRST-ANGLE PROJECTION", report[name]["sheet"]):
            assert field in text, (name, field)


# The hidden-hole block: 40 x 30 x 10, three blind holes that each open away from the view along their axis.
# (diameter, depth, mouth on the block's face, axis pointing into the block, view that sees it from behind)
HIDDEN_HOLES = ((4.0, 6.0, (12, 30, 5), (0, -1, 0), "front"),     # opens towards +Y
                (5.0, 4.0, (28, 15, 0), (0, 0, 1), "top"),        # opens towards -Z
                (3.0, 5.0, (0, 10, 5), (1, 0, 0), "left"))        # opens towards -X: seen from -X, visible
HIDDEN_BLOCK = (40, 30, 10)

# The callout block: 50 x 40 x 10, with along Z a Ø5 hole 6 deep from the top, two Ø4 through, a Ø2.2 through
# counterbored Ø4.4 x 2.2 from below, and an M3 tapped 7 deep from the top (its thread as the build would say).
CALLOUT_BLOCK = (50, 40, 10)
CALLOUT_THREADS = [{"thread": "M3", "diameter": 3.0, "pitch": 0.5, "tap_drill": 2.5, "point": [40.0, 30.0, 0.0],
                    "direction": [0.0, 0.0, 1.0], "span": [3.0, 10.0]}]
CALLOUT_TEXTS = ["⌀5 ↧6", "2× ⌀4", "⌀2.2", "⌴⌀4.4 ↧2.2", "M3 ↧7"]


# A character is taken as 0.6 text heights wide: more than the sans FreeCAD falls back to for Tahoma (DejaVu
# Sans, 0.49 to 0.59 on these texts) and than Tahoma itself.
CHAR_WIDTH = 0.6


def text_boxes_outside_their_cells(svg: str) -> list:
    """Title-block texts whose box (estimated width, one text height high) leaves the cell it starts in, or
    overlaps another text."""
    lines, texts = title_block(svg)
    vertical = [(x0, min(y0, y1), max(y0, y1)) for x0, y0, x1, y1 in lines if x0 == x1]
    horizontal = [(y0, min(x0, x1), max(x0, x1)) for x0, y0, x1, y1 in lines if y0 == y1]
    bad = []
    boxes = []
    for t in texts:
        box = (t.x, t.y - t.size, t.x + CHAR_WIDTH * t.size * len(t.text), t.y)
        right = min(x for x, a, b in vertical if x > t.x and a < t.y < b + 1e-9)
        top = max(y for y, a, b in horizontal if y < t.y and a <= t.x <= b)
        bottom = min(y for y, a, b in horizontal if y >= t.y and a <= t.x <= b)
        if box[2] > right or box[1] < top or box[3] > bottom:
            bad.append((t.text, round(t.size, 2), round(box[2], 1), right))
        boxes.append((t, box))
    for i, (t, a) in enumerate(boxes):
        for u, b in boxes[i + 1:]:
            if a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]:
                bad.append((t.text, u.text))
    return bad


def test_every_title_block_text_fits_its_cell(fab, machined, known_parts):
    """The part name in the "Part number" cell, the licence line, every label and value: each inside the cell it
    starts in and clear of the others, at the size the page gives it."""
    _, folder = known_parts
    pages = [fab / "drawings" / f"{name}.svg" for name in machined] + sorted(folder.glob("*.svg"))
    for page in pages:
        assert text_boxes_outside_their_cells(page.read_text()) == [], page.name
    # a longer name than any part's is still fitted, not left to overflow
    assert any(len(name) >= 21 for name in machined)


@pytest.fixture(scope="module")
def known_parts(tmp_path_factory):
    """Four parts of known size drawn in one FreeCAD session:
    - a 60 x 40 x 12 block with Ø6.6 and Ø4.5 holes through its top and a Ø3 hole through its front;
    - a 50 x 16 x 6 slot-shaped plate (round ends, so no vertex at its left and right extremes) with a
      Ø5 hole in the middle;
    - the hidden-hole block (HIDDEN_HOLES);
    - the callout block (CALLOUT_BLOCK)."""
    folder = tmp_path_factory.mktemp("known")
    block = cq.Solid.makeBox(60, 40, 12)
    for d, at, axis, length in ((6.6, (10, 8, 0), (0, 0, 1), 12), (4.5, (45, 30, 0), (0, 0, 1), 12),
                                (3.0, (30, 0, 6), (0, 1, 0), 40)):
        block = block.cut(cq.Solid.makeCylinder(d / 2, length, cq.Vector(*at), cq.Vector(*axis)))
    cq.exporters.export(cq.Workplane().add(block), str(folder / "test_block.step"))
    slot = cq.Workplane("XY").slot2D(50, 16).extrude(6).faces(">Z").workplane().hole(5)
    cq.exporters.export(slot, str(folder / "test_slot.step"))
    hidden = cq.Solid.makeBox(*HIDDEN_BLOCK)
    for d, depth, at, axis, _ in HIDDEN_HOLES:
        hidden = hidden.cut(cq.Solid.makeCylinder(d / 2, depth, cq.Vector(*at), cq.Vector(*axis)))
    cq.exporters.export(cq.Workplane().add(hidden), str(folder / "test_hidden.step"))
    block = cq.Solid.makeBox(*CALLOUT_BLOCK)
    for d, at, depth in ((5.0, (10, 10, 4), 6), (4.0, (25, 10, 0), 10), (4.0, (25, 30, 0), 10), (2.2, (10, 30, 0), 10),
                         (4.4, (10, 30, 0), 2.2), (3.0, (40, 30, 3), 7)):
        block = block.cut(cq.Solid.makeCylinder(d / 2, depth, cq.Vector(*at), cq.Vector(0, 0, 1)))
    cq.exporters.export(cq.Workplane().add(block), str(folder / "test_callouts.step"))
    jobs = [freecad.DrawingJob(n, folder / f"{n}.step", "aluminium-6082", 2700.0)
            for n in ("test_block", "test_slot", "test_hidden")]
    jobs.append(freecad.DrawingJob("test_callouts", folder / "test_callouts.step", "aluminium-6082", 2700.0,
                                   threads=CALLOUT_THREADS))
    data = freecad.draw(jobs, folder / "drawings")
    return {d["name"]: d for d in data["drawings"]}, folder / "drawings"


def dimension_set(entry) -> set:
    return {(d["view"], d["kind"], d["type"], round(d["value"], 3)) for d in entry["dimensions"]}


def test_a_part_of_known_size_is_dimensioned_exactly(known_parts):
    """Every extent, diameter and hole position must be printed, positions from the left and bottom edges."""
    drawings, folder = known_parts
    assert dimension_set(drawings["test_block"]) == {
        ("front", "extent", "DistanceX", 60), ("front", "extent", "DistanceY", 12),
        ("left", "extent", "DistanceX", 40), ("left", "extent", "DistanceY", 12),
        ("top", "extent", "DistanceX", 60), ("top", "extent", "DistanceY", 40),
        ("top", "position", "DistanceX", 10), ("top", "position", "DistanceX", 45),
        ("top", "position", "DistanceY", 8), ("top", "position", "DistanceY", 30),
        ("top", "diameter", "Diameter", 6.6), ("top", "diameter", "Diameter", 4.5),
        ("front", "position", "DistanceX", 30), ("front", "position", "DistanceY", 6),
        ("front", "diameter", "Diameter", 3),
    }
    text = pdf_text(folder / "test_block.pdf")
    assert sorted(float(re.sub(r"\s", "", d)) for d in DIAMETER.findall(text)) == [3.0, 4.5, 6.6]
    assert missing([60, 40, 12, 10, 45, 8, 30, 6], numbers(text), tol=1e-9) == []
    # and a sheet that printed 60 where 60.6 was due would be caught
    assert missing([60.6], numbers(text)) == [60.6]


def test_an_extreme_on_a_curve_is_dimensioned_to_the_curve(known_parts):
    """The slot's ends are arcs: its length runs to their apexes (cosmetic vertices), not to the arcs' ends."""
    drawings, folder = known_parts
    assert dimension_set(drawings["test_slot"]) == {
        ("front", "extent", "DistanceX", 50), ("front", "extent", "DistanceY", 6),
        ("left", "extent", "DistanceX", 16), ("left", "extent", "DistanceY", 6),
        ("top", "extent", "DistanceX", 50), ("top", "extent", "DistanceY", 16),
        ("top", "position", "DistanceX", 25), ("top", "position", "DistanceY", 8),
        ("top", "diameter", "Diameter", 5),
    }
    assert missing([50, 16, 6, 25, 8], numbers(pdf_text(folder / "test_slot.pdf")), tol=1e-9) == []


# model axis -> (view, sign) of the view's across and up directions: front looks from -Y, left from -X, top from +Z
VIEW_AXES = {"front": ((0, 1), (2, 1)), "left": ((1, -1), (2, 1)), "top": ((0, 1), (1, 1))}


def test_a_hole_that_opens_away_from_the_view_is_drawn_dashed(known_parts):
    """A blind hole seen from behind is a dashed circle at its place in the view along its axis: in the SVG a
    path drawn with a dash of 1 to 4 mm and a gap of at least 0.3 mm (ISO 128-20 proportions for a narrow
    line), and in the PDF a ring with gaps in the ink. A visible hole is a solid circle."""
    drawings, folder = known_parts
    entry = drawings["test_hidden"]
    svg = (folder / "test_hidden.svg").read_text()
    page_height = 210.0 if entry["sheet"] == "A4" else 297.0
    lines = strokes(svg)
    dashed = [s for s in lines if s.dash]
    assert dashed and all(1.0 <= s.dash[0] <= 4.0 and s.dash[1] >= 0.3 for s in dashed), [s.dash for s in dashed]
    scale = entry["scale"]
    for d, depth, at, axis, view in HIDDEN_HOLES:
        (ia, sa), (ib, sb) = VIEW_AXES[view]
        cx, cy = entry["views"][view]
        # TechDraw centres a view on the part's box; page y runs down
        want = (cx + sa * (at[ia] - HIDDEN_BLOCK[ia] / 2) * scale,
                page_height - cy - sb * (at[ib] - HIDDEN_BLOCK[ib] / 2) * scale)
        found = {bool(s.dash) for s in lines for line in s.lines
                 if (c := circle_of(line)) and math.dist(c[:2], want) < 0.05 and abs(c[2] - d / 2 * scale) < 0.05}
        hidden = view != "left"
        assert hidden in found, (view, d, want, found)
        inked, gaps = ring_gaps(folder / "test_hidden.pdf", want, d / 2 * scale)
        assert inked > 0.5, (view, d, inked)
        assert (gaps >= 2) if hidden else (gaps == 0), (view, d, gaps)


VIEW_OF_AXIS = {1: "front", 0: "left", 2: "top"}     # the principal view that looks along each model axis


def number(value: float) -> str:
    return f"{value:.2f}".rstrip("0").rstrip(".")


def expected_callouts(step: Path, tapped: list) -> Counter:
    """(view, symbol, diameter, suffix) -> number of holes, from the STEP measured here and the build's tapped
    holes: a bore "⌀" (or "M" when tapped), " ↧depth" when blind; a counterbore "⌴⌀" with its depth."""
    out = Counter()
    for h in step_holes.holes(step):
        view = VIEW_OF_AXIS[h.axis]
        is_tapped = any(abs(abs(t["direction"][h.axis]) - 1) < 1e-6 and abs(t["diameter"] - h.diameter) < 1e-3 and
                        math.dist([t["point"][i] for i in range(3) if i != h.axis], h.centre) < 1e-3 and
                        min(t["span"][1], h.faces[-1][2]) - max(t["span"][0], h.faces[0][1]) > 1e-3 for t in tapped)
        suffix = "" if h.through else f" ↧{number(h.depth)}"
        out[(view, "M" if is_tapped else "⌀", round(h.diameter, 2), suffix)] += 1
        for d, depth in h.counterbores:
            out[(view, "⌴⌀", round(d, 2), f" ↧{number(depth)}")] += 1
    return out


def printed_callouts(entry) -> Counter:
    out = Counter()
    for d in entry["dimensions"]:
        if d["kind"] == "diameter":
            count = int(d["prefix"].removesuffix("× ")) if d["prefix"] else 1
            out[(d["view"], d["symbol"], round(d["value"], 2), d["suffix"])] += count
    return out


def callout_texts(entry) -> list:
    return [f"{d['prefix']}{d['symbol']}{number(d['value'])}{d['suffix']}" for d in entry["dimensions"]
            if d["kind"] == "diameter"]


def check_callouts(entry, step: Path, pdf: Path, svg: Path, tapped: list) -> None:
    """Every hole of the STEP is called out in the view along its axis, with its count, diameter or thread,
    depth and counterbore; a diameter that is no hole's is a plain one (a shaft, a round outline). Each callout
    is printed on the PDF and the SVG."""
    expected, printed = expected_callouts(step, tapped), printed_callouts(entry)
    assert {k: printed.get(k) for k in expected} == dict(expected), (entry["name"], expected, printed)
    extra = [k for k in printed if k not in expected]
    assert all(symbol == "⌀" and suffix == "" for _, symbol, _, suffix in extra), (entry["name"], extra)
    pdf_squashed = re.sub(r"\s", "", pdf_text(pdf))
    svg_all = svg_text(svg)
    for text in callout_texts(entry):
        assert text in svg_all, (entry["name"], text)
        assert re.sub(r"\s", "", text) in pdf_squashed, (entry["name"], text)


def test_every_hole_is_called_out_as_the_step_and_the_assembly_have_it(fab, machined, params, assembly):
    """Depths measured here from each STEP solid, threads where the assembly screws a fastener into the hole."""
    report = {d["name"]: d for d in json.loads((fab / "reports" / "drawings.json").read_text())["drawings"]}
    tapped = threads.tapped_holes(params, assembly.parts)
    assert tapped, "no tapped hole in the head"
    for name in machined:
        check_callouts(report[name], fab / "step" / f"{name}.step", fab / "drawings" / f"{name}.pdf",
                       fab / "drawings" / f"{name}.svg", [t.as_dict() for t in tapped.get(name, [])])
    # the gearhead screws' counterbores and a tapped blind hole are among them
    called = [k for name in machined for k in printed_callouts(report[name])]
    assert any(symbol == "⌴⌀" for _, symbol, _, _ in called)
    assert any(symbol == "M" and suffix.startswith(" ↧") for _, symbol, _, suffix in called)


def test_a_part_of_known_holes_is_called_out_exactly(known_parts):
    """The callout block: each kind of hole once, with what the drawing must say about it."""
    drawings, folder = known_parts
    entry = drawings["test_callouts"]
    assert sorted(callout_texts(entry)) == sorted(CALLOUT_TEXTS), callout_texts(entry)
    check_callouts(entry, folder.parent / "test_callouts.step", folder / "test_callouts.pdf",
                   folder / "test_callouts.svg", CALLOUT_THREADS)


def test_a_missing_step_is_reported_by_name(tmp_path):
    with pytest.raises(RuntimeError, match="no_such_part"):
        freecad.draw([freecad.DrawingJob("no_such_part", tmp_path / "no_such_part.step")], tmp_path / "drawings")


def test_only_changed_parts_are_redrawn(tmp_path, monkeypatch):
    """The build's cache: a second run draws nothing; a part whose geometry changed is drawn alone."""
    import io

    from robogene_head import fab
    from robogene_head.cache import Cache
    from robogene_head.progress import Progress

    sessions = []

    def fake_draw(jobs, folder, on_progress=None, timeout=None):
        sessions.append([j.name for j in jobs])
        for i, j in enumerate(jobs):
            for ext in ("pdf", "svg"):
                (folder / f"{j.name}.{ext}").parent.mkdir(parents=True, exist_ok=True)
                (folder / f"{j.name}.{ext}").write_text(j.revision)
            on_progress(i, len(jobs), f"drawn {j.name}")
        return {"drawings": [{"name": j.name, "dimensions": []} for j in jobs]}

    monkeypatch.setattr(freecad, "draw", fake_draw)
    jobs = [freecad.DrawingJob(n, tmp_path / f"{n}.step", "aluminium-6082", 2700.0, "", "rev1") for n in ("a", "b", "c")]
    log = io.StringIO()
    for _ in range(2):
        fab._draw_machined(tmp_path, Cache(tmp_path / "state.json"), Progress(log), jobs)
    jobs[1] = freecad.DrawingJob("b", tmp_path / "b.step", "aluminium-6082", 2700.0, "", "rev2")
    fab._draw_machined(tmp_path, Cache(tmp_path / "state.json"), Progress(log), jobs)
    assert sessions == [["a", "b", "c"], ["b"]]
    assert (tmp_path / "drawings" / "b.pdf").read_text() == "rev2"
    report = json.loads((tmp_path / "reports" / "drawings.json").read_text())
    assert [d["name"] for d in report["drawings"]] == ["a", "b", "c"]
    assert "unchanged" in log.getvalue() and "drawn b" in log.getvalue()
