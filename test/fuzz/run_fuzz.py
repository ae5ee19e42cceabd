#!/usr/bin/env python3
"""Runs the libFuzzer targets of test/fuzz (sanitizer build only).

  run_fuzz.py fuzz --bin-dir B --seeds S --work W --runs       each target for a fixed number of inputs (CI)
  run_fuzz.py fuzz --bin-dir B --seeds S --work W --seconds N   each target for N seconds (exploring)
  run_fuzz.py replay --target T --inputs DIR                    every kept input once (ctest)

A crash in our code, a sanitizer report, a timeout or a leak exits non-zero; `fuzz` names the input
that did it, which belongs under test/fuzz/regressions/<target>/ once looked at.

A crash whose faulting frames (the first stack of the report, before the first frame of our own code)
are all in a packaged library (glslang, SPIRV-Tools, SPIRV-Cross) is a known third-party crash: `fuzz`
keeps the input under W/<target>/third-party-crashes/, says where it crashed and fuzzes on from the same
corpus for the rest of the target's budget.

`--runs` is the CI mode and does not depend on the machine's speed: each target starts from the seeds
alone (the corpus earlier runs grew is set aside), with a fixed libFuzzer seed, for a fixed number of
executions (RUN_BUDGET, or --runs-scale times it). The same tree gives the same inputs on a busy machine
as on an idle one, only later; a wall-clock cap (--seconds, generous) only stops a run early, which is
never a failure. `--seconds` alone keeps the corpus from run to run and explores for that long. `replay` runs the inputs of DIR/known-*-crashes/ one by
one and accepts each that passes or crashes in that same library, and nothing else."""
import argparse
import hashlib
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
SOURCE_ROOT = HERE.parents[1]
TARGETS = ["fuzz_transpile_glsl", "fuzz_transpile_hlsl", "fuzz_transpile_spirv", "fuzz_decompiled_dump", "fuzz_scene_manifest",
           "fuzz_reproject_options"]
DICTIONARIES = {"fuzz_scene_manifest": HERE / "scene.dict",  # the others: shader.dict
                "fuzz_reproject_options": HERE / "reproject.dict"}
# One input that takes longer than this is a finding (a hang or a super-linear blow-up); generous, so a
# loaded CI machine does not report a slow but finite input.
INPUT_TIMEOUT_S = 60
RSS_LIMIT_MB = 4096
# Executions per target in --runs mode: about 25-30 s each on one idle core of the CI machine's kind
# under ASan + UBSan (the transpile targets run the whole glslang front end per input; SPIR-V input
# skips it), which keeps the whole suite within its time on two cores.
# fuzz_decompiled_dump writes a whole decompiled shader per input and converts it (about 4 a second
# under ASan): a small budget, spent on programs the parser accepts.
RUN_BUDGET = {"fuzz_transpile_glsl": 7200, "fuzz_transpile_hlsl": 9000, "fuzz_transpile_spirv": 120000,
              "fuzz_decompiled_dump": 120, "fuzz_scene_manifest": 30000, "fuzz_reproject_options": 6000}
# After a third-party crash the fuzzer restarts (reloading the corpus) only if this much time is left.
MIN_RESTART_S = 3

# --- Where a crash happened -------------------------------------------------------------------------
# The packaged libraries are linked statically (Debian ships glslang and SPIRV-Tools as .a), so their
# frames are in the fuzz binary too: `#3 0x5f... in glslang::HlslGrammar::acceptDeclaration(...)
# (/path/fuzz_transpile_hlsl+0x1c2d3e)`, without a source line (they have no debug info), while our
# frames carry one (`... in stereoshift::transpile(...) /src/transpiler/transpile.cpp:12:3`). So a frame
# is placed by its function's namespace first, then by its source file, then by its module (for a
# shared library: `(/lib/x86_64-linux-gnu/libglslang.so.11+0x...)`).
THIRD_PARTY_NAMESPACES = {"glslang": "glslang", "spv": "glslang",  # glslang's SPIR-V builder
                          "spvtools": "spirv-tools", "spirv_cross": "spirv-cross"}
THIRD_PARTY_FUNCTIONS = [  # their C entry points and glslang's generated parser, outside a namespace
    (re.compile(r"(yy\w*|Sh[A-Z]\w*|glslang_\w*|InitializeProcess|FinalizeProcess)$"), "glslang"),
    (re.compile(r"spvc_\w*$"), "spirv-cross"),
    (re.compile(r"spv[A-Z]\w*$"), "spirv-tools")]
