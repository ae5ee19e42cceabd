#!/usr/bin/env python3
"""service.*: the conversion service (cli/service_*) end to end, one behaviour per --case.

  identical     every command gives the same exit status, stdout, stderr and output bytes (depfiles
                included) through the service as in-process, in several dialects, stdin and errors too
  concurrent    8 commands start at once with no server: exactly one server starts, all are served
  crash         a shader that crashes glslang: reported as in-process, and the server lives on
  killed        the server (and its workers) killed in the middle of a build: every command still
                succeeds with the same bytes; a server that answers garbage is not believed either
  stale         a copy of the tool, then the copy touched: each gets its own server
  private_dir   a socket directory that others could enter is refused: in-process, with a warning

Every case runs in its own scratch directory (the servers' too) with a short idle exit, and kills
whatever server it started before it ends. The shaders are written here, in the conventions of
public samples (Vulkan GLSL with includes, GL 3.3 core, ESSL, HLSL named basicVS/basicPS).
"""
import argparse
import concurrent.futures
import fcntl
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SHADERS = {
    "include/camera.glsl": """#ifndef CAMERA_GLSL
#define CAMERA_GLSL
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; vec3 eye; } camera;
#endif
""",
    "vk/mesh.vert": """#version 450
#extension GL_GOOGLE_include_directive : require
#include "camera.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inUV;
layout(location = 0) out vec2 outUV;
void main() {
  outUV = inUV;
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
""",
    "vk/mesh.frag": """#version 450
layout(set = 0, binding = 1) uniform sampler2D albedo;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main() { outColor = texture(albedo, inUV); }
""",
    "gl/4.1.blending.vs": """#version 330 core
layout (location = 0) in vec3 aPos;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
void main() { gl_Position = projection * view * model * vec4(aPos, 1.0); }
""",
    "gl/4.1.blending.fs": """#version 330 core
out vec4 FragColor;
uniform vec4 tint;
void main() { FragColor = tint; }
""",
    "es/sprite.vert": """#version 300 es
in vec4 a_position;
uniform mat4 u_mvp;
void main() { gl_Position = u_mvp * a_position; }
""",
    "hlsl/basicVS.hlsl": """cbuffer PerFrame : register(b0) { float4x4 worldViewProj; };
struct VSOut { float4 pos : SV_Position; float3 color : COLOR0; };
VSOut main(float3 pos : POSITION, float3 color : COLOR0) {
  VSOut o;
  o.pos = mul(worldViewProj, float4(pos, 1.0));
  o.color = color;
  return o;
}
""",
    "hlsl/basicPS.hlsl": """float4 main(float4 pos : SV_Position, float3 color : COLOR0) : SV_Target {
  return float4(color, 1.0);
}
""",
    "broken/typo.vert": """#version 450
void main() { gl_Position = vec4(0.0) +; }
""",
}

# (name, arguments after the tool, relative to the work directory, stdin file or None)
COMMANDS = [
    ("vulkan pipeline with an include", ["--pipeline", "vk/mesh.vert,vk/mesh.frag", "-I", "include", "-o", "out/vk",
                                         "--depfile", "out/vk.d"], None),
    ("GL 3.3 pipeline to ESSL", ["--pipeline", "gl/4.1.blending.vs,gl/4.1.blending.fs", "--target", "essl",
                                 "-o", "out/gl"], None),
    ("ESSL single shader", ["es/sprite.vert", "-o", "out/sprite.vert", "--depfile", "out/sprite.d"], None),
    ("HLSL pipeline to MSL", ["--pipeline", "hlsl/basicVS.hlsl,hlsl/basicPS.hlsl", "--target", "msl", "-o", "out/hlsl"], None),
    ("HLSL to standard output", ["hlsl/basicVS.hlsl", "-o", "-"], None),
    ("stdin to standard output", ["-", "-S", "vert", "-I", "include", "-o", "-"], "vk/mesh.vert"),
    ("a shader with an error", ["broken/typo.vert", "-o", "out/typo.vert"], None),
    ("a report", ["vk/mesh.vert", "-I", "include", "-o", "out/report.vert", "--report", "out/report.json"], None),
]

CRASHER = ("#define A ((((((((((\n#define Z ))))))))))\nfloat4 main(float4 p : POSITION) : SV_Position {\n  return "
           + "A " * 1000 + "p" + " Z" * 1000 + ";\n}\n")

SERVICE_NOTE = "stereoshift: service: "
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print(f"FAIL: {message}", flush=True)
    return condition


