# lit configuration: one behaviour per file, RUN lines at the top, CHECK lines beside the source.
import os
import shutil
import sys
import lit.formats

config.name = "stereoshift"
config.test_format = lit.formats.ShTest(execute_external=True)
config.suffixes = [".vert", ".tesc", ".tese", ".geom", ".frag", ".comp", ".mesh", ".hlsl", ".spvasm", ".test"]
# Inputs/ holds the extra files of multi-file tests; it is never a test itself.
config.excludes = ["Inputs", "CMakeLists.txt", "lit.cfg.py", "lit.site.cfg.py.in"]
config.test_source_root = os.path.dirname(__file__)

# Order matters: lit applies these before its own %s/%t, so longer names that start with %s go first.
config.substitutions.append(("%stereoshift", config.stereoshift))
# SPIR-V 1.0 so hand-written modules list only Input/Output variables in OpEntryPoint.
config.substitutions.append(("%spirv-as", "spirv-as --target-env spv1.0"))
config.substitutions.append(("%python", sys.executable))
# Strips the test's own // CHECK:/RUN: comments from a converted shader: stereoshift may keep the
# input's source text, and those lines would otherwise match themselves.
config.substitutions.append(("%rmchecks", "%s %s" % (sys.executable, os.path.join(os.path.dirname(__file__), "rmchecks.py"))))
config.substitutions.append(("FileCheck", config.filecheck))
config.substitutions.append(("%not", config.not_tool))
config.substitutions.append(("%corpus", os.path.join(config.source_root, "corpus")))
config.environment["PATH"] = os.pathsep.join(["/usr/lib/llvm-14/bin", config.environment.get("PATH", os.environ.get("PATH", ""))])

# Features for the external tools some tests need.
for tool in ["spirv-as", "spirv-dis", "spirv-val", "glslangValidator", "split-file"]:
    if shutil.which(tool, path=config.environment["PATH"]):
        config.available_features.add(tool)
