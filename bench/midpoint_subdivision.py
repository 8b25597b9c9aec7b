#!/usr/bin/python3
"""A finely meshed copy of a mesh: each triangle cut into four at its edges' midpoints, CUTS times.

Usage: bench/midpoint_subdivision.py IN.off OUT.off CUTS   (numpy)

The same surface, meshed 4^CUTS times as finely (test::midpoint_subdivision in
tests/unit/test_meshes.h does the same): docs/quality.md item 28 measures the denoiser's crease
readings on libcgal-demo's CAD meshes so cut, e.g. fandisk cut twice (into 16).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from laplacian_spectrum import load_off  # noqa: E402


def cut(vertices, faces):
    edges = np.sort(np.vstack([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), 1)
    unique, index = np.unique(edges, axis=0, return_inverse=True)
    midpoints = len(vertices) + index.reshape(3, -1)  # per face: ab, bc, ca
    ab, bc, ca = midpoints
    a, b, c = faces.T
    new_faces = np.vstack([np.stack([a, ab, ca], 1), np.stack([ab, b, bc], 1), np.stack([ca, bc, c], 1),
                           np.stack([ab, bc, ca], 1)])
    return np.vstack([vertices, 0.5 * (vertices[unique[:, 0]] + vertices[unique[:, 1]])]), new_faces


def main():
    vertices, faces = load_off(sys.argv[1])
    for _ in range(int(sys.argv[3])):
        vertices, faces = cut(vertices, faces)
    with open(sys.argv[2], "w") as out:
        out.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        out.writelines(f"{x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in vertices)
        out.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)


if __name__ == "__main__":
    main()
