#!/usr/bin/env python3
"""The shipped scripts on meshes outside the quality corpus, through the staged meshlabserver:
enhance.mlx, smooth.mlx and denoise.mlx on each clean mesh, smooth.mlx and denoise.mlx at 2%, 10%
and 40% isotropic noise (seed 7; 40%: the denoiser's heavy-noise route, its trial refinement). Prints each run's E_a / RMS / flipped faces (the definitions of
evaluate_quality.py) against the clean mesh, then the failures, the clean meshes with faces turned
over and the noisy cases left worse than their input (docs/quality.md, "Meshes outside the
corpus through meshlabserver").

  xvfb-run -a /usr/bin/python3 scripts/evaluate_outside_corpus.py [--work DIR] MESH.off [...]
"""
import argparse
import concurrent.futures
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import evaluate_quality as q  # noqa: E402

LEVELS = {0: ("enhance", "smooth", "denoise"), 2: ("smooth", "denoise"), 10: ("smooth", "denoise"),
          40: ("smooth", "denoise")}


def run(work, path, level, method):
    name = os.path.basename(path)[:-4]
    v, faces = q.read_off(path)
    if faces.ndim != 2 or len(faces) == 0:
        return name, level, method, "no faces", None
    folded = q.folded_faces(v, faces)
    diagonal = float(np.linalg.norm(v.max(0) - v.min(0)))
    tag = "%s_%d_%s" % (name, level, method)
    source, noisy = path, None
    if level:
        nv = q.add_noise(v, faces, level, "isotropic", 7)
        source = os.path.join(work, tag + "_in.ply")
        q.write_ply(source, nv, faces)
        noisy = q.metrics(v, faces, folded, diagonal, nv)
    try:
        out, _, _ = q.run_server(work, tag, path, source, q.resource_filter(method))
        result, _ = q.read_ply(out)
        return name, level, method, q.metrics(v, faces, folded, diagonal, result), noisy
    except RuntimeError as e:
        return name, level, method, "failed: %s" % e, noisy


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--work", default=os.path.join(q.ROOT, "build", "outside_corpus"))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    jobs = [(p, level, m) for p in args.meshes for level, methods in LEVELS.items() for m in methods]
    rows = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for row in pool.map(lambda j: run(args.work, *j), jobs):
            name, level, method, m, noisy = row
            cell = m if isinstance(m, str) else "E_a %.2f RMS %.1f flipped %d" % (m["E_a"], m["RMS"], m["flipped"])
            print("%-28s %3d%% %-8s %s%s" % (name, level, method, cell,
                                             "" if noisy is None else "  (noisy E_a %.2f)" % noisy["E_a"]), flush=True)
            rows.append(row)
    done = [r for r in rows if isinstance(r[3], dict)]
    print("\nfailed or refused:", [(r[0], r[1], r[2], r[3][:200]) for r in rows if not isinstance(r[3], dict)])
    print("clean meshes with faces turned over:", [(r[0], r[2], r[3]["flipped"]) for r in done if r[1] == 0 and r[3]["flipped"]])
    for level in (2, 10, 40):
        for method in ("smooth", "denoise"):
            cases = [r for r in done if r[1] == level and r[2] == method]
            worse = [r for r in cases if r[3]["E_a"] > r[4]["E_a"]]
            print("%d%% %s: E_a above the noisy input's in %d of %d: %s" % (
                level, method, len(worse), len(cases), ", ".join("%s %.2f (%.2f)" % (r[0], r[3]["E_a"], r[4]["E_a"]) for r in worse)))


if __name__ == "__main__":
    main()
