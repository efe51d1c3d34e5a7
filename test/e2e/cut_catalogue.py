#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Helpers of test/e2e/cut_catalogue.sh (python3 standard library only).

  problem BOX_LO BOX_HI -o problem.json --exact exact.json [--linear]
      problem.json: E = 1, nu = 0.3, every node on the box's six faces gets the exact field: the
      rigid motion of its side (above / below, two different small rotations and translations), or
      with --linear uniaxial tension along x (for horizontal cuts whose front lies inside the body);
      exact.json: the same field for xfem-rmserror --exact.
  cut MESH.vtu --through node|edge|face|front-on-face|front-node -o cut.obj
      a planar cut on an unstructured mesh through a node, containing an interior edge (not its
      faces), containing an interior face, ending on an interior face (front inside it), or
      ending at a front through a node; the mesh's own coordinates are the cut's vertices, so
      "through" is exact.
  check --cut CUT --deformed deformed.vtu --wound wound.vtp --box LO HI --mode through|front|miss
        [--rms error.json] [--exact exact.json]
      the opened visualization and the patch test's figures; prints one line per failed check,
      exits 1 if any (deformed.vtu and wound.vtp of different runs are one).
  pair deformed.vtu wound.vtp
      exit 0 if both carry the same inputs_fingerprint (one xfem-visualize run), 1 if they differ,
      2 if either has none.

