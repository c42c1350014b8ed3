# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Build one part's TechDraw page in FreeCAD's GUI: template, projection views, dimensions, title block,
notes. Runs inside FreeCAD (draw_parts.py drives it); TechDraw only exports pages with its GUI loaded."""
from __future__ import annotations

import dataclasses
import functools
import os
import shutil
import tempfile
import time

import FreeCAD
import Part

import dimension_plan
import hole_callouts
import hole_features
import line_overlay
import notes_block
import sheet_layout
import title_block
import view_geometry

# name, direction towards the viewer, drawing's right (XDirection), model axes shown across and up
VIEWS = (
    ("front", (0, -1, 0), (1, 0, 0), ("X", "Z")),
    ("left", (-1, 0, 0), (0, -1, 0), ("Y", "Z")),   # seen from -X, placed right of the front (first angle)
    ("top", (0, 0, 1), (1, 0, 0), ("X", "Y")),     # seen from +Z, placed below the front (first angle)
    ("iso", (1, -1, 1), (1, 1, 0), ("", "")),
)
PRINCIPAL = ("front", "left", "top")
SETTLE_TIMEOUT = 60.0
FORMAT = "%.2w"      # TechDraw: up to two decimals, trailing zeros dropped
VALUE_TOLERANCE = 1e-3
NOTE_SIZE = 3.5      # font size of the notes (2.5 mm capitals, ISO 3098); a part's note may run to several lines
SYMBOL_ROOM = 30.0   # width kept for the projection symbol at the right of the notes strip


class DrawingError(RuntimeError):
    pass


def templates_dir() -> str:
    return os.path.join(FreeCAD.getResourceDir(), "Mod", "TechDraw", "Templates")


def _settle(objects) -> None:
    """Wait until TechDraw has computed every object. In 0.20 a DrawViewPart's hidden-line removal runs in
    a worker thread; the view stays 'Touched' until its geometry is in."""
    from PySide2 import QtWidgets
    app = QtWidgets.QApplication.instance()
    deadline = time.monotonic() + SETTLE_TIMEOUT
    while True:
        app.processEvents()
        pending = [o.Name for o in objects if "Touched" in o.State or "Invalid" in o.State or
                   (o.isDerivedFrom("TechDraw::DrawViewPart") and not o.getVisibleEdges())]
        if not pending:
            break
        if time.monotonic() > deadline:
            raise DrawingError(f"TechDraw did not finish {', '.join(pending)} in {SETTLE_TIMEOUT:.0f} s")
        time.sleep(0.02)
    for _ in range(3):
        app.processEvents()


def _first_angle_symbol() -> str:
    """ISO 5456-2 first-angle projection symbol: the truncated cone, its view from the left drawn right. Drawn in
    0.1 mm units, so that every line width is at least one unit (Qt's SVG writer misscales the dashes of thinner
    lines), and sized in whole pixels at TechDraw's 3.78 px/mm (line_overlay)."""
    px = line_overlay.PX_PER_MM
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{round(26 * px)}" height="{round(12 * px)}" '
            'viewBox="0 0 260 120"><g fill="none" stroke="#000" stroke-width="3.5">'
            '<path d="M10,40 L110,10 L110,110 L10,80 Z"/><circle cx="200" cy="60" r="50"/>'
            '<circle cx="200" cy="60" r="20"/></g><g fill="none" stroke="#000" stroke-width="1.8" '
            'stroke-dasharray="30,10,5,10"><path d="M0,60 H125 M135,60 H265 M200,0 V120"/></g></svg>')


def _text_width(text: str) -> float:
    """Width of a title-block text in text heights, in the font Qt draws the template with (its Tahoma, or the
    font that stands in for it)."""
    from PySide2 import QtGui
    font = QtGui.QFont("tahoma")
    font.setPixelSize(1000)
    return QtGui.QFontMetricsF(font).horizontalAdvance(text) / 1000


