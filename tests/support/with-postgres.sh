#!/usr/bin/env bash
# Runs a test program (its arguments follow) beside a throwaway PostgreSQL cluster, one per
# program: initdb into a new folder of /tmp, as an unprivileged user when run as root (the server
# refuses root: `nobody` through setpriv), listening on a Unix socket in that folder, trust
# authentication on it but for the role `needle_password` (scram-sha-256: a test gives it a
# password and connects with PGPASSFILE), fsync off (a test's data need not survive a power cut;
# NEEDLE_PG_FSYNC=on for a benchmark that compares durable commits). With NEEDLE_PG_TLS=on it also
# listens on 127.0.0.1, TLS only (hostssl, scram-sha-256, a self-signed certificate made by openssl
# in the folder, $NEEDLE_TEST_PG_DIR/tls/server.crt, valid for 127.0.0.1), on a free port.
# The program finds it through NEEDLE_TEST_PG_DIR (the socket's folder; user `needle`, superuser)
# and NEEDLE_TEST_PG_PORT (the port of the socket and of TCP), and stops and starts the server with
# $NEEDLE_TEST_PG_DIR/ctl stop|start. The cluster and its folder are removed when the program
# ends, also when it fails, crashes or is interrupted.
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
cleanup() {
  [ -x "$dir/ctl" ] && "$dir/ctl" stop 2>/dev/null || true
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
"${run_as[@]}" "$bin/initdb" -D "$dir/data" -U needle --auth=trust -E UTF8 --no-sync >"$dir/initdb.log" 2>&1 ||
  { cat "$dir/initdb.log" >&2; exit 1; }
port=5432  # the socket's name only, in a folder of its own
options="-c unix_socket_directories='$dir' -c fsync=${NEEDLE_PG_FSYNC:-off} -c max_connections=120"
{
  echo "local all needle_password scram-sha-256"
  echo "local all all trust"
} >"$dir/data/pg_hba.conf"
if [ "${NEEDLE_PG_TLS:-off}" = on ]; then
  command -v openssl >/dev/null || { echo "with-postgres: NEEDLE_PG_TLS=on needs openssl" >&2; exit 1; }
  mkdir "$dir/tls"
  openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 2 -subj /CN=127.0.0.1 \
    -addext subjectAltName=IP:127.0.0.1 -keyout "$dir/tls/server.key" -out "$dir/tls/server.crt" 2>"$dir/tls/openssl.log" ||
    { cat "$dir/tls/openssl.log" >&2; exit 1; }
  chmod 600 "$dir/tls/server.key"
  [ "$(id -u)" -eq 0 ] && chown -R nobody:nogroup "$dir/tls"
  for _ in 1 2 3 4 5 6 7 8; do  # a port nothing listens on
    port=$((20000 + RANDOM % 40000))
    [ -z "$(ss -Htln "sport = :$port")" ] && break
  done
  options="$options -c listen_addresses='127.0.0.1' -c port=$port -c ssl=on -c ssl_cert_file='$dir/tls/server.crt' -c ssl_key_file='$dir/tls/server.key'"
  echo "hostssl all all 127.0.0.1/32 scram-sha-256" >>"$dir/data/pg_hba.conf"
else
  options="$options -c listen_addresses=''"
fi
cat >"$dir/ctl" <<CTL
#!/bin/sh
# start | stop (immediate: as a server that dies) the test cluster
case "\$1" in
  start) exec ${run_as[*]} "$bin/pg_ctl" -D "$dir/data" -l "$dir/log" -w -t 60 start -o "$options" >/dev/null ;;
  stop) exec ${run_as[*]} "$bin/pg_ctl" -D "$dir/data" -w -m immediate stop >/dev/null ;;
esac
CTL
chmod 755 "$dir/ctl"
"$dir/ctl" start || { cat "$dir/log" >&2; exit 1; }
NEEDLE_TEST_PG_DIR="$dir" NEEDLE_TEST_PG_PORT="$port" "$@"