The true volumes and areas come from the cut file itself, independently of the tools: every cut
of the catalogue is a height field z = f(x, y) (one or more disjoint sheets, none vertical), so
the volume of the box below a sheet is the integral of clamp(f, zlo, zhi) - zlo over the box's
rectangle, exact for the triangulated sheet (each triangle's projection clipped to the rectangle
and to zlo <= f <= zhi, the linear f integrated over the clipped polygon).
"""
import argparse
import json
import math
import re
import struct
import sys
import zlib

# ---------------------------------------------------------------------------------------------
# VTK XML reader: ascii, or appended raw binary with or without zlib (the project's writer).

TYPES = {"Float64": "d", "Float32": "f", "Int32": "i", "Int64": "q", "UInt8": "B", "Int8": "b",
         "UInt32": "I", "UInt64": "Q", "Int16": "h", "UInt16": "H"}


def read_vtk_xml(path):
    """{'points': [(x,y,z)], 'cells': [[ids]], 'point': {name: [tuples]}, 'cell': {...}}."""
    data = open(path, "rb").read()
    mark = data.find(b"<AppendedData")
    head = data[:mark] if mark >= 0 else data
    appended = b""
    if mark >= 0:
        appended = data[data.index(b"_", data.index(b">", mark)) + 1:]
    text = head.decode("latin-1")
    m = re.search(r"<VTKFile([^>]*)>", text)
    if not m:
        raise SystemExit(f"{path}: not a VTK XML file")
    attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
    header = "Q" if attrs.get("header_type", "UInt32") == "UInt64" else "I"
    hsize = struct.calcsize("<" + header)
    compressed = "compressor" in attrs

    def decode(arr_attrs, body):
        fmt = TYPES[arr_attrs["type"]]
        if arr_attrs.get("format") == "ascii":
            return [float(v) for v in body.split()]
        if arr_attrs.get("format") == "binary":
            raise SystemExit(f"{path}: inline base64 binary arrays not supported")
        pos = int(arr_attrs["offset"])
        if compressed:
            nb, bs, last = struct.unpack_from("<3" + header, appended, pos)
            sizes = struct.unpack_from(f"<{nb}{header}", appended, pos + 3 * hsize)
            p = pos + (3 + nb) * hsize
            raw = b""
            for s in sizes:
                raw += zlib.decompress(appended[p:p + s])
                p += s
        else:
            (n,) = struct.unpack_from("<" + header, appended, pos)
            raw = appended[pos + hsize:pos + hsize + n]
        return list(struct.unpack(f"<{len(raw) // struct.calcsize(fmt)}{fmt}", raw))

    out = {"point": {}, "cell": {}, "field": {}, "raw": {}}
    section = None
    for t in re.finditer(r"<(/?)(PointData|CellData|FieldData|Points|Cells|Polys|DataArray)\b([^>]*?)(/?)>", text):
        close, tag, a, selfclose = t.groups()
        if tag != "DataArray":
            section = None if close else tag
            continue
        if close:
            continue
        aa = dict(re.findall(r'(\w+)="([^"]*)"', a))
        body = ""
        if not selfclose:
            body = text[t.end():text.index("</DataArray>", t.end())]
        values = decode(aa, body)
        nc = int(aa.get("NumberOfComponents", "1"))
        tuples = [tuple(values[i:i + nc]) for i in range(0, len(values), nc)] if nc > 1 else values
        name = aa.get("Name", "")
        if section == "PointData":
            out["point"][name] = tuples
        elif section == "CellData":
            out["cell"][name] = tuples
        elif section == "FieldData":
            out["field"][name] = tuples
        else:
            out["raw"][(section, name)] = values
    pts = out["raw"][("Points", "Points")] if ("Points", "Points") in out["raw"] else \
        next(v for (s, _), v in out["raw"].items() if s == "Points")
    out["points"] = [tuple(pts[i:i + 3]) for i in range(0, len(pts), 3)]
    sec = "Cells" if ("Cells", "connectivity") in out["raw"] else "Polys"
    conn, offs = out["raw"][(sec, "connectivity")], out["raw"][(sec, "offsets")]
    cells, start = [], 0
    for o in offs:
        cells.append([int(c) for c in conn[start:o]])
        start = o
    out["cells"] = cells
    return out


def read_surface(path):
    """Points and triangles of a .vtp or .obj cut."""
    if path.endswith(".obj"):
        pts, tris = [], []
        for line in open(path):
            w = line.split()
            if w and w[0] == "v":
                pts.append(tuple(float(v) for v in w[1:4]))
            elif w and w[0] == "f":
                tris.append([int(v.split("/")[0]) - 1 for v in w[1:4]])
        return pts, tris
    s = read_vtk_xml(path)
    return s["points"], s["cells"]


# ---------------------------------------------------------------------------------------------
# Geometry.

def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def mul(s, a): return (s * a[0], s * a[1], s * a[2])
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): return math.sqrt(dot(a, a))
def unit(a): return mul(1 / norm(a), a)


def tet_volume(p):
    return dot(sub(p[1], p[0]), cross(sub(p[2], p[0]), sub(p[3], p[0]))) / 6


def clip(poly, a, b, c):
    """Sutherland-Hodgman: the part of the 2D polygon with a x + b y + c >= 0."""
    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        fp, fq = a * p[0] + b * p[1] + c, a * q[0] + b * q[1] + c
        if fp >= 0:
            out.append(p)
        if (fp >= 0) != (fq >= 0):
            t = fp / (fp - fq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def polygon_integral(poly, g):
    """Area of a 2D polygon and the integral of the linear g(x, y) = g0 + gx x + gy y over it."""
    area, ix, iy = 0.0, 0.0, 0.0
    for i in range(len(poly)):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % len(poly)]
        w = x0 * y1 - x1 * y0
        area += w
        ix += (x0 + x1) * w
        iy += (y0 + y1) * w
    area /= 2
    if area == 0:
        return 0.0, 0.0
    return abs(area), math.copysign(1, area) * (g[0] * area + g[1] * ix / 6 + g[2] * iy / 6)


class Sheet:
    """One connected piece of a cut, a height field z = f(x, y) over its triangles' projections."""

    def __init__(self, pts, tris):
        self.tris = []
        signs = set()
        for t in tris:
            p = [pts[i] for i in t]
            n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
            if abs(n[2]) <= 1e-9 * norm(n):
                raise SystemExit("cut_catalogue.py: a cut triangle is vertical: not a height field")
            signs.add(n[2] > 0)
            # f = g0 + gx x + gy y on the triangle's plane.
            gx, gy = -n[0] / n[2], -n[1] / n[2]
            g0 = p[0][2] - gx * p[0][0] - gy * p[0][1]
            self.tris.append((p, (g0, gx, gy), norm(n) / abs(n[2])))
        if len(signs) != 1:
            raise SystemExit("cut_catalogue.py: a cut piece folds over (normals up and down)")
        self.up = signs.pop()  # its normal points to +z: the +1 side is above it

    def height(self, x, y):
        """f(x, y), or None outside the sheet's projection."""
        for p, g, _ in self.tris:
            (x0, y0, _), (x1, y1, _), (x2, y2, _) = p
            d = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
            l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / d
            l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / d
            if l1 >= -1e-13 and l2 >= -1e-13 and l1 + l2 <= 1 + 1e-13:
                return g[0] + g[1] * x + g[2] * y
        return None

    def in_box(self, lo, hi):
        """(area of the sheet inside the box, projected area covered, volume of the box below it)."""
        area = covered = below = 0.0
        rect = [(lo[0], 1, 0, -lo[0]), (lo[1], 0, 1, -lo[1]), (hi[0], -1, 0, hi[0]), (hi[1], 0, -1, hi[1])]
        for p, g, stretch in self.tris:
            poly = [(q[0], q[1]) for q in p]
            for _, a, b, c in rect:
                poly = clip(poly, a, b, c)
            if len(poly) < 3:
                continue
            A, _ = polygon_integral(poly, g)
            covered += A
            # Inside: zlo <= f <= zhi; above the box (f > zhi): the full height counts below.
            inside = clip(clip(poly, g[1], g[2], g[0] - lo[2]), -g[1], -g[2], hi[2] - g[0])
            if len(inside) >= 3:
                a_in, f_in = polygon_integral(inside, g)
                area += a_in * stretch
                below += f_in - lo[2] * a_in
            over = clip(poly, g[1], g[2], g[0] - hi[2])
            if len(over) >= 3:
                below += polygon_integral(over, g)[0] * (hi[2] - lo[2])
        return area, covered, below


