"""Imports run one way: motion → text → planner/trajectory/generators/reaction/review →
pipeline → {api, cli, eval, bench}; no stage imports the web layer, the CLI or the
measurements; retrieval never imports SPAM or CODA; models/ may import interplay, never the
reverse; nothing in interplay reads tests/; and there are no import cycles at all. Each rule
is shown to fail on a planted violation in a temporary tree."""

from __future__ import annotations

from pathlib import Path

from tests.helpers.imports import cycles, import_graph, module_names, reads_tests, violations

ROOT = Path(__file__).resolve().parents[1]
TREES = {"interplay": ROOT / "backend" / "interplay", "models": ROOT / "models"}
MAX_MODULES = 15


def test_the_product_follows_the_layers():
    assert violations(import_graph(TREES)) == []


def test_there_are_no_import_cycles():
    graph = import_graph(TREES)
    assert len(graph) > 150      # the trees were read
    assert cycles(graph) == []


def test_nothing_in_interplay_reads_tests():
    assert [p for p in module_names({"interplay": TREES["interplay"]}).values() if reads_tests(p)] == []


def test_no_flat_package_holds_more_than_15_modules():
    big = {}
    for tree in TREES.values():
        for folder in [tree, *[p for p in tree.rglob("*") if p.is_dir()]]:
            n = len([p for p in folder.glob("*.py") if p.name != "__init__.py"])
            if n > MAX_MODULES:
                big[str(folder.relative_to(ROOT))] = n
    assert big == {}


def _tree(tmp_path: Path, files: dict[str, str]) -> dict[str, Path]:
    for rel, text in files.items():
        path = tmp_path / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return {"interplay": tmp_path / "interplay", "models": tmp_path / "models"}


CLEAN = {
    "interplay/__init__.py": "",
    "interplay/motion/__init__.py": "",
    "interplay/motion/skeleton.py": "FPS = 20\n",
    "interplay/generators/__init__.py": "",
    "interplay/generators/retrieval/__init__.py": "",
    "interplay/generators/retrieval/index.py": "from interplay.motion.skeleton import FPS\n",
    "interplay/generators/spam/__init__.py": "",
    "interplay/generators/spam/runtime.py": "from ..retrieval import index\n",
    "interplay/api/__init__.py": "",
    "interplay/api/app.py": "from interplay.generators.spam import runtime\n",
    "models/__init__.py": "",
    "models/spam.py": "import interplay.motion.skeleton\n",
}


def test_a_clean_tree_passes(tmp_path):
    graph = import_graph(_tree(tmp_path, CLEAN))
    assert graph["interplay.generators.spam.runtime"] == {"interplay.generators.retrieval",
                                                          "interplay.generators.retrieval.index"}
    assert violations(graph) == [] and cycles(graph) == []


def test_a_stage_importing_the_web_layer_inside_a_function_fails(tmp_path):
    files = {**CLEAN, "interplay/motion/skeleton.py":
             "def f():\n    from interplay.api.app import x\n    return x\n"}
    bad = violations(import_graph(_tree(tmp_path, files)))
    assert bad and "interplay.motion.skeleton imports interplay.api.app" in bad[0]


def test_retrieval_importing_spam_fails(tmp_path):
    files = {**CLEAN, "interplay/generators/retrieval/index.py":
             "from interplay.generators.spam.runtime import y\n"}
    graph = import_graph(_tree(tmp_path, files))
    assert any("never imports" in v for v in violations(graph))
    assert cycles(graph) == [["interplay.generators.retrieval.index",
                              "interplay.generators.spam.runtime"]]


def test_interplay_importing_models_fails(tmp_path):
    files = {**CLEAN, "interplay/motion/skeleton.py": "import models.spam\n"}
    assert any("never imports models" in v for v in violations(import_graph(_tree(tmp_path, files))))


def test_reading_tests_is_found(tmp_path):
    path = tmp_path / "m.py"
    path.write_text("from pathlib import Path\nDATA = Path(__file__).parents[2] / 'tests' / 'x.json'\n")
    assert reads_tests(path)
    path.write_text("NAME = 'tests pass'\n")
    assert not reads_tests(path)


def test_test_modules_have_unique_names():
    # pytest's default import mode keys test modules by basename: two test_travel.py in
    # different folders stop collection for the whole suite.
    seen: dict[str, list[str]] = {}
    for p in (ROOT / "tests").rglob("test_*.py"):
        seen.setdefault(p.name, []).append(str(p.relative_to(ROOT)))
    assert {name: paths for name, paths in seen.items() if len(paths) > 1} == {}
