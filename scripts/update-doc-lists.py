#!/usr/bin/env python3
"""The lists the docs give of commands, options, settings, libraries and grades.csv columns, kept
equal to the code.

Generated blocks, between `<!-- generated:NAME ... -->` and `<!-- end:NAME -->`, are rewritten
from what the programs say of themselves (`aula --help`, `aula run --help`, the libs/ folders and
their CMakeLists' first comment, the header grades.csv gets from `gradesCsv`). Everything else a
doc names is checked where it stands:
  - every `aula COMMAND` and `aula COMMAND --option` in a code span or block is declared
    (`aula COMMAND --help`);
  - every `Section.Key` of a settings section is declared (`aula config EXERCISE`, `aula-sim --help`),
    and a table row that gives a key's value gives the one `aula config` shows;
  - every command's row in docs/architecture.md's command table is a command, and each command
    has a row; its layer table has a row naming each library of libs/;
  - every `--option` standing alone is declared by an Aula program or used by Aula's code (what it
    passes to bwrap, prlimit or sbatch, and between its own processes);
  - every path a doc names in backquotes (`libs/.../x.hpp`) exists.

  scripts/update-doc-lists.py [BUILD_DIR]          rewrite the generated blocks
  scripts/update-doc-lists.py --check [BUILD_DIR]  exit 1 naming each drift (the test docs.ListsMatchTheCode)
The grades.csv columns come from build/bin/aula-test-grades-columns
(`cmake --build build --target aula-test-grades-columns`).
"""
import difflib
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The docs whose lists are kept; adding-an-exercise.md names files a new exercise is to create.
DOCS = ["README.md"] + sorted(p for p in glob.glob("docs/**/*.md", root_dir=ROOT, recursive=True)
                              if p != "docs/adding-an-exercise.md")
TOP_FOLDERS = "bench cmake components config docs drivers lcmtypes libs referees scripts simulator tests tools worlds".split()


def run(args):
    out = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if out.returncode != 0:
        sys.exit(f"{' '.join(args)} failed ({out.returncode}):\n{out.stdout}")
    return out.stdout


def section(text, title):
    """The lines under `title:` in a --help, up to the next unindented line."""
    lines, inside = [], False
    for line in text.splitlines():
        if line == title:
            inside = True
        elif inside and line and not line.startswith(" "):
            break
        elif inside:
            lines.append(line)
    return lines


class Code:
    """What the build's programs say of themselves."""

    def __init__(self, build):
        self.build = build
        aula = os.path.join(build, "bin", "aula")
        top = run([aula, "--help"])
        self.commands = []  # (name, summary)
        for line in section(top, "commands:"):
            name, summary = re.match(r"\s+(\S+)\s+(.*)", line).groups()
            self.commands.append((name, summary))
        self.usage = {re.match(r"\s+usage: aula (\S+)", l).group(1): l.strip()[len("usage: "):]
                      for l in section(top, "usage of each:")}
        self.exercises = [re.match(r"\s+(\S+)", l).group(1) for l in section(top, "exercises:")]
        self.help = {name: run([aula, name, "--help"]) for name, _ in self.commands}
        self.settings = set()
        self.values = {}  # key -> the effective values `aula config` shows, over the exercises
        for exercise in self.exercises:
            for line in run([aula, "config", exercise]).splitlines():
                m = re.match(r"\s+([A-Z][\w.]*) = (.*?)    \[", line)
                if m:
                    self.settings.add(m.group(1))
                    self.values.setdefault(m.group(1), set()).add(m.group(2).strip())
        for line in run([os.path.join(build, "bin", "aula-sim"), "--help"]).splitlines():
            m = re.match(r"\s+([A-Z][\w.]*(?:\.\*)?)\s+\(", line)
            if m:
                self.settings.add(m.group(1))
        self.sections = {key.split(".")[0] for key in self.settings}
        # The other programs a doc may show with options (the build's bin/ less aula, the tests and
        # the benchmarks): each one's --help names all it takes.
        self.programs = {}
        for name in sorted(os.listdir(os.path.join(build, "bin"))):
            if name == "aula" or name.startswith(("test_", "bench_", "aula-test-")):
                continue
            text = run([os.path.join(build, "bin", name), "--help"])
            self.programs[name] = (text, set(re.findall(r"(?<![\w-])--([a-z][\w-]*)", text)) | {"help"})

    def options(self, command):
        """(syntax, help) of each option `aula COMMAND --help` declares."""
        lines = section(self.help[command], "options:")
        return [(lines[i].strip(), lines[i + 1].strip()) for i in range(0, len(lines) - 1, 2)]

    def option_names(self, command):
        return {re.match(r"--([\w.-]+)", syntax).group(1) for syntax, _ in self.options(command)}

    def grades_columns(self):
        header = run([os.path.join(self.build, "bin", "aula-test-grades-columns")]).strip()
        return header.split(",")


