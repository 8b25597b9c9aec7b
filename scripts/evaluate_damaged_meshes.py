#!/usr/bin/env python3
"""Damaged meshes through the shipped scripts (docs/quality.md item 48).

Each mesh gets isotropic noise (LEVEL % of the mean edge, seed 7), then one damage at a time (seed
3), and goes through each script on the staged meshlabserver. A row per run: the damage, the
script, then `ok` with the RMS distance of the mesh's own vertices to the clean mesh (1e-4 of its
bounding-box diagonal; spiked vertices left out, coordinates scaled back for `huge` and `tiny`)
against the noisy input's, or `refused` with the log's reason, or CRASH (a signal, a sanitizer's
report). `--subdivide` instead cuts the noisy mesh into flat pieces (Midpoint subdivision, each
face into four) and prints E_a against the clean mesh subdivided alike, with and without the noise
level given (NOISE % of the subdivided mesh's mean edge).

    xvfb-run -a /usr/bin/python3 scripts/evaluate_damaged_meshes.py [--level 10] [--damages a,b]
        [--scripts smooth,denoise] MESH.off ...
    xvfb-run -a /usr/bin/python3 scripts/evaluate_damaged_meshes.py --subdivide [--level 20] [--noise 40] MESH.off ...
"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import evaluate_quality as q  # noqa: E402

DAMAGES = ("none holes repeated repeated_reversed slivers near_slivers small_copy spikes huge tiny unreferenced "
           "glued strips reversed dust cracks").split()
SCRIPTS = ("smooth denoise enhance guided_denoise bilateral_normal_denoise nonlocal_means surface_emd_smooth "
           "bilateral hilbert_spectra hamiltonian_cycle curvature_signal feature_centric_emd").split()


def damage(v, f, kind, rng):
    """(positions, faces, scale, shift): the damaged mesh, and how its coordinates map back."""
    n = len(v)
    if kind == "holes":  # a tenth of the faces removed
        return v, f[rng.random(len(f)) > 0.1], 1, 0
    if kind in ("repeated", "repeated_reversed"):  # 5% of the faces given again, drawn with replacement
        extra = f[rng.choice(len(f), len(f) // 20)]
        return v, np.vstack([f, extra[:, ::-1] if kind == "repeated_reversed" else extra]), 1, 0
    if kind == "slivers":  # 5% of the faces collapsed: a corner moved onto another
        v = v.copy()
        for a, b in f[rng.choice(len(f), len(f) // 20), :2]:
            v[a] = v[b]
        return v, f, 1, 0
    if kind == "near_slivers":  # a tenth of the faces bent to a corner all but on the opposite edge
        v = v.copy()
        for a, b, c in f[rng.choice(len(f), len(f) // 10)]:
            v[a] = 0.5 * (v[b] + v[c]) + 1e-9 * (v[b] - v[c])
        return v, f, 1, 0
    if kind == "small_copy":  # a second copy at 1e-4 of the size, its noise scaled alike
        return np.vstack([v, v * 1e-4 + 2 * v.max(0)]), np.vstack([f, f + n]), 1, 0
    if kind == "spikes":  # 1% of the vertices moved by up to a bounding-box diagonal
        v = v.copy()
        idx = rng.choice(n, max(1, n // 100))
        v[idx] += rng.normal(size=(len(idx), 3)) * np.ptp(v, 0).max()
        return v, f, 1, 0
    if kind == "huge":  # large coordinates far from the origin for the mesh's size
        return v * 1e12 + 1e15, f, 1e12, 1e15
    if kind == "tiny":
        return v * 1e-12, f, 1e-12, 0
    if kind == "unreferenced":  # a tenth more vertices, in no face
        return np.vstack([v, rng.normal(size=(n // 10, 3))]), f, 1, 0
    if kind == "glued":  # 2% of the vertices replaced by others far away
        a, b = rng.choice(n, n // 50), rng.choice(n, n // 50)
        m = np.arange(n)
        m[b] = a
        g = m[f]
        return v, g[(g[:, 0] != g[:, 1]) & (g[:, 1] != g[:, 2]) & (g[:, 0] != g[:, 2])], 1, 0
    if kind == "strips":  # 60% of the faces removed
        return v, f[rng.random(len(f)) > 0.6], 1, 0
    if kind == "reversed":  # 30% of the faces against their neighbours
        f = f.copy()
        flip = rng.random(len(f)) < 0.3
        f[flip] = f[flip][:, ::-1]
        return v, f, 1, 0
    if kind == "dust":  # 300 small floating triangles near the surface, as a scan's dust
        edge = q.mean_edge_length(v, f)
        base = v[rng.choice(n, 300)] + rng.normal(size=(300, 3)) * 3 * edge
        tri = np.repeat(base, 3, axis=0) + rng.normal(size=(900, 3)) * 0.3 * edge
        return np.vstack([v, tri]), np.vstack([f, n + np.arange(900).reshape(300, 3)]), 1, 0
    if kind == "cracks":  # 5% of the faces split at an edge's midpoint, the neighbour left whole
        keep, new_faces, extra = np.ones(len(f), bool), [], []
        for i in rng.choice(len(f), len(f) // 20, replace=False):
            a, b, c = f[i]
            mid = n + len(extra)
            extra.append(0.5 * (v[a] + v[b]))
            keep[i] = False
            new_faces += [[a, mid, c], [mid, b, c]]
        return np.vstack([v, extra]), np.vstack([f[keep], new_faces]), 1, 0
    return v, f, 1, 0


def run_script(work, tag, mesh_path, script):
    out = os.path.join(work, tag + "_out.ply")
    if os.path.exists(out):
        os.remove(out)
    p = subprocess.run([q.SERVER, "-i", mesh_path, "-o", out, "-s", script], capture_output=True, text=True, cwd=work)
    text = p.stdout + p.stderr
    if p.returncode < 0 or "AddressSanitizer" in text or "runtime error" in text:
        return "CRASH", text[-400:]
    if p.returncode != 0 or not os.path.exists(out):
        reasons = [l for l in text.splitlines() if re.search(r"failed|refus", l, re.I)]
        return "refused", (reasons[-1] if reasons else text.strip().splitlines()[-1:])
    return "ok", q.read_ply(out)[0]


def damaged_run(work, level, mesh, kind, script):
    v, f = q.read_off(mesh)
    noisy = q.add_noise(v, f, level, "isotropic", 7)
    dv, df, scale, shift = damage(noisy, f, kind, np.random.default_rng(3))
    tag = "%s_%s_%s" % (os.path.basename(mesh)[:-4], kind, script)
    path = os.path.join(work, tag + "_in.ply")
    q.write_ply(path, dv, df)
    status, result = run_script(work, tag, path, os.path.join(q.ROOT, "resources", script + ".mlx"))
    if status != "ok":
        return tag, "%s %s" % (status, result)
    n = len(v)
    keep = np.linalg.norm((dv[:n] - shift) / scale - noisy, axis=1) < 1e-9 * np.ptp(v, 0).max()
    if not np.isfinite(result).all() or len(result) != len(dv):
        return tag, "BAD RESULT (non-finite or another vertex count)"
    diagonal = np.linalg.norm(v.max(0) - v.min(0))

    def rms(x):
        return 1e4 * np.sqrt((np.linalg.norm(x[keep] - v[keep], axis=1) ** 2).mean()) / diagonal

    return tag, "ok RMS %.1f (noisy %.1f)" % (rms((result[:n] - shift) / scale), rms(noisy))


def midpoint_subdivision(v, f):
    index, points, faces = {}, list(v), []

    def middle(a, b):
        key = (min(a, b), max(a, b))
        if key not in index:
            index[key] = len(points)
            points.append(0.5 * (v[a] + v[b]))
        return index[key]

    for a, b, c in f:
        ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
        faces += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
    return np.array(points), np.array(faces)


def subdivided_runs(work, level, noise, mesh):
    v, f = q.read_off(mesh)
    clean, faces = midpoint_subdivision(v, f)
    noisy, _ = midpoint_subdivision(q.add_noise(v, f, level, "isotropic", 7), f)
    name = os.path.basename(mesh)[:-4]
    path = os.path.join(work, name + "_subdivided_in.ply")
    q.write_ply(path, noisy, faces)
    folded = q.folded_faces(clean, faces)
    diagonal = float(np.linalg.norm(clean.max(0) - clean.min(0)))
    print("%s %g%%, subdivided after the noise: noisy E_a %.2f" % (name, level, q.metrics(clean, faces, folded, diagonal, noisy)["E_a"]))
    for script in ("smooth", "denoise"):
        for given in (0, noise):
            body = q.resource_filter(script, noisePercent=given)
            script_path = os.path.join(work, "%s_%s_%g.mlx" % (name, script, given))
            with open(script_path, "w") as s:
                s.write("<!DOCTYPE FilterScript>\n<FilterScript>\n%s\n</FilterScript>\n" % body)
            status, result = run_script(work, "%s_%s_%g" % (name, script, given), path, script_path)
            cell = ("E_a %.2f" % q.metrics(clean, faces, folded, diagonal, result)["E_a"]) if status == "ok" else status
            print("  %-8s noise %s: %s" % (script, "%g%% given" % given if given else "estimated", cell))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--level", type=float, default=10, help="isotropic noise, % of the mean edge")
    parser.add_argument("--damages", default=",".join(DAMAGES))
    parser.add_argument("--scripts", default=",".join(SCRIPTS))
    parser.add_argument("--subdivide", action="store_true")
    parser.add_argument("--noise", type=float, default=40, help="with --subdivide: the level given to the scripts")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--work", default=None)
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="damaged_")
    os.makedirs(work, exist_ok=True)
    if args.subdivide:
        for mesh in args.meshes:
            subdivided_runs(work, args.level, args.noise, mesh)
        return
    jobs = [(m, d, s) for m in args.meshes for d in args.damages.split(",") for s in args.scripts.split(",")]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for tag, cell in pool.map(lambda j: damaged_run(work, args.level, *j), jobs):
            print("%-55s %s" % (tag, cell), flush=True)


if __name__ == "__main__":
    main()
