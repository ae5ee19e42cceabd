#!/usr/bin/env python3
"""Corpus reference test (SPIRV-Cross style mirrored trees).

Converts corpus/ with `stereoshift build`, then for every shader:
  - compares the output with test/corpus/reference/<same path> byte for byte (shaders that need no
    change must come out as the very bytes of their source, and keep no reference),
  - re-compiles the output with glslangValidator (every output, copied or re-emitted),
  - checks the classification in the JSON report against the `// stereoshift-expect:` header,
  - for every output spliced into its own text (the GLSL and HLSL source-splice routes): undoes the
    marked edits (the blocks between the "---- stereoshift" markers, the renamed `main`, the
    wrapped emits and returns) and requires the very bytes of the input back, so the splice changes
    nothing a user did not see marked.
`--update` rewrites the references instead of comparing them.
"""
import argparse
import difflib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

# The corpus header names what a shader is; the report names what stereoshift decided.
EXPECTED_CLASSIFICATION = {
    "shift": {"perspective"},
    "2d": {"2d-constant-w"},
    "intermediate": {"intermediate-stage"},
    "fragment": {"no-position-stage"},
    "compute": {"no-position-stage"},
    "deferred-unproject": {"no-position-stage"},
    # per-eye view vectors live in vertex (shifted, or intermediate in front of a geometry stage that
    # passes them on) or fragment (untouched) shaders
    "per-eye-view": {"perspective", "intermediate-stage", "no-position-stage"},
    "already-stereo": {"already-stereo"},  # multiview shaders (gl_ViewIndex, gl_ViewID_OVR, SV_ViewID)
}

STAGE_OF = {"vert": "vert", "tesc": "tesc", "tese": "tese", "geom": "geom", "frag": "frag", "comp": "comp"}


