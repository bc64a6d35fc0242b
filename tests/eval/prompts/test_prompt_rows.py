"""`eval-prompts` rows: which prompts each serves, and rows whose weights are missing skipped
with the router's reason."""

from __future__ import annotations

import pytest

from interplay.eval.prompts.rows import load_rows
from interplay.settings import Settings


def test_rows_without_weights_are_skipped_with_the_reason(tmp_path):
    settings = Settings(spam_dir=tmp_path / "no_spam", coda_dir=tmp_path / "no_coda")
    rows, skipped = load_rows(("retrieval", "spam", "coda", "default"), settings)
    assert [r.name for r in rows] == ["retrieval", "default"]
    assert set(skipped) == {"spam", "coda"} and all(skipped.values())
    served = {r.name: r.persons for r in rows}
    assert served == {"retrieval": (1, 2), "default": (1, 2)}
    assert "retrieve_edit" in next(r for r in rows if r.name == "default").about


def test_unknown_rows_are_refused():
    with pytest.raises(ValueError):
        load_rows(("nope",))
