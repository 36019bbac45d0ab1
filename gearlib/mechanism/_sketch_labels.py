"""Where the labels of a kinematic sketch go: each clear of every line, block and other label.

Private to :mod:`gearlib.mechanism.sketch`. A label's size is known only on the page (its font
size in points, the figure's scale), so :func:`place` runs when the sketch is drawn. For each
link's id, in the order of the sketch's labels: positions inside the link's largest block
(off the pin through a planet), then around its blocks, then beside its lines, nearest first;
for each brake and clutch its name beside its plates. The first position whose box (with a
margin) meets no line, no other link's block or hatched frame, and no label placed before is
taken; where none is free, the one that meets the fewest.
"""

from __future__ import annotations

import numpy as np

__all__: list = []

CHAR = 0.62      # width of a character, in font sizes
LINE = 1.35      # height of a line of text, in font sizes
PAD = 2.5        # points around a label's text (its box) and clear of what is drawn


def text_size(text: str, font_size: float, style: str = "normal") -> tuple:
    """``(width, height)`` of a label's box in points: the text's width from the font's metrics
    (as matplotlib lays it out), a line's height, and the padding."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath

    try:
        width = TextToPath().get_text_width_height_descent(text, FontProperties(size=font_size, style=style),
                                                           ismath=False)[0]
    except Exception:   # pragma: no cover - a font matplotlib cannot measure: a generous estimate
        width = CHAR * font_size * len(text)
    return width + 2 * PAD + 1.0, LINE * font_size + 2 * PAD


def points_per_unit(ax) -> float:
    fig = ax.figure
    box = ax.get_position()
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    w_in, h_in = fig.get_size_inches()
    return min(box.width * w_in * 72 / (x1 - x0), box.height * h_in * 72 / (y1 - y0))


def place(ax, sk, texts, names, font_size) -> tuple:
    """Positions (data units) for the link labels (``texts``, one per ``sk.labels``) and for the
    names of the brakes and clutches (``names``: ``(symbol, text)``)."""
    per = points_per_unit(ax)
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    margin = 1.5 / per
    segs = [(a.start, a.end) for a in sk.axes] + [(ln.start, ln.end) for ln in sk.lines]
    segs += [seg for s in sk.symbols for seg in s.segments]
    owner = [None] * len(segs)
    polys = [(b.link, b.polygon) for b in sk.blocks] + [(None, h) for s in sk.symbols for h in s.hatch]
    for link, poly in polys:   # a label may sit on its own block, over its edges
        segs += [(poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly))]
        owner += [link] * len(poly)
    seg = np.array([(a[0], a[1], b[0], b[1]) for a, b in segs], dtype=float).reshape(-1, 4)
    ids = {link: i + 1 for i, link in enumerate(dict.fromkeys(lb.link for lb in sk.labels))}
    owner = np.array([ids.get(o, 0) if o is not None else 0 for o in owner])
    quads = np.array([poly for _, poly in polys if len(poly) == 4], dtype=float).reshape(-1, 4, 2)
    quad_owner = np.array([ids.get(link, 0) if link is not None else 0 for link, poly in polys if len(poly) == 4])
    boxes: list = []   # placed labels: (x0, x1, y0, y1)
    bounds = (x0, x1, y0, y1)

    def choose(cands, w, h, own):
        """The first free candidate (the preferred ones, then rings around the first), or the one
        that meets the fewest."""
        near, ring = cands
        best = score(np.array(near, dtype=float).reshape(-1, 2), w, h, own)
        if best[0] > 0:
            far = score(_around(*near[0], w, h), w, h, own)
            best = min(best, far, key=lambda t: t[0])
        c = best[1]
        boxes.append((c[0] - w / 2, c[0] + w / 2, c[1] - h / 2, c[1] + h / 2))
        return float(c[0]), float(c[1])

    def score(c, w, h, own):
        rect = np.column_stack([c[:, 0] - w / 2 - margin, c[:, 0] + w / 2 + margin,
                                c[:, 1] - h / 2 - margin, c[:, 1] + h / 2 + margin])
        mine = ids.get(own) if own is not None else None
        keep = owner != mine if mine is not None else slice(None)
        bad = _hits(rect, seg[keep]).astype(float)
        if len(quads):
            inside = _inside(c, quads)
            if mine is not None:
                inside[:, quad_owner == mine] = False
            bad += inside.sum(axis=1)
        if boxes:
            b = np.array(boxes)
            bad += ((rect[:, None, 0] < b[None, :, 1]) & (b[None, :, 0] < rect[:, None, 1])
                    & (rect[:, None, 2] < b[None, :, 3]) & (b[None, :, 2] < rect[:, None, 3])).sum(axis=1) * 3
        out = ((rect[:, 0] < bounds[0]) | (rect[:, 1] > bounds[1]) | (rect[:, 2] < bounds[2])
               | (rect[:, 3] > bounds[3]))
        bad += out * 2
        i = int(np.argmin(bad))   # the first of the fewest
        return float(bad[i]), c[i]

    spots, leaders = [], []
    for lb, text in zip(sk.labels, texts):
        w, h = (v / per for v in text_size(text, font_size))
        x, y = choose(_candidates(sk, lb, w, h, margin), w, h, lb.link)
        spots.append((x, y))
        leader = _leader(sk, lb.link, (x - w / 2, x + w / 2, y - h / 2, y + h / 2), 1.2 * h)
        if leader is not None:
            leaders.append((lb.link, leader))
    name_spots = []
    for sym, text in names:
        w, h = (v / per for v in text_size(text, font_size - 1, "italic"))
        x, y = choose(_symbol_candidates(sym, w, h, margin), w, h, None)
        name_spots.append((x, y))
        pts = [q for seg in sym.segments for q in seg]
        anchor = (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
        near = (min(max(anchor[0], x - w / 2), x + w / 2), min(max(anchor[1], y - h / 2), y + h / 2))
        if ((near[0] - anchor[0]) ** 2 + (near[1] - anchor[1]) ** 2) ** 0.5 > 1.5 * h:
            leaders.append((None, (near, anchor)))
    return spots, name_spots, leaders


def _leader(sk, link, rect, near):
    """A leader from a label's box to its link, when the box stands more than *near* from it
    (from its blocks, or, for a link without one, from its lines)."""
    x0, x1, y0, y1 = rect
    best = None
    for b in sk.blocks:
        if b.link == link and not b.copy:
            xs, ys = [p[0] for p in b.polygon], [p[1] for p in b.polygon]
            dx = max(min(xs) - x1, x0 - max(xs), 0.0)
            dy = max(min(ys) - y1, y0 - max(ys), 0.0)
            if (dx * dx + dy * dy) ** 0.5 <= near:
                return None
            points = [(sum(xs) / len(xs), sum(ys) / len(ys))]
            best = _nearer(best, points, rect)
    if best is None:
        for ln in sk.lines:
            if ln.link == link and not ln.copy:
                mid = ((ln.start[0] + ln.end[0]) / 2, (ln.start[1] + ln.end[1]) / 2)
                best = _nearer(best, [ln.start, ln.end, mid], rect)
    if best is None or best[0] <= near:
        return None
    return best[1], best[2]


def _nearer(best, points, rect):
    x0, x1, y0, y1 = rect
    for px, py in points:
        cx, cy = min(max(px, x0), x1), min(max(py, y0), y1)
        d = ((px - cx) ** 2 + (py - cy) ** 2) ** 0.5
        if best is None or d < best[0]:
            best = (d, (cx, cy), (px, py))
    return best


def _hits(rect, seg) -> np.ndarray:
    """How many segments each rectangle meets (separating axes: the boxes, then the segment's line)."""
    if not len(seg):
        return np.zeros(len(rect))
    sx0, sy0, sx1, sy1 = (seg[:, i][None, :] for i in range(4))
    rx0, rx1, ry0, ry1 = (rect[:, i][:, None] for i in range(4))
    box = ((np.minimum(sx0, sx1) < rx1) & (np.maximum(sx0, sx1) > rx0)
           & (np.minimum(sy0, sy1) < ry1) & (np.maximum(sy0, sy1) > ry0))
    dx, dy = sx1 - sx0, sy1 - sy0
    side = [dx * (cy - sy0) - dy * (cx - sx0) for cx, cy in ((rx0, ry0), (rx1, ry0), (rx0, ry1), (rx1, ry1))]
    above = sum((s > 0).astype(int) for s in side)
    below = sum((s < 0).astype(int) for s in side)
    straddle = (above < 4) & (below < 4)
    return (box & straddle).sum(axis=1)


def _inside(points, quads) -> np.ndarray:
    """``(points, quads)``: True where a point lies inside a convex quadrilateral."""
    a = quads
    b = np.roll(quads, -1, axis=1)
    px, py = points[:, 0][:, None, None], points[:, 1][:, None, None]
    side = (b[None, :, :, 0] - a[None, :, :, 0]) * (py - a[None, :, :, 1]) - \
           (b[None, :, :, 1] - a[None, :, :, 1]) * (px - a[None, :, :, 0])
    return (side > 0).all(axis=2) | (side < 0).all(axis=2)


def _candidates(sk, lb, w, h, m) -> list:
    """Positions for a link's id: inside its largest block, around its blocks, beside its lines."""
    out = []
    blocks = sorted((b for b in sk.blocks if b.link == lb.link and not b.copy),
                    key=lambda b: -_area(b.polygon))
    for b in blocks[:1]:
        xs, ys = [q[0] for q in b.polygon], [q[1] for q in b.polygon]
        cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
        bx0, bx1, by0, by1 = min(xs), max(xs), min(ys), max(ys)
        room = (by1 - by0 - h) / 2 - m
        out.append((cx, cy))
        for f in (0.5, 0.25, 0.75, 1.0):
            out += [(cx, cy + f * room), (cx, cy - f * room)]
    for b in blocks:
        xs, ys = [q[0] for q in b.polygon], [q[1] for q in b.polygon]
        cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
        bx0, bx1, by0, by1 = min(xs), max(xs), min(ys), max(ys)
        gx, gy = w / 2 + 2 * m, h / 2 + 2 * m
        for dy in np.linspace(-0.4, 0.4, 5) * (by1 - by0):   # on the block, wider than it
            out += [(cx, cy + dy)]
        out += [(cx, by1 + gy), (cx, by0 - gy), (bx1 + gx, cy), (bx0 - gx, cy)]
        for f in (0.3, -0.3, 0.15, -0.15, 0.45, -0.45):
            out += [(bx1 + gx, cy + f * (by1 - by0)), (bx0 - gx, cy + f * (by1 - by0))]
        for f in (0.5, -0.5, 1.0, -1.0):
            out += [(cx + f * w, by1 + gy), (cx + f * w, by0 - gy)]
        out += [(bx1 + gx, by1 + gy), (bx0 - gx, by1 + gy), (bx1 + gx, by0 - gy), (bx0 - gx, by0 - gy)]
    lines = sorted((ln for ln in sk.lines if ln.link == lb.link and not ln.copy),
                   key=lambda ln: -abs(ln.end[0] - ln.start[0]) - abs(ln.end[1] - ln.start[1]))
    x, y = lb.xy
    out.append((x, y))
    for ln in lines[:4]:
        (ax_, ay), (bx, by) = ln.start, ln.end
        horizontal = abs(by - ay) <= abs(bx - ax_)
        for t in (0.5, 0.3, 0.7, 0.15, 0.85):
            px, py = ax_ + t * (bx - ax_), ay + t * (by - ay)
            if horizontal:
                out += [(px, py + h / 2 + 2 * m), (px, py - h / 2 - 2 * m)]
            else:
                out += [(px + w / 2 + 2 * m, py), (px - w / 2 - 2 * m, py)]
    return out, None


def _around(x, y, w, h, rings=10) -> np.ndarray:
    """Positions on rings around (x, y), nearest first: where nothing nearer is free."""
    i, j = np.meshgrid(np.arange(-rings, rings + 1), np.arange(-rings, rings + 1))
    i, j = i.ravel(), j.ravel()
    ring = np.maximum(abs(i), abs(j))
    keep = np.argsort(ring, kind="stable")[1:]
    return np.column_stack([x + i[keep] * 0.55 * w, y + j[keep] * 1.1 * h])


def _symbol_candidates(sym, w, h, m) -> list:
    pts = [q for seg in sym.segments for q in seg]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    bx0, bx1, by0, by1 = min(xs), max(xs), min(ys), max(ys)
    cy = (by0 + by1) / 2
    cx = (bx0 + bx1) / 2
    gx, gy = w / 2 + 2 * m, h / 2 + 2 * m
    out = [(bx1 + gx, cy), (bx0 - gx, cy), (cx, by0 - gy), (cx, by1 + gy),
           (bx1 + gx, by0 - gy), (bx0 - gx, by0 - gy), (bx1 + gx, by1 + gy), (bx0 - gx, by1 + gy)]
    for k in (2, 3):
        out += [(bx1 + gx, cy - (k - 1) * h), (bx0 - gx, cy - (k - 1) * h), (cx, by0 - gy - (k - 1) * h),
                (bx1 + k * gx, cy), (bx0 - k * gx, cy)]
    return out, None


def _area(poly) -> float:
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1])))
