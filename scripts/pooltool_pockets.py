#!/usr/bin/env python3
"""Our jaws against pooltool's pocket table: for a slow ball rolled straight at a pocket, what comes first, a jaw
(its rounded point or its facing), a rail or the pocket?

pooltool (github.com/ekiefl/pooltool) cannot be installed on our machines: it is published only on the Python
package index (as pooltool-billiards, with numba and panda3d), which they do not reach. This script is therefore a
reconstruction: it rebuilds pooltool 0.6.0's default pocket table from the geometric definitions in pooltool's
source at tag v0.6.0, read file by file. No pooltool code is copied, and neither pooltool nor numpy is needed:
  pooltool/objects/table/specs.py        PocketTableSpecs and its defaults (78 x 39 in, corner mouth 0.118 m, ...)
  pooltool/objects/ball/params.py        BallParams.R = 0.028575 m
  pooltool/objects/table/collection.py   the default table, SEVEN_FOOT_SHOWOOD, takes the same numbers
  pooltool/objects/table/layout.py       create_pocket_table_cushion_segments and create_pocket_table_pockets:
                                         where the rails, the jaws' facings, their rounding circles and the pockets'
                                         circles lie, and the side each straight segment is met from
  pooltool/objects/table/components.py   LinearCushionSegment (the line lx x + ly y + l0 = 0 through p1 and p2, and
                                         its direction: SIDE1, SIDE2), CircularCushionSegment, Pocket
  pooltool/evolution/event_based/solve.py  the event rules: a straight segment is met when the ball's centre comes
                                         within R of its line on its side, with the centre's projection between p1
                                         and p2; a jaw's circle when the centre comes within its radius plus R; a
                                         pocket when the centre reaches the pocket's circle
  pooltool/evolution/event_based/simulate.py  the earliest event comes first
  pooltool/physics/resolve/ball_pocket/__init__.py  a potted ball leaves the table at once
A ball rolling straight (no side spin) runs along a line, so its first event in pooltool follows from these rules by
geometry alone, whatever its speed.

pooltool's frame has its origin at a corner of the cloth, x across the width (0..w) and y along the length (0..l);
ours has its origin at the centre and x along the length: x_ours = y_pt - l/2, y_ours = w/2 - x_pt. pooltool's
pocket "lt" is then our top_right, "lc" our top_side.

The reconstruction maps onto our cut (table.corner_pockets, table.side_pockets; docs/tables.md): the jaw points are
pooltool's sharp points (mouth = pocket width), the facing turns from the nose by 135 deg + the corner's angle or
90 deg + the side's, the rounding is pooltool's jaw radius, and pooltool's pocket circle is our drop circle (shelf =
how far behind the mouth's middle its centre lies, less its radius). Our nose height decides where a ball touches a
nose, R cos(theta) from its centre with sin(theta) = (h - R)/R; pooltool touches at R whatever its cushion height.
--nose-height r puts our nose at R, where the two contact rules coincide; --nose-height pooltool keeps pooltool's
0.036576 m, where our contact is 27.432 mm from the centre.

The sweep: parallel lines into our top_right pocket (pooltool's "lt") at 0, 15, 30 and 40 deg from its axis and into
top_side ("lc") at 0, 20, 40 and 60 deg. The heading is the pocket's axis turned clockwise by the angle; the offset
is measured across the line from the middle of the mouth, positive to the left of the ball's travel. Lines lie 4 mm
apart over the mouth and two balls beyond, and 1 mm apart within 4.5 mm of every place where the first event
changes (pooltool's rules at either nose height, and our outline rebuilt here from docs/tables.md's definitions).
Each ball starts 0.3 m back along its line (or where the line comes onto the cloth), rolling, with the speed that
brings it to its first event at about 0.5 m/s, and impact_solve (problem ball_motion, pocket_model jaws) predicts
it. Then every edge, the offset where pooltool's first event changes (its geometry alone, bisected), is checked by a
ball 0.1 mm to each side of it.

Usage: pooltool_pockets.py IMPACT_SOLVE [--nose-height r|pooltool] [--out DIR] [--quick] [--edges-only]
  IMPACT_SOLVE   the path of the impact_solve binary, run one request at a time. A binary in the build tree finds
                 its libraries by its rpath; for a copy elsewhere the caller sets LD_LIBRARY_PATH, which the script
                 passes on unchanged.
  --quick        one angle per pocket (corner 40 deg, side 40 deg), lines 8 mm apart and 0.5 and 1.5 mm either
                 side of each change: 111 lines and 13 edges, about 140 runs (the full sweep: 831 lines and 45
                 edges, about 920 runs)
  --edges-only   only the balls either side of the edges (2 runs per edge)
Prints the reconstruction, the mapped table, the agreement per pocket and angle and the edge checks; writes
results.json (every line and edge with pooltool's, our outline's and impact_solve's first event) and agreement.txt
(the report without the progress lines) to --out (default: the current directory). The script exits with 1 when a line's
first event differs at --nose-height r, where the two should agree everywhere.
"""
import argparse
import json
import math
import os
import subprocess
import sys

BALL_RADIUS = 0.028575  # pooltool's BallParams.R, a 2.25 in ball

