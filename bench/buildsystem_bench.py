#!/usr/bin/env python3
"""Build-system benchmark: one generated shader project built every way, side by side in one run
(a benchmark, not a test: the ratios are printed, never asserted).

The project: pipelines in the dialects and naming conventions of public samples (Vulkan GLSL 450
with a shared #include, LearnOpenGL-style GL 3.3 core .vs/.fs, ESSL 300 es, HLSL basicVS/basicPS,
GLSL 460 compute), every shader different. Built with, each clean (nothing built) and no-op (built
just before, nothing changed) and, for the CMake forms and `build`, after an edit to one shader:
  cmake+ninja            stereoshift_add_shaders(SOURCES ...), the default: one build step for the
                         target (`stereoshift build --files-from`, its cache, restat)
  cmake+ninja per pipeline          PER_PIPELINE: one command per pipeline, each its own process
                         (-DSTEREOSHIFT_USE_SERVICE=OFF)
  cmake+ninja per pipeline+service  the same commands through the conversion service; the clean
                         build starts with no server running, so the server's start is in it
  stereoshift build      one `stereoshift build <tree> -o <dir>` (its own warm workers, its cache)
  glslang|spirv-cross    per file, glslangValidator to SPIR-V then spirv-cross back, from a Ninja
                         file: what a project does without stereoshift (no stereo work at all)
All with -j JOBS (default: the machine's cores).

  bench/buildsystem_bench.py [--stereoshift build/stereoshift] [--pipelines-per-dialect 36]
                             [--reps 1] [--jobs N] [--work-dir DIR] [--json FILE]

Exit status 0 whatever the ratios are; non-zero only when a tool is missing or a build fails.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT_ROOT = os.path.dirname(HERE)

# The aims, printed beside the measured ratios.
AIM_CMAKE_OVER_BUILD = 1.5  # cmake+ninja (the default form) at most this many times `stereoshift build`
AIM_NOOP_PERCENT = 2.0  # a no-op build at most this share of its clean build


# ---------------------------------------------------------------------------------------------------
# The generated project
# ---------------------------------------------------------------------------------------------------

def vulkan_pipeline(i):
    vert = f"""#version 450
#extension GL_GOOGLE_include_directive : require
#include "camera.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUV;
layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec2 outUV;
layout(push_constant) uniform Push {{ mat4 model; }} push;
void main() {{
  vec4 world = push.model * vec4(inPosition * {1.0 + i * 0.01:.3f}, 1.0);
  outNormal = mat3(push.model) * inNormal;
  outUV = inUV * {1 + i % 7}.0;
  gl_Position = camera.viewProj * world;
}}
"""
    frag = f"""#version 450
layout(set = 1, binding = 0) uniform sampler2D albedo{i};
layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main() {{
  float light = max(dot(normalize(inNormal), normalize(vec3(0.3, {0.5 + i * 0.01:.3f}, 0.8))), 0.1);
  outColor = texture(albedo{i}, inUV) * light;
}}
"""
    return {f"vulkan/mesh{i:03d}.vert": vert, f"vulkan/mesh{i:03d}.frag": frag}


def opengl_pipeline(i):
    vs = f"""#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec2 aTexCoords;
out vec2 TexCoords;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
void main() {{
  TexCoords = aTexCoords * {1 + i % 5}.0;
  gl_Position = projection * view * model * vec4(aPos + vec3({i * 0.01:.3f}), 1.0);
}}
"""
    fs = f"""#version 330 core
out vec4 FragColor;
in vec2 TexCoords;
uniform sampler2D texture{i};
void main() {{ FragColor = texture(texture{i}, TexCoords) * {0.5 + i * 0.005:.3f}; }}
"""
    return {f"opengl/{i // 10}.{i % 10}.lesson.vs": vs, f"opengl/{i // 10}.{i % 10}.lesson.fs": fs}


def es_pipeline(i):
    vert = f"""#version 300 es
in vec4 a_position;
in vec2 a_texCoord;
out vec2 v_texCoord;
uniform mat4 u_mvpMatrix;
void main() {{
  v_texCoord = a_texCoord + vec2({i * 0.01:.3f});
  gl_Position = u_mvpMatrix * a_position;
}}
"""
    frag = f"""#version 300 es
precision mediump float;
in vec2 v_texCoord;
out vec4 o_fragColor;
uniform sampler2D s_texture;
void main() {{ o_fragColor = texture(s_texture, v_texCoord) * {0.25 + i * 0.01:.3f}; }}
"""
    return {f"es/sprite{i:03d}.vert": vert, f"es/sprite{i:03d}.frag": frag}


def hlsl_pipeline(i):
    vs = f"""cbuffer PerObject : register(b0) {{ float4x4 worldViewProj; float4 tint{i}; }};
