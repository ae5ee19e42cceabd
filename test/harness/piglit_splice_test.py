#!/usr/bin/env python3
"""Execution in a real OpenGL driver: each test/harness/piglit/*.shader_test is a piglit shader_runner
test written here, run by Mesa's OpenGL (or OpenGL ES) driver, headless (surfaceless EGL, an FBO):

  1. the original shaders, as written: the test's own probes must pass (the test is right);
  2. the stereo probes (`[stereo +1]`, `[stereo -1]`) on the original shaders must FAIL unless the
     case says `moves: no` (the probes can tell a shifted image from the mono one);
  3. stereoshift converts the pre-rasterisation stages as one pipeline (`--pipeline`, the case's
     `options:`), the converted text replaces each shader section as it is;
  4. eyeSign = 0: the converted pipeline must pass the original probes (it renders what the
     original renders);
  5. eyeSign = +1 and -1 (separation and convergence from the case): the stereo probes must pass
     (perspective geometry moves by eyeSign*separation*(w - convergence)/w in NDC x; w = 1
     geometry does not move).

A case may name the route its last stage must take (`route:`), checked in the JSON report.
Sections of our own, removed before shader_runner reads a file:
  [stereoshift]   key: value lines: options, separation, convergence, moves, route
  [stereo +1]     probe lines that replace the [test] section's probes for eyeSign = +1
  [stereo -1]     the same for eyeSign = -1
Exit 0 when every case passes, 1 otherwise; 77 (skipped) when shader_runner is missing.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

STAGE_SECTIONS = {
    "vertex shader": "vert",
    "tessellation control shader": "tesc",
    "tessellation evaluation shader": "tese",
    "geometry shader": "geom",
    "fragment shader": "frag",
}
OURS = ("stereoshift", "stereo +1", "stereo -1")


def parse(text):
    """[(section name, body text)] in order; text before the first section has the name ''."""
    sections, name, body = [], "", []
    for line in text.splitlines(True):
        m = re.match(r"^\[([^\]]+)\]\s*$", line)
        if m:
            sections.append((name, "".join(body)))
            name, body = m.group(1).strip(), []
        else:
            body.append(line)
    sections.append((name, "".join(body)))
    return sections


def render(sections):
    return "".join(("[%s]\n" % n if n else "") + b for n, b in sections if n not in OURS)


def settings(sections):
    out = {"options": "", "separation": "0.5", "convergence": "1.0", "moves": "yes", "route": ""}
    for name, body in sections:
        if name == "stereoshift":
            for line in body.splitlines():
                if ":" in line and not line.lstrip().startswith("#"):
                    k, v = line.split(":", 1)
                    out[k.strip()] = v.strip()
    return out


def with_test(sections, eye_params, probes):
    """The sections with the eye parameters set first in [test] and, if given, its probes replaced."""
    out = []
    for name, body in sections:
        if name == "test":
            lines = body.splitlines(True)
            if probes is not None:
                kept = [l for l in lines if not re.match(r"^\s*(relative )?probe", l)]
                lines = kept + [l if l.endswith("\n") else l + "\n" for l in probes]
            body = "".join("uniform float %s %s\n" % kv for kv in eye_params) + "".join(lines)
        out.append((name, body))
    return out


def probes_of(sections, name):
    for n, body in sections:
        if n == name:
            return [l for l in body.splitlines() if l.strip() and not l.lstrip().startswith("#")]
    return None


def run_runner(runner, text, work, label):
    path = os.path.join(work, label + ".shader_test")
    with open(path, "w") as f:
        f.write(text)
    env = dict(os.environ, PIGLIT_PLATFORM="surfaceless_egl")
    r = subprocess.run([runner, path, "-auto", "-fbo"], capture_output=True, text=True, env=env, timeout=120)
    return r.returncode == 0 and '"result": "pass"' in r.stdout, r.stdout + r.stderr


def run_case(path, args):
    text = open(path).read()
    sections = parse(text)
    cfg = settings(sections)
    es = any(n == "require" and re.search(r"GL ES", b) for n, b in sections)
    runner = os.path.join(args.piglit_bin, "shader_runner_gles3" if es else "shader_runner")
    name = os.path.splitext(os.path.basename(path))[0]
    problems = []
    with tempfile.TemporaryDirectory() as work:
        ok, log = run_runner(runner, render(sections), work, "original")
        if not ok:
            return ["the original does not pass its own probes:\n" + log]
        stereo_probes = {sign: probes_of(sections, "stereo %s" % sign) for sign in ("+1", "-1")}
        if any(p is None for p in stereo_probes.values()):
            return ["no [stereo +1] / [stereo -1] probes"]
        if cfg["moves"] == "yes":
            for sign, probes in stereo_probes.items():
                ok, _ = run_runner(runner, render(with_test(sections, [], probes)), work, "control" + sign)
                if ok:
                    problems.append("the stereo %s probes pass on the original: they cannot tell a shift" % sign)
        # Convert the pre-rasterisation stages as one pipeline (the fragment stage too, so it is
        # part of the pipeline stereoshift sees).
        files = []
        for i, (n, body) in enumerate(sections):
            if n in STAGE_SECTIONS:
                # One file per section: a stage may be linked from several (two [vertex shader]s).
                f = os.path.join(work, "%s-%d.%s" % (name, i, STAGE_SECTIONS[n]))
                with open(f, "w") as out:
                    out.write(body)
                files.append((i, f))
        outdir = os.path.join(work, "out")
        report = os.path.join(work, "report.json")
        cmd = [args.stereoshift, "--pipeline", ",".join(f for _, f in files), "-o", outdir, "--report", report]
        cmd += cfg["options"].split() + args.extra_options.split()
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            return problems + ["stereoshift failed (exit %d):\n%s" % (r.returncode, r.stderr)]
        converted = list(sections)
        for i, f in files:
            out = os.path.join(outdir, os.path.basename(f))
            converted[i] = (sections[i][0], open(out).read())
        if cfg["route"]:
            data = json.load(open(report))
            stages = data if isinstance(data, list) else data.get("shaders", [data])
            routes = [s.get("route") for s in stages]
            if cfg["route"] not in routes:
                problems.append("no stage took the %s route (routes: %s)" % (cfg["route"], routes))
        # The eye parameters by the names the GL API gives them: a member of the injected block
        # StereoParams is "StereoParams.eyeSign", a loose uniform "eyeSign".
        block = any(re.search(r"\buniform\s+StereoParams\b", body) for _, body in converted)
        prefix = "StereoParams." if block else ""
        # A pipeline stereoshift proved 2D declares none (a w = 1 draw stays mono in both eyes): it
        # is run with none set, and must still pass every probe; where they are declared, shader_runner
        # fails on one the driver's compiler removed (an application's glUniform would be a no-op).
        declared = any(re.search(r"\beyeSign\b", body) for _, body in converted)
        base = [(prefix + "separation", cfg["separation"]), (prefix + "convergence", cfg["convergence"])]
        eye = lambda sign: [(prefix + "eyeSign", sign)] + base if declared else []
        ok, log = run_runner(runner, render(with_test(converted, eye("0"), None)), work, "mono")
        if not ok:
            problems.append("eyeSign = 0: the converted pipeline does not render what the original renders:\n" + log)
        for sign, probes in stereo_probes.items():
            ok, log = run_runner(runner, render(with_test(converted, eye(sign), probes)), work, "stereo" + sign)
            if not ok:
                problems.append("eyeSign = %s: the stereo probes fail:\n%s" % (sign, log))
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--stereoshift", required=True)
    ap.add_argument("--cases", required=True, help="folder of .shader_test cases")
    ap.add_argument("--extra-options", default="", help="more stereoshift options for every case "
                    "(--extra-options=--force-reemit shows what the re-emit route does)")
    ap.add_argument("--piglit-bin", default="/usr/lib/x86_64-linux-gnu/piglit/bin")
    args = ap.parse_args()
    if not os.path.exists(os.path.join(args.piglit_bin, "shader_runner")):
        print("piglit's shader_runner is not installed: skipped")
        return 77
    cases = sorted(os.path.join(args.cases, f) for f in os.listdir(args.cases) if f.endswith(".shader_test"))
    failed = 0
    for case in cases:
        problems = run_case(case, args)
        print("%s: %s" % (os.path.basename(case), "ok" if not problems else "FAILED"))
        for p in problems:
            print("  " + p.replace("\n", "\n    "))
        failed += bool(problems)
    print("piglit: %d cases, %d passed, %d failed" % (len(cases), len(cases) - failed, failed))
    return 1 if failed or not cases else 0


if __name__ == "__main__":
    sys.exit(main())
