#!/usr/bin/env python3
"""Bazel in the build-system comparison: a benchmark, not a test (ratios measured side by side in one
run, printed, never asserted).

Rows, on one generated project (default 160 pipelines, 320 shaders, in GLSL, ESSL and HLSL, half of
them #including a shared file), the Bazel server already running and warmed by one unmeasured build
(its start is printed apart):
  stereoshift build          `stereoshift build <project> -o <fresh dir>`: the reference
  bazel + worker             `bazel clean; bazel build //...`: one stereoshift_shaders target per
                             pipeline, run by the persistent worker (the rule's default)
  bazel, no worker           the same with --strategy=StereoshiftConvert=sandboxed: a process per action
and a no-op build of each (the same command again).

  bench/bazel_bench.py [--stereoshift build/stereoshift] [--pipelines 160] [--work-dir DIR] [--json FILE]

For a combined table (bench/build_systems_bench.py or the like), call
    bazel_rows(tool, project_dir, pipelines, work_dir)
with the project's pipelines as (name, [stage paths relative to project_dir], [-I dirs]): it returns
{"bazel + worker": {"clean": s, "noop": s}, "bazel, no worker": {...}, "server start": s}, or None
when bazel is not installed. Nothing is downloaded: the generated workspace has no external
repositories beyond the local rules (bazel/) and the tool (stereoshift_local_tool).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT_ROOT = os.path.dirname(HERE)
RULES = os.path.join(PROJECT_ROOT, "bazel")

AIM_WORKER_OVER_BUILD = 2.0  # issue 15: Bazel with the worker within 2x of `stereoshift build`
AIM_NOOP_PERCENT = 2.0  # a no-op build at most this share of a clean one


def generate_project(root, pipelines):
    """Writes `pipelines` two-stage pipelines, a third each in GLSL (Vulkan), ESSL 3.00 and HLSL; every
    other pipeline #includes common/lighting.h. Returns [(name, [stages], [include dirs])]."""
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(os.path.join(root, "common"))
    with open(os.path.join(root, "common", "lighting.h"), "w") as f:
        f.write("#define LIGHT_COUNT 3\n#define AMBIENT 0.08\n")
    made = []
    for i in range(pipelines):
        dialect = ("glsl", "essl", "hlsl")[i % 3]
        shared = i % 2 == 0
        include = '#include "lighting.h"\n' if shared else "#define AMBIENT 0.1\n"
        scale = 1.0 + i / 1000.0
        name = f"{dialect}/p{i:04d}"
        os.makedirs(os.path.join(root, dialect), exist_ok=True)
        if dialect == "hlsl":
            stages = [name + "_vs.hlsl", name + "_ps.hlsl"]
            texts = [
                include + "cbuffer Frame : register(b0) { float4x4 ViewProjection; };\n"
                "struct VSOut { float4 position : SV_Position; float3 normal : NORMAL; };\n"
                "VSOut VSMain(float3 position : POSITION, float3 normal : NORMAL) {\n"
                f"  VSOut o; o.position = mul(ViewProjection, float4(position * {scale:.3f}, 1.0));\n"
                "  o.normal = normal; return o;\n}\n",
                include + "float4 PSMain(float4 position : SV_Position, float3 normal : NORMAL) : SV_Target {\n"
                f"  return float4(normalize(normal) * 0.5 + AMBIENT + {i % 7} * 0.01, 1.0);\n}}\n",
            ]
        else:
            version = "#version 300 es\nprecision highp float;\n" if dialect == "essl" else "#version 450\n"
            block = ("uniform Frame { mat4 viewProjection; } frame;\n" if dialect == "essl"
                     else "layout(set = 0, binding = 0) uniform Frame { mat4 viewProjection; } frame;\n")
            location = (lambda n: f"layout(location = {n}) ")
            stages = [name + ".vert", name + ".frag"]
            texts = [
                version + include + block + location(0) + "in vec3 inPosition;\n" + location(1) + "in vec3 inNormal;\n"
                + ("out vec3 vNormal;\n" if dialect == "essl" else location(0) + "out vec3 vNormal;\n")
                + f"void main() {{ vNormal = inNormal; gl_Position = frame.viewProjection * vec4(inPosition * {scale:.3f}, 1.0); }}\n",
                version + include + ("in vec3 vNormal;\n" if dialect == "essl" else location(0) + "in vec3 vNormal;\n")
                + location(0) + "out vec4 outColor;\n"
                + f"void main() {{ outColor = vec4(normalize(vNormal) * 0.5 + AMBIENT + {i % 7}.0 * 0.01, 1.0); }}\n",
            ]
        for stage, text in zip(stages, texts):
            with open(os.path.join(root, stage), "w") as f:
                f.write(text)
        made.append((name.replace("/", "_"), stages, ["common"] if shared else []))
    return made


def find_bazel():
    return shutil.which("bazel")


