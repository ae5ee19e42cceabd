"""Makes a stereoshift binary built outside Bazel (by CMake) a label: @<name>//:stereoshift.

stereoshift is built with CMake, so a workspace does not build it; it names the binary instead:

    load("@stereoshift_rules//:repositories.bzl", "stereoshift_local_tool")
    stereoshift_local_tool(name = "stereoshift_tool", path = "/abs/path/to/build/stereoshift")

The environment variable STEREOSHIFT_TOOL (an absolute path), when set, wins over `path`, so a
checkout can point at its own build tree without editing the WORKSPACE:
    bazel build --repo_env=STEREOSHIFT_TOOL=$PWD/build/stereoshift //...
Nothing is downloaded. The binary is a declared input of every conversion action (the rule's `tool`
attribute, cfg = "exec"), so remote execution ships it and a rebuilt tool invalidates the cache.
"""

def _stereoshift_local_tool_impl(rctx):
    path = rctx.os.environ.get("STEREOSHIFT_TOOL", "") or rctx.attr.path
    if not path:
        fail("stereoshift_local_tool: set `path` or the environment variable STEREOSHIFT_TOOL to the stereoshift binary (an absolute path)")
    binary = rctx.path(path)
    if not binary.exists:
        fail("stereoshift_local_tool: '%s' does not exist (build it first: cmake --build <build-dir> --target stereoshift)" % path)
    rctx.symlink(binary, "stereoshift")
    rctx.file("WORKSPACE", 'workspace(name = "%s")\n' % rctx.name)
    rctx.file("BUILD.bazel", 'exports_files(["stereoshift"], visibility = ["//visibility:public"])\n')

stereoshift_local_tool = repository_rule(
    implementation = _stereoshift_local_tool_impl,
    attrs = {
        "path": attr.string(doc = "Absolute path of the stereoshift binary (STEREOSHIFT_TOOL overrides it)."),
    },
    environ = ["STEREOSHIFT_TOOL"],
    local = True,
)
