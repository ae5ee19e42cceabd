#!/usr/bin/env python3
"""Complexity benchmark: how conversion time and memory grow with the size and shape of a shader
(a benchmark, not a test: it prints figures and exits 0 whatever they are).

Each axis generates shaders at 1x, 4x, 16x and 64x of a base size and converts each with the tool
(one process per conversion, same-language output). Printed per run: the SPIR-V instructions of the
shader (from a separate, untimed `--target spirv` conversion), the conversion's CPU seconds and peak
resident memory (from the child's rusage, so a busy machine's waiting is not counted), and both per
instruction. Below each axis, the growth: the CPU time each added KiB of source costs from 16x to
64x over what it costs from 1x to 16x (the process's fixed start-up cost cancels out; linear work
gives 1, quadratic about 4.5 for these scales). The aim is <= 2.

Axes (what real shaders do at scale):
  statements     one long function of plain statements (GLSL and HLSL; HLSL's entry point is a helper)
  shared-subexpr a chain `s1 = s0 * s0 + s0; s2 = s1 * s1 + s1; ...` in a helper (value numbering)
  nesting        nested `if`s (capped at the source limits' nesting depth)
  outputs        outputs that copy or derive from the clip position (halo analysis per output)
  techniques     entry points and techniques in one effect file (.fx)
  include-fanout a shader including many small files, each with a helper it calls

  bench/complexity_bench.py [--stereoshift build/stereoshift] [--axes a,b] [--scales 1,4,16,64]
                            [--reps 3] [--work-dir DIR] [--json FILE]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT_ROOT = os.path.dirname(HERE)
AIM_RATIO = 2.0
MAX_NESTING = 120  # below the front end's 128-level limit


def statements_glsl(scale):
    n = 64 * scale
    body = "\n".join(f"    x = x * 1.0001 + u.y.{'xyzw'[i % 4]};" for i in range(n))
    return "statements.vert", f"""#version 450
layout(set = 0, binding = 0) uniform U {{ mat4 mvp; vec4 y; }} u;
layout(location = 0) in vec3 p;
void main() {{
    float x = p.x;
{body}
    gl_Position = u.mvp * vec4(p.x + x * 1e-30, p.yz, 1.0);
}}
""", {}


def statements_hlsl(scale):
    n = 64 * scale
    body = "\n".join(f"    x = x * 1.0001 + y.{'xyzw'[i % 4]};" for i in range(n))
    return "statements.vert.hlsl", f"""cbuffer C : register(b0) {{ float4x4 mvp; float4 y; }};
float4 main(float3 p : POSITION) : SV_Position {{
    float x = p.x;
{body}
    return mul(mvp, float4(p.x + x * 1e-30, p.yz, 1));
}}
""", {}


def shared_subexpr(scale):
    n = 8 * scale
    chain = "\n".join(f"    float s{i} = s{i - 1} * s{i - 1} + s{i - 1};" for i in range(1, n + 1))
    return "shared.vert.hlsl", f"""cbuffer C : register(b0) {{ float4x4 mvp; float4 wind; }};
float3 sway(float3 p) {{
    float s0 = sin(p.x + wind.w) * wind.z;
{chain}
    return p + float3(wind.xy, 0) * frac(s{n});
}}
float4 main(float3 p : POSITION, out float4 clipCopy : TEXCOORD0) : SV_Position {{
    float4 pos = mul(mvp, float4(sway(p), 1));
    clipCopy = pos;
    return pos;
}}
""", {}


def nesting(scale):
    depth = min(2 * scale, MAX_NESTING)
    opening = "".join(f"{'    ' * (i + 1)}if (p.x > {i}.0) {{\n{'    ' * (i + 2)}x += {i}.5;\n" for i in range(depth))
    closing = "".join(f"{'    ' * (i + 1)}}}\n" for i in reversed(range(depth)))
    return "nesting.vert", f"""#version 450
layout(set = 0, binding = 0) uniform U {{ mat4 mvp; }} u;
layout(location = 0) in vec3 p;
void main() {{
    float x = 0.0;
{opening}{closing}    gl_Position = u.mvp * vec4(p + vec3(x * 1e-30), 1.0);
}}
""", {}


def outputs(scale):
    n = min(scale // 2 + 1, 30)  # location limit: outputs are vec4 varyings
    decls = "\n".join(f"layout(location = {i}) out vec4 v{i};" for i in range(n))
    writes = "\n".join(f"    v{i} = clip * {1.0 + i * 0.25};" if i % 2 else f"    v{i} = clip;" for i in range(n))
    return "outputs.vert", f"""#version 450
layout(set = 0, binding = 0) uniform U {{ mat4 mvp; }} u;
layout(location = 0) in vec3 p;
{decls}
void main() {{
    vec4 clip = u.mvp * vec4(p, 1.0);
{writes}
    gl_Position = clip;
}}
""", {}


def techniques(scale):
    n = 2 * scale
    parts = ["cbuffer PerFrame : register(b0) { float4x4 g_ViewProj; float4 g_Offset; };"]
    for i in range(n):
        parts.append(f"float4 VS_{i}(float3 p : POSITION) : SV_Position {{ return mul(float4(p + g_Offset.xyz * {i}.0, 1), g_ViewProj); }}")
        parts.append(f"float4 PS_{i}() : SV_Target {{ return g_Offset * {i}.0; }}")
        parts.append(f"technique10 T{i} {{ pass P0 {{ SetVertexShader(CompileShader(vs_4_0, VS_{i}())); "
                     f"SetPixelShader(CompileShader(ps_4_0, PS_{i}())); }} }}")
    return "effect.vert.fx", "\n".join(parts) + "\n", {}


def include_fanout(scale):
    n = 2 * scale
    includes = {f"inc/part{i}.glsl": f"vec3 part{i}(vec3 q) {{ return q * {1.0 + i * 0.001}; }}\n" for i in range(n)}
    lines = "\n".join(f'#include "inc/part{i}.glsl"' for i in range(n))
    calls = "\n".join(f"    q = part{i}(q);" for i in range(n))
    return "fanout.vert", f"""#version 450
