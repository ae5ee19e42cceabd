#!/usr/bin/env python3
"""Tree-conversion benchmark: ratios measured side by side in one run (a benchmark, not a test).

Variants, all on the same corpus, interleaved within every repetition:
  process pipeline   for every shader, what a user would script without stereoshift: glslangValidator
                     to SPIR-V, then spirv-cross back to the input's dialect, one process after the
                     other. It does no stereo work at all, so the ratio against it is conservative.
  stereoshift -j1    `stereoshift build <corpus> -o <fresh dir> -j 1` (full conversion, one worker)
  stereoshift -j2    the same with two workers
  no-op rebuild      `stereoshift build <corpus> -o <dir of the -j1 run just before> -j 1` again: the
                     output directory's content-hash cache should leave nothing to convert.

  bench/tree_bench.py [--stereoshift build/stereoshift] [--corpus corpus] [--reps 5] [--json FILE]
                      [--work-dir DIR] [--quick]

Exit status 0 whatever the ratios are; non-zero only when a tool is missing, stereoshift fails, or
no shader of the process pipeline converts at all.
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT_ROOT = os.path.dirname(HERE)

# The aims, printed beside the measured ratios.
AIM_PROCESS_OVER_J1 = 30.0  # stereoshift -j1 at least this many times faster than the process pipeline
AIM_J1_OVER_J2 = 1.8  # speed-up from one worker to two
AIM_NOOP_PERCENT = 1.0  # a no-change rebuild at most this share of a full one (issue 23)

SHADER_EXTENSIONS = (".vert", ".tesc", ".tese", ".geom", ".frag", ".comp", ".hlsl")
HLSL_DEFAULT_ENTRY = {"vert": "VSMain", "frag": "PSMain", "geom": "GSMain", "tesc": "HSMain",
                      "tese": "DSMain", "comp": "CSMain"}
# What the quick (CTest) run feeds through the process pipeline; stereoshift still converts the tree.
QUICK_PROCESS_SUBSET = 10


# ---------------------------------------------------------------------------------------------------
# Corpus and the per-file process pipeline
# ---------------------------------------------------------------------------------------------------

def find_shaders(corpus):
    """Shader files of the tree, as corpus/check.sh sees them: include directories hold no shaders."""
    shaders = []
    for root, dirs, files in os.walk(corpus):
        dirs[:] = sorted(d for d in dirs if d != "include")
        for name in sorted(files):
            if name.endswith(SHADER_EXTENSIONS):
                shaders.append(os.path.relpath(os.path.join(root, name), corpus))
    return shaders


def spread_subset(shaders, count):
    """Up to `count` shaders taken in turn from each top-level directory, so every dialect is timed."""
    by_dialect = {}
    for rel in shaders:
        by_dialect.setdefault(rel.split(os.sep)[0], []).append(rel)
    queues = [list(files) for _, files in sorted(by_dialect.items())]
    subset = []
    while len(subset) < count and any(queues):
        for queue in queues:
            if queue and len(subset) < count:
                subset.append(queue.pop(0))
    return subset


def read_version_line(text):
    match = re.search(r"^\s*#\s*version\s+(\d+)\s*(es)?", text, re.MULTILINE)
    if not match:
        return None, False
    return int(match.group(1)), match.group(2) == "es"


def hlsl_entry(text, stage):
    """The entry point the corpus convention names: `main` if defined, else the stage's usual name."""
    if re.search(r"(^|[^A-Za-z0-9_])main\s*\(", text):
        return "main"
    return HLSL_DEFAULT_ENTRY.get(stage, "main")


