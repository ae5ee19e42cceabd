#!/usr/bin/env python3
"""Fails when the code loses the shape docs/architecture.md promises.

- No product source file (core/, passes/, transpiler/, cli/) over 800 lines.
- No function over 120 lines outside test/ (C++ in the product and bench/, Python in bench/ and
  scripts/): a body that long mixes phases that deserve names of their own.
- The JSON report is an output, never an API: the keys that describe what passes found
  (`report["passes"]`, `shifted_outputs`, `per_eye_outputs`) appear in product code only in the
  report renderer (transpiler/report.cpp), which writes them from the typed run record.
- Source text is read by one lexer (transpiler/source/): identifier-character helpers are defined
  there and nowhere else.

Functions are found by a small brace scanner (comments, strings and preprocessor lines removed):
a `{` at namespace or class scope that follows a parameter list, a qualifier after it, or a
constructor's initialiser list opens a function body; its length is the number of lines from that
brace to the one that closes it.
"""
import argparse
import ast
import os
import pathlib
import re
import sys

PRODUCT = ("core", "passes", "transpiler", "cli", "include")
CXX = (".h", ".hpp", ".cpp", ".cc")
MAX_FILE_LINES = 800
MAX_FUNCTION_LINES = 120
REPORT_RENDERER = "transpiler/report.cpp"
REPORT_KEYS = ('report["passes"]', "shifted_outputs", "per_eye_outputs")
LEXER_DIR = "transpiler/source/"
IDENT_HELPER = re.compile(r"\bbool\s+(is(?:Ident|Identifier)\w*)\s*\(\s*(?:unsigned\s+)?char\b")