THIRD_PARTY_MODULES = [
    (re.compile(r"lib(glslang|SPIRV(?!-Tools)|HLSL|MachineIndependent|OSDependent|GenericCodeGen|OGLCompiler)"
                r"[\w.+-]*\.(so|a)", re.I), "glslang"),
    (re.compile(r"libSPIRV-Tools[\w.+-]*\.(so|a)", re.I), "spirv-tools"),
    (re.compile(r"libspirv-cross[\w.+-]*\.(so|a)", re.I), "spirv-cross")]
THIRD_PARTY_SOURCES = [(re.compile(r"/glslang/|/(HLSL|MachineIndependent)/"), "glslang"),
                       (re.compile(r"SPIRV-Tools|spirv-tools"), "spirv-tools"),
                       (re.compile(r"SPIRV-Cross|spirv[-_]cross", re.I), "spirv-cross")]
OUR_DIRECTORIES = ("core", "passes", "transpiler", "cli", "test", "include", "runtime", "src")
# Frames that belong to whoever called them: the C and C++ runtimes, the sanitizers and libFuzzer.
NEUTRAL_MODULES = re.compile(r"(^|/)(libc|libstdc\+\+|libgcc_s|libm|libpthread|libdl|librt|ld-linux[\w-]*)"
                             r"[\w.-]*\.so|<unknown module>|linux-vdso")
NEUTRAL_PREFIXES = ("std::", "__gnu_cxx::", "__cxxabiv1::", "__cxa_", "__asan", "__lsan", "__ubsan",
                    "__sanitizer", "__interceptor", "__interception::", "__libc_", "__GI_", "__pthread", "fuzzer::",
                    "operator new", "operator delete", "_start")
NEUTRAL_FUNCTIONS = {"malloc", "calloc", "realloc", "free", "memcpy", "memmove", "memset", "memcmp", "bcmp",
                     "strlen", "strnlen", "strcmp", "strncmp", "strcpy", "strncpy", "strchr", "strrchr",
                     "strstr", "strdup", "abort", "raise", "pthread_kill", "__assert_fail", "__assert_fail_base",
                     "gsignal", "exit", "_exit", "qsort", "bsearch"}
NEUTRAL_SOURCES = re.compile(r"compiler-rt/|/usr/include/c\+\+/|/libstdc\+\+|/glibc|sysdeps/"  # glibc's own paths:
                             r"|^(nptl|signal|stdlib|string|libio|malloc|assert|elf|csu|posix|misc|stdio-common)/")

FRAME = re.compile(r"^\s*#(\d+)\s+(0x[0-9a-fA-F]+)\s*(.*)$")
REPORT_START = re.compile(r"==\d+==\s*ERROR: (\w+): (.*)$|^(?:.*?: )?runtime error: ")


def parse_frame(line):
    """{'pc', 'function', 'module', 'source'} of one `#N 0x... in FUNC LOCATION` line, or None."""
    match = FRAME.match(line)
    if not match:
        return None
    rest = re.sub(r"\s*\(BuildId: [0-9a-fA-F]+\)$", "", match.group(3).strip())
    module = source = None
    located = re.search(r"\s*\(([^()]*)\+0x[0-9a-fA-F]+\)$", rest)
    if located:
        module, rest = located.group(1), rest[:located.start()]
    elif rest.endswith("(<unknown module>)"):
        module, rest = "<unknown module>", rest[:-len("(<unknown module>)")]
    elif rest.startswith("in "):
        head, _, tail = rest.rpartition(" ")
        # a source file (`/src/x.cpp:12:3`), or an archive member without line info (`ShaderLang.cpp.o`)
        if head and (tail.startswith("/") or re.search(r":\d+(:\d+)?$|\.o$", tail)):
            source, rest = tail, head
    function = rest[3:].strip() if rest.startswith("in ") else rest.strip()
    return {"pc": match.group(2), "function": function, "module": module, "source": source}


def qualified_name(function):
    """`glslang::TParseContextBase::growGlobalUniformBlock` of a demangled signature (its arguments and,
    for a template, its return type cut off)."""
    text = function.replace("(anonymous namespace)", "{anonymous}")
    depth, cut, spaces = 0, len(text), []
    for i, c in enumerate(text):
        if c == "<":
            depth += 1
        elif c == ">":
            depth = max(0, depth - 1)
        elif c == "(" and depth == 0 and not text[:i].endswith("operator"):
            cut = i
            break
        elif c == " " and depth == 0:
            spaces.append(i)
    head = text[:cut]
    spaces = [i for i in spaces if i < cut and not head[:i].endswith("operator")]
    return head[spaces[-1] + 1:] if spaces else head


