#!/usr/bin/env python3
"""Writes the small STL test files of this folder (run it here to regenerate them).

Every file is made from the coordinates below; none comes from elsewhere. The tests in
tests/test_mesh_stl.cpp state what each file must read as, or the message it must give.
"""
import struct

TET = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]  # as tests/data/3d/tetrahedron.off

CUBE = [(-1, -1, -1), (-1, 1, -1), (1, 1, -1), (1, -1, -1), (-1, -1, 1), (-1, 1, 1), (1, 1, 1), (1, -1, 1)]
CUBE_FACES = [(0, 1, 3), (3, 1, 2), (0, 4, 1), (1, 4, 5), (3, 2, 7), (7, 2, 6), (4, 0, 3), (7, 4, 3),
              (6, 4, 7), (6, 5, 4), (1, 5, 6), (2, 1, 6)]  # as data/meshes/cube.off


def facets(points, faces):
    return [tuple(points[i] for i in f) for f in faces]


def binary(path, tris, header=b"grassfire test STL", count=None, nan_at=None):
    out = bytearray(header.ljust(80, b" ")[:80])
    out += struct.pack("<I", len(tris) if count is None else count)
    for k, t in enumerate(tris):
        out += struct.pack("<3f", 0, 0, 0)  # normals are ignored by the reader; exporters often write zeros
        for j, p in enumerate(t):
            q = list(map(float, p))
            if nan_at == (k, j):
                q[1] = float("nan")
            out += struct.pack("<3f", *q)
        out += struct.pack("<H", 0)
    open(path, "wb").write(bytes(out))


def ascii_text(solids, upper=False):
    lines = []
    for name, tris in solids:
        lines.append(f"solid {name}")
        for t in tris:
            lines += ["  facet normal 0 0 0", "    outer loop"]
            lines += [f"      vertex {p[0]} {p[1]} {p[2]}" for p in t]
            lines += ["    endloop", "  endfacet"]
        lines.append(f"endsolid {name}")
    text = "\n".join(lines) + "\n"
    return text.upper() if upper else text


def ascii(path, solids, upper=False):
    open(path, "w").write(ascii_text(solids, upper))


tet = facets(TET, TET_FACES)
cube = facets(CUBE, CUBE_FACES)
# A Thingi10K-like triangle soup: every facet repeats its corners (36 -> 8 points), one facet
# appears twice, one facet has two equal corners (zero length edge).
soup = cube + [cube[3], (CUBE[0], CUBE[0], CUBE[5])]

ascii("tetrahedron_ascii.stl", [("tetrahedron", tet)], upper=True)
binary("tetrahedron_binary.stl", tet, header=b"solid tetrahedron: a binary STL whose header begins with 'solid'")
binary("cube_soup.stl", soup)
ascii("cube_soup_ascii.stl", [("first_half", soup[:7]), ("second_half", soup[7:])])
binary("open_cube.stl", cube[:11])
# Two unit cubes sharing the corner (1, 1, 1): after welding, a non-manifold vertex.
unit = [tuple((c + 1) / 2 for c in p) for p in CUBE]
binary("pinched_cubes.stl", facets(unit, CUBE_FACES) + facets([tuple(c + 1 for c in p) for p in unit], CUBE_FACES))
# Two tetrahedra without common vertices, the second pushed through a face of the first.
binary("crossing_tetrahedra.stl", tet + facets([(x + 0.25, y + 0.25, z + 0.25) for x, y, z in TET], TET_FACES))
# A tetrahedron whose face (0 2 1) is split at the midpoint m of edge 01, closed by the
# zero-area sliver (1 0 m).
M = (0.5, 0, 0)
P = TET + [M]
binary("zero_area.stl", facets(P, [(0, 2, 4), (4, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3), (1, 0, 4)]))
binary("bad_size.stl", tet, count=5)
binary("bad_nan.stl", tet, nan_at=(1, 2))
bad = ascii_text([("broken", tet)]).replace("vertex 1 0 0", "vertex 1 0", 1)
open("bad_ascii.stl", "w").write(bad)
