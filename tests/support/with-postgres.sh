#!/usr/bin/env bash
# Runs a test program (its arguments follow) beside a throwaway PostgreSQL cluster, one per
# program: initdb into a new folder of /tmp, as an unprivileged user when run as root (the server
# refuses root: `nobody` through setpriv), listening on a Unix socket in that folder only (no
# TCP), trust authentication on it, fsync off (a test's data need not survive a power cut;
# NEEDLE_PG_FSYNC=on for a benchmark that compares durable commits). The
# program finds it through NEEDLE_TEST_PG_DIR (the socket's folder; user `needle`, superuser)
# and stops and starts the server with $NEEDLE_TEST_PG_DIR/ctl stop|start. The cluster and its
# folder are removed when the program ends, also when it fails, crashes or is interrupted.
set -euo pipefail
bin=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n 1)
[ -x "$bin/initdb" ] || { echo "with-postgres: no PostgreSQL server (tools/setup.sh installs postgresql)" >&2; exit 1; }
dir=$(mktemp -d /tmp/needle-pg.XXXXXX)
run_as=()
if [ "$(id -u)" -eq 0 ]; then
  chown nobody:nogroup "$dir"
  run_as=(setpriv --reuid=nobody --regid=nogroup --clear-groups env HOME="$dir")
fi
chmod 700 "$dir"
cat >"$dir/ctl" <<CTL
#!/bin/sh
# start | stop (immediate: as a server that dies) the test cluster
case "\$1" in
  start) exec ${run_as[*]} "$bin/pg_ctl" -D "$dir/data" -l "$dir/log" -w -t 60 start -o "-c listen_addresses='' -c unix_socket_directories='$dir' -c fsync=${NEEDLE_PG_FSYNC:-off} -c max_connections=120" >/dev/null ;;
  stop) exec ${run_as[*]} "$bin/pg_ctl" -D "$dir/data" -w -m immediate stop >/dev/null ;;
esac
CTL
chmod 755 "$dir/ctl"
cleanup() {
  "$dir/ctl" stop 2>/dev/null || true
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
"${run_as[@]}" "$bin/initdb" -D "$dir/data" -U needle --auth=trust -E UTF8 --no-sync >"$dir/initdb.log" 2>&1 ||
  { cat "$dir/initdb.log" >&2; exit 1; }
"$dir/ctl" start || { cat "$dir/log" >&2; exit 1; }
NEEDLE_TEST_PG_DIR="$dir" "$@"
