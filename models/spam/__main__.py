"""Train and export SPAM, its ablations and the text–motion evaluator (`models/spam/pipeline.py`
lists the stages); or export a run that stopped before its export.

  python -m models.spam --all [--scale 0.5]
  python -m models.spam --resume train.log
"""

from __future__ import annotations

from pathlib import Path


def main(argv: list[str] | None = None) -> None:
    import argparse

    ap = argparse.ArgumentParser(prog="python -m models.spam", description=__doc__.split("\n")[0])
    ap.add_argument("--all", action="store_true", help="train and export everything")
    ap.add_argument("--scale", type=float, default=1.0, help="multiply every time budget")
    ap.add_argument("--resume", metavar="LOG", type=Path,
                    help="export and document a run that trained every stage but stopped "
                         "before its export, from its checkpoints and log (models/spam/resume.py)")
    a = ap.parse_args(argv)
    if a.resume:
        from models.spam.resume import resume
        resume(a.resume)
        return
    if not a.all:
        ap.error("pass --all (train everything) or --resume LOG; stages: models/spam/pipeline.py")
    from models.spam.pipeline import run_all
    run_all(scale=a.scale)


if __name__ == "__main__":
    main()
