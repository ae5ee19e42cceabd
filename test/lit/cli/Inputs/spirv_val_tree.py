#!/usr/bin/env python3
"""Runs spirv-val --target-env ENV on every SPIR-V file of a `stereoshift build` output tree and
checks the build's own errors: each is one of the refusals that say why no SPIR-V for ENV was
written. Usage: spirv_val_tree.py ENV OUT_DIR STDERR_FILE MIN_OUTPUTS"""
import os
import subprocess
import sys

REFUSALS = ("this is OpenGL GLSL (glslang takes it only under OpenGL's rules)",
            "glslang's SPIR-V for this shader does not validate",
            "the SPIR-V needs the relaxed block layout (VK_KHR_relaxed_block_layout")


def main():
    env, out, stderr, minimum = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    checked, bad = 0, []
    for root, _, files in os.walk(out):
        for name in sorted(files):
            if name.startswith(".stereoshift") or name.endswith(".json"):
                continue
            path = os.path.join(root, name)
            run = subprocess.run(["spirv-val", "--target-env", env, path], capture_output=True, text=True)
            checked += 1
            if run.returncode != 0:
                bad.append("%s: %s" % (path, (run.stdout + run.stderr).strip().splitlines()[0]))
    errors = [line for line in open(stderr, encoding="utf-8") if ": error: " in line]
    unexplained = [e for e in errors if not any(r in e for r in REFUSALS)]
    print("%d outputs validated for %s, %d invalid; %d shaders refused, %d without a known reason"
          % (checked, env, len(bad), len(errors), len(unexplained)))
    for line in bad + unexplained:
        print("  " + line.strip())
    return 0 if checked >= minimum and not bad and not unexplained else 1


if __name__ == "__main__":
    sys.exit(main())
