#!/usr/bin/env python3
"""Lines of code per top folder and the longest C++ functions (for refactoring notes).

usage: tools/metrics/function_lengths.py [TOP_N]
Counts the lines of tracked .cpp/.hpp files per top-level folder, and the length in lines of
each function body found by brace matching after a `) {` or `) const {` line (a heuristic that
fits this code base's style: clang-format, braces on the signature line).
"""
import re
import subprocess
import sys
from collections import defaultdict

top_n = int(sys.argv[1]) if len(sys.argv) > 1 else 10
files = [f for f in subprocess.check_output(["git", "ls-files"], text=True).split()
         if f.endswith((".cpp", ".hpp"))]
per_folder = defaultdict(int)
functions = []
signature = re.compile(r"^(?!\s*(if|for|while|switch|catch|else|do)\b)\s*[\w:<>,~*&\s\[\]]+\(.*\)\s*(const\s*)?(noexcept\s*)?(override\s*)?\{\s*$")
for path in files:
    lines = open(path, encoding="utf-8", errors="replace").read().split("\n")
    per_folder[path.split("/")[0]] += len(lines)
    i = 0
    while i < len(lines):
        line = lines[i]
        m = signature.match(line)
        if m and not line.strip().startswith(("return", "//")) and "=" not in line.split("(")[0]:
            depth, j = 0, i
            while j < len(lines):
                depth += lines[j].count("{") - lines[j].count("}")
                if depth <= 0 and j > i:
                    break
                j += 1
            name = line.split("(")[0].split()[-1] if line.split("(")[0].split() else "?"
            functions.append((j - i + 1, f"{path}:{i + 1}", name))
            i += 1
            continue
        i += 1
print("lines per folder (.cpp/.hpp):")
for folder, n in sorted(per_folder.items()):
    print(f"  {folder:12s} {n:6d}")
print(f"  {'total':12s} {sum(per_folder.values()):6d}")
print(f"longest functions (top {top_n}):")
for length, where, name in sorted(functions, reverse=True)[:top_n]:
    print(f"  {length:4d}  {name:40s} {where}")