def is_our_source(path):
    path = path.split(":")[0]
    if path.startswith(str(SOURCE_ROOT) + "/"):
        return True
    # Built from another checkout of the same tree (a CI workspace, a copy): the same file under ours.
    parts = pathlib.PurePosixPath(path).parts
    for i, part in enumerate(parts):
        if part in OUR_DIRECTORIES and (SOURCE_ROOT.joinpath(*parts[i:])).is_file():
            return True
    return False


def place(frame):
    """('ours' | 'third-party' | 'neutral' | 'unknown', library or None) for one frame."""
    function, module, source = frame["function"], frame["module"], frame["source"]
    name = qualified_name(function) if function else ""
    if name.startswith("stereoshift::") or name.startswith("LLVMFuzzer") or name == "main" \
            or (source and is_our_source(source)):
        return "ours", None
    namespace = name.split("::")[0] if "::" in name else None
    if namespace in THIRD_PARTY_NAMESPACES:
        return "third-party", THIRD_PARTY_NAMESPACES[namespace]
    for pattern, library in THIRD_PARTY_FUNCTIONS:
        if pattern.match(name):
            return "third-party", library
    for pattern, library in THIRD_PARTY_SOURCES if source else []:
        if pattern.search(source):
            return "third-party", library
    for pattern, library in THIRD_PARTY_MODULES if module else []:
        if pattern.search(module):
            return "third-party", library
    if function.startswith(NEUTRAL_PREFIXES) or name.startswith(NEUTRAL_PREFIXES) \
            or re.sub(r"\.(part|isra|constprop|cold)\.\d+$", "", name) in NEUTRAL_FUNCTIONS \
            or (module and NEUTRAL_MODULES.search(module)) or (source and NEUTRAL_SOURCES.search(source)):
        return "neutral", None
    return "unknown", None


def triage(text):
    """Where the first sanitizer or libFuzzer report in `text` happened: a dict with 'owner' ('ours' or
    'third-party'), 'library', 'error' (e.g. 'AddressSanitizer: SEGV'), 'frame' (the first faulting
    third-party frame, as `NAME (LOCATION)`) and 'caller'. Anything unclear counts as ours."""
    lines = text.splitlines()
    start = next((i for i, line in enumerate(lines) if REPORT_START.search(line)), None)
    result = {"owner": "ours", "library": None, "error": "no sanitizer report", "frame": None, "caller": None}
    if start is None:
        return result
    header = REPORT_START.search(lines[start])
    if header.group(1) is None:  # UBSan: only our code is instrumented
        result["error"] = "UndefinedBehaviorSanitizer: " + lines[start].split("runtime error: ", 1)[1]
        return result
    kind = header.group(2).split(" on ")[0].split(" (")[0].strip()
    result["error"] = f"{header.group(1)}: {kind}"
    if header.group(1) not in ("AddressSanitizer", "libFuzzer") or kind in ("timeout", "out-of-memory") \
            or kind.startswith("out-of-memory"):
        return result  # a leak, a timeout, running out of memory: ours to look at
    frames = []
    for line in lines[start + 1:]:
        frame = parse_frame(line)
        if frame:
            frames.append(frame)
        elif frames:
            break  # the first stack only (the access; not `freed by` or `allocated by`)
    # Frames inlined into one function share its pc: the function they were compiled into decides.
    groups = []
    for frame in frames:
        if groups and groups[-1][-1]["pc"] == frame["pc"]:
            groups[-1].append(frame)
        else:
            groups.append([frame])
    seen = None
    for group in groups:
        owner, library = place(group[-1])
        if owner == "neutral":
            continue
        if owner != "third-party":
            break  # ours, or a frame nobody can place: not a third-party crash unless theirs came first
        if seen is None:
            seen = (group[-1], library)
        elif result["caller"] is None and qualified_name(group[-1]["function"]) != qualified_name(
                seen[0]["function"]):
            result["caller"] = qualified_name(group[-1]["function"])
    if seen is not None:
        frame, library = seen
        where = pathlib.PurePath(frame["source"] or frame["module"]).name
        result.update(owner="third-party", library=library,
                      frame=f"{qualified_name(frame['function']) or '??'} ({where})")
    return result


def sanitizer_environment():
    env = dict(os.environ)
    if "ASAN_SYMBOLIZER_PATH" not in env and not shutil.which("llvm-symbolizer"):
        for candidate in ("llvm-symbolizer-14", "/usr/lib/llvm-14/bin/llvm-symbolizer"):
            if shutil.which(candidate):
                env["ASAN_SYMBOLIZER_PATH"] = shutil.which(candidate)
                break
    return env


# --- replay ------------------------------------------------------------------------------------------