def sheets_of(pts, tris):
    """Connected pieces (triangles sharing points) as Sheets."""
    parent = list(range(len(pts)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for t in tris:
        for i in t[1:]:
            parent[find(i)] = find(t[0])
    groups = {}
    for t in tris:
        groups.setdefault(find(t[0]), []).append(t)
    return [Sheet(pts, g) for g in groups.values()]


# ---------------------------------------------------------------------------------------------
# problem: the discontinuous patch test.

ABOVE = {"translation": [0.01, -0.02, 0.03], "rotation": [0.002, 0.001, -0.003], "centre": [0.5, 0.5, 0.5]}
BELOW = {"translation": [-0.015, 0.01, -0.02], "rotation": [-0.001, 0.003, 0.002], "centre": [0.4, 0.6, 0.5]}


def rigid(m, x):
    return add(tuple(m["translation"]), cross(tuple(m["rotation"]), sub(x, tuple(m["centre"]))))


# Uniaxial tension along x (E = 1, nu = 0.3): sigma = diag(1e-3, 0, 0) leaves every cut with
# normal z traction-free, so it is exact for a horizontal cut ending inside the body.
LINEAR = {"gradient": [[1e-3, 0, 0], [0, -3e-4, 0], [0, 0, -3e-4]], "translation": [0.01, -0.02, 0.005]}


def linear(field, x):
    return add(tuple(field["translation"]), tuple(dot(tuple(r), x) for r in field["gradient"]))


def cmd_problem(args):
    lo, hi = args.box[:3], args.box[3:]
    field = {"linear": LINEAR} if args.linear else {"rigid": {"above": ABOVE, "below": BELOW}}
    eps = 1e-9 * max(h - l for l, h in zip(lo, hi))
    conditions = []
    for axis in range(3):
        for name, at in (("low", lo[axis]), ("high", hi[axis])):
            blo = [v - 1 for v in lo]
            bhi = [v + 1 for v in hi]
            blo[axis], bhi[axis] = at - eps, at + eps
            conditions.append({"name": f"{'xyz'[axis]} {name} face",
                               "selector": {"box": {"lo": blo, "hi": bhi}}, "exact": field})
    problem = {"description": "patch test: every outer face moved by the exact field (rigid: each side of the cut by its own motion)",
               "material": {"E": 1.0, "nu": 0.3}, "dirichlet": conditions}
    json.dump(problem, open(args.output, "w"), indent=1)
    json.dump(field, open(args.exact, "w"), indent=1)


# ---------------------------------------------------------------------------------------------
# cut: exact planar cuts through an unstructured mesh's own nodes, edges and faces.

def interior_faces(mesh, lo, hi, margin):
    """Faces shared by two tets, all three nodes at least `margin` inside the box."""
    count = {}
    for t in mesh["cells"]:
        for f in ((t[0], t[1], t[2]), (t[0], t[1], t[3]), (t[0], t[2], t[3]), (t[1], t[2], t[3])):
            k = tuple(sorted(f))
            count[k] = count.get(k, 0) + 1
    pts = mesh["points"]
    inside = lambda p: all(l + margin < v < h - margin for v, l, h in zip(p, lo, hi))
    return [f for f, k in sorted(count.items()) if k == 2 and all(inside(pts[i]) for i in f)]


def quality(p):
    """Shape of a triangle: 4 sqrt(3) area / sum of squared edges (1 equilateral)."""
    a = norm(cross(sub(p[1], p[0]), sub(p[2], p[0]))) / 2
    return 4 * math.sqrt(3) * a / sum(dot(sub(p[i], p[j]), sub(p[i], p[j])) for i, j in ((0, 1), (1, 2), (2, 0)))


def annulus(inner, scale):
    """A big triangle around the inner triangle `inner`, as the inner triangle plus three quads to
    the outer triangle (its corners on the rays from the inner centroid through the inner corners,
    `scale` times farther): 7 triangles in the inner triangle's plane, the inner corners exact."""
    g = mul(1 / 3, add(add(inner[0], inner[1]), inner[2]))
    outer = [add(g, mul(scale, sub(p, g))) for p in inner]
    pts = list(inner) + outer
    tris = [(0, 1, 2)]
    for i in range(3):
        j = (i + 1) % 3
        tris += [(i, j, 3 + j), (i, 3 + j, 3 + i)]
    return pts, tris


def write_obj(path, pts, tris, up):
    with open(path, "w") as f:
        for p in pts:
            f.write("v %r %r %r\n" % p)
        for t in tris:
            p = [pts[i] for i in t]
            if dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), up) < 0:
                t = (t[0], t[2], t[1])
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def cmd_cut(args):
    mesh = read_vtk_xml(args.mesh)
    pts = mesh["points"]
    lo = tuple(min(p[i] for p in pts) for i in range(3))
    hi = tuple(max(p[i] for p in pts) for i in range(3))
    size = max(h - l for l, h in zip(lo, hi))
    centre = mul(0.5, add(lo, hi))
    # The best shaped interior face near the centre that is not close to vertical (height field).
    faces = interior_faces(mesh, lo, hi, 0.1 * size)

    def score(f, need_flat):
        p = [pts[i] for i in f]
        n = unit(cross(sub(p[1], p[0]), sub(p[2], p[0])))
        g = mul(1 / 3, add(add(p[0], p[1]), p[2]))
        tilt = abs(n[2]) if need_flat else math.sqrt(max(0.0, 1 - n[2] ** 2))
        return quality(p) * tilt - norm(sub(g, centre)) / size
    if args.through == "node":
        # The horizontal plane through the interior node nearest the centre.
        k = min(range(len(pts)), key=lambda i: (norm(sub(pts[i], centre)), i))
        z = pts[k][2]
        big = 2 * size
        c = [(lo[0] - big, lo[1] - big, z), (hi[0] + big, lo[1] - big, z), (hi[0] + big, hi[1] + big, z),
             (lo[0] - big, hi[1] + big, z)]
        write_obj(args.output, c, [(0, 1, 2), (0, 2, 3)], (0, 0, 1))
        return
    if args.through == "front-node":
        # A horizontal strip through the interior node N nearest the centre, ending at the
        # front x = N_x: the front, a line across the body, passes through N.
        k = min(range(len(pts)), key=lambda i: (norm(sub(pts[i], centre)), i))
        x, z = pts[k][0], pts[k][2]
        big = 2 * size
        # From x - 0.12 size: enriched nodes stay off the face x = lo, where tension along x pulls.
        w = x - 0.12 * size
        c = [(w, lo[1] - big, z), (x, lo[1] - big, z), (x, hi[1] + big, z), (w, hi[1] + big, z)]
        write_obj(args.output, c, [(0, 1, 2), (0, 2, 3)], (0, 0, 1))
        return
    if args.through in ("face", "edge"):
        f = max(faces, key=lambda f: score(f, True))
        p = [pts[i] for i in f]
        if args.through == "edge":
            # The plane through edge p0 p1 tilted about it (by 0.3 rad from the face's plane, so
            # it contains the edge but neither of its faces): a third point off the face.
            n = unit(cross(sub(p[1], p[0]), sub(p[2], p[0])))
            m = mul(0.5, add(p[0], p[1]))
            d = sub(mul(1 / 3, add(add(p[0], p[1]), p[2])), m)
            p = [p[0], p[1], add(m, add(mul(math.cos(0.3), d), mul(math.sin(0.3) * norm(d), n)))]
        n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
        cp, ct = annulus(p, 100 * size / min(norm(sub(p[i], p[(i + 1) % 3])) for i in range(3)))
        write_obj(args.output, cp, ct, (0, 0, 1 if n[2] > 0 else -1))
        return
    # front-on-face: a near-vertical interior face; the front is the horizontal line through its
    # centroid in its plane, the cut a horizontal square of side 0.12 size from there along the
    # face's normal, inside the body.
    f = max(faces, key=lambda f: score(f, False))
    p = [pts[i] for i in f]
    g = mul(1 / 3, add(add(p[0], p[1]), p[2]))
    nf = unit(cross(sub(p[1], p[0]), sub(p[2], p[0])))
    d = unit(cross(nf, (0, 0, 1)))
    e = unit(cross(d, (0, 0, 1)))  # horizontal, across the front
    if dot(e, nf) < 0:
        e = mul(-1, e)
    # The half-plane ends at the front through g, so the cut lies on the side of e. The plane
    # through g spanned by d and e is horizontal: z = g_z (exact), the front in the face's plane
    # up to rounding.
    half = 0.06 * size
    c = [add(g, mul(-half, d)), add(g, mul(half, d)), add(add(g, mul(half, d)), mul(2 * half, e)),
         add(add(g, mul(-half, d)), mul(2 * half, e))]
    c = [(q[0], q[1], g[2]) for q in c]
    write_obj(args.output, c, [(0, 1, 2), (0, 2, 3)], (0, 0, 1))


