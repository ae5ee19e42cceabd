#!/usr/bin/env python3
"""Coverage on generated game dumps: a measure, not a test.

Writes N vertex-shader dumps in 3Dmigoto's decompiler's conventions with the fuzz target's own
generator (fuzz_decompiled_dump, sanitizer tree: FUZZ_DUMP_SHOW=1 prints each dump it writes), from
byte strings of a fixed-seed generator, as a ShaderFixes/ folder (`<16 hex>-vs_replace.txt`). Then:

  1. `stereoshift build` over the folder (the dump's default eye source, 3Dmigoto's t125): how many
     convert, how many are refused, how many are lost to a crash ("crashed" in the log);
  2. `stereoshift verify` on each (lavapipe, with a uniform block in place of the texture): mono bit for
     bit, the stereo x within its bound, other outputs unchanged.

  python3 test/fuzz/dump_coverage.py --stereoshift build/stereoshift \\
      --generator build-sanitize/test/fuzz/fuzz_decompiled_dump [--count 200] [--seed 2026] [--work DIR]

Exit status 0 whatever the figures (77 without the generator)."""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile


def write_dumps(generator, count, seed, folder):
    chooser = random.Random(seed)
    env = dict(os.environ, FUZZ_DUMP_SHOW="1", ASAN_OPTIONS="detect_leaks=0")
    for i in range(count):
        # Vertex shaders (even setup byte), every eye-source choice of the target.
        data = bytes([chooser.choice([0, 2, 4, 6, 8, 10])]) + bytes(chooser.randrange(256) for _ in range(300))
        with tempfile.NamedTemporaryFile(delete=False) as f:
            f.write(data)
        try:
            shown = subprocess.run([generator, "-runs=1", f.name], env=env, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.PIPE, text=True, errors="replace").stderr
        finally:
            os.unlink(f.name)
        start = shown.find("// ---- Created with 3Dmigoto")
        end = shown.find("\n--- ", start)
        if start < 0 or end < 0:
            sys.exit(f"dump_coverage: the generator printed no dump for input {i}")
        with open(os.path.join(folder, f"{0x1000 + i:016x}-vs_replace.txt"), "w") as out:
            out.write(shown[start:end + 1])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stereoshift", required=True)
    parser.add_argument("--generator", required=True)
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    if not os.access(args.generator, os.X_OK):
        print(f"dump_coverage: no generator at {args.generator} (build the sanitizer tree's fuzz_decompiled_dump)")
        return 77
    work = args.work or tempfile.mkdtemp(prefix="dump-coverage-")
    folder, out = os.path.join(work, "ShaderFixes"), os.path.join(work, "out")
    shutil.rmtree(folder, ignore_errors=True)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(folder)
    write_dumps(args.generator, args.count, args.seed, folder)

    built = subprocess.run([args.stereoshift, "build", folder, "-o", out], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
    crashed = len(re.findall(r": error: .*crashed", built.stdout))
    summary = re.search(r"(\d+) converted", built.stdout)
    converted = int(summary.group(1)) if summary else 0
    print(f"{args.count} generated dumps (seed {args.seed}): {converted} converted, "
          f"{args.count - converted - crashed} refused, {crashed} lost to a crash")

    verified, failures = 0, []
    for name in sorted(os.listdir(folder)):
        run = subprocess.run([args.stereoshift, "verify", os.path.join(folder, name)], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
        if run.returncode == 0:
            verified += 1
        else:
            lines = run.stdout.splitlines()
            problem = next((line.strip() for line in lines if "problem:" in line),
                           next((line.strip() for line in lines if ": error:" in line), "failed"))
            failures.append(f"{name}: {problem}")
    print(f"verify: {verified} of {args.count} pass")
    for failure in failures:
        print("  " + failure)
    print(f"(dumps and outputs under {work})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