def expected_class(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f.readlines()[:5]:
            m = re.search(r"stereoshift-expect:\s*([\w-]+)", line)
            if m:
                return m.group(1)
    return None


def hlsl_entry(text):
    if re.search(r"(^|[^A-Za-z0-9_])main\s*\(", text):
        return "main"
    for name in ("VSMain", "PSMain", "GSMain", "HSMain", "DSMain", "CSMain"):
        if re.search(r"\b%s\s*\(" % name, text):
            return name
    return "main"


def blank_techniques(text):
    """Effect files: technique/state blocks blanked (line breaks kept), as glslang cannot parse them."""
    out = list(text)
    for m in re.finditer(r"^[ \t]*(technique(?:10|11)?|BlendState|DepthStencilState|RasterizerState)\b[^{;]*\{",
                         text, re.I | re.M):
        depth, i = 0, m.end() - 1
        while i < len(text):
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            if depth == 0:
                break
            i += 1
        for k in range(m.start(), min(i + 1, len(text))):
            if out[k] not in "\r\n":
                out[k] = " "
    return "".join(out)


def recompile_entry_points(glslang, path, entry_points):
    """A file with several entry points: every one of them compiled from the output, each with its stage."""
    text = blank_techniques(open(path, encoding="utf-8", errors="replace").read())
    logs, ok = [], True
    with tempfile.NamedTemporaryFile("w", suffix=".hlsl", delete=False) as f:
        f.write(text)
    try:
        for name, facts in sorted(entry_points.items()):
            if facts.get("stage") not in STAGE_OF:
                continue
            # The techniques-blanked copy lives elsewhere: its #includes resolve from the output's folder.
            cmd = [glslang, "-D", "-V", "-I" + os.path.dirname(os.path.abspath(path)), "-S", facts["stage"], "-e", name,
                   "-o", os.devnull, f.name]
            run = subprocess.run(cmd, capture_output=True, text=True)
            ok &= run.returncode == 0
            logs.append(run.stdout + run.stderr)
    finally:
        os.remove(f.name)
    return ok, "".join(logs)


def recompile(glslang, path, rel, language, reported_stage=None):
    """Compiles an output shader the way its dialect is consumed (`language`: the report's, so HLSL
    in a stage-named file such as hlsl-stage-named/textured.vert is compiled as HLSL). The stage is
    the report's where it gives one (file-conventions/ names stages as .vs, basicVS.hlsl, #pragma)."""
    parts = os.path.basename(rel).split(".")
    text = open(path, encoding="utf-8", errors="replace").read()
    if rel.endswith(".fx"):
        text = blank_techniques(text)
        cmd = [glslang, "-D", "-V", "-S", STAGE_OF[parts[-2]], "-e", hlsl_entry(text), "-o", os.devnull, "--stdin"]
        run = subprocess.run(cmd, input=text, capture_output=True, text=True)
        return run.returncode == 0, run.stdout + run.stderr
    if rel.endswith(".hlsl") or language == "hlsl":
        stage = STAGE_OF.get(reported_stage) or STAGE_OF[parts[-2] if rel.endswith(".hlsl") else parts[-1]]
        cmd = [glslang, "-D", "-V", "-S", stage, "-e", hlsl_entry(text), "-o", os.devnull, path]
    else:
        stage = STAGE_OF.get(reported_stage) or STAGE_OF[parts[-1]]
        vulkan = os.path.basename(os.path.dirname(rel)) == "vk450"  # vk450/, relief-tutorial/vk450/
        cmd = [glslang, "-S", stage, path] + (["-V", "-o", os.devnull] if vulkan else [])
        include = os.path.join(os.path.dirname(path), "include")
        if os.path.isdir(include):
            cmd.insert(1, "-I" + include)
    run = subprocess.run(cmd, capture_output=True, text=True)
    return run.returncode == 0, run.stdout + run.stderr


SPLICE_ROUTES = {"glsl-source-splice", "hlsl-source-splice", "hlsl-pixel-source-splice"}


def unwrap_calls(text, prefix):
    """`prefix_T(expr)` -> `expr` for every call of a helper whose name starts with `prefix`."""
    out, i = [], 0
    pattern = re.compile(r"\b%s\w*\(" % re.escape(prefix))
    while True:
        m = pattern.search(text, i)
        if not m:
            out.append(text[i:])
            return "".join(out)
        out.append(text[i:m.start()])
        depth, j = 1, m.end()
        while j < len(text) and depth:
            depth += {"(": 1, ")": -1}.get(text[j], 0)
            j += 1
        out.append(text[m.end():j - 1])
        i = j


def undo_inline_edits(text):
    """The splices' edits inside lines undone: renamed entry points, wrapped emits, returns and out
    parameters, attributes moved to a wrapper, per-eye camera reads, unprojections, re-projections and
    view rays, derived outputs' reads of the position, one-line marked insertions."""
    text = re.sub(r"/\* ---- stereoshift ---- \*/.*?/\* ---- end stereoshift ---- \*/ ", "", text)
    text = re.sub(r"/\* stereoshift: moved to the wrapper: (.*?) \*/", r"\1", text)
    text = re.sub(r"\{ stereoshift_shiftPosition\(\); (.*?) \}", r"\1", text)
    # HLSL `out` parameters shifted before a return (`{ p = stereoshift_shift_T(p); return; }`) or
    # at the end of the body (a line of its own, or before the closing brace).
    text = re.sub(r"\{ ((?:\w+ = stereoshift_shift_\w+\(\w+\); )+)(return\b[^;]*;) \}", r"\2", text)
    text = re.sub(r"(?m)^[ \t]*(?:\w+ = stereoshift_shift_\w+\(\w+\); ?)+\r?\n", "", text)
    text = re.sub(r"(?:\w+ = stereoshift_shift_\w+\(\w+\); )+(?=\})", "", text)
    text = unwrap_calls(text, "stereoshift_shift_")
    text = unwrap_calls(text, "stereoshift_eye_")  # a per-eye camera read through its helper
    text = unwrap_calls(text, "stereoshift_unproject_")  # an unprojection through its helper
    text = unwrap_calls(text, "stereoshift_reproject_")  # a re-projection of a corrected position
    text = unwrap_calls(text, "stereoshift_view_ray_")  # a view ray's position through its helper
    text = unwrap_calls(text, "stereoshift_shifted_position")  # a derived output's read of the position
    text = unwrap_calls(text, "stereoshift_holder_")  # a struct holding the camera, read whole
    return re.sub(r"\b(\w+)_stereoshift_mono\b", r"\1", text)


def only_marked_edits(source, output):
    """Whether `output` is `source` plus the splices' marked edits: the inline edits undone, every
    block between a "// ---- stereoshift" line and "// ---- end stereoshift ----" removed (with a
    blank line beside it, which the splices add to set it apart), the lines must be the source's."""
    lines = undo_inline_edits(output).splitlines(True)
    kept, optional, i = [], [], 0
    while i < len(lines):
        if lines[i].startswith("// ---- stereoshift"):
            j = i
            while j < len(lines) and not lines[j].startswith("// ---- end stereoshift ----"):
                j += 1
            if j == len(lines):
                return False  # a block that does not end
            if kept and not kept[-1].strip():
                optional[-1] = True
            i = j + 1
            if i < len(lines) and not lines[i].strip():
                kept.append(lines[i])
                optional.append(True)
                i += 1
            continue
        kept.append(lines[i])
        optional.append(False)
        i += 1
    want = source.splitlines(True)
    # A blank line beside a block may be the splice's or the source's: match with that choice open.
    seen = set()

    def match(a, b):
        while True:
            if (a, b) in seen:
                return False
            seen.add((a, b))
            if b == len(kept):
                return a == len(want)
            if optional[b] and match(a, b + 1):
                return True
            if a == len(want) or want[a] != kept[b]:
                return False
            a, b = a + 1, b + 1

    return match(0, 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--stereoshift", required=True)
    ap.add_argument("--corpus", required=True)
    ap.add_argument("--reference", required=True)
    ap.add_argument("--glslang", default=shutil.which("glslangValidator") or "glslangValidator")
    ap.add_argument("--update", action="store_true", help="rewrite the reference tree")
    args = ap.parse_args()

    failures = []
    with tempfile.TemporaryDirectory() as out:
        # Include files are copied so re-compiling a copied-through shader finds them.
        run = subprocess.run([args.stereoshift, "build", args.corpus, "-o", out, "--verify"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stderr)
            failures.append("stereoshift build failed (exit %d)" % run.returncode)
        report = json.load(open(os.path.join(out, "stereoshift-report.json")))
        by_file = {os.path.relpath(s["file"], args.corpus): s for s in report["shaders"]}

        checked = 0
        spliced = 0
        for root, _, files in os.walk(args.corpus):
            for name in sorted(files):
                src = os.path.join(root, name)
                rel = os.path.relpath(src, args.corpus)
                expect = expected_class(src)
                if expect is None:
                    continue  # not a shader (include, README, script)
                checked += 1
                entry = by_file.get(rel)
                if entry is None or not entry.get("ok"):
                    failures.append("%s: not converted" % rel)
                    continue
                got = entry.get("classification")
                allowed = set(EXPECTED_CLASSIFICATION.get(expect, set()))
                if rel.split(".")[-1] == "tesc" or ".tesc." in rel:
                    allowed.add("no-position-stage")  # nothing to shift before tessellation evaluation
                if got not in allowed:
                    failures.append("%s: classified %s, corpus header says %s" % (rel, got, expect))
                produced = os.path.join(out, rel)
                inc = os.path.join(os.path.dirname(src), "include")
                if os.path.isdir(inc) and not os.path.isdir(os.path.join(os.path.dirname(produced), "include")):
                    shutil.copytree(inc, os.path.join(os.path.dirname(produced), "include"))
                if entry.get("entry_points"):
                    ok, log = recompile_entry_points(args.glslang, produced, entry["entry_points"])
                else:
                    ok, log = recompile(args.glslang, produced, rel, entry.get("language"), entry.get("stage"))
                if not ok:
                    failures.append("%s: output does not compile:\n%s" % (rel, log))
                ref = os.path.join(args.reference, rel)
                data = open(produced, "rb").read()
                if entry.get("route") in SPLICE_ROUTES:
                    source = open(src, "rb").read().decode("utf-8", "surrogateescape")
                    spliced_text = data.decode("utf-8", "surrogateescape")
                    if not only_marked_edits(source, spliced_text):
                        diff = "".join(difflib.unified_diff(source.splitlines(True), spliced_text.splitlines(True),
                                                            "input", "output"))
                        failures.append("%s: edits outside the marked regions:\n%s" % (rel, diff[:3000]))
                    spliced += 1
                if entry.get("output") == "copied":
                    # Nothing injected: the output must be the input, byte for byte; no reference kept.
                    if data != open(src, "rb").read():
                        failures.append("%s: reported as copied but differs from the source" % rel)
                    if args.update and os.path.exists(ref):
                        os.remove(ref)
                        print("removed", ref)
                    elif os.path.exists(ref):
                        failures.append("%s: stale reference for a copied-through shader (run --update)" % rel)
                    continue
                if args.update:
                    os.makedirs(os.path.dirname(ref), exist_ok=True)
                    if not os.path.exists(ref) or open(ref, "rb").read() != data:
                        open(ref, "wb").write(data)
                        print("updated", ref)
                elif not os.path.exists(ref):
                    failures.append("%s: no reference (run with --update)" % rel)
                elif open(ref, "rb").read() != data:
                    diff = subprocess.run(["diff", "-u", ref, produced], capture_output=True, text=True).stdout
                    failures.append("%s: differs from reference:\n%s" % (rel, diff[:3000]))

    for f in failures:
        print("FAIL:", f)
    print("corpus: %d shaders checked, %d spliced into their own text" % (checked, spliced))
    print("%d passed, %d failed" % (checked - len(failures), len(failures)) if len(failures) <= checked
          else "0 passed, %d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
