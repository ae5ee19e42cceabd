"""stereoshift_shaders: turns mono shaders into stereo ones as hermetic Bazel actions.

    load("@stereoshift_rules//:stereoshift.bzl", "stereoshift_shaders")

    stereoshift_shaders(
        name = "forward",
        srcs = ["shaders/forward.vert", "shaders/forward.frag"],   # the stages of one pipeline
        hdrs = ["shaders/include/lighting.glsl"],                   # every file they #include
        target = "glsl",
    )

Outputs: `<name>/<basename of each src>` (the CLI names a pipeline's outputs by its inputs), and a
Makefile depfile (`<name>/<name>.d`, or `<name>/<basename>.d` per shader) in the output group "depfile".

One action per pipeline (`pipeline = True`, the default: all srcs are the stages of one pipeline and
only its last pre-rasterization stage is shifted) or per shader (`pipeline = False`: each src is
converted on its own). Touching an include reruns exactly the actions that declare it in hdrs.

Hermetic actions (they cache and run under remote execution unchanged):
- every input is declared: srcs, hdrs and the tool itself; `includes` adds -I roots, and only those:
  the CLI's own search path is the including file's directory, the -I roots, then the shader's
  directory and its `include/` subdirectory, all inside the declared inputs' tree;
- the tool is told the declared inputs (--declared-input=...) and fails the action, removing its
  outputs, when the conversion read any other file (checked on the depfile), so an undeclared
  include fails under the persistent worker or --spawn_strategy=local too, not only in a sandbox;
- no environment is passed (use_default_shell_env = False), no absolute paths are on the command
  line, and the outputs depend only on the inputs and the options (byte-identical to the CLI's).

Persistent worker: the actions declare supports-workers with the JSON protocol, so Bazel runs them in
a long-lived `stereoshift --persistent_worker` by default (glslang initialised once); pass
--strategy=StereoshiftConvert=sandboxed (or remote) to run each as its own process.
"""

_LANGUAGES = ["", "glsl", "essl", "hlsl", "msl", "spirv", "spirv-asm"]
_EYE_SOURCES = ["", "auto", "uniform-block", "push-constant", "spec-constant", "loose-uniforms"]

def _root_relative(ctx, path):
    """The path of a package-relative directory, from the execution root."""
    package = ctx.label.package
    if ctx.label.workspace_root:
        package = ctx.label.workspace_root + ("/" + package if package else "")
    return (package + "/" + path) if package and path not in ["", "."] else (package or path or ".")

def _add_options(ctx, args):
    if ctx.attr.target:
        args.add("--target", ctx.attr.target)
    if ctx.attr.target_version:
        args.add("--target-version", str(ctx.attr.target_version))
    if ctx.attr.eye_source:
        args.add("--eye-source", ctx.attr.eye_source)
    if ctx.attr.block_name:
        args.add("--block-name", ctx.attr.block_name)
    if ctx.attr.descriptor_set >= 0:
        args.add("--set", str(ctx.attr.descriptor_set))
    if ctx.attr.binding >= 0:
        args.add("--binding", str(ctx.attr.binding))
    if ctx.attr.stage:
        args.add("--stage", ctx.attr.stage)
    for define in ctx.attr.defines:
        args.add("-D" + define)
    for include in ctx.attr.includes:
        root = _root_relative(ctx, include)
        args.add("-I", root)

        # A generated header lives under the output tree: its root is searched too.
        args.add("-I", ctx.bin_dir.path + "/" + root)
    args.add_all(ctx.attr.opts)