def process_pipeline_commands(glslang, spirv_cross, corpus, rel, spirv_path, output_path):
    """The two commands a user would run for one shader, mirroring test/corpus/check_corpus.py and
    corpus/check.sh for the front end and going back to the same dialect with spirv-cross."""
    source = os.path.join(corpus, rel)
    text = open(source, encoding="utf-8", errors="replace").read()
    name_parts = os.path.basename(rel).split(".")
    if rel.endswith(".hlsl"):
        stage = name_parts[-2]
        to_spirv = [glslang, "-D", "-V", "-S", stage, "-e", hlsl_entry(text, stage), "-o", spirv_path, source]
        to_source = [spirv_cross, spirv_path, "--hlsl", "--shader-model", "50", "--output", output_path]
        return to_spirv, to_source

    stage = name_parts[-1]
    version, es = read_version_line(text)
    version = version or 110
    to_spirv = [glslang, "-S", stage]
    include_dir = os.path.join(os.path.dirname(source), "include")
    if os.path.isdir(include_dir):
        to_spirv.append("-I" + include_dir)  # glslang wants the directory glued to -I
    to_source = [spirv_cross, spirv_path, "--version", str(version)] + (["--es"] if es else [])
    vulkan = (not es and version >= 400) or (es and version >= 310)
    if vulkan:
        # Vulkan GLSL, as the project's front end tries first for these versions.
        to_spirv += ["-V"]
        to_source += ["--vulkan-semantics"]
    else:
        # OpenGL GLSL with loose uniforms: OpenGL SPIR-V needs locations and bindings assigned.
        to_spirv += ["-G", "--auto-map-locations", "--auto-map-bindings"]
        if es and version < 310:
            # glslang 12 refuses ES < 310 for SPIR-V; the project parses ESSL 300 as 310 too.
            to_spirv += ["--glsl-version", "310es"]
    to_spirv += ["-o", spirv_path, source]
    to_source += ["--output", output_path]
    return to_spirv, to_source


def first_error_line(run):
    for line in (run.stderr + "\n" + run.stdout).splitlines():
        line = line.strip()
        if line and ("error" in line.lower() or "exception" in line.lower()):
            return line
    lines = [l.strip() for l in (run.stderr + "\n" + run.stdout).splitlines() if l.strip()]
    return lines[-1] if lines else "exit status %d" % run.returncode


def run_process_pipeline(commands, scratch_dir):
    """Runs every shader's two commands in turn. Returns the wall time of the whole sequence, the time
    spent in each tool, and the shaders whose commands failed (with the reason)."""
    shutil.rmtree(scratch_dir, ignore_errors=True)
    os.makedirs(scratch_dir)
    step_seconds = {"glslangValidator": 0.0, "spirv-cross": 0.0}
    succeeded_seconds = 0.0
    failures = {}
    start = time.perf_counter()
    for rel, (to_spirv, to_source) in commands:
        shader_start = time.perf_counter()
        run = subprocess.run(to_spirv, capture_output=True, text=True)
        after_front_end = time.perf_counter()
        step_seconds["glslangValidator"] += after_front_end - shader_start
        if run.returncode != 0:
            failures[rel] = "glslangValidator: " + first_error_line(run)
            continue
        run = subprocess.run(to_source, capture_output=True, text=True)
        shader_end = time.perf_counter()
        step_seconds["spirv-cross"] += shader_end - after_front_end
        if run.returncode != 0:
            failures[rel] = "spirv-cross: " + first_error_line(run)
            continue
        succeeded_seconds += shader_end - shader_start
    total = time.perf_counter() - start
    return {"seconds": total, "succeeded_seconds": succeeded_seconds, "step_seconds": step_seconds,
            "failures": failures}


# ---------------------------------------------------------------------------------------------------
# stereoshift build
# ---------------------------------------------------------------------------------------------------

def run_stereoshift_build(stereoshift, corpus, out_dir, jobs, fresh):
    if fresh:
        shutil.rmtree(out_dir, ignore_errors=True)
    command = [stereoshift, "build", corpus, "-o", out_dir, "-j", str(jobs)]
    start = time.perf_counter()
    run = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if run.returncode != 0:
        raise RuntimeError("%s failed (exit %d):\n%s%s" % (" ".join(command), run.returncode,
                                                           run.stdout[-2000:], run.stderr[-2000:]))
    report_path = os.path.join(out_dir, "stereoshift-report.json")
    try:
        with open(report_path, encoding="utf-8") as f:
            report = json.load(f)
    except (OSError, ValueError) as error:
        raise RuntimeError("%s: no readable report (%s)" % (" ".join(command), error))
    return {"seconds": seconds, "report": report, "command": command}