class PartPage:
    def __init__(self, doc, entry: dict):
        self.doc = doc
        self.entry = entry
        self.shape = Part.Shape()
        self.shape.read(entry["step"])
        if not self.shape.Solids:
            raise DrawingError(f"{entry['step']}: no solid")
        self.feature = doc.addObject("Part::Feature", "Part")
        self.feature.Shape = self.shape
        self.page = doc.addObject("TechDraw::DrawPage", "Page")
        self.template = doc.addObject("TechDraw::DrawSVGTemplate", "Template")
        self.template.Template = os.path.join(templates_dir(), sheet_layout.SHEETS[0].template)
        self.page.Template = self.template
        self.page.ProjectionType = "First Angle"
        self.views = {}
        for name, direction, xdir, _ in VIEWS:
            v = doc.addObject("TechDraw::DrawViewPart", name.capitalize())
            self.page.addView(v)
            v.Source = [self.feature]
            v.Direction = FreeCAD.Vector(*direction)
            v.XDirection = FreeCAD.Vector(*xdir)
            v.ScaleType = "Custom"
            v.Scale = 1.0
            # Hidden lines in the principal views (drawn dashed by line_overlay); an isometric view shows none.
            v.HardHidden = name in PRINCIPAL
            if name in PRINCIPAL and v.ViewObject is not None:
                v.ViewObject.ArcCenterMarks = True
            self.views[name] = v
        self.dimensions = []
        self.holes = hole_features.classify(
            hole_features.cylinder_segments(self.shape),
            lambda x, y, z: self.shape.isInside(FreeCAD.Vector(x, y, z), 1e-6, True))
        hole_features.apply_threads(self.holes, entry.get("threads", []))
        self.scratch = tempfile.mkdtemp(prefix="robogene-drawing-")   # the page's fitted template

    def _circles(self, name: str, view, visible: list) -> list:
        """The view's full circles to dimension, each hole with its callout: every visible circle, and the hidden
        ones that are holes (those that open away from the view)."""
        _, direction, xdir, _ = next(v for v in VIEWS if v[0] == name)
        up = FreeCAD.Vector(*direction).cross(FreeCAD.Vector(*xdir))
        depth = max(range(3), key=lambda i: abs(direction[i]))
        shown = view_geometry.full_circles(visible)
        hidden = view_geometry.full_circles(view_geometry.hidden_edges(view, len(visible)))
        callouts = hole_callouts.label(shown + hidden, self.holes, depth, xdir, (up.x, up.y, up.z),
                                       tuple(self.shape.BoundBox.Center))
        return ([dataclasses.replace(c, callout=k) for c in shown for k in callouts.get(c.edge, [None])] +
                [dataclasses.replace(c, callout=k) for c in hidden for k in callouts.get(c.edge, [])])

    def _measure(self):
        """Per principal view: vertices, the dimension plan and the view's extremes."""
        out = {}
        for name, _, _, axes in VIEWS:
            v = self.views[name]
            visible = view_geometry.visible_edges(v)
            ext = view_geometry.extremes(visible)
            if name in PRINCIPAL:
                verts = view_geometry.vertices(v)
                plan = dimension_plan.plan(verts, self._circles(name, v, visible), ext, axes)
            else:
                verts, plan = [], dimension_plan.Plan()
            out[name] = (verts, plan, ext)
        return out

    def layout(self) -> sheet_layout.Layout:
        self.doc.recompute()
        _settle(self.views.values())
        measured = self._measure()
        boxes = {}
        for name, (_, plan, ext) in measured.items():
            texts = functools.lru_cache(maxsize=None)(functools.partial(dimension_plan.label_room, plan, extremes=ext))
            boxes[name] = sheet_layout.ViewBox(ext["xmin"].coord, ext["xmax"].coord, ext["ymin"].coord,
                                               ext["ymax"].coord, plan.left, plan.right, plan.below, plan.above, texts)
        # The notes' height before the layout: only the scale line depends on it, and fits one line at any scale.
        strip = sheet_layout.SHEETS[0].title_block[2] - sheet_layout.SHEETS[0].title_block[0]
        count = len(self._notes("SCALE 1:10 (isometric view 1:10)", strip))
        try:
            layout = sheet_layout.choose(boxes, notes_block.height(count, NOTE_SIZE))
        except ValueError as exc:
            raise DrawingError(f"{self.entry['name']}: {exc}") from None
        self.template.Template = os.path.join(templates_dir(), layout.sheet.template)
        self.page.Scale = layout.scale
        for name, v in self.views.items():
            v.Scale = layout.iso_scale if name == "iso" else layout.scale
            v.X, v.Y = layout.centres[name]
        self.doc.recompute()
        _settle(self.views.values())
        self.chosen = layout
        return layout

    def _resolve(self, view, refs, cosmetic: dict) -> list:
        names = []
        for kind, what in refs:
            if kind == "vertex":
                names.append(f"Vertex{what}")
            elif kind == "edge":
                names.append(f"Edge{what}")
            else:
                names.append(cosmetic[(round(what[0], 6), round(what[1], 6))])
        return names

    def dimension(self) -> list:
        """Create the planned dimensions; each must measure what the plan says (else the drawing is wrong)."""
        measured = self._measure()
        scale = self.chosen.scale
        for name in PRINCIPAL:
            dimension_plan.place_labels(measured[name][1], scale, measured[name][2])
        # Curves without a vertex at their extreme get a cosmetic vertex there, so a dimension can end on it.
        cosmetic = {}
        for name in PRINCIPAL:
            view = self.views[name]
            points = {tuple(r[1]) for d in measured[name][1].dims for r in d.refs if r[0] == "point"}
            for p in points:
                view.makeCosmeticVertex(FreeCAD.Vector(p[0], p[1], 0))
        self.doc.recompute()
        _settle(self.views.values())
        for name in PRINCIPAL:
            verts = view_geometry.vertices(self.views[name])
            table = {}
            for p in {tuple(r[1]) for d in measured[name][1].dims for r in d.refs if r[0] == "point"}:
                idx = [i for i, v in enumerate(verts) if abs(v[0] - p[0]) < 1e-6 and abs(v[1] - p[1]) < 1e-6]
                if not idx:
                    raise DrawingError(f"{self.entry['name']}: cosmetic vertex at {p} missing from the {name} view")
                table[(round(p[0], 6), round(p[1], 6))] = f"Vertex{idx[-1]}"
            cosmetic[name] = table
        report = []
        for name in PRINCIPAL:
            view = self.views[name]
            verts, plan, ext = measured[name]
            for k, d in enumerate(plan.dims):
                dim = self.doc.addObject("TechDraw::DrawViewDimension", f"Dim_{name}_{k}")
                dim.Type = d.type
                dim.MeasureType = "Projected"
                dim.References2D = [(view, self._resolve(view, d.refs, cosmetic[name]))]
                diameter = d.type == "Diameter"
                dim.FormatSpec = d.prefix + (d.symbol + FORMAT + d.suffix if diameter else FORMAT)
                self.page.addView(dim)
                if diameter and dim.ViewObject is not None:
                    # on a reference line, horizontal: where dimension_plan expects it (not turned along the leader)
                    dim.ViewObject.StandardAndStyle = "ISO Referencing"
                dim.X, dim.Y = d.text_position(ext["xmin"].coord, ext["ymin"].coord, scale)
                self.dimensions.append((dim, d, name))
        self.doc.recompute()
        _settle([dim for dim, _, _ in self.dimensions])
        for dim, d, name in self.dimensions:
            raw = dim.getRawValue()
            if abs(raw - d.value) > VALUE_TOLERANCE:
                raise DrawingError(f"{self.entry['name']}: {name} view {d.kind} {d.type} measures {raw:.4f}, "
                                   f"the geometry says {d.value:.4f}")
            report.append({"view": name, "kind": d.kind, "type": d.type, "axis": d.axis, "value": round(raw, 4),
                           "prefix": d.prefix, "symbol": d.symbol if d.type == "Diameter" else "", "suffix": d.suffix})
        return report

    def annotate(self, layout: sheet_layout.Layout) -> None:
        e = self.entry
        values = {
            "AUTHOR_NAME": "Robogene contributors", "APPROVER_NAME": "-", "OWNER_NAME": "Robogene contributors",
            "TITLELINE-1": "Robogene head", "TITLELINE-2": e["name"],
            "TITLELINE-3": f"source: {e['source']}",
            "DOCUMENT_TYPE": "Machined part, first-angle projection", "SHEET": "1 of 1",
            "SCALE": sheet_layout.scale_label(layout.scale), "TOLERANCE": "ISO 2768-m",
            "PM": e["material"] or "-", "PN": e["name"], "DN": "-",
            "DATE": "-", "REVISION": e["revision"], "SIZE": layout.sheet.name,
            "RIGHTS": f"Licence {e['licence']} | units mm | reference geometry: {e['source']}",
        }
        # FreeCAD's template with each text sized to its cell (title_block); setting the template resets the
        # editable texts, so they come after.
        with open(os.path.join(templates_dir(), layout.sheet.template), encoding="utf-8") as fh:
            original = fh.read()
        try:
            fitted = title_block.fitted(original, values, _text_width)
        except title_block.TitleBlockError as exc:
            raise DrawingError(f"{e['name']}: {exc}") from None
        path = os.path.join(self.scratch, layout.sheet.template)
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(fitted)
        self.template.Template = path
        texts = self.template.EditableTexts
        texts.update(values)
        self.template.EditableTexts = texts
        x0, y0, x1, y1 = layout.notes
        symbol = self.doc.addObject("TechDraw::DrawViewSymbol", "ProjectionSymbol")
        symbol.Symbol = _first_angle_symbol()
        self.page.addView(symbol)
        symbol.X, symbol.Y = x1 - SYMBOL_ROOM / 2, (y0 + y1) / 2
        scale = sheet_layout.scale_label(layout.scale)
        iso = "same scale" if layout.iso_scale == layout.scale else sheet_layout.scale_label(layout.iso_scale)
        notes = self.doc.addObject("TechDraw::DrawViewAnnotation", "Notes")
        notes.Text = self._notes(f"SCALE {scale} (isometric view {iso})", layout.notes[2] - layout.notes[0])
        notes.TextSize = NOTE_SIZE
        self.page.addView(notes)
        # TechDraw centres an annotation on X, Y: centre it in the strip left of the projection symbol.
        notes.X, notes.Y = (x0 + x1 - SYMBOL_ROOM) / 2, (y0 + y1) / 2
        self.notes = notes
        self.doc.recompute()
        _settle([notes, symbol])

    def _notes(self, scale_line: str, strip_width: float) -> list:
        """The notes' lines, wrapped to the strip left of the projection symbol."""
        e = self.entry
        mass = self.shape.Volume * e["density"] * 1e-9 * 1000 if e["density"] else None
        lines = ["FIRST-ANGLE PROJECTION", "UNITS: mm", scale_line,
                 f"MATERIAL: {e['material'] or '-'}" + (f", mass {mass:.1f} g" if mass else ""),
                 "General tolerances ISO 2768-m; break sharp edges 0.3"]
        if e.get("note"):
            lines.append(e["note"])
        return notes_block.wrap(lines, strip_width - SYMBOL_ROOM, NOTE_SIZE)

    def draw_lines(self) -> None:
        """Each view's lines at their ISO widths and dash (line_overlay), over TechDraw's hairlines."""
        symbols = []
        for name, v in self.views.items():
            symbol = self.doc.addObject("TechDraw::DrawViewSymbol", f"Lines{name.capitalize()}")
            symbol.Symbol = line_overlay.svg(view_geometry.polylines(v.getVisibleEdges()),
                                             view_geometry.polylines(v.getHiddenEdges() if v.HardHidden else []))
            self.page.addView(symbol)
            symbol.X, symbol.Y = v.X, v.Y
            symbols.append(symbol)
        self.doc.recompute()
        _settle(symbols)

    def view_centres(self) -> dict:
        """Page mm (y up) of each view's centre, for the report."""
        return {name: [round(float(v.X), 4), round(float(v.Y), 4)] for name, v in self.views.items()}

    def close(self) -> None:
        shutil.rmtree(self.scratch, ignore_errors=True)

    def export(self) -> None:
        import TechDrawGui
        for path in (self.entry["pdf"], self.entry["svg"]):
            if os.path.exists(path):
                os.unlink(path)
        TechDrawGui.exportPageAsPdf(self.page, self.entry["pdf"])
        TechDrawGui.exportPageAsSvg(self.page, self.entry["svg"])
        for path in (self.entry["pdf"], self.entry["svg"]):
            if not os.path.exists(path) or os.path.getsize(path) < 1000:
                raise DrawingError(f"TechDraw wrote no {os.path.basename(path)}")
