# termcolor, when Debian's python3-termcolor is not installed: colored() gives the text as it is,
# cprint() prints it (Aula's console and the run's log keep plain text). Said once, when imported.
import sys as _sys


def colored(text, *args, **kwargs):
    return str(text)


def cprint(text, *args, **kwargs):
    print(colored(text), **{k: v for k, v in kwargs.items() if k in ("sep", "end", "file", "flush")})


COLORS, HIGHLIGHTS, ATTRIBUTES = {}, {}, {}

print("[aula] termcolor: Aula's Python has no python3-termcolor; its colours are left out", file=_sys.stderr)
