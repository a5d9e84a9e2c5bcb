"""The import rules of the layout, read from the source with ``ast`` (nothing is imported for them).

Layers, lowest first: ``asymptotics`` < ``numeric.core`` < ``numeric.solutions`` and
``numeric.baseline`` (siblings) < ``numeric`` (the public API, ``numeric/__init__.py``) <
``numeric.studies`` < ``numeric.app``. A module imports its own layer or lower ones; the
baseline (the paper's scheme, kept independent on purpose) only ``asymptotics``, numpy,
scipy, mpmath and the standard library. Also: no cycle between modules (lazy imports inside
functions count), no private name taken from another module (by import or as an attribute
of an imported module; ``derivations/`` scripts included), no re-export from a subpackage's
``__init__``, and no submodule shadowed by an attribute of its package of the same name.

Each rule is also run on small made-up trees that break it (``test_each_rule_catches_its_offence``),
so a rule that stops firing fails here.
"""

from __future__ import annotations

import ast
import importlib
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("asymptotics", "numeric")
#: layer -> rank; a module may import a layer of lower or equal rank (siblings of equal rank excepted)
LAYERS = {"asymptotics": 0, "numeric.core": 1, "numeric.solutions": 2, "numeric.baseline": 2, "numeric": 3,
          "numeric.plane": 3, "numeric.studies": 4, "numeric.app": 5}
BASELINE_MAY_IMPORT = {"numpy", "scipy", "mpmath"}
# top-level packages and the plane-strain API (numeric.plane mirrors numeric's API): their __init__ may re-export
API_PACKAGES = {"numeric", "numeric.plane", "asymptotics"}


@dataclass(frozen=True)
class Module:
    name: str
    path: Path
    is_package: bool
    tree: ast.Module


@dataclass(frozen=True)
class Import:
    source: str
    target: str  # a module: a project module, or the top of a third-party one
    line: int
    names: tuple[str, ...]  # the names taken from ``target`` (empty for a whole module)


def load(root: Path, packages=PACKAGES, scripts: str | None = None) -> dict[str, Module]:
    """Every module of ``packages`` under ``root`` (and the scripts of the folder ``scripts``)."""
    out = {}
    folders = [(root / p, True) for p in packages] + ([(root / scripts, False)] if scripts else [])
    for folder, is_package_tree in folders:
        for path in sorted(folder.rglob("*.py") if is_package_tree else folder.glob("*.py")):
            parts = list(path.relative_to(root).with_suffix("").parts)
            is_package = parts[-1] == "__init__"
            name = ".".join(parts[:-1] if is_package else parts)
            out[name] = Module(name, path, is_package, ast.parse(path.read_text(encoding="utf-8"), str(path)))
    return out


def _resolve(module: Module, node: ast.ImportFrom) -> str:
    if not node.level:
        return node.module or ""
    base = module.name.split(".") if module.is_package else module.name.split(".")[:-1]
    base = base[: len(base) - node.level + 1]
    return ".".join(base + ([node.module] if node.module else []))


