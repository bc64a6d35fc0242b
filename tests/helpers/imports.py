"""The import graph of Python package trees, read with `ast` (module-level imports and those
inside functions alike), and the layering rules the product's packages follow.

    graph = import_graph({"interplay": Path("backend/interplay"), "models": Path("models")})
    violations(graph)        # ["interplay.review.x imports interplay.eval.y (review may not …)", …]
    cycles(graph)            # [["a.b", "a.c"], …]: strongly connected groups of modules
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

# What each top-level package of `interplay` may import (besides itself). Data flows
# motion → text → catalogue → planner/trajectory/generators/reaction/review → pipeline → {api, cli, eval, bench}.
BASE = {"settings"}
STAGES = {"planner", "trajectory", "generators", "reaction", "review"}
ALLOWED: dict[str, set[str]] = {
    "interplay": set(),
    "settings": set(),
    "motion": BASE,
    "text": BASE,
    "catalogue": BASE | {"motion", "text"},
    "store": BASE | {"motion"},
    "data": BASE | {"motion"},
    "planner": BASE | {"motion", "text", "catalogue"},
    "trajectory": BASE | {"motion", "planner", "catalogue"},
    "reaction": BASE | {"motion", "text"},
    "review": BASE | {"motion", "text", "planner", "catalogue"},
    "generators": BASE | {"motion", "text", "planner", "catalogue"},
    "pipeline": BASE | {"motion", "text", "store", "catalogue"} | STAGES,
    "api": BASE | {"interplay", "motion", "text", "store", "pipeline", "catalogue"} | STAGES,
    "eval": BASE | {"motion", "text", "pipeline", "data", "catalogue"} | STAGES,
    "bench": BASE | {"motion", "text", "pipeline", "api"} | STAGES,
    "cli": BASE | {"motion", "text", "store", "pipeline", "data", "eval", "bench", "catalogue"} | STAGES,
}
# The doors from the CLI into the web layer: `interplay serve` builds the app, `interplay
# worker` runs the app's job runners from the PostgreSQL queue.
EXCEPTIONS = {("interplay.cli.serve", "api"), ("interplay.cli.worker", "api")}
# Within generators: retrieval stands alone (SPAM and CODA may build on it, never the reverse).
FORBIDDEN_WITHIN = [("interplay.generators.retrieval", ("interplay.generators.spam",
                                                        "interplay.generators.coda"))]


def module_names(roots: dict[str, Path]) -> dict[str, Path]:
    """{dotted module name: file} for every .py under each root (root name = package name)."""
    out = {}
    for name, root in roots.items():
        for path in sorted(root.rglob("*.py")):
            parts = [name, *path.relative_to(root).with_suffix("").parts]
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = path
    return out


def _imported(module: str, path: Path, tree: ast.AST) -> set[str]:
    """Dotted names `module` imports, absolute, relative ones resolved, `from a import b` as
    both `a` and `a.b`."""
    names = set()
    package = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - (node.level - 1)]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            names.add(mod)
            names.update(f"{mod}.{a.name}" for a in node.names)
    return names


def import_graph(roots: dict[str, Path]) -> dict[str, set[str]]:
    """{module: modules of the same trees it imports}."""
    mods = module_names(roots)

    def resolve(name: str) -> str | None:
        while name and name not in mods:
            name = name.rpartition(".")[0]
        return name or None

    graph = {}
    for module, path in mods.items():
        tree = ast.parse(path.read_text(), filename=str(path))
        targets = {resolve(n) for n in _imported(module, path, tree)}
        graph[module] = {t for t in targets if t and t != module}
    return graph


def _top(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else parts[0]


def violations(graph: dict[str, set[str]]) -> list[str]:
    out = []
    for module, targets in sorted(graph.items()):
        for target in sorted(targets):
            if module.startswith("interplay") and target.startswith("models"):
                out.append(f"{module} imports {target} (interplay never imports models/)")
                continue
            if not (module.startswith("interplay") and target.startswith("interplay")):
                continue
            src, dst = _top(module), _top(target)
            if src != dst and dst not in ALLOWED.get(src, set()) \
                    and (module, dst) not in EXCEPTIONS:
                out.append(f"{module} imports {target} ({src} may import only "
                           f"{sorted(ALLOWED.get(src, set()))})")
            for pkg, banned in FORBIDDEN_WITHIN:
                if (module == pkg or module.startswith(pkg + ".")) \
                        and target.startswith(banned):
                    out.append(f"{module} imports {target} ({pkg} never imports {banned})")
    return out


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected groups of more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    found: list[list[str]] = []
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 10 * len(graph) + 100))

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                found.append(sorted(group))

    try:
        for v in sorted(graph):
            if v not in index:
                visit(v)
    finally:
        sys.setrecursionlimit(limit)
    return found


def reads_tests(path: Path) -> bool:
    """Whether a module builds a path into the tests/ folder (a string constant "tests" used
    as a path part)."""
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Div):
            for side in (node.left, node.right):
                if isinstance(side, ast.Constant) and side.value == "tests":
                    return True
        if isinstance(node, ast.Constant) and isinstance(node.value, str) \
                and ("tests/" in node.value and node.value.strip().startswith("tests/")):
            return True
    return False
