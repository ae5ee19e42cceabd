#!/usr/bin/env python3
"""Coverage of `stereoshift verify`: runs it over every pre-rasterization shader of a shader tree
(the corpus by default), each shader by itself as a user would hand it over, and prints how many
get the perspective shift, how many of those `verify` can run, how many pass, and why the rest
could not run or failed, grouped by reason (names and numbers taken out so alike reasons group).

  python3 test/harness/verify_coverage.py --stereoshift build/stereoshift [--root DIR ...] [-v]
      [--eye-source two-pass|multiview|instanced ...] [--verify-arg ARG ...]

--eye-source (repeatable; default two-pass) measures the single-pass modes too, one block of figures
each; a shader the conversion refuses in a mode (its output cannot express the mode) is counted as
refused, by reason, apart from the shaders verify cannot run.

Default roots: corpus/ and test/harness/shaders/verify/ (shaders written for verify in the manner of
public tutorials and SDK samples: every resource kind, input shape and lone stage).

Exit status 0 whatever the figures: this measures, it does not judge.
"""
import argparse
import json
import os
import re
import subprocess
import sys
from collections import Counter

PRE_RASTER = ("vert", "tesc", "tese", "geom")


def stage_of(name):
    parts = name.split(".")
    # foo.vert, foo.vert.hlsl, foo.vert.glsl
    for part in reversed(parts[1:]):
        if part in PRE_RASTER:
            return part
        if part in ("frag", "comp"):
            return None
    return None


def reason_key(text):
    """One line of a reason with the shader-specific parts (paths, names, numbers) taken out."""
    line = text.strip().splitlines()[0] if text.strip() else "(no message)"
    line = re.sub(r"^\S+?:(\d+:)*\s*error:\s*", "", line)
    line = re.sub(r"'[^']*'", "'…'", line)
    line = re.sub(r"\b\d+(\.\d+)?\b", "N", line)
    return line


def measure(args, shaders, mode):
    """Verifies every shader in one mode and prints the figures."""
    perspective = ran = passed = unshifted_ran = unshifted_passed = 0
    cannot_run, failed, other, refused = Counter(), Counter(), Counter(), Counter()
    mode_flags = [] if mode == "two-pass" else ["--eye-source", mode]
    for root, path in shaders:
        rel = os.path.join(os.path.basename(os.path.normpath(root)), os.path.relpath(path, root))
        try:
            # An include/ folder beside the shader is its #include search path (as corpus/check.sh does).
            include = os.path.join(os.path.dirname(path), "include")
            flags = ["-I", include] if os.path.isdir(include) else []
            p = subprocess.run([args.stereoshift, "verify", "--json"] + mode_flags + args.verify_arg + flags + [path], capture_output=True,
                               text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            perspective += 1
            cannot_run["timed out"] += 1
            if args.verbose:
                print(f"{rel}: cannot run: timed out")
            continue
        result = None
        try:
            result = json.loads(p.stdout) if p.stdout.strip() else None
        except json.JSONDecodeError:
            result = None
        if result is not None and result.get("verified") is False:
            other[result.get("classification", "?")] += 1
            if args.verbose:
                print(f"{rel}: {result.get('classification')}: nothing injected")
            continue
        if result is None and mode_flags and f"{mode_flags[0]} {mode}:" in p.stderr:
            key = reason_key(p.stderr)
            refused[key] += 1
            if args.verbose:
                print(f"{rel}: refused: {p.stderr.strip().splitlines()[0]}")
            continue
        if result is not None and result.get("shifted") is False:
            # Instanced mode rewrites 2D vertex shaders too (eye routes, instance reads), without a shift.
            unshifted_ran += 1
            unshifted_passed += bool(result.get("ok"))
            if args.verbose:
                print(f"{rel}: {result.get('classification')}, no shift: "
                      + ("verified" if result.get("ok") else "FAILED: " + (result.get("problems") or ["?"])[0]))
            continue
        perspective += 1
        if result is None or result.get("ran") is False:
            key = reason_key(p.stderr)
            cannot_run[key] += 1
            if args.verbose:
                print(f"{rel}: cannot run: {p.stderr.strip().splitlines()[0] if p.stderr.strip() else '?'}")
            continue
        ran += 1
        if result.get("ok"):
            passed += 1
            if args.verbose:
                print(f"{rel}: verified")
        else:
            problems = result.get("problems") or ["(no problem listed)"]
            failed[reason_key(problems[0])] += 1
            if args.verbose:
                print(f"{rel}: FAILED: {problems[0]}")

    pct = lambda n: f"{100.0 * n / perspective:.1f}%" if perspective else "-"
    print(f"pre-rasterization shaders: {len(shaders)} "
          f"(not shifted: {sum(other.values())}: " + ", ".join(f"{k} {v}" for k, v in sorted(other.items())) + ")")
    if mode != "two-pass":
        print(f"refused in {mode} mode: {sum(refused.values())} (not run; by the conversion's reason)")
        for k, v in refused.most_common():
            print(f"  {v:3d}  {k}")
    if unshifted_ran:
        print(f"rewritten without a shift: {unshifted_ran} (2D vertex shaders), pass: {unshifted_passed}")
    print(f"get the shift:             {perspective}")
    print(f"verify runs:               {ran} ({pct(ran)})")
    print(f"verify passes:             {passed} ({pct(passed)})")
    if cannot_run:
        print("cannot run, by reason:")
        for k, v in cannot_run.most_common():
            print(f"  {v:3d}  {k}")
    if failed:
        print("ran but failed, by first problem:")
        for k, v in failed.most_common():
            print(f"  {v:3d}  {k}")



def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--stereoshift", default=os.path.join(here, "..", "..", "build", "stereoshift"))
    ap.add_argument("--root", action="append", help="a shader tree (repeatable); default: corpus and shaders/verify")
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("-v", "--verbose", action="store_true", help="one line per shader")
    ap.add_argument("--eye-source", action="append", choices=["two-pass", "multiview", "instanced"],
                    help="mode to verify in (repeatable); default two-pass")
    ap.add_argument("--verify-arg", action="append", default=[],
                    help="one more argument for every verify call (repeatable: --verify-arg=--target --verify-arg=spirv)")
    args = ap.parse_args()
    roots = args.root or [os.path.join(here, "..", "..", "corpus"), os.path.join(here, "shaders", "verify")]

    shaders = []  # (root, path)
    for root in roots:
        found = []
        for dirpath, dirs, files in os.walk(root):
            dirs[:] = [d for d in dirs if d != "include"]  # include/ folders hold headers, not shaders
            for f in sorted(files):
                if stage_of(f):
                    found.append((root, os.path.join(dirpath, f)))
        shaders += sorted(found)

    for mode in args.eye_source or ["two-pass"]:
        if len(args.eye_source or []) > 1:
            print(f"--- {mode}")
        measure(args, shaders, mode)
    return 0


if __name__ == "__main__":
    sys.exit(main())
