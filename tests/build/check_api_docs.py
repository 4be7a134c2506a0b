#!/usr/bin/env python3
"""The student API documented where it is declared, and its page agreeing (issue 59).

For each exercise of the build (build/generated/aula/exercise_abi.hpp: its API headers), every
member of its `struct ...Api` (what execute() is given) must carry a doc comment an IDE shows
(`///<` on its line, or `///`/`/** */` just before it), and the exercise's page
(docs/exercises/<name>.md) must name each member in code (`api.member`, or `member` in a list of
the same row). Usage: check_api_docs.py SOURCE_DIR BUILD_DIR
"""
import re
import sys
from pathlib import Path


def exercises(build):
    text = (Path(build) / "generated/aula/exercise_abi.hpp").read_text()
    for name, headers in re.findall(r'\{"(\w+)", \d+, "[^"]*", "[^"]*", "([^"]*)"\}', text):
        yield name, [entry.split(":", 1)[1] for entry in headers.split(";")]


def api_members(header_text):
    """(name, documented, line) of each member of each `struct XApi { ... };`."""
    for body in re.findall(r"^struct \w+Api \{\n(.*?)^\};", header_text, re.M | re.S):
        lines = body.split("\n")
        for i, line in enumerate(lines):
            code = re.sub(r"/\*.*?\*/|//.*", "", line).strip()
            # a data member (`Type& name;`, `Type a, b = 1;`) or a method (`double time_s() const {`)
            method = re.match(r"[\w:<>&\s]+?\b(\w+)\(\)[^;]*\{", code)
            field = re.match(r"[\w:<>]+&?\s+(.*?);$", code) if not method else None
            if not (method or field) or code.startswith(("TaxiApi(", "explicit", "return")):
                continue
            before = lines[i - 1].strip() if i > 0 else ""
            documented = ("///<" in line or line.strip().startswith("/**") or before.startswith("///")
                          or before.startswith("/**"))
            names = [method.group(1)] if method else [re.match(r"(\w+)", d.strip()).group(1)
                                                      for d in field.group(1).split(",")]
            for name in names:
                yield name, documented, line.strip()


def main(source, build):
    problems = []
    for name, headers in exercises(build):
        page = (Path(source) / "docs/exercises" / f"{name}.md").read_text()
        code_words = set(re.findall(r"\b\w+\b", " ".join(re.findall(r"`([^`]*)`", page))))
        found = 0
        for header in headers:
            for member, documented, line in api_members((Path(source) / header).read_text()):
                found += 1
                if not documented:
                    problems.append(f"{header}: the API member {member} has no doc comment (///<): {line}")
                if member not in code_words:
                    problems.append(f"docs/exercises/{name}.md does not name the API member {member} ({header})")
        if found == 0:
            problems.append(f"{name}: no struct ...Api in its API headers {headers}")
    print("\n".join(problems) if problems else "every API member is documented and named in its page")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