def input_files(folder):
    return sorted(p for p in folder.glob("*") if p.is_file() and not p.name.startswith(".")
                  and p.suffix != ".md") if folder.is_dir() else []


def replay(args):
    # The files directly in the folder must pass; known-<library>-crashes/ below it may crash in <library>.
    inputs = input_files(args.inputs)
    known = {folder: input_files(folder) for folder in sorted(args.inputs.glob("known-*-crashes"))}
    if not inputs and not any(known.values()):
        print(f"run_fuzz: no regression inputs in {args.inputs}")
        return 0
    env = sanitizer_environment()
    failed = False
    with tempfile.TemporaryDirectory(prefix="run_fuzz_") as scratch:
        flags = [f"-timeout={INPUT_TIMEOUT_S}", f"-rss_limit_mb={RSS_LIMIT_MB}", f"-artifact_prefix={scratch}/"]
        if inputs:
            # Given files, a libFuzzer binary runs each once and does not fuzz.
            result = subprocess.run([str(args.target)] + flags + [str(p) for p in inputs], env=env)
            print(f"run_fuzz: {len(inputs)} inputs replayed through {args.target.name}: "
                  + ("ok" if result.returncode == 0 else f"FAILED (exit {result.returncode})"))
            failed |= result.returncode != 0
        for folder, files in known.items():
            expected = folder.name[len("known-"):-len("-crashes")]  # glslang
            for path in files:  # one process each: a crash ends the process
                result = subprocess.run([str(args.target)] + flags + [str(path)], env=env,
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
                text = result.stdout.decode(errors="replace")
                where = f"{folder.name}/{path.name}"
                if result.returncode == 0:
                    print(f"run_fuzz: {where}: no longer crashes (move it up into {args.inputs.name}/): ok")
                    continue
                verdict = triage(text)
                if verdict["owner"] == "third-party" and verdict["library"] == expected:
                    print(f"run_fuzz: {where}: known {expected} crash ({verdict['error']} in {verdict['frame']}): ok")
                    continue
                failed = True
                print(text[-12000:])
                print(f"run_fuzz: {where}: FAILED: expected a crash inside {expected} or none, got "
                      f"{verdict['error']}" + (f" in {verdict['library']}" if verdict["library"] else " in our code"))
    return 1 if failed else 0


# --- fuzz --------------------------------------------------------------------------------------------

def content_hash(path):
    return hashlib.sha1(path.read_bytes()).hexdigest()


def drop_from_startup(artifact, corpus, seeds, excluded):
    """A third-party crash while libFuzzer read its corpus would recur on every restart: take the input
    out of the work corpus, or leave it out of the seeds. False if it is in neither."""
    digest = content_hash(artifact)
    found = False
    for path in corpus.iterdir():
        if path.is_file() and content_hash(path) == digest:
            path.unlink()
            found = True
    if seeds.is_dir() and any(p.is_file() and content_hash(p) == digest for p in seeds.iterdir()):
        excluded.add(digest)
        found = True
    return found


def filtered_seeds(seeds, excluded, into):
    shutil.rmtree(into, ignore_errors=True)
    into.mkdir(parents=True)
    for path in seeds.iterdir():
        if path.is_file() and content_hash(path) not in excluded:
            shutil.copy2(path, into / path.name)
    return into


def fuzz_target(name, args, env):
    binary = args.bin_dir / name
    # Grows from run to run in the build tree; the --runs mode starts each time from the seeds alone.
    corpus = args.work / ("corpus-fixed" if args.runs else "corpus") / name
    if args.runs and corpus.exists():
        shutil.rmtree(corpus)
    budget = int(RUN_BUDGET[name] * args.runs_scale) if args.runs else None
    artifacts = args.work / "artifacts" / name
    third_party_dir = args.work / name / "third-party-crashes"
    seeds = args.seeds / name
    for folder in (corpus, artifacts):
        folder.mkdir(parents=True, exist_ok=True)
    log = args.work / f"{name}.log"
    log.write_text("")
    started = time.monotonic()
    deadline = started + args.seconds
    executions, sessions, third_party, ours, excluded = 0, 0, [], [], set()
    failure_text = ""
    while True:
        remaining = deadline - time.monotonic()
        if sessions and remaining < MIN_RESTART_S:
            break
        seed_dir = filtered_seeds(seeds, excluded, args.work / name / "seeds") if excluded else seeds
        if budget is not None and sessions and executions >= budget:
            break
        pinned = [f"-seed={sessions + 1}", f"-runs={budget - executions}"] if budget is not None else []
        command = [str(binary), *pinned, f"-max_total_time={max(1, int(remaining))}", f"-timeout={INPUT_TIMEOUT_S}",
                   f"-rss_limit_mb={RSS_LIMIT_MB}", f"-dict={DICTIONARIES.get(name, HERE / 'shader.dict')}",
                   f"-artifact_prefix={artifacts}/", "-print_final_stats=1", str(corpus), str(seed_dir)]
        sessions += 1
        offset = log.stat().st_size
        with open(log, "a") as out:
            out.write(f"run_fuzz: session {sessions}: {' '.join(command)}\n")
            out.flush()
            result = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, env=env)
        with open(log, "rb") as stream:
            stream.seek(offset)
            text = stream.read().decode(errors="replace")
        runs = re.findall(r"stat::number_of_executed_units:\s*(\d+)", text)
        executions += int(runs[-1]) if runs else 0
        if result.returncode == 0:
            break  # its budget (runs or time) is spent
        written = re.findall(r"Test unit written to (\S+)", text)
        artifact = pathlib.Path(written[-1]) if written else None
        verdict = triage(text)
        if artifact is None or not artifact.is_file() or not artifact.name.startswith("crash-") \
                or verdict["owner"] != "third-party":
            ours.append(artifact)
            failure_text = text
            break
        third_party_dir.mkdir(parents=True, exist_ok=True)
        kept = third_party_dir / artifact.name
        shutil.move(str(artifact), str(kept))
        third_party.append(kept)
        left = deadline - time.monotonic()
        print(f"run_fuzz: {name}: known third-party crash in {verdict['library']}: {verdict['error']} in "
              f"{verdict['frame']}" + (f" from {verdict['caller']}" if verdict["caller"] else "")
              + f"; input kept as {kept}; " + (f"fuzzing on ({budget - executions} runs left)" if budget is not None
                                               and left >= MIN_RESTART_S
                                               else f"fuzzing on ({left:.0f} s left)" if left >= MIN_RESTART_S
                                               else "no time left"))
        if "INITED" not in text and not drop_from_startup(kept, corpus, seeds, excluded):
            print(f"run_fuzz: {name}: it crashed while reading the corpus and is in neither {corpus} nor "
                  f"{seeds}; not restarting")
            break
    elapsed = time.monotonic() - started
    status = "FAILED" if ours else "ok"
    print(f"run_fuzz: {name}: {executions} executions in {elapsed:.0f} s ({sessions} session"
          f"{'s' if sessions != 1 else ''}), {len(list(corpus.iterdir()))} corpus inputs, crashes: "
          f"{len(ours)} ours, {len(third_party)} third-party: {status}")
    if ours:
        print("\n".join(failure_text.splitlines()[-60:]))
        if ours[-1] is not None:
            print(f"run_fuzz: {name}: input {ours[-1]} (keep it under test/fuzz/regressions/{name}/)")
        else:
            print(f"run_fuzz: {name}: the fuzzer stopped without writing an input; see {log}")
    return executions, bool(ours)