# PocketTableSpecs' defaults at v0.6.0 (= TABLE_SPECS[SEVEN_FOOT_SHOWOOD]), m and deg.
SPECS = {
    "l": 1.9812,
    "w": 1.9812 / 2,
    "cushion_width": 2 * 2.54 / 100,  # how far behind the rails' lines the facings' far ends lie
    "cushion_height": 0.64 * 2 * 0.028575,
    "corner_pocket_width": 0.118,
    "corner_pocket_angle": 5.3,
    "corner_pocket_depth": 0.0417,
    "corner_pocket_radius": 0.062,
    "corner_jaw_radius": 0.02095,
    "side_pocket_width": 0.137,
    "side_pocket_angle": 7.14,
    "side_pocket_depth": 0.0685,
    "side_pocket_radius": 0.0645,
    "side_jaw_radius": 0.00795,
}

# layout.py's direction of each straight segment: 0 = SIDE1 (met where lx x + ly y + l0 = -R |(lx, ly)|), 1 = SIDE2.
PT_DIRECTION = {"3": 1, "6": 1, "18": 1, "4": 1, "14": 1, "1": 1, "7": 1, "11": 1, "17": 1,
                "15": 0, "12": 0, "9": 0, "5": 0, "13": 0, "2": 0, "8": 0, "10": 0, "16": 0}

# pooltool's segment and pocket ids in ours (docs/tables.md: a corner's jaws are named by their rails, a side
# pocket's by the side of it they stand on). The frame map above places each one.
PT_POCKETS = {"lb": "top_left", "lt": "top_right", "rb": "bottom_left", "rt": "bottom_right", "lc": "top_side",
              "rc": "bottom_side"}
PT_JAWS = {"1": "top_left.jaw.left", "2": "top_left.jaw.top", "7": "top_right.jaw.top", "8": "top_right.jaw.right",
           "10": "bottom_right.jaw.right", "11": "bottom_right.jaw.bottom", "16": "bottom_left.jaw.bottom",
           "17": "bottom_left.jaw.left", "4": "top_side.jaw.left", "5": "top_side.jaw.right",
           "14": "bottom_side.jaw.left", "13": "bottom_side.jaw.right"}
PT_RAILS = {"3": "rail.top.left", "6": "rail.top.right", "9": "rail.right", "12": "rail.bottom.right",
            "15": "rail.bottom.left", "18": "rail.left"}

ANGLES = {"top_right": [0, 15, 30, 40], "top_side": [0, 20, 40, 60]}
QUICK_ANGLES = {"top_right": [40], "top_side": [40]}
RUN_UP = 0.3  # m before the mouth
ARRIVAL = 0.5  # m/s at the first event
EDGE_MARGIN = 1e-4  # m either side of an edge
SCAN_STEP = 1e-4  # m between the offsets scanned for changes of the first event


class V(tuple):
    """A vector of the table plane (numpy may be absent)."""

    def __new__(cls, x, y):
        return tuple.__new__(cls, (float(x), float(y)))

    def __add__(self, o):
        return V(self[0] + o[0], self[1] + o[1])

    def __sub__(self, o):
        return V(self[0] - o[0], self[1] - o[1])

    def __neg__(self):
        return V(-self[0], -self[1])

    def __mul__(self, k):
        return V(self[0] * k, self[1] * k)

    __rmul__ = __mul__

    def __truediv__(self, k):
        return V(self[0] / k, self[1] / k)

    def __matmul__(self, o):
        return self[0] * o[0] + self[1] * o[1]


def norm(v):
    return math.hypot(v[0], v[1])


def unit(v):
    return v / norm(v)


def rotated(v, angle):
    c, s = math.cos(angle), math.sin(angle)
    return V(c * v[0] - s * v[1], s * v[0] + c * v[1])


def to_pooltool(p, specs=SPECS):
    return V(specs["w"] / 2 - p[1], p[0] + specs["l"] / 2)


def direction_to_pooltool(d):
    return V(-d[1], d[0])


def to_ours(p, specs=SPECS):
    return V(p[1] - specs["l"] / 2, specs["w"] / 2 - p[0])


