"""What a process builds from the settings: the retention policy, the generator, the libpq URL."""

from __future__ import annotations

import importlib

from sqlalchemy.engine import make_url

from interplay.settings import Settings
from interplay.store.retention import Retention


def retention_of(settings: Settings) -> Retention:
    return Retention(settings.retention_max_motions, settings.retention_max_age_s)


def build_generator(settings: Settings):
    """`INTERPLAY_GENERATOR_FACTORY` ("module:callable", called with no arguments) when set,
    else the models (`generators.router.load_generator`)."""
    if settings.generator_factory:
        module, _, name = settings.generator_factory.partition(":")
        if not module or not name:
            raise ValueError(f"INTERPLAY_GENERATOR_FACTORY must be 'module:callable', got "
                             f"{settings.generator_factory!r}")
        return getattr(importlib.import_module(module), name)()
    from interplay.generators.router import load_generator
    return load_generator(settings)


def conninfo(db_url: str) -> str:
    """A libpq URL (what psycopg and procrastinate take) from the SQLAlchemy one."""
    return make_url(db_url).set(drivername="postgresql").render_as_string(hide_password=False)