def report_summary(report):
    """What the report says about the run: shader count, failures, and the converted/cached counts
    when the tool writes them (the incremental cache adds them; older binaries have none)."""
    shaders = report.get("shaders", [])
    summary = {"shaders": len(shaders), "not_ok": sum(1 for s in shaders if not s.get("ok", True))}
    # Any top-level count whose name speaks of conversion or the cache, whatever its exact spelling.
    for key, value in report.items():
        if isinstance(value, int) and re.search(r"convert|cache|skip|up.to.date", key):
            summary[key] = value
        elif isinstance(value, dict) and re.search(r"count|build|cache", key) and key != "classification_counts":
            for sub_key, sub_value in value.items():
                if isinstance(sub_value, int) and re.search(r"convert|cache|skip|up.to.date", sub_key):
                    summary[key + "." + sub_key] = sub_value
    # Per-shader output kinds (copied / emitted today; a cache may add its own kind or flag).
    for shader in shaders:
        kind = "output=%s" % shader.get("output", "?")
        summary[kind] = summary.get(kind, 0) + 1
        if shader.get("cached"):
            summary["cached"] = summary.get("cached", 0) + 1
    timing_sums = {}
    for shader in shaders:
        for step, ms in (shader.get("timings_ms") or {}).items():
            if isinstance(ms, (int, float)):
                timing_sums[step] = timing_sums.get(step, 0.0) + ms
    summary["timings_ms_sum"] = timing_sums
    by_dialect = {}
    for shader in shaders:
        ms = (shader.get("timings_ms") or {}).get("front_end")
        if isinstance(ms, (int, float)) and not shader.get("cached"):
            dialect = "%s %s" % (shader.get("language", "?"), shader.get("dialect") or "")
            by_dialect.setdefault(dialect.strip(), []).append(ms)
    summary["front_end_by_dialect"] = by_dialect
    return summary


def setup_per_dialect(front_end_by_dialect):
    """Per dialect: the slowest front end (the one that built glslang's tables) minus the median."""
    return {dialect: max(ms) - statistics.median(ms)
            for dialect, ms in front_end_by_dialect.items() if len(ms) >= 2}


# ---------------------------------------------------------------------------------------------------
# Measurement and the table
# ---------------------------------------------------------------------------------------------------

def available_cores():
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def ratio(numerator, denominator):
    return numerator / denominator if denominator > 0 else float("inf")


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stereoshift", default=os.path.join(PROJECT_ROOT, "build", "stereoshift"))
    parser.add_argument("--corpus", default=os.path.join(PROJECT_ROOT, "corpus"))
    parser.add_argument("--glslang", default=shutil.which("glslangValidator") or "glslangValidator")
    parser.add_argument("--spirv-cross", default=shutil.which("spirv-cross") or "spirv-cross")
    parser.add_argument("--reps", type=int, default=5, help="repetitions (median and min are reported)")
    parser.add_argument("--work-dir", help="where output trees go (default: a temporary directory, removed)")
    parser.add_argument("--json", help="write the figures to this file")
    parser.add_argument("--quick", action="store_true",
                        help="smoke run: 1 repetition, %d shaders through the process pipeline" % QUICK_PROCESS_SUBSET)
    return parser.parse_args()


def missing_tool(args):
    """The first of the three tools that is neither an executable file nor on PATH, else None."""
    for tool in (args.stereoshift, args.glslang, args.spirv_cross):
        if not (os.path.isfile(tool) and os.access(tool, os.X_OK)) and shutil.which(tool) is None:
            return tool
    return None


