#!/usr/bin/python3
"""The normal part of a mesh's shape per band of the uniform Laplacian's spectrum, in noise units.

Usage: bench/laplacian_spectrum.py MESH.off [BANDS]   (numpy; dense eigendecomposition, so
meshes of a few thousand vertices: cow, femur, dino, homer, elephant).

The graph Laplacian D - A of the faces is diagonalised; each band (an equal share of the
eigenvectors, lowest frequencies first) of the clean coordinates is projected on the area-weighted
vertex normals, and its mean squared value is divided by that of unit white noise put through the
same band. The last column is thus the noise sigma (in mean edges) that would carry as much energy
in that band. Noise is white: flat across the bands. A smooth, finely meshed surface decays towards
the top band; where a clean mesh's columns stay flat over the upper bands, its own detail at the
edge scale is as white as noise, and no reading of the spectrum tells the two apart
(docs/quality.md, "Goals not reached").
"""
import sys

import numpy as np


def load_off(path):
    tokens = open(path).read().split()
    header = tokens[0]
    at = 1 if header in ("OFF", "COFF", "NOFF") else 0
    n, f = int(tokens[at]), int(tokens[at + 1])
    at += 3
    stride = 7 if header == "COFF" else 6 if header == "NOFF" else 3
    vertices = np.array(tokens[at:at + stride * n], float).reshape(n, stride)[:, :3]
    at += stride * n
    faces = []
    for _ in range(f):
        k = int(tokens[at])
        faces.append([int(x) for x in tokens[at + 1:at + 1 + k]])
        at += 1 + k
    return vertices, np.array(faces)


def main():
    vertices, faces = load_off(sys.argv[1])
    bands = int(sys.argv[2]) if len(sys.argv) > 2 else 12
    n = len(vertices)
    adjacency = np.zeros((n, n))
    for a, b in ((0, 1), (1, 2), (2, 0)):
        adjacency[faces[:, a], faces[:, b]] = 1
        adjacency[faces[:, b], faces[:, a]] = 1
    eigenvalues, eigenvectors = np.linalg.eigh(np.diag(adjacency.sum(1)) - adjacency)
    edge = np.linalg.norm(vertices[faces[:, 0]] - vertices[faces[:, 1]], axis=1).mean()
    area_vectors = np.cross(vertices[faces[:, 1]] - vertices[faces[:, 0]], vertices[faces[:, 2]] - vertices[faces[:, 0]])
    normals = np.zeros_like(vertices)
    for corner in range(3):
        np.add.at(normals, faces[:, corner], area_vectors)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    bounds = np.linspace(0, n, bands + 1).astype(int)

    def band_energies(x):
        coefficients = eigenvectors.T @ x
        return np.array([np.mean(np.sum((eigenvectors[:, lo:hi] @ coefficients[lo:hi]) * normals, 1) ** 2)
                         for lo, hi in zip(bounds, bounds[1:])])

    clean = band_energies(vertices / edge)
    noise = band_energies(np.random.default_rng(11).standard_normal((n, 3)))
    print(f"{sys.argv[1]}: {n} vertices; band, middle eigenvalue, noise sigma (mean edges) of equal energy")
    for b, (lo, hi) in enumerate(zip(bounds, bounds[1:])):
        print(f"{b:3d} {eigenvalues[(lo + hi) // 2]:7.2f} {np.sqrt(clean[b] / noise[b]):9.4f}")


if __name__ == "__main__":
    main()
