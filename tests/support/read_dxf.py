#!/usr/bin/env python3
"""Reads a DXF with ezdxf (an independent reader, Debian's python3-ezdxf) and
prints what it holds as JSON: the layers, and every POLYLINE as a 3D
polyline (its points, closed or not) or a polyface mesh (its vertices and
faces, 0-based). The test compares that with the truth; this script only
reads."""
import json
import sys

import ezdxf

doc = ezdxf.readfile(sys.argv[1])
out = {"layers": sorted(layer.dxf.name for layer in doc.layers), "entities": [],
       "other": []}
for e in doc.modelspace():
    if e.dxftype() != "POLYLINE":
        out["other"].append(e.dxftype())
        continue
    item = {"layer": e.dxf.layer}
    if e.is_poly_face_mesh:
        vertices = []
        faces = []
        index = {}
        for v in e.vertices:
            if v.is_poly_face_mesh_vertex:
                index[len(vertices)] = len(vertices)
                vertices.append(list(v.dxf.location))
            elif v.is_face_record:
                faces.append([abs(v.get_dxf_attrib(k, 0)) - 1 for k in ("vtx0", "vtx1", "vtx2", "vtx3")
                              if v.get_dxf_attrib(k, 0) != 0])
        item.update(kind="polyface", vertices=vertices, faces=faces)
    elif e.is_3d_polyline:
        item.update(kind="polyline3d", closed=e.is_closed,
                    points=[list(p) for p in e.points()])
    else:
        item.update(kind="other polyline")
    out["entities"].append(item)
json.dump(out, sys.stdout)