# ------------------------------------------------------------------------------------------ the reconstruction
def reconstruction(specs=SPECS):
    """pooltool's pocket table in its own frame: straight segments (rails, facings), jaw circles and pocket circles.

    Each jaw is built from its sharp point P on the rail's line, e the unit along the rail away from the pocket and n
    the rail's outward normal (into the cushion). The facing leaves P at f = cos(a) n - sin(a) e, turned from the rail
    by 90 deg + a (a = 45 deg + the corner's angle, or the side's angle). The rounding circle of radius rho touches
    the rail and the facing d = rho / tan((90 deg + a) / 2) from P; the rail stops at P + d e and the facing runs from
    its tangent point P + d f to its far end cushion_width behind the rail's line. layout.py places a corner facing's
    far end on the facing's line (cushion_width tan(a) along the rail) and a side facing's at cushion_width sin(a),
    0.05 mm off that line: the reconstruction keeps that kink.
    """
    l, w, cw = specs["l"], specs["w"], specs["cushion_width"]
    ca = math.radians(specs["corner_pocket_angle"] + 45)
    sa = math.radians(specs["side_pocket_angle"])
    pw, sw = specs["corner_pocket_width"], specs["side_pocket_width"]
    rc, rs = specs["corner_jaw_radius"], specs["side_jaw_radius"]
    dc = rc / math.tan((math.pi / 2 + ca) / 2)
    ds = rs / math.tan((math.pi / 2 + sa) / 2)
    east, north = V(1, 0), V(0, 1)
    lines, circles, rail_ends = {}, {}, {}

    def jaw(jid, P, e, n, a, rho, d, far_along, pocket):
        f = math.cos(a) * n - math.sin(a) * e
        lines[jid] = {"id": jid, "p1": P + cw * n - cw * far_along * e, "p2": P + d * f, "kind": "facing",
                      "pocket": pocket}
        circles[jid + "t"] = {"id": jid + "t", "centre": P + d * e + rho * n, "radius": rho, "kind": "point",
                              "pocket": pocket, "jaw": jid}
        rail_ends[jid] = P + d * e

    k = pw * math.cos(math.pi / 4)
    tc, ts = math.tan(ca), math.sin(sa)
    # Corners: (0, 0) jaws 1 (on y = 0) and 2 (on x = 0); (0, l) 7 and 8; (w, l) 10 and 11; (w, 0) 16 and 17.
    jaw("1", V(k, 0), east, -north, ca, rc, dc, tc, "lb")
    jaw("2", V(0, k), north, -east, ca, rc, dc, tc, "lb")
    jaw("7", V(0, l - k), -north, -east, ca, rc, dc, tc, "lt")
    jaw("8", V(k, l), east, north, ca, rc, dc, tc, "lt")
    jaw("10", V(w - k, l), -east, north, ca, rc, dc, tc, "rt")
    jaw("11", V(w, l - k), -north, east, ca, rc, dc, tc, "rt")
    jaw("16", V(w, k), north, east, ca, rc, dc, tc, "rb")
    jaw("17", V(w - k, 0), -east, -north, ca, rc, dc, tc, "rb")
    # Sides: (0, l/2) jaws 4 (towards y = 0) and 5; (w, l/2) 14 and 13.
    jaw("4", V(0, (l - sw) / 2), -north, -east, sa, rs, ds, ts, "lc")
    jaw("5", V(0, (l + sw) / 2), north, -east, sa, rs, ds, ts, "lc")
    jaw("14", V(w, (l - sw) / 2), -north, east, sa, rs, ds, ts, "rc")
    jaw("13", V(w, (l + sw) / 2), north, east, sa, rs, ds, ts, "rc")
    for rid, a, b in [("3", "2", "4"), ("6", "5", "7"), ("15", "16", "14"), ("12", "13", "11"), ("18", "1", "17"),
                      ("9", "8", "10")]:
        lines[rid] = {"id": rid, "p1": rail_ends[a], "p2": rail_ends[b], "kind": "rail", "pocket": None}
    cd, sd = specs["corner_pocket_depth"] / math.sqrt(2), specs["side_pocket_depth"]
    rcp, rsp = specs["corner_pocket_radius"], specs["side_pocket_radius"]
    pockets = {"lb": (V(-cd, -cd), rcp), "lt": (V(-cd, l + cd), rcp), "rb": (V(w + cd, -cd), rcp),
               "rt": (V(w + cd, l + cd), rcp), "lc": (V(-sd, l / 2), rsp), "rc": (V(w + sd, l / 2), rsp)}
    for segment in lines.values():  # components.py's line form through p1 and p2
        p1, p2 = segment["p1"], segment["p2"]
        if p2[0] == p1[0]:
            lx, ly, l0 = 1.0, 0.0, -p1[0]
        else:
            m = (p2[1] - p1[1]) / (p2[0] - p1[0])
            lx, ly, l0 = -m, 1.0, m * p1[0] - p1[1]
        segment.update(lx=lx, ly=ly, l0=l0, direction=PT_DIRECTION[segment["id"]])
    return {"lines": lines, "circles": circles, "pockets": pockets, "tangent": {"corner": dc, "side": ds}}


RECONSTRUCTION = reconstruction()


def our_name(kind, pt_id):
    """pooltool's segment, circle or pocket by our id (the pocket's id for a pot)."""
    if kind == "pocket":
        return PT_POCKETS[pt_id]
    if kind == "rail":
        return PT_RAILS[pt_id]
    if kind == "facing":
        return "pocket." + PT_JAWS[pt_id] + ".facing"
    return "pocket." + PT_JAWS[pt_id[:-1]] + ".point"


def circle_entry(start, d, centre, radius):
    """The least distance t > 0 along the unit d at which start + t d lies on the circle, or inf."""
    q = start - centre
    b = q @ d
    disc = b * b - (q @ q - radius * radius)
    if disc < 0:
        return math.inf
    root = math.sqrt(disc)
    for t in (-b - root, -b + root):
        if t > 1e-12:
            return t
    return math.inf


