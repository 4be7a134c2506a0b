# Checks, inside Aula's Python, that the shipped .pyi stubs name exactly what the exercise's
# module binds: every class with every public member, every function. Run in any exercise: it
# checks the module that exercise has (aula_vacuum, aula_teletaxi or aula_autopark), prints
# "stubs match: MODULE", and raises when a name is missing on either side. It prints the seed it
# was made with, too.
import ast
import importlib
import os

SOURCE = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", ".."))


def stub_names(path):
    """{class: {members}} and {functions} declared in a .pyi, re-exports resolved."""
    tree = ast.parse(open(path).read(), path)
    classes, functions = {}, set()
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            members = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    members.add(item.name)
                elif isinstance(item, ast.AnnAssign):
                    members.add(item.target.id)
            classes[node.name] = members
        elif isinstance(node, ast.FunctionDef):
            functions.add(node.name)
        elif isinstance(node, ast.ImportFrom) and node.module == "aula_devices":
            devices, _ = stub_names(os.path.join(os.path.dirname(path), "aula_devices.pyi"))
            for alias in node.names:
                classes[alias.asname or alias.name] = devices[alias.name]
    return classes, functions


def check(name):
    exercise = name[len("aula_"):]
    classes, functions = stub_names(os.path.join(SOURCE, "components", exercise, "student", name + ".pyi"))
    module = importlib.import_module(name)
    bound = {n for n in dir(module) if not n.startswith("_")}
    if bound != set(classes) | functions:
        raise AssertionError(f"{name}: bound but not in the stub: {sorted(bound - set(classes) - functions)}; "
                             f"in the stub but not bound: {sorted(set(classes) | functions - bound)}")
    for cls, members in classes.items():
        have = {n for n in dir(getattr(module, cls)) if not n.startswith("_")}
        if have != members:
            raise AssertionError(f"{name}.{cls}: bound but not in the stub: {sorted(have - members)}; "
                                 f"in the stub but not bound: {sorted(members - have)}")
    print("stubs match:", name, flush=True)


class MyAlgorithm:
    def __init__(self, seed):
        print(f"MyAlgorithm(seed={seed})", flush=True)  # the run's seed, in every exercise
        for name in ("aula_vacuum", "aula_teletaxi", "aula_autopark"):
            try:
                importlib.import_module(name)
            except ImportError:
                continue
            check(name)

    def generatePath(self, api):
        pass

    def execute(self, api):
        api.motors.sendV(0.0)
