#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets from the repository's own shaders (corpus/ and the lit
tests), so the repository keeps no copies: one directory per target under --out, each file in the
layout its target reads (fuzz_transpile.cpp: an options byte, a stage byte, then the shader)."""
import argparse
import hashlib
import pathlib
import random
import re
import shutil
import subprocess
import sys
import tempfile

# fuzz_transpile.cpp's stage byte: the index of the stage's extension.
STAGES = ["vert", "tesc", "tese", "geom", "frag", "comp", "task", "mesh"]
DEFAULT_OPTIONS = 0  # target Auto, eye source Auto, branch shift


def stage_of(path):
    """The stage extension of a shader file name (x.vert, x.vert.hlsl), or None."""
    parts = path.name.split(".")
    if len(parts) >= 3 and parts[-1] == "hlsl" and parts[-2] in STAGES:
        return parts[-2]
    if len(parts) >= 2 and parts[-1] in STAGES:
        return parts[-1]
    return None


def shaders(source_root, want_hlsl):
    roots = [source_root / "corpus", source_root / "test" / "lit"]
    for root in roots:
        for path in sorted(root.rglob("*")):
            if not path.is_file() or stage_of(path) is None:
                continue
            if path.name.endswith(".hlsl") == want_hlsl:
                yield path


def write_seed(directory, payload):
    # Content-named, as libFuzzer names its own corpus files: the same seed is written once.
    (directory / hashlib.sha1(payload).hexdigest()).write_bytes(payload)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--source-root", required=True, type=pathlib.Path)
    parser.add_argument("--glslang-validator", required=True)
    parser.add_argument("--out", required=True, type=pathlib.Path)
    args = parser.parse_args()

    dirs = {name: args.out / name for name in
            ["fuzz_transpile_glsl", "fuzz_transpile_hlsl", "fuzz_transpile_spirv", "fuzz_decompiled_dump",
             "fuzz_scene_manifest", "fuzz_reproject_options"]}
    for d in dirs.values():
        shutil.rmtree(d, ignore_errors=True)
        d.mkdir(parents=True)

    # fuzz_decompiled_dump reads its bytes as choices (fuzz_decompiled_dump.cpp): byte strings from a
    # fixed-seed generator, each stage and eye source, long enough for a few dozen statements.
    chooser = random.Random(40)
    for setup in range(16):
        write_seed(dirs["fuzz_decompiled_dump"], bytes([setup]) + bytes(chooser.randrange(256) for _ in range(600)))

    for want_hlsl, target in [(False, "fuzz_transpile_glsl"), (True, "fuzz_transpile_hlsl")]:
        for path in shaders(args.source_root, want_hlsl):
            header = bytes([DEFAULT_OPTIONS, STAGES.index(stage_of(path))])
            write_seed(dirs[target], header + path.read_bytes())

    # SPIR-V seeds: the Vulkan GLSL corpus compiled by glslangValidator (the stage byte is unused).
    with tempfile.TemporaryDirectory() as scratch:
        for path in sorted((args.source_root / "corpus" / "vk450").glob("*")):
            if not path.is_file() or stage_of(path) is None:
                continue
            spv = pathlib.Path(scratch) / (path.name + ".spv")
            compiled = subprocess.run([args.glslang_validator, "-V", "--quiet", "-I" + str(path.parent / "include"), "-o", str(spv), str(path)],
                                      cwd=path.parent, capture_output=True)
            if compiled.returncode == 0:
                write_seed(dirs["fuzz_transpile_spirv"], bytes([DEFAULT_OPTIONS, 0]) + spv.read_bytes())
            else:
                print(f"make_seeds: {path}: glslangValidator failed, no SPIR-V seed", file=sys.stderr)

        # The lit tests' hand-written modules, assembled (they hold the odd cases).
        spirv_as = shutil.which("spirv-as")
        for path in sorted((args.source_root / "test" / "lit").rglob("*.spvasm")) if spirv_as else []:
            spv = pathlib.Path(scratch) / (path.name + ".spv")
            assembled = subprocess.run([spirv_as, "--target-env", "spv1.0", "-o", str(spv), str(path)],
                                       capture_output=True)
            if assembled.returncode == 0:
                write_seed(dirs["fuzz_transpile_spirv"], bytes([DEFAULT_OPTIONS, 0]) + spv.read_bytes())

    for root in ["corpus", "examples", "test/lit"]:
        for path in sorted((args.source_root / root).rglob("*.toml")):
            write_seed(dirs["fuzz_scene_manifest"], path.read_bytes())

    # The manifests the lit tests write with `printf '...' > x.toml` (the error cases among them).
    printf_toml = re.compile(r"printf '([^']*)' > \S+\.toml")
    for path in sorted((args.source_root / "test" / "lit").rglob("*.test")):
        for text in printf_toml.findall(path.read_text(errors="replace")):
            manifest = text.replace("\\n", "\n").replace("\\t", "\t").replace('\\"', '"')
            write_seed(dirs["fuzz_scene_manifest"], manifest.encode())

    # The reproject command lines of the lit tests, one word per line, without the paths (%t...) and
    # the options that take them.
    reproject_run = re.compile(r"%stereoshift reproject (.*)")
    for path in sorted((args.source_root / "test" / "lit").rglob("*.test")):
        for line in reproject_run.findall(path.read_text(errors="replace")):
            words, skip = [], False
            for word in line.split():
                if word.startswith(("2>", "|", ">", "&&", ";")):
                    break  # the shell's part of the RUN line
                if skip or word.startswith("%"):
                    skip = False
                    continue
                if word in ("-o", "--output", "--report"):
                    skip = True
                    continue
                words.append(word)
            write_seed(dirs["fuzz_reproject_options"], ("\n".join(words) + "\n").encode())

    for name, d in dirs.items():
        count = len(list(d.iterdir()))
        print(f"make_seeds: {count} seeds for {name}")
        if count == 0:
            print(f"make_seeds: error: no seeds for {name}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