def measure(args, corpus, commands, work_dir, reps):
    """Every variant `reps` times, interleaved; the warm-up first. Returns the stereoshift samples,
    the process pipeline's runs and the report summaries. Raises RuntimeError when a run fails."""
    scratch = os.path.join(work_dir, "process-pipeline")
    out_j1 = os.path.join(work_dir, "out-j1")
    out_j2 = os.path.join(work_dir, "out-j2")
    samples = {"j1": [], "j2": [], "noop": []}
    process_runs, summaries = [], {"j1": [], "j2": [], "noop": []}
    # Warm-up (untimed): loads both binaries and the corpus into the page cache, so the variant that
    # happens to run first in repetition 1 pays no cold start the others do not.
    run_stereoshift_build(args.stereoshift, corpus, os.path.join(work_dir, "warm-up"), 1, fresh=True)
    run_process_pipeline(commands[:1], scratch)

    def measure_process():
        result = run_process_pipeline(commands, scratch)
        process_runs.append(result)

    def measure_full(jobs):
        key, out_dir = ("j1", out_j1) if jobs == 1 else ("j2", out_j2)
        result = run_stereoshift_build(args.stereoshift, corpus, out_dir, jobs, fresh=True)
        samples[key].append(result["seconds"])
        summaries[key].append(report_summary(result["report"]))
        if jobs == 1:
            # The no-op rebuild follows the full -j1 conversion it reuses, before anything else
            # touches that directory.
            noop = run_stereoshift_build(args.stereoshift, corpus, out_j1, 1, fresh=False)
            samples["noop"].append(noop["seconds"])
            summaries["noop"].append(report_summary(noop["report"]))

    # Machines are shared and noisy: every repetition runs every variant, and the order rotates
    # from one repetition to the next so none always runs first or last.
    variants = [measure_process, lambda: measure_full(1), lambda: measure_full(2)]
    for rep in range(reps):
        for i in range(len(variants)):
            variants[(rep + i) % len(variants)]()
        print("repetition %d/%d done" % (rep + 1, reps), file=sys.stderr, flush=True)
    return samples, process_runs, summaries


class Figures:
    """What the measurements say: per variant its samples, median and minimum, and the ratios."""

    def __init__(self, shaders, process_shaders, samples, process_runs, summaries):
        self.shaders, self.process_shaders = shaders, process_shaders
        self.samples, self.process_runs, self.summaries = samples, process_runs, summaries
        # The process pipeline is compared per shader, over the shaders whose two commands both
        # succeeded: timing a command that stops at an error would flatter the baseline.
        self.failures = {}
        for run in process_runs:
            self.failures.update(run["failures"])
        self.process_ok_count = len(process_shaders) - len(self.failures)

    def compute(self):
        shaders = self.shaders
        process_ok_seconds = [run["succeeded_seconds"] for run in self.process_runs]
        # Scaled to the whole tree so the row compares with stereoshift's whole-tree rows.
        tree_scale = len(shaders) / self.process_ok_count
        self.rows = [
            ("process pipeline (glslangValidator + spirv-cross)", [s * tree_scale for s in process_ok_seconds],
             self.process_ok_count),
            ("stereoshift build -j 1 (full)", self.samples["j1"], len(shaders)),
            ("stereoshift build -j 2 (full)", self.samples["j2"], len(shaders)),
            ("stereoshift build -j 1 (no-op rebuild)", self.samples["noop"], len(shaders)),
        ]
        self.median = {name: statistics.median(values) for name, values, _ in self.rows}
        self.minimum = {name: min(values) for name, values, _ in self.rows}
        names = [name for name, _, _ in self.rows]
        self.names = names
        self.cores, self.cpu_count = available_cores(), os.cpu_count()
        self.process_over_j1 = ratio(self.median[names[0]], self.median[names[1]])
        self.process_over_j2 = ratio(self.median[names[0]], self.median[names[2]])
        self.j1_over_j2 = ratio(self.median[names[1]], self.median[names[2]])
        self.noop_percent = 100.0 * ratio(self.median[names[3]], self.median[names[1]])
        self.process_steps = {step: statistics.median(run["step_seconds"][step] for run in self.process_runs)
                              for step in ("glslangValidator", "spirv-cross")}

    def per_shader_ms(self, name):
        return self.median[name] * 1000.0 / len(self.shaders)


