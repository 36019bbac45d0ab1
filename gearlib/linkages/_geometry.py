"""How a Davies network finds its couplings' geometry at a pose (used by
:class:`~gearlib.linkages.LinkageNetwork`): index arrays, built once per linkage, that turn the
links' frames into every coupling's point and directions, and those into unit screws."""

from __future__ import annotations

import numpy as np

from .pose import _basis, _v3

__all__ = ["geometry_plan"]


def geometry_plan(net):
    """How to find every coupling's point and directions from the links' frames: points
    fixed in a link, directions fixed in the world, in a link, or the normalised cross
    product of two others (a universal joint's third direction, a slider's normal)."""
    index = {k: i for i, k in enumerate(net.linkage.link_ids)}
    points, dirs, where = [], [], {}   # dirs: ("world", v) | ("link", l, v) | ("cross", i, j)

    def add(key, value):
        where[key] = len(dirs)
        dirs.append(value)

    z, eye = _v3([0, 0, 1]), np.eye(3)
    for j in net.linkage.joints:
        keys = ([("split", j.name, k, on) for k, on in enumerate(j.split_in)] if j.split is not None
                else [("joint", j.name)])
        refs = ([(index[on], _v3(j.split[k])) for k, on in enumerate(j.split_in)] if j.split is not None
                else [(index[j.tail], _v3(j.point))])
        first = keys[0]
        for k, key in enumerate(keys):
            points.append(refs[k])
            if k:  # a split pair's two couplings share the pair's directions
                for name in ("x", "y", "z", "a", "axis", "normal", "u", "w"):
                    if (first, name) in where:
                        where[(key, name)] = where[(first, name)]
                continue
            for name, v in (("x", eye[0]), ("y", eye[1]), ("z", z)):
                add((key, name), ("world", v))
            a = ("link", index[j.tail], _v3(j.axis)) if j.axis is not None else ("world", z)
            add((key, "a"), a)
            where[(key, "axis")] = where[(key, "a")]
            if net.planar:
                if j.axis is not None:
                    add((key, "normal"), ("cross", where[(key, "z")], where[(key, "a")]))
            elif j.kind == "universal":
                add((key, "d1"), ("link", index[j.fixed_in[0]], _v3(j.axes[0])))
                add((key, "d2"), ("link", index[j.fixed_in[1]], _v3(j.axes[1])))
                add((key, "d3"), ("cross", where[(key, "d1")], where[(key, "d2")]))
            elif j.axis is not None:
                u = _v3(j.normal) if j.normal is not None else _basis(_v3(j.axis))[0]
                add((key, "u"), ("link", index[j.tail], u))
                add((key, "w"), ("cross", where[(key, "a")], where[(key, "u")]))
    for p in net.linkage.ports:
        if p.kind == "load":
            key = ("port", p.name)
            points.append((index[p.link], _v3(p.point)))
            load = (_v3(p.force) if p.force is not None else (z * p.torque[0] if net.planar else _v3(p.torque)))
            for name, v in (("x", eye[0]), ("y", eye[1]), ("z", z), ("load", load)):
                add((key, name), ("world", v))
    keys = [k for k in dict.fromkeys(key for key, _ in where)]
    pos = {k: i for i, k in enumerate(keys)}
    kinds = [d[0] for d in dirs]
    plan = {
        "keys": keys, "where": where,
        "pt_link": np.array([lk for lk, _ in points], dtype=int), "pt_ref": np.array([c for _, c in points]),
        "world": np.array([i for i, k in enumerate(kinds) if k == "world"], dtype=int),
        "world_v": np.array([d[1] for d in dirs if d[0] == "world"]),
        "link": np.array([i for i, k in enumerate(kinds) if k == "link"], dtype=int),
        "link_l": np.array([d[1] for d in dirs if d[0] == "link"], dtype=int),
        "link_v": np.array([d[2] for d in dirs if d[0] == "link"]).reshape(-1, 3),
        "cross": np.array([i for i, k in enumerate(kinds) if k == "cross"], dtype=int),
        "cross_ij": np.array([(d[1], d[2]) for d in dirs if d[0] == "cross"], dtype=int).reshape(-1, 2),
        "n": len(dirs),
    }

    def arrays(cols):
        point = np.array([pos[c.spec[1]] for c in cols], dtype=int)
        direction = np.array([where[(c.spec[1], c.spec[2])] for c in cols], dtype=int)
        moment = np.array([c.spec[0] in ("rot", "force") for c in cols])[:, None]
        angular = np.array([c.spec[0] in ("rot", "couple") for c in cols])[:, None]
        return point, direction, moment, angular

    plan["motion"], plan["action"] = arrays(net.motion_cols), arrays(net.action_cols)
    return plan
