#!/usr/bin/env bash
# A throw-away PostgreSQL cluster for the dnc tests: a real server from
# Debian's postgresql package on 127.0.0.1, never a mock.
#   pg_cluster.sh start DIR   initdb (from a cached template) + pg_ctl start in
#                             DIR; prints postgresql://usina@127.0.0.1:PORT/postgres
#   pg_cluster.sh start-shared DIR   the same, the URL also written to DIR/url
#                             (the ctest fixture; exits 0 even without
#                             PostgreSQL: the tests then say why they skip)
#   pg_cluster.sh stop DIR    stops it (immediate) and removes DIR
# Exit 77 (with the reason on stderr) when PostgreSQL is not installed.
# As root the server runs as the `postgres` user (initdb refuses root).
set -euo pipefail
cmd=${1:?start or stop}
dir=${2:?a folder}

find_bin() {
  local d
  for d in $(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V -r); do
    [ -x "$d/initdb" ] && [ -x "$d/pg_ctl" ] && { echo "$d"; return 0; }
  done
  command -v initdb >/dev/null 2>&1 && command -v pg_ctl >/dev/null 2>&1 &&
    { dirname "$(command -v initdb)"; return 0; }
  return 1
}

if [ "$cmd" = start-shared ]; then
  bash "$0" stop "$dir"
  url=$(bash "$0" start "$dir") || { echo "no shared cluster; each test starts its own or skips" >&2; exit 0; }
  echo "$url" >"$dir/url.tmp" && mv "$dir/url.tmp" "$dir/url"
  echo "$url"
  exit 0
fi

if ! bin=$(find_bin); then
  echo "PostgreSQL's initdb and pg_ctl were not found: install Debian's postgresql package (scripts/setup.sh)" >&2
  exit 77
fi
owner=$(id -un)
if [ "$(id -u)" -eq 0 ]; then
  if ! id postgres >/dev/null 2>&1; then
    echo "running as root and there is no postgres user to run the server as" >&2
    exit 77
  fi
  owner=postgres
fi
as_owner() { if [ "$owner" = "$(id -un)" ]; then "$@"; else runuser -u "$owner" -- "$@"; fi; }

if [ "$cmd" = stop ]; then
  [ -d "$dir/data" ] && as_owner "$bin/pg_ctl" -D "$dir/data" -m immediate -w stop >/dev/null 2>&1 || true
  rm -rf "$dir"
  exit 0
fi

# One initdb per machine and version, copied for each cluster (initdb takes
# seconds, a copy a fraction of one).
version=$(basename "$(dirname "$bin")")
template="${TMPDIR:-/tmp}/usina-pg-template-$owner-$version"
(
  flock 9
  if [ ! -f "$template/PG_VERSION" ]; then
    rm -rf "$template.tmp" && mkdir -p "$template.tmp" && chown "$owner" "$template.tmp"
    as_owner "$bin/initdb" -D "$template.tmp" -A trust -U usina -E UTF8 --locale=C --no-sync \
      >/dev/null
    rm -rf "$template" && mv "$template.tmp" "$template"
  fi
) 9>"${TMPDIR:-/tmp}/usina-pg-template-$owner-$version.lock"

mkdir -p "$dir"
chown "$owner" "$dir"
cp -a "$template" "$dir/data"
for try in 1 2 3 4 5 6 7 8; do
  port=$((20000 + RANDOM % 40000))
  if as_owner "$bin/pg_ctl" -D "$dir/data" -l "$dir/log" -w -t 30 start \
      -o "-p $port -k $dir -c listen_addresses=127.0.0.1 -c fsync=off -c max_connections=50" \
      >/dev/null 2>&1; then
    echo "postgresql://usina@127.0.0.1:$port/postgres"
    exit 0
  fi
done
echo "the PostgreSQL server did not start; its log:" >&2
cat "$dir/log" >&2 || true
exit 1
