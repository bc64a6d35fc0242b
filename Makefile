# The two commands of the README: `make run` (install what is missing, start the app on
# http://127.0.0.1:8000) and `make test` (install what is missing, lint, run every test).
# Installing is idempotent: stamps record what was installed for which inputs.

PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
PY_STAMP := $(VENV)/.installed-$(shell cat pyproject.toml | md5sum | cut -c1-12)
NPM_STAMP := node_modules/.installed-$(shell cat package-lock.json 2>/dev/null | md5sum | cut -c1-12)
FRONT_SRC := $(shell find frontend/src frontend/public frontend/index.html frontend/vite.config.* -type f 2>/dev/null)
HOST ?= 127.0.0.1
PORT ?= 8000

.PHONY: run test install lint test-py test-front test-e2e frontend data train train-deps train-smoke chromium postgres clean

run: install frontend/dist/index.html
	$(BIN)/interplay serve --host $(HOST) --port $(PORT)

test: install train-deps frontend/dist/index.html chromium postgres
	$(MAKE) lint
	$(MAKE) test-py test-front test-e2e

install: $(PY_STAMP) $(NPM_STAMP)

$(PY_STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --disable-pip-version-check -e '.[dev,postgres]'
	rm -f $(VENV)/.installed-* && touch $@

$(NPM_STAMP): package.json package-lock.json frontend/package.json e2e/package.json
	npm ci --no-audit --no-fund --loglevel=error
	rm -f node_modules/.installed-* && touch $@

frontend/dist/index.html: $(NPM_STAMP) $(FRONT_SRC)
	npm run build --workspace frontend

# Debian's Chromium for the end-to-end tests (never a browser download).
chromium:
	@command -v chromium >/dev/null || { apt-get update -qq && apt-get install -y -qq chromium >/dev/null; }

# Debian's PostgreSQL for the store, API and scale-out tests: installed when missing; the
# tests start (and stop) their own throw-away cluster with scripts/postgres.sh.
postgres:
	@sh scripts/postgres.sh install

# Static checks, run first by `make test`: ruff and mypy (configured in pyproject.toml) on the
# Python code, tsc on the front end.
lint: install
	$(BIN)/ruff check .
	$(BIN)/mypy
	npm run typecheck --workspace frontend

# INTERPLAY_REQUIRE_POSTGRES: the PostgreSQL tests fail, not skip, without a cluster.
test-py:
	INTERPLAY_REQUIRE_POSTGRES=1 $(BIN)/python -m pytest -q

test-front:
	npm test --workspace frontend

test-e2e:
	npm test --workspace e2e

# The [train] extra (torch, onnx): the model tests run with it, `make train` needs it.
TRAIN_STAMP := $(VENV)/.train-installed-$(shell cat pyproject.toml | md5sum | cut -c1-12)
train-deps: $(TRAIN_STAMP)

$(TRAIN_STAMP): $(PY_STAMP)
	$(BIN)/pip install --quiet --disable-pip-version-check -e '.[dev,postgres,train]'
	rm -f $(VENV)/.train-installed-* && touch $@

# Retrain every model from models/data, every source (single-person models ≤ 60 min on 2
# cores), export ONNX to models/weights/, write the model cards. EXCLUDE_NONCOMMERCIAL=1
# retrains without the non-commercial source (Bandai Namco, CC BY-NC 4.0); the cards say so.
train: install train-deps
	$(BIN)/python -m models.train_all $(if $(EXCLUDE_NONCOMMERCIAL),--exclude-noncommercial)

# Seconds-long training of tiny configs on a few real clips (also part of `make test`).
train-smoke: install train-deps
	$(BIN)/python -m pytest -q tests/models/test_spam_smoke.py tests/models/common/test_sources.py

# Rebuild the processed data set from ../shared/data (not needed to run or test the app).
data: install
	$(BIN)/interplay data build

clean:
	rm -rf $(VENV) node_modules frontend/dist