def libraries():
    """Each libs/ folder and the first sentence of its CMakeLists' opening comment."""
    out = []
    for folder in sorted(os.listdir(os.path.join(ROOT, "libs"))):
        cmake = os.path.join(ROOT, "libs", folder, "CMakeLists.txt")
        if not os.path.isfile(cmake):
            continue
        comment = []
        for line in open(cmake):
            if not line.startswith("#"):
                break
            comment.append(line[1:].strip())
        text = " ".join(comment)
        m = re.match(r"(aula_\w+): (.*?\.)(?:\s|$)", text)
        if not m:
            sys.exit(f"libs/{folder}/CMakeLists.txt: its first line should say `# aula_{folder}: what it is.`")
        out.append((folder, m.group(1), m.group(2)))
    return out


def cell(text):
    """Text for a Markdown table's cell: a `|` there ends the cell, even in a code span."""
    return text.replace("|", "\\|")


def generated(code):
    """NAME -> the block's text, generated."""
    blocks = {}
    rows = ["| command | what it does |", "|---|---|"]
    rows += [f"| `{cell(code.usage[name])}` | {cell(summary)} |" for name, summary in code.commands]
    blocks["commands"] = "\n".join(rows)
    rows = ["| option | meaning |", "|---|---|"]
    rows += [f"| `{cell(syntax)}` | {cell(meaning)} |" for syntax, meaning in code.options("run") if syntax != "--help"]
    blocks["run-options"] = "\n".join(rows)
    blocks["aula-sim-usage"] = "```\n" + code.programs["aula-sim"][0].split("\n  WORLD")[0].rstrip() + "\n```"
    blocks["libs"] = "\n".join(f"- `{folder}` (`{target}`): {what}" for folder, target, what in libraries())
    # A column per world and per measure: the helper names them <world> and <measure>.
    columns = [f"`{c}`..." if c.startswith("median_<") else f"`{c}`" for c in code.grades_columns()]
    blocks["grades-columns"] = ", ".join(columns)
    return blocks


BLOCK = re.compile(r"(<!-- generated:([\w-]+)[^>]*-->\n)(.*?)(<!-- end:\2 -->)", re.S)


def rewrite(text, blocks, path, problems):
    def fill(m):
        name = m.group(2)
        if name not in blocks:
            problems.append(f"{path}: unknown generated block '{name}'")
            return m.group(0)
        return m.group(1) + blocks[name] + "\n" + m.group(4)
    return BLOCK.sub(fill, text)


def code_spans(text):
    """The text of each code span and each line of a code block, with its line number."""
    in_block = False
    for number, line in enumerate(text.splitlines(), 1):
        if line.lstrip().startswith("```"):
            in_block = not in_block
            continue
        if in_block:
            yield number, line
        else:
            for m in re.finditer(r"`([^`]+)`", line):
                yield number, m.group(1)


def check_commands_and_options(path, text, code, problems):
    names = {name for name, _ in code.commands}
    for number, span in code_spans(text):
        for m in re.finditer(r"(?:^|[\s/(])aula ([a-z][\w-]*)((?:\s+[^|;&#`]*)?)", span):
            command, rest = m.group(1), m.group(2)
            if command not in names:
                # `aula EXERCISE` is no command of aula's; `aula` followed by prose is not a command line.
                if re.match(r"(?:run|grade|new|config|check|re|cal)", command):
                    problems.append(f"{path}:{number}: `aula {command}` is no command (aula --help)")
                continue
            declared = code.option_names(command) | {"help"}
            for option in re.findall(r"(?<![\w-])--([a-z][\w-]*)", rest):
                if option not in declared:
                    problems.append(f"{path}:{number}: `aula {command} --{option}` is not declared (aula {command} --help)")


def check_program_options(path, text, code, problems):
    """A program's command line in a doc (`aula-sim WORLD --rtf 0`, `build/bin/teletaxi --config=...`)."""
    names = "|".join(re.escape(n) for n in sorted(code.programs, key=len, reverse=True))
    for number, span in code_spans(text):
        m = re.match(r"\s*(?:\./|build/bin/|\$build/bin/|<bin>/)?(%s)(\s.*)?$" % names, span)
        if not m:
            continue
        program, rest = m.group(1), (m.group(2) or "").split("#")[0]
        for option in re.findall(r"(?<![\w-])--([a-z][\w-]*)", rest):
            if option not in code.programs[program][1]:
                problems.append(f"{path}:{number}: `{program} --{option}` is not an option of {program} ({program} --help)")


def source_text():
    """Aula's own C++ sources, where the options it passes to other programs (bwrap, prlimit, sbatch)
    and between its own processes (--control-fd) are written, and the world generators
    (worlds/tools/*.py), whose options the docs' bench commands use."""
    text = []
    for folder in ("components", "drivers", "libs", "referees", "simulator", "tools"):
        for name in glob.glob(f"{folder}/**/*.[ch]pp", root_dir=ROOT, recursive=True):
            text.append(open(os.path.join(ROOT, name), errors="replace").read())
    for name in glob.glob("worlds/tools/*.py", root_dir=ROOT):
        text.append(open(os.path.join(ROOT, name), errors="replace").read())
    return "\n".join(text)