struct VSOut {{ float4 pos : SV_Position; float4 color : COLOR0; }};
VSOut main(float3 pos : POSITION, float4 color : COLOR0) {{
  VSOut o;
  o.pos = mul(worldViewProj, float4(pos * {1.0 + i * 0.01:.3f}, 1.0));
  o.color = color * tint{i};
  return o;
}}
"""
    ps = f"""float4 main(float4 pos : SV_Position, float4 color : COLOR0) : SV_Target {{
  return color * {0.5 + i * 0.01:.3f};
}}
"""
    return {f"hlsl/pass{i:03d}ColorVS.hlsl": vs, f"hlsl/pass{i:03d}ColorPS.hlsl": ps}


def compute_shader(i):
    comp = f"""#version 460
layout(local_size_x = {32 + 32 * (i % 4)}) in;
layout(set = 0, binding = 0, std430) buffer Particles {{ vec4 positions[]; }};
void main() {{ positions[gl_GlobalInvocationID.x] += vec4({i * 0.001:.4f}); }}
"""
    return {f"compute/particles{i:03d}.comp": comp}


CAMERA_HEADER = """#ifndef CAMERA_GLSL
#define CAMERA_GLSL
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; vec3 eye; } camera;
#endif
"""

# The stage of each generated file, for the glslangValidator baseline (glslangValidator -S).
STAGE_OF_SUFFIX = {".vert": "vert", ".frag": "frag", ".vs": "vert", ".fs": "frag", ".comp": "comp",
                   "VS.hlsl": "vert", "PS.hlsl": "frag"}


def generate_project(root, per_dialect, stereoshift):
    shaders = {}
    for i in range(per_dialect):
        for make in (vulkan_pipeline, opengl_pipeline, es_pipeline, hlsl_pipeline):
            shaders.update(make(i))
    for i in range(per_dialect // 2):
        shaders.update(compute_shader(i))
    source = os.path.join(root, "shaders")
    for rel, text in shaders.items():
        path = os.path.join(source, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
    os.makedirs(os.path.join(root, "include"), exist_ok=True)
    with open(os.path.join(root, "include", "camera.glsl"), "w") as f:
        f.write(CAMERA_HEADER)
    # The module straight from this checkout, with the binary under test as stereoshift::stereoshift.
    with open(os.path.join(root, "CMakeLists.txt"), "w") as f:
        f.write(f"""cmake_minimum_required(VERSION 3.20)
project(buildsystem_bench NONE)
add_executable(stereoshift::stereoshift IMPORTED)
set_target_properties(stereoshift::stereoshift PROPERTIES IMPORTED_LOCATION "{stereoshift}")
include("{PROJECT_ROOT}/cmake/StereoshiftShaders.cmake")
file(GLOB_RECURSE bench_shaders CONFIGURE_DEPENDS "${{CMAKE_CURRENT_SOURCE_DIR}}/shaders/*")
if(BENCH_PER_PIPELINE)
  set(form PER_PIPELINE)
endif()
stereoshift_add_shaders(bench_shaders SOURCES ${{bench_shaders}} BASE_DIR shaders OUTPUT_DIR stereo
                        INCLUDE_DIRS include ${{form}})
