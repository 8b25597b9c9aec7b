#!/usr/bin/python3
"""A noise estimate from how the one-ring heights correlate across rings (a study, not shipped).

Usage: bench/height_correlation_noise.py MESH.off [LEVELS] [iso|random]   (numpy)

The shipped estimate (common/signal/noise_estimate.h) reads the spread of the one-ring heights'
finest IMF, and a clean coarse mesh's own detail at the edge scale spreads them as noise would
(femur reads 0.102 mean edges clean). Noise and detail differ in how they correlate: white noise
put through h = (I - W) n, W the neighbours' mean, correlates the heights of vertices one ring
apart by -1/k_i - 1/k_j + c_ij/(k_i k_j) of its variance (k the valences, c the common
neighbours), two rings apart by c_ij/(k_i k_j), three rings apart not at all, while a surface's
detail correlates over several rings. Assuming the detail's covariance falls geometrically from
one ring to three (d2^2 = d1 d3), the covariances at one, two and three rings give the noise's
variance as the root of a quadratic: the variogram's nugget.

For each noise level (sigma per coordinate in the clean mesh's mean edge, seed 11; `random`: along
a random direction per vertex, the paper's model) it prints the estimate / the same with the
heights beyond 4 MADs left out / the truth, all in the noisy mesh's mean edge along the normals.
docs/quality.md ("A noise estimate from the heights' correlation") has the readings and why it
is not shipped.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from laplacian_spectrum import load_off  # noqa: E402


class RingPairs:
    """The vertex pairs one, two and three rings apart, and the noise's covariance at each."""

    def __init__(self, faces, n):
        edges = np.unique(np.sort(np.vstack([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), 1), axis=0)
        self.edges, self.faces, self.n = edges, faces, n
        self.valence = np.bincount(edges.ravel(), minlength=n).astype(float)
        rings = [set() for _ in range(n)]
        for a, b in edges:
            rings[a].add(b)
            rings[b].add(a)
        second, third, common_second = [], [], []
        for i in range(n):
            two = set().union(*(rings[j] for j in rings[i])) - rings[i] - {i} if rings[i] else set()
            three = set().union(*(rings[j] for j in two)) - two - rings[i] - {i} if two else set()
            for j in two:
                if j > i:
                    second.append((i, j))
                    common_second.append(len(rings[i] & rings[j]))
            third += [(i, j) for j in three if j > i]
        self.second, self.third = np.array(second).reshape(-1, 2), np.array(third).reshape(-1, 2)
        k = self.valence
        common_first = np.array([len(rings[a] & rings[b]) for a, b in edges])
        a, b = edges[:, 0], edges[:, 1]
        self.noise_first = np.mean(-1 / k[a] - 1 / k[b] + common_first / (k[a] * k[b]))
        a, b = self.second[:, 0], self.second[:, 1]
        self.noise_second = np.mean(np.array(common_second) / (k[a] * k[b]))
        self.noise_variance = np.mean(1 + 1 / k)

    def heights(self, vertices):
        """The one-ring heights along the area-weighted vertex normals, in mean edges."""
        f, e = self.faces, self.edges
        edge = np.linalg.norm(vertices[e[:, 0]] - vertices[e[:, 1]], axis=1).mean()
        normals = np.zeros_like(vertices)
        area_vectors = np.cross(vertices[f[:, 1]] - vertices[f[:, 0]], vertices[f[:, 2]] - vertices[f[:, 0]])
        for corner in range(3):
            np.add.at(normals, f[:, corner], area_vectors)
        normals /= np.linalg.norm(normals, axis=1)[:, None] + 1e-300
        sums = np.zeros_like(vertices)
        np.add.at(sums, e[:, 0], vertices[e[:, 1]])
        np.add.at(sums, e[:, 1], vertices[e[:, 0]])
        return ((vertices - sums / np.maximum(self.valence, 1)[:, None]) * normals).sum(1) / edge, edge

    def nugget_sigma(self, vertices, trim=None):
        h, _ = self.heights(vertices)
        h = h - np.median(h)
        kept = np.ones(self.n)
        if trim:
            kept = (np.abs(h) <= trim * np.median(np.abs(h)) / 0.6745).astype(float)

        def covariance(pairs):
            w = kept[pairs[:, 0]] * kept[pairs[:, 1]]
            return np.sum(w * h[pairs[:, 0]] * h[pairs[:, 1]]) / np.sum(w)

        c0 = np.sum(kept * h * h) / np.sum(kept)
        c1, c2, c3 = covariance(self.edges), covariance(self.second), covariance(self.third)
        # (c2 - R2 s)^2 = (c1 - R1 s) c3, s the noise's variance, R1 and R2 its covariances per unit
        r1, r2 = self.noise_first, self.noise_second
        top = c0 / self.noise_variance
        roots = [r.real for r in np.roots([r2 * r2, r1 * c3 - 2 * c2 * r2, c2 * c2 - c1 * c3])
                 if abs(r.imag) < 1e-12 and 0 <= r.real <= top]
        if not roots:  # no exact root: the variance nearest one
            grid = np.linspace(0, top, 4001)
            roots = [grid[np.argmin(np.abs((c2 - r2 * grid) ** 2 - (c1 - r1 * grid) * c3))]]
        return np.sqrt(min(roots))


def main():
    vertices, faces = load_off(sys.argv[1])
    levels = [float(x) for x in (sys.argv[2] if len(sys.argv) > 2 else "0,0.02,0.05,0.1,0.2").split(",")]
    model = sys.argv[3] if len(sys.argv) > 3 else "iso"
    pairs = RingPairs(faces, len(vertices))
    edge = np.linalg.norm(vertices[pairs.edges[:, 0]] - vertices[pairs.edges[:, 1]], axis=1).mean()
    cells = []
    for level in levels:
        rng = np.random.default_rng(11)
        noise = rng.standard_normal(vertices.shape)
        if model == "random":
            noise = noise / np.linalg.norm(noise, axis=1)[:, None] * rng.standard_normal((len(vertices), 1))
        noisy = vertices + noise * level * edge
        _, noisy_edge = pairs.heights(noisy)
        truth = np.sqrt(np.mean(noise ** 2)) * level * edge / noisy_edge
        cells.append(f"{level:.2f}: {pairs.nugget_sigma(noisy):.3f} / {pairs.nugget_sigma(noisy, trim=4):.3f} / {truth:.3f}")
    print(f"{os.path.basename(sys.argv[1]):20s}", "  ".join(cells))


if __name__ == "__main__":
    main()
