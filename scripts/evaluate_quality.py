#!/usr/bin/env python3
"""Quality harness of issue 7: smoothing and denoising methods on libcgal-demo's meshes, every
method run through the staged meshlabserver, metrics computed against the clean mesh.

Run through scripts/evaluate_quality.sh (it builds nothing; it checks the build, installs numpy
and gives this script an X display). See docs/quality.md for the tables this writes.

Noise (fixed seeds, sigma in mean edge lengths): isotropic Gaussian per coordinate, Gaussian
along the area-weighted vertex normals, or Gaussian along a random direction per vertex; and
impulsive noise on the CAD and the organic meshes (a share of the vertices moved along the normals,
the others left as they were).
Metrics against the clean mesh (same connectivity):
  E_a      mean angle between result and clean face normals (degrees);
  E_v      mean distance of the result's vertices to the clean surface / clean bbox diagonal
           (logged by the plugin's "HHT: Compare to Reference", run in the same meshlabserver
           call right after the method);
  RMS      root mean square distance of each vertex to its clean position, 1e-4 bbox diagonal;
  flipped  faces whose normal is more than 90 degrees from the clean face normal, counted over
           the faces that are not already folded in the clean mesh (a clean face is folded when
           its normal points against the sum of its corners' area-weighted vertex normals);
  time     wall time of the whole meshlabserver call (start-up, loading the clean and the input
           mesh, the method, the comparison, saving).
"""
import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import tarfile
import threading
import time
import zlib

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SERVER = os.path.join(ROOT, "build", "stage", "bin", "meshlabserver")
RENDER = os.path.join(ROOT, "build", "tools", "render_mesh")
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"
DOC = os.path.join(ROOT, "docs", "quality.md")
IMAGES = os.path.join(ROOT, "docs", "images")
BEGIN, END = "<!-- quality-table:begin -->", "<!-- quality-table:end -->"

ORGANIC = ["homer", "cow", "femur", "elephant", "armadillo", "bunny00", "bull", "camel", "dino", "man"]
CAD = ["fandisk", "cube-meshed", "anchor_dense", "mech-holes-shark", "turbine", "blade"]
ORGANIC_LEVELS = [0, 10, 20, 30]
CAD_LEVELS = [5, 10, 20, 30]
QUICK = {"organic": (["cow", "bull"], [0, 20]), "cad": (["fandisk", "blade"], [10, 20])}
# Light noise (percent), where a denoiser must not leave the mesh worse than it was: its own table.
LIGHT_LEVEL = 2
LIGHT_METHODS = ("smooth", "denoise", "denoise_given", "guided", "guided_authors", "bilnormal", "taubin")
# The organic meshes with noise along the normals too (the denoising literature's protocol, which
# has no tangential part): the smoothers and the denoisers only.
ORGANIC_NORMAL_LEVELS = [10, 20, 30]
ORGANIC_NORMAL_METHODS = ("smooth", "denoise", "guided", "guided_authors", "bilnormal", "taubin", "hc", "laplacian", "twostep")
# Impulsive noise (the denoising literature's other model; docs/quality.md items 25 and 26): the
# given percentage of the vertices moved by a Gaussian of IMPULSIVE_SIGMA mean edges along the
# normals, the others left where they were. Tables of their own (CAD, organic), the denoisers and
# smoothers only.
IMPULSIVE_SHARES = [5, 10, 30]
IMPULSIVE_SIGMA = 50
IMPULSIVE_METHODS = ("smooth", "denoise", "guided", "guided_authors", "bilnormal", "taubin")
# denoise.mlx told the true noise level: the path a user takes on a mesh known to be lightly noisy
# (the noise estimate reads a clean mesh's own detail as noise; docs/quality.md item 18).
GIVEN_LABEL = "HHT: Feature-Preserving Denoise told the true noise (denoise.mlx, noisePercent %d)" % LIGHT_LEVEL


# ----------------------------------------------------------------------------------------------
# Methods: each is the <filter> element(s) of a script, applied to the input (current layer).

def resource_filter(name, **overrides):
    with open(os.path.join(ROOT, "resources", name + ".mlx")) as f:
        text = f.read()
    xml = text[text.index("<filter "):text.rindex("</filter>") + len("</filter>")]
    for key, value in overrides.items():
        xml, count = re.subn(r'name="%s" value="[^"]*"' % key, 'name="%s" value="%s"' % (key, value), xml)
        if count != 1:
            sys.exit("resources/%s.mlx has no parameter %s" % (name, key))
    return xml


def meshlab_filter(name, **params):
    kinds = {int: "RichInt", float: "RichFloat", bool: "RichBool"}
    lines = ['<filter name="%s">' % name]
    for key, value in params.items():
        text = ("true" if value else "false") if isinstance(value, bool) else str(value)
        lines.append(' <Param type="%s" name="%s" value="%s"/>' % (kinds[type(value)], key, text))
    lines.append("</filter>")
    return "\n".join(lines)