def fuzz(args):
    env = sanitizer_environment()
    failed = []
    total_runs = 0
    for name in args.targets or TARGETS:
        runs, target_failed = fuzz_target(name, args, env)
        total_runs += runs
        if target_failed:
            failed.append(name)
    print(f"run_fuzz: {total_runs} executions in all" + (f"; failed: {', '.join(failed)}" if failed else ""))
    return 1 if failed else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    modes = parser.add_subparsers(dest="mode", required=True)
    f = modes.add_parser("fuzz")
    f.add_argument("--bin-dir", required=True, type=pathlib.Path)
    f.add_argument("--seeds", required=True, type=pathlib.Path)
    f.add_argument("--work", required=True, type=pathlib.Path)
    f.add_argument("--seconds", type=int, default=None,
                   help="wall-clock limit per target (default 45; with --runs, a cap of 240)")
    f.add_argument("--runs", action="store_true", help="a fixed execution budget per target, from the seeds "
                   "alone with a fixed libFuzzer seed (CI: independent of the machine's speed)")
    f.add_argument("--runs-scale", type=float, default=1.0, help="multiply each --runs budget")
    f.add_argument("--targets", nargs="*", help="default: all of them")
    r = modes.add_parser("replay")
    r.add_argument("--target", required=True, type=pathlib.Path)
    r.add_argument("--inputs", required=True, type=pathlib.Path)
    args = parser.parse_args()
    if args.mode == "fuzz" and args.seconds is None:
        args.seconds = 240 if args.runs else 45
    return fuzz(args) if args.mode == "fuzz" else replay(args)


if __name__ == "__main__":
    sys.exit(main())
