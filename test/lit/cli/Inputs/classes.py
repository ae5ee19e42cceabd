"""Prints `path: classification [fixes]` for every shader of a build report, sorted by path, so
a lit test can check the whole listing. `fixes` names the per-eye pixel passes that changed it."""
import json
import os
import sys

report = json.load(open(sys.argv[1]))
root = sys.argv[2]
for entry in sorted(report["shaders"], key=lambda e: e["file"]):
    passes = entry.get("passes", {})
    fixes = [name for name in ("hud-at-depth", "per-eye-view", "deferred-unprojection")
             if passes.get(name, {}).get("result") == "changed"]
    print("%s: %s%s" % (os.path.relpath(entry["file"], root), entry.get("classification", "?"),
                        (" [" + ", ".join(fixes) + "]") if fixes else ""))
