# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Read the lines and texts of an exported TechDraw page (SVG) back in page millimetres, y down, as the
tests need them: independent of the drawing code, from the file the shop gets."""
from __future__ import annotations

import math
import re
import subprocess
from dataclasses import dataclass
from pathlib import Path

GROUP = re.compile(r"<g\b([^>]*)>(.*?)</g>", re.S)
ATTR = re.compile(r'([\w:-]+)="([^"]*)"')
PATH_D = re.compile(r'<path\b[^>]*\bd="([^"]*)"')
PAIR = re.compile(r"(-?\d+(?:\.\d+)?(?:e-?\d+)?),(-?\d+(?:\.\d+)?(?:e-?\d+)?)")


@dataclass
class Stroke:
    width: float          # mm
    dash: tuple           # (dash, gap) mm, () for a solid line
    lines: list           # polylines [(x, y)] in page mm, y down


def mm_per_unit(svg: str) -> float:
    m = re.search(r'<svg\b[^>]*>', svg).group(0)
    attrs = dict(ATTR.findall(m))
    return float(attrs["width"].removesuffix("mm")) / float(attrs["viewBox"].split()[2])


def strokes(svg: str) -> list:
    """Every stroked group of paths with its width, dash and lines; Qt writes one group per pen and transform."""
    unit = mm_per_unit(svg)
    out = []
    for attrs_text, body in GROUP.findall(svg):
        attrs = dict(ATTR.findall(attrs_text))
        transform = attrs.get("transform", "matrix(1,0,0,1,0,0)")
        # Qt writes each pen's paths as one flat group with a matrix; the template's nested groups are not lines
        if attrs.get("stroke", "none") == "none" or "<path" not in body or not transform.startswith("matrix("):
            continue
        a, b, c, d, e, f = (float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", transform))
        scale = math.hypot(a, b)
        dash = tuple(float(v) * scale * unit for v in attrs["stroke-dasharray"].split(",")) \
            if "stroke-dasharray" in attrs else ()
        lines = []
        for path in PATH_D.findall(body):
            for sub in re.split(r"(?=M)", path):
                points = [(float(x), float(y)) for x, y in PAIR.findall(sub)]
                if points:
                    lines.append([((a * x + c * y + e) * unit, (b * x + d * y + f) * unit) for x, y in points])
        out.append(Stroke(float(attrs.get("stroke-width", "1")) * scale * unit, dash, lines))
    return out


def circle_of(line: list, tol: float = 0.02):
    """(cx, cy, r) when the polyline is a closed circle, else None."""
    if len(line) < 8 or math.dist(line[0], line[-1]) > tol:
        return None
    ring = line[:-1]      # the closing point repeats the first
    cx = sum(x for x, _ in ring) / len(ring)
    cy = sum(y for _, y in ring) / len(ring)
    radii = [math.dist((cx, cy), p) for p in line]
    if max(radii) - min(radii) > tol:
        return None
    return cx, cy, sum(radii) / len(radii)


def ring_gaps(pdf: Path, centre: tuple, radius: float, dpi: int = 600) -> tuple:
    """Rasterise the PDF around a circle (page mm, y down) and walk the ring: (fraction of the ring that is
    inked, number of blank stretches at least 0.25 mm long)."""
    from PIL import Image
    px = dpi / 25.4
    half = radius + 1.0
    x0, y0 = int((centre[0] - half) * px), int((centre[1] - half) * px)
    size = int(2 * half * px) + 1
    out = pdf.parent / f"{pdf.stem}-ring"
    subprocess.run(["pdftoppm", "-gray", "-png", "-r", str(dpi), "-x", str(x0), "-y", str(y0), "-W", str(size),
                    "-H", str(size), "-singlefile", str(pdf), str(out)], check=True, capture_output=True, timeout=120)
    img = Image.open(f"{out}.png").convert("L")
    steps = 1440
    inked = []
    for k in range(steps):
        t = 2 * math.pi * k / steps
        dark = False
        for dr in (-0.15, -0.075, 0.0, 0.075, 0.15):
            x = (centre[0] + (radius + dr) * math.cos(t)) * px - x0
            y = (centre[1] + (radius + dr) * math.sin(t)) * px - y0
            if 0 <= x < img.width and 0 <= y < img.height and img.getpixel((int(x), int(y))) < 128:
                dark = True
                break
        inked.append(dark)
    arc = 2 * math.pi * radius / steps
    gaps, run = 0, 0
    start = inked.index(True) if any(inked) else 0
    for k in range(steps):
        if inked[(start + k) % steps]:
            gaps += run * arc >= 0.25
            run = 0
        else:
            run += 1
    gaps += run * arc >= 0.25
    return sum(inked) / steps, gaps


@dataclass
class Label:
    text: str
    x: float              # baseline start, template mm, y down
    y: float
    size: float           # text height, mm


def title_block(svg: str) -> tuple:
    """The title block as the page carries it: its lines (x0, y0, x1, y1) and its texts, in template mm."""
    import xml.etree.ElementTree as ET
    ns = "{http://www.w3.org/2000/svg}"
    root = ET.fromstring(svg.encode())
    lines = []
    structure = root.find(f".//{ns}g[@id='titleblock-structure']")
    for el in structure:
        if el.tag == ns + "rect":
            x, y, w, h = (float(el.get(k)) for k in ("x", "y", "width", "height"))
            lines += [(x, y, x + w, y), (x, y + h, x + w, y + h), (x, y, x, y + h), (x + w, y, x + w, y + h)]
        elif el.tag == ns + "path":
            x, y, kind, d = re.fullmatch(r"m ([\d.]+),([\d.]+) ([hv]) ([\d.]+)", el.get("d")).groups()
            x, y, d = float(x), float(y), float(d)
            lines.append((x, y, x + d, y) if kind == "h" else (x, y, x, y + d))
    texts = []
    for group_id in ("titleblock-text-non-editable", "titleblock-text-editable"):
        group = root.find(f".//{ns}g[@id='{group_id}']")
        default = float(re.search(r"font-size:([\d.]+)px", group.get("style")).group(1))
        for el in group.iter(ns + "text"):
            text = "".join(el.itertext()).strip()
            m = re.search(r"font-size:([\d.]+)px", el.get("style", ""))
            if text:
                texts.append(Label(text, float(el.get("x")), float(el.get("y")), float(m.group(1)) if m else default))
    return lines, texts