def strip_cxx(text: str) -> str:
    """Comments, string and character literals and preprocessor lines blanked; line breaks kept."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if c == "\n":
            out.append(c)
            line_start = True
            i += 1
            continue
        if line_start and c in " \t":
            out.append(c)
            i += 1
            continue
        if line_start and c == "#":
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append("\n")
                    i += 2
                    continue
                i += 1
            continue
        line_start = False
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                i += 1
            continue
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append("\n" * text.count("\n", i, end))
            i = end
            continue
        m = re.match(r'(?:u8|u|U|L)?R"([^(\s]*)\(', text[i:i + 40])
        if m:
            close = text.find(")" + m.group(1) + '"', i + m.end())
            end = n if close < 0 else close + len(m.group(1)) + 2
            out.append('""' + "\n" * text.count("\n", i, end))
            i = end
            continue
        if c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
            continue
        out.append(c)
        i += 1
    return "".join(out)


TOKEN = re.compile(r"[A-Za-z_]\w*|\d[\w.']*|->|::|\S")
QUALIFIERS = {"const", "override", "final", "noexcept", "mutable", "volatile", "&", "&&", "try"}
SCOPE_WORDS = {"namespace", "struct", "class", "union", "enum", "extern"}


def cxx_functions(text: str):
    """(name, first line, line count) of every function body at namespace or class scope."""
    stripped = strip_cxx(text)
    tokens = [(m.group(0), stripped.count("\n", 0, m.start()) + 1) for m in TOKEN.finditer(stripped)]
    stack = []  # per open brace: 'function', 'scope' or 'block'
    found = []
    paren_names = []  # name before each open parenthesis at the current statement
    statement = []    # tokens since the last ; { } at this depth
    for index, (tok, line) in enumerate(tokens):
        inside_function = "function" in stack
        if tok == "{":
            kind = "block"
            if not inside_function:
                words = [t for t, _ in statement]
                if any(w in SCOPE_WORDS for w in words) and ")" not in words:
                    kind = "scope"
                elif words and "=" not in words[:1] and (words[-1] == ")" or words[-1] in QUALIFIERS or
                                                          _after_trailing_return(words) or _after_initialiser(words)):
                    kind = "function"
                elif words and ("=" in words or words[-1] in ("return", ",")):
                    kind = "block"
                else:
                    kind = "scope"
            if kind == "function":
                found.append([_function_name(statement), line, None])
            stack.append(kind)
            statement = []
            continue
        if tok == "}":
            kind = stack.pop() if stack else "block"
            if kind == "function":
                for entry in reversed(found):
                    if entry[2] is None:
                        entry[2] = line - entry[1] + 1
                        break
            statement = []
            continue
        if tok == ";" and not inside_function:
            statement = []
            continue
        if not inside_function:
            statement.append((tok, line))
    return [(name, first, count) for name, first, count in found if count is not None]


def _after_trailing_return(words):
    return "->" in words and ")" in words and words.index("->") > words.index(")")


def _after_initialiser(words):
    # `Foo(int a) : a_(a), b_{b}` — a `:` after the parameter list, the statement ending in ) or }.
    if ":" not in words or ")" not in words:
        return False
    return words.index(":") > words.index(")") and words[-1] in (")", "}")


def _function_name(statement):
    words = [t for t, _ in statement]
    depth = 0
    for i, w in enumerate(words):
        if w == "(" and depth == 0 and i > 0:
            name = words[i - 1]
            if i > 2 and words[i - 2] == "::":
                name = words[i - 3] + "::" + name
            if name == "operator" or (i > 1 and words[i - 2] == "operator"):
                return "operator" + words[i - 1]
            return name
        depth += w == "("
        depth -= w == ")"
    return "?"


def python_functions(text: str):
    tree = ast.parse(text)
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield node.name, node.lineno, node.end_lineno - node.lineno + 1


def check(root: pathlib.Path):
    errors = []
    # Walked with the build trees, out/ and .git pruned, not filtered afterwards: a test running
    # beside this one (lit) creates and removes its temporaries under build/ while the walk goes on.
    files = []
    for folder, subfolders, names in os.walk(root):
        if pathlib.Path(folder) == root:
            subfolders[:] = [d for d in subfolders if not d.startswith(("build", "out")) and d != ".git"]
        subfolders[:] = [d for d in subfolders if d != ".git"]
        files.extend(p for p in (pathlib.Path(folder) / name for name in names) if p.is_file())
    files.sort()
    for path in files:
        rel = path.relative_to(root).as_posix()
        top = rel.split("/", 1)[0]
        if top in ("test", "corpus", "examples", "docs") or "/Output/" in rel:
            continue
        if path.suffix in CXX and top in PRODUCT + ("bench",):
            text = path.read_text(encoding="utf-8", errors="replace")
            lines = text.count("\n")
            if top in PRODUCT and path.suffix in (".cpp", ".cc") and lines > MAX_FILE_LINES:
                errors.append(f"{rel}:1:1: error: {lines} lines (at most {MAX_FILE_LINES} in a product source file)")
            for name, first, count in cxx_functions(text):
                if count > MAX_FUNCTION_LINES:
                    errors.append(f"{rel}:{first}:1: error: function '{name}' is {count} lines "
                                  f"(at most {MAX_FUNCTION_LINES})")
            if top in PRODUCT and rel != REPORT_RENDERER:
                stripped_lines = strip_cxx_keep_strings(text).splitlines()
                for number, line in enumerate(stripped_lines, 1):
                    for key in REPORT_KEYS:
                        if key in line:
                            errors.append(f"{rel}:{number}:1: error: '{key}' outside the report renderer "
                                          f"({REPORT_RENDERER}): read the typed run record instead")
            if top in PRODUCT and not rel.startswith(LEXER_DIR):
                stripped = strip_cxx(text)
                for m in IDENT_HELPER.finditer(stripped):
                    number = stripped.count("\n", 0, m.start()) + 1
                    errors.append(f"{rel}:{number}:1: error: '{m.group(1)}' defined outside the source-text layer "
                                  f"({LEXER_DIR}): use its lexer")
        elif path.suffix == ".py" and top in ("bench", "scripts"):
            for name, first, count in python_functions(path.read_text(encoding="utf-8")):
                if count > MAX_FUNCTION_LINES:
                    errors.append(f"{rel}:{first}:1: error: function '{name}' is {count} lines "
                                  f"(at most {MAX_FUNCTION_LINES})")
    return errors


def strip_cxx_keep_strings(text: str) -> str:
    """Comments removed, strings kept (a report key is spelled in a string literal)."""
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", required=True, type=pathlib.Path)
    parser.add_argument("--list", action="store_true", help="print every function with its length, longest first")
    args = parser.parse_args()
    if args.list:
        rows = []
        for path in sorted(args.root.rglob("*")):
            rel = path.relative_to(args.root).as_posix()
            if path.suffix in CXX and rel.split("/", 1)[0] in PRODUCT + ("bench", "test") and "build" not in rel:
                rows += [(count, f"{rel}:{first} {name}") for name, first, count in
                         cxx_functions(path.read_text(encoding="utf-8", errors="replace"))]
        for count, where in sorted(rows, reverse=True)[:60]:
            print(f"{count:5d} {where}")
        return 0
    errors = check(args.root)
    for e in errors:
        print(e)
    if errors:
        print(f"{len(errors)} error{'s' if len(errors) != 1 else ''} generated.")
        return 1
    print("structure: files and functions within their limits, one report renderer, one lexer")
    return 0


if __name__ == "__main__":
    sys.exit(main())