def check_loose_options(path, text, code, source, problems):
    """A `--option` standing alone in a doc: an Aula program declares it, or Aula's code uses it."""
    declared = set().union(*(code.option_names(name) for name, _ in code.commands),
                           *(options for _, options in code.programs.values()))
    for number, line in enumerate(text.splitlines(), 1):
        for m in re.finditer(r"`--([a-z][\w-]*)", line):
            option = m.group(1)
            if option in declared or re.search(r'(--%s(?![\w-])|"%s")' % (re.escape(option), re.escape(option)), source):
                continue
            problems.append(f"{path}:{number}: `--{option}` is no option of any Aula program, nor used by Aula's code")


def declared_setting(key, code):
    if key in code.settings:
        return True
    if any(s.startswith(key + ".") for s in code.settings):  # a group: `Vacuum.Window`
        return True
    return any(s.endswith(".*") and key.startswith(s[:-1]) for s in code.settings)  # a family


def check_settings(path, text, code, problems):
    pattern = re.compile(r"(?<![\w.])((?:%s)\.[A-Z][\w]*(?:\.[\w]+)*)(\.\*)?" % "|".join(sorted(code.sections)))
    for number, line in enumerate(text.splitlines(), 1):
        for m in pattern.finditer(line):
            key = m.group(1).rstrip(".")
            if "Key" in key.split("."):  # `--Simulator.Key=value`: a placeholder, not a setting
                continue
            if not declared_setting(key, code):
                problems.append(f"{path}:{number}: setting {key} is not declared (aula config EXERCISE)")


def check_setting_tables(path, text, code, problems):
    """A table row `| `Key` | 2 s of CPU | ...`: the number it gives is the key's value in `aula config`."""
    for number, line in enumerate(text.splitlines(), 1):
        m = re.match(r"\|\s*`([A-Z][\w.]*)`\s*\|\s*(-?[0-9][0-9.]*)", line)
        if not m or m.group(1) not in code.values:
            continue
        shown = {re.match(r"-?[0-9.]*", v).group(0) for v in code.values[m.group(1)]}
        if len(shown) == 1 and float(m.group(2)) != float(shown.pop() or "nan"):
            problems.append(f"{path}:{number}: {m.group(1)} is {sorted(code.values[m.group(1)])[0]} (aula config), the doc says {m.group(2)}")


def check_paths(path, text, problems):
    top = "|".join(TOP_FOLDERS)
    for number, line in enumerate(text.splitlines(), 1):
        for m in re.finditer(r"`((?:%s)/[\w./+-]*)`" % top, line):
            if not os.path.exists(os.path.join(ROOT, m.group(1))):
                problems.append(f"{path}:{number}: `{m.group(1)}` does not exist")


def check_command_table(text, code, problems):
    """docs/architecture.md, "The command table": one row per command."""
    table = text.split("### The command table", 1)[1].split("\n#", 1)[0]
    rows = re.findall(r"^\| `([a-z][\w-]*)[ `]", table, re.M)
    names = [name for name, _ in code.commands]
    if sorted(rows) != sorted(names):
        problems.append(f"docs/architecture.md, \"The command table\": rows {rows}, commands {names} (aula --help)")


def check_library_rows(text, problems):
    """docs/architecture.md's layer table names every library of libs/."""
    rows = "\n".join(line for line in text.splitlines() if line.startswith("| libs |"))
    for folder, target, _ in libraries():
        if f"`{target}`" not in rows:
            problems.append(f"docs/architecture.md, \"Layers\": no `| libs |` row names `{target}` (libs/{folder})")


def main():
    args = sys.argv[1:]
    check = "--check" in args
    args = [a for a in args if a != "--check"]
    build = os.path.abspath(args[0] if args else os.path.join(ROOT, "build"))
    code = Code(build)
    blocks = generated(code)
    problems, used = [], set()
    source = source_text()
    for path in DOCS:
        full = os.path.join(ROOT, path)
        text = open(full).read()
        used.update(m.group(2) for m in BLOCK.finditer(text))
        new = rewrite(text, blocks, path, problems)
        if new != text:
            if check:
                diff = difflib.unified_diff(text.splitlines(), new.splitlines(), path, path + " (generated)", lineterm="")
                problems.append(f"{path}: a generated list differs from the code:\n" + "\n".join(diff))
            else:
                open(full, "w").write(new)
                print(f"{path}: regenerated")
        check_commands_and_options(path, new, code, problems)
        check_program_options(path, new, code, problems)
        check_loose_options(path, new, code, source, problems)
        check_settings(path, new, code, problems)
        check_setting_tables(path, new, code, problems)
        check_paths(path, new, problems)
        if path == "docs/architecture.md":
            check_command_table(new, code, problems)
            check_library_rows(new, problems)
    for name in sorted(set(blocks) - used):
        problems.append(f"no doc holds the generated block '{name}'")
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} drift(s); regenerate with scripts/update-doc-lists.py, fix the rest by hand")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