# The surface EMD factors the whole mesh's bi-harmonic system twice per sift (6-7 sifts for the
# 3 IMFs here: 9 s at 37,706 vertices; Table 1 of docs/benchmarks.md: 53 s for 6 IMFs at 70k):
# meshes above this many vertices are skipped for the two surface EMD methods.
SURFACE_EMD_VERTEX_LIMIT = 50000
VERTEX_LIMITS = {"surface_emd": SURFACE_EMD_VERTEX_LIMIT, "fc_emd": SURFACE_EMD_VERTEX_LIMIT}


def methods():
    """(key, label, filter xml) in table order."""
    return [
        ("smooth", "HHT: Adaptive Smooth (smooth.mlx)", resource_filter("smooth")),
        ("denoise", "HHT: Feature-Preserving Denoise (denoise.mlx)", resource_filter("denoise")),
        ("guided", "Guided Normal Filtering Denoise (guided_denoise.mlx; turned faces stood up)",
         resource_filter("guided_denoise")),
        # The guided filter as its authors' code runs it by default (bldeng/GuidedDenoising: 20
        # steps of one normal pass and 10 vertex iterations, no faces stood up): stronger at heavy
        # noise than the shipped script's one round of 8 passes, weaker at light noise.
        ("guided_authors", "Guided normal filtering, its authors' scheme (guided_denoise.mlx: rounds 20, "
                           "normalPasses 1, vertexIterations 10, standUpTurnedFaces false)",
         resource_filter("guided_denoise", rounds=20, normalPasses=1, vertexIterations=10,
                         standUpTurnedFaces="false")),
        ("bilnormal", "Bilateral normal filtering (Zheng et al. 2011; bilateral_normal_denoise.mlx: the guided "
                      "filter's range kernel on each face's own normal, the authors' defaults: 20 passes, sigma_r "
                      "0.35, 10 vertex iterations; turned faces stood up)", resource_filter("bilateral_normal_denoise")),
        # The paper's smoothing by HHT: Spectral Filter (its dialog's defaults enhance, as enhance.mlx).
        ("spectral", "HHT: Spectral Filter, the paper's smoothing (gain 0 above 0.1, lambda 0.01, 1 cycle)",
         resource_filter("enhance", gain=0, **{"lambda": 0.01}, cycles=1)),
        ("bilateral", "Bilateral (bilateral.mlx)", resource_filter("bilateral")),
        ("taubin", "Taubin Smooth (0.5, -0.53, 10 steps)",
         meshlab_filter("Taubin Smooth", **{"lambda": 0.5}, mu=-0.53, stepSmoothNum=10, Selected=False)),
        ("hc", "HC Laplacian Smooth", '<filter name="HC Laplacian Smooth"></filter>'),
        ("laplacian", "Laplacian Smooth (3 steps, cotangent)",
         meshlab_filter("Laplacian Smooth", stepSmoothNum=3, Boundary=True, cotangentWeight=True, Selected=False)),
        ("twostep", "TwoStep Smooth (defaults: 3, 60 deg, 20, 20)",
         meshlab_filter("TwoStep Smooth", stepSmoothNum=3, normalThr=60.0, stepNormalNum=20, stepFitNum=20,
                        Selected=False)),
        ("nlm", "Non-Local Means Denoising (nonlocal_means.mlx: eta 3, 1.3, 1.0, 1 iteration)",
         resource_filter("nonlocal_means")),
        # maxImfs 3 = the residue the scripts rebuild from: IMFs 1-3 and so the result are the same
        # as with no cap, the later IMFs are not computed.
        ("surface_emd", "HHT: Surface EMD, rebuilt from residue 3 (surface_emd_smooth.mlx, maxImfs 3)",
         resource_filter("surface_emd_smooth", maxImfs=3)),
        ("fc_emd", "HHT: Feature-Centric Surface EMD, residue 3 (feature_centric_emd.mlx, maxImfs 3)",
         resource_filter("feature_centric_emd", maxImfs=3)),
        # The paper's own denoising (sec. 4.3), what its Figs. 8-10 compare: denoise.mlx with the
        # paper's stage on and what this project added (untangling, refinement) off.
        ("paper", "HHT: the paper's feature-preserving denoising alone (denoise.mlx: paperStage on, "
                  "untangle off, refineNormalPasses 0)",
         resource_filter("denoise", paperStage="true", untangle="false", refineNormalPasses=0)),
    ]


SHORT = {"smooth": "smooth", "denoise": "denoise", "guided": "guided", "guided_authors": "guided (authors' scheme)",
         "bilnormal": "bilateral normal",
         "spectral": "spectral (paper)",
         "bilateral": "bilateral", "taubin": "Taubin", "hc": "HC", "laplacian": "Laplacian",
         "twostep": "TwoStep", "nlm": "NLM", "surface_emd": "3D-EMD", "fc_emd": "FC-EMD",
         "paper": "paper's HHT denoise", "denoise_given": "denoise (noise given)",
         "enhance": "enhance.mlx"}


# ----------------------------------------------------------------------------------------------
# Meshes: OFF in (libcgal-demo), binary PLY in and out (meshlabserver).