def pooltool_first_event(start, d, contact=BALL_RADIUS, table=RECONSTRUCTION):
    """pooltool's first event for a ball running from `start` along the unit `d` (our frame) by its event rules:
    (class, our id, distance). `contact` is how far from a nose the centre stops, R in pooltool; our reach in its
    place gives the events our contact rule would give on pooltool's outline."""
    s, dp = to_pooltool(start), direction_to_pooltool(d)
    best = (math.inf, "none", None)
    for segment in table["lines"].values():
        scale = math.hypot(segment["lx"], segment["ly"])
        target = (contact if segment["direction"] == 1 else -contact) * scale
        f0 = segment["lx"] * s[0] + segment["ly"] * s[1] + segment["l0"]
        df = segment["lx"] * dp[0] + segment["ly"] * dp[1]
        if df == 0:
            continue
        t = (target - f0) / df
        if t <= 1e-12:
            continue
        centre = s + t * dp
        p1, p2 = segment["p1"], segment["p2"]
        along = (centre - p1) @ (p2 - p1) / ((p2 - p1) @ (p2 - p1))
        if 0 <= along <= 1 and t < best[0]:
            best = (t, segment["kind"], segment["id"])
    for circle in table["circles"].values():
        t = circle_entry(s, dp, circle["centre"], circle["radius"] + contact)
        if t < best[0]:
            best = (t, "point", circle["id"])
    for pid, (centre, radius) in table["pockets"].items():
        t = circle_entry(s, dp, centre, radius)
        if t < best[0]:
            best = (t, "pocket", pid)
    if best[1] == "none":
        return "none", None, math.inf
    return best[1], our_name(best[1], best[2]), best[0]


# ------------------------------------------------------------------------------------------ our table and outline
def mapped_table(nose_height, specs=SPECS):
    """Our table parameters (impact_solve's `table`) for pooltool's table."""
    return {
        "length": specs["l"],
        "width": specs["w"],
        "cushion_height": nose_height,
        "pocket_layout": "six",
        "pocket_model": "jaws",
        "corner_pockets": {"mouth": specs["corner_pocket_width"], "facing_angle": 135.0 + specs["corner_pocket_angle"],
                           "shelf": specs["corner_pocket_width"] / 2 + specs["corner_pocket_depth"]
                           - specs["corner_pocket_radius"],
                           "jaw_radius": specs["corner_jaw_radius"], "drop_radius": specs["corner_pocket_radius"]},
        "side_pockets": {"mouth": specs["side_pocket_width"], "facing_angle": 90.0 + specs["side_pocket_angle"],
                         "shelf": specs["side_pocket_depth"] - specs["side_pocket_radius"],
                         "jaw_radius": specs["side_jaw_radius"], "drop_radius": specs["side_pocket_radius"]},
    }


def reach(nose_height, radius=BALL_RADIUS):
    """Our contact distance: R cos(theta), sin(theta) = (h - R)/R."""
    sin_theta = max(-1.0, min(1.0, (nose_height - radius) / radius))
    return radius * math.sqrt(1 - sin_theta * sin_theta)


def our_outline(table):
    """Our outline rebuilt from docs/tables.md's definitions: rails and facings as segments, each jaw's rounding as a
    full circle (for a ball coming from the cloth the rest of the circle lies behind the nose), the drop circles, and
    per pocket the middle of its mouth and its axis."""
    x, y = table["length"] / 2, table["width"] / 2
    east, north = V(1, 0), V(0, 1)
    # Counterclockwise from the bottom-left pocket: the direction the outline comes in by and leaves by, and the
    # names of the jaw it reaches the pocket by and leaves it by, then the rail that follows.
    places = [("bottom_left", V(-x, -y), -north, east, True, "left", "bottom", "rail.bottom.left"),
              ("bottom_side", V(0, -y), east, east, False, "left", "right", "rail.bottom.right"),
              ("bottom_right", V(x, -y), east, north, True, "bottom", "right", "rail.right"),
              ("top_right", V(x, y), north, -east, True, "right", "top", "rail.top.right"),
              ("top_side", V(0, y), -east, -east, False, "right", "left", "rail.top.left"),
              ("top_left", V(-x, y), -east, -north, True, "top", "left", "rail.left")]
    lines, circles, pockets, rail_in, rail_out = [], [], {}, {}, {}
    for pid, corner_at, d_in, d_out, corner, jaw_in, jaw_out, _ in places:
        cut = table["corner_pockets"] if corner else table["side_pockets"]
        angle = math.radians(cut["facing_angle"])
        if corner:
            a_in = corner_at - cut["mouth"] / math.sqrt(2) * d_in
            a_out = corner_at + cut["mouth"] / math.sqrt(2) * d_out
            axis = unit(d_in - d_out)
        else:
            a_in, a_out = corner_at - 0.5 * cut["mouth"] * d_in, corner_at + 0.5 * cut["mouth"] * d_in
            axis = -rotated(d_in, math.pi / 2)
        f_in, f_out = rotated(d_in, -(math.pi - angle)), rotated(-d_out, math.pi - angle)
        depth = cut["shelf"] + cut["drop_radius"]
        facing_length = depth / (f_in @ axis)
        middle = 0.5 * (a_in + a_out)
        pockets[pid] = {"drop": (middle + depth * axis, cut["drop_radius"]), "middle": middle, "axis": axis}
        rho = cut["jaw_radius"]
        tangent = rho / math.tan(0.5 * angle)
        for tip, rail, facing, name, store in [(a_in, d_in, f_in, jaw_in, rail_in),
                                               (a_out, -d_out, f_out, jaw_out, rail_out)]:
            jid = f"pocket.{pid}.jaw.{name}"
            store[pid] = tip - tangent * rail
            lines.append((jid + ".facing", tip + tangent * facing, tip + facing_length * facing))
            if rho > 0:
                circles.append((jid + ".point", tip + unit(facing - rail) * (rho / math.sin(0.5 * angle)), rho))
    for k, place in enumerate(places):
        lines.append((place[7], rail_out[place[0]], rail_in[places[(k + 1) % 6][0]]))
    return {"lines": lines, "circles": circles, "pockets": pockets}


