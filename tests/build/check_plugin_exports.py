#!/usr/bin/env python3
"""A component exports to the plugins it loads only the student API (issue 28).

Usage: check_plugin_exports.py NM EXPORTS_LIST@COMPONENT[=PLUGIN,PLUGIN...]...

Each component's dynamic symbols (nm -D --defined-only, demangled) are checked against the
linker dynamic list it is linked with (build/plugin_exports/<exercise>.list: the common patterns
of cmake/aula_plugin_exports.list.in and the exercise's own): every symbol that names
Aula must match one of the list's patterns (globs on demangled names, as ld reads them). The
others are what any program exports for the shared libraries it links (libc's and libstdc++'s
copy relocations, template instances of the standard library's or OMPL's that a library also
defines, the linker's section marks). A component linked with -rdynamic (ENABLE_EXPORTS) exports
its references and some 800 other symbols of Aula's, and fails here; so does a pattern that
reaches past the API (Laser* also exports the LCM proxy LaserProxy).

The PLUGINs after a component are its exercise's built-in algorithms (the references, plugins of
their own since no component contains them): every symbol of the API they call must be one the
component exports, or they (and a student's plugin calling the same) would fail to load.
"""
import fnmatch
import re
import subprocess
import sys



def patterns(list_path):
    text = re.sub(r"/\*.*?\*/", "", open(list_path).read(), flags=re.S)
    cxx = re.search(r'extern\s+"C\+\+"\s*\{(.*?)\}', text, flags=re.S)
    plain = text.replace(cxx.group(0), "") if cxx else text
    names = lambda block: [p.strip() for p in block.replace("{", "").replace("}", "").split(";") if p.strip()]
    return names(plain), names(cxx.group(1)) if cxx else []


def exports(nm, program):
    out = subprocess.run([nm, "-D", "--defined-only", "-C", program], check=True, capture_output=True, text=True).stdout
    # "0000000000012340 T name": the name is everything after the type letter.
    return [line.split(" ", 2)[2] for line in out.splitlines() if line.count(" ") >= 2]


def imports(nm, plugin):
    out = subprocess.run([nm, "-D", "--undefined-only", "-C", plugin], check=True, capture_output=True, text=True).stdout
    return [line.strip().split(" ", 1)[1] for line in out.splitlines() if line.strip().startswith("U ")]


def main():
    nm, arguments = sys.argv[1], sys.argv[2:]
    if not arguments:
        print("FAIL: no component to check")
        return 1
    failures = 0
    for argument in arguments:
        list_path, rest = argument.split("@", 1)
        program, _, plugins = rest.partition("=")
        c_names, cxx_globs = patterns(list_path)
        if not cxx_globs:
            print(f"FAIL: no extern \"C++\" patterns in {list_path}")
            return 1
        symbols = exports(nm, program)
        api = [s for s in symbols if s in c_names or any(fnmatch.fnmatchcase(s, g) for g in cxx_globs)]
        stray = [s for s in symbols if s not in api and "aula" in s.lower()]
        name = program.rsplit("/", 1)[-1]
        if stray:
            failures += 1
            print(f"FAIL: {name} exports {len(stray)} symbol(s) that are not the student API:")
            for s in stray[:20]:
                print(f"  {s[:160]}")
        if not api:
            failures += 1
            print(f"FAIL: {name} exports nothing of the student API (is it linked with {list_path}?)")
        for plugin in filter(None, plugins.split(",")):
            wanted = [s for s in imports(nm, plugin) if "aula" in s.lower()]
            missing = [s for s in wanted if s not in api]
            if missing:
                failures += 1
                print(f"FAIL: {plugin.rsplit('/', 1)[-1]} calls {len(missing)} symbol(s) {name} does not export:")
                for s in missing[:20]:
                    print(f"  {s[:160]}")
            else:
                print(f"{plugin.rsplit('/', 1)[-1]}: the {len(wanted)} API symbols it calls are exported by {name}")
        if not stray and api:
            print(f"{name}: {len(api)} API symbols exported, nothing else of Aula's ({len(symbols)} in all)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
