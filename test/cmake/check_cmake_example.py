#!/usr/bin/env python3
"""integration.cmake_example: the installed CMake package and stereoshift_add_shaders() end to end.

Installs the stereoshift build under test into a fresh prefix, then, on a copy of
examples/cmake-project (the test edits its files, never the source tree), per generator
(Ninja, and Unix Makefiles where make exists):
  1. configures against that prefix (and checks that prefix's package was the one found);
  2. builds: every expected output exists, the list the example exposes is exactly those outputs,
     shifted stages carry the eye parameters, fragment stages do not, no output holds a path of
     the machine and every copy of the example (each at another path) gives the same bytes;
  3. builds again: nothing runs (Ninja says "no work to do"; no output is rewritten);
  4. touches the shared header: the target's one build step runs and converts nothing (the bytes are
     the same), no output is rewritten, and the next build has no work; then edits it: exactly the
     pipelines with a stage that includes it convert;
  5. edits one source of a pipeline without the header: exactly that pipeline converts, and only
     outputs whose bytes changed are rewritten.
Which pipelines converted is read from the step's report (entries not marked "cached").
The example's second target converts the same shaders through scene.toml (MANIFEST): its step must
run exactly when one of its inputs changed, and write the same bytes as the per-pipeline steps.
Also: the package from the build tree (export()), TARGET_LANGUAGE/DEFINES/OPTIONS reaching the
command line, a caller whose CMP0116 is OLD (no work on a second build), and argument errors.
Needs Python >= 3.11 (tomllib).

What is expected is derived from the copied example's files (which shaders exist, which ones
#include the header), not written down here.
"""
import argparse
import fnmatch
import json
import os
import re
import shutil
import subprocess
import sys
import time
import tomllib
from pathlib import Path

HEADER_NAME = "common.glsl"
# The stages that can be a pipeline's last pre-rasterization stage (mesh aside), which gets the shift.
SHIFTED_STAGES = {"vert", "tese", "geom"}
EYE_PARAMETERS = ("eyeSign", "separation", "convergence")
# The COMMENT of the SOURCES target's one build step, and of the MANIFEST target's.
STEP_RAN = "stereoshift: example_shaders:"
SCENE_RAN = "stereoshift: example_scene:"

failures = []
# Output bytes of each first build, by path under the output directory: every copy of the example
# sits at another absolute path, and the outputs must not differ (what a shared cache relies on).
first_build_outputs = {}


def check(condition, message):
    if not condition:
        failures.append(message)
        print(f"FAIL: {message}", flush=True)
    return condition


def run(command, cwd=None, expect_success=True):
    result = subprocess.run([str(c) for c in command], cwd=cwd, capture_output=True, text=True)
    if expect_success and result.returncode != 0:
        sys.exit(f"command failed ({result.returncode}): {' '.join(map(str, command))}\n"
                 f"{result.stdout}\n{result.stderr}")
    return result


def pipeline_key(relative_path):
    """The CLI's pipeline grouping: directory plus the file name up to its first dot."""
    return str(relative_path.parent / relative_path.name.split(".")[0]).removeprefix("./")


def stage_of(path):
    return path.name.split(".")[1]


class Example:
    """What the example's sources say the build must produce."""

    def __init__(self, source_dir, build_dir):
        self.source_dir = source_dir
        self.shader_dir = source_dir / "shaders"
        self.header = source_dir / "include" / HEADER_NAME
        self.sources = sorted(p for p in self.shader_dir.rglob("*") if p.is_file())
        self.output_of = {s: build_dir / "stereo" / s.relative_to(self.shader_dir) for s in self.sources}
        self.pipelines = {}
        for s in self.sources:
            self.pipelines.setdefault(pipeline_key(s.relative_to(self.shader_dir)), []).append(s)
        include = re.compile(r'^\s*#\s*include\s+"' + re.escape(HEADER_NAME) + '"', re.MULTILINE)
        self.including = {k for k, stages in self.pipelines.items()
                          if any(include.search(s.read_text()) for s in stages)}
        # The MANIFEST target: scene.toml's pipelines (names or globs), converted into stereo-scene/.
        manifest = tomllib.loads((source_dir / "scene.toml").read_text())
        patterns = [p for scene_pass in manifest["pass"] for p in scene_pass["pipelines"]]
        self.scene_pipelines = {k for k in self.pipelines if any(fnmatch.fnmatchcase(k, p) for p in patterns)}
        self.scene_report = build_dir / "stereo-scene" / "stereoshift-report.json"
        self.scene_output_of = {s: build_dir / "stereo-scene" / s.relative_to(self.shader_dir)
                                for k in self.scene_pipelines for s in self.pipelines[k]}

    def outputs(self, keys=None):
        keys = self.pipelines if keys is None else keys
        return {self.output_of[s] for k in keys for s in self.pipelines[k]}


