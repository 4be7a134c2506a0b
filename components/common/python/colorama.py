# colorama, when Debian's python3-colorama is not installed: its names, no colours (Aula's console
# and the run's log keep plain text). Said once, when a program imports it.
import sys as _sys


class _NoColour:
    def __getattr__(self, name):
        return ""


Fore = Back = Style = Cursor = _NoColour()


def init(*args, **kwargs):
    pass


deinit = reinit = just_fix_windows_console = init

print("[aula] colorama: Aula's Python has no python3-colorama; its colours are left out", file=_sys.stderr)