""")
    return sorted(shaders)


def baseline_ninja(root, shaders, glslang, spirv_cross):
    """A build.ninja converting every shader with glslangValidator then spirv-cross, as a project
    without stereoshift would: GLSL back to its own version, HLSL back to HLSL 5.0."""
    lines = [
        "rule spirv\n  command = $glslang $flags -o $out $in\n",
        "rule cross\n  command = $spirv_cross $in $flags --output $out\n",
        f"glslang = {glslang}\nspirv_cross = {spirv_cross}\n",
    ]
    for rel in shaders:
        stage = next(s for suffix, s in STAGE_OF_SUFFIX.items() if rel.endswith(suffix))
        source = os.path.join(root, "shaders", rel)
        spirv = os.path.join("spv", rel + ".spv")
        output = os.path.join("out", rel)
        if rel.endswith(".hlsl"):
            to_spirv, back = f"-D -V -S {stage} -e main", "--hlsl --shader-model 50"
        elif rel.startswith("opengl/"):
            to_spirv, back = f"-G --auto-map-locations --auto-map-bindings -S {stage}", "--version 330"
        elif rel.startswith("es/"):
            to_spirv = f"-G --auto-map-locations --auto-map-bindings --glsl-version 310es -S {stage}"
            back = "--version 300 --es"
        else:
            to_spirv = f"-V -S {stage} -I{os.path.join(root, 'include')}"
            back = "--version 460 --vulkan-semantics" if rel.endswith(".comp") else "--version 450 --vulkan-semantics"
        lines.append(f"build {spirv}: spirv {source}\n  flags = {to_spirv}\n")
        lines.append(f"build {output}: cross {spirv}\n  flags = {back}\n")
    directory = os.path.join(root, "baseline")
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "build.ninja"), "w") as f:
        f.write("\n".join(lines))
    return directory


# ---------------------------------------------------------------------------------------------------
# Running
# ---------------------------------------------------------------------------------------------------

def timed(command, cwd=None, env=None):
    start = time.perf_counter()
    run = subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if run.returncode != 0:
        raise RuntimeError("%s failed (exit %d):\n%s%s" % (" ".join(map(str, command)), run.returncode,
                                                           run.stdout[-3000:], run.stderr[-3000:]))
    return seconds, run


def kill_servers(service_dir):
    """Ends the servers this benchmark started (their pid files are in its own service directory)."""
    for name in os.listdir(service_dir) if os.path.isdir(service_dir) else []:
        if name.endswith(".pid"):
            try:
                pid = int(open(os.path.join(service_dir, name)).read())
                if "stereoshift" in open(f"/proc/{pid}/cmdline").read():
                    os.kill(pid, 15)
            except (OSError, ValueError):
                pass


def print_results(samples, shaders, pipelines, args, identical):
    """The table of medians, the ratio against the aim, and whether the forms wrote the same bytes."""
    median = {key: statistics.median(values) for key, values in samples.items()}
    build_clean = median[("stereoshift build", "clean")]
    print(f"{len(shaders)} shaders in {pipelines} pipelines (GLSL 450 Vulkan, GL 3.3 core, ESSL 300, HLSL, "
          f"GLSL 460 compute); -j{args.jobs}; {args.reps} repetition(s), medians")
    print(f"{'variant':42s} {'clean s':>9s} {'x build':>8s} {'no-op s':>9s} {'no-op %':>8s} {'edit s':>8s}")
    for variant in ("cmake+ninja", "cmake+ninja per pipeline", "cmake+ninja per pipeline+service",
                    "cmake+ninja per pipeline+service (warm server)", "stereoshift build", "glslang|spirv-cross"):
        clean = median[(variant, "clean")]
        noop = median.get((variant, "no-op"))
        edit = median.get((variant, "edit"))
        noop_text = f"{noop:9.3f} {100 * noop / clean:7.1f}%" if noop is not None else f"{'':9s} {'':8s}"
        edit_text = f"{edit:8.3f}" if edit is not None else ""
        print(f"{variant:42s} {clean:9.2f} {clean / build_clean:7.2f}x {noop_text} {edit_text}")
    cmake_ratio = median[("cmake+ninja", "clean")] / build_clean
    print(f"aim: cmake+ninja within {AIM_CMAKE_OVER_BUILD}x of stereoshift build (clean): "
          f"{cmake_ratio:.2f}x; every no-op under {AIM_NOOP_PERCENT}% of its clean build")
    print(f"outputs of the three CMake forms byte-identical: {'yes' if identical else 'NO'}")
    return median


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stereoshift", default=os.path.join(PROJECT_ROOT, "build", "stereoshift"))
    parser.add_argument("--cmake", default=shutil.which("cmake"))
    parser.add_argument("--ninja", default=shutil.which("ninja"))
    parser.add_argument("--glslang", default=shutil.which("glslangValidator"))
    parser.add_argument("--spirv-cross", default=shutil.which("spirv-cross"))
    parser.add_argument("--pipelines-per-dialect", type=int, default=36)
    parser.add_argument("--reps", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--work-dir")
    parser.add_argument("--json")
    args = parser.parse_args()
    for tool in ("cmake", "ninja", "glslang", "spirv_cross"):
        if not getattr(args, tool):
            sys.exit(f"buildsystem_bench: {tool} not found")
    stereoshift = os.path.abspath(args.stereoshift)
    if not os.access(stereoshift, os.X_OK):
        sys.exit(f"buildsystem_bench: {stereoshift} is not an executable (build the stereoshift target)")

    # Short, so the service's socket path fits (Unix sockets: 107 bytes).
    work = args.work_dir or tempfile.mkdtemp(prefix="stbench-")
    os.makedirs(work, exist_ok=True)
    project = os.path.join(work, "project")
    shutil.rmtree(project, ignore_errors=True)
    shaders = generate_project(project, args.pipelines_per_dialect, stereoshift)
    pipelines = 4 * args.pipelines_per_dialect + args.pipelines_per_dialect // 2  # compute shaders stand alone
    baseline = baseline_ninja(project, shaders, args.glslang, args.spirv_cross)
    service_dir = os.path.join(work, "svc")
    env = {k: v for k, v in os.environ.items() if not k.startswith("STEREOSHIFT_")}
    env.update(STEREOSHIFT_SERVICE_DIR=service_dir, STEREOSHIFT_SERVICE_IDLE="30")

    trees = {}
    forms = (("cmake+ninja", "OFF", "OFF"), ("cmake+ninja per pipeline", "ON", "OFF"),
             ("cmake+ninja per pipeline+service", "ON", "ON"))
    for name, per_pipeline, use_service in forms:
        tree = os.path.join(work, name.replace("+", "_").replace(" ", "_"))
        shutil.rmtree(tree, ignore_errors=True)
        timed([args.cmake, "-S", project, "-B", tree, "-G", "Ninja", f"-DCMAKE_MAKE_PROGRAM={args.ninja}",
               f"-DBENCH_PER_PIPELINE={per_pipeline}", f"-DSTEREOSHIFT_USE_SERVICE={use_service}"], env=env)
        trees[name] = tree
    edited = os.path.join(project, "shaders", shaders[len(shaders) // 2])

    def edit_one_shader():
        """Appends a comment to one shader: new bytes, so every form has one pipeline to convert."""
        with open(edited, "a") as f:
            f.write("// edited\n")
    ninja = [args.ninja, f"-j{args.jobs}"]
    build_out = os.path.join(work, "build_out")

    samples = {}

    def record(variant, kind, seconds):
        samples.setdefault((variant, kind), []).append(seconds)

    try:
        for rep in range(args.reps):
            # Interleaved, so a change in the machine's load hits every variant alike.
            for name, _, _ in forms:
                timed(ninja + ["-t", "clean"], cwd=trees[name], env=env)
                # The one step's cache and outputs go too: a clean build converts everything.
                shutil.rmtree(os.path.join(trees[name], "stereo"), ignore_errors=True)
                kill_servers(service_dir)
                shutil.rmtree(service_dir, ignore_errors=True)
                record(name, "clean", timed(ninja, cwd=trees[name], env=env)[0])
                seconds, run = timed(ninja, cwd=trees[name], env=env)
                if "no work to do" not in run.stdout:
                    print(f"warning: {name}: the no-op build did work:\n{run.stdout[-500:]}", file=sys.stderr)
                record(name, "no-op", seconds)
                edit_one_shader()
                record(name, "edit", timed(ninja, cwd=trees[name], env=env)[0])
                if name == "cmake+ninja per pipeline+service":
                    # Once more with the server left running: what every later clean build costs.
                    timed(ninja + ["-t", "clean"], cwd=trees[name], env=env)
                    record(name + " (warm server)", "clean", timed(ninja, cwd=trees[name], env=env)[0])
            shutil.rmtree(build_out, ignore_errors=True)
            command = [stereoshift, "build", os.path.join(project, "shaders"), "-o", build_out, "-j", str(args.jobs),
                       "-I", os.path.join(project, "include")]
            record("stereoshift build", "clean", timed(command, env=env)[0])
            record("stereoshift build", "no-op", timed(command, env=env)[0])
            edit_one_shader()
            record("stereoshift build", "edit", timed(command, env=env)[0])
            shutil.rmtree(os.path.join(baseline, "spv"), ignore_errors=True)
            shutil.rmtree(os.path.join(baseline, "out"), ignore_errors=True)
            timed(ninja + ["-t", "clean"], cwd=baseline)
            record("glslang|spirv-cross", "clean", timed(ninja, cwd=baseline)[0])
            record("glslang|spirv-cross", "no-op", timed(ninja, cwd=baseline)[0])
    finally:
        kill_servers(service_dir)

    # Every form brought up to the last edit, then the same bytes from each (what the choice of form
    # relies on).
    for name, _, _ in forms:
        timed(ninja, cwd=trees[name], env=env)
    kill_servers(service_dir)
    def tree_bytes(tree):
        found = {}
        for root, _, files in os.walk(os.path.join(tree, "stereo")):
            for name in files:
                path = os.path.join(root, name)
                found[os.path.relpath(path, tree)] = open(path, "rb").read()
        return found
    one_step = tree_bytes(trees["cmake+ninja"])
    one_step.pop(os.path.join("stereo", "stereoshift-report.json"), None)
    one_step.pop(os.path.join("stereo", ".stereoshift-cache.msgpack"), None)
    identical = all(one_step == tree_bytes(trees[name]) for name, _, _ in forms[1:])

    median = print_results(samples, shaders, pipelines, args, identical)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"shaders": len(shaders), "pipelines": pipelines, "jobs": args.jobs, "reps": args.reps,
                       "identical": identical,
                       "seconds": {f"{v} {k}": s for (v, k), s in median.items()}}, f, indent=2)
    if not args.work_dir:
        shutil.rmtree(work, ignore_errors=True)
    return 0 if identical else 1


if __name__ == "__main__":
    sys.exit(main())
