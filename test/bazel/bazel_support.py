"""What the Bazel integration tests share: a Bazel client with its own output root, the conversion
spawns of one build read from Bazel's execution log, and which targets those spawns belong to."""
import json
import os
import subprocess
import sys
import time

SKIP = 77

# The example's pipelines and the CLI options its BUILD.bazel gives them (kept in step by hand: this
# table is the independent statement of what each target must produce).
PIPELINES = {
    "forward": (["shaders/glsl/forward.vert", "shaders/glsl/forward.frag"],
                ["-I", "shaders/common", "-I", "{bin}/shaders/common"]),
    "skybox": (["shaders/glsl/skybox.vert", "shaders/glsl/skybox.frag"],
               ["--target", "essl", "--eye-source", "push-constant"]),
    "terrain": (["shaders/hlsl/terrain_vs.hlsl", "shaders/hlsl/terrain_ps.hlsl"],
                ["-I", "shaders/common", "-I", "{bin}/shaders/common", "--shift-form=select"]),
}
# Converted one by one (pipeline = False): each is its own CLI command and its own action.
SINGLE_SHADERS = {"standalone": ["shaders/glsl/crosshair.vert", "shaders/glsl/particles.vert"]}
SHARED_INCLUDE = "shaders/common/scene_limits.h"
USERS_OF_SHARED_INCLUDE = {"forward", "terrain"}


def parse_arguments(description, add_more=None):
    """The options both Bazel tests take (and the test's own, from `add_more(parser)`); None when
    bazel is not installed (the test then exits SKIP)."""
    import argparse
    import shutil
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--stereoshift", required=True)
    parser.add_argument("--bazel", default=shutil.which("bazel"))
    if add_more:
        add_more(parser)
    parser.add_argument("--rules", required=True, help="the bazel/ directory of this checkout")
    parser.add_argument("--example", required=True, help="examples/bazel")
    parser.add_argument("--work-dir", required=True)
    args = parser.parse_args()
    if not args.bazel or not shutil.which(args.bazel):
        print("SKIP: bazel is not installed (Debian: apt-get install bazel-bootstrap)")
        return None
    return args


def check(condition, message):
    if not condition:
        sys.exit("FAIL: " + message)


class Bazel:
    def __init__(self, bazel, workspace, output_root, tool, rules):
        self.bazel = bazel
        self.workspace = workspace
        # The user's ~/.bazelrc may add caches or remote services: not here. The system rc stays
        # (Debian's bazel-bootstrap keeps its install base there).
        self.startup = ["--nohome_rc", "--output_user_root=" + output_root, "--max_idle_secs=120"]
        self.flags = ["--repo_env=STEREOSHIFT_TOOL=" + tool, "--override_repository=stereoshift_rules=" + rules]

    def run(self, command, *args, check=True):
        started = time.monotonic()
        p = subprocess.run([self.bazel] + self.startup + [command] + list(args), cwd=self.workspace,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        seconds = time.monotonic() - started
        if check and p.returncode != 0:
            sys.exit(f"FAIL: bazel {command} {' '.join(args)} exited {p.returncode}:\n{p.stdout}")
        return p, seconds

    def build(self, log_path, *extra, check=True):
        p, seconds = self.run("build", *self.flags, "--execution_log_json_file=" + log_path, *extra, "//...", check=check)
        return p, seconds, (read_execution_log(log_path) if os.path.exists(log_path) else [])


def read_execution_log(path):
    """The conversion spawns of one build (Bazel writes a stream of JSON objects, not one array)."""
    text = open(path).read()
    decoder = json.JSONDecoder()
    spawns, at = [], 0
    while True:
        while at < len(text) and text[at].isspace():
            at += 1
        if at >= len(text):
            break
        entry, at = decoder.raw_decode(text, at)
        if entry.get("mnemonic") == "StereoshiftConvert":
            spawns.append(entry)
    return spawns


def pipelines_run(spawns):
    """Which targets' actions ran: an output path is <bin>/<target>/<file>."""
    names = set()
    for spawn in spawns:
        for output in spawn.get("listedOutputs", []):
            names.add(output.split("/")[-2])
    return names


def edit_shared_include(workspace):
    """An edit of the include two pipelines share that changes their outputs (a touch that keeps the
    bytes is no change to Bazel): the fog density flips between two values."""
    include = os.path.join(workspace, SHARED_INCLUDE)
    text = open(include).read()
    edited = text.replace("0.015", "0.02") if "0.015" in text else text.replace("0.02", "0.015")
    check(edited != text, "the shared include has no fog density to edit")
    open(include, "w").write(edited)
