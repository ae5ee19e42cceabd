#!/usr/bin/env python3
"""Fails when a source file includes a header of a higher layer.

The layers, bottom up (docs/architecture.md): core/ (a shader's stage and languages, diagnostics,
crash phases), passes/ (with passes/ir/), transpiler/ (frontend/, backend/, verify/, the driver),
cli/. A file may include headers of its own layer and of the layers below. Product code (core/,
passes/, transpiler/, cli/) never includes test/ or bench/. Inside transpiler/, source/ (the lexer
and the stage and file-name rules) is at the bottom: it includes only itself (and core/), and every
other part may include it. frontend/ and backend/ do not include each other, the driver or verify/:
the driver sits on top of both and verify/ on top of the driver. The parts that read text and know
nothing of SPIR-V passes (source/, frontend/, d3dasm/) take the basic types from core/, never from
passes/.
"""
import argparse
import pathlib
import re
import sys

RANK = {"core": 0, "passes": 1, "transpiler": 2, "cli": 3}
# Sub-layers of transpiler/: what each may include from transpiler/ besides itself.
TRANSPILER_ALLOWED = {
    "source": {"source"},
    "frontend": {"source", "frontend"},
    "backend": {"source", "backend"},
    "driver": {"source", "frontend", "backend", "driver"},
    "verify": {"source", "frontend", "backend", "driver", "verify"},
}
# Parts of transpiler/ that include core/ but nothing of passes/.
BELOW_PASSES = {"source", "frontend", "d3dasm"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def transpiler_part(rel: pathlib.PurePosixPath) -> str:
    parts = rel.parts
    return parts[1] if len(parts) > 2 and parts[1] in TRANSPILER_ALLOWED else "driver"


def check(root: pathlib.Path) -> list[str]:
    errors = []
    for top in RANK:
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in (".h", ".hpp", ".cpp", ".cc"):
                continue
            rel = pathlib.PurePosixPath(path.relative_to(root).as_posix())
            text = path.read_text(encoding="utf-8", errors="replace")
            for m in INCLUDE.finditer(text):
                target = pathlib.PurePosixPath(m.group(1))
                line = text.count("\n", 0, m.start()) + 1
                where = f"{rel}:{line}: error: "
                head = target.parts[0]
                if head in ("test", "bench"):
                    errors.append(where + f"product code includes {target} (test and bench code are never linked into the tool)")
                    continue
                if head not in RANK:
                    continue  # a system or package header spelled with quotes, or a file beside it
                if RANK[head] > RANK[top]:
                    errors.append(where + f"{top}/ is below {head}/ but includes {target}")
                    continue
                if top == "transpiler" and head == "passes" and rel.parts[1] in BELOW_PASSES:
                    errors.append(where + f"transpiler/{rel.parts[1]} takes its basic types from core/, not passes/ ({target})")
                    continue
                if top == head == "transpiler":
                    mine, theirs = transpiler_part(rel), transpiler_part(target)
                    if theirs not in TRANSPILER_ALLOWED[mine]:
                        errors.append(where + f"transpiler/{mine} may not include transpiler/{theirs} ({target})")
    return errors


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--root", required=True, type=pathlib.Path)
    args = parser.parse_args()
    errors = check(args.root)
    for e in errors:
        print(e)
    if errors:
        print(f"{len(errors)} layering error{'s' if len(errors) != 1 else ''} generated.")
        return 1
    print("layering: no file includes a higher layer")
    return 0


if __name__ == "__main__":
    sys.exit(main())