def mtimes(paths):
    return {p: p.stat().st_mtime_ns for p in paths if p.exists()}


def make_newer(path, than, edit=None):
    """Edits or touches `path` until its mtime is strictly newer than every file in `than`: two
    writes within one tick of the kernel's coarse file clock get the same time, and a build tool
    would then (rightly) see nothing to do."""
    newest = max(p.stat().st_mtime_ns for p in than)
    for _ in range(200):
        if edit:
            edit(path)
            edit = None
        else:
            os.utime(path)
        if path.stat().st_mtime_ns > newest:
            return
        time.sleep(0.01)
    sys.exit(f"could not make {path} newer than the outputs")


def check_reproducible(label, example, build_dir):
    for source, output in sorted(example.output_of.items()):
        if not output.is_file():
            continue
        data = output.read_bytes()
        for path in (example.source_dir, build_dir):
            check(str(path).encode() not in data, f"{label}: {output} contains the path {path}")
        relative = output.relative_to(build_dir)
        expected = first_build_outputs.setdefault(relative, data)
        check(data == expected, f"{label}: {output} differs from the same output in an earlier copy of the example")


def converted_pipelines(build_dir):
    """The pipelines the SOURCES step converted in its last run: its report's entries not cached."""
    path = build_dir / "stereo" / "stereoshift-report.json"
    if not path.is_file():  # a project of another layout (the checks of options and errors)
        return set()
    report = json.loads(path.read_text())
    return {entry["pipeline"] for entry in report["shaders"] if not entry.get("cached", False)}


def build(cmake, build_dir, extra=()):
    result = run([cmake, "--build", build_dir, *extra])
    log = result.stdout + result.stderr
    ran = converted_pipelines(build_dir) if STEP_RAN in log else set()
    return log, ran, SCENE_RAN in log