def capsule_entry(start, d, a, b, r):
    """The least t > 0 at which start + t d comes within r of the segment ab."""
    best = min(circle_entry(start, d, a, r), circle_entry(start, d, b, r))
    u = b - a
    length = norm(u)
    if length > 0:
        u = u / length
        normal = V(-u[1], u[0])
        dn = d @ normal
        if dn != 0:
            for side in (r, -r):
                t = (side - (start - a) @ normal) / dn
                if t > 1e-12 and 0 <= (start + t * d - a) @ u <= length:
                    best = min(best, t)
    return best


def kind_of(name):
    """The class of a first event by our id: pocket (a pocket's id), rail, point or facing."""
    if name.startswith("rail."):
        return "rail"
    if name.endswith(".point"):
        return "point"
    if name.endswith(".facing"):
        return "facing"
    return "pocket"


def outline_first_event(start, d, outline, contact):
    """Our first event by geometry alone along the line: the centre within `contact` of a nose, or over a drop
    circle. (class, id, distance)."""
    candidates = [(capsule_entry(start, d, a, b, contact), name) for name, a, b in outline["lines"]]
    candidates += [(circle_entry(start, d, centre, radius + contact), name)
                   for name, centre, radius in outline["circles"]]
    candidates += [(circle_entry(start, d, *pocket["drop"]), pid) for pid, pocket in outline["pockets"].items()]
    best = min(candidates, key=lambda candidate: candidate[0])
    if best[0] == math.inf:
        return "none", None, math.inf
    return kind_of(best[1]), best[1], best[0]


def coarse(kind):
    """pocket, jaw (a point or a facing) or rail."""
    return "jaw" if kind in ("point", "facing") else kind


# ------------------------------------------------------------------------------------------ the lines
class Lines:
    """The lines of the sweep on the mapped table; the same lines whatever the nose height, so that the two runs
    compare line by line."""

    def __init__(self):
        self.table = mapped_table(BALL_RADIUS)
        self.outline = our_outline(self.table)
        self.reaches = {"r": BALL_RADIUS, "pooltool": reach(SPECS["cushion_height"])}

    def line(self, pocket, theta, offset):
        """(start, d, run-up) of the line at `theta` deg from the pocket's axis and `offset` m across it, or None.
        The run-up is RUN_UP when the start is then on the cloth (its centre more than R + 1 mm inside the rails'
        lines); else the start is 0.15 m back from where the line comes onto the cloth, or as far back as it stays
        there."""
        frame = self.outline["pockets"][pocket]
        d = rotated(frame["axis"], -math.radians(theta))
        through = frame["middle"] + offset * rotated(d, math.pi / 2)
        half = (self.table["length"] / 2 - BALL_RADIUS - 0.001, self.table["width"] / 2 - BALL_RADIUS - 0.001)
        lo, hi = 0.0, 2.0  # run-ups k for which through - k d is on the cloth
        for i in (0, 1):
            if d[i] == 0:
                if abs(through[i]) > half[i]:
                    return None
                continue
            k1, k2 = (through[i] - half[i]) / d[i], (through[i] + half[i]) / d[i]
            lo, hi = max(lo, min(k1, k2)), min(hi, max(k1, k2))
        if lo > hi:
            return None
        run_up = RUN_UP if lo <= RUN_UP <= hi else (min(hi, lo + 0.15) if lo > RUN_UP else hi)
        return through - run_up * d, d, run_up

    def classify(self, pocket, theta, offset):
        """pooltool's first event and our outline's at each nose height, by geometry alone; None off the cloth."""
        got = self.line(pocket, theta, offset)
        if got is None:
            return None
        start, d, run_up = got
        answer = {"start": list(start), "d": list(d), "run_up": run_up, "pooltool": pooltool_first_event(start, d)}
        for name, contact in self.reaches.items():
            answer["outline_" + name] = outline_first_event(start, d, self.outline, contact)
        return answer

    def offsets(self, pocket, theta, quick=False):
        """The sweep's offsets: 4 mm apart over the mouth and two balls beyond (8 mm when quick), and within 4.5 mm
        of every change of any geometric first event 1 mm apart (quick: 0.5 mm and 1.5 mm either side)."""
        mouth = self.table["corner_pockets" if pocket == "top_right" else "side_pockets"]["mouth"]
        reach_out = mouth / 2 + 2 * BALL_RADIUS + 0.01
        count = int(reach_out / SCAN_STEP)
        keys = ["pooltool"] + ["outline_" + name for name in self.reaches]
        previous, changes = None, []
        for k in range(-count, count + 1):
            s = k * SCAN_STEP
            c = self.classify(pocket, theta, s)
            label = None if c is None else tuple(coarse(c[key][0]) for key in keys)
            if previous is not None and label != previous[1]:
                changes.append(0.5 * (s + previous[0]))
            previous = (s, label)
        grid = 0.008 if quick else 0.004
        chosen = {round(k * grid, 4) for k in range(-int(reach_out / grid), int(reach_out / grid) + 1)}
        steps = (-2, -1, 0, 1) if quick else range(-4, 5)
        for change in changes:
            base = round(change, 3)
            for j in steps:
                chosen.add(round(base + j * 0.001 + 0.0005, 4))
        return sorted(s for s in chosen if abs(s) <= reach_out)

    def edges(self, pocket, theta):
        """The offsets where pooltool's first event changes (its class or what it meets), scanned every 0.1 mm over
        the mouth and two balls beyond and bisected to 1e-8 m: [(offset, event below, event above, run-up)]. A band
        narrower than the scan's step may be missed."""
        mouth = self.table["corner_pockets" if pocket == "top_right" else "side_pockets"]["mouth"]
        count = int((mouth / 2 + 2 * BALL_RADIUS + 0.01) / SCAN_STEP)

        def event(s):
            c = self.classify(pocket, theta, s)
            return None if c is None else c["pooltool"][1]

        found, previous = [], None
        for k in range(-count, count + 1):
            s = k * SCAN_STEP
            now = event(s)
            if previous is not None and now != previous[1] and now is not None and previous[1] is not None:
                lo, hi = previous[0], s
                while hi - lo > 1e-8:
                    middle = 0.5 * (lo + hi)
                    if event(middle) == previous[1]:
                        lo = middle
                    else:
                        hi = middle
                at = 0.5 * (lo + hi)
                found.append((at, previous[1], now, self.line(pocket, theta, at)[2]))
            previous = (s, now)
        return found


