#!/usr/bin/env python3
"""Break one stage at a time and check that a test fails (docs/testing.md, "Breaking stages").

Each entry of tests/stage_breaks.json replaces one exact piece of a source file by a plausible
but wrong one (a step left out, a decision always taken, a rule made simpler, a filter parameter
ignored). For each, this script writes the change into the checkout, rebuilds the unit tests
(build/ must be configured: ./scripts/build.sh) and runs them in two shards, or, for an entry
with "suite": "meshlabserver" (the plugin's code), rebuilds the plugin and runs the tests that
drive the staged meshlabserver (ctest -L meshlabserver); then it restores the file, whatever
happens. A break no
test catches is reported as SURVIVED; an entry whose text is not found once is STALE (the code
moved on: update the entry). An entry with a "survives" note is a known gap, reported as
`known` with the note. Exit status 1 if any other survived or an entry is stale.

  python3 scripts/break_stages.py                # every entry (about a minute each)
  python3 scripts/break_stages.py --match planar  # entries whose stage or change says so
  python3 scripts/break_stages.py --start 45      # from the 46th entry on
  python3 scripts/break_stages.py --stop 79       # the library's entries only (unit tests)
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
    try:
        for index, shard in enumerate(shards):
            out, _ = shard.communicate()
            named = re.findall(r"^\[  FAILED  \] (\w[\w/]*\.\w[\w/]*)", out, re.M)
            # A shard that crashed or aborted names no failed test: it caught the break all the same.
            failed.update(named or ([] if shard.returncode == 0 else ["shard %d exited %d" % (index, shard.returncode)]))
    finally:
        for shard in shards:
            shard.kill()
    return sorted(failed)


def failing_meshlabserver_tests():
    run = subprocess.run(["ctest", "-L", "meshlabserver", "-j2", "--timeout", "600"], cwd=BUILD,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    failed = re.findall(r"^\s*\d+ - (\S+)", out_after(run.stdout, "The following tests FAILED:"), re.M)
    return sorted(failed or ([] if run.returncode == 0 else ["ctest exited %d" % run.returncode]))


def out_after(text, marker):
    return text[text.index(marker):] if marker in text else ""


TARGETS = {"unit": "hht_unit_tests", "meshlabserver": "filter_hht"}
FAILING = {"unit": failing_tests, "meshlabserver": failing_meshlabserver_tests}


def build(target="hht_unit_tests"):
    # In a session of its own, so that an interrupted run stops the compilers too: one left
    # running would write a broken object after the source is put back, newer than it, and
    # every later build would keep the break.
    make = subprocess.Popen(["cmake", "--build", BUILD, "--target", target, "-j2"], start_new_session=True,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        out, _ = make.communicate()
    except BaseException:
        os.killpg(make.pid, signal.SIGKILL)
        make.wait()
        raise
    return make.returncode, out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--match", default="", help="only entries whose stage or change contains this")
    parser.add_argument("--start", type=int, default=0, help="skip the file's first START entries (to resume a run)")
    parser.add_argument("--stop", type=int, default=None, help="only the file's first STOP entries")
    args = parser.parse_args()
    if not os.path.exists(UNIT):
        sys.exit("no unit test binary at %s: run ./scripts/build.sh first" % UNIT)
    with open(os.path.join(ROOT, "tests", "stage_breaks.json")) as f:
        breaks = [b for b in json.load(f)[args.start:args.stop] if args.match in b["stage"] + " " + b["change"]]
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
            suite = b.get("suite", "unit")
            status, out = build(TARGETS[suite])
            if status != 0:
                print("NO BUILD  %s\n%s" % (label, out[-3000:]), flush=True)
                bad += 1
                continue
            failed = FAILING[suite]()
            known = b.get("survives")
            bad += not failed and not known
            if failed:
                print("caught    %s (%d: %s)%s" % (label, len(failed), ", ".join(failed),
                                              " (listed as surviving: drop its note)" if known else ""), flush=True)
            else:
                print("%s %s%s" % ("known    " if known else "SURVIVED ", label, ": " + known if known else ""), flush=True)
        finally:
            with open(path, "w") as f:
                f.write(source)
            os.utime(path)  # newer than any object built from the break
    for suite in sorted({b.get("suite", "unit") for b in breaks}):
        if build(TARGETS[suite])[0] != 0:
            sys.exit("the restored tree does not build")
    known = sum(1 for b in breaks if b.get("survives"))
    print("%d of %d breaks caught or known to survive (%d known)" % (len(breaks) - bad, len(breaks), known))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