def check_generator(args, generator, make_program, prefix, work):
    name = "ninja" if generator == "Ninja" else "make"
    print(f"--- {generator}", flush=True)
    source_dir = work / f"example-{name}"
    build_dir = work / f"build-{name}"
    shutil.copytree(args.example, source_dir)
    example = Example(source_dir, build_dir)
    check(example.including and set(example.pipelines) - example.including,
          f"{name}: the example needs pipelines with and without {HEADER_NAME}")
    all_outputs = example.outputs()

    # 1. configure against the fresh prefix, and nothing else
    run([args.cmake, "-S", source_dir, "-B", build_dir, "-G", generator,
         f"-DCMAKE_MAKE_PROGRAM={make_program}", f"-DCMAKE_PREFIX_PATH={prefix}",
         "-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF"])
    cache = (build_dir / "CMakeCache.txt").read_text()
    found = re.search(r"^stereoshift_DIR:PATH=(.*)$", cache, re.MULTILINE)
    check(found and Path(found.group(1)).resolve() == (prefix / "lib/cmake/stereoshift").resolve(),
          f"{name}: the example found stereoshift at {found and found.group(1)}, not in {prefix}")

    # 2. first build
    log, ran, scene_ran = build(args.cmake, build_dir)
    check(ran == set(example.pipelines), f"{name}: first build ran {sorted(ran)}, expected {sorted(example.pipelines)}")
    check(scene_ran and example.scene_report.is_file(), f"{name}: the MANIFEST step did not write {example.scene_report}")
    # SOURCES and MANIFEST convert a pipeline alike (the example passes the same options both ways).
    check(example.scene_pipelines, f"{name}: scene.toml names none of the example's pipelines")
    for source, output in sorted(example.scene_output_of.items()):
        per_pipeline = example.output_of[source]
        check(output.is_file() and per_pipeline.is_file() and output.read_bytes() == per_pipeline.read_bytes(),
              f"{name}: {output} (MANIFEST) is missing or differs from {example.output_of[source]} (SOURCES)")
    for output in sorted(all_outputs):
        check(output.is_file(), f"{name}: missing output {output}")
    listed = {Path(line) for line in (build_dir / "stereo-shaders.txt").read_text().split()}
    check(listed == all_outputs, f"{name}: OUTPUTS_VAR lists {sorted(map(str, listed))}, expected {sorted(map(str, all_outputs))}")
    for source, output in example.output_of.items():
        if not output.is_file():
            continue
        text = output.read_text()
        if stage_of(source) in SHIFTED_STAGES:
            missing = [p for p in EYE_PARAMETERS if p not in text]
            check(not missing, f"{name}: {output} lacks the eye parameters {missing}")
        else:
            check("eyeSign" not in text, f"{name}: {output} ({stage_of(source)} stage) got eye parameters")
    check_reproducible(name, example, build_dir)
    if generator == "Ninja":
        check(str(prefix / "bin" / "stereoshift") in (build_dir / "build.ninja").read_text(),
              f"{name}: build.ninja does not run {prefix}/bin/stereoshift")

    # 3. a second build does nothing
    before = mtimes(all_outputs)
    log, ran, scene_ran = build(args.cmake, build_dir)
    check(not ran, f"{name}: the second build reran {sorted(ran)}")
    check(not scene_ran, f"{name}: the second build reran the MANIFEST step")
    check(mtimes(all_outputs) == before, f"{name}: the second build rewrote outputs")
    if generator == "Ninja":
        check("ninja: no work to do." in log, f"{name}: the second build did work:\n{log}")

    # 4. touching the header runs the step, which converts nothing and rewrites nothing; editing it
    # converts exactly the pipelines that include it
    before = mtimes(all_outputs)
    make_newer(example.header, all_outputs)
    log, ran, scene_ran = build(args.cmake, build_dir)
    check(STEP_RAN in log, f"{name}: after touching {HEADER_NAME} the build step did not run:\n{log}")
    check(scene_ran == bool(example.including & example.scene_pipelines),
          f"{name}: after touching {HEADER_NAME} the MANIFEST step {'ran' if scene_ran else 'did not run'}")
    check(not ran, f"{name}: after touching {HEADER_NAME} (same bytes) converted {sorted(ran)}")
    check(mtimes(all_outputs) == before, f"{name}: after touching {HEADER_NAME} (same bytes) outputs were rewritten")
    log, ran, scene_ran = build(args.cmake, build_dir)
    check(STEP_RAN not in log and not scene_ran, f"{name}: the build after touching {HEADER_NAME} is not stable:\n{log}")
    make_newer(example.header, all_outputs, edit=lambda p: p.write_text(p.read_text() + "// edited by the test\n"))
    log, ran, scene_ran = build(args.cmake, build_dir)
    check(ran == example.including,
          f"{name}: after editing {HEADER_NAME} converted {sorted(ran)}, expected {sorted(example.including)}")
    after = mtimes(all_outputs)
    changed = {p for p in all_outputs if after.get(p) != before.get(p)}
    check(changed <= example.outputs(example.including),
          f"{name}: after editing {HEADER_NAME} rewrote {sorted(map(str, changed))}, which do not include it")

    # 5. editing one stage of a pipeline without the header reruns that pipeline only
    edited_key = next(k for k in sorted(example.pipelines)
                      if k not in example.including and len(example.pipelines[k]) > 1)
    # A stage that is not shifted, where possible: the edit is then all that changes in its pipeline.
    stages = example.pipelines[edited_key]
    edited = next((s for s in stages if stage_of(s) not in SHIFTED_STAGES), stages[-1])
    before = mtimes(all_outputs)
    make_newer(edited, all_outputs, edit=lambda p: p.write_text(p.read_text() + "// edited by the test\n"))
    log, ran, scene_ran = build(args.cmake, build_dir)
    check(scene_ran == (edited_key in example.scene_pipelines),
          f"{name}: after editing {edited.name} the MANIFEST step {'ran' if scene_ran else 'did not run'}")
    check(ran == {edited_key}, f"{name}: after editing {edited.name} converted {sorted(ran)}, expected ['{edited_key}']")
    after = mtimes(all_outputs)
    changed = {p for p in all_outputs if after.get(p) != before.get(p)}
    # The edited stage's output changed; its pipeline's other outputs are rewritten only if their bytes did.
    check(example.output_of[edited] in changed and changed <= example.outputs([edited_key]),
          f"{name}: after editing {edited.name} rewrote {sorted(map(str, changed))}, expected "
          f"{example.output_of[edited]} and at most {sorted(map(str, example.outputs([edited_key])))}")
    log, ran, scene_ran = build(args.cmake, build_dir)
    check(not ran and not scene_ran, f"{name}: the build after the edit is not stable:\n{log}")