# ---------------------------------------------------------------------------------------------
# check: the opened visualization and the patch test.

def inputs_fingerprint(data):
    """xfem-visualize's field array inputs_fingerprint as 'fnv1a64:<hex>', None if absent."""
    f = data["field"].get("inputs_fingerprint")
    if not f or len(f) != 2:
        return None
    return "fnv1a64:%016x" % ((int(f[0]) << 32) | int(f[1]))


def cmd_pair(args):
    """deformed.vtu and wound.vtp of one xfem-visualize run? (docs/FORMATS.md "wound.vtp")"""
    a, b = inputs_fingerprint(read_vtk_xml(args.deformed)), inputs_fingerprint(read_vtk_xml(args.wound))
    if a is None or b is None:
        print(f"no inputs_fingerprint in {args.deformed if a is None else args.wound}")
        return 2
    if a != b:
        print(f"{args.wound} ({b}) is not of the run that wrote {args.deformed} ({a})")
        return 1
    print(f"same run: {a}")
    return 0


def cmd_check(args):
    lo, hi = tuple(args.box[:3]), tuple(args.box[3:])
    box_volume = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
    failures = []
    fail = failures.append
    d = read_vtk_xml(args.deformed)
    pts, cells = d["points"], d["cells"]
    if args.mode == "clean":
        # A cut that is no height field (a vertical blade): the tools' stderr is checked by the
        # caller; here the split body's volume and the pair's fingerprints only.
        total = sum(tet_volume([pts[i] for i in c]) for c in cells)
        if abs(total - box_volume) > 1e-12 * box_volume:
            fail(f"deformed.vtu total volume {total:.17g} != body {box_volume:.17g}")
        if args.wound and inputs_fingerprint(read_vtk_xml(args.wound)) != inputs_fingerprint(d):
            fail(f"{args.wound} and {args.deformed} are not of one xfem-visualize run")
        for f in failures:
            print(f)
        return 1 if failures else 0
    cpts, ctris = read_surface(args.cut)
    sheets = sheets_of(cpts, ctris)
    side = [int(s) for s in d["cell"]["piece_side" if "piece_side" in d["cell"] else "side"]]
    vol = {-1: 0.0, 0: 0.0, 1: 0.0}
    for c, s in zip(cells, side):
        vol[s] += tet_volume([pts[i] for i in c])
    total = sum(vol.values())
    rel = lambda a, b: abs(a - b) / abs(b) if b else abs(a)
    if rel(total, box_volume) > 1e-12:
        fail(f"deformed.vtu total volume {total:.17g} != body {box_volume:.17g} (rel {rel(total, box_volume):.2e})")

    # True cut area inside the body and, for cuts through, the volume on each side: the sheets
    # stacked from bottom to top, region k (above k sheets) on side sides[k].
    area = sum(s.in_box(lo, hi)[0] for s in sheets)
    rect_area = (hi[0] - lo[0]) * (hi[1] - lo[1])
    order = sorted(sheets, key=lambda s: s.in_box(lo, hi)[2])
    sides = [-1 if order[0].up else 1] + [1 if s.up else -1 for s in order]
    if args.mode == "through":
        for s in order:
            if rel(s.in_box(lo, hi)[1], rect_area) > 1e-12:
                raise SystemExit("cut_catalogue.py: --mode through but a cut piece does not span the body")
        for k in range(1, len(order)):
            if sides[k] != (-1 if order[k].up else 1):
                raise SystemExit("cut_catalogue.py: the region between two cut pieces has two sides")
        bounds = [0.0] + [s.in_box(lo, hi)[2] for s in order] + [box_volume]
        expect = {-1: 0.0, 1: 0.0}
        for k, s in enumerate(sides):
            expect[s] += bounds[k + 1] - bounds[k]
    elif args.mode == "miss":
        if vol[0] != total:
            fail(f"cut misses the body but {sum(1 for s in side if s)} cells of deformed.vtu have a side")

    # No cell straddles the cut: relative to each sheet, a cell's nodes lie on one side (within
    # `tol` of the sheet; a front-inside cut's joined cells ahead of the front excepted). A cell
    # with side +-1 lies on that side: its centroid (strictly inside its piece) is judged. Heights
    # outside a sheet's projection: for planar sheets the plane extended, else unknown (skipped).
    tol = 1e-12 * max(h - l for l, h in zip(lo, hi))

    def height(sheet, x, y):
        f = sheet.height(x, y)
        if f is None and len(set(round(g, 15) for _, gs, _ in sheet.tris for g in gs)) <= 3:
            g = sheet.tris[0][1]
            f = g[0] + g[1] * x + g[2] * y
        return f
    hcache = {}
    straddle, wrong_side, first, wrong_first = 0, 0, None, None
    vol_side = {-1: 0.0, 1: 0.0}
    for ci, (c, s) in enumerate(zip(cells, side)):
        cp = [pts[i] for i in c]
        centroid = mul(0.25, add(add(cp[0], cp[1]), add(cp[2], cp[3])))
        above = 0  # sheets the centroid lies above (z > f)
        for si, sh in enumerate(order):
            hs = []
            for i in c:
                if (i, si) not in hcache:
                    f = height(sh, pts[i][0], pts[i][1])
                    hcache[(i, si)] = None if f is None else pts[i][2] - f
                hs.append(hcache[(i, si)])
            fc = height(sh, centroid[0], centroid[1])
            if fc is not None and centroid[2] > fc:
                above += 1
            if any(h is None for h in hs):
                continue
            if max(hs) > tol and min(hs) < -tol and (args.mode != "front" or s != 0):
                straddle += 1
                first = first or (ci, s, max(hs), min(hs))
            if args.mode == "front" and s != 0 and fc is not None and (centroid[2] > fc) != ((s > 0) == sh.up):
                wrong_side += 1
                wrong_first = wrong_first or (ci, s)
        if args.mode == "through":
            region = sides[above]
            if s != 0 and s != region:
                wrong_side += 1
                wrong_first = wrong_first or (ci, s)
            vol_side[s or region] += tet_volume(cp)
    if args.mode == "through":
        for s in (-1, 1):
            if rel(vol_side[s], expect[s]) > 1e-12:
                fail(f"side {s:+d}: deformed.vtu volume {vol_side[s]:.17g}, true {expect[s]:.17g} "
                     f"(rel {rel(vol_side[s], expect[s]):.2e})")
    if straddle:
        fail(f"{straddle} cells of deformed.vtu straddle the cut (first: cell {first[0]}, side {first[1]}, "
             f"node heights {first[3]:.3g} .. {first[2]:.3g} about the cut)")
    if wrong_side:
        fail(f"{wrong_side} cells of deformed.vtu lie on the other side of the cut than their side array says "
             f"(first: cell {wrong_first[0]}, side {wrong_first[1]})")

    # Wound area: every triangle twice, once per side; each side = the cut's area in the body.
    if args.wound:
        w = read_vtk_xml(args.wound)
        if inputs_fingerprint(w) != inputs_fingerprint(d):
            fail(f"{args.wound} and {args.deformed} are not of one xfem-visualize run (inputs_fingerprint "
                 f"{inputs_fingerprint(w)} != {inputs_fingerprint(d)})")
        wa = {-1: 0.0, 1: 0.0}
        for t, s in zip(w["cells"], w["cell"].get("side", [])):
            p = [w["points"][i] for i in t]
            wa[int(s)] += norm(cross(sub(p[1], p[0]), sub(p[2], p[0]))) / 2
        for s in (-1, 1):
            if (area == 0 and wa[s] != 0) or (area > 0 and rel(wa[s], area) > 1e-12):
                fail(f"wound.vtp side {s:+d} area {wa[s]:.17g}, cut inside the body {area:.17g} (rel {rel(wa[s], area):.2e})")

    # Patch test: nodal displacement and strain exact.
    if args.rms:
        r = json.load(open(args.rms))
        exact = json.load(open(args.exact))
        corners = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
        size = box_volume ** (1 / 3)
        if "rigid" in exact:
            field = exact["rigid"]
            umax = max(norm(rigid(m, x)) for m in field.values() for x in corners)
            grad = max(norm(tuple(m["rotation"])) for m in field.values()) + \
                norm(sub(tuple(field["above"]["translation"]), tuple(field["below"]["translation"]))) / size
            eps = [0.0] * 6
        else:
            G = exact["linear"]["gradient"]
            umax = max(norm(linear(exact["linear"], x)) for x in corners)
            grad = math.sqrt(sum(v * v for row in G for v in row))
            eps = [G[0][0], G[1][1], G[2][2], (G[0][1] + G[1][0]) / 2, (G[1][2] + G[2][1]) / 2, (G[0][2] + G[2][0]) / 2]
        if not r["max"] <= 1e-10 * umax:
            fail(f"nodal displacement error {r['max']:.3g} m at node {r.get('max_node')} > 1e-10 x max|u| = {1e-10 * umax:.3g}")
        if not r["max_strain_error"] <= 1e-10 * grad:
            fail(f"xfem-rmserror max_strain_error {r['max_strain_error']:.3g} > {1e-10 * grad:.3g}")
        if r.get("max_gap_error", -1) > 1e-10 * umax:
            fail(f"xfem-rmserror max_gap_error {r['max_gap_error']:.3g} m > {1e-10 * umax:.3g}")
        # Strain error per cell (Frobenius norm of the tensor; components xx yy zz xy yz xz).
        error = [math.sqrt(sum((a - b) ** 2 for a, b in zip(s[:3], eps[:3])) + 2 * sum((a - b) ** 2 for a, b in zip(s[3:], eps[3:])))
                 for s in d["cell"]["strain"]]
        worst = max(range(len(error)), key=lambda i: error[i])
        if not error[worst] <= 1e-10 * grad:
            fail(f"deformed.vtu strain error {error[worst]:.3g} in cell {worst} (parent tet {int(d['cell']['parent'][worst])}, "
                 f"side {side[worst]}) > {1e-10 * grad:.3g}: the exact (constant) strain expected in every cell")
    for f in failures:
        print(f)
    print(f"volumes: side -1 {vol[-1]:.15g}, +1 {vol[1]:.15g}, whole cells {vol[0]:.15g}; cut area in body {area:.15g}",
          file=sys.stderr)
    return 1 if failures else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sp = ap.add_subparsers(dest="command", required=True)
    p = sp.add_parser("problem")
    p.add_argument("box", type=float, nargs=6)
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--exact", required=True)
    p.add_argument("--linear", action="store_true")
    p = sp.add_parser("cut")
    p.add_argument("mesh")
    p.add_argument("--through", choices=["node", "edge", "face", "front-on-face", "front-node"], required=True)
    p.add_argument("-o", "--output", required=True)
    p = sp.add_parser("check")
    p.add_argument("--cut", required=True)
    p.add_argument("--deformed", required=True)
    p.add_argument("--wound")
    p.add_argument("--box", type=float, nargs=6, required=True)
    p.add_argument("--mode", choices=["through", "front", "miss", "clean"], required=True)
    p.add_argument("--rms")
    p.add_argument("--exact")
    p = sp.add_parser("pair")
    p.add_argument("deformed")
    p.add_argument("wound")
    a = ap.parse_args()
    sys.exit({"problem": cmd_problem, "cut": cmd_cut, "check": cmd_check, "pair": cmd_pair}[a.command](a) or 0)


if __name__ == "__main__":
    main()
