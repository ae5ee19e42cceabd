#!/usr/bin/env python3
"""Drops lit/FileCheck directive comments (// RUN:, // CHECK:, // PREFIX-NEXT:, // XFAIL: ...)
from a converted shader before FileCheck reads it.

stereoshift may keep the input's source text (and so its comments) in what it emits; the test's own
CHECK lines would then be in the output and match themselves. Everything else passes unchanged.
Usage: rmchecks.py [FILE]   (standard input when no FILE)
"""
import re
import sys

DIRECTIVE = re.compile(r"^\s*//\s*[A-Z][A-Z0-9_]*(-[A-Z0-9_]+)*:")


def main():
    data = open(sys.argv[1], "rb").read() if len(sys.argv) > 1 else sys.stdin.buffer.read()
    out = sys.stdout.buffer
    for line in data.splitlines(keepends=True):
        if not DIRECTIVE.match(line.decode("utf-8", "replace")):
            out.write(line)


if __name__ == "__main__":
    main()