def print_tables(f, corpus, args, reps):
    """The variants' table and the ratios against the aims."""
    shaders = f.shaders
    print()
    print("Tree conversion of %s: %d shaders, %d repetition(s), %s" %
          (os.path.relpath(corpus), len(shaders), reps, "quick" if args.quick else "full"))
    print("stereoshift: %s" % args.stereoshift)
    print()
    header = "| variant | shaders | median s | min s | ms/shader |"
    print(header)
    print("| --- | ---: | ---: | ---: | ---: |")
    for name, _, timed in f.rows:
        shown = "%d" % timed if timed == len(shaders) else "%d timed, scaled to %d" % (timed, len(shaders))
        print("| %s | %s | %.3f | %.3f | %.2f |" % (name, shown, f.median[name], f.minimum[name], f.per_shader_ms(name)))
    print()

    def verdict(met):
        return "met" if met else "NOT met"

    core_note = "os.cpu_count() = %s" % f.cpu_count + ("" if f.cores == f.cpu_count else ", %d usable here" % f.cores)
    if f.cores < 2:
        core_note += "; fewer than 2 cores: -j 2 cannot be faster"
    print("| ratio (medians) | measured | aim | |")
    print("| --- | ---: | ---: | --- |")
    print("| process pipeline / stereoshift -j1 | %.1fx | >= %.0fx | %s |" %
          (f.process_over_j1, AIM_PROCESS_OVER_J1, verdict(f.process_over_j1 >= AIM_PROCESS_OVER_J1)))
    print("| stereoshift -j1 / -j2 (%s) | %.2fx | >= %.1fx | %s |" %
          (core_note, f.j1_over_j2, AIM_J1_OVER_J2, verdict(f.j1_over_j2 >= AIM_J1_OVER_J2)))
    print("| no-op rebuild / full -j1 | %.1f%% | <= %.0f%% | %s |" %
          (f.noop_percent, AIM_NOOP_PERCENT, verdict(f.noop_percent <= AIM_NOOP_PERCENT)))
    print("| process pipeline / stereoshift -j2 (the default: one worker per core) | %.1fx | | |" % f.process_over_j2)
    print()


def print_breakdown(f):
    """Where the time goes: glslang's set-up floor, the process pipeline's steps and failures, the
    steps of stereoshift's last -j1 run, and what the reports counted."""
    # The floor under any one-process conversion with glslang: its built-in symbol tables, built once
    # per dialect in a process (the process pipeline builds them once per shader). Read from the last
    # -j1 run's report: in each dialect the first shader's front end carries the set-up, the others not.
    setup = setup_per_dialect(f.summaries["j1"][-1].get("front_end_by_dialect", {}))
    if setup:
        floor_s = sum(setup.values()) / 1000.0
        print("glslang built-in tables, once per dialect in the -j1 run (first shader's front end minus the "
              "dialect's median): %s = %.0f ms; with no other work at all, process pipeline / -j1 could reach "
              "at most %.1fx on this tree" %
              (", ".join("%s %.0f ms" % kv for kv in sorted(setup.items())), floor_s * 1000.0,
               ratio(f.median[f.names[0]], floor_s)))

    # Where the time goes.
    process_shaders = f.process_shaders
    processes_per_shader = 2
    print("process pipeline: %d processes for %d shaders; per shader: glslangValidator %.1f ms, "
          "spirv-cross %.1f ms (medians, failed shaders included)" %
          (processes_per_shader * len(process_shaders), len(process_shaders),
           f.process_steps["glslangValidator"] * 1000.0 / len(process_shaders),
           f.process_steps["spirv-cross"] * 1000.0 / len(process_shaders)))
    if f.failures:
        print("process pipeline: %d of %d shaders failed and are left out of its timing "
              "(the tree row is scaled from the %d that went through):" %
              (len(f.failures), len(process_shaders), f.process_ok_count))
        for rel, why in sorted(f.failures.items()):
            print("  %s: %s" % (rel, why))
    last_j1 = f.summaries["j1"][-1]
    timing_sums = last_j1["timings_ms_sum"]
    if timing_sums:
        # The three steps of a conversion; `pipeline_wall` is per pipeline (repeated on each of its
        # stages) and `total` excludes a pipeline's shared front-end run, so neither is summed.
        steps_measured = ("front_end", "passes", "back_end")
        in_shaders = sum(timing_sums.get(step, 0.0) for step in steps_measured)
        steps = ", ".join("%s %.0f ms" % (step, timing_sums.get(step, 0.0)) for step in steps_measured)
        print("stereoshift -j1, last run: front end, passes and back end of every shader add up to %.0f ms (%s) "
              "of %.0f ms wall; the rest is process start, worker processes, reading and writing files, the "
              "cache and the report" % (in_shaders, steps, f.samples["j1"][-1] * 1000.0))
    for key, label in (("j1", "full -j1"), ("noop", "no-op rebuild")):
        counts = {k: v for k, v in f.summaries[key][-1].items() if k not in ("timings_ms_sum", "front_end_by_dialect")}
        print("report of the %s run: %s" % (label, ", ".join("%s %s" % kv for kv in sorted(counts.items()))))
    not_ok = sum(s["not_ok"] for key in f.summaries for s in f.summaries[key])
    if not_ok:
        print("warning: stereoshift reported %d shader(s) not ok across the runs" % not_ok)


