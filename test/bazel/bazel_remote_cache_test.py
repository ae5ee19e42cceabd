#!/usr/bin/env python3
"""integration.bazel_remote_cache: the example's conversions served from a real HTTP cache.

The test starts nginx (its WebDAV module: GET, and PUT with the directories made) on a free port of
the loopback address as Bazel's --remote_cache, then builds a copy of examples/bazel in three fresh
output roots, each its own Bazel server with nothing on its disk:

1. the first build runs every conversion and uploads it (the server's log shows the PUTs);
2. a clean build of the same tree is served from the cache: every conversion a remote-cache hit, the
   outputs byte-identical to the first build's;
3. after an edit of the include two pipelines share, exactly those two pipelines run and the others
   are remote-cache hits (the cache key covers the declared include, and only the declared ones).

What the cache serves is what stereoshift's actions are: hermetic (every input declared, no absolute
path on the command line, no environment), so their keys are equal across output roots. Remote
execution needs an executor and stays documented only (bazel/README.md).

Exits 77 (ctest SKIP_RETURN_CODE) when bazel or nginx is not installed. Scratch files, Bazel's output
roots and the cache go under --work-dir only.
"""
import filecmp
import grp
import os
import pwd
import shutil
import signal
import socket
import subprocess
import sys
import time

from bazel_support import (PIPELINES, SINGLE_SHADERS, SKIP, USERS_OF_SHARED_INCLUDE, Bazel, check,
                           edit_shared_include, parse_arguments, pipelines_run)

ALL_TARGETS = set(PIPELINES) | set(SINGLE_SHADERS)
CONVERSIONS = len(PIPELINES) + sum(len(s) for s in SINGLE_SHADERS.values())