def check_build_tree_package(args, work):
    """export(): the package straight from the stereoshift build tree, no install."""
    print("--- build-tree package", flush=True)
    source_dir = work / "example-build-tree"
    build_dir = work / "build-build-tree"
    shutil.copytree(args.example, source_dir)
    run([args.cmake, "-S", source_dir, "-B", build_dir, "-G", "Ninja", f"-DCMAKE_MAKE_PROGRAM={args.ninja}",
         f"-Dstereoshift_DIR={args.stereoshift_build / 'cmake'}", "-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF"])
    build(args.cmake, build_dir)
    example = Example(source_dir, build_dir)
    for output in sorted(example.outputs()):
        check(output.is_file(), f"build tree: missing output {output}")
    check_reproducible("build tree", example, build_dir)
    check(str(args.stereoshift.resolve()) in (build_dir / "build.ninja").read_text(),
          f"build tree: build.ninja does not run {args.stereoshift}")


def write_project(directory, prefix, body, preamble=""):
    directory.mkdir(parents=True)
    (directory / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.25)\nproject(probe LANGUAGES NONE)\n" + preamble +
        f'find_package(stereoshift REQUIRED PATHS "{prefix}" NO_DEFAULT_PATH)\n' + body)
    return directory


def check_options_and_errors(args, prefix, work):
    print("--- options and argument errors", flush=True)
    shaders = args.example / "shaders"
    include = args.example / "include"
    # TARGET_LANGUAGE, DEFINES and OPTIONS reach the command: HLSL out of GLSL, with a renamed block.
    # The caller's CMP0116 is OLD (set before the package defines the function, as an old
    # cmake_minimum_required would): the function must still give Ninja depfiles it can match.
    project = write_project(work / "options", prefix, preamble="cmake_policy(SET CMP0116 OLD)\n", body=f"""
stereoshift_add_shaders(to_hlsl SOURCES "{shaders}/lit.vert" BASE_DIR "{shaders}" OUTPUT_DIR hlsl
  INCLUDE_DIRS "{include}" DEFINES NORMAL_SCALE=2.0 TARGET_LANGUAGE hlsl
  OPTIONS --block-name EyeParams OUTPUTS_VAR outputs)
get_target_property(property_outputs to_hlsl STEREOSHIFT_OUTPUTS)
if(NOT property_outputs STREQUAL outputs)
  message(FATAL_ERROR "STEREOSHIFT_OUTPUTS '${{property_outputs}}' differs from OUTPUTS_VAR '${{outputs}}'")
endif()
""")
    build_dir = work / "build-options"
    run([args.cmake, "-S", project, "-B", build_dir, "-G", "Ninja", f"-DCMAKE_MAKE_PROGRAM={args.ninja}"])
    build(args.cmake, build_dir)
    output = build_dir / "hlsl" / "lit.vert"
    text = output.read_text() if output.is_file() else ""
    check("cbuffer EyeParams" in text, f"TARGET_LANGUAGE hlsl + OPTIONS --block-name: no 'cbuffer EyeParams' in {output}")
    check("2.0" in text, f"DEFINES NORMAL_SCALE=2.0 did not reach {output}")
    log, _, _ = build(args.cmake, build_dir)
    check("ninja: no work to do." in log, f"with the caller's CMP0116 OLD, the second build did work:\n{log}")

    # LANGUAGE reaches every command as -x: HLSL in a file named by stage only.
    hlsl_dir = work / "language-src"
    hlsl_dir.mkdir(parents=True)
    (hlsl_dir / "mesh.vert").write_text(
        "cbuffer Camera : register(b0) { float4x4 ViewProj; };\n"
        "float4 main(float3 pos : POSITION) : SV_Position { return mul(ViewProj, float4(pos, 1.0)); }\n")
    project = write_project(work / "language", prefix, body=f"""
stereoshift_add_shaders(stage_named SOURCES "{hlsl_dir}/mesh.vert" BASE_DIR "{hlsl_dir}" OUTPUT_DIR out LANGUAGE hlsl)
""")
    build_dir = work / "build-language"
    run([args.cmake, "-S", project, "-B", build_dir, "-G", "Ninja", f"-DCMAKE_MAKE_PROGRAM={args.ninja}"])
    commands = run([args.ninja, "-C", build_dir, "-t", "commands"]).stdout
    check(" -x hlsl " in commands, f"LANGUAGE hlsl: no '-x hlsl' in the commands:\n{commands}")
    build(args.cmake, build_dir)
    output = build_dir / "out" / "mesh.vert"
    text = output.read_text() if output.is_file() else ""
    check("cbuffer StereoParams" in text, f"LANGUAGE hlsl: {output} is not the converted HLSL shader")

    # PER_PIPELINE keeps one command per pipeline (through the conversion service), the same bytes.
    project = write_project(work / "per-pipeline", prefix, body=f"""
stereoshift_add_shaders(per_pipeline SOURCES "{shaders}/lit.vert" "{shaders}/lit.frag" "{shaders}/sky.vert" "{shaders}/sky.frag"
  BASE_DIR "{shaders}" OUTPUT_DIR stereo INCLUDE_DIRS "{include}" DEFINES NORMAL_SCALE=1.0 PER_PIPELINE)
""")
    build_dir = work / "build-per-pipeline"
    run([args.cmake, "-S", project, "-B", build_dir, "-G", "Ninja", f"-DCMAKE_MAKE_PROGRAM={args.ninja}"])
    commands = run([args.ninja, "-C", build_dir, "-t", "commands"]).stdout
    check(commands.count("--pipeline") == 2 and " build " not in commands,
          f"PER_PIPELINE: expected two --pipeline commands and no build step:\n{commands}")
    build(args.cmake, build_dir)
    for name in ("lit.vert", "lit.frag", "sky.vert", "sky.frag"):
        one_step = first_build_outputs.get(Path("stereo") / name)
        per_pipeline = build_dir / "stereo" / name
        check(per_pipeline.is_file() and one_step is not None and per_pipeline.read_bytes() == one_step,
              f"PER_PIPELINE: {per_pipeline} is missing or differs from the one-step build's")

    bad_calls = {
        "no_output_dir": (f'stereoshift_add_shaders(t SOURCES "{shaders}/sky.vert")', "OUTPUT_DIR is required"),
        "outside_base_dir": (f'stereoshift_add_shaders(t SOURCES "{shaders}/sky.vert" BASE_DIR "{include}" OUTPUT_DIR o)',
                             "is not inside BASE_DIR"),
        "sources_and_manifest": (f'stereoshift_add_shaders(t SOURCES "{shaders}/sky.vert" MANIFEST "{shaders}/sky.frag" OUTPUT_DIR o)',
                                 "not both"),
        "bad_language": (f'stereoshift_add_shaders(t SOURCES "{shaders}/sky.vert" OUTPUT_DIR o TARGET_LANGUAGE wgsl)',
                         "is not one of"),
        "bad_input_language": (f'stereoshift_add_shaders(t SOURCES "{shaders}/sky.vert" OUTPUT_DIR o LANGUAGE wgsl)',
                               "LANGUAGE 'wgsl' is not one of: glsl hlsl"),
        "reserved_option": (f'stereoshift_add_shaders(t SOURCES "{shaders}/sky.vert" OUTPUT_DIR o OPTIONS -o x)',
                            "may not contain '-o'"),
        "missing_source": (f'stereoshift_add_shaders(t SOURCES "{shaders}/nothing.vert" OUTPUT_DIR o)', "does not exist"),
        "missing_value": (f'stereoshift_add_shaders(t SOURCES "{shaders}/sky.vert" OUTPUT_DIR)', "OUTPUT_DIR needs a value"),
        "base_dir_with_manifest": (f'stereoshift_add_shaders(t MANIFEST "{args.example}/scene.toml" BASE_DIR "{shaders}" OUTPUT_DIR o)',
                                   "BASE_DIR applies to SOURCES only"),
        "unknown_keyword": (f'stereoshift_add_shaders(t SOURCES "{shaders}/sky.vert" OUTPUT_DIR o SHADERS x)',
                            "unknown arguments"),
        "shared_output_dir": (f'stereoshift_add_shaders(a SOURCES "{shaders}/sky.vert" BASE_DIR "{shaders}" OUTPUT_DIR o)\n'
                              f'stereoshift_add_shaders(b SOURCES "{shaders}/lit.vert" BASE_DIR "{shaders}" OUTPUT_DIR o)',
                              "is already another target's"),
    }
    for case, (call, message) in bad_calls.items():
        project = write_project(work / "errors" / case, prefix, call + "\n")
        result = run([args.cmake, "-S", project, "-B", work / "errors" / f"build-{case}", "-G", "Ninja",
                      f"-DCMAKE_MAKE_PROGRAM={args.ninja}"], expect_success=False)
        # CMake wraps a message to its terminal width, so where the lines break depends on the
        # length of the paths in it (the checkout's location): compare with whitespace collapsed.
        unwrapped = " ".join(result.stderr.split())
        check(result.returncode != 0 and message in unwrapped,
              f"argument error '{case}': expected a failed configure saying '{message}', got "
              f"rc {result.returncode}:\n{result.stderr}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cmake", type=Path, required=True)
    parser.add_argument("--ninja", type=Path, required=True)
    parser.add_argument("--make", type=Path, help="GNU make for the Unix Makefiles pass (skipped without)")
    parser.add_argument("--stereoshift-build", type=Path, required=True, help="the stereoshift build tree to install")
    parser.add_argument("--stereoshift", type=Path, required=True, help="the stereoshift executable of that build")
    parser.add_argument("--example", type=Path, required=True, help="examples/cmake-project (read only)")
    parser.add_argument("--work-dir", type=Path, required=True, help="scratch directory, recreated")
    args = parser.parse_args()
    started = time.monotonic()

    work = args.work_dir.resolve()
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    prefix = work / "prefix"
    run([args.cmake, "--install", args.stereoshift_build, "--prefix", prefix])
    installed = prefix / "bin" / "stereoshift"
    check(installed.is_file(), f"cmake --install did not install {installed}")
    built_version = run([args.stereoshift, "--version"]).stdout
    check(run([installed, "--version"]).stdout == built_version,
          f"the installed stereoshift is not the one built in {args.stereoshift_build}")

    check_generator(args, "Ninja", args.ninja, prefix, work)
    if args.make:
        check_generator(args, "Unix Makefiles", args.make, prefix, work)
    check_build_tree_package(args, work)
    check_options_and_errors(args, prefix, work)

    print(f"{len(failures)} failures, {time.monotonic() - started:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
