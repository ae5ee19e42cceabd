#!/usr/bin/env python3
"""Runs the libFuzzer targets of test/fuzz (sanitizer build only).

  run_fuzz.py fuzz --bin-dir B --seeds S --work W --seconds N   each target for N seconds (CI)
  run_fuzz.py replay --target T --inputs DIR                    every kept input once (ctest)

A crash, a sanitizer report, a timeout or a leak exits non-zero; `fuzz` names the input that did
it, which belongs under test/fuzz/regressions/<target>/ once looked at."""
import argparse
import pathlib
import re
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
TARGETS = ["fuzz_transpile_glsl", "fuzz_transpile_hlsl", "fuzz_transpile_spirv", "fuzz_scene_manifest"]
DICTIONARIES = {"fuzz_scene_manifest": HERE / "scene.dict"}  # the others: shader.dict
# One input that takes longer than this is a finding (a hang or a super-linear blow-up); generous, so a
# loaded CI machine does not report a slow but finite input.
INPUT_TIMEOUT_S = 60
RSS_LIMIT_MB = 4096


def replay(args):
    # Only the files directly in the folder: known-glslang-crashes/ below it is not replayed.
    inputs = sorted(p for p in args.inputs.glob("*") if p.is_file() and not p.name.startswith(".")
                    and p.suffix != ".md") if args.inputs.is_dir() else []
    if not inputs:
        print(f"run_fuzz: no regression inputs in {args.inputs}")
        return 0
    # Given files, a libFuzzer binary runs each once and does not fuzz.
    result = subprocess.run([str(args.target), f"-timeout={INPUT_TIMEOUT_S}", f"-rss_limit_mb={RSS_LIMIT_MB}"]
                            + [str(p) for p in inputs])
    print(f"run_fuzz: {len(inputs)} inputs replayed through {args.target.name}: "
          + ("ok" if result.returncode == 0 else f"FAILED (exit {result.returncode})"))
    return 0 if result.returncode == 0 else 1


def fuzz(args):
    failed = []
    total_runs = 0
    for name in args.targets or TARGETS:
        binary = args.bin_dir / name
        corpus = args.work / "corpus" / name     # grows from run to run in the build tree
        artifacts = args.work / "artifacts" / name
        corpus.mkdir(parents=True, exist_ok=True)
        artifacts.mkdir(parents=True, exist_ok=True)
        log = args.work / f"{name}.log"
        command = [str(binary), f"-max_total_time={args.seconds}", f"-timeout={INPUT_TIMEOUT_S}",
                   f"-rss_limit_mb={RSS_LIMIT_MB}", f"-dict={DICTIONARIES.get(name, HERE / 'shader.dict')}",
                   f"-artifact_prefix={artifacts}/", "-print_final_stats=1", str(corpus), str(args.seeds / name)]
        started = time.monotonic()
        with open(log, "w") as out:
            result = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT)
        elapsed = time.monotonic() - started
        text = log.read_text(errors="replace")
        runs = re.search(r"stat::number_of_executed_units:\s*(\d+)", text)
        runs = int(runs.group(1)) if runs else 0
        total_runs += runs
        print(f"run_fuzz: {name}: {runs} executions in {elapsed:.0f} s, "
              f"{len(list(corpus.iterdir()))} corpus inputs: " + ("ok" if result.returncode == 0 else "FAILED"))
        if result.returncode != 0:
            failed.append(name)
            print("\n".join(text.splitlines()[-60:]))
            for artifact in sorted(artifacts.iterdir()):
                print(f"run_fuzz: {name}: input {artifact} (keep it under test/fuzz/regressions/{name}/)")
    print(f"run_fuzz: {total_runs} executions in all" + (f"; failed: {', '.join(failed)}" if failed else ""))
    return 1 if failed else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    modes = parser.add_subparsers(dest="mode", required=True)
    f = modes.add_parser("fuzz")
    f.add_argument("--bin-dir", required=True, type=pathlib.Path)
    f.add_argument("--seeds", required=True, type=pathlib.Path)
    f.add_argument("--work", required=True, type=pathlib.Path)
    f.add_argument("--seconds", type=int, default=45)
    f.add_argument("--targets", nargs="*", help="default: all of them")
    r = modes.add_parser("replay")
    r.add_argument("--target", required=True, type=pathlib.Path)
    r.add_argument("--inputs", required=True, type=pathlib.Path)
    args = parser.parse_args()
    return fuzz(args) if args.mode == "fuzz" else replay(args)


if __name__ == "__main__":
    sys.exit(main())