# ------------------------------------------------------------------------------------------ impact_solve
class Solver:
    """impact_solve on the mapped table, one request at a time."""

    def __init__(self, path, nose_height):
        self.path = path
        self.table = mapped_table(nose_height)
        self.runs = 0
        self.deceleration = self.calibrate()

    def request(self, start, velocity):
        """A rolling ball (omega = z x v / R) on the mapped table."""
        return {"problem": "ball_motion", "position": [start[0], start[1]], "v": [velocity[0], velocity[1], 0.0],
                "omega": [-velocity[1] / BALL_RADIUS, velocity[0] / BALL_RADIUS, 0.0], "ball_radius": BALL_RADIUS,
                "table": self.table}

    def solve(self, request):
        self.runs += 1
        done = subprocess.run([self.path], input=json.dumps(request), capture_output=True, text=True)
        if done.returncode != 0:
            return None, f"exit {done.returncode}: {done.stderr.strip()[:200]}"
        return json.loads(done.stdout), None

    def calibrate(self):
        """The rolling deceleration of impact_solve's default rolling model, from a roll along the table's long axis
        into rail.right: constant between the last event before the hit and the hit."""
        answer, error = self.solve(self.request(V(-0.5, 0.0), V(1.0, 0.0)))
        if error:
            sys.exit(f"impact_solve failed: {error}")
        hit = next(e for e in answer["events"] if e["type"] == "cushion_hit")
        before = [e for e in answer["events"] if e["t"] < hit["t"]][-1]
        t, x, u = hit["t"] - before["t"], hit["position"][0] - before["position"][0], before["v"][0]
        return 2 * (u * t - x) / (t * t)

    def first_event(self, start, d, distance):
        """impact_solve's first event for a ball that reaches `distance` along its line at about ARRIVAL m/s:
        {class, id, position, speed} or {error}."""
        speed = math.sqrt(ARRIVAL ** 2 + 2 * self.deceleration * min(distance, 2.0))
        answer, error = self.solve(self.request(start, V(speed * d[0], speed * d[1])))
        if error:
            return {"error": error}
        for event in answer["events"]:
            name = {"cushion_hit": event.get("cushion"), "cushion_contact": event.get("cushion"),
                    "pocketed": event.get("pocket")}.get(event["type"])
            if name is not None:
                return {"kind": kind_of(name), "id": name, "position": event["position"][:2],
                        "speed": math.hypot(*event["v"][:2]) if event.get("v") else None}
            if event["type"] not in ("start", "slide_to_roll", "roll_to_spin", "spin_stop"):
                return {"kind": "other", "id": event["type"], "position": event["position"][:2], "speed": None}
        return {"kind": "none", "id": None, "position": None, "speed": None}


