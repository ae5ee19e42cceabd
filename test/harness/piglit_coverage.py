#!/usr/bin/env python3
"""Coverage on piglit's own shader tests (the Debian package installs them under
/usr/lib/x86_64-linux-gnu/piglit/tests/spec): a measure of how stereoshift does on GLSL written by
an OpenGL driver's developers, never a test of ours (nothing of piglit's is copied into this tree).

For each sampled .shader_test with inline pre-rasterization stages whose original passes in Mesa
(shader_runner, headless), the stages are converted as one pipeline (`--pipeline`, default options)
and the converted test is run again with the eye parameters left at 0 (mono); with --stereo, again
with eyeSign 1 where the test draws. Printed: how many ran,
how many converted and still pass ("ok"), how many stereoshift refused, and how many it converted
but no longer pass ("wrong": the worst result, a broken drop-in written with exit 0), with the
reasons grouped.

  python3 test/harness/piglit_coverage.py --stereoshift build/stereoshift [--sample N] [--seed S]
      [--jobs J] [--json out.json] [--execution-only]

Exit status 0 whatever the figures: this measures, it does not judge. 77 when piglit is missing.
"""
import argparse
import json
import os
import random
import re
import subprocess
import sys
import tempfile
from collections import Counter
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import piglit_splice_test as piglit  # noqa: E402

PRE_RASTER = ("vertex shader", "tessellation evaluation shader", "geometry shader")


def measure(path, args):
    try:
        text = open(path, errors="replace").read()
    except OSError as e:
        return "skip", str(e)
    sections = piglit.parse(text)
    names = [n for n, _ in sections]
    if not any(n in PRE_RASTER for n in names):
        return "skip", "no pre-rasterization stage"
    if any(n.endswith(" file") or "program" in n or n == "vertex shader passthrough" for n in names):
        return "skip", "a stage from a file, ARB assembly or the passthrough shader"
    es = any(n == "require" and re.search(r"GL ES", b) for n, b in sections)
    runner = os.path.join(args.piglit_bin, "shader_runner_gles3" if es else "shader_runner")
    with tempfile.TemporaryDirectory() as work:
        try:
            ok, _ = piglit.run_runner(runner, piglit.render(sections), work, "original")
        except subprocess.TimeoutExpired:
            return "skip", "the original timed out"
        if not ok:
            return "skip", "the original does not pass"
        files = []
        for i, (n, body) in enumerate(sections):
            if n in piglit.STAGE_SECTIONS:
                f = os.path.join(work, "s%d.%s" % (i, piglit.STAGE_SECTIONS[n]))
                with open(f, "w") as out:
                    out.write(body)
                files.append((i, f))
        outdir = os.path.join(work, "out")
        r = subprocess.run([args.stereoshift, "--pipeline", ",".join(f for _, f in files), "-o", outdir],
                           capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            errors = [l for l in r.stderr.splitlines() if "error:" in l]
            return "refused", errors[0] if errors else r.stderr[-300:]
        converted = list(sections)
        for i, f in files:
            out = outdir if os.path.isfile(outdir) else os.path.join(outdir, os.path.basename(f))
            with open(out) as o:
                converted[i] = (sections[i][0], o.read())
        try:
            ok, log = piglit.run_runner(runner, piglit.render(converted), work, "mono")
            # Only where the converted stages declare the eye parameters, the test draws (a linker
            # test only links) and one program takes uniforms (not separate shader objects).
            declared = any(re.search(r"\beyeSign\b", body) for _, body in converted)
            draws = any(n == "test" and re.search(r"^\s*draw\b", b, re.M) for n, b in sections)
            if ok and args.stereo and declared and draws and "SPIRV" not in text and "separate_shader" not in text \
                    and "SSO ENABLED" not in text:
                # The test's own probes with the eye parameters set: they hold where it draws with
                # w = 1 (the runtime cutoff keeps such draws mono); a test drawing perspective
                # geometry moves, which this cannot tell from a fault: listed for a person to look at.
                block = any(re.search(r"\buniform\s+StereoParams\b", body) for _, body in converted)
                prefix = "StereoParams." if block else ""
                eye = [(prefix + "eyeSign", "1"), (prefix + "separation", "0.5"), (prefix + "convergence", "1.0")]
                stereo_ok, stereo_log = piglit.run_runner(
                    runner, piglit.render(piglit.with_test(converted, eye, None)), work, "stereo")
                if not stereo_ok:
                    return "stereo-differs", stereo_log[-400:]
        except subprocess.TimeoutExpired:
            return "wrong", "the converted test timed out"
        return ("ok", "") if ok else ("wrong", log[-400:])


def reason_key(text):
    line = text.strip().splitlines()[0] if text.strip() else "(no message)"
    line = re.sub(r"^\S+?( \(emitted\))?:(\d+:)*\s*(error|warning):\s*", r"\1 ", line).strip()
    line = re.sub(r"'[^']*'", "'…'", line)
    line = re.sub(r"\b\d+(\.\d+)?\b", "N", line)
    return line[:120]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--stereoshift", required=True)
    ap.add_argument("--piglit-tests", default="/usr/lib/x86_64-linux-gnu/piglit/tests/spec")
    ap.add_argument("--piglit-bin", default="/usr/lib/x86_64-linux-gnu/piglit/bin")
    ap.add_argument("--sample", type=int, default=600, help="tests drawn (0: all)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--execution-only", action="store_true", help="only tests under an execution/ folder")
    ap.add_argument("--json", help="write every test's result here")
    ap.add_argument("--stereo", action="store_true",
                    help="also run each converted test with eyeSign 1 (separation 0.5, convergence 1): its own probes "
                         "must hold where it draws with w = 1 ('stereo-differs' otherwise, for a person to look at)")
    args = ap.parse_args()
    if not os.path.exists(os.path.join(args.piglit_bin, "shader_runner")) or not os.path.isdir(args.piglit_tests):
        print("piglit's shader_runner or its tests are not installed: skipped")
        return 77
    tests = sorted(os.path.join(d, f) for d, _, fs in os.walk(args.piglit_tests) for f in fs
                   if f.endswith(".shader_test"))
    if args.execution_only:
        tests = [t for t in tests if "/execution/" in t]
    random.Random(args.seed).shuffle(tests)
    if args.sample:
        tests = tests[:args.sample]
    with ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda t: measure(t, args), tests))
    counts = Counter(kind for kind, _ in results)
    ran = counts["ok"] + counts["refused"] + counts["wrong"] + counts["stereo-differs"]
    print("piglit tests sampled: %d (seed %d); run (the original passes, a pre-rasterization stage): %d"
          % (len(tests), args.seed, ran))
    if ran:
        print("converted and still passing: %d (%.1f%%)" % (counts["ok"], 100.0 * counts["ok"] / ran))
        print("refused:                     %d" % counts["refused"])
        print("converted, no longer pass:   %d" % counts["wrong"])
        if args.stereo:
            print("mono ok, stereo differs:     %d" % counts["stereo-differs"])
    for kind in ("wrong", "stereo-differs", "refused"):
        reasons = Counter(reason_key(why) for k, why in results if k == kind)
        if reasons:
            print("%s, by reason:" % kind)
            for why, n in reasons.most_common():
                print("  %4d  %s" % (n, why))
    if args.json:
        with open(args.json, "w") as f:
            json.dump([{"test": t, "result": k, "why": w} for t, (k, w) in zip(tests, results)], f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
