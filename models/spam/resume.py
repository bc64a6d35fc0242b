"""Finish a `python -m models.spam --all` run that trained every stage but stopped before
its export (the process was killed during the evaluator stage): export and document the
checkpoints it left in models/cache/<variant>/, with the steps, times and final losses read
back from its log.

  python -m models.spam --resume models/cache/train_all2.log

Only the numbers a log line carries are recovered: a stage's steps and seconds are those of
its last logged step (lines every `log_every` steps), and the "final" training losses average
the last logged lines rather than the last steps. Test reconstruction, code usage and
validation CE/accuracy are measured again from the checkpoints (they are deterministic).
"""

from __future__ import annotations

import re
import time
from pathlib import Path

from interplay.motion.features import Normalizer
from models.common.schedule import History

from . import checkpoint
from .data import CACHE_DIR, TextBank, load_tracks
from .pipeline import WEIGHTS, Budgets, finish, stack_numbers

_STEP = re.compile(r"^\[(?P<name>[\w/]+)\] step (?P<step>\d+) t=(?P<t>[\d.]+)s (?P<terms>.*)$")
VARIANTS = {"spam": ("base", "residual"), "spam_short": (), "spam_nocs": ("base", "residual"),
            "spam_single": ()}


def log_histories(text: str) -> dict[str, History]:
    """Stage name ("spam/vq", "spam/base", …) → History of its logged lines. A stage logged
    twice (an earlier run in the same file) keeps the last run."""
    out: dict[str, History] = {}
    for line in text.splitlines():
        m = _STEP.match(line.strip())
        if not m:
            continue
        step = int(m["step"])
        hist = out.get(m["name"])
        if hist is None or step == 0:
            hist = out[m["name"]] = History()
        row = {"step": step, "t": float(m["t"])}
        row.update({k: float(v) for k, v in (kv.split("=") for kv in m["terms"].split())})
        hist.rows.append(row)
        hist.steps, hist.seconds = step, row["t"]
    return out


def resume(log_path: Path, weights_dir: Path = WEIGHTS, cache_dir: Path = CACHE_DIR,
           budgets: Budgets | None = None, log=print) -> dict:
    budgets = budgets or Budgets()
    histories = log_histories(Path(log_path).read_text())
    missing = [f"{n}/{s}" for n, stages in VARIANTS.items() for s in ("vq", *stages)
               if f"{n}/{s}" not in histories or not (cache_dir / n / f"{s}.pt").is_file()]
    if missing:
        raise SystemExit(f"cannot resume: no log lines or checkpoint for {', '.join(missing)}")
    start = time.perf_counter()
    tracks = load_tracks(cache_dir=cache_dir)
    normalizer = Normalizer.load(cache_dir / "spam" / "normalizer.npz")
    bank = TextBank(tracks, cache_dir)
    times = {name: h.seconds for name, h in histories.items()}
    results = {}
    for name, stages in VARIANTS.items():
        models = {s: (checkpoint.load(cache_dir / name / f"{s}.pt"), histories[f"{name}/{s}"])
                  for s in stages}
        results[name] = stack_numbers(name, checkpoint.load(cache_dir / name / "vq.pt"),
                                      histories[f"{name}/vq"], models, tracks, normalizer, bank,
                                      times, log)
    times["total"] = sum(h.seconds for h in histories.values()) + time.perf_counter() - start
    note = (f"resumed from {Path(log_path).name}: the run trained every stage, then stopped "
            "during the evaluator stage; steps and seconds are those of each stage's last "
            "logged line, the evaluator is the previous run's")
    return finish(results, tracks, normalizer, bank, times, budgets,
                  "not retrained (the run stopped during its training; the committed "
                  "evaluator is the previous run's)", weights_dir, start, note=note)