# ------------------------------------------------------------------------------------------ the report
def describe_reconstruction(out):
    specs, rec = SPECS, RECONSTRUCTION

    def at(p):
        return f"({p[0]:+.5f}, {p[1]:+.5f})"

    out(f"pooltool v0.6.0's default pocket table, reconstructed (our frame, m): cloth {specs['l']} x {specs['w']:.4f},"
        f" cushion height {specs['cushion_height']:.6f}, ball R {BALL_RADIUS}")
    for pid in ("lt", "lc"):
        centre, radius = rec["pockets"][pid]
        out(f"  pocket {pid} (our {PT_POCKETS[pid]}): centre {at(to_ours(centre))}, radius {radius}")
    for jid in ("7", "8", "4", "5"):
        facing, circle = rec["lines"][jid], rec["circles"][jid + "t"]
        out(f"  jaw {jid} (our {PT_JAWS[jid]}): facing {at(to_ours(facing['p2']))} -> {at(to_ours(facing['p1']))}, "
            f"rounding centre {at(to_ours(circle['centre']))} radius {circle['radius']}")
    table = mapped_table(BALL_RADIUS)
    for key in ("corner_pockets", "side_pockets"):
        out(f"  mapped {key}: " + ", ".join(f"{k} {v:.6g}" for k, v in table[key].items()))
    outline = our_outline(table)
    worst = 0.0
    for name, centre, radius in outline["circles"]:  # our roundings against pooltool's
        jid = next(j for j, ours in PT_JAWS.items() if name == f"pocket.{ours}.point")
        worst = max(worst, norm(centre - to_ours(rec["circles"][jid + "t"]["centre"])))
    for pid, pocket in outline["pockets"].items():
        pt_id = next(p for p, ours in PT_POCKETS.items() if ours == pid)
        worst = max(worst, norm(pocket["drop"][0] - to_ours(rec["pockets"][pt_id][0])))
    out(f"  our outline's jaw roundings and drop circles lie within {worst * 1e9:.1f} nm of pooltool's")


def agreement(records, variant, out):
    """The agreement table of impact_solve's first events with pooltool's; the number of lines that differ."""
    key = "solver"
    out(f"nose height {variant}: our contact {reach_for(variant) * 1e3:.3f} mm from the ball's centre, pooltool's "
        f"{BALL_RADIUS * 1e3:.3f} mm")
    out("first event: pocket, jaw (point or facing) or rail. same: lines with the same class of first event; part:")
    out("the same part of the jaw, of the lines where both meet a jaw; id: the same cushion or pocket; reach: lines")
    out("that differ where pooltool's rules, with the contact at our reach, give our event (the contact rule's doing)")
    out(f"{'pocket':10} {'deg':>3} {'lines':>5} {'same':>5} {'part':>9} {'id':>5} {'reach':>5}  "
        "lines that differ (offset mm: pooltool -> ours)")
    totals = {"lines": 0, "same": 0, "jaws": 0, "parts": 0, "ids": 0, "differ": 0, "explained": 0, "errors": 0}
    groups = sorted({(r["pocket"], r["theta"]) for r in records}, key=lambda g: (g[0] != "top_right", g[1]))
    for pocket, theta in groups:
        rows = [r for r in records if (r["pocket"], r["theta"]) == (pocket, theta) and "kind" in r[key]]
        totals["errors"] += sum(1 for r in records if (r["pocket"], r["theta"]) == (pocket, theta)
                                and "error" in r[key])
        differ = [r for r in rows if coarse(r["pooltool"][0]) != coarse(r[key]["kind"])]
        jaws = [r for r in rows if coarse(r["pooltool"][0]) == "jaw" == coarse(r[key]["kind"])]
        parts = sum(r["pooltool"][0] == r[key]["kind"] for r in jaws)
        ids = sum(r["pooltool"][1] == r[key]["id"] for r in rows)
        explained = sum(coarse(r["pooltool_at_reach"][0]) == coarse(r[key]["kind"]) for r in differ)
        totals.update(lines=totals["lines"] + len(rows), same=totals["same"] + len(rows) - len(differ),
                      jaws=totals["jaws"] + len(jaws), parts=totals["parts"] + parts, ids=totals["ids"] + ids,
                      differ=totals["differ"] + len(differ), explained=totals["explained"] + explained)
        listed = ", ".join(f"{r['offset'] * 1e3:+.1f}: {coarse(r['pooltool'][0])} -> {coarse(r[key]['kind'])}"
                           for r in differ)
        out(f"{pocket:10} {theta:>3} {len(rows):>5} {len(rows) - len(differ):>5} {f'{parts}/{len(jaws)}':>9} "
            f"{ids:>5} {explained:>5}  {listed}")
    out(f"total: {totals['lines']} lines, {totals['same']} with the same first event, the same part of the jaw on "
        f"{totals['parts']} of {totals['jaws']}, the same cushion or pocket on {totals['ids']}; of the "
        f"{totals['differ']} that differ, {totals['explained']} are the contact rule's; impact_solve failed on "
        f"{totals['errors']}")
    ours = [r for r in records if "kind" in r[key]]
    selfcheck = sum(r["outline"][1] != r[key]["id"] for r in ours)
    out(f"our outline (geometry alone) against impact_solve: {selfcheck} of {len(ours)} lines differ in what they "
        "meet first")
    speeds = [r[key]["speed"] for r in ours if r[key].get("speed") is not None]
    if speeds:
        out(f"speed at the first event: {min(speeds):.3f}..{max(speeds):.3f} m/s")
    return totals["differ"] + totals["errors"]


