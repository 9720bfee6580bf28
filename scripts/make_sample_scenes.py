#!/usr/bin/env python3
"""Writes the sample scenes in resources/scenes/.

The scenes are committed as JSON; this script documents where every number
comes from and regenerates them after a deliberate change. Run it from anywhere: python3 scripts/make_sample_scenes.py [OUT_DIR]
(default: resources/scenes). The committed files are exactly its output, and
a test (sample_scenes_generator) keeps them so: after changing a number here,
run it and commit both.
"""
import json
import math
import os
import sys

OUT = os.path.join(os.path.dirname(__file__), "..", "resources", "scenes")


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def newell(points):
    n = [0.0, 0.0, 0.0]
    for i, a in enumerate(points):
        b = points[(i + 1) % len(points)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return n


def r(v):
    return [round(x, 6) + 0.0 for x in v]


class PartBuilder:
    """Collects faces of one part, welding shared vertices."""

    def __init__(self, pid, material, name=None):
        self.pid, self.material, self.name = pid, material, name
        self.vertices, self.faces = [], []

    def vertex(self, p):
        p = r(p)
        for i, q in enumerate(self.vertices):
            if max(abs(p[k] - q[k]) for k in range(3)) < 1e-9:
                return i
        self.vertices.append(p)
        return len(self.vertices) - 1

    def face(self, fid, points, towards=None, away=None, material=None):
        """Adds a face; orients its loop so the normal points towards / away from a point."""
        n = newell(points)
        c = [sum(p[k] for p in points) / len(points) for k in range(3)]
        if towards is not None and dot(n, sub(towards, c)) < 0:
            points = points[::-1]
        if away is not None and dot(n, sub(c, away)) < 0:
            points = points[::-1]
        f = {"id": f"{self.pid}.{fid}", "loop": [self.vertex(p) for p in points]}
        if material:
            f["material"] = material
        self.faces.append(f)
        return f["id"]

    def json(self):
        d = {"id": self.pid}
        if self.name:
            d["name"] = self.name
        d["material"] = self.material
        d["vertices"] = self.vertices
        d["faces"] = self.faces
        return d


def box_part(pid, lo, hi, material, name=None, face_materials=None):
    """A closed box, normals outward. Face ids: px nx py ny pz nz."""
    b = PartBuilder(pid, material, name)
    c = [(lo[k] + hi[k]) / 2 for k in range(3)]
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    quads = {
        "px": [[x1, y0, z0], [x1, y1, z0], [x1, y1, z1], [x1, y0, z1]],
        "nx": [[x0, y0, z0], [x0, y0, z1], [x0, y1, z1], [x0, y1, z0]],
        "py": [[x0, y1, z0], [x0, y1, z1], [x1, y1, z1], [x1, y1, z0]],
        "ny": [[x0, y0, z0], [x1, y0, z0], [x1, y0, z1], [x0, y0, z1]],
        "pz": [[x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]],
        "nz": [[x0, y0, z0], [x0, y1, z0], [x1, y1, z0], [x1, y0, z0]],
    }
    for fid, q in quads.items():
        m = (face_materials or {}).get(fid)
        b.face(fid, q, away=c, material=m)
    return b


def mm(p):
    return [x / 1000.0 for x in p]


def cornell_box():
    """The published Cornell box (its measured geometry), in metres."""
    centre = mm([278, 274.4, 279.6])
    materials = [
        {"id": "white", "reflectance": [0.725, 0.71, 0.68], "emission": [0, 0, 0]},
        {"id": "red", "reflectance": [0.63, 0.065, 0.05], "emission": [0, 0, 0]},
        {"id": "green", "reflectance": [0.14, 0.45, 0.091], "emission": [0, 0, 0]},
        # Exitance = pi x the published radiance 17 12 4.
        {"id": "emitter", "name": "Light", "reflectance": [0.78, 0.78, 0.78],
         "emission": [round(math.pi * v, 6) for v in (17, 12, 4)]},
    ]
    parts = []
    floor = PartBuilder("floor", "white", "Floor")
    floor.face("top", [mm(p) for p in [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]]], towards=centre)
    parts.append(floor)

    # The light sits in a hole of the ceiling: the ceiling is the 3 x 3 grid
    # around the light minus its centre, so light and ceiling share edges.
    ceiling = PartBuilder("ceiling", "white", "Ceiling")
    xs = [0, 213, 343, 556]
    zs = [0, 227, 332, 559.2]
    for i in range(3):
        for j in range(3):
            if i == 1 and j == 1:
                continue
            q = [[xs[i], 548.8, zs[j]], [xs[i + 1], 548.8, zs[j]], [xs[i + 1], 548.8, zs[j + 1]], [xs[i], 548.8, zs[j + 1]]]
            ceiling.face(f"tile{i}{j}", [mm(p) for p in q], towards=centre)
    parts.append(ceiling)

    back = PartBuilder("back-wall", "white", "Back wall")
    back.face("front", [mm(p) for p in [[549.6, 0, 559.2], [0, 0, 559.2], [0, 548.8, 559.2], [556, 548.8, 559.2]]], towards=centre)
    parts.append(back)

    right = PartBuilder("right-wall", "green", "Right wall (green)")
    right.face("inside", [mm(p) for p in [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]]], towards=centre)
    parts.append(right)

    # The published left wall is not planar (its corners leave a plane by about
    # 1.6 mm), so it is two triangles.
    left = PartBuilder("left-wall", "red", "Left wall (red)")
    a, b, c, d = [mm(p) for p in [[552.8, 0, 0], [549.6, 0, 559.2], [556, 548.8, 559.2], [556, 548.8, 0]]]
    left.face("lower", [a, b, c], towards=centre)
    left.face("upper", [a, c, d], towards=centre)
    parts.append(left)

    def block(pid, name, quads, height):
        bl = PartBuilder(pid, "white", name)
        pts = [mm(p) for q in quads for p in q]
        c = [sum(p[k] for p in pts) / len(pts) for k in range(3)]
        names = ["top", "side1", "side2", "side3", "side4"]
        for fid, q in zip(names, quads):
            bl.face(fid, [mm(p) for p in q], away=c)
        # The published blocks have no bottom; closing them makes each a solid.
        top = [mm(p) for p in quads[0]]
        bl.face("bottom", [[p[0], 0.0, p[2]] for p in top], away=c)
        return bl

    short = block("short-block", "Short block", [
        [[130, 165, 65], [82, 165, 225], [240, 165, 272], [290, 165, 114]],
        [[290, 0, 114], [290, 165, 114], [240, 165, 272], [240, 0, 272]],
        [[130, 0, 65], [130, 165, 65], [290, 165, 114], [290, 0, 114]],
        [[82, 0, 225], [82, 165, 225], [130, 165, 65], [130, 0, 65]],
        [[240, 0, 272], [240, 165, 272], [82, 165, 225], [82, 0, 225]],
    ], 165)
    tall = block("tall-block", "Tall block", [
        [[423, 330, 247], [265, 330, 296], [314, 330, 456], [472, 330, 406]],
        [[423, 0, 247], [423, 330, 247], [472, 330, 406], [472, 0, 406]],
        [[472, 0, 406], [472, 330, 406], [314, 330, 456], [314, 0, 456]],
        [[314, 0, 456], [314, 330, 456], [265, 330, 296], [265, 0, 296]],
        [[265, 0, 296], [265, 330, 296], [423, 330, 247], [423, 0, 247]],
    ], 330)

    light = PartBuilder("light.panel", "emitter", "Light")
    light.face("emitter", [mm(p) for p in [[343, 548.8, 227], [343, 548.8, 332], [213, 548.8, 332], [213, 548.8, 227]]], towards=centre)

    objects = [
        {"id": "box", "name": "Cornell box", "parts": [p.json() for p in parts]},
        {"id": "light", "name": "Light", "parts": [light.json()]},
        {"id": "short", "name": "Short block", "parts": [short.json()]},
        {"id": "tall", "name": "Tall block", "parts": [tall.json()]},
    ]
    fov = 2 * math.degrees(math.atan(12.5 / 35))
    return {
        "format": "regio-scene", "version": 1,
        "materials": materials, "objects": objects, "regions": [],
        # Converges (0.1 % unshot) at about 2200 shots, inside its limit.
        "solver": {"hemicube": 200, "patchSize": 0.1, "elementsPerPatch": 9,
                   "adaptive": {"enabled": True, "threshold": 0.05, "minEdge": 0.01},
                   "maxIterations": 3000, "convergence": 0.001},
        "camera": {"position": [0.278, 0.273, -0.8], "target": [0.278, 0.273, 0.0],
                   "up": [0.0, 1.0, 0.0], "fovY": round(fov, 4)},
    }