#extension GL_GOOGLE_include_directive : require
{lines}
layout(set = 0, binding = 0) uniform U {{ mat4 mvp; }} u;
layout(location = 0) in vec3 p;
void main() {{
    vec3 q = p;
{calls}
    gl_Position = u.mvp * vec4(q, 1.0);
}}
""", includes


AXES = {
    "statements-glsl": statements_glsl,
    "statements-hlsl": statements_hlsl,
    "shared-subexpr": shared_subexpr,
    "nesting": nesting,
    "outputs": outputs,
    "techniques": techniques,
    "include-fanout": include_fanout,
}


def write_case(directory, name, text, includes):
    os.makedirs(directory, exist_ok=True)
    for rel, body in includes.items():
        os.makedirs(os.path.join(directory, os.path.dirname(rel)), exist_ok=True)
        with open(os.path.join(directory, rel), "w") as f:
            f.write(body)
    path = os.path.join(directory, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def run_measured(command):
    """Runs `command`; returns (exit status, CPU seconds, peak resident MiB) of that child alone."""
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    process.returncode = os.waitstatus_to_exitcode(status)
    stderr = process.stderr.read().decode(errors="replace")
    process.stderr.close()
    # The tool converts in a child of its own: the grandchild's time is in ru_*time of the child
    # once it has reaped it, and ru_maxrss is the largest of the two processes.
    return process.returncode, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0, stderr


def spirv_instructions(path):
    with open(path, "rb") as f:
        data = f.read()
    words = [int.from_bytes(data[i:i + 4], "little") for i in range(0, len(data) - 3, 4)]
    count, at = 0, 5
    while at < len(words):
        length = words[at] >> 16
        if length == 0:
            break
        count += 1
        at += length
    return count


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--stereoshift", default=os.path.join(PROJECT_ROOT, "build", "stereoshift"))
    parser.add_argument("--axes", default=",".join(AXES))
    parser.add_argument("--scales", default="1,4,16,64")
    parser.add_argument("--reps", type=int, default=3, help="conversions per shader; the least CPU time counts")
    parser.add_argument("--work-dir")
    parser.add_argument("--json")
    args = parser.parse_args()
    if not os.access(args.stereoshift, os.X_OK):
        print(f"complexity_bench: no tool at {args.stereoshift}", file=sys.stderr)
        return 2
    scales = [int(s) for s in args.scales.split(",")]
    work = args.work_dir or tempfile.mkdtemp(prefix="complexity_bench.")
    results = {}
    print(f"{'axis':16} {'scale':>5} {'src KiB':>8} {'instr':>8} {'cpu s':>8} {'us/instr':>9} {'peak MiB':>9} {'KiB/instr':>9}")
    for axis in args.axes.split(","):
        rows = []
        for scale in scales:
            name, text, includes = AXES[axis](scale)
            directory = os.path.join(work, axis, str(scale))
            shutil.rmtree(directory, ignore_errors=True)
            source = write_case(directory, name, text, includes)
            spv = os.path.join(directory, "count.spv")
            counted = subprocess.run([args.stereoshift, source, "--target", "spirv", "-o", spv],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            instructions = spirv_instructions(spv) if counted.returncode == 0 else 0
            out = os.path.join(directory, "out", name)
            status, cpu, peak, stderr = run_measured([args.stereoshift, source, "-o", out])
            for _ in range(args.reps - 1):
                if status != 0:
                    break
                status, again, again_peak, stderr = run_measured([args.stereoshift, source, "-o", out])
                cpu, peak = min(cpu, again), max(peak, again_peak)
            if status != 0 or instructions == 0:
                print(f"{axis:16} {scale:>5} failed: {(stderr or counted.stderr.decode()).strip()[:200]}")
                rows.append({"scale": scale, "failed": True})
                continue
            per = cpu * 1e6 / instructions
            kib = (len(text) + sum(len(b) for b in includes.values())) / 1024.0
            rows.append({"scale": scale, "source_kib": kib, "instructions": instructions, "cpu_seconds": cpu,
                         "peak_mib": peak, "us_per_instruction": per, "kib_per_instruction": peak * 1024 / instructions})
            print(f"{axis:16} {scale:>5} {kib:>8.1f} {instructions:>8} {cpu:>8.3f} {per:>9.1f} {peak:>9.1f} "
                  f"{peak * 1024 / instructions:>9.2f}")
        measured = [r for r in rows if not r.get("failed")]
        if len(measured) >= 3:
            first, middle, last = measured[0], measured[len(measured) // 2], measured[-1]

            def slope(a, b):
                return max(b["cpu_seconds"] - a["cpu_seconds"], 1e-3) / max(b["source_kib"] - a["source_kib"], 1e-3)

            growth = slope(middle, last) / slope(first, middle)
            verdict = "linear" if growth <= AIM_RATIO else "GROWS"
            print(f"{axis:16} growth: s per KiB {middle['scale']}x-{last['scale']}x / {first['scale']}x-"
                  f"{middle['scale']}x = {growth:.2f} (aim <= {AIM_RATIO}: {verdict})")
            results[axis] = {"runs": rows, "growth": growth}
        else:
            results[axis] = {"runs": rows}
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1, sort_keys=True)
    if not args.work_dir:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