def edge_report(edges, out):
    """The edges of pooltool's first event and impact_solve's first event EDGE_MARGIN either side; the number of
    sides where the class differs."""
    out(f"edges of pooltool's first event (its geometry alone, bisected to 1e-8 m) and impact_solve's first event "
        f"{EDGE_MARGIN * 1e3:.1f} mm to each side")
    out(f"{'pocket':10} {'deg':>3} {'offset mm':>10} {'run-up':>6}  pooltool below | above  ->  ours below | above")
    wrong = same_id = explained = 0
    for e in edges:
        ours = [e[side + "_solver"].get("id") or e[side + "_solver"].get("error", "?") for side in ("below", "above")]
        same = [kind_of(e[side]) == e[side + "_solver"].get("kind") for side in ("below", "above")]
        by_reach = [kind_of(e[side + "_at_reach"]) == e[side + "_solver"].get("kind") for side in ("below", "above")]
        wrong += same.count(False)
        explained += sum(not a and b for a, b in zip(same, by_reach))
        same_id += (e["below"] == ours[0]) + (e["above"] == ours[1])
        mark = "" if all(same) else ("   <- differs (the contact rule's)" if all(by_reach) else "   <- differs")
        out(f"{e['pocket']:10} {e['theta']:>3} {e['offset'] * 1e3:+10.4f} {e['run_up']:6.3f}  {e['below']} | "
            f"{e['above']}  ->  {ours[0]} | {ours[1]}{mark}")
    out(f"{len(edges)} edges: on {2 * len(edges) - wrong} of {2 * len(edges)} sides impact_solve's first event is of "
        f"pooltool's class, on {same_id} it meets the same cushion or pocket; of the {wrong} sides that differ, "
        f"{explained} are the contact rule's")
    return wrong


def reach_for(variant):
    return reach(BALL_RADIUS if variant == "r" else SPECS["cushion_height"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("impact_solve", help="path of the impact_solve binary")
    parser.add_argument("--nose-height", choices=["r", "pooltool"], default="r",
                        help="our nose height: the ball's radius (default) or pooltool's cushion height")
    parser.add_argument("--out", default=".", help="directory for results.json and agreement.txt (default: .)")
    parser.add_argument("--quick", action="store_true", help="one angle per pocket and fewer lines")
    parser.add_argument("--edges-only", action="store_true", help="only the balls either side of the edges")
    args = parser.parse_args()
    if not os.access(args.impact_solve, os.X_OK):
        sys.exit(f"{args.impact_solve}: not an executable")
    os.makedirs(args.out, exist_ok=True)
    report = []

    def out(text=""):
        print(text, flush=True)
        report.append(text)

    describe_reconstruction(out)
    height = BALL_RADIUS if args.nose_height == "r" else SPECS["cushion_height"]
    solver = Solver(args.impact_solve, height)
    lines = Lines()
    out(f"our nose height {height:.6f} m; impact_solve's rolling deceleration {solver.deceleration:.4f} m/s^2")
    angles = QUICK_ANGLES if args.quick else ANGLES
    records, edges = [], []
    for pocket, thetas in angles.items():
        for theta in thetas:
            offsets = [] if args.edges_only else lines.offsets(pocket, theta, args.quick)
            for offset in offsets:
                c = lines.classify(pocket, theta, offset)
                if c is None:
                    continue
                start, d = V(*c["start"]), V(*c["d"])
                record = {"pocket": pocket, "theta": theta, "offset": offset, **c,
                          "outline": c["outline_" + args.nose_height],
                          "pooltool_at_reach": pooltool_first_event(start, d, reach(height))}
                record["solver"] = solver.first_event(start, d, c["pooltool"][2])
                records.append(record)
            for at, below, above, run_up in lines.edges(pocket, theta):
                e = {"pocket": pocket, "theta": theta, "offset": at, "below": below, "above": above, "run_up": run_up}
                for side, sign in (("below", -1), ("above", 1)):
                    c = lines.classify(pocket, theta, at + sign * EDGE_MARGIN)
                    start, d = V(*c["start"]), V(*c["d"])
                    e[side + "_at_reach"] = pooltool_first_event(start, d, reach(height))[1]
                    e[side + "_solver"] = solver.first_event(start, d, c["pooltool"][2])
                edges.append(e)
            print(f"  {pocket} {theta} deg: {len(offsets)} lines, {solver.runs} runs so far", flush=True)
    out()
    failures = 0
    if records:
        failures += agreement(records, args.nose_height, out)
        out()
    wrong = edge_report(edges, out)
    if args.nose_height == "r":
        failures += wrong
    with open(os.path.join(args.out, "results.json"), "w") as fh:
        json.dump({"nose_height": height, "reach": reach(height), "table": mapped_table(height),
                   "deceleration": solver.deceleration, "lines": records, "edges": edges}, fh, indent=1)
    with open(os.path.join(args.out, "agreement.txt"), "w") as fh:
        fh.write("\n".join(report) + "\n")
    print(f"{solver.runs} impact_solve runs; wrote results.json and agreement.txt to {args.out}")
    return 1 if args.nose_height == "r" and failures else 0


if __name__ == "__main__":
    sys.exit(main())