def write_json(path, f, corpus, args, reps):
    figures = {
        "corpus": corpus, "shaders": len(f.shaders), "repetitions": reps, "quick": args.quick,
        "stereoshift": args.stereoshift, "cores_available": f.cores, "cpu_count": f.cpu_count,
        "variants": {
            key: {"name": name, "seconds": values, "median_s": f.median[name], "min_s": f.minimum[name],
                  "ms_per_shader": f.per_shader_ms(name)}
            for key, (name, values, _) in zip(("process_pipeline", "j1", "j2", "noop"), f.rows)
        },
        "process_pipeline": {
            "shaders_timed": f.process_ok_count, "shaders_run": len(f.process_shaders),
            "wall_seconds": [run["seconds"] for run in f.process_runs],
            "step_seconds_median": f.process_steps, "failures": f.failures,
        },
        "ratios": {
            "process_over_j1": {"value": f.process_over_j1, "aim_min": AIM_PROCESS_OVER_J1,
                                "met": f.process_over_j1 >= AIM_PROCESS_OVER_J1},
            "process_over_j2": {"value": f.process_over_j2},
            "j1_over_j2": {"value": f.j1_over_j2, "aim_min": AIM_J1_OVER_J2, "met": f.j1_over_j2 >= AIM_J1_OVER_J2},
            "noop_percent_of_full": {"value": f.noop_percent, "aim_max": AIM_NOOP_PERCENT,
                                     "met": f.noop_percent <= AIM_NOOP_PERCENT},
        },
        "reports": {key: values[-1] for key, values in f.summaries.items()},
    }
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as out:
        json.dump(figures, out, indent=2, sort_keys=True)
        out.write("\n")


def main():
    args = parse_args()
    reps = 1 if args.quick else max(1, args.reps)
    tool = missing_tool(args)
    if tool is not None:
        print("tree_bench: error: %s not found or not executable" % tool, file=sys.stderr)
        return 2
    corpus = os.path.abspath(args.corpus)
    shaders = find_shaders(corpus)
    if not shaders:
        print("tree_bench: error: no shaders under %s" % corpus, file=sys.stderr)
        return 2
    process_shaders = spread_subset(shaders, QUICK_PROCESS_SUBSET) if args.quick else shaders

    own_work_dir = args.work_dir is None
    work_dir = tempfile.mkdtemp(prefix="tree_bench.") if own_work_dir else os.path.abspath(args.work_dir)
    os.makedirs(work_dir, exist_ok=True)
    if os.path.commonpath([work_dir, corpus]) == corpus:
        print("tree_bench: error: --work-dir must not be inside the corpus", file=sys.stderr)
        return 2
    scratch = os.path.join(work_dir, "process-pipeline")
    commands = [(rel, process_pipeline_commands(args.glslang, args.spirv_cross, corpus, rel,
                                                os.path.join(scratch, rel.replace(os.sep, "_") + ".spv"),
                                                os.path.join(scratch, rel.replace(os.sep, "_"))))
                for rel in process_shaders]
    try:
        samples, process_runs, summaries = measure(args, corpus, commands, work_dir, reps)
    except RuntimeError as error:
        print("tree_bench: error: %s" % error, file=sys.stderr)
        return 1
    finally:
        if own_work_dir:
            shutil.rmtree(work_dir, ignore_errors=True)

    figures = Figures(shaders, process_shaders, samples, process_runs, summaries)
    if figures.process_ok_count <= 0:
        print("tree_bench: error: no shader went through glslangValidator + spirv-cross", file=sys.stderr)
        for rel, why in sorted(figures.failures.items()):
            print("  %s: %s" % (rel, why), file=sys.stderr)
        return 1
    figures.compute()
    print_tables(figures, corpus, args, reps)
    print_breakdown(figures)
    if args.json:
        write_json(args.json, figures, corpus, args, reps)
    return 0


if __name__ == "__main__":
    sys.exit(main())
