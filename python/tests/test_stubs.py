"""The type stubs (__init__.pyi, _boreas.pyi) describe the API that is there: every public
name, every method, and the parameters of every Python function in order."""
import ast
import inspect
import os

import pytest

import boreas
from boreas import _boreas


def stub(name):
    with open(os.path.join(os.path.dirname(boreas.__file__), name)) as f:
        return ast.parse(f.read())


def definitions(tree):
    """{name: node} of a module's or class's functions, classes and annotated names."""
    out = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            # A property's setter repeats its name; the getter stands for both.
            out.setdefault(node.name, node)
        elif isinstance(node, ast.AnnAssign):
            out[node.target.id] = node
        elif isinstance(node, ast.ImportFrom) and node.module == "_boreas":  # re-exports
            for alias in node.names:
                out[alias.asname or alias.name] = node
    return out


def parameters(fn):
    args = fn.args
    names = [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs]
    if args.vararg:
        names.append("*" + args.vararg.arg)
    if args.kwarg:
        names.append("**" + args.kwarg.arg)
    return names


def runtime_parameters(fn):
    out = []
    for p in inspect.signature(fn).parameters.values():
        prefix = {p.VAR_POSITIONAL: "*", p.VAR_KEYWORD: "**"}.get(p.kind, "")
        out.append(prefix + p.name)
    return out


PACKAGE = definitions(stub("__init__.pyi"))


@pytest.mark.parametrize("name", boreas.__all__)
def test_every_public_name_is_in_the_stub(name):
    assert name in PACKAGE


@pytest.mark.parametrize("name", [n for n in boreas.__all__
                                  if isinstance(PACKAGE.get(n), (ast.FunctionDef, ast.ClassDef))])
def test_stub_signatures_match(name):
    node, obj = PACKAGE[name], getattr(boreas, name)
    if isinstance(node, ast.FunctionDef):
        assert parameters(node) == runtime_parameters(obj)
        return
    members = definitions(node)
    public = {m for m in vars(obj) if not m.startswith("_") or m in ("__init__", "__enter__",
                                                                      "__exit__")}
    if "__dataclass_fields__" in vars(obj):  # the stub's @dataclass makes these
        public -= set(obj.__dataclass_fields__) | {"__init__"}
    for member in public:
        assert member in members, f"{name}.{member} is missing from __init__.pyi"
    for member, fn in members.items():
        fields = getattr(obj, "__dataclass_fields__", {})
        assert hasattr(obj, member) or member in fields, f"{name}.{member} is not in boreas"
        value = inspect.getattr_static(obj, member, None)
        if isinstance(fn, ast.FunctionDef) and inspect.isfunction(value):
            assert parameters(fn) == runtime_parameters(value), f"{name}.{member}"
    for field in getattr(obj, "__dataclass_fields__", {}):
        assert field in members, f"{name}.{field} is missing from __init__.pyi"


def test_the_extension_stub_lists_what_the_module_has():
    names = definitions(stub("_boreas.pyi"))
    public = {n for n in dir(_boreas) if not n.startswith("_")} | {"__version__"}
    assert public == {n for n in names if n not in ("Id", "Fields")}
    world = definitions(names["World"])
    assert {m for m in dir(_boreas.World) if not m.startswith("_")} | {"__init__"} == set(world)


@pytest.mark.parametrize("name", [n for n in boreas.__all__ if n != "__version__"])
def test_every_public_name_has_a_docstring(name):
    obj = getattr(boreas, name)
    if isinstance(obj, (int, type(boreas.BRANCH_DTYPE))):
        return  # constants: documented in the module and README
    assert obj.__doc__ and obj.__doc__.strip()
    if inspect.isclass(obj):
        for member, value in vars(obj).items():
            if not member.startswith("_") and (callable(value) or isinstance(value, property)):
                assert value.__doc__, f"{name}.{member}"