def imports(modules: dict[str, Module]) -> list[Import]:
    """Every import statement of every module, at any depth, resolved to the module it reaches."""
    out = []
    for module in modules.values():
        for node in ast.walk(module.tree):
            if isinstance(node, ast.Import):
                out += [Import(module.name, alias.name, node.lineno, ()) for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module != "__future__":
                base = _resolve(module, node)
                for alias in node.names:
                    full = f"{base}.{alias.name}"
                    if full in modules:
                        out.append(Import(module.name, full, node.lineno, ()))
                    else:
                        out.append(Import(module.name, base, node.lineno, (alias.name,)))
    return out


def _project(name: str) -> bool:
    return name.split(".")[0] in PACKAGES


def layer_of(name: str) -> str | None:
    """The layer of a project module (the longest layer prefix); None for a numeric module outside the
    layer folders (only numeric/__init__.py itself is the API layer)."""
    if name in ("numeric", "numeric.plane"):
        return name
    for layer in sorted(LAYERS, key=len, reverse=True):
        if layer != "numeric" and (name == layer or name.startswith(layer + ".")):
            return layer
    return None


def layer_violations(modules: dict[str, Module]) -> list[str]:
    out = []
    for name in modules:
        if _project(name) and layer_of(name) is None:
            out.append(f"{name}: not in a layer folder ({', '.join(LAYERS)})")
    for imp in imports(modules):
        source, target = layer_of(imp.source), layer_of(imp.target) if _project(imp.target) else None
        if source is None or not _project(imp.source):
            continue
        where = f"{imp.source}:{imp.line} imports {imp.target}"
        if source == "numeric.baseline":
            top = imp.target.split(".")[0]
            if target not in (None, "numeric.baseline", "asymptotics") or (
                    target is None and top not in BASELINE_MAY_IMPORT and top not in sys.stdlib_module_names):
                out.append(f"{where}: the baseline imports only asymptotics, numpy, scipy, mpmath, the stdlib")
            continue
        if target is None or target == source:
            continue
        if LAYERS[target] > LAYERS[source]:
            out.append(f"{where}: upward ({source} -> {target})")
        elif LAYERS[target] == LAYERS[source]:
            out.append(f"{where}: sideways between sibling layers ({source} -> {target})")
    return out


def cycles(modules: dict[str, Module]) -> list[list[str]]:
    """Strongly connected components of more than one module (or a module importing itself)."""
    graph: dict[str, set[str]] = {name: set() for name in modules}
    for imp in imports(modules):
        if imp.target in modules:
            graph[imp.source].add(imp.target)
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    out = []

    def visit(v: str) -> None:  # Tarjan
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1 or v in graph[v]:
                out.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def private_imports(modules: dict[str, Module]) -> list[str]:
    """Private names taken from another project module: imported, or read as an attribute of a
    name bound to a project module."""
    out = [f"{imp.source}:{imp.line} imports {name} from {imp.target}"
           for imp in imports(modules) if _project(imp.target) for name in imp.names if _private(name)]
    out += [f"{imp.source}:{imp.line} imports the private module {imp.target}"
            for imp in imports(modules) if _project(imp.target) and any(_private(p) for p in imp.target.split("."))]
    for module in modules.values():
        bound = set()
        for node in ast.walk(module.tree):
            if isinstance(node, ast.ImportFrom) and node.module != "__future__":
                base = _resolve(module, node)
                bound |= {alias.asname or alias.name for alias in node.names if f"{base}.{alias.name}" in modules}
            elif isinstance(node, ast.Import):
                bound |= {alias.asname for alias in node.names if alias.asname and _project(alias.name)}
        for node in ast.walk(module.tree):
            if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in bound
                    and _private(node.attr)):
                out.append(f"{module.name}:{node.lineno} reads {node.value.id}.{node.attr}")
    return out


def reexports(modules: dict[str, Module]) -> list[str]:
    """Subpackage __init__ files that import anything or set __all__ (only the top packages re-export)."""
    out = []
    for module in modules.values():
        if not module.is_package or module.name in API_PACKAGES:
            continue
        for node in module.tree.body:
            if isinstance(node, (ast.Import, ast.ImportFrom)) and getattr(node, "module", None) != "__future__":
                out.append(f"{module.name}:{node.lineno}: a subpackage __init__ imports (re-exports)")
            if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets):
                out.append(f"{module.name}:{node.lineno}: a subpackage __init__ sets __all__")
    return out


def _bindings(module: Module) -> dict[str, str | None]:
    """Names bound at the top of a module -> the module they are bound to (None for anything else)."""
    out: dict[str, str | None] = {}
    for node in module.tree.body:
        if isinstance(node, ast.ImportFrom) and node.module != "__future__":
            base = _resolve(module, node)
            for alias in node.names:
                out[alias.asname or alias.name] = f"{base}.{alias.name}"
        elif isinstance(node, ast.Import):
            for alias in node.names:
                out[alias.asname or alias.name.split(".")[0]] = alias.name if alias.asname else alias.name.split(".")[0]
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            out[node.name] = None
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            for target in node.targets if isinstance(node, ast.Assign) else [node.target]:
                if isinstance(target, ast.Name):
                    out[target.id] = None
    return out


def shadowed(modules: dict[str, Module]) -> list[str]:
    """Submodules whose name the package's __init__ binds to something else (a function, say)."""
    out = []
    for package in (m for m in modules.values() if m.is_package):
        children = {name.rsplit(".", 1)[1] for name in modules if name.rsplit(".", 1)[0] == package.name and name != package.name}
        for name, bound in _bindings(package).items():
            if name in children and bound != f"{package.name}.{name}":
                out.append(f"{package.name}.{name}: the module is shadowed by the package's own '{name}'")
    return out


MODULES = load(ROOT, scripts="derivations")
PACKAGE_MODULES = {k: v for k, v in MODULES.items() if _project(k)}


