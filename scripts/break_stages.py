#!/usr/bin/env python3
"""Break one stage at a time and check that a unit test fails (docs/testing.md, "Breaking stages").

Each entry of tests/stage_breaks.json replaces one exact piece of a source file by a plausible
but wrong one (a step left out, a decision always taken, a rule made simpler). For each, this
script writes the change into the checkout, rebuilds the unit tests (build/ must be configured:
./scripts/build.sh), runs them in two shards and restores the file, whatever happens. A break no
test catches is reported as SURVIVED; an entry whose text is not found once is STALE (the code
moved on: update the entry). Exit status 1 if any survived or is stale.

  python3 scripts/break_stages.py                # every entry (about a minute each)
  python3 scripts/break_stages.py --match planar  # entries whose stage or change says so
"""
import argparse
import json
import os
import re
import signal
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build")
UNIT = os.path.join(BUILD, "tests", "hht_unit_tests")


def failing_tests():
    shards = []
    for index in range(2):
        env = dict(os.environ, GTEST_TOTAL_SHARDS="2", GTEST_SHARD_INDEX=str(index))
        shards.append(subprocess.Popen([UNIT, "--gtest_brief=1"], cwd=os.path.dirname(UNIT), env=env,
                                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True))
    failed = set()
    for shard in shards:
        out, _ = shard.communicate()
        failed.update(re.findall(r"^\[  FAILED  \] (\w[\w/]*\.\w[\w/]*)", out, re.M))
    return sorted(failed)


def build():
    return subprocess.run(["cmake", "--build", BUILD, "--target", "hht_unit_tests", "-j2"],
                          capture_output=True, text=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--match", default="", help="only entries whose stage or change contains this")
    args = parser.parse_args()
    if not os.path.exists(UNIT):
        sys.exit("no unit test binary at %s: run ./scripts/build.sh first" % UNIT)
    with open(os.path.join(ROOT, "tests", "stage_breaks.json")) as f:
        breaks = [b for b in json.load(f) if args.match in b["stage"] + " " + b["change"]]
    # A SIGTERM ends the run through the finally below, which puts the file back.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("terminated"))
    bad = 0
    for b in breaks:
        label = "%s: %s" % (b["stage"], b["change"])
        path = os.path.join(ROOT, b["file"])
        with open(path) as f:
            source = f.read()
        if source.count(b["old"]) != 1:
            print("STALE     %s (%s: the text to replace is found %d times)" % (label, b["file"], source.count(b["old"])), flush=True)
            bad += 1
            continue
        try:
            with open(path, "w") as f:
                f.write(source.replace(b["old"], b["new"]))
            made = build()
            if made.returncode != 0:
                print("NO BUILD  %s\n%s" % (label, (made.stdout + made.stderr)[-3000:]), flush=True)
                bad += 1
                continue
            failed = failing_tests()
            bad += not failed
            print("%s %s%s" % ("caught   " if failed else "SURVIVED ", label,
                               " (%d: %s)" % (len(failed), ", ".join(failed)) if failed else ""), flush=True)
        finally:
            with open(path, "w") as f:
                f.write(source)
    if build().returncode != 0:
        sys.exit("the restored tree does not build")
    print("%d of %d breaks caught" % (len(breaks) - bad, len(breaks)))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
