#!/usr/bin/env python3
"""integration.persistent_worker: the real binary speaking Bazel's JSON worker protocol, no Bazel
needed. Requests in Bazel's form (an @params file, --declared-input=) convert byte-identically to the
plain CLI; a shader that crashes glslang costs its request an error response, and the next request
is served; an undeclared include fails its request and leaves no output; a plain `stereoshift @params`
(Bazel without the worker) behaves the same.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile


def check(condition, message):
    if not condition:
        sys.exit("FAIL: " + message)


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def params(path, args):
    write(path, "".join(a + "\n" for a in args))
    return "@" + path


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--stereoshift", required=True)
    args = parser.parse_args()
    tool = os.path.abspath(args.stereoshift)
    work = tempfile.mkdtemp(prefix="stereoshift_worker_cli_")
    try:
        os.chdir(work)
        write("shaders/include/camera.glsl",
              "layout(set = 0, binding = 0) uniform Camera { mat4 viewProjection; } camera;\n")
        write("shaders/lit.vert", "#version 450\n#include \"camera.glsl\"\n"
              "layout(location = 0) in vec3 inPosition;\n"
              "void main() { gl_Position = camera.viewProjection * vec4(inPosition, 1.0); }\n")
        write("shaders/lit.frag", "#version 450\nlayout(location = 0) out vec4 color;\nvoid main() { color = vec4(1.0); }\n")
        # glslang's HLSL parser overflows its stack on brackets nested this deep through macros.
        write("shaders/crasher.vert.hlsl", "#define A ((((((((((\n#define Z ))))))))))\n"
              "float4 main(float4 p : POSITION) : SV_Position {\n  return " + "A " * 1000 + "p" + " Z" * 1000 + ";\n}\n")
        stages = ["shaders/lit.vert", "shaders/lit.frag"]
        declared = ["--declared-input=" + s for s in stages]
        common = ["--target", "essl", "--pipeline", ",".join(stages)]

        p = subprocess.run([tool] + common + ["-o", "cli", "--depfile", "cli.d"], capture_output=True, text=True)
        check(p.returncode == 0, "the CLI failed:\n" + p.stderr)

        requests = [
            [params("p/ok", common + ["-o", "worker", "--depfile", "worker.d"] + declared
                    + ["--declared-input=shaders/include/camera.glsl"])],
            ["shaders/crasher.vert.hlsl", "-o", "crashed.vert"],
            [params("p/after", common + ["-o", "after", "--depfile", "after.d"])],
            [params("p/undeclared", common + ["-o", "undeclared", "--depfile", "undeclared.d"] + declared)],
            ["@p/missing"],
        ]
        stdin = "".join(json.dumps({"arguments": r, "requestId": i + 1}) + "\n" for i, r in enumerate(requests))
        p = subprocess.run([tool, "--persistent_worker"], input=stdin, capture_output=True, text=True, timeout=120)
        check(p.returncode == 0, f"the worker exited {p.returncode}:\n{p.stderr}")
        responses = [json.loads(line) for line in p.stdout.splitlines()]
        check([r.get("requestId") for r in responses] == [1, 2, 3, 4, 5], "responses: " + p.stdout)
        ok, crashed, after, undeclared, missing = responses

        check(ok["exitCode"] == 0, "the conversion failed in the worker: " + ok["output"])
        for out in ("worker", "after"):
            for stage in stages:
                name = os.path.basename(stage)
                check(open(f"cli/{name}", "rb").read() == open(f"{out}/{name}", "rb").read(),
                      f"{out}/{name} differs from the CLI's output")
        check(open("cli.d").read().split(":")[1] == open("worker.d").read().split(":")[1],
              "the worker's depfile lists other dependencies than the CLI's")
        check(crashed["exitCode"] == 1 and "crashed (signal 11, SIGSEGV)" in crashed["output"],
              "the crash was not reported: " + json.dumps(crashed))
        check(not os.path.exists("crashed.vert"), "a crashed conversion left an output")
        check(after["exitCode"] == 0, "the request after the crash failed: " + after["output"])
        check(undeclared["exitCode"] == 1 and "shaders/include/camera.glsl: error: read by this action but not one of "
              "its declared inputs" in undeclared["output"], "the undeclared include passed: " + json.dumps(undeclared))
        check(not os.path.exists("undeclared/lit.vert") and not os.path.exists("undeclared.d"),
              "a request that read an undeclared include left its outputs")
        check(missing["exitCode"] == 2 and "cannot read argument file 'p/missing'" in missing["output"],
              "a missing params file was not reported: " + json.dumps(missing))

        # Bazel without the worker runs `stereoshift @params` itself.
        p = subprocess.run([tool, params("p/plain", common + ["-o", "plain", "--depfile", "plain.d"] + declared)],
                           capture_output=True, text=True)
        check(p.returncode == 1 and "declared inputs" in p.stderr and not os.path.exists("plain/lit.vert"),
              f"plain @params run: exit {p.returncode}:\n{p.stderr}")
        p = subprocess.run([tool, "@p/ok"], capture_output=True, text=True)
        check(p.returncode == 0, "plain @params run failed:\n" + p.stderr)
    finally:
        os.chdir("/")
        shutil.rmtree(work, ignore_errors=True)
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
