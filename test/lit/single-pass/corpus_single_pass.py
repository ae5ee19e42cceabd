#!/usr/bin/env python3
"""Counts how many perspective vertex / tessellation-evaluation / geometry shaders of corpus/ convert
in each single-pass mode (--eye-source multiview | instanced), and why the others are refused.

Usage: corpus_single_pass.py --stereoshift BUILD/stereoshift --corpus CORPUS [--out DIR]
Converts the corpus with `stereoshift build --verify` three times (default, multiview, instanced)
and prints the counts; a measurement, not a test (the refusals are the documented limits)."""
import argparse
import collections
import json
import os
import re
import subprocess
import tempfile


def build(stereoshift, corpus, out, extra):
    run = subprocess.run([stereoshift, "build", corpus, "-o", out, "--verify", "-j2"] + extra,
                         capture_output=True, text=True)
    report = json.load(open(os.path.join(out, "stereoshift-report.json")))
    errors = {}
    for line in run.stderr.splitlines():
        m = re.match(r"(\S+?)(?::\d+:\d+)?: error: (.*)", line)
        if m:
            errors.setdefault(os.path.normpath(m.group(1)), m.group(2))
    return {os.path.normpath(s["file"]): s for s in report["shaders"]}, errors


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--stereoshift", required=True)
    ap.add_argument("--corpus", required=True)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        default, _ = build(args.stereoshift, args.corpus, os.path.join(tmp, "default"), [])
        perspective = sorted(f for f, s in default.items()
                             if s.get("classification") == "perspective" and s.get("stage") in ("vert", "tese", "geom"))
        print("perspective vertex/tessellation/geometry shaders: %d" % len(perspective))
        for mode in ("multiview", "instanced"):
            shaders, errors = build(args.stereoshift, args.corpus, os.path.join(tmp, mode), ["--eye-source", mode])
            converted = [f for f in perspective if shaders.get(f, {}).get("ok") and f not in errors]
            reasons = collections.Counter()
            for f in perspective:
                if f in converted:
                    continue
                why = errors.get(f, "not converted")
                reasons[re.sub(r"\(this output is [^)]*\)", "(...)", why.split(";")[0])] += 1
            print("%s: %d of %d convert" % (mode, len(converted), len(perspective)))
            for why, n in reasons.most_common():
                print("  %3d refused: %s" % (n, why))


if __name__ == "__main__":
    main()
