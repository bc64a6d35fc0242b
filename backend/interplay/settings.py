"""Runtime settings, read once from the environment (prefix INTERPLAY_; DATABASE_URL as is).

    INTERPLAY_VAR_DIR        where the database and other run-time files live (default <repo>/var)
    DATABASE_URL             SQLAlchemy URL; PostgreSQL when it says so (install the [postgres] extra),
                             default sqlite:///<var>/interplay.db
    INTERPLAY_HOST / _PORT   where `interplay serve` listens (127.0.0.1:8000)
    INTERPLAY_FRONTEND_DIST  the built front end served at / (default <repo>/frontend/dist)
    INTERPLAY_JOB_WORKERS    generation threads (CPU bound: 1 on a small machine)
    INTERPLAY_DATA_DIR       processed motion data the generator loads (default <repo>/models/data)
    INTERPLAY_SPAM_DIR       SPAM's ONNX weights (default <repo>/models/weights/spam); retrieval
                             serves when they are missing or do not load
    INTERPLAY_CODA_DIR       CODA's ONNX weights for two people (default models/weights/coda);
                             retrieval serves two people when they are missing or untrained
    INTERPLAY_LLM_BASE_URL   optional OpenAI-compatible endpoint for the planner (e.g.
                             http://localhost:11434/v1); with INTERPLAY_LLM_MODEL set the planner
                             asks it and falls back to the embedded planner on any failure
    INTERPLAY_LLM_MODEL / _API_KEY / _TIMEOUT_S   its model name, bearer key, timeout (20 s)
    INTERPLAY_JOB_QUEUE      auto (default) | embedded | procrastinate: who runs jobs
    INTERPLAY_DRAIN_S        on SIGTERM, seconds running jobs may finish before they fail (5)
    INTERPLAY_JOB_STALE_S    a job whose worker is silent this long is failed (30)
    INTERPLAY_GENERATOR_FACTORY  "module:callable" building the generator (tests; default: models)
    INTERPLAY_RETENTION_MAX_MOTIONS / _MAX_AGE_S  retention, off by default
    INTERPLAY_MAX_BODY_BYTES  larger request bodies are answered 413 (262144 = 256 KiB)
    INTERPLAY_RETRY_AFTER_S   the Retry-After header of every 429 (5)
    INTERPLAY_ALLOWED_ORIGINS extra origins a WebSocket may come from, comma-separated
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Literal

from pydantic import AliasChoices, Field, SecretStr
from pydantic_settings import BaseSettings, SettingsConfigDict

REPO_ROOT = Path(__file__).resolve().parents[2]


class Settings(BaseSettings):
    model_config = SettingsConfigDict(env_prefix="INTERPLAY_", extra="ignore")

    var_dir: Path = REPO_ROOT / "var"
    database_url: str | None = Field(
        default=None, validation_alias=AliasChoices("DATABASE_URL", "INTERPLAY_DATABASE_URL"))
    host: str = "127.0.0.1"
    port: int = Field(default=8000, ge=0, le=65535)
    frontend_dist: Path = REPO_ROOT / "frontend" / "dist"
    data_dir: Path | None = None                      # None: the generator's default
    spam_dir: Path | None = None                      # None: models/weights/spam
    coda_dir: Path | None = None                      # None: models/weights/coda
    job_workers: int = Field(default=1, ge=1, le=16)
    max_pending_jobs: int = Field(default=16, ge=1)   # beyond this POST /api/jobs answers 429
    job_retention_s: float = 900.0                    # finished jobs stay streamable this long
    # Durable jobs (docs/api.md "Jobs"): which queue runs them (auto: procrastinate when
    # DATABASE_URL is PostgreSQL, else worker threads in the API process), how long SIGTERM
    # lets running jobs finish, when a silent worker's job counts as orphaned, and an optional
    # "module:callable" that builds the generator instead of loading the models (tests).
    job_queue: Literal["auto", "embedded", "procrastinate"] = "auto"
    drain_s: float = Field(default=5.0, ge=0, le=600)
    job_stale_s: float = Field(default=30.0, gt=0)
    job_max_attempts: int = Field(default=3, ge=1, le=20)  # a job whose process died runs again
    generator_factory: str | None = None
    # Retention (off by default): keep at most this many motions / motions this young.
    retention_max_motions: int | None = Field(default=None, ge=1)
    retention_max_age_s: float | None = Field(default=None, gt=0)
    llm_base_url: str | None = None                   # planner LLM (OpenAI-compatible), optional
    llm_model: str | None = None
    llm_api_key: SecretStr | None = None
    llm_timeout_s: float = Field(default=20.0, gt=0, le=600)
    # HTTP hardening (api/security.py): request bodies above this are 413, the Retry-After of
    # every 429, extra origins a WebSocket may come from (comma-separated) besides the host's.
    max_body_bytes: int = Field(default=256 * 1024, ge=1024)
    retry_after_s: int = Field(default=5, ge=1, le=3600)
    allowed_origins: str = ""

    @property
    def queue(self) -> str:
        """The job queue in use: "procrastinate" or "embedded"."""
        if self.job_queue != "auto":
            return self.job_queue
        return "procrastinate" if self.db_url.startswith("postgresql") else "embedded"

    @property
    def db_url(self) -> str:
        """The SQLAlchemy URL to connect to: DATABASE_URL, normalised for psycopg 3, or the
        SQLite file in the var dir."""
        url = self.database_url
        if not url:
            return f"sqlite:///{self.var_dir / 'interplay.db'}"
        # Heroku-style URLs say postgres://; SQLAlchemy wants a dialect (psycopg 3 driver).
        for prefix in ("postgres://", "postgresql://"):
            if url.startswith(prefix):
                return "postgresql+psycopg://" + url[len(prefix):]
        return url


@lru_cache(maxsize=1)
def get_settings() -> Settings:
    return Settings()
