#!/usr/bin/env python3
"""Fails when a C++ file under FOLDER is longer than MAX_FILE lines or a function in it longer
than MAX_FUNCTION lines (body, from its opening brace to its closing one).

usage: check_sizes.py FOLDER MAX_FILE MAX_FUNCTION

Functions are found by brace matching: namespaces, classes, structs, enums and unions are
containers; any other block opened at a container's level after a `)` is a function (free,
member or a lambda at namespace level), however many lines its signature takes.
"""
import pathlib
import re
import sys

CONTAINER = re.compile(r"\b(namespace|class|struct|enum|union)\b[^()]*$")


def strip(text):
    """Comments, strings and character literals blanked, newlines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    text = strip(path.read_text(encoding="utf-8", errors="replace"))
    stack, line, since = [], 1, ""  # stack: (kind, start line, name)
    for c in text:
        if c == "\n":
            line += 1
        if c == "{":
            in_container = all(kind == "container" for kind, _, _ in stack)
            head = since.strip()
            if in_container and CONTAINER.search(head):
                stack.append(("container", line, head))
            elif in_container and ")" in head and not re.search(r"=\s*$", head):
                name = re.sub(r"\s+", " ", head)[-80:]
                stack.append(("function", line, name))
            else:
                stack.append(("block", line, head))
            since = ""
        elif c == "}":
            if stack:
                kind, start, name = stack.pop()
                if kind == "function":
                    yield name, line - start + 1
            since = ""
        elif c == ";":
            since = ""
        else:
            since += c


def main():
    folder, max_file, max_function = pathlib.Path(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
    problems = []
    for path in sorted(folder.rglob("*")):
        if path.suffix not in (".cpp", ".hpp", ".h", ".cc"):
            continue
        lines = path.read_text(encoding="utf-8", errors="replace").count("\n")
        if lines > max_file:
            problems.append(f"{path}: {lines} lines (at most {max_file})")
        for name, length in functions(path):
            if length > max_function:
                problems.append(f"{path}: a function of {length} lines (at most {max_function}): {name}")
    for p in problems:
        print(p)
    print(f"{len(problems)} problem(s) in {folder}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
