#!/usr/bin/env python3
"""integration.bazel_example: builds a copy of examples/bazel with Bazel and checks what the rule set
promises.

- With the persistent worker (the actions' default strategy) and without it (sandboxed): one action
  per pipeline and one per shader of a `pipeline = False` target, every output byte-identical to the
  CLI's on the same command line.
- After an edit of the include two pipelines share, exactly those two pipelines rerun (read from
  Bazel's --execution_log_json_file), in both modes.
- A shader that #includes a file its target does not declare fails: under the worker by the tool's
  own check, in the sandbox because the file is not there.

Offline: the workspace has no external repositories. Exits 77 (ctest SKIP_RETURN_CODE) when bazel is
not installed. Scratch files (and Bazel's output root) go under --work-dir only.
"""
import os
import shutil
import subprocess
import sys
import time

from bazel_support import (PIPELINES, SINGLE_SHADERS, SHARED_INCLUDE, SKIP, USERS_OF_SHARED_INCLUDE, Bazel, check,
                           edit_shared_include, parse_arguments, pipelines_run)



def compare_with_cli(tool, workspace, bin_dir, cli_dir):
    """Runs the CLI on each pipeline in the workspace and compares every output with Bazel's."""
    shutil.rmtree(cli_dir, ignore_errors=True)
    bin_relative = os.path.relpath(bin_dir, os.path.realpath(os.path.join(bin_dir, "../../..")))
    for name, (stages, options) in PIPELINES.items():
        out = os.path.join(cli_dir, name)
        args = [a.format(bin=bin_relative) for a in options]
        p = subprocess.run([tool] + args + ["--pipeline", ",".join(stages), "-o", out], cwd=workspace,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        check(p.returncode == 0, f"the CLI failed on {name}:\n{p.stdout}")
        for stage in stages:
            file = os.path.basename(stage)
            with open(os.path.join(out, file), "rb") as a, open(os.path.join(bin_dir, name, file), "rb") as b:
                check(a.read() == b.read(), f"{name}/{file}: Bazel's output differs from the CLI's")
    for name, shaders in SINGLE_SHADERS.items():
        for shader in shaders:
            out = os.path.join(cli_dir, name, os.path.basename(shader))
            p = subprocess.run([tool, shader, "-o", out], cwd=workspace, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
            check(p.returncode == 0, f"the CLI failed on {shader}:\n{p.stdout}")
            with open(out, "rb") as a, open(os.path.join(bin_dir, name, os.path.basename(shader)), "rb") as b:
                check(a.read() == b.read(), f"{name}/{os.path.basename(shader)}: Bazel's output differs from the CLI's")


def main():
    args = parse_arguments(__doc__)
    if args is None:
        return SKIP

    total_started = time.monotonic()
    args.work_dir = os.path.abspath(args.work_dir)
    tool = os.path.abspath(args.stereoshift)
    workspace = os.path.join(args.work_dir, "workspace")
    shutil.rmtree(workspace, ignore_errors=True)
    shutil.copytree(args.example, workspace)
    bazel = Bazel(args.bazel, workspace, os.path.join(args.work_dir, "output_root"), tool, os.path.abspath(args.rules))
    logs = os.path.join(args.work_dir, "logs")
    os.makedirs(logs, exist_ok=True)
    timings = []
    try:
        _, seconds = bazel.run("info", "output_base")  # starts the server (Debian's build has no `version`)
        timings.append(("server start", seconds))
        # A clean start: an earlier run's outputs would make this run's first build a no-op.
        _, seconds = bazel.run("clean")
        timings.append(("clean", seconds))
        p, seconds = bazel.run("info", *bazel.flags, "bazel-bin")
        timings.append(("info", seconds))
        bin_dir = p.stdout.strip().splitlines()[-1]

        for mode, flags in (("worker", []), ("sandboxed", ["--strategy=StereoshiftConvert=sandboxed"])):
            if mode != "worker":
                _, seconds = bazel.run("clean")
                timings.append(("clean", seconds))
            _, seconds, spawns = bazel.build(os.path.join(logs, mode + "-clean.json"), *flags)
            timings.append((f"{mode}: clean build", seconds))
            check(pipelines_run(spawns) == set(PIPELINES) | set(SINGLE_SHADERS),
                  f"{mode}: the clean build ran {sorted(pipelines_run(spawns))}")
            check(len(spawns) == len(PIPELINES) + sum(len(s) for s in SINGLE_SHADERS.values()),
                  f"{mode}: the clean build ran {len(spawns)} conversions")
            runners = {s.get("runner", "") for s in spawns}
            if mode == "worker":
                check(runners == {"worker"}, f"the conversions ran on {runners}, not the persistent worker")
            else:
                check(all("sandbox" in r for r in runners), f"the conversions ran on {runners}, not in a sandbox")
            compare_with_cli(tool, workspace, bin_dir, os.path.join(args.work_dir, "cli"))

            _, seconds, spawns = bazel.build(os.path.join(logs, mode + "-noop.json"), *flags)
            timings.append((f"{mode}: no-op build", seconds))
            check(not spawns, f"{mode}: a no-op build reran {sorted(pipelines_run(spawns))}")

            # An edit that changes the shaders' outputs (a touch that keeps the bytes is no change to Bazel).
            edit_shared_include(workspace)
            _, seconds, spawns = bazel.build(os.path.join(logs, mode + "-include.json"), *flags)
            timings.append((f"{mode}: rebuild after the include", seconds))
            check(pipelines_run(spawns) == USERS_OF_SHARED_INCLUDE,
                  f"{mode}: after editing {SHARED_INCLUDE} the build reran {sorted(pipelines_run(spawns))}, "
                  f"not exactly {sorted(USERS_OF_SHARED_INCLUDE)}")
            compare_with_cli(tool, workspace, bin_dir, os.path.join(args.work_dir, "cli"))

        # An include the target does not declare.
        leak = os.path.join(workspace, "undeclared")
        os.makedirs(leak)
        open(os.path.join(leak, "secret.glsl"), "w").write("const float SECRET_SCALE = 2.0;\n")
        open(os.path.join(leak, "leak.vert"), "w").write(
            "#version 450\n#include \"secret.glsl\"\nlayout(location = 0) in vec3 inPosition;\n"
            "layout(set = 0, binding = 0) uniform Camera { mat4 viewProjection; } camera;\n"
            "void main() { gl_Position = camera.viewProjection * vec4(inPosition * SECRET_SCALE, 1.0); }\n")
        open(os.path.join(leak, "BUILD.bazel"), "w").write(
            'load("@stereoshift_rules//:stereoshift.bzl", "stereoshift_shaders")\n'
            'stereoshift_shaders(name = "leak", srcs = ["leak.vert"])\n')
        for mode, flags, expected in (
                ("worker", [], "secret.glsl: error: read by this action but not one of its declared inputs"),
                ("sandboxed", ["--strategy=StereoshiftConvert=sandboxed"], "Could not process include directive")):
            p, seconds, _ = bazel.build(os.path.join(logs, mode + "-undeclared.json"), *flags, "--keep_going", check=False)
            timings.append((f"{mode}: undeclared include", seconds))
            check(p.returncode != 0, f"{mode}: a target reading an undeclared include built:\n{p.stdout}")
            check(expected in p.stdout, f"{mode}: the failure does not say '{expected}':\n{p.stdout}")
    finally:
        _, seconds = bazel.run("shutdown", check=False)
        timings.append(("shutdown", seconds))

    for what, seconds in timings:
        print(f"{what:40s} {seconds:6.2f} s")
    print(f"{'total (with the server start)':40s} {time.monotonic() - total_started:6.2f} s")
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
