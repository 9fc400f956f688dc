"""The import graph of tampcli (read with ast, imports inside functions included)
keeps the layering of docs/ARCHITECTURE.md: no cycles, no import from a higher
layer, PyBullet only inside geometry/world/."""

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "tampcli"

# Lowest first: a module imports only from its own layer or lower ones.
LAYERS = (
    ("tampcli", "errors"),
    ("pddl",),
    ("task",),
    ("search",),
    ("geometry",),
    ("solution_kkt", "solution", "solution_read", "solution_fit"),
    ("optimize",),
    ("bnb",),
    ("minlp",),
    ("render",),
    ("pipeline", "stage_evaluator", "skeleton_pool"),
    ("batch",),
    ("cli", "__main__"),
)

WORLD = "tampcli.geometry.world"
WORLD_PRIVATE = ("_pb", "_client", "_robot", "_bodies", "_fingers")

def _modules() -> dict[str, Path]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = path
    return out


MODULES = _modules()
TREES = {name: ast.parse(path.read_text(), str(path)) for name, path in MODULES.items()}


def _resolve(name: str) -> str | None:
    """The tampcli module an imported name lives in (a submodule, else its package)."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


def _imported(tree: ast.AST) -> set[str]:
    """Every dotted name the module imports, `from a import b` as both a.b and a."""
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.update(f"{node.module}.{alias.name}" for alias in node.names)
    return names


def _graph() -> dict[str, set[str]]:
    graph = {}
    for name, tree in TREES.items():
        targets = {_resolve(n) for n in _imported(tree)} - {None, name}
        graph[name] = targets
    return graph


GRAPH = _graph()


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
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
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def _layer(module: str) -> int:
    top = module.split(".")[1] if "." in module else module
    for rank, names in enumerate(LAYERS):
        if top in names:
            return rank
    raise AssertionError(f"{module}: in no layer of LAYERS")


def test_the_graph_is_read():
    assert "tampcli.geometry.world.World" not in GRAPH
    assert WORLD in GRAPH["tampcli.render.physics"]
    assert "tampcli.geometry.transforms" in GRAPH["tampcli.geometry.chain"]
    # An import inside a function counts.
    assert "tampcli.render.video" in GRAPH["tampcli.cli.render"]


def test_no_import_cycle():
    assert _cycles(GRAPH) == []


def test_the_cycle_finder_finds_one():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


def test_no_import_from_a_higher_layer():
    upward = [f"{a} -> {b}" for a, targets in GRAPH.items() for b in targets
              if _layer(b) > _layer(a)]
    assert upward == []


def test_batch_and_geometry_never_import_cli():
    bad = [f"{a} -> {b}" for a, targets in GRAPH.items() for b in targets
           if a.startswith(("tampcli.batch", "tampcli.geometry")) and b.startswith("tampcli.cli")]
    assert bad == []


def test_pybullet_only_inside_the_world_package():
    users = sorted(name for name, tree in TREES.items()
                   if any(n.split(".")[0] in ("pybullet", "pybullet_data")
                          for n in _imported(tree)))
    assert users and all(name.startswith(WORLD + ".") for name in users), users


def test_world_private_parts_stay_inside_it():
    outside = [name for name in GRAPH if not name.startswith(WORLD)]
    private_imports = [f"{a} -> {b}" for a in outside for b in GRAPH[a]
                       if b.startswith(WORLD + "._")]
    assert private_imports == []
    reached = sorted({f"{name}: .{node.attr}" for name in outside
                      for node in ast.walk(TREES[name])
                      if isinstance(node, ast.Attribute) and node.attr in WORLD_PRIVATE})
    assert reached == []