def test_every_import_goes_down_a_layer():
    assert layer_violations(PACKAGE_MODULES) == []


def test_no_cycle_between_modules():
    assert cycles(PACKAGE_MODULES) == []


def test_no_private_name_crosses_a_module():
    assert private_imports(MODULES) == []


def test_subpackage_inits_do_not_reexport():
    assert reexports(PACKAGE_MODULES) == []


def test_no_module_is_shadowed_statically():
    assert shadowed(PACKAGE_MODULES) == []


def test_no_module_is_shadowed_once_imported():
    # the same as it happens: after importing every module, each package's attribute of a
    # submodule's name is that submodule (not a function the __init__ bound over it)
    names = sorted(PACKAGE_MODULES)
    for name in names:
        importlib.import_module(name)
    for name in names:
        parent, _, child = name.rpartition(".")
        if parent:
            assert getattr(sys.modules[parent], child) is sys.modules[name], name


def test_the_layers_are_folders():
    folders = {p.name for p in (ROOT / "numeric").iterdir() if (p / "__init__.py").exists()}
    assert folders == {"core", "solutions", "baseline", "studies", "app", "plane"}
    assert [p.name for p in (ROOT / "numeric").glob("*.py")] == ["__init__.py"]


# ------------------------------------------------------------------------------------------
# the rules catch what they are for


def _tree(tmp_path: Path, files: dict[str, str]) -> dict[str, Module]:
    for rel in ("asymptotics/__init__.py", "numeric/__init__.py", "numeric/core/__init__.py",
                "numeric/solutions/__init__.py", "numeric/baseline/__init__.py", *files):
        path = tmp_path / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(files.get(rel, '"""A package."""\n'), encoding="utf-8")
    return load(tmp_path)


OFFENCES = {
    "upward": (layer_violations, {"numeric/core/mesh.py": "from numeric.solutions import law\n",
                                  "numeric/solutions/law.py": "X = 1\n"}),
    "asymptotics imports numeric": (layer_violations, {"asymptotics/first_order.py": "import numeric.core.graded_mesh\n",
                                                       "numeric/core/mesh.py": "X = 1\n"}),
    "baseline imports core": (layer_violations, {"numeric/baseline/scheme.py": "from numeric.core.graded_mesh import X\n",
                                                 "numeric/core/mesh.py": "X = 1\n"}),
    "baseline imports matplotlib": (layer_violations, {"numeric/baseline/scheme.py": "import matplotlib\n"}),
    "sideways": (layer_violations, {"numeric/solutions/law.py": "from numeric.baseline.scheme import X\n",
                                    "numeric/baseline/scheme.py": "X = 1\n"}),
    "outside the folders": (layer_violations, {"numeric/loose.py": "X = 1\n"}),
    "cycle": (cycles, {"numeric/core/a.py": "def f():\n    from numeric.core import b\n",
                       "numeric/core/b.py": "from numeric.core.a import f\n"}),
    "private import": (private_imports, {"numeric/core/a.py": "from numeric.core.b import _helper\n",
                                         "numeric/core/b.py": "def _helper():\n    pass\n"}),
    "private attribute": (private_imports, {"numeric/core/a.py": "from numeric.core import b\nb._helper()\n",
                                            "numeric/core/b.py": "def _helper():\n    pass\n"}),
    "re-export": (reexports, {"numeric/core/__init__.py": "from numeric.core.graded_mesh import X\n",
                              "numeric/core/mesh.py": "X = 1\n"}),
    "shadowed": (shadowed, {"numeric/__init__.py": "from numeric.solutions.law import law\n",
                            "numeric/law.py": "X = 1\n", "numeric/solutions/law.py": "def law():\n    pass\n"}),
}


@pytest.mark.parametrize("offence", sorted(OFFENCES))
def test_each_rule_catches_its_offence(tmp_path, offence):
    check, files = OFFENCES[offence]
    assert check(_tree(tmp_path, files)), offence


def test_the_made_up_tree_is_clean_without_an_offence(tmp_path):
    modules = _tree(tmp_path, {"numeric/core/mesh.py": "import numpy\nfrom asymptotics import first_order\n",
                               "asymptotics/first_order.py": "X = 1\n",
                               "numeric/solutions/law.py": "from numeric.core.graded_mesh import first_order\n"})
    for check in (layer_violations, cycles, private_imports, reexports, shadowed):
        assert check(modules) == [], check.__name__
