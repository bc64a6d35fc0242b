#!/bin/sh
# A throw-away PostgreSQL cluster for the tests (Debian's `postgresql`, never a mock):
#
#   scripts/postgres.sh install       install Debian's postgresql when initdb is missing (root)
#   scripts/postgres.sh start [DIR]   initdb + start on a free 127.0.0.1 port in DIR (default: a
#                                     new temp dir); prints "URL DIR" on its last line
#   scripts/postgres.sh stop DIR      stop that cluster and delete DIR
#
# As root (CI) the cluster runs as the unprivileged `postgres` user the package creates (or
# `nobody`); otherwise as the calling user. No durability (fsync off): it lives for one test run.
# Idempotent: `install` does nothing when PostgreSQL is there, `stop` of a stopped or missing
# cluster succeeds.
set -eu

pg_bin() {
    ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n 1
}

install_pg() {
    if [ -n "$(pg_bin)" ] && [ -x "$(pg_bin)/initdb" ]; then
        return 0
    fi
    if [ "$(id -u)" -ne 0 ]; then
        echo "postgres.sh: PostgreSQL is not installed and this is not root: apt-get install postgresql" >&2
        exit 3
    fi
    echo "postgres.sh: installing Debian's postgresql" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq >&2
    apt-get install -y -qq postgresql >/dev/null
    # The package may start (and enable) its own cluster; the tests do not use it.
    if command -v pg_ctlcluster >/dev/null 2>&1; then
        for c in /etc/postgresql/*/main; do
            [ -d "$c" ] || continue
            v=$(basename "$(dirname "$c")")
            pg_ctlcluster "$v" main stop >/dev/null 2>&1 || true
        done
    fi
}

# Run a command as the cluster's user (root cannot run postgres).
as_owner() {
    if [ "$(id -u)" -eq 0 ]; then
        runuser -u "$OWNER" -- "$@"
    else
        "$@"
    fi
}

owner() {
    if [ "$(id -u)" -ne 0 ]; then
        id -un
    elif id postgres >/dev/null 2>&1; then
        echo postgres
    else
        echo nobody
    fi
}

free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

start() {
    install_pg
    BIN=$(pg_bin)
    OWNER=$(owner)
    DIR=${1:-$(mktemp -d "${TMPDIR:-/tmp}/interplay-pg.XXXXXX")}
    mkdir -p "$DIR"
    chmod 700 "$DIR"
    if [ "$(id -u)" -eq 0 ]; then
        chown "$OWNER" "$DIR"
    fi
    if [ ! -f "$DIR/data/PG_VERSION" ]; then
        as_owner "$BIN/initdb" -D "$DIR/data" -U interplay --auth=trust -E UTF8 --no-sync \
            --locale=C >"$DIR/initdb.log" 2>&1 || { cat "$DIR/initdb.log" >&2; exit 1; }
    fi
    # A port that was free a moment ago can be taken before the server binds it: try a few.
    for _ in 1 2 3 4 5; do
        PORT=$(free_port)
        if as_owner "$BIN/pg_ctl" -D "$DIR/data" -l "$DIR/server.log" -w -t 60 start -o \
            "-c listen_addresses=127.0.0.1 -p $PORT -k $DIR -c fsync=off -c synchronous_commit=off -c full_page_writes=off -c max_connections=200" \
            >/dev/null 2>&1; then
            echo "$PORT" >"$DIR/port"
            as_owner "$BIN/createdb" -h 127.0.0.1 -p "$PORT" -U interplay interplay
            echo "postgresql://interplay@127.0.0.1:$PORT/interplay $DIR"
            return 0
        fi
    done
    cat "$DIR/server.log" >&2 || true
    echo "postgres.sh: the server did not start" >&2
    exit 1
}

stop() {
    DIR=${1:?usage: postgres.sh stop DIR}
    OWNER=$(owner)
    BIN=$(pg_bin)
    if [ -f "$DIR/data/postmaster.pid" ] && [ -n "$BIN" ]; then
        as_owner "$BIN/pg_ctl" -D "$DIR/data" -m immediate -w stop >/dev/null 2>&1 || true
    fi
    case "$DIR" in
        */interplay-pg.*) rm -rf "$DIR" ;;
    esac
}

cmd=${1:-}
[ $# -gt 0 ] && shift
case "$cmd" in
    install) install_pg ;;
    start) start "$@" ;;
    stop) stop "$@" ;;
    *) echo "usage: $0 install | start [DIR] | stop DIR" >&2; exit 2 ;;
esac