def _workspace(tool, project_dir, pipelines, workspace):
    """A Bazel workspace holding a copy of the project and one target per pipeline."""
    shutil.rmtree(workspace, ignore_errors=True)
    shutil.copytree(project_dir, workspace)
    with open(os.path.join(workspace, "WORKSPACE"), "w") as f:
        f.write('workspace(name = "stereoshift_bazel_bench")\n'
                f'local_repository(name = "stereoshift_rules", path = "{RULES}")\n'
                'load("@stereoshift_rules//:repositories.bzl", "stereoshift_local_tool")\n'
                f'stereoshift_local_tool(name = "stereoshift_tool", path = "{os.path.abspath(tool)}")\n')
    with open(os.path.join(workspace, ".bazelrc"), "w") as f:
        f.write("build --experimental_worker_allow_json_protocol\nbuild --symlink_prefix=/\n")
    lines = ['load("@stereoshift_rules//:stereoshift.bzl", "stereoshift_shaders")\n']
    for name, stages, includes in pipelines:
        hdrs = []
        for d in includes:
            for root, _, files in os.walk(os.path.join(project_dir, d)):
                hdrs += [os.path.relpath(os.path.join(root, n), project_dir) for n in sorted(files)]
        lines.append(f"stereoshift_shaders(name = {name!r}, srcs = {stages!r}, hdrs = {hdrs!r}, includes = {includes!r})\n")
    with open(os.path.join(workspace, "BUILD.bazel"), "w") as f:
        f.writelines(lines)


def bazel_rows(tool, project_dir, pipelines, work_dir, bazel=None):
    bazel = bazel or find_bazel()
    if not bazel:
        return None
    work_dir = os.path.abspath(work_dir)
    workspace = os.path.join(work_dir, "workspace")
    _workspace(tool, project_dir, pipelines, workspace)
    startup = [bazel, "--nohome_rc", "--output_user_root=" + os.path.join(work_dir, "output_root")]

    def run(*args):
        started = time.monotonic()
        p = subprocess.run(startup + list(args), cwd=workspace, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if p.returncode != 0:
            raise RuntimeError(f"bazel {' '.join(args)} failed:\n{p.stdout[-4000:]}")
        return time.monotonic() - started

    rows = {}
    try:
        rows["server start"] = run("info", "output_base")
        for row, flags in (("bazel + worker", []), ("bazel, no worker", ["--strategy=StereoshiftConvert=sandboxed"])):
            # A first build warms the server's JIT (as a developer's running server is); then the
            # measured clean build from scratch.
            run("clean")
            run("build", *flags, "//...")
            run("clean")
            clean = run("build", *flags, "//...")
            noop = run("build", *flags, "//...")
            rows[row] = {"clean": clean, "noop": noop}
    finally:
        subprocess.run(startup + ["shutdown"], cwd=workspace, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return rows


def stereoshift_build_rows(tool, project_dir, work_dir, include_dirs=("common",)):
    out = os.path.join(work_dir, "build_out")
    shutil.rmtree(out, ignore_errors=True)
    rows = {}
    for kind in ("clean", "noop"):
        started = time.monotonic()
        includes = [a for d in include_dirs for a in ("-I", os.path.join(project_dir, d))]
        p = subprocess.run([tool, "build", project_dir, "-o", out] + includes, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        rows[kind] = time.monotonic() - started
        if p.returncode != 0:
            raise RuntimeError("stereoshift build failed:\n" + p.stdout[-4000:])
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stereoshift", default=os.path.join(PROJECT_ROOT, "build", "stereoshift"))
    parser.add_argument("--pipelines", type=int, default=160)
    parser.add_argument("--work-dir", default=os.path.join(PROJECT_ROOT, "build", "bazel_bench"))
    parser.add_argument("--json")
    args = parser.parse_args()
    if not find_bazel():
        print("bazel is not installed (Debian: apt-get install bazel-bootstrap): nothing to measure")
        return 0
    work = os.path.abspath(args.work_dir)
    project = os.path.join(work, "project")
    pipelines = generate_project(project, args.pipelines)
    results = {"stereoshift build": stereoshift_build_rows(args.stereoshift, project, work)}
    results.update(bazel_rows(args.stereoshift, project, pipelines, work))
    build_clean = results["stereoshift build"]["clean"]
    print(f"{len(pipelines)} pipelines, {2 * len(pipelines)} shaders; {os.cpu_count()} cores; "
          f"load average {os.getloadavg()[0]:.1f}; Bazel server start {results['server start']:.2f} s (not counted)")
    print(f"{'':22s} {'clean':>9s} {'no-op':>9s} {'clean / build':>14s} {'no-op / clean':>14s}")
    for row in ("stereoshift build", "bazel + worker", "bazel, no worker"):
        r = results[row]
        print(f"{row:22s} {r['clean']:8.2f}s {r['noop']:8.2f}s {r['clean'] / build_clean:13.2f}x "
              f"{100 * r['noop'] / r['clean']:13.1f}%")
    print(f"aims: bazel + worker within {AIM_WORKER_OVER_BUILD}x of stereoshift build; no-op under {AIM_NOOP_PERCENT}% of clean")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