class CacheServer:
    """nginx serving one directory over WebDAV on 127.0.0.1, in the foreground, with every file it
    writes (logs, temporary bodies, its pid) under its own directory."""

    def __init__(self, nginx, directory):
        self.nginx = nginx
        self.directory = directory
        self.root = os.path.join(directory, "cache")
        self.access_log = os.path.join(directory, "access.log")
        self.process = None
        self.port = None

    def _config(self, port):
        d = self.directory
        # nginx started by root hands its workers to `nobody`, who cannot write here: keep our user.
        user = ""
        if os.geteuid() == 0:
            user = f"user {pwd.getpwuid(os.getuid()).pw_name} {grp.getgrgid(os.getgid()).gr_name};\n"
        temp = "".join(f"  {kind}_temp_path {d}/tmp_{kind};\n"
                       for kind in ("client_body", "proxy", "fastcgi", "uwsgi", "scgi"))
        return (f"daemon off;\n{user}worker_processes 1;\npid {d}/nginx.pid;\nerror_log {d}/error.log;\n"
                "events { worker_connections 64; }\n"
                "http {\n"
                f"  access_log {self.access_log};\n{temp}"
                "  server {\n"
                f"    listen 127.0.0.1:{port};\n"
                f"    root {self.root};\n"
                "    client_max_body_size 0;\n"
                "    location / {\n"
                "      dav_methods PUT;\n"
                "      create_full_put_path on;\n"
                "      dav_access user:rw;\n"
                "    }\n"
                "  }\n"
                "}\n")

    def start(self):
        shutil.rmtree(self.directory, ignore_errors=True)
        os.makedirs(self.root)
        # A port free now may be taken before nginx binds it: try a few.
        for _ in range(5):
            with socket.socket() as probe:
                probe.bind(("127.0.0.1", 0))
                port = probe.getsockname()[1]
            config = os.path.join(self.directory, "nginx.conf")
            open(config, "w").write(self._config(port))
            self.process = subprocess.Popen([self.nginx, "-p", self.directory, "-c", config,
                                             "-e", os.path.join(self.directory, "error.log")],
                                            stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
            # Ready when it accepts a connection; gone when the port was taken.
            for _ in range(200):
                if self.process.poll() is not None:
                    break
                try:
                    socket.create_connection(("127.0.0.1", port), timeout=1).close()
                    self.port = port
                    return "http://127.0.0.1:%d" % port
                except OSError:
                    time.sleep(0.05)
            self.stop()
        log = os.path.join(self.directory, "error.log")
        sys.exit("FAIL: nginx did not start:\n" + (open(log).read() if os.path.exists(log) else ""))

    def stop(self):
        if self.process and self.process.poll() is None:
            self.process.send_signal(signal.SIGQUIT)
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.process = None

    def requests(self, method):
        """(path, status) of each request of that method the server answered."""
        result = []
        if os.path.exists(self.access_log):
            for line in open(self.access_log):
                # combined format: ... "PUT /cas/abc HTTP/1.1" 201 ...
                try:
                    request, rest = line.split('"')[1], line.split('"')[2]
                except IndexError:
                    continue
                parts = request.split()
                if len(parts) >= 2 and parts[0] == method:
                    result.append((parts[1], rest.split()[0]))
        return result


def cache_hits(spawns):
    return {name for name in pipelines_run([s for s in spawns if s.get("remoteCacheHit")])}


def executed(spawns):
    return {name for name in pipelines_run([s for s in spawns if not s.get("remoteCacheHit")])}


def main():
    args = parse_arguments(__doc__, lambda parser: parser.add_argument(
        "--nginx", default=shutil.which("nginx") or "/usr/sbin/nginx"))
    if args is None:
        return SKIP
    if not os.access(args.nginx, os.X_OK):
        print("SKIP: nginx is not installed (Debian: apt-get install nginx)")
        return SKIP

    args.work_dir = os.path.abspath(args.work_dir)
    tool = os.path.abspath(args.stereoshift)
    workspace = os.path.join(args.work_dir, "workspace")
    shutil.rmtree(workspace, ignore_errors=True)
    shutil.copytree(args.example, workspace)
    logs = os.path.join(args.work_dir, "logs")
    os.makedirs(logs, exist_ok=True)
    server = CacheServer(args.nginx, os.path.join(args.work_dir, "nginx"))
    url = server.start()
    cache_flags = ["--remote_cache=" + url, "--remote_upload_local_results"]
    timings = []

    def fresh_build(name):
        """A build in a new output root (nothing on disk, a server of its own), shut down after."""
        root = os.path.join(args.work_dir, "root-" + name)
        shutil.rmtree(root, ignore_errors=True)
        bazel = Bazel(args.bazel, workspace, root, tool, os.path.abspath(args.rules))
        try:
            _, seconds, spawns = bazel.build(os.path.join(logs, name + ".json"), *cache_flags)
            timings.append((name, seconds))
            p, _ = bazel.run("info", *bazel.flags, "bazel-bin")
            return spawns, p.stdout.strip().splitlines()[-1]
        finally:
            bazel.run("shutdown", check=False)

    try:
        first_spawns, first_bin = fresh_build("first")
        spawns = first_spawns
        check(len(spawns) == CONVERSIONS, f"the first build ran {len(spawns)} conversions, not {CONVERSIONS}")
        check(not cache_hits(spawns), f"an empty cache served {sorted(cache_hits(spawns))}")
        check({s.get("runner", "") for s in spawns} == {"worker"}, "the first build's conversions did not run on the worker")
        stored = [path for path, status in server.requests("PUT") if status in ("201", "204")]
        check(any(p.startswith("/ac/") for p in stored) and any(p.startswith("/cas/") for p in stored),
              f"the first build stored no action results and blobs in the cache: {stored[:10]}")

        spawns, second_bin = fresh_build("second")
        check(len(spawns) == CONVERSIONS and cache_hits(spawns) == ALL_TARGETS and not executed(spawns),
              f"a clean build of the same tree ran {sorted(executed(spawns))} instead of reading them from the cache")
        check({s.get("runner", "") for s in spawns} == {"remote cache hit"},
              f"the second build's runners were {sorted({s.get('runner', '') for s in spawns})}")
        served = [path for path, status in server.requests("GET") if status == "200"]
        check(any(p.startswith("/ac/") for p in served), "the cache server answered no action-cache reads")
        # The actions' declared outputs (a local run also leaves Bazel's params file beside them).
        outputs = sorted({o for s in first_spawns for o in s.get("listedOutputs", [])})
        check(len(outputs) >= CONVERSIONS, f"the first build's log lists the outputs {outputs}")
        for output in outputs:
            relative = output.split("/bin/", 1)[1]
            a, b = os.path.join(first_bin, relative), os.path.join(second_bin, relative)
            check(os.path.isfile(b), f"the cached build has no {relative}")
            check(filecmp.cmp(a, b, shallow=False), f"the cached {relative} differs from the built one")

        edit_shared_include(workspace)
        spawns, _ = fresh_build("after-include-edit")
        check(executed(spawns) == USERS_OF_SHARED_INCLUDE,
              f"after the include edit a clean build ran {sorted(executed(spawns))}, not exactly "
              f"{sorted(USERS_OF_SHARED_INCLUDE)}")
        check(cache_hits(spawns) == ALL_TARGETS - USERS_OF_SHARED_INCLUDE,
              f"after the include edit the cache served {sorted(cache_hits(spawns))}")
    finally:
        server.stop()

    for what, seconds in timings:
        print(f"{what + ' build':40s} {seconds:6.2f} s")
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
