"""The type stubs (tribez/*.pyi) describe the package as it is: every public name, and the same
parameters for every public function and method."""

import ast
import inspect
import pathlib

import tribez
import tribez.testing

PKG = pathlib.Path(tribez.__file__).resolve().parent


def stub(name):
    return ast.parse((PKG / name).read_text())


def params(node):
    a = node.args
    names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
    if a.vararg:
        names.append("*" + a.vararg.arg)
    if a.kwarg:
        names.append("**" + a.kwarg.arg)
    return [n for n in names if n not in ("self", "cls")]


def runtime_params(f):
    out = []
    for p in inspect.signature(f).parameters.values():
        if p.name in ("self", "cls") or p.name.startswith("_"):
            continue
        prefix = {p.VAR_POSITIONAL: "*", p.VAR_KEYWORD: "**"}.get(p.kind, "")
        out.append(prefix + p.name)
    return out


def check_module(tree, module):
    seen = 0
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            assert params(node) == runtime_params(getattr(module, node.name)), node.name
            seen += 1
        elif isinstance(node, ast.ClassDef):
            cls = getattr(module, node.name)
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    attr = inspect.getattr_static(cls, item.name)
                    if isinstance(attr, property):
                        continue
                    assert params(item) == runtime_params(getattr(cls, item.name)), f"{node.name}.{item.name}"
                    seen += 1
    return seen


def test_stubs_match_the_package():
    tree = stub("__init__.pyi")
    names = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    names |= {a.asname or a.name for n in tree.body if isinstance(n, ast.ImportFrom) for a in n.names}
    assert set(tribez.__all__) <= names, set(tribez.__all__) - names
    assert check_module(tree, tribez) >= 10
    assert check_module(stub("testing.pyi"), tribez.testing) == 1
    for name in ("check", "check_claims", "certify", "Patch", "Report", "InputError"):
        assert name in names