class Scratch:
    """A work directory with the shaders, and a private service directory for this case's servers."""

    def __init__(self, tool):
        # Short, under /tmp: a Unix socket path has at most 107 bytes.
        self.root = Path(tempfile.mkdtemp(prefix="sts-"))
        self.work = self.root / "w"
        self.service = self.root / "s"
        self.service.mkdir(mode=0o700)
        self.tool = str(tool)
        for name, text in SHADERS.items():
            path = self.work / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        (self.work / "out").mkdir()

    def environment(self, **extra):
        env = {k: v for k, v in os.environ.items() if not k.startswith("STEREOSHIFT_")}
        env.update(STEREOSHIFT_SERVICE_DIR=str(self.service), STEREOSHIFT_SERVICE_IDLE="4")
        env.update(extra)
        return env

    def run(self, arguments, service, stdin_file=None, tool=None, env=None):
        """(exit status, stdout bytes, stderr bytes without the service's notes, whether it was served)."""
        flag = "--service" if service else "--no-service"
        stdin = open(self.work / stdin_file, "rb") if stdin_file else subprocess.DEVNULL
        try:
            result = subprocess.run([tool or self.tool, flag, *arguments], cwd=self.work, stdin=stdin,
                                    capture_output=True, timeout=120,
                                    env=env or self.environment(STEREOSHIFT_SERVICE_LOG="1"))
        finally:
            if stdin_file:
                stdin.close()
        lines = result.stderr.decode(errors="replace").splitlines(keepends=True)
        notes = [l for l in lines if l.startswith(SERVICE_NOTE)]
        stderr = "".join(l for l in lines if not l.startswith(SERVICE_NOTE))
        served = any("served by the server" in n for n in notes)
        return result.returncode, result.stdout, stderr, served

    def outputs(self):
        """Every output's bytes; a JSON report without its timings (which no two runs share)."""
        found = {}
        for p in sorted((self.work / "out").rglob("*")):
            if p.is_file():
                data = p.read_bytes()
                if p.suffix == ".json":
                    data = json.dumps(without_timings(json.loads(data)), sort_keys=True).encode()
                # The mode too: a worker must create files as the command would (its umask).
                found[p.relative_to(self.work).as_posix()] = (oct(p.stat().st_mode), data)
        return found

    def clear_outputs(self):
        shutil.rmtree(self.work / "out")
        (self.work / "out").mkdir()

    def log(self):
        path = self.service / "service.log"
        return path.read_text().splitlines() if path.exists() else []

    def started_servers(self):
        """(pid, identity) of every server that started in this case."""
        found = []
        for line in self.log():
            words = line.split()
            if len(words) >= 5 and words[0] == "server" and words[2] == "started":
                found.append((int(words[1]), words[4].rstrip(")")))
        return found

    def running_pid(self):
        pid_files = list(self.service.glob("*.pid"))
        return int(pid_files[0].read_text()) if len(pid_files) == 1 else None

    def close(self):
        for pid, _ in self.started_servers():
            kill_group_of(pid)
        shutil.rmtree(self.root, ignore_errors=True)


def without_timings(report):
    if isinstance(report, dict):
        return {k: without_timings(v) for k, v in report.items() if k != "timings_ms"}
    if isinstance(report, list):
        return [without_timings(v) for v in report]
    return report


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    try:
        return "stereoshift" in Path(f"/proc/{pid}/cmdline").read_text(errors="replace")
    except OSError:
        return False