def _convert(ctx, stages, hdrs, depfile_name):
    """One action: `stages` (one pipeline, or one shader) into `<target name>/<basename>` outputs."""
    name = ctx.label.name
    seen = {}
    outputs = []
    for src in stages:
        if src.basename in seen:
            fail("two stages named '%s' (%s and %s): their outputs would clash" % (src.basename, seen[src.basename].path, src.path))
        seen[src.basename] = src
        outputs.append(ctx.actions.declare_file(name + "/" + src.basename))
    depfile = ctx.actions.declare_file(name + "/" + depfile_name)

    args = ctx.actions.args()
    args.use_param_file("@%s", use_always = True)
    args.set_param_file_format("multiline")
    _add_options(ctx, args)
    if len(stages) > 1:
        args.add("--pipeline", ",".join([s.path for s in stages]))
        args.add("-o", outputs[0].dirname)
    else:
        args.add(stages[0])
        args.add("-o", outputs[0])
    args.add("--depfile", depfile)
    args.add_all(stages, format_each = "--declared-input=%s")
    args.add_all(hdrs, format_each = "--declared-input=%s")

    ctx.actions.run(
        executable = ctx.executable.tool,
        arguments = [args],
        inputs = depset(stages, transitive = [hdrs]),
        outputs = outputs + [depfile],
        mnemonic = "StereoshiftConvert",
        progress_message = "stereoshift %s" % ", ".join([s.short_path for s in stages]),
        use_default_shell_env = False,
        execution_requirements = {
            "supports-workers": "1",
            "requires-worker-protocol": "json",
        },
    )
    return outputs, depfile

def _stereoshift_shaders_impl(ctx):
    hdrs = depset(ctx.files.hdrs)
    outputs = []
    depfiles = []
    if ctx.attr.pipeline:
        converted, depfile = _convert(ctx, ctx.files.srcs, hdrs, ctx.label.name + ".d")
        outputs += converted
        depfiles.append(depfile)
    else:
        for src in ctx.files.srcs:
            converted, depfile = _convert(ctx, [src], hdrs, src.basename + ".d")
            outputs += converted
            depfiles.append(depfile)
    return [
        DefaultInfo(files = depset(outputs)),
        OutputGroupInfo(depfile = depset(depfiles)),
    ]

stereoshift_shaders = rule(
    implementation = _stereoshift_shaders_impl,
    doc = "Converts mono shaders into stereo ones with stereoshift (one action per pipeline or per shader).",
    attrs = {
        "srcs": attr.label_list(
            allow_files = True,
            mandatory = True,
            allow_empty = False,
            doc = "The shaders: the stages of one pipeline (pipeline = True) or shaders converted one by one.",
        ),
        "pipeline": attr.bool(
            default = True,
            doc = "True: srcs are one pipeline (one action, only its last pre-rasterization stage shifted). False: one action per src.",
        ),
        "hdrs": attr.label_list(
            allow_files = True,
            doc = "Every file the srcs #include. An include read that is not listed fails the action.",
        ),
        "includes": attr.string_list(
            doc = "#include search directories, relative to this package (-I).",
        ),
        "defines": attr.string_list(doc = "Preprocessor macros: NAME or NAME=VALUE (-D)."),
        "target": attr.string(values = _LANGUAGES, doc = "Output language (--target); default: the input's own."),
        "target_version": attr.int(default = 0, doc = "GLSL/ESSL version or HLSL shader model of the output (--target-version); 0: the default."),
        "stage": attr.string(doc = "Stage of a shader whose name does not say it (--stage), with pipeline = False."),
        "eye_source": attr.string(values = _EYE_SOURCES, doc = "Where eyeSign/separation/convergence live (--eye-source)."),
        "block_name": attr.string(doc = "Name of the injected uniform block / cbuffer (--block-name)."),
        "descriptor_set": attr.int(default = -1, doc = "Descriptor set of the injected block (--set); -1: the default."),
        "binding": attr.int(default = -1, doc = "Binding of the injected block (--binding); -1: the default."),
        "opts": attr.string_list(doc = "Further stereoshift options, as on its command line (e.g. --no-cutoff, --shift-form=select)."),
        "tool": attr.label(
            default = "@stereoshift_tool//:stereoshift",
            executable = True,
            cfg = "exec",
            allow_single_file = True,
            doc = "The stereoshift binary (see repositories.bzl).",
        ),
    },
)