def read_off(path):
    with open(path) as f:
        tokens = []
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                tokens.append(line)
    header = tokens[0].split()
    rest = header[1:] if len(header) > 1 else []
    body = tokens[1:]
    if not rest:
        rest, body = body[0].split(), body[1:]
    nv, nf = int(rest[0]), int(rest[1])
    v = np.array([[float(x) for x in body[i].split()[:3]] for i in range(nv)])
    faces = []
    for i in range(nv, nv + nf):
        parts = body[i].split()
        n = int(parts[0])
        idx = [int(x) for x in parts[1:1 + n]]
        faces.extend([idx[0], idx[k], idx[k + 1]] for k in range(1, n - 1))
    return v, np.array(faces, dtype=np.int64)


PLY_TYPES = {"char": "i1", "uchar": "u1", "short": "<i2", "ushort": "<u2", "int": "<i4", "uint": "<u4",
             "float": "<f4", "double": "<f8", "int8": "i1", "uint8": "u1", "int16": "<i2", "uint16": "<u2",
             "int32": "<i4", "uint32": "<u4", "float32": "<f4", "float64": "<f8"}


def read_ply(path):
    """Binary little-endian triangle PLY as MeshLab writes it: positions and faces."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    elements = []
    for line in data[:end].decode("ascii").splitlines():
        w = line.split()
        if w[0] == "format" and w[1] != "binary_little_endian":
            raise ValueError("%s: %s PLY not supported" % (path, w[1]))
        if w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            if w[1] == "list":
                elements[-1][2].append((w[4], PLY_TYPES[w[2]], PLY_TYPES[w[3]]))
            else:
                elements[-1][2].append((w[2], PLY_TYPES[w[1]], None))
    offset, v, faces = end, None, None
    for name, count, props in elements:
        dtype = []
        for pname, t, list_t in props:
            if list_t is None:
                dtype.append((pname, t))
            else:  # triangle meshes only: every list holds 3 items
                dtype.append((pname + "_n", t))
                dtype.append((pname, list_t, (3,)))
        arr = np.frombuffer(data, dtype=np.dtype(dtype), count=count, offset=offset)
        offset += arr.nbytes
        if name == "vertex":
            v = np.stack([arr["x"], arr["y"], arr["z"]], axis=1).astype(np.float64)
        elif name == "face":
            key = [p[0] for p in props if p[2] is not None][0]
            if np.any(arr[key + "_n"] != 3):
                raise ValueError("%s: not a triangle mesh" % path)
            faces = arr[key].astype(np.int64)
    return v, faces


def write_ply(path, v, faces):
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
              "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % (len(v), len(faces)))
    fv = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", (3,))])
    fv["n"], fv["i"] = 3, faces
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(v.astype("<f4").tobytes())
        f.write(fv.tobytes())


# ----------------------------------------------------------------------------------------------
# Geometry

def face_cross(v, faces):
    return np.cross(v[faces[:, 1]] - v[faces[:, 0]], v[faces[:, 2]] - v[faces[:, 0]])


def unit(x):
    n = np.linalg.norm(x, axis=1, keepdims=True)
    return x / np.where(n > 0, n, 1)


def vertex_normals(v, faces):
    """Area-weighted vertex normals (unnormalised sums of the faces' cross products)."""
    cross = face_cross(v, faces)
    normals = np.zeros_like(v)
    for k in range(3):
        np.add.at(normals, faces[:, k], cross)
    return normals


def mean_edge_length(v, faces):
    edges = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    edges = np.unique(np.sort(edges, axis=1), axis=0)
    return float(np.mean(np.linalg.norm(v[edges[:, 0]] - v[edges[:, 1]], axis=1)))


def folded_faces(v, faces):
    """Clean faces whose normal points against the sum of their corners' area-weighted normals."""
    vn = vertex_normals(v, faces)
    corner_sum = vn[faces[:, 0]] + vn[faces[:, 1]] + vn[faces[:, 2]]
    return np.einsum("ij,ij->i", face_cross(v, faces), corner_sum) < 0


def add_noise(v, faces, percent, model, seed):
    rng = np.random.default_rng(seed)
    if model == "impulsive":  # `percent`: the share of the vertices moved
        moved = rng.random(len(v)) < percent / 100.0
        sigma = IMPULSIVE_SIGMA / 100.0 * mean_edge_length(v, faces)
        offset = rng.normal(0.0, sigma, (len(v), 1)) * unit(vertex_normals(v, faces))
        return v + offset * moved[:, None]
    sigma = percent / 100.0 * mean_edge_length(v, faces)
    if model == "isotropic":
        return v + rng.normal(0.0, sigma, v.shape)
    if model == "normal":
        direction = unit(vertex_normals(v, faces))
    elif model == "random":
        direction = unit(rng.normal(size=v.shape))
    else:
        raise ValueError(model)
    return v + rng.normal(0.0, sigma, (len(v), 1)) * direction


def metrics(clean, faces, folded, diagonal, result):
    nc, nr = unit(face_cross(clean, faces)), unit(face_cross(result, faces))
    cos = np.einsum("ij,ij->i", nc, nr)
    sin = np.linalg.norm(np.cross(nc, nr), axis=1)
    angle = np.degrees(np.arctan2(sin, cos))  # atan2: accurate for small angles
    rms = np.sqrt(np.mean(np.sum((result - clean) ** 2, axis=1))) / diagonal * 1e4
    return {"E_a": float(np.mean(angle)), "RMS": float(rms), "flipped": int(np.sum((cos < 0) & ~folded))}


# ----------------------------------------------------------------------------------------------
# meshlabserver

def run_server(work, tag, clean_path, input_path, filter_xml):
    """Runs the method then "HHT: Compare to Reference" in one call; returns (result, E_v, seconds)
    or raises RuntimeError with the log's telling lines."""
    script = os.path.join(work, tag + ".mlx")
    output = os.path.join(work, tag + ".ply")
    log = os.path.join(work, tag + ".log")
    with open(script, "w") as f:
        f.write("<!DOCTYPE FilterScript>\n<FilterScript>\n%s\n%s\n</FilterScript>\n"
                % (filter_xml, resource_filter("compare")))
    for attempt in range(3):  # a busy X server sometimes refuses a client: that is no filter's fault
        if os.path.exists(output):
            os.remove(output)
        start = time.monotonic()
        with open(log, "w") as f:
            code = subprocess.call([SERVER, "-i", clean_path, "-i", input_path, "-o", output, "-s", script],
                                   stdout=f, stderr=subprocess.STDOUT, cwd=work)
        seconds = time.monotonic() - start
        with open(log, errors="replace") as f:
            text = f.read()
        if "no Qt platform plugin could be initialized" not in text:
            break
    ev = re.search(r"E_v = ([0-9.eE+-]+)", text)
    if code != 0 or ev is None or not os.path.exists(output):
        telling = [l for l in text.splitlines() if re.search(r"fail|error|abort|crash|Nothing was changed", l, re.I)]
        raise RuntimeError("exit %d; %s" % (code, " | ".join(telling[-3:]) or text.strip().splitlines()[-1:]))
    return output, float(ev.group(1)), seconds


# ----------------------------------------------------------------------------------------------

class Corpus:
    def __init__(self, work):
        self.dir = os.path.join(work, "meshes")
        os.makedirs(self.dir, exist_ok=True)
        self.cache = {}

    def clean(self, name):
        if name not in self.cache:
            path = os.path.join(self.dir, name + ".off")
            if not os.path.exists(path):
                with tarfile.open(CGAL_DATA) as tar:
                    member = tar.getmember("data/meshes/%s.off" % name)
                    with tar.extractfile(member) as src, open(path, "wb") as dst:
                        dst.write(src.read())
            v, faces = read_off(path)
            lo, hi = v.min(axis=0), v.max(axis=0)
            self.cache[name] = {"path": path, "v": v, "faces": faces, "folded": folded_faces(v, faces),
                                "diagonal": float(np.linalg.norm(hi - lo)), "edge": mean_edge_length(v, faces)}
        return self.cache[name]


def case_name(mesh, model, level):
    return "%s_%s%d" % (mesh, model[:3], level) if level else "%s_clean" % mesh


def evaluate_case(corpus, work, previous, mesh, model, level, method_list, log):
    """Runs the methods missing from `previous` (a case's row of results) on one case; returns the row."""
    c = corpus.clean(mesh)
    name = case_name(mesh, model, level)
    row = dict(previous)
    if level:
        noisy = add_noise(c["v"], c["faces"], level, model, zlib.crc32(name.encode()))
        input_path = os.path.join(work, name + "_noisy.ply")
        write_ply(input_path, noisy, c["faces"])
        noisy = read_ply(input_path)[0]  # as meshlabserver reads it (float)
        row["noisy"] = metrics(c["v"], c["faces"], c["folded"], c["diagonal"], noisy)
    else:
        input_path = c["path"]
        row["noisy"] = {"E_a": 0.0, "RMS": 0.0, "flipped": 0}
    row["meta"] = {"mesh": mesh, "model": model, "level": level}
    for key, _label, xml in method_list:
        if key in row and "error" not in row[key] and "skipped" not in row[key]:  # --resume runs failed ones again
            continue
        tag = "%s_%s" % (name, key)
        limit = VERTEX_LIMITS.get(key)
        if limit is not None and len(c["v"]) > limit:
            row[key] = {"skipped": "%d vertices > %d" % (len(c["v"]), limit)}
            log("%-28s %-10s %s" % (name, key, json.dumps(row[key])))
            continue
        try:
            out, ev, seconds = run_server(work, tag, c["path"], input_path, xml)
            v, faces = read_ply(out)
            if len(v) != len(c["v"]) or not np.array_equal(faces, c["faces"]):
                raise RuntimeError("connectivity changed: %d vertices, %d faces (clean: %d, %d)"
                                   % (len(v), len(faces), len(c["v"]), len(c["faces"])))
            r = metrics(c["v"], c["faces"], c["folded"], c["diagonal"], v)
            r.update({"E_v": ev, "time": seconds})
        except (RuntimeError, ValueError, OSError) as e:
            r = {"error": str(e)}
        row[key] = r
        log("%-28s %-10s %s" % (name, key, json.dumps(r)))
    return name, row


# ----------------------------------------------------------------------------------------------
# Tables

def fmt(x, digits):
    return "%.*f" % (digits, x)


def case_table(results, names, method_keys, labels):
    head = "| case | noisy | " + " | ".join(SHORT[k] for k in method_keys) + " |"
    lines = [head, "|" + "---|" * (2 + len(method_keys))]
    for name in names:
        row = results[name]
        ok = [k for k in method_keys if "error" not in row[k] and "skipped" not in row[k]]
        best_a = min((row[k]["E_a"] for k in ok), default=None)
        best_r = min((row[k]["RMS"] for k in ok), default=None)
        cells = []
        for k in method_keys:
            r = row[k]
            if "error" in r:
                cells.append("failed")
                continue
            if "skipped" in r:
                cells.append("skipped: %s" % r["skipped"])
                continue
            a, rms = fmt(r["E_a"], 2), fmt(r["RMS"], 0)
            if r["E_a"] == best_a:
                a = "**%s**" % a
            if r["RMS"] == best_r:
                rms = "**%s**" % rms
            cells.append("%s / %s%s" % (a, rms, " (%d flipped)" % r["flipped"] if r["flipped"] else ""))
        n = row["noisy"]
        noisy = "-" if row["meta"]["level"] == 0 else "%s / %s" % (fmt(n["E_a"], 2), fmt(n["RMS"], 0))
        lines.append("| %s | %s | %s |" % (label_case(row["meta"]), noisy, " | ".join(cells)))
    return "\n".join(lines)


def label_case(meta):
    if meta["level"] == 0:
        return "%s clean" % meta["mesh"]
    return "%s %d%% %s" % (meta["mesh"], meta["level"], {"isotropic": "iso", "normal": "normal",
                                                          "random": "random dir"}[meta["model"]])


def summary_table(results, names, method_keys):
    noisy_names = [n for n in names if results[n]["meta"]["level"] > 0]
    lines = ["| method | beats Taubin on E_a and RMS | E_a <= noisy | RMS <= noisy | both <= noisy | "
             "cases with flipped faces | failed | skipped (too large) | mean time (s) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for k in method_keys:
        beats = ea_ok = rms_ok = both = flips = failed = 0
        skipped = sum("skipped" in results[n][k] for n in noisy_names)
        total = len(noisy_names) - skipped
        times = []
        for n in noisy_names:
            r, t, noisy = results[n][k], results[n]["taubin"], results[n]["noisy"]
            if "skipped" in r:
                continue
            if "error" in r:
                failed += 1
                continue
            times.append(r["time"])
            if k != "taubin" and "error" not in t and r["E_a"] < t["E_a"] and r["RMS"] < t["RMS"]:
                beats += 1
            ea_ok += r["E_a"] <= noisy["E_a"]
            rms_ok += r["RMS"] <= noisy["RMS"]
            both += r["E_a"] <= noisy["E_a"] and r["RMS"] <= noisy["RMS"]
            flips += r["flipped"] > 0
        lines.append("| %s | %s | %d/%d | %d/%d | %d/%d | %d/%d | %d | %d | %.2f |" % (
            SHORT[k], "-" if k == "taubin" else "%d/%d" % (beats, total), ea_ok, total, rms_ok, total, both, total,
            flips, total, failed, skipped, np.mean(times) if times else float("nan")))
    return "\n".join(lines)


def detail_table(results, names, method_keys, labels):
    lines = ["| case | method | E_a (deg) | E_v (/ diag) | RMS (1e-4 diag) | flipped | time (s) |",
             "|---|---|---|---|---|---|---|"]
    for name in names:
        row = results[name]
        for k in ["noisy"] + method_keys:
            r = row[k]
            label = "noisy input" if k == "noisy" else labels[k]
            if "error" in r:
                lines.append("| %s | %s | failed: %s | | | | |" % (label_case(row["meta"]), label,
                                                                 r["error"].replace("|", "/")))
            elif "skipped" in r:
                lines.append("| %s | %s | skipped: %s | | | | |" % (label_case(row["meta"]), label, r["skipped"]))
            elif k == "noisy":
                if row["meta"]["level"]:
                    lines.append("| %s | noisy input | %.3f | | %.1f | %d | |" % (
                        label_case(row["meta"]), r["E_a"], r["RMS"], r["flipped"]))
            else:
                lines.append("| %s | %s | %.3f | %.3e | %.1f | %d | %.2f |" % (
                    label_case(row["meta"]), label, r["E_a"], r["E_v"], r["RMS"], r["flipped"], r["time"]))
    return "\n".join(lines)


def write_doc(markdown):
    text = open(DOC).read() if os.path.exists(DOC) else "# Quality of smoothing and denoising\n\n%s\n%s\n" % (BEGIN, END)
    if BEGIN not in text or END not in text:
        text = text.rstrip("\n") + "\n\n%s\n%s\n" % (BEGIN, END)
    before, after = text.split(BEGIN)[0], text.split(END)[1]
    with open(DOC, "w") as f:
        f.write(before + BEGIN + "\n" + markdown + "\n" + END + after)


def render(work, out, files, titles, azimuth=35, elevation=25):
    if not os.path.exists(RENDER):
        print("no %s: pictures skipped" % RENDER)
        return
    paths = [os.path.join(work, f) if not os.path.isabs(f) else f for f in files]
    missing = [p for p in paths if not os.path.exists(p)]
    if missing:
        print("picture %s skipped, missing %s" % (out, missing))
        return
    subprocess.check_call([RENDER, "--azimuth", str(azimuth), "--elevation", str(elevation), "--size", "360",
                           "--title", "|".join(titles), os.path.join(IMAGES, out)] + paths,
                          stdout=subprocess.DEVNULL)


def against_noisy_table(results, cases, keys, bold_best):
    """A table of (case name, row label) by method, each cell E_a / RMS marked *worse* above the noisy
    input's E_a (the row's best E_a in bold if bold_best); returns its lines and, per method, the cases
    worse than the noisy input and the cases scored (not failed)."""
    lines = ["| case | noisy input | %s |" % " | ".join(SHORT[k] for k in keys), "|---|---|" + "---|" * len(keys)]
    worse, scored = {k: 0 for k in keys}, {k: 0 for k in keys}
    for name, label in cases:
        row = results[name]
        valid = [row[k]["E_a"] for k in keys if "error" not in row[k]]
        best = min(valid) if bold_best and valid else None
        cells = ["%.2f / %.0f" % (row["noisy"]["E_a"], row["noisy"]["RMS"])]
        for k in keys:
            r = row[k]
            if "error" in r:
                cells.append("failed")
                continue
            above = r["E_a"] > row["noisy"]["E_a"]
            worse[k] += above
            scored[k] += 1
            ea = "%.2f" % r["E_a"]
            cells.append("%s / %.0f%s" % ("**%s**" % ea if r["E_a"] == best else ea, r["RMS"], " *worse*" if above else ""))
        lines.append("| %s | %s |" % (label, " | ".join(cells)))
    return lines, worse, scored


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="2 organic + 2 CAD meshes, 2 levels each; "
                        "writes WORK/quality_quick.md instead of docs/quality.md")
    parser.add_argument("--work", default=os.path.join(ROOT, "build", "quality"))
    parser.add_argument("--cad-models", default="isotropic,normal",
                        help="noise models of the CAD cases: isotropic, normal, random (comma-separated)")
    parser.add_argument("--jobs", type=int, default=1, help="cases run in parallel (times then overlap)")
    parser.add_argument("--rerun", default="", help="with --resume: methods to run again (comma-separated keys, "
                        "e.g. smooth,denoise,enhance after a change to those filters)")
    parser.add_argument("--resume", action="store_true", help="keep the results already in WORK/results.json")
    args = parser.parse_args()

    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    os.makedirs(IMAGES, exist_ok=True)
    results_path = os.path.join(work, "results.json")
    results = json.load(open(results_path)) if args.resume and os.path.exists(results_path) else {}
    for row in results.values():
        for key in filter(None, args.rerun.split(",")):
            row.pop(key, None)
    corpus = Corpus(work)
    method_list = methods()
    keys = [k for k, _, _ in method_list]
    labels = {k: label for k, label, _ in method_list}
    labels["enhance"] = "HHT: Spectral Filter (enhance.mlx)"
    labels["denoise_given"] = GIVEN_LABEL
    cad_models = args.cad_models.split(",")

    organic, organic_levels = QUICK["organic"] if args.quick else (ORGANIC, ORGANIC_LEVELS)
    cad, cad_levels = QUICK["cad"] if args.quick else (CAD, CAD_LEVELS)
    organic_cases = [(m, "isotropic", l) for m in organic for l in organic_levels]
    cad_cases = [(m, model, l) for m in cad for model in cad_models for l in cad_levels]

    started = time.monotonic()

    def log(line):
        print("[%6.0fs] %s" % (time.monotonic() - started, line), flush=True)

    def save():
        with open(results_path, "w") as f:
            json.dump(results, f, indent=1)

    # The shipped enhance.mlx and smooth.mlx on every clean mesh: flipped faces (goal: none); and
    # the denoisers, which should leave a clean mesh nearly as it is (the organic clean cases
    # already have them from the first batch, which the second then skips).
    enhance = [("enhance", labels["enhance"], resource_filter("enhance")),
               ("smooth", labels["smooth"], resource_filter("smooth")),
               ("denoise", labels["denoise"], resource_filter("denoise")),
               ("guided", labels["guided"], resource_filter("guided_denoise"))]
    jobs = [(m, model, l, method_list) for m, model, l in organic_cases + cad_cases]
    jobs += [(m, "isotropic", 0, enhance) for m in organic + cad]
    light = [m for m in method_list if m[0] in LIGHT_METHODS] + [
        ("denoise_given", GIVEN_LABEL, resource_filter("denoise", noisePercent=LIGHT_LEVEL))]
    light_cases = [(m, "isotropic", LIGHT_LEVEL) for m in organic] + [
        (m, model, LIGHT_LEVEL) for m in cad for model in cad_models]
    organic_normal_cases = [] if args.quick else [(m, "normal", l) for m in organic for l in ORGANIC_NORMAL_LEVELS]
    impulsive_cases = [] if args.quick else [(m, "impulsive", l) for m in cad for l in IMPULSIVE_SHARES]
    organic_impulsive_cases = [] if args.quick else [(m, "impulsive", l) for m in organic for l in IMPULSIVE_SHARES]
    if not args.quick:
        jobs += [(m, model, l, [x for x in method_list if x[0] in IMPULSIVE_METHODS])
                 for m, model, l in impulsive_cases + organic_impulsive_cases]
        jobs += [(m, model, l, light) for m, model, l in light_cases]
        jobs += [(m, model, l, [x for x in method_list if x[0] in ORGANIC_NORMAL_METHODS])
                 for m, model, l in organic_normal_cases]
    for mesh in organic + cad:
        corpus.clean(mesh)  # extract and load once, before the workers share the corpus
    lock = threading.Lock()

    def work_on(job):
        mesh, model, level, method_subset = job
        with lock:
            previous = dict(results.get(case_name(mesh, model, level), {}))
        name, row = evaluate_case(corpus, work, previous, mesh, model, level, method_subset, log)
        with lock:
            results.setdefault(name, {}).update(row)
            save()

    # Clean cases appear twice (all methods, then enhance): the second job waits for the first.
    # The light-noise cases share no case with the first batch and run with the second.
    first, second = jobs[:len(organic_cases) + len(cad_cases)], jobs[len(organic_cases) + len(cad_cases):]
    for batch in (first, second):
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            list(pool.map(work_on, batch))

    organic_names = [case_name(*c) for c in organic_cases]
    organic_normal_names = [case_name(*c) for c in organic_normal_cases]
    cad_names = [case_name(*c) for c in cad_cases]
    elapsed_path = os.path.join(work, "elapsed_minutes")  # accumulated over --resume runs
    minutes, passes = (time.monotonic() - started) / 60, 1
    if args.resume and os.path.exists(elapsed_path):
        before = open(elapsed_path).read().split()
        minutes, passes = minutes + float(before[0]), passes + (int(before[1]) if len(before) > 1 else 1)
    with open(elapsed_path, "w") as f:
        f.write("%.2f %d\n" % (minutes, passes))
    cmd = "scripts/evaluate_quality.sh" + (" --quick" if args.quick else "") + (
        " --jobs %d" % args.jobs if args.jobs > 1 else "") + (" --resume" if args.resume else "") + (
        " --rerun %s" % args.rerun if args.rerun else "")
    out = ["Generated by `%s` (%s; %.0f minutes%s on a shared 2-core machine%s, so times are indicative)."
           % (cmd, time.strftime("%Y-%m-%d", time.gmtime()), minutes,
              " over %d passes (--resume)" % passes if passes > 1 else "",
              ", %d cases at a time" % args.jobs if args.jobs > 1 else ""), "",
           "Cells: E_a (degrees) / RMS vertex distance to the clean mesh (1e-4 of the bounding-box diagonal), "
           "with the count of flipped faces when there are any; the best E_a and the best RMS of each row in "
           "bold. Noise sigma in mean edge lengths, fixed seeds. Methods:", ""]
    out += ["- **%s**: %s" % (SHORT[k], labels[k]) for k in keys]
    out += ["", "%s: skipped on meshes above %d vertices (\"skipped\" in the cells)." % (
        " and ".join(SHORT[k] for k in VERTEX_LIMITS), SURFACE_EMD_VERTEX_LIMIT)]
    out += ["", "### The meshes", "",
            "| mesh | class | vertices | faces | mean edge / diag | folded faces in the clean mesh |",
            "|---|---|---|---|---|---|"]
    for mesh in organic + cad:
        c = corpus.clean(mesh)
        out.append("| %s | %s | %d | %d | %.4f | %d |" % (mesh, "organic" if mesh in organic else "CAD", len(c["v"]),
                                                           len(c["faces"]), c["edge"] / c["diagonal"],
                                                           int(c["folded"].sum())))
    out += ["", "### Summary over the noisy cases", "",
            "Counts of cases out of the noisy ones of each class (clean cases excluded). \"beats Taubin\": "
            "strictly lower E_a and strictly lower RMS than Taubin Smooth; \"<= noisy\": not worse than the "
            "noisy input.", ""]
    for title, names in (("Organic (isotropic noise)", organic_names), ("CAD", cad_names)):
        out += ["**%s**" % title, "", summary_table(results, names, keys), ""]
    if organic_normal_names:
        normal_keys = [k for k in keys if k in ORGANIC_NORMAL_METHODS]
        out += ["**Organic (noise along the normals)**", "", summary_table(results, organic_normal_names, normal_keys), ""]
    out += ["### Organic meshes (isotropic noise; clean = the method run on the clean mesh)", "",
            case_table(results, organic_names, keys, labels), "",
            "### CAD meshes", "", case_table(results, cad_names, keys, labels), "",
            ] + ([] if not organic_normal_names else [
            "### Organic meshes, noise along the normals", "",
            "The smoothers and the denoisers only.", "",
            case_table(results, organic_normal_names, [k for k in keys if k in ORGANIC_NORMAL_METHODS], labels), ""]) + [
            "### The shipped scripts on the clean meshes", "",
            "Flipped faces (goal for enhance.mlx and smooth.mlx: zero), counted over the faces not folded in "
            "the clean mesh, and E_a / RMS against the clean mesh: what each does to a mesh without noise "
            "(a denoiser should leave it nearly as it is).", "",
            "| mesh | folded in clean | enhance.mlx flipped | enhance.mlx E_a / RMS | smooth.mlx flipped | "
            "smooth.mlx E_a / RMS | denoise.mlx flipped | denoise.mlx E_a / RMS | guided_denoise.mlx flipped | "
            "guided_denoise.mlx E_a / RMS |", "|---|---|---|---|---|---|---|---|---|---|"]
    for mesh in organic + cad:
        row = results[case_name(mesh, "isotropic", 0)]
        cells = []
        for k in ("enhance", "smooth", "denoise", "guided"):
            r = row[k]
            cells += ["failed", "-"] if "error" in r else [str(r["flipped"]), "%.2f / %.0f" % (r["E_a"], r["RMS"])]
        out.append("| %s | %d | %s |" % (mesh, int(corpus.clean(mesh)["folded"].sum()), " | ".join(cells)))
    if not args.quick:
        out += ["", "### The shipped scripts at light noise (%d%%)" % LIGHT_LEVEL, "",
                "E_a (degrees) / RMS (1e-4 of the diagonal) against the clean mesh; a cell marked *worse* is "
                "above the noisy input's E_a: a denoiser made the mesh worse than it was. Not in the summary "
                "counts above. *denoise.mlx, noise given*: %s." % GIVEN_LABEL, ""]
        rows, worse, scored = against_noisy_table(
            results, [(case_name(m, model, l), "%s %d%% %s" % (m, l, model)) for m, model, l in light_cases], LIGHT_METHODS, bold_best=False)
        out += rows + ["", "Worse than the noisy input: " + ", ".join(
            "%s %d of %d" % (SHORT[k], worse[k], len(light_cases)) for k in LIGHT_METHODS) + "."]
    for title, cases, item in (("CAD meshes", impulsive_cases, "items 25 and 26"),
                               ("Organic meshes", organic_impulsive_cases, "item 26")):
        if not cases:
            continue
        out += ["", "### %s with impulsive noise" % title, "",
                "A share of the vertices moved by a Gaussian of %d%% of the mean edge along the normals, the "
                "others left where they were (docs/quality.md %s); E_a / RMS, the best E_a of each row in "
                "bold, *worse* above the noisy input's E_a. Not in the summary counts above." % (IMPULSIVE_SIGMA, item), ""]
        rows, worse, scored = against_noisy_table(
            results, [(case_name(m, model, l), "%s %d%% of the vertices" % (m, l)) for m, model, l in cases],
            IMPULSIVE_METHODS, bold_best=True)
        out += rows + ["", "At or below the noisy input: " + ", ".join(
            "%s %d of %d" % (SHORT[k], scored[k] - worse[k], len(cases)) for k in IMPULSIVE_METHODS) + "."]
    failures = [(n, k, r["error"]) for n, row in results.items() for k, r in row.items()
                if isinstance(r, dict) and "error" in r]
    out += ["", "### Failures", ""]
    out += ["- %s, %s: %s" % (n, labels.get(k, k), e) for n, k, e in failures] or ["None."]
    out += ["", "<details><summary>All figures (E_v and times included)</summary>", "",
            detail_table(results, organic_names + cad_names, keys, labels), "", "</details>"]
    markdown = "\n".join(out)

    if args.quick:
        with open(os.path.join(work, "quality_quick.md"), "w") as f:
            f.write(markdown + "\n")
        print(markdown)
        return
    write_doc(markdown)
    render(work, "quality_cow_iso20.png",
           [corpus.clean("cow")["path"], "cow_iso20_noisy.ply", "cow_iso20_smooth.ply", "cow_iso20_taubin.ply",
            "cow_iso20_denoise.ply", "cow_iso20_spectral.ply"],
           ["clean", "noisy (20% iso)", "HHT smooth", "Taubin", "HHT denoise", "spectral (paper)"], 200, 10)
    render(work, "quality_fandisk_nor20.png",
           [corpus.clean("fandisk")["path"], "fandisk_nor20_noisy.ply", "fandisk_nor20_denoise.ply",
            "fandisk_nor20_guided.ply", "fandisk_nor20_bilateral.ply", "fandisk_nor20_twostep.ply"],
           ["clean", "noisy (20% normal)", "HHT denoise", "guided", "bilateral", "TwoStep"], 210, -45)
    # The paper's Figs. 9 and 10: cube at 10% and Fandisk at 5% Gaussian noise, against the surface
    # EMD (3D-EMD), the feature-centric EMD and non-local means.
    for mesh, case, title in (("cube-meshed", "cube-meshed_iso10", "10% iso"), ("fandisk", "fandisk_iso5", "5% iso")):
        render(work, "quality_%s.png" % case.replace("-meshed", ""),
               [corpus.clean(mesh)["path"]] + ["%s_%s.ply" % (case, k) for k in
                                               ("noisy", "denoise", "paper", "surface_emd", "fc_emd", "nlm")],
               ["clean", "noisy (%s)" % title, "HHT denoise", "paper's HHT denoise", "3D-EMD (residue 3)",
                "feature-centric EMD", "non-local means"], 210, -45)
    render(work, "quality_bull_clean.png",
           [corpus.clean("bull")["path"], "bull_clean_smooth.ply", "bull_clean_enhance.ply", "bull_clean_taubin.ply"],
           ["clean", "smooth.mlx", "enhance.mlx", "Taubin"])
    print(markdown)


if __name__ == "__main__":
    main()
