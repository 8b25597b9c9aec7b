#!/usr/bin/env python3
"""Methods of the quality harness on a noisy mesh that comes with its own clean mesh (a dataset's
pair, such as the noisy files published with a denoising paper), through the staged
meshlabserver. Prints, for each method, E_a / RMS / flipped faces against the clean mesh (the
definitions of evaluate_quality.py) and the noise the pair holds: its RMS in mean edge lengths of
the clean mesh, and the share of its energy along the clean vertex normals (1 for noise along the
normals, about 1/3 for isotropic noise).

The two meshes must have the same triangulation. Their vertex order and frame may differ (another
export of the same model): with --match the noisy mesh is brought into the clean mesh's frame by a
similarity (principal axes, then iterative closest points) and its vertices renumbered to the clean
mesh's by walking the faces from one matched face; the run stops if any face fails to match.

  xvfb-run -a /usr/bin/python3 scripts/evaluate_pair.py [--match] [--methods KEY,...] CLEAN NOISY
  (CLEAN, NOISY: .off, .obj or binary .ply; KEY: the harness's method keys, default
  denoise,smooth,guided,bilnormal,bilateral,taubin,hc,twostep)
"""
import argparse
import collections
import itertools
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import evaluate_quality as q  # noqa: E402

DEFAULT_METHODS = "denoise,smooth,guided,bilnormal,bilateral,taubin,hc,twostep"


def read_obj(path):
    v, faces = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                v.append([float(x) for x in w[1:4]])
            elif w[0] == "f":
                idx = [int(x.split("/")[0]) for x in w[1:]]
                idx = [i - 1 if i > 0 else len(v) + i for i in idx]
                faces.extend([idx[0], idx[k], idx[k + 1]] for k in range(1, len(idx) - 1))
    return np.array(v), np.array(faces, dtype=np.int64)


def read_mesh(path):
    ext = os.path.splitext(path)[1].lower()
    return {".off": q.read_off, ".obj": read_obj, ".ply": q.read_ply}[ext](path)


def nearest(points, targets, chunk=2048):
    """Index of the nearest target of each point, and the distance (brute force, chunked)."""
    index, dist = np.empty(len(points), dtype=np.int64), np.empty(len(points))
    t2 = np.sum(targets ** 2, axis=1)
    for s in range(0, len(points), chunk):
        p = points[s:s + chunk]
        d2 = np.sum(p ** 2, axis=1)[:, None] - 2 * p @ targets.T + t2[None, :]
        index[s:s + chunk] = np.argmin(d2, axis=1)
        dist[s:s + chunk] = np.sqrt(np.maximum(d2[np.arange(len(p)), index[s:s + chunk]], 0))
    return index, dist


def similarity(source, target, mirror):
    """Scale s, orthogonal r (a reflection if mirror), shift t minimising |s r source + t - target|
    (Umeyama)."""
    ms, mt = source.mean(0), target.mean(0)
    a, b = source - ms, target - mt
    u, sv, vt = np.linalg.svd(b.T @ a)
    d = np.diag([1, 1, (-1 if mirror else 1) * np.sign(np.linalg.det(u @ vt))])
    r = u @ d @ vt
    s = np.trace(np.diag(sv) @ d) / np.sum(a ** 2)
    return s, r, mt - s * r @ ms


def align(noisy, clean, iterations=30, sample=2000):
    """The similarity taking the noisy vertices onto the clean surface: principal axes in each of
    their sign choices, each refined by iterative closest points; the best fit wins. A mirror
    image (one sign flipped) is a similarity too: its rotation part is improper."""
    rng = np.random.default_rng(0)
    pick = rng.choice(len(noisy), min(sample, len(noisy)), replace=False)
    axes = []
    for x in (noisy, clean):
        c = x - x.mean(0)
        w, vec = np.linalg.eigh(c.T @ c)
        axes.append(vec[:, np.argsort(w)[::-1]])
    best = None
    for signs in itertools.product((1, -1), repeat=3):
        r = axes[1] @ np.diag(signs) @ axes[0].T
        s = np.sqrt(np.sum((clean - clean.mean(0)) ** 2) / np.sum((noisy - noisy.mean(0)) ** 2))
        t = clean.mean(0) - s * r @ noisy.mean(0)
        for _ in range(iterations):
            moved = s * noisy[pick] @ r.T + t
            index, _ = nearest(moved, clean)
            s, r, t = similarity(noisy[pick], clean[index], np.linalg.det(r) < 0)
        _, dist = nearest(s * noisy[pick] @ r.T + t, clean)
        fit = float(np.sqrt(np.mean(dist ** 2)))
        if best is None or fit < best[0]:
            best = (fit, s, r, t)
    return best[1:]