def kill_group_of(pid):
    """Kills a server and its workers (they share its process group); only a stereoshift process."""
    if not alive(pid):
        return
    try:
        os.killpg(os.getpgid(pid), signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    for _ in range(100):
        if not alive(pid):
            return
        time.sleep(0.02)


def case_identical(s):
    for name, arguments, stdin_file in COMMANDS:
        s.clear_outputs()
        expected = s.run(arguments, service=False, stdin_file=stdin_file)
        expected_outputs = s.outputs()
        s.clear_outputs()
        got = s.run(arguments, service=True, stdin_file=stdin_file)
        check(got[3], f"{name}: the service did not serve the command")
        check(got[0] == expected[0], f"{name}: exit status {got[0]} through the service, {expected[0]} in-process")
        check(got[1] == expected[1], f"{name}: stdout differs through the service")
        check(got[2] == expected[2], f"{name}: stderr differs through the service:\n{got[2]}\n--- in-process:\n{expected[2]}")
        check(s.outputs() == expected_outputs,
              f"{name}: output files differ through the service: {sorted(s.outputs())} vs {sorted(expected_outputs)}")
        check(expected_outputs or expected[1] or expected[0], f"{name}: the command produced nothing (the test is wrong)")
    check(len(s.started_servers()) == 1, f"one server expected for the whole case, {len(s.started_servers())} started")


def case_concurrent(s):
    arguments = COMMANDS[0][1]
    expected = s.run(arguments, service=False)
    expected_outputs = s.outputs()
    s.clear_outputs()
    # The worst case, made certain: every job finds no server and then waits for the start lock,
    # which the test holds until all eight are waiting. (The lock's name is the tool's identity,
    # learnt from a server started, and stopped, in another directory.)
    probe = s.root / "probe"
    probe.mkdir(mode=0o700)
    s.run(COMMANDS[2][1], service=True, env=s.environment(STEREOSHIFT_SERVICE_DIR=str(probe)))
    probe_log = (probe / "service.log").read_text().split()
    kill_group_of(int(probe_log[1]))
    identity = probe_log[4].rstrip(")")
    env = s.environment(STEREOSHIFT_SERVICE_LOG="1")
    lock = os.open(s.service / f"{identity}.lock", os.O_RDWR | os.O_CREAT, 0o600)
    fcntl.flock(lock, fcntl.LOCK_EX)
    processes = []
    for i in range(8):
        # Each its own output directory and depfile: eight Ninja jobs of one build.
        own = [a.replace("out/vk", f"out/job{i}") for a in arguments]
        processes.append(subprocess.Popen([s.tool, "--service", *own], cwd=s.work, env=env,
                                          stdout=subprocess.PIPE, stderr=subprocess.PIPE))
    time.sleep(1.0)  # all eight have found no socket and wait for the lock
    os.close(lock)
    for i, p in enumerate(processes):
        out, err = p.communicate(timeout=120)
        check(p.returncode == 0, f"job {i}: exit status {p.returncode}: {err.decode(errors='replace')}")
        check("served by the server" in err.decode(errors="replace"), f"job {i} was not served by the service")
    outputs = s.outputs()
    for i in range(8):
        for path, data in expected_outputs.items():
            if path.endswith(".d"):
                continue
            mine = path.replace("out/vk", f"out/job{i}")
            check(outputs.get(mine) == data, f"job {i}: {mine} differs from the in-process output")
    started = s.started_servers()
    check(len(started) == 1, f"exactly one server must start for 8 simultaneous jobs, {len(started)} did: {s.log()}")


def case_crash(s):
    (s.work / "crasher.vert.hlsl").write_text(CRASHER)
    arguments = ["crasher.vert.hlsl", "-o", "out/crasher.vert"]
    expected = s.run(arguments, service=False)
    check(expected[0] != 0 and "crashed on this input (signal" in expected[2],
          f"the crasher does not crash in-process (the test needs another one): {expected}")
    s.run(COMMANDS[2][1], service=True)  # a server is up before the crash
    server = s.running_pid()
    got = s.run(arguments, service=True)
    check(got[3], "the crashing command was not answered by the service")
    check(got[0] == expected[0] and got[2] == expected[2],
          f"the crash is not reported as in-process: {got[0]} {got[2]!r} vs {expected[0]} {expected[2]!r}")
    check(not (s.work / "out/crasher.vert").exists(), "the crashing command left an output")
    check(server is not None and alive(server), "the server died with the crashing shader")
    after = s.run(COMMANDS[2][1], service=True)
    check(after[0] == 0 and after[3], "the server does not serve the next command after a crash")
    check(s.running_pid() == server and len(s.started_servers()) == 1, "a new server was started after the crash")


def case_killed(s):
    pipelines = [COMMANDS[0][1], COMMANDS[1][1], COMMANDS[2][1], COMMANDS[3][1]]
    expected = []
    for arguments in pipelines:
        expected.append(s.run(arguments, service=False)[:3])
    expected_outputs = s.outputs()
    s.clear_outputs()
    # A build of 16 commands, 4 at a time; the server and its workers are killed after the 4th.
    jobs = [pipelines[i % len(pipelines)] for i in range(16)]
    done = 0
    killed = False
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        futures = [pool.submit(s.run, arguments, True) for arguments in jobs]
        for i, future in enumerate(futures):
            result = future.result()
            check(result[:3] == expected[i % len(pipelines)], f"command {i} differs after the server was killed: {result}")
            done += 1
            if done == 4 and not killed:
                pid = s.running_pid()
                check(pid is not None, "no server was running during the build")
                if pid:
                    kill_group_of(pid)
                killed = True
    check(s.outputs() == expected_outputs, "outputs differ from the in-process ones after the server was killed")
    # A later command gets a new server.
    check(s.run(COMMANDS[2][1], service=True)[3], "no server serves commands after the old one was killed")
    check(len(s.started_servers()) >= 2, "no second server was started after the first was killed")

    # A socket that answers garbage: the command converts in-process and succeeds.
    for pid, _ in s.started_servers():
        kill_group_of(pid)
    socket_path = next(s.service.glob("*.sock"))
    socket_path.unlink()
    import socket as sockets
    liar = sockets.socket(sockets.AF_UNIX, sockets.SOCK_STREAM)
    liar.bind(str(socket_path))
    liar.listen(8)
    liar.settimeout(30)
    s.clear_outputs()
    with concurrent.futures.ThreadPoolExecutor(max_workers=1) as pool:
        future = pool.submit(s.run, COMMANDS[2][1], True)
        connection, _ = liar.accept()
        connection.recv(8)  # answers before the request is read: the client must survive the closed socket
        connection.sendall(b"\x10\x00\x00\x00\x00\x00\x00\x00not an answer!!!")
        connection.close()
        result = future.result()
        # A request larger than the socket's buffer (2 MB on stdin), closed on without a word: the
        # client is still writing when the socket goes, and must survive that (no SIGPIPE death).
        big = s.work / "big.vert"
        big.write_text((s.work / "es/sprite.vert").read_text() + "// " + "x" * (2 << 20) + "\n")
        expected_big = s.run(["-", "-S", "vert", "-o", "-"], service=False, stdin_file="big.vert")
        future = pool.submit(s.run, ["-", "-S", "vert", "-o", "-"], True, "big.vert")
        connection, _ = liar.accept()
        connection.close()
        result_big = future.result()
    liar.close()
    check(result_big[:3] == expected_big[:3] and result_big[0] == 0 and not result_big[3],
          f"a server gone mid-request: the command did not convert in-process alike: {result_big[0]} {result_big[2]!r}")
    check(result[0] == 0 and not result[3], f"a garbage answer was believed, or the fall-back failed: {result}")
    check(s.outputs().get("out/sprite.vert") == expected_outputs.get("out/sprite.vert"),
          "the in-process fall-back after a garbage answer wrote other bytes")


def case_stale(s):
    copy = s.root / "bin" / "stereoshift"
    copy.parent.mkdir()
    shutil.copy2(s.tool, copy)
    first = s.run(COMMANDS[2][1], service=True, tool=str(copy))
    check(first[0] == 0 and first[3], "the copied tool was not served")
    servers = s.started_servers()
    check(len(servers) == 1, f"one server expected for the copy, got {servers}")
    again = s.run(COMMANDS[2][1], service=True, tool=str(copy))
    check(again[3] and len(s.started_servers()) == 1, "the same tool build did not reuse its server")
    # A rebuilt tool (here: the same path, a new modification time) must never reach the old server.
    later = time.time() + 5
    os.utime(copy, (later, later))
    touched = s.run(COMMANDS[2][1], service=True, tool=str(copy))
    servers = s.started_servers()
    check(touched[0] == 0 and touched[3], "the touched tool was not served")
    check(len(servers) == 2 and servers[0][1] != servers[1][1],
          f"the touched tool must start a server of its own identity: {servers}")
    check(touched[1:3] == first[1:3], "the touched tool's answer differs")


def case_private_dir(s):
    expected = s.run(COMMANDS[2][1], service=False)
    for mode in (0o755, 0o770, 0o701):
        os.chmod(s.service, mode)
        s.clear_outputs()
        got = s.run(COMMANDS[2][1], service=True)
        check(got[0] == 0 and not got[3], f"mode {mode:o}: the command was not converted in-process: {got}")
        check("not using the conversion service" in got[2] and "0700" in got[2],
              f"mode {mode:o}: no warning about the directory: {got[2]!r}")
        check(not list(s.service.glob("*.sock")), f"mode {mode:o}: a socket was created in a shared directory")
        check(s.outputs().get("out/sprite.vert") is not None, f"mode {mode:o}: no output")
    os.chmod(s.service, 0o700)
    # A symbolic link to a private directory is refused too (it could be swapped).
    link = s.root / "link"
    link.symlink_to(s.service)
    got = s.run(COMMANDS[2][1], service=True, env=s.environment(STEREOSHIFT_SERVICE_DIR=str(link),
                                                                  STEREOSHIFT_SERVICE_LOG="1"))
    check(got[0] == 0 and not got[3] and "not a directory" in got[2], f"a symbolic link was used: {got}")
    check(not s.started_servers(), "a server was started in a refused directory")
    # The same directory made private again is used.
    check(s.run(COMMANDS[2][1], service=True)[3], "the private directory is not used")
    check(expected[0] == 0, "the command fails in-process (the test is wrong)")


CASES = {
    "identical": case_identical,
    "concurrent": case_concurrent,
    "crash": case_crash,
    "killed": case_killed,
    "stale": case_stale,
    "private_dir": case_private_dir,
}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stereoshift", required=True)
    parser.add_argument("--case", required=True, choices=sorted(CASES))
    args = parser.parse_args()
    # Not the common 022: a worker that created files with any mask but its client's would show.
    os.umask(0o027)
    s = Scratch(Path(args.stereoshift).resolve())
    try:
        CASES[args.case](s)
    finally:
        s.close()
    if failures:
        sys.exit(f"{len(failures)} failure(s)")
    print(f"service.{args.case}: ok")


if __name__ == "__main__":
    main()
