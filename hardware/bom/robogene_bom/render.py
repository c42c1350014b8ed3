# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Write a BOM as an ordering CSV, a Markdown table for the docs and a standalone HTML page."""
from __future__ import annotations

import csv
import html
import io

from .collect import Bom

COLUMNS = ["key", "description", "manufacturer", "mpn", "supplier", "unit", "qty_per_head", "qty_batch",
           "unit_price_batch", "line_cost_batch", "datasheet"]


def _money(value: float) -> str:
    return f"{value:,.2f}"


def rows(bom: Bom, batch: int) -> list[dict]:
    out = []
    for line in bom.lines:
        qty = line.ordered(batch)
        unit = line.item.unit_price(qty)
        per_head = f"{line.per_head:.2f}" if line.item.unit == "m" else str(int(round(line.per_head)))
        out.append({"key": line.item.key, "description": line.item.description, "manufacturer": line.item.manufacturer,
                    "mpn": line.item.mpn, "supplier": line.item.supplier, "unit": line.item.unit, "qty_per_head": per_head,
                    "qty_batch": qty, "unit_price_batch": f"{unit:.2f}", "line_cost_batch": f"{unit * qty:.2f}",
                    "datasheet": line.item.datasheet})
    return out


def to_csv(bom: Bom, batch: int) -> str:
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows(bom, batch))
    return buf.getvalue()


def made_csv(bom: Bom, batch: int, costs: dict | None = None) -> str:
    """costs: design -> (estimated unit cost for one head, for a batch), see making.py."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(["design", "process", "material", "qty_per_head", "qty_batch", "step", "stl",
                     "est_unit_cost_one_head", "est_unit_cost_batch"])
    for m in bom.made:
        one, each = (costs or {}).get(m.design, ("", ""))
        writer.writerow([m.design, m.kind, m.material, m.per_head, m.per_head * batch, f"step/{m.design}.step",
                         f"stl/{m.design}.stl" if m.kind == "printed" else "",
                         f"{one:.2f}" if one != "" else "", f"{each:.2f}" if each != "" else ""])
    return buf.getvalue()


def totals(bom: Bom, batch: int) -> tuple[float, float, float]:
    one = bom.cost_per_head(1)
    each_in_batch = bom.cost_per_head(batch)
    return one, each_in_batch, each_in_batch * batch


def _md_escape(text: str) -> str:
    return text.replace("|", "\\|")


def making_sentence(bom: Bom, batch: int, costs: dict) -> str:
    one = sum(m.per_head * costs[m.design][0] for m in bom.made)
    each = sum(m.per_head * costs[m.design][1] for m in bom.made)
    c = bom.currency
    return (f"Making the parts (estimate, from the shop rates in the parameter file, not quotes): **{c} {_money(one)} "
            f"for one head**, {c} {_money(each)} per head in a batch of {batch}.")


def to_markdown(bom: Bom, batch: int, costs: dict | None = None) -> str:
    one, each, total = totals(bom, batch)
    c = bom.currency
    out = [f"| # | part | manufacturer | MPN | qty/head | unit ({c}, batch of {batch}) | line ({c}, batch) |",
           "|---:|---|---|---|---:|---:|---:|"]
    for i, r in enumerate(rows(bom, batch), start=1):
        part = f"[{_md_escape(r['description'])}]({r['datasheet']})" if r["datasheet"] else _md_escape(r["description"])
        out.append(f"| {i} | {part} | {_md_escape(r['manufacturer'])} | "
                   f"{_md_escape(r['mpn'])} | {r['qty_per_head']}{' m' if r['unit'] == 'm' else ''} | {r['unit_price_batch']} | {r['line_cost_batch']} |")
    out += ["", f"Purchased parts: **{c} {_money(one)} for one head**, {c} {_money(each)} per head in a batch of "
                f"{batch} ({c} {_money(total)} for the batch). Estimated list prices, not quotes.", ""]
    if costs:
        out += ["| made part | process | material | qty/head | est. unit (one head) | est. unit (batch) |",
                "|---|---|---|---:|---:|---:|"]
        out += [f"| {m.design} | {m.kind} | {m.material} | {m.per_head} | {costs[m.design][0]:.2f} | "
                f"{costs[m.design][1]:.2f} |" for m in bom.made]
        out += ["", making_sentence(bom, batch, costs)]
    else:
        out += ["| made part | process | material | qty/head |", "|---|---|---|---:|"]
        out += [f"| {m.design} | {m.kind} | {m.material} | {m.per_head} |" for m in bom.made]
    if not bom.boards:
        out += ["", "The motor-control boards are not included yet: their BOM merges in once the KiCad boards exist."]
    else:
        out += ["", "Includes the parts of the boards: " + ", ".join(bom.boards) + "."]
    return "\n".join(out) + "\n"


def to_html(bom: Bom, batch: int, title: str, costs: dict | None = None) -> str:
    one, each, total = totals(bom, batch)
    c = html.escape(bom.currency)
    e = html.escape
    body = [f"<h1>{e(title)}</h1>",
            f"<p class=sum>Purchased parts: <b>{c} {_money(one)}</b> for one head; {c} {_money(each)} per head in a "
            f"batch of {batch} (<b>{c} {_money(total)}</b> for the batch). Estimated list prices, not quotes.</p>",
            "<table><thead><tr><th>#</th><th>part</th><th>manufacturer</th><th>MPN</th><th>supplier</th>"
            f"<th>qty/head</th><th>qty (batch)</th><th>unit {c}</th><th>line {c}</th></tr></thead><tbody>"]
    for i, r in enumerate(rows(bom, batch), start=1):
        part = f"<a href=\"{e(r['datasheet'])}\">{e(r['description'])}</a>" if r["datasheet"] else e(r["description"])
        body.append(f"<tr><td>{i}</td><td>{part}</td>"
                    f"<td>{e(r['manufacturer'])}</td><td>{e(r['mpn'])}</td><td>{e(r['supplier'])}</td>"
                    f"<td class=n>{r['qty_per_head']}</td><td class=n>{r['qty_batch']}</td>"
                    f"<td class=n>{r['unit_price_batch']}</td><td class=n>{r['line_cost_batch']}</td></tr>")
    body.append(f"</tbody><tfoot><tr><td colspan=8>total for {batch} heads</td><td class=n>{_money(total)}</td></tr>"
                "</tfoot></table>")
    body.append("<h2>Made parts</h2><table><thead><tr><th>design</th><th>process</th><th>material</th>"
                "<th>qty/head</th></tr></thead><tbody>")
    body += [f"<tr><td>{e(m.design)}</td><td>{e(m.kind)}</td><td>{e(m.material)}</td><td class=n>{m.per_head}</td></tr>"
             for m in bom.made]
    body.append("</tbody></table>")
    if costs:
        body.append(f"<p class=sum>{e(making_sentence(bom, batch, costs)).replace('**', '')}</p>")
    style = ("body{font-family:sans-serif;margin:2em;max-width:75em}table{border-collapse:collapse;width:100%}"
             "td,th{border:1px solid #ccc;padding:.3em .5em;text-align:left}td.n{text-align:right}"
             "thead{background:#eef}tfoot{font-weight:bold}")
    # REUSE-IgnoreStart
    licence = "<!-- SPDX-FileCopyrightText: 2026 Robogene contributors -->\n<!-- SPDX-License-Identifier: CERN-OHL-S-2.0 -->\n"
    # REUSE-IgnoreEnd
    return (f"<!DOCTYPE html>\n{licence}<html lang=en><head><meta charset=utf-8>"
            f"<title>{e(title)}</title><style>{style}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")
