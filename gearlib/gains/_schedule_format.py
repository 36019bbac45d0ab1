"""Text, HTML, JSON and CSV forms of a shift table (:class:`gearlib.gains.ScheduleTable`)."""

from __future__ import annotations

import csv
import html
import io

from ..mechanism.kinematics import format_value


def _num(x):
    if x is None:
        return None
    try:
        return float(x)
    except TypeError:
        return str(x)


def _fix(x, digits: int = 4) -> str:
    if x is None:
        return "-"
    try:
        return f"{float(x):.{digits}f}"
    except TypeError:
        return str(x)


def _speed(x) -> str:
    try:
        return f"{float(x):+.3f}"
    except TypeError:
        return format_value(x, 4)


def to_json(t) -> dict:
    m = t.mechanism
    return {
        "mechanism": m.name, "ground": str(t.ground), "input": str(t.input), "output": str(t.output),
        "eta": t.eta_text,
        "spread": _num(t.spread),
        "gears": [{
            "gear": g.name, "engaged": list(g.engaged), "i": _num(g.i), "i_exact": str(g.i),
            "ratio": _num(g.ratio), "ratio_exact": str(g.ratio), "step": _num(g.step),
            "efficiency": g.efficiency,
            "speeds": {str(k): _num(v) for k, v in g.speeds.items()},
            "slips": {k: _num(v) for k, v in g.slips.items()},
            "element_torques": g.element_torques,
            "meshes": [{"gears": [str(x) for x in p.gears], "carrier": str(p.carrier), "driver": None if p.driver is None else str(p.driver),
                        "rolling_power": p.rolling, "real_power": p.real, "loss": p.loss,
                        "circulating": p.circulating} for p in g.meshes],
            "notes": list(g.notes),
        } for g in t.gears],
        "combinations": [{"elements": list(c.elements), "kind": c.kind, "dof": c.dof, "ratio": _num(c.ratio),
                          "gear": c.gear, "note": c.note} for c in t.combinations],
    }


def to_csv(t, table: str = "gears") -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    if table == "combinations":
        w.writerow(["elements", "kind", "dof", "ratio", "i", "gear", "note"])
        for c in t.combinations:
            i = None if c.ratio is None or c.ratio == 0 else 1 / c.ratio
            w.writerow(["+".join(c.elements), c.kind, c.dof, _num(c.ratio), _num(i), c.gear or "", c.note])
        return buf.getvalue()
    elements = [e.name for e in t.mechanism.shift_elements]
    links = list(t.mechanism.link_ids)
    w.writerow(["gear", "engaged", "i", "ratio", "step", "efficiency", "circulating"]
               + [f"slip_{e}" for e in elements] + [f"speed_{k}" for k in links])
    for g in t.gears:
        w.writerow([g.name, "+".join(g.engaged), _num(g.i), _num(g.ratio), _num(g.step), g.efficiency,
                    " ".join(f"{a}-{b}" for a, b in g.circulating)]
                   + [_num(g.slips.get(e)) if e in g.slips else "" for e in elements]
                   + [_num(g.speeds[k]) for k in links])
    return buf.getvalue()


def _slips(g) -> str:
    return ", ".join(f"{k} {_speed(v)}" for k, v in g.slips.items()) or "-"


def _circ(g) -> str:
    return ", ".join(f"{a}-{b}" for a, b in g.circulating) or "-"


def _summary(t) -> list:
    kinds: dict = {}
    for c in t.combinations:
        kinds.setdefault(c.kind, []).append(c)
    sizes = sorted({len(c.elements) for c in t.combinations})
    n = len(t.mechanism.shift_elements)
    head = f"{len(t.combinations)} combinations of {' or '.join(map(str, sizes))} of the {n} elements:"
    parts = []
    for kind in ("gear", "tie-up", "output held", "under-constrained", "over-constrained"):
        cs = kinds.get(kind, [])
        if not cs:
            continue
        if kind == "gear":
            extra = [c.label for c in cs if c.gear is None]
            parts.append(f"{len(cs)} gear{'s' * (len(cs) != 1)}"
                         + (f" (not in the schedule: {', '.join(extra)})" if extra else ""))
        else:
            parts.append(f"{len(cs)} {kind} ({', '.join(c.label for c in cs)})")
    return [head + " " + "; ".join(parts)]


def to_text(t) -> str:
    m = t.mechanism
    lines = [f"shift table of {m.name!r}: input {t.input}, output {t.output}, ground {t.ground}",
             f"efficiency with {t.eta_text}" if t.rated else t.eta_text]
    rows = [("gear", "engaged", "i", "step", "ratio out/in", "efficiency", "circulating", "slip of open elements")]
    for g in t.gears:
        rows.append((g.name, "+".join(g.engaged), _fix(g.i), _fix(g.step, 3), str(g.ratio),
                     _fix(g.efficiency, 5), _circ(g), _slips(g)))
    if not t.rated:
        rows = [r[:5] + r[7:] for r in rows]
    widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]) - 1)]
    for r in rows:
        lines.append("  ".join(f"{x:<{w}}" for x, w in zip(r, widths)) + "  " + r[-1])
    if t.spread is not None:
        lines.append(f"spread {_fix(t.spread)} (first / last forward gear)")
    lines += _summary(t)
    common = set.intersection(*(set(g.notes) for g in t.gears)) if t.gears else set()
    lines += [f"note: {n}" for n in t.gears[0].notes if n in common] if t.gears else []
    for g in t.gears:
        lines += [f"note ({g.name}): {n}" for n in g.notes if n not in common]
    return "\n".join(lines)


def to_html(t) -> str:
    e = html.escape
    keep = [0, 1, 2, 3, 4, 5, 6, 7] if t.rated else [0, 1, 2, 3, 4, 7]
    heads = ("gear", "engaged", "i", "step", "ratio ω_out/ω_in", "η", "circulating power", "slip of the open elements")
    head = "".join(f"<th>{heads[k]}</th>" for k in keep)
    body = ""
    for g in t.gears:
        cells = (g.name, " ".join(g.engaged), _fix(g.i), _fix(g.step, 3), str(g.ratio), _fix(g.efficiency, 5),
                 _circ(g), _slips(g))
        body += "<tr>" + "".join(f"<td>{e(cells[k])}</td>" for k in keep) + "</tr>"
    foot = ""
    if t.spread is not None:
        foot += f"<p>Spread {_fix(t.spread)}. " + (f"Efficiency with {e(t.eta_text)}.</p>" if t.rated else "</p>")
    foot += "".join(f"<p>{e(s)}</p>" for s in _summary(t))
    return (f"<table><caption>Shift table of {e(t.mechanism.name)} (input {e(str(t.input))}, output "
            f"{e(str(t.output))})</caption><tr>{head}</tr>{body}</table>{foot}")
