# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Fit the title block's texts to their cells: a copy of FreeCAD's ISO 7200 template with smaller type where a
text would run past the line or the text that follows it.

FreeCAD's templates set every text at 3 mm in Tahoma, which is narrow; where Tahoma is missing (Debian) the
text falls back to a wider sans, and labels run into their values ("Part material:aluminium") and long part
names past the "Part number" cell. The width of a text is estimated conservatively from its length (EM per
character, more than DejaVu Sans needs for these texts), or measured, whichever is wider. The labels all get
the size of the tightest one, so they stay alike; each value gets the largest size up to the template's that
fits. Pure Python (runs inside FreeCAD and in the tests): the template is patched as text, so FreeCAD reads it
as it reads its own."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass

EM = 0.6            # assumed width of a character, in text heights
GAP = 0.5           # mm left between a text's end and the next line or text
MIN_SIZE = 1.8      # mm: ISO 3098's smallest text height
SVG = "{http://www.w3.org/2000/svg}"
EDITABLE = "{http://www.freecadweb.org/wiki/index.php?title=Svg_Namespace}editable"


class TitleBlockError(ValueError):
    pass


@dataclass
class Text:
    id: str
    field: str          # the editable field's name, "" for a label
    x: float            # start of the baseline, mm, y down
    y: float
    size: float         # text height, mm
    text: str


def _size(style: str, default: float) -> float:
    m = re.search(r"font-size:\s*([\d.]+)px", style or "")
    return float(m.group(1)) if m else default


def _lines(structure) -> list:
    """The title block's lines as (x0, y0, x1, y1): the rectangles' sides and the 'm x,y h dx' / 'v dy' paths."""
    out = []
    for el in structure.iter():
        if el.tag == SVG + "rect":
            x, y, w, h = (float(el.get(k)) for k in ("x", "y", "width", "height"))
            out += [(x, y, x + w, y), (x, y + h, x + w, y + h), (x, y, x, y + h), (x + w, y, x + w, y + h)]
        elif el.tag == SVG + "path":
            m = re.fullmatch(r"\s*[mM]\s*([\d.]+),([\d.]+)\s*([hv])\s*(-?[\d.]+)\s*", el.get("d", ""))
            if not m:
                raise TitleBlockError(f"title block line {el.get('id')}: path {el.get('d')!r} not understood")
            x, y, kind, d = float(m.group(1)), float(m.group(2)), m.group(3), float(m.group(4))
            out.append((x, y, x + d, y) if kind == "h" else (x, y, x, y + d))
    return out


def texts(template: str, values: dict) -> list:
    """The title block's texts (labels and editable fields, these with their values)."""
    root = ET.fromstring(template)
    out = []
    for group_id in ("titleblock-text-non-editable", "titleblock-text-editable"):
        group = root.find(f".//{SVG}g[@id='{group_id}']")
        default = _size(group.get("style"), 3.0)
        for el in group.iter(SVG + "text"):
            field = el.get(EDITABLE, "")
            text = values.get(field, "".join(el.itertext()).strip()) if field else "".join(el.itertext()).strip()
            if text:
                out.append(Text(el.get("id"), field, float(el.get("x")), float(el.get("y")),
                                _size(el.get("style"), default), text))
    return out


def room(template: str, values: dict) -> dict:
    """Text id -> mm from the text's start to the first line or text to its right (less GAP)."""
    root = ET.fromstring(template)
    lines = _lines(root.find(f".//{SVG}g[@id='titleblock-structure']"))
    all_texts = texts(template, values)
    out = {}
    for t in all_texts:
        top = t.y - 0.8 * t.size           # the text's cap height above its baseline
        ends = [x0 for x0, y0, x1, y1 in lines
                if x0 == x1 and x0 > t.x and min(y0, y1) < t.y and max(y0, y1) > top]
        ends += [o.x for o in all_texts if o is not t and abs(o.y - t.y) < 0.5 and o.x > t.x]
        if not ends:
            raise TitleBlockError(f"title block text {t.id} ({t.text!r}) has no cell edge to its right")
        out[t.id] = min(ends) - GAP - t.x
    return out


def sizes(template: str, values: dict, measure=None) -> dict:
    """Text id -> text height that fits. measure(text) -> width in text heights, if the renderer can tell."""
    space = room(template, values)
    fit = {}
    for t in texts(template, values):
        width = max(EM * len(t.text), measure(t.text) if measure else 0.0)
        fit[t.id] = min(t.size, space[t.id] / width)
        if fit[t.id] < MIN_SIZE:
            raise TitleBlockError(f"title block: {t.field or 'label'} {t.text!r} needs {width * MIN_SIZE:.1f} mm at "
                                  f"{MIN_SIZE} mm high, its cell has {space[t.id]:.1f} mm")
    labels = [t.id for t in texts(template, values) if not t.field]
    if labels:
        smallest = min(fit[i] for i in labels)
        fit.update({i: smallest for i in labels})
    return fit


def _restyle(tag: str, size: float) -> str:
    """A <text ...> start tag with its font size set (in its style attribute, which may already exist)."""
    size_css = f"font-size:{size:.3f}px"
    m = re.search(r'\bstyle="([^"]*)"', tag)
    if not m:
        return tag[:5] + f' style="{size_css}"' + tag[5:]
    style = re.sub(r"font-size:\s*[\d.]+px", size_css, m.group(1)) if "font-size" in m.group(1) \
        else f"{m.group(1).rstrip(';')};{size_css}"
    return tag[:m.start(1)] + style + tag[m.end(1):]


def fitted(template: str, values: dict, measure=None) -> str:
    """The template with a font size on every text that must be smaller than the template's."""
    original = {t.id: t.size for t in texts(template, values)}
    out = template
    for text_id, size in sizes(template, values, measure).items():
        if size < original[text_id] - 1e-9:
            tags = re.findall(rf'<text\b[^>]*?\bid="{re.escape(text_id)}"[^>]*>', out)
            if len(tags) != 1:
                raise TitleBlockError(f"title block text {text_id}: {len(tags)} elements")
            out = out.replace(tags[0], _restyle(tags[0], size))
    return out
