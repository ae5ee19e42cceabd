# lit configuration: one behaviour per file, RUN lines at the top, CHECK lines beside the source.
import os
import lit.formats

config.name = "stereoshift"
config.test_format = lit.formats.ShTest(execute_external=True)
config.suffixes = [".vert", ".tesc", ".tese", ".geom", ".frag", ".comp", ".mesh", ".hlsl", ".spvasm", ".test"]
config.excludes = ["Inputs", "CMakeLists.txt", "lit.cfg.py", "lit.site.cfg.py.in"]
config.test_source_root = os.path.dirname(__file__)

config.substitutions.append(("%stereoshift", config.stereoshift))
config.substitutions.append(("FileCheck", config.filecheck))
config.substitutions.append(("%not", config.not_tool))
config.substitutions.append(("%corpus", os.path.join(config.source_root, "corpus")))
config.environment["PATH"] = os.pathsep.join(["/usr/lib/llvm-14/bin", config.environment.get("PATH", os.environ.get("PATH", ""))])