def two_lights_room():
    """A room lit by two ceiling panels, with a table (desk + legs), a shelf and
    boxes: the kind of scene of the paper's Figure 6. Three regions split the
    room along x; walls, floor and ceiling are cut at the region boundaries so
    that no part straddles one, and each region's BSP order starts with the
    room surfaces that bound it (they split nothing)."""
    W, H, D = 6.0, 3.0, 4.0
    cuts = [0.0, 2.0, 4.0, W]
    centre = [W / 2, H / 2, D / 2]
    materials = [
        {"id": "wall", "name": "Wall paint", "reflectance": [0.75, 0.73, 0.7], "emission": [0, 0, 0]},
        {"id": "floor", "name": "Oak floor", "reflectance": [0.45, 0.32, 0.2], "emission": [0, 0, 0]},
        {"id": "wood", "name": "Table wood", "reflectance": [0.55, 0.4, 0.28], "emission": [0, 0, 0]},
        {"id": "blue", "name": "Blue box", "reflectance": [0.15, 0.25, 0.6], "emission": [0, 0, 0]},
        {"id": "lamp", "name": "Lamp panel", "reflectance": [0.8, 0.8, 0.8], "emission": [40.0, 38.0, 34.0]},
        {"id": "steel", "name": "Lamp housing", "reflectance": [0.6, 0.6, 0.6], "emission": [0, 0, 0]},
    ]
    regions = []
    names = ["west", "middle", "east"]
    room_parts = []
    orders = {n: [] for n in names}
    for k, n in enumerate(names):
        x0, x1 = cuts[k], cuts[k + 1]
        # One flat panel per surface: a room is an open shell, and flat panels
        # are walls by nature (validation does not call them open solids).
        surfaces = [
            ("floor", [[x0, 0, 0], [x1, 0, 0], [x1, 0, D], [x0, 0, D]], "floor"),
            ("ceiling", [[x0, H, 0], [x1, H, 0], [x1, H, D], [x0, H, D]], None),
            ("back", [[x0, 0, D], [x1, 0, D], [x1, H, D], [x0, H, D]], None),
            ("front", [[x0, 0, 0], [x1, 0, 0], [x1, H, 0], [x0, H, 0]], None),
        ]
        if k == 0:
            surfaces.append(("west", [[0, 0, 0], [0, 0, D], [0, H, D], [0, H, 0]], None))
        if k == 2:
            surfaces.append(("east", [[W, 0, 0], [W, 0, D], [W, H, D], [W, H, 0]], None))
        for surface, quad, material in surfaces:
            p = PartBuilder(f"room.{n}.{surface}", material or "wall", f"{surface.capitalize()}, {n}")
            orders[n].append(p.face("inside", quad, towards=centre))
            room_parts.append(p)
        pad = 0.05
        regions.append({"id": n, "name": n.capitalize(),
                        "min": [x0 - (pad if k == 0 else 0), -pad, -pad],
                        "max": [x1 + (pad if k == 2 else 0), H + pad, D + pad],
                        "bspOrder": []})

    objects = [{"id": "room", "name": "Room", "parts": [p.json() for p in room_parts]}]

    # Two lamps hanging just below the ceiling: closed thin boxes whose bottom
    # face emits (a face material overriding the part's).
    for lid, cx in (("lamp1", 1.0), ("lamp2", 5.0)):
        b = box_part(f"{lid}.panel", [cx - 0.4, H - 0.06, 1.6], [cx + 0.4, H - 0.02, 2.4], "steel",
                     name="Lamp panel", face_materials={"ny": "lamp"})
        objects.append({"id": lid, "name": f"Lamp {lid[-1]}", "parts": [b.json()]})
        orders["west" if cx < 2 else "east"].append(f"{lid}.panel.ny")

    # The paper's whole-part table: a desk and four legs, in the middle region.
    tx0, tx1, tz0, tz1, th = 2.4, 3.6, 1.4, 2.4, 0.75
    table = [box_part("table.desk", [tx0, th - 0.04, tz0], [tx1, th, tz1], "wood", name="Desk")]
    for i, (lx, lz) in enumerate([(tx0, tz0), (tx1 - 0.06, tz0), (tx0, tz1 - 0.06), (tx1 - 0.06, tz1 - 0.06)]):
        table.append(box_part(f"table.leg{i + 1}", [lx, 0, lz], [lx + 0.06, th - 0.04, lz + 0.06], "wood", name=f"Leg {i + 1}"))
    objects.append({"id": "table", "name": "Table", "parts": [p.json() for p in table]})
    orders["middle"] += ["table.desk.py", "table.desk.ny"]

    # A shelf against the back wall, in the west region.
    sx0, sx1, sz0, sz1 = 0.2, 1.6, 3.6, 4.0
    shelf = [box_part("shelf.left", [sx0, 0, sz0], [sx0 + 0.03, 1.8, sz1], "wood", name="Left side"),
             box_part("shelf.right", [sx1 - 0.03, 0, sz0], [sx1, 1.8, sz1], "wood", name="Right side")]
    for i, y in enumerate([0.05, 0.6, 1.2, 1.77]):
        shelf.append(box_part(f"shelf.board{i + 1}", [sx0 + 0.03, y, sz0], [sx1 - 0.03, y + 0.03, sz1], "wood", name=f"Board {i + 1}"))
    objects.append({"id": "shelf", "name": "Shelf", "parts": [p.json() for p in shelf]})
    orders["west"] += ["shelf.left.px", "shelf.right.nx", "shelf.board2.py", "shelf.board3.py"]

    # Boxes in the east region: one on the floor, one on top of it.
    boxes = [box_part("boxes.big", [4.6, 0, 0.8], [5.3, 0.6, 1.5], "blue", name="Big box"),
             box_part("boxes.small", [4.75, 0.6, 0.95], [5.15, 0.95, 1.35], "blue", name="Small box")]
    objects.append({"id": "boxes", "name": "Boxes", "parts": [p.json() for p in boxes]})
    orders["east"] += ["boxes.big.py", "boxes.big.nz"]

    for reg in regions:
        reg["bspOrder"] = orders[reg["id"]]
    return {
        "format": "regio-scene", "version": 1,
        "materials": materials, "objects": objects, "regions": regions,
        "solver": {"hemicube": 150, "patchSize": 0.5, "elementsPerPatch": 4,
                   "adaptive": {"enabled": True, "threshold": 0.05, "minEdge": 0.02},
                   # Converges (0.1 % unshot) at about 6900 shots.
                   "maxIterations": 10000, "convergence": 0.001},
        # Inside the room, just in front of the front wall: the walls are
        # one-sided and face inwards, so a camera outside sees their backs.
        "camera": {"position": [3.0, 1.6, 0.15], "target": [3.0, 1.2, 3.0],
                   "up": [0.0, 1.0, 0.0], "fovY": 60.0},
    }


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else OUT
    os.makedirs(out, exist_ok=True)
    for name, scene in (("cornell-box.json", cornell_box()), ("two-lights-room.json", two_lights_room())):
        with open(os.path.join(out, name), "w") as f:
            json.dump(scene, f, indent=2)
            f.write("\n")


if __name__ == "__main__":
    main()