def renumber(noisy_v, noisy_faces, clean_v, clean_faces):
    """order[i] = the noisy vertex that is clean vertex i, by walking the faces from a face whose
    corners' nearest clean vertices form a clean face; None if the triangulations differ."""
    directed = {}
    for a, b, c in clean_faces:
        for x, y, z in ((a, b, c), (b, c, a), (c, a, b)):
            directed[(x, y)] = z
    near, _ = nearest(noisy_v, clean_v)
    by_edge = collections.defaultdict(list)
    for f, (a, b, c) in enumerate(noisy_faces):
        for x, y in ((a, b), (b, c), (c, a)):
            by_edge[frozenset((x, y))].append(f)
    for seed in range(len(noisy_faces)):
        a, b, c = noisy_faces[seed]
        if directed.get((near[a], near[b])) == near[c]:
            break
    else:
        return None
    to_clean = {a: near[a], b: near[b], c: near[c]}
    queue, seen = collections.deque([seed]), {seed}
    while queue:
        a, b, c = noisy_faces[queue.popleft()]
        for x, y in ((a, b), (b, c), (c, a)):
            for g in by_edge[frozenset((x, y))]:
                if g in seen:
                    continue
                seen.add(g)
                corners = list(noisy_faces[g])
                k = corners.index(y)  # the neighbour runs the shared edge the other way: y, x, z
                if corners[(k + 1) % 3] != x:
                    return None
                z = corners[(k + 2) % 3]
                third = directed.get((to_clean[y], to_clean[x]))
                if third is None or to_clean.setdefault(z, third) != third:
                    return None
                queue.append(g)
    if len(to_clean) != len(clean_v) or len(set(to_clean.values())) != len(clean_v):
        return None
    order = np.empty(len(clean_v), dtype=np.int64)
    for noisy_index, clean_index in to_clean.items():
        order[clean_index] = noisy_index
    clean_of = np.argsort(order)
    if {tuple(sorted(f)) for f in clean_of[noisy_faces]} != {tuple(sorted(f)) for f in clean_faces}:
        return None
    return order


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--work", default=os.path.join(q.ROOT, "build", "pair"))
    parser.add_argument("--match", action="store_true", help="bring the noisy mesh into the clean mesh's frame "
                        "and vertex order (same triangulation, another export)")
    parser.add_argument("--methods", default=DEFAULT_METHODS)
    parser.add_argument("clean")
    parser.add_argument("noisy")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    clean_v, clean_faces = read_mesh(args.clean)
    noisy_v, noisy_faces = read_mesh(args.noisy)
    if len(noisy_v) != len(clean_v) or len(noisy_faces) != len(clean_faces):
        sys.exit("the meshes differ: %d / %d vertices, %d / %d faces" % (
            len(clean_v), len(noisy_v), len(clean_faces), len(noisy_faces)))
    if args.match:
        s, r, t = align(noisy_v, clean_v)
        noisy_v = s * noisy_v @ r.T + t
        order = renumber(noisy_v, noisy_faces, clean_v, clean_faces)
        if order is None:  # a mirror image's faces turn the other way
            order = renumber(noisy_v, noisy_faces[:, ::-1], clean_v, clean_faces)
        if order is None:
            sys.exit("--match: the noisy mesh's faces do not map onto the clean mesh's (another triangulation?)")
        noisy_v = noisy_v[order]
        print("matched: scale %.6g, every face of the noisy mesh is a face of the clean one" % s)
    elif not np.array_equal(noisy_faces, clean_faces):
        sys.exit("the faces differ (the same triangulation in another vertex order? try --match)")

    name = os.path.splitext(os.path.basename(args.noisy))[0]
    clean_path = os.path.join(args.work, name + "_clean.ply")
    input_path = os.path.join(args.work, name + "_noisy.ply")
    q.write_ply(clean_path, clean_v, clean_faces)
    q.write_ply(input_path, noisy_v, clean_faces)
    clean_v, noisy_v = q.read_ply(clean_path)[0], q.read_ply(input_path)[0]  # as meshlabserver reads them
    edge = q.mean_edge_length(clean_v, clean_faces)
    offset = noisy_v - clean_v
    along = np.einsum("ij,ij->i", offset, q.unit(q.vertex_normals(clean_v, clean_faces)))
    print("noise: RMS %.4f mean edges, %.3f of its energy along the clean normals" % (
        np.sqrt(np.mean(np.sum(offset ** 2, axis=1))) / edge, np.sum(along ** 2) / np.sum(offset ** 2)))

    folded = q.folded_faces(clean_v, clean_faces)
    diagonal = float(np.linalg.norm(clean_v.max(0) - clean_v.min(0)))
    rows = [("noisy input", q.metrics(clean_v, clean_faces, folded, diagonal, noisy_v))]
    labels = {key: q.SHORT[key] for key, _, _ in q.methods()}  # the labels in full: evaluate_quality.py
    xml = {key: x for key, _, x in q.methods()}
    for key in args.methods.split(","):
        if key not in xml:
            sys.exit("no method %s (one of %s)" % (key, ", ".join(xml)))
        try:
            out, _, _ = q.run_server(args.work, name + "_" + key, clean_path, input_path, xml[key])
            result = q.read_ply(out)[0]
            rows.append((labels[key], q.metrics(clean_v, clean_faces, folded, diagonal, result)))
        except RuntimeError as e:
            rows.append((labels[key], str(e)))
    print("| method | E_a | RMS | flipped |\n|---|---|---|---|")
    for label, m in rows:
        print("| %s | %s |" % (label, m if isinstance(m, str) else "%.3f | %.1f | %d" % (m["E_a"], m["RMS"], m["flipped"])))


if __name__ == "__main__":
    main()
