#!/usr/bin/env python3
"""Builds a shader tree for every --target-version the help lists (GLSL 110-460, ESSL 100-320,
HLSL shader models 40-67) and checks each run: every GLSL/ESSL output written declares the version
asked for, every shader not written is refused for a reason that says the version (or the target)
cannot express it, and at least the floor of shaders converts (a regression floor: the figures of
corpus/ when this test was written). Usage: target_version_matrix.py STEREOSHIFT TREE OUT_DIR"""
import json
import os
import re
import subprocess
import sys

# (target, version): fewest shaders that must convert.
FLOORS = {
    **{("glsl", v): n for v, n in [(110, 98), (120, 98), (130, 135), (140, 137), (150, 176), (330, 178), (400, 178),
                                   (410, 178), (420, 179), (430, 186), (440, 186), (450, 186), (460, 186)]},
    **{("essl", v): n for v, n in [(100, 98), (300, 145), (310, 186), (320, 186)]},
    **{("hlsl", v): n for v, n in [(40, 165), (41, 165), (50, 165), (51, 165), (60, 165)]},
    **{("hlsl", v): 167 for v in range(61, 68)},
}

# What a version or a target cannot express, as the refusals say it (the tool's own words, SPIRV-Cross's
# and glslang's on the emitted text). A refusal for any other reason fails the test.
CANNOT_EXPRESS = [
    r"#version: (geometry|tessellation|compute) shaders require",
    r"At least ESSL 3\.10 required for compute shaders",
    r"Unsigned integers are not supported on legacy targets",
    r"Array of varying structs cannot be flattened",
    r"Buffer block cannot be expressed",
    r"SSBOs not supported in legacy targets",
    r"'std430' : not supported",
    r"View Index input is only supported in VS and PS 6\.1",
    r"SPIRV-Cross, which writes the HLSL, has no (geometry|hull|domain|mesh|amplification)",
    r"'(gl_VertexID|gl_InstanceID|gl_ViewID_OVR)' : undeclared identifier",
    r"'inverse' : no matching overloaded function",  # the shader's own inverse(), below GLSL 150 / ESSL 300
    r"'texelFetch\w*' : no matching overloaded function",
    r"texelFetch not supported in legacy ES",
    r"textureSize is not supported in ESSL 100",
    r"'(switch|sampler3D)' : Reserved word",
    r"extension not supported: GL_EXT_(texture_array|draw_buffers)",
    r"noperspective requires ESSL 300",
    r"'arrayed constructor' : not supported",
    # glslang asks for the extension even in a legacy vertex shader, where texture2DLod is built in.
    r"texture2DLod' : required extension not requested: GL_ARB_shader_texture_lod",
]
# Before GLSL 1.50 and in ESSL 1.00 what the version lacks can also be a word it does not know
# (noperspective, sampler2DArray, a multiview layout): a syntax error in the emitted text.
LEGACY_ONLY = [r"syntax error, unexpected IDENTIFIER"]


def legacy(target, version):
    return (target == "glsl" and version < 150) or (target == "essl" and version < 300)


def check(tool, tree, out, target, version):
    where = os.path.join(out, "%s%d" % (target, version))
    run = subprocess.run([tool, "build", tree, "-o", where, "--no-cache", "--no-caret", "--target", target,
                          "--target-version", str(version)], capture_output=True, text=True)
    report = json.load(open(os.path.join(where, "stereoshift-report.json"), encoding="utf-8"))
    problems = []
    converted = report["summary"]["converted"]
    if converted < FLOORS[(target, version)]:
        problems.append("%d converted, fewer than %d" % (converted, FLOORS[(target, version)]))
    expected = "#version %d%s" % (version, " es" if target == "essl" and version >= 300 else "")  # ESSL 1.00: no "es"
    known = CANNOT_EXPRESS + (LEGACY_ONLY if legacy(target, version) else [])
    for entry in report["shaders"]:
        if not entry.get("ok"):
            errors = entry.get("errors", [])
            if not any(re.search(p, e) for p in known for e in errors):
                problems.append("%s refused for no known reason: %s" % (entry["file"], errors[-1:] or run.stderr[-300:]))
        elif entry.get("output_file") and target in ("glsl", "essl"):
            text = open(entry["output_file"], encoding="utf-8", errors="replace").read()
            first = next((l.strip() for l in text.splitlines() if l.startswith("#version")), None)
            if first != expected:
                problems.append("%s declares %r, not %r" % (entry["output_file"], first, expected))
    print("%s %d: %d converted, %d refused; %s" % (target, version, converted, report["summary"]["failed"],
                                                     "ok" if not problems else "%d problems" % len(problems)))
    for p in problems:
        print("  " + p)
    return not problems


def main():
    tool, tree, out = sys.argv[1:4]
    results = [check(tool, tree, out, t, v) for (t, v) in FLOORS]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
