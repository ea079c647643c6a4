#!/usr/bin/env python3
"""Writes the Surface Evolver datafiles of the statics benchmark (statics.sh): box-shaped cells
on a lattice, every lattice rectangle between two different regions a face (outward normals
from each body's +face), volumes 1 (the targets). `n` subdivides every lattice interval into n
equal parts, so that Evolver's refinement levels (x4 vertices each) fall in between those of
n = 1: level L of n = 3 is about level L + log2(3) = L + 1.58 of n = 1.
  python3 bench/evolver/make_cells_fe.py two_cubes 3 > bench/evolver/two_cubes_3.fe
  python3 bench/evolver/make_cells_fe.py three_cells 1 > bench/evolver/three_cells.fe"""
import sys

CASES = {
    # name: (lattice x, y, z; body of lattice cell (i, j, k), 0 = outside; comment)
    "two_cubes": ([0, 1, 2], [0, 1], [0, 1], lambda i, j, k: 1 + i,
                  "Two unit cubes sharing the face x = 1: bodies of volume 1 each (a double bubble)."),
    "three_cells": ([0, 1, 2], [0, 1], [0, 1, 1.5], lambda i, j, k: 1 + i if k == 0 else 3,
                    "Three cells of volume 1: the unit cubes A = [0,1]^3 (body 1), B = [1,2]x[0,1]x[0,1]\n"
                    "// (body 2) and on them the slab C = [0,2]x[0,1]x[1,1.5] (body 3); each touches the other\n"
                    "// two (4 triple lines, 2 quadruple points), so it relaxes to the standard triple bubble.\n"
                    "// froth's start is the same three boxes (statics_froth.lua problem=triple)."),
}


def main():
    name, n = sys.argv[1], int(sys.argv[2])
    lx, ly, lz, cell_body, comment = CASES[name]

    def sub(lat):  # subdivided coordinates and the lattice cell of each sub-interval
        pts, owner = [], []
        for a in range(len(lat) - 1):
            for s in range(n):
                pts.append(lat[a] + (lat[a + 1] - lat[a]) * s / n)
                owner.append(a)
        pts.append(lat[-1])
        return pts, owner

    (xs, ox), (ys, oy), (zs, oz) = sub(lx), sub(ly), sub(lz)
    dims = [len(xs), len(ys), len(zs)]
    owners = [ox, oy, oz]

    def body(c):
        if any(not (0 <= c[a] < dims[a] - 1) for a in range(3)):
            return 0
        return cell_body(ox[c[0]], oy[c[1]], oz[c[2]])

    vid, verts = {}, []
    for k in range(dims[2]):
        for j in range(dims[1]):
            for i in range(dims[0]):
                vid[(i, j, k)] = len(verts) + 1
                verts.append((xs[i], ys[j], zs[k]))
    eid, edges = {}, []

    def edge(a, b):
        if (b, a) in eid:
            return -eid[(b, a)]
        if (a, b) not in eid:
            edges.append((a, b))
            eid[(a, b)] = len(edges)
        return eid[(a, b)]

    faces, bodies = [], {}
    for ax in range(3):
        u_ax, w_ax = [(1, 2), (2, 0), (0, 1)][ax]  # (u, w, normal) right-handed
        for p in range(dims[ax]):
            for u in range(dims[u_ax] - 1):
                for w in range(dims[w_ax] - 1):
                    def at(du, dw, dp=0):
                        c = [0, 0, 0]
                        c[ax], c[u_ax], c[w_ax] = p + dp, u + du, w + dw
                        return tuple(c)
                    bn, bp = body(at(0, 0, -1)), body(at(0, 0))
                    if bn == bp:
                        continue
                    loop = [vid[at(0, 0)], vid[at(1, 0)], vid[at(1, 1)], vid[at(0, 1)]]
                    faces.append([edge(loop[q], loop[(q + 1) % 4]) for q in range(4)])
                    f = len(faces)
                    if bn:
                        bodies.setdefault(bn, []).append(f)  # normal +ax points out of bn
                    if bp:
                        bodies.setdefault(bp, []).append(-f)
    print("// " + comment)
    print(f"// Written by make_cells_fe.py {name} {n} (lattice intervals subdivided {n} times).")
    used = sorted({v for e in edges for v in e})  # the lattice points on a face, renumbered
    number = {v: q + 1 for q, v in enumerate(used)}
    print("vertices")
    for v in used:
        x, y, z = verts[v - 1]
        print(f"{number[v]} {x:.17g} {y:.17g} {z:.17g}")
    print("\nedges")
    for q, (a, b) in enumerate(edges):
        print(f"{q + 1} {number[a]} {number[b]}")
    print("\nfaces")
    for q, es in enumerate(faces):
        print(f"{q + 1} " + " ".join(map(str, es)))
    print("\nbodies")
    for b in sorted(bodies):
        print(f"{b} " + " ".join(map(str, bodies[b])) + " volume 1")


main()
