#!/usr/bin/env python3
"""Edges of more than two faces through the shipped scripts (docs/quality.md item 44).

Each mesh gets a fin: a strip of triangles one mean edge high standing along its vertex normals on
a path of EDGES of its edges, each path edge then shared by three faces; with --repeated instead
every 50th face given twice (as some exports repeat faces: each edge of such a face then has three
or four). The changed mesh and the mesh as it was get the same noise on their shared vertices
(isotropic, seed 7) and go through the staged meshlabserver; E_a / RMS / flipped faces are measured
on the mesh's own faces, so the two columns differ only by what the change does to the filtering of
the surface. With --soup a third column runs the changed mesh written as a triangle soup (every face
with vertices of its own; item 46), read back at each vertex's first copy, and counts the vertices
whose copies came apart.

    xvfb-run -a /usr/bin/python3 scripts/evaluate_nonmanifold_edges.py [--edges 30 | --repeated] [--soup] MESH.off...
"""

import argparse
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import evaluate_quality as q  # noqa: E402


def add_fin(v, faces, edges):
    """The mesh with a fin on a path of `edges` edges from vertex 0, climbing one direction."""
    neighbours = [set() for _ in range(len(v))]
    for f in faces:
        for k in range(3):
            neighbours[f[k]].add(f[(k + 1) % 3])
    climb = np.array([1.0, 0.3, 0.1]) / np.linalg.norm([1.0, 0.3, 0.1])
    start = int(np.argmin(v @ climb))
    path = [start]
    while len(path) <= edges:
        higher = [j for j in neighbours[path[-1]] if v[j] @ climb > v[path[-1]] @ climb]
        if not higher:
            break
        path.append(max(higher, key=lambda j: v[j] @ climb))
    height = q.mean_edge_length(v, faces)
    normals = q.unit(q.vertex_normals(v, faces))
    n = len(v)
    fin_v = v[path] + height * normals[path]
    fin_f = []
    for i in range(len(path) - 1):
        fin_f.append([path[i], path[i + 1], n + i + 1])
        fin_f.append([path[i], n + i + 1, n + i])
    return np.vstack([v, fin_v]), np.vstack([faces, np.array(fin_f, dtype=faces.dtype)]), len(path) - 1


def soup_of(v, faces):
    """Every face with three vertices of its own: vertex 3 f + k is corner k of face f."""
    return v[faces.reshape(-1)], np.arange(3 * len(faces), dtype=faces.dtype).reshape(-1, 3)


def from_soup(result, faces, count):
    """The soup's result at each of the first `count` vertices (its first copy), and how many of
    those vertices have copies at other places."""
    out = np.full((count, 3), np.nan)
    apart = set()
    for corner, vertex in enumerate(faces.reshape(-1)):
        if vertex >= count:
            continue
        if np.isnan(out[vertex, 0]):
            out[vertex] = result[corner]
        elif not np.array_equal(out[vertex], result[corner]):
            apart.add(int(vertex))
    return out, len(apart)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--edges", type=int, default=30)
    parser.add_argument("--repeated", action="store_true")
    parser.add_argument("--levels", default="10,20")
    parser.add_argument("--soup", action="store_true")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="hht_fin_")
    change = "repeated faces" if args.repeated else "path edges"
    what = "the faces repeated" if args.repeated else "the fin"
    soup_header = (" with %s, as a soup (vertices apart) |" % what) if args.soup else ""
    print("| mesh, noise | %s | script | noisy | without %s | with %s |%s" % (change, what, what, soup_header))
    print("|---|---|---|---|---|---|" + ("---|" if args.soup else ""))
    for path in args.meshes:
        name = os.path.basename(path)[:-4]
        v, faces = q.read_off(path)
        if args.repeated:
            fv, ff, steps = v, np.vstack([faces, faces[::50]]), len(faces[::50])
        else:
            fv, ff, steps = add_fin(v, faces, args.edges)
        folded = q.folded_faces(v, faces)
        diagonal = float(np.linalg.norm(v.max(0) - v.min(0)))
        plain_clean = os.path.join(work, name + "_clean.ply")
        finned_clean = os.path.join(work, name + "_fin_clean.ply")
        q.write_ply(plain_clean, v, faces)
        q.write_ply(finned_clean, fv, ff)
        soup_clean = os.path.join(work, name + "_soup_clean.ply")
        if args.soup:
            q.write_ply(soup_clean, *soup_of(fv, ff))
        for level in [int(x) for x in args.levels.split(",")]:
            noisy = q.add_noise(fv, ff, level, "isotropic", 7)
            plain_in = os.path.join(work, "%s_%d.ply" % (name, level))
            finned_in = os.path.join(work, "%s_fin_%d.ply" % (name, level))
            q.write_ply(plain_in, noisy[: len(v)], faces)
            q.write_ply(finned_in, noisy, ff)
            soup_in = os.path.join(work, "%s_soup_%d.ply" % (name, level))
            if args.soup:
                q.write_ply(soup_in, *soup_of(noisy, ff))
            before = q.metrics(v, faces, folded, diagonal, noisy[: len(v)])
            for script in ("smooth", "denoise"):
                cells = []
                runs = [("plain", plain_clean, plain_in), ("fin", finned_clean, finned_in)]
                if args.soup:
                    runs.append(("soup", soup_clean, soup_in))
                for tag, clean, source in runs:
                    try:
                        out, _, _ = q.run_server(work, "%s_%d_%s_%s" % (name, level, script, tag), clean, source,
                                                 q.resource_filter(script))
                        result, _ = q.read_ply(out)
                        apart = None
                        if tag == "soup":
                            result, apart = from_soup(result, ff, len(v))
                        m = q.metrics(v, faces, folded, diagonal, result[: len(v)])
                        cells.append("%.2f / %.1f / %d" % (m["E_a"], m["RMS"], m["flipped"])
                                     + ("" if apart is None else " (%d)" % apart))
                    except RuntimeError as e:
                        cells.append("failed: %s" % e)
                print("| %s %d%% | %d | %s.mlx | %.2f / %.1f | %s |"
                      % (name, level, steps, script, before["E_a"], before["RMS"], " | ".join(cells)))
                sys.stdout.flush()


if __name__ == "__main__":
    main()
