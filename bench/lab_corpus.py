#!/usr/bin/env python3
"""The lab's organic counts (docs/quality.md): build/bench/quality_lab in mode `a` (the shipped
smoothing against Taubin Smooth's 10 steps) on the 22 organic meshes of item 8 at 10-30% noise,
66 cases per noise model, seed 11 unless LAB_SEED says otherwise. Prints how many cases have both
E_a and RMS at or below Taubin's, how many also have neither above the noisy input's (the whole
goal), how many have E_a at or below Taubin's, and the mean log E_a; writes each case's numbers to
OUT/TAG_MODEL.tsv. Settings go to the lab as environment variables (LAB_FINISH=1 ...).

  python3 bench/lab_corpus.py TAG iso|normal|random|axis [NAME=VALUE ...]
  python3 bench/lab_corpus.py --oracle MODEL TAG [TAG ...]   cases won by at least one TAG's run

Options: --levels 0.1,0.2,0.3, --meshes NAME,... (default the 22 above), --jobs 2, --out build/lab. The meshes are read from libcgal-demo's
archive (scripts/setup.sh installs it) into OUT/meshes on first use.
"""
import argparse
import concurrent.futures
import csv
import math
import os
import re
import subprocess
import sys
import tarfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LAB = os.path.join(ROOT, "build", "bench", "quality_lab")
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"
MESHES = ("homer cow femur elephant armadillo bunny00 bull camel dino man bear lion-head triceratops "
          "mannequin-devil diplodocus ChineseDragon-10kv elk hand head pig mushroom cactus").split()
# The table's columns after mesh and level (--oracle reads them by name).
COLUMNS = ("noisy_ea", "noisy_rms", "taubin_ea", "taubin_rms", "ours_ea", "ours_rms", "below_taubin", "whole")


def mesh_folder(out, meshes):
    folder = os.path.join(out, "meshes")
    missing = [m for m in meshes if not os.path.exists(os.path.join(folder, m + ".off"))]
    if missing:
        if not os.path.exists(CGAL_DATA):
            sys.exit("no %s: run ./scripts/setup.sh (it installs libcgal-demo)" % CGAL_DATA)
        os.makedirs(folder, exist_ok=True)
        wanted = {"data/meshes/%s.off" % m: m for m in missing}
        with tarfile.open(CGAL_DATA) as tar:
            for member in tar.getmembers():
                if member.name in wanted:
                    with tar.extractfile(member) as src, open(os.path.join(folder, wanted[member.name] + ".off"), "wb") as dst:
                        dst.write(src.read())
        absent = [m for m in missing if not os.path.exists(os.path.join(folder, m + ".off"))]
        if absent:
            sys.exit("not in %s: %s" % (CGAL_DATA, " ".join(absent)))
    return folder


def scores(output, prefix):
    """E_a and RMS of the lab's line that starts with `prefix`."""
    for line in output.splitlines():
        if line.strip().startswith(prefix):
            found = re.search(r"E_a\s+([\d.]+)\s+rms\s+([\d.]+)", line)
            if found:
                return float(found.group(1)), float(found.group(2))
    return None


def run_case(folder, model, env, mesh, level):
    args = [LAB, os.path.join(folder, mesh + ".off"), str(level), "a"] + ([] if model == "iso" else [model])
    output = subprocess.run(args, env=env, capture_output=True, text=True).stdout
    return mesh, level, scores(output, "noisy"), scores(output, "taubin10"), scores(output, "NAS")


def count(args):
    env = dict(os.environ)
    for setting in args.settings:
        name, _, value = setting.partition("=")
        env[name] = value
    meshes = args.meshes.split(",")
    folder = mesh_folder(args.out, meshes)
    cases = [(m, float(l)) for m in meshes for l in args.levels.split(",")]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda c: run_case(folder, args.model, env, *c), cases))
    below = whole = angle = 0
    log_sum = 0.0
    path = os.path.join(args.out, "%s_%s.tsv" % (args.tag, args.model))
    with open(path, "w") as table:
        table.write("mesh\tlevel\t" + "\t".join(COLUMNS) + "\n")
        for mesh, level, noisy, taubin, ours in results:
            if not (noisy and taubin and ours):
                sys.exit("the lab printed no scores for %s at %s" % (mesh, level))
            b = ours[0] <= taubin[0] and ours[1] <= taubin[1]
            w = b and ours[0] <= noisy[0] and ours[1] <= noisy[1]
            below, whole, angle = below + b, whole + w, angle + (ours[0] <= taubin[0])
            log_sum += math.log(ours[0])
            table.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%d\t%d\n" % ((mesh, level) + noisy + taubin + ours + (b, w)))
    print("%s %s: both at or below Taubin %d of %d, whole goal %d, E_a at or below Taubin %d, mean log E_a %.4f (%s)"
          % (args.tag, args.model, below, len(results), whole, angle, log_sum / len(results), path))


def oracle(args):
    won = {}
    for tag in args.tags:
        with open(os.path.join(args.out, "%s_%s.tsv" % (tag, args.model))) as table:
            for row in csv.DictReader(table, delimiter="\t"):
                best = won.setdefault((row["mesh"], row["level"]), [0, 0])
                best[0] = max(best[0], int(row["below_taubin"]))
                best[1] = max(best[1], int(row["whole"]))
    print("%s, best of %s by the truth: both at or below Taubin %d of %d, whole goal %d"
          % (args.model, " ".join(args.tags), sum(b for b, _ in won.values()), len(won), sum(w for _, w in won.values())))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--oracle", action="store_true", help="combine earlier runs' tables instead of running")
    parser.add_argument("--levels", default="0.1,0.2,0.3")
    parser.add_argument("--meshes", default=",".join(MESHES), help="libcgal-demo mesh names (default: the 22 organic ones)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "lab"))
    parser.add_argument("words", nargs="+", help="TAG MODEL [NAME=VALUE ...], or with --oracle MODEL TAG [TAG ...]")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.oracle:
        args.model, args.tags = args.words[0], args.words[1:]
        oracle(args)
        return
    if len(args.words) < 2 or args.words[1] not in ("iso", "normal", "random", "axis"):
        parser.error("give TAG and a noise model: iso, normal, random or axis")
    args.tag, args.model, args.settings = args.words[0], args.words[1], args.words[2:]
    if not os.access(LAB, os.X_OK):
        sys.exit("build the lab first: ./scripts/build.sh")
    count(args)


if __name__ == "__main__":
    main()
