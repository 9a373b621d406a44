#!/usr/bin/env python3
"""An independent writer of the face clouds `rockface import` reads (issue 43).

Plain python3 (struct, random, math): no line of rockface's own readers or
writers. A tunnel face in UTM survey coordinates (E 276,771 N 5,151,636 Z
2,385, millimetres in every coordinate) made of two planar joint facets
meeting in a ridge, sampled on a jittered grid as a scanner would, with
Gaussian range noise, coloured by facet. Written as:

  face.ply  binary little-endian PLY, double x y z, uchar red green blue
  face.las  LAS 1.4 point format 7 (scale 0.1 mm, offset at the datum)
  face.csv  text with a header line "x,y,z,red,green,blue"
  face.pts  PTS: the count, then x y z intensity r g b

and truth.json: every point's count, the bounding box, the facets' dip /
dip direction and a polygon of survey points well inside each facet, the
first three points exactly as written (for the 0.1 mm round trip).

usage: write_face_cloud.py OUTDIR [--points N] [--noise M] [--seed S]
"""
import argparse
import json
import math
import os
import random
import struct

DATUM = (276771.2345, 5151636.7891, 2385.4321)  # metres: a face on a UTM grid


def normal(dip_deg, dipdir_deg):
    a, b = math.radians(dip_deg), math.radians(dipdir_deg)
    return (math.sin(a) * math.sin(b), math.sin(a) * math.cos(b), math.cos(a))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def add(a, b, s=1.0):
    return tuple(x + s * y for x, y in zip(a, b))


# The face looks south (the viewer stands at bearing 180 from it); its plane
# is vertical. u runs along it (east), w up.
VIEW = (0.0, -1.0, 0.0)
U = (1.0, 0.0, 0.0)
W = (0.0, 0.0, 1.0)
FACETS = [
    {"name": "F1", "dip": 58.0, "dipdir": 148.0, "colour": (180, 120, 90)},
    {"name": "F2", "dip": 66.0, "dipdir": 216.0, "colour": (90, 130, 170)},
]
WIDTH, HEIGHT = 4.0, 3.0  # metres of face


def surface_point(u, w):
    """The face point seen along VIEW at (u, w): the nearer facet's."""
    base = add(add(DATUM, U, u), W, w)
    best = None
    for i, f in enumerate(FACETS):
        n = normal(f["dip"], f["dipdir"])
        # Both planes pass through the face's centre line: n . (p - centre) = 0.
        centre = add(add(DATUM, U, WIDTH / 2), W, HEIGHT / 2)
        t = dot(n, tuple(c - b for c, b in zip(centre, base))) / dot(n, VIEW)
        if best is None or t > best[0]:
            best = (t, i)
    return add(base, VIEW, best[0]), best[1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("outdir")
    ap.add_argument("--points", type=int, default=20000)
    ap.add_argument("--noise", type=float, default=0.002)  # metres, one sigma along the view
    ap.add_argument("--seed", type=int, default=43)
    a = ap.parse_args()
    rnd = random.Random(a.seed)
    side = int(math.sqrt(a.points * WIDTH / HEIGHT))
    rows = max(2, a.points // side)
    du, dw = WIDTH / side, HEIGHT / rows
    pts = []
    for r in range(rows):
        for c in range(side):
            u = (c + 0.5 + rnd.uniform(-0.3, 0.3)) * du
            w = (r + 0.5 + rnd.uniform(-0.3, 0.3)) * dw
            p, i = surface_point(u, w)
            p = add(p, VIEW, rnd.gauss(0.0, a.noise))
            # Millimetres, as a scanner's export writes them.
            p = tuple(round(x, 4) for x in p)
            pts.append((p, FACETS[i]["colour"]))
    os.makedirs(a.outdir, exist_ok=True)
    n = len(pts)

    with open(os.path.join(a.outdir, "face.ply"), "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\ncomment independent writer\n"
                 "element vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
                 "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
                 % n).encode())
        for p, c in pts:
            f.write(struct.pack("<dddBBB", *p, *c))

    scale = 0.0001
    lo = [min(p[k] for p, _ in pts) for k in range(3)]
    hi = [max(p[k] for p, _ in pts) for k in range(3)]
    offset = [math.floor(x) for x in DATUM]
    header = bytearray(375)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, 4
    header[26:58] = b"write_face_cloud.py".ljust(32, b"\0")
    struct.pack_into("<HIIBHI", header, 94, 375, 375, 0, 7, 36, 0)
    struct.pack_into("<ddd", header, 131, scale, scale, scale)
    struct.pack_into("<ddd", header, 155, *offset)
    struct.pack_into("<dddddd", header, 179, hi[0], lo[0], hi[1], lo[1], hi[2], lo[2])
    struct.pack_into("<Q", header, 247, n)
    with open(os.path.join(a.outdir, "face.las"), "wb") as f:
        f.write(bytes(header))
        for p, c in pts:
            xyz = [round((p[k] - offset[k]) / scale) for k in range(3)]
            rec = struct.pack("<iiiHBBBBhHd", *xyz, 0, 0x11, 0, 0, 0, 0, 0, 0.0)
            rec += struct.pack("<HHH", *(v * 256 for v in c))
            f.write(rec)

    with open(os.path.join(a.outdir, "face.csv"), "w") as f:
        f.write("x,y,z,red,green,blue\n")
        for p, c in pts:
            f.write("%.4f,%.4f,%.4f,%d,%d,%d\n" % (*p, *c))
    with open(os.path.join(a.outdir, "face.pts"), "w") as f:
        f.write("%d\n" % n)
        for p, c in pts:
            f.write("%.4f %.4f %.4f %d %d %d %d\n" % (*p, 0, *c))

    # A polygon inside each facet: a square of the face's (u, w) a quarter of
    # the face from the ridge, carried onto the facet.
    truth = {"points": n, "bbox_min": lo, "bbox_max": hi, "first_points": [p for p, _ in pts[:3]],
             "facets": []}
    for i, f in enumerate(FACETS):
        uc = WIDTH * (0.2 if i == 0 else 0.8)
        poly = []
        for du_, dw_ in ((-0.35, -0.5), (0.35, -0.5), (0.35, 0.5), (-0.35, 0.5)):
            p, k = surface_point(uc + du_, HEIGHT / 2 + dw_)
            assert k == i, "the polygon leaves its facet"
            poly.append(p)
        truth["facets"].append({"name": f["name"], "dip": f["dip"], "dipdir": f["dipdir"],
                                "polygon": poly})
    with open(os.path.join(a.outdir, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)


if __name__ == "__main__":
    main()
