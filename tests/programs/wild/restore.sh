#!/usr/bin/env bash
# Re-create usina's wild corpus (tests/programs/wild/corpus/) from the
# manifest, reading every file out of the fetched mirror git directories.
#
# Usage:  tests/programs/wild/restore.sh [MIRROR_DIR] [WILD_DIR]
#   MIRROR_DIR  where `fetch github:owner/name` puts snapshots; each repo is
#               MIRROR_DIR/owner+name/repo (a bare git dir). Default /work/.mirror
#   WILD_DIR    the folder holding manifest.tsv. Default: this script's folder
#
# First get a git snapshot of each repository of the manifest's `repo` column
# (MIRROR_DIR/owner+name/repo), then run this once. For each row it writes
# WILD_DIR/corpus/<file> from `git cat-file blob COMMIT:PATH` (raw bytes, no
# text conversion), falling back to HEAD:PATH when the pinned commit is not in
# the snapshot, and checks the SHA-256 against the manifest. A file whose hash
# differs is removed again, so that the test skips nothing silently.
# Exit status: 0 when every row was restored with a matching hash, 1 otherwise;
# the rows that failed are listed with the reason (no mirror / no such path /
# hash mismatch): get those from the repository at the commit by other means.
#
# Restore of 2026-12-02: all 15 repositories came with fetch and held the
# pinned commits.
set -u -o pipefail

mirror=${1:-/work/.mirror}
wild=${2:-$(cd "$(dirname "$0")" && pwd)}
manifest=$wild/manifest.tsv
corpus=$wild/corpus

[[ -r $manifest ]] || { echo "no manifest at $manifest" >&2; exit 2; }

ok=0 head=0 bad=0
failures=()
while IFS=$'\t' read -r file _dialect _options _expect _xfail _today _ax _at \
    repo path commit _licence sha _note; do
    [[ -z $file || $file == \#* || $file == file ]] && continue
    gitdir=$mirror/${repo/\//+}/repo
    if [[ ! -d $gitdir ]]; then
        failures+=("$file	no mirror of $repo")
        bad=$((bad + 1))
        continue
    fi
    rev=$commit
    if ! git --git-dir="$gitdir" cat-file -e "$commit:$path" 2>/dev/null; then
        rev=HEAD
        if ! git --git-dir="$gitdir" cat-file -e "HEAD:$path" 2>/dev/null; then
            failures+=("$file	$repo: $path not at $commit nor at HEAD")
            bad=$((bad + 1))
            continue
        fi
    fi
    out=$corpus/$file
    mkdir -p "$(dirname "$out")"
    git --git-dir="$gitdir" cat-file blob "$rev:$path" >"$out.tmp" &&
        mv "$out.tmp" "$out"
    got=$(sha256sum "$out" | cut -d' ' -f1)
    if [[ $got != "$sha" ]]; then
        failures+=("$file	$repo: sha256 $got at $rev, manifest says $sha")
        rm -f "$out"
        bad=$((bad + 1))
        continue
    fi
    ok=$((ok + 1))
    [[ $rev == HEAD ]] && head=$((head + 1))
done <"$manifest"

echo "restored $ok files with a matching SHA-256 ($head of them from HEAD, not the pinned commit); $bad failed"
for f in "${failures[@]}"; do echo "FAILED	$f"; done
[[ $bad -eq 0 ]]
